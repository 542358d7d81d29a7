"""Helpers shared by the fuzz tests: a call must be refused with a ParameterError or return finite numbers,
within a wall-time budget."""

from __future__ import annotations

import time

import numpy as np
import pytest

from vibration.physics.model import ParameterError

#: Wall time allowed for one refused or bounded call, s: "not minutes", with room for a loaded 2-core machine
#: (the stiff Duffing sweep took 9.9 s at load 8 against the 10 s this used to be).
WALL = 30.0


def finite(value) -> bool:
    """Whether every number inside ``value`` (floats, arrays, tuples, dicts, dataclasses) is finite."""
    if isinstance(value, (bool, np.bool_, str)) or value is None:
        return True
    if isinstance(value, (int, float, complex, np.number)):
        return bool(np.isfinite(value))
    if isinstance(value, np.ndarray):
        return value.dtype.kind in "bUO" or bool(np.all(np.isfinite(value)))
    if isinstance(value, (list, tuple)):
        return all(finite(v) for v in value)
    if isinstance(value, dict):
        return all(finite(v) for v in value.values())
    if hasattr(value, "__dataclass_fields__"):
        return all(finite(getattr(value, f)) for f in value.__dataclass_fields__)
    return True


def refused_or(fn, *args, check=finite, **kwargs):
    """Call ``fn``: a ParameterError or a result passing ``check``, within WALL seconds. Returns the result or None."""
    t0 = time.perf_counter()
    try:
        out = fn(*args, **kwargs)
    except ParameterError as exc:
        assert str(exc), "a ParameterError must say what is wrong"
        out = None
    else:
        assert check(out), f"{fn.__name__} returned a non-finite result {out!r:.200}"
    wall = time.perf_counter() - t0
    assert wall < WALL, f"{fn.__name__} took {wall:.1f} s"
    return out


def refused(fn, *args, name=None, **kwargs) -> str:
    """Call ``fn``: it must raise a ParameterError (naming ``name`` when given) within WALL seconds."""
    t0 = time.perf_counter()
    with pytest.raises(ParameterError) as info:
        fn(*args, **kwargs)
    assert time.perf_counter() - t0 < WALL
    if name is not None:
        assert name in str(info.value), str(info.value)
    return str(info.value)
