"""The bad-input battery: for each parameter of an entry, the values its kind must survive.

A kind is read from the baseline value (float, int, str, bool, 1-D array, matrix, record, callable, tuple, path,
None) unless the entry names it. Each bad call must end in a :class:`vibration.ParameterError` whose message
names the parameter and says what is ``allowed``, or return a result the entry's check accepts (by default: every
number finite), within the wall-time budget of ``tests/fuzzing.py``.
"""

from __future__ import annotations

import numbers
import re
import time
from pathlib import Path

import numpy as np
from entries import Entry
from fuzzing import WALL, finite

from vibration import ParameterError

NAN, INF = float("nan"), float("inf")


def kind_of(entry: Entry, name: str) -> str:
    if name in entry.kinds:
        return entry.kinds[name]
    value = entry.args[name]
    if value is None:
        return "optional"
    if isinstance(value, bool | np.bool_):
        return "bool"
    if isinstance(value, numbers.Integral):
        return "int"
    if isinstance(value, numbers.Real):
        return "real"
    if isinstance(value, str):
        return "choice"
    if isinstance(value, Path):
        return "path"
    if isinstance(value, tuple) and all(isinstance(x, numbers.Real) for x in value):
        return "pair"
    if isinstance(value, list | np.ndarray):
        return "array" if np.ndim(value) == 1 else "matrix"
    if callable(value) and not hasattr(value, "__dataclass_fields__"):
        return "callable"
    return "record"


def _array_battery(a) -> dict[str, object]:
    a = np.asarray(a, dtype=float)
    out = {
        "empty": np.array([]),
        "nan": np.where(np.arange(a.size) == a.size // 2, NAN, a),
        "+inf": np.where(np.arange(a.size) == a.size // 2, INF, a),
        "-inf": np.where(np.arange(a.size) == 0, -INF, a),
        "2-D": np.vstack([a, a]),
        "strings": ["a"] * a.size,
        "complex": a + 1j,
        "bools": np.ones(a.size, dtype=bool),
        "zeros": np.zeros(a.size),
        "negative": -np.abs(a) - 1.0,
        "huge": a * 0.0 + 1e300,
        "subnormal": a * 0.0 + 1e-320,
        "scalar string": "abc",
        "None": None,
    }
    if a.size > 1:
        out["unsorted"] = a[::-1].copy()
        out["duplicated"] = np.concatenate([a[:1], a[:-1]])
        out["mismatched"] = a[:-1].copy()
    return out


BATTERY = {
    "real": {"nan": NAN, "+inf": INF, "-inf": -INF, "0": 0.0, "negative": -1.0, "subnormal": 1e-320,
             "huge": 1e300, "-huge": -1e300, "string": "1.0", "None": None, "list": [1.0, 2.0], "complex": 1 + 1j},
    "int": {"nan": NAN, "fraction": 2.5, "negative": -1, "0": 0, "huge": 10**18, "string": "3", "None": None,
            "bool": True},
    "choice": {"unknown": "no such", "list": ["x"], "None": None, "number": 3, "empty": ""},
    "bool": {"string": "yes", "nan": NAN, "None": None, "2": 2},
    "record": {"None": None, "string": "x", "number": 1.0},
    "callable": {"None": None, "string": "f"},
    "pair": {"nan": (NAN, 1.0), "reversed": (2.0, 1.0), "one": (1.0,), "string": "ab", "None": None},
    "optional": {"nan": NAN, "negative": -1.0, "string": "x"},
    "path": {"missing": Path("/nonexistent/file.csv"), "number": 3, "None": None},
}  # fmt: skip


def bad_values(entry: Entry, name: str) -> dict[str, object]:
    kind = kind_of(entry, name)
    if kind == "array":
        return _array_battery(entry.args[name])
    if kind == "matrix":
        m = np.asarray(entry.args[name], dtype=float)
        return {"nan": m * NAN, "huge": m + 1e300, "subnormal": np.where(m != 0, 1e-320, 0.0), "1-D": m[0],
                "non-square": m[:1], "strings": [["a"] * m.shape[1]] * m.shape[0], "None": None}  # fmt: skip
    return BATTERY[kind]


def cases(entry: Entry):
    """Every (parameter, label, bad value) of the entry's battery."""
    if entry.record:
        return
    for name in entry.args:
        if name in entry.skip:
            continue
        for label, value in bad_values(entry, name).items():
            yield name, label, value


def call(entry: Entry, name: str | None = None, value=None):
    """Run the entry (with ``name`` replaced by ``value``); assert the outcome the battery demands."""
    args = dict(entry.args)
    if name is not None:
        args[name] = value
    t0 = time.perf_counter()
    try:
        with np.errstate(all="ignore"):
            out = entry.fn(**args)
    except ParameterError as exc:
        msg = str(exc)
        wall = time.perf_counter() - t0
        assert wall < WALL, f"{entry.name}({name}=...) took {wall:.1f} s"
        assert name is not None, f"the baseline of {entry.name} is refused: {msg}"
        assert "allowed" in msg, f"{entry.name}({name}={value!r:.60}): the message does not say what is allowed: {msg}"
        assert re.search(rf"(?<![A-Za-z0-9_]){re.escape(name)}(?![A-Za-z0-9_])", msg), (
            f"{entry.name}({name}={value!r:.60}): the message does not name {name}: {msg}"
        )
        return None
    wall = time.perf_counter() - t0
    assert wall < WALL, f"{entry.name}({name}=...) took {wall:.1f} s"
    check = entry.check or finite
    assert check(out), f"{entry.name}({name}={value!r:.60}) returned a non-finite result {out!r:.200}"
    return out
