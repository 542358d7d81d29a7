"""Measurements and their input checks: the record, the CSV file format, validation of signals and seeds."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..duffing import _real_array
from ..files import read_text_file
from ..model import N_POINTS_MAX, ParameterError, check_int, check_real

__all__ = [
    "Measurements",
    "load_measurements",
    "measurements_csv",
    "save_measurements",
]

#: Columns of a measurement file: time (s), force (N), displacement (m), acceleration (m/s^2).
TIME, FORCE, DISPLACEMENT, ACCELERATION = "t_s", "force_N", "x_m", "a_m_s2"
COLUMNS = (TIME, FORCE, DISPLACEMENT, ACCELERATION)

#: Largest measurement file read, bytes (about 2e6 rows of four numbers).
MAX_BYTES = 200_000_000

#: Fewest samples a record may have (identification needs several periods as well).
MIN_SAMPLES = 32

#: Largest |value| accepted in a measurement, SI units (N, m, m/s^2, s).
MAX_ABS = 1e9

#: Largest deviation of a time sample from the uniform grid, as a fraction of the step.
UNIFORM_TOL = 0.25

#: Largest seed accepted (numpy's SeedSequence takes any non-negative int; this keeps seed + offsets an int64).
SEED_MAX = 2**62


# --------------------------------------------------------------------------- measurements


@dataclass(frozen=True, eq=False, kw_only=True)
class Measurements:
    """A uniformly sampled record: time (s), force (N), and displacement (m) or acceleration (m/s^2).

    Behaves as a mapping of ``t, force, x, a`` so that ``identify(**meas)`` works.
    """

    t: np.ndarray  # time, s; uniform, increasing
    force: np.ndarray  # force, N
    x: np.ndarray | None = None  # displacement, m
    a: np.ndarray | None = None  # acceleration, m/s^2

    @property
    def sensor(self) -> str:
        """``"x"`` (displacement) or ``"a"`` (acceleration)."""
        return "x" if self.x is not None else "a"

    @property
    def response(self) -> np.ndarray:
        """The measured response: ``x`` (m) or ``a`` (m/s^2)."""
        return self.x if self.x is not None else self.a

    @property
    def dt(self) -> float:
        """Sampling step, s."""
        return float((self.t[-1] - self.t[0]) / (self.t.size - 1))

    def keys(self):
        return ("t", "force", "x", "a")

    def __getitem__(self, key):
        if key not in self.keys():
            raise KeyError(key)
        return getattr(self, key)

    def __len__(self) -> int:
        return int(self.t.size)


def _sampling(t: np.ndarray, where) -> float:
    """Check that ``t`` is strictly increasing and uniform; return the step (s).

    ``where(i)`` names sample ``i`` in messages (e.g. "column t_s, row 12 (line 13)").
    """
    steps = np.diff(t)
    bad = np.nonzero(~(steps > 0.0))[0]
    if bad.size:
        i = int(bad[0]) + 1
        raise ParameterError(
            f"{where(i)}: time {t[i]!r} s does not increase (previous {t[i - 1]!r} s): "
            "allowed strictly increasing, uniformly sampled times"
        )
    h = float((t[-1] - t[0]) / (t.size - 1))
    h_med = float(np.median(steps))
    gap = np.nonzero(steps > (1.0 + 2.0 * UNIFORM_TOL) * h_med)[0]
    if gap.size:
        i = int(gap[0]) + 1
        raise ParameterError(
            f"{where(i)}: gap in time, step {steps[i - 1]:.6g} s after {t[i - 1]!r} s where the typical step is "
            f"{h_med:.6g} s (missing samples?): allowed uniform sampling without gaps"
        )
    odd = np.nonzero(np.abs(steps - h_med) > 2.0 * UNIFORM_TOL * h_med)[0]
    if odd.size:
        i = int(odd[0]) + 1
        raise ParameterError(
            f"{where(i)}: non-uniform time, step {steps[i - 1]:.6g} s where the typical step is {h_med:.6g} s: "
            f"allowed uniform sampling (every step within {2 * UNIFORM_TOL:.0%} of the typical step)"
        )
    dev = np.abs(t - (t[0] + h * np.arange(t.size)))
    i = int(np.argmax(dev))
    if dev[i] > UNIFORM_TOL * h:
        raise ParameterError(
            f"{where(i)}: non-uniform time, {t[i]!r} s is {dev[i] / h:.2g} steps off the uniform grid "
            f"t0 + n h (h = {h:.6g} s): allowed uniform sampling (within {UNIFORM_TOL:g} of a step)"
        )
    return h


def load_measurements(path) -> Measurements:
    """Read and validate a measurement CSV file.

    The first line is the header: ``t_s`` (time, s), ``force_N`` (force, N) and
    exactly one of ``x_m`` (displacement, m) or ``a_m_s2`` (acceleration,
    m/s^2), in any order, comma-separated. Every following line is one sample
    with a finite decimal number in each column; the time must increase with a
    uniform step. Blank lines at the end and lines starting with ``#`` are
    ignored.

    Parameters
    ----------
    path : str or os.PathLike
        The file (UTF-8, at most ``MAX_BYTES`` bytes and ``N_POINTS_MAX`` rows,
        at least ``MIN_SAMPLES`` rows).

    Returns
    -------
    Measurements
        ``t`` (s), ``force`` (N) and ``x`` (m) or ``a`` (m/s^2), float arrays.

    Raises
    ------
    ParameterError
        On anything else, naming the column and the row (data rows count from 1
        after the header; the file line is given too): a missing, unknown or
        duplicate column, a cell that is empty, not a number, NaN, infinite or
        absurdly large, a row with too few or too many cells, time that does not
        increase, has a gap or is not uniform, an empty or absurdly large file.

    Examples
    --------
    >>> from vibration.physics.twin import example_measurements
    >>> import tempfile, os
    >>> d = tempfile.mkdtemp()
    >>> path = os.path.join(d, "m.csv")
    >>> save_measurements(path, example_measurements())
    >>> meas = load_measurements(path)
    >>> meas.sensor, len(meas), round(meas.dt, 6)     # -, samples, s
    ('x', 3001, 0.02)
    >>> _ = open(path, "a").write("60.04,1.0,nan\\n")
    >>> load_measurements(path)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: column x_m, row 3002 (line 3003): 'nan' is not a finite number: ...
    """
    name, text = read_text_file(path, "measurement CSV file", max_bytes=MAX_BYTES)
    return _parse(text, name)


def _parse(text: str, name: str) -> Measurements:
    lines = [(i + 1, ln.strip()) for i, ln in enumerate(text.splitlines())]
    lines = [(n, ln) for n, ln in lines if not ln.startswith("#")]
    while lines and not lines[-1][1]:
        lines.pop()
    if not lines or not lines[0][1]:
        raise ParameterError(
            f"path = {name!r}: the file is empty (no header): allowed a header line "
            f"{TIME},{FORCE},{DISPLACEMENT} or {TIME},{FORCE},{ACCELERATION} and rows of numbers"
        )
    head_line, head = lines[0]
    cols = [c.strip().strip('"').strip("'").strip() for c in head.split(",")]
    allowed = f"allowed the columns {TIME}, {FORCE} and one of {DISPLACEMENT} or {ACCELERATION}"
    for j, c in enumerate(cols):
        if c not in COLUMNS:
            raise ParameterError(f"column {c!r} (header, line {head_line}, position {j + 1}) is unknown: {allowed}")
        if cols.index(c) != j:
            raise ParameterError(f"column {c} appears twice in the header (line {head_line}): {allowed}")
    for c in (TIME, FORCE):
        if c not in cols:
            raise ParameterError(f"column {c} is missing from the header (line {head_line}): {allowed}")
    if DISPLACEMENT in cols and ACCELERATION in cols:
        raise ParameterError(
            f"columns {DISPLACEMENT} and {ACCELERATION} are both in the header (line {head_line}): {allowed}, not both"
        )
    if DISPLACEMENT not in cols and ACCELERATION not in cols:
        raise ParameterError(
            f"column {DISPLACEMENT} (or {ACCELERATION}) is missing from the header (line {head_line}): {allowed}"
        )
    rows = lines[1:]
    n = len(rows)
    if n < MIN_SAMPLES:
        raise ParameterError(f"path = {name!r} has {n} data rows: allowed {MIN_SAMPLES} to {N_POINTS_MAX} rows")
    if n > N_POINTS_MAX:
        raise ParameterError(f"path = {name!r} has {n} data rows: allowed {MIN_SAMPLES} to {N_POINTS_MAX} rows")

    def where(col: str, r: int) -> str:
        return f"column {col}, row {r + 1} (line {rows[r][0]})"

    cells = []
    for r, (_, ln) in enumerate(rows):
        parts = ln.split(",")
        if len(parts) != len(cols):
            col = cols[min(len(parts), len(cols) - 1)] if len(parts) < len(cols) else "(extra)"
            raise ParameterError(
                f"{where(col, r)}: {len(parts)} cells where the header has {len(cols)}: "
                f"allowed one number per column ({', '.join(cols)})"
            )
        cells.append(parts)
    data = {}
    for j, col in enumerate(cols):
        raw = [p[j].strip() for p in cells]
        try:
            values = np.array(raw, dtype=float)
        except ValueError:
            values = None
        if values is None or not np.all(np.isfinite(values)) or np.any(np.abs(values) > MAX_ABS):
            for r, s in enumerate(raw):
                try:
                    v = float(s)
                except ValueError:
                    what = "empty" if not s else f"{s!r} is not a number"
                    raise ParameterError(
                        f"{where(col, r)}: {what}: allowed finite decimal numbers with |value| <= {MAX_ABS:g}"
                    ) from None
                if not math.isfinite(v):
                    raise ParameterError(
                        f"{where(col, r)}: {s!r} is not a finite number: "
                        f"allowed finite decimal numbers with |value| <= {MAX_ABS:g}"
                    )
                if abs(v) > MAX_ABS:
                    raise ParameterError(
                        f"{where(col, r)}: {s!r} is absurdly large: allowed finite decimal numbers with "
                        f"|value| <= {MAX_ABS:g}"
                    )
        data[col] = values
    _sampling(data[TIME], lambda i: where(TIME, i))
    return Measurements(t=data[TIME], force=data[FORCE], x=data.get(DISPLACEMENT), a=data.get(ACCELERATION))


def measurements_csv(meas: Measurements, digits: int = 9) -> str:
    """The CSV text of a record (header and rows; ``digits`` significant figures).

    Examples
    --------
    >>> print(measurements_csv(Measurements(t=np.arange(3) * 0.5, force=np.ones(3), x=np.zeros(3))))
    t_s,force_N,x_m
    0,1,0
    0.5,1,0
    1,1,0
    <BLANKLINE>
    """
    if not isinstance(meas, Measurements):
        raise ParameterError(f"meas = {meas!r:.60} is not a Measurements: allowed a record (load_measurements)")
    digits = check_int("digits", digits, low=3, high=17)
    name = DISPLACEMENT if meas.x is not None else ACCELERATION
    cols = np.column_stack([meas.t, meas.force, meas.response])
    out = [f"{TIME},{FORCE},{name}"]
    out += [",".join(f"{float(v):.{digits}g}" for v in row) for row in cols]
    return "\n".join(out) + "\n"


def save_measurements(path, meas: Measurements, digits: int = 9) -> None:
    """Write a record as a measurement CSV file (see :func:`measurements_csv`)."""
    Path(os.fspath(path)).write_text(measurements_csv(meas, digits), encoding="utf-8")


# --------------------------------------------------------------------------- inputs


def _check_seed(seed, name: str = "seed", none: bool = False):
    """A seed: a non-negative int (or None when ``none``), else :class:`ParameterError`."""
    if seed is None and none:
        return None
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)):
        allowed = "a non-negative integer" + (" or None" if none else "")
        raise ParameterError(f"{name} = {seed!r:.60} is not an integer: allowed {allowed} (<= {SEED_MAX})")
    return check_int(name, int(seed), low=0, high=SEED_MAX)


def _check_band(band) -> tuple[float, float]:
    """A frequency band ``(low, high)``, Hz, 0 < low < high."""
    if isinstance(band, (str, bytes)) or not hasattr(band, "__len__") or len(band) != 2:
        raise ParameterError(f"band = {band!r:.60} is not a pair: allowed (low, high) Hz with 0 < low < high")
    lo = check_real("band[0]", band[0], low=0.0, low_open=True, unit="Hz")
    hi = check_real("band[1]", band[1], low=lo, low_open=True, unit="Hz")
    return lo, hi


def _check_sensor(sensor) -> str:
    if not isinstance(sensor, str) or sensor not in ("x", "a"):
        raise ParameterError(f"sensor = {sensor!r:.60}: allowed 'x' (displacement) or 'a' (acceleration)")
    return sensor


def _grid_size(duration: float, dt: float, what: str = "duration") -> int:
    """Samples of ``arange(round(duration / dt) + 1) * dt``, refused above ``N_POINTS_MAX`` before allocating."""
    n = duration / dt + 1.0
    if not n <= N_POINTS_MAX:
        raise ParameterError(
            f"{what} = {duration!r} s with dt = {dt!r} s makes {n:.3g} samples: allowed at most {N_POINTS_MAX} "
            f"({what} / dt <= {N_POINTS_MAX - 1})"
        )
    return int(round(duration / dt)) + 1


def _work(name: str, value, work: float, limit: float, what: str) -> None:
    if not work <= limit:
        raise ParameterError(f"{name} = {value!r:.60} makes {work:.3g} {what}: allowed at most {limit:.3g}")


def _finite_output(arr, what: str, cause: str) -> None:
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{what} overflows (not finite): {cause}")


def _signal(name: str, value, n: int | None = None) -> np.ndarray:
    if isinstance(value, (str, bytes)):
        raise ParameterError(f"{name} = {value!r:.60} is a string: allowed a 1-D array of numbers")
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} = {value!r:.60} is not an array of numbers: allowed a 1-D array") from None
    if raw.dtype.kind not in "iufO":
        raise ParameterError(
            f"{name} = {value!r:.60} has values of type {raw.dtype} (bool, complex or string): allowed a 1-D "
            "array of real numbers"
        )
    try:
        arr = _real_array(name, raw, max_size=N_POINTS_MAX) if raw.dtype.kind == "O" else raw.astype(float)
    except ParameterError:
        raise ParameterError(f"{name} = {value!r:.60} is not an array of real numbers: allowed a 1-D array") from None
    if arr.ndim != 1:
        raise ParameterError(f"{name} has shape {arr.shape}: allowed a 1-D array")
    if n is not None and arr.size != n:
        raise ParameterError(f"{name} has {arr.size} samples: allowed as many as t ({n})")
    if not 1 <= arr.size <= N_POINTS_MAX:
        raise ParameterError(f"{name} has {arr.size} samples: allowed 1 to {N_POINTS_MAX}")
    bad = np.nonzero(~np.isfinite(arr) | (np.abs(arr) > MAX_ABS))[0]
    if bad.size:
        i = int(bad[0])
        raise ParameterError(f"{name}[{i}] = {arr[i]!r}: allowed finite numbers with |value| <= {MAX_ABS:g}")
    return arr


def _record(t, force, x, a):
    """Validated ``(t, h, force, y, sensor)``."""
    t = _signal("t", t)
    if not MIN_SAMPLES <= t.size <= N_POINTS_MAX:
        raise ParameterError(f"t has {t.size} samples: allowed {MIN_SAMPLES} to {N_POINTS_MAX}")
    h = _sampling(t, lambda i: f"t[{i}]")
    force = _signal("force", force, t.size)
    if (x is None) == (a is None):
        given = "both given" if x is not None else "both missing"
        raise ParameterError(
            f"x and a are {given}: allowed exactly one of x (displacement, m) or a (acceleration, m/s^2)"
        )
    sensor = "x" if x is not None else "a"
    y = _signal(sensor, x if x is not None else a, t.size)
    if np.ptp(force) == 0.0:
        raise ParameterError(
            f"force is constant ({force[0]!r} N): allowed a force that varies (a broadband test: chirp or random)"
        )
    if np.ptp(y) == 0.0:
        raise ParameterError(f"{sensor} is constant ({y[0]!r}): allowed a measured response that varies")
    return t, h, force, y, sensor
