"""A digital twin: measurements, identification, tracking and change detection (Part II).

The twin is the linear oscillator ``m x'' + c x' + k x = F(t)`` fed with a measured
force and compared with a measured displacement ``x`` or acceleration ``a``.

Model of the data (the assumptions every function here relies on)
-----------------------------------------------------------------
* The force is measured without noise and sampled uniformly (step ``h``); between
  samples it is taken as linear (first-order hold). That is exact for a
  piecewise-linear force and accurate to ``h^2 |F''| / 8`` otherwise, so the force
  should be band-limited well below the Nyquist frequency ``pi / h``.
* The response is sampled at the same instants and carries additive white
  Gaussian noise of constant standard deviation (m for ``x``, m/s^2 for ``a``);
  no offset, no drift, no noise on the force.
* The initial state ``x(t0), v(t0)`` is unknown and estimated with the parameters.
* Over the analysed window the parameters are constant (identification) or
  constant until a change (detection), and the first part of a monitored record
  is healthy when no reference is given.

Exact discretisation
--------------------
With ``z = (x, v)``, ``z' = A z + B F``, ``A = [[0, 1], [-k/m, -c/m]]``,
``B = (0, 1/m)`` and ``F`` linear on ``[t_n, t_n + h]``, the state advances
exactly as ``z[n+1] = Phi z[n] + (P0 - P1) F[n] + P1 F[n+1]`` where
``expm(h [[A, B, 0], [0, 0, 1/h], [0, 0, 0]]) = [[Phi, P0, P1], ...]``
(one 4 x 4 matrix exponential per step size and parameter set). The recursion is
run as a second-order IIR filter (``scipy.signal.lfilter``), so a response costs
one matrix exponential and one pass over the samples.

Identification
--------------
Nonlinear least squares on that exact discrete model (output error). The
output is linear in ``1/m`` and in the initial state once ``omega_n`` and
``zeta`` are fixed, so those three are projected out (variable projection) and a
global grid over ``(omega_n, zeta)``, a frequency-domain (Levy) start and a
local ``least_squares`` polish find the minimum. Standard errors come from the
Jacobian of the full model in ``(m, c, k, x0, v0)`` at the optimum,
``cov = s^2 (J^T J)^-1`` with ``s^2 = RSS / (N - 5)``, and the 95 % intervals
use Student's t with ``N - 5`` degrees of freedom.

Tracking and detection
----------------------
:func:`track_stiffness` is an extended Kalman filter on ``(x, v, k)`` with a
random walk on ``k``; :func:`detect_change` runs a one-sided CUSUM on the
normalised squared output-error residual of the reference model.

Examples
--------
>>> from vibration import Oscillator
>>> t = np.arange(0.0, 60.0, 0.02)
>>> meas = synthetic_measurements(Oscillator(1.0, 0.5, 20.0), t, random_force(t, seed=1), noise=1e-3, seed=2)
>>> fit = identify(meas.t, meas.force, x=meas.x)
>>> [round(v, 2) for v in (fit.m, fit.c, fit.k)]      # kg, N s/m, N/m
[1.0, 0.5, 20.0]
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import signal
from scipy.optimize import least_squares
from scipy.stats import t as student_t

from .duffing import _Counted, _OverBudget, _real_array
from .model import N_POINTS_MAX, Oscillator, ParameterError, check_int, check_real

__all__ = [
    "ChangeDetection",
    "Discretization",
    "EstimateGrid",
    "FaultScenario",
    "THRESHOLDS",
    "FrequencyEstimate",
    "FrequencyResponse",
    "Identification",
    "Measurements",
    "SampledResponse",
    "StiffnessTrack",
    "detect_change",
    "CoverageExperiment",
    "DetectionExperiment",
    "detection_experiment",
    "detection_study",
    "discretisation_checks",
    "fault_scenario",
    "estimate_grid",
    "identification_experiment",
    "identification_sweep",
    "discretize",
    "expm_batch",
    "example_measurements",
    "frequency_estimates",
    "frf_estimate",
    "identify",
    "load_measurements",
    "measurements_csv",
    "random_force",
    "sampled_response",
    "save_measurements",
    "simulated_test",
    "stiffness_profile",
    "synthetic_measurements",
    "track_stiffness",
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

#: Relative spacing of the natural-frequency grid of the global search, and its damping ratios.
GRID_STEP = 0.05
GRID_ZETAS = (0.05, 0.3)

#: Default CUSUM drift (in units of the noise variance) and threshold of :func:`detect_change`.
CUSUM_DRIFT = 1.0
CUSUM_THRESHOLD = 40.0

#: Resolution of the stiffness at which the Kalman filter recomputes its exact step, fraction of the reference k.
K_QUANTUM = 1e-5

#: Fraction of a record used to calibrate the detector (and to identify it when no reference is given).
CALIBRATION = 0.25

#: Work budgets: samples times frequencies of one :func:`random_force` (cosines evaluated); samples
#: of one :func:`track_stiffness` (a Python loop); samples simulated and identified (or monitored) by one
#: Monte Carlo experiment, all its records together; right-hand-side evaluations of the ``solve_ivp``
#: reference of :func:`discretisation_checks`.
MAX_MULTISINE_TERMS = 100_000_000
MAX_TRACK_SAMPLES = 1_000_000
MAX_EXPERIMENT_SAMPLES = 20_000_000
MAX_RHS_EVALUATIONS = 300_000

#: Largest seed accepted (numpy's SeedSequence takes any non-negative int; this keeps seed + offsets an int64).
SEED_MAX = 2**62


# --------------------------------------------------------------------------- measurements


@dataclass(frozen=True, eq=False)
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
    path = Path(os.fspath(path))
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise ParameterError(
            f"path = {str(path)!r} cannot be read ({exc.strerror}): allowed an existing file"
        ) from None
    if size > MAX_BYTES:
        raise ParameterError(f"path = {str(path)!r} has {size} bytes: allowed at most {MAX_BYTES} bytes")
    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise ParameterError(f"path = {str(path)!r} is not UTF-8 text: allowed a UTF-8 CSV file") from None
    return _parse(text, str(path))


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
    return Measurements(data[TIME], data[FORCE], data.get(DISPLACEMENT), data.get(ACCELERATION))


def measurements_csv(meas: Measurements, digits: int = 9) -> str:
    """The CSV text of a record (header and rows; ``digits`` significant figures).

    Examples
    --------
    >>> print(measurements_csv(Measurements(np.arange(3) * 0.5, np.ones(3), x=np.zeros(3))))
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


def example_measurements() -> Measurements:
    """The synthetic record shipped as ``data/twin_example.csv`` (made here, not measured).

    The paper's oscillator (m = 1 kg, c = 0.5 N s/m, k = 20 N/m) driven by a
    band-limited random force (0.1 to 2 Hz, 2 N rms, seed 13) for 60 s at 50 Hz
    from rest, displacement with white Gaussian noise of 2 mm (seed 14); values
    rounded to 7 significant figures.

    Examples
    --------
    >>> meas = example_measurements()
    >>> len(meas), meas.sensor
    (3001, 'x')
    """
    t = np.round(np.arange(3001) * 0.02, 10)
    force = random_force(t, band=(0.1, 2.0), rms=2.0, seed=13)
    meas = synthetic_measurements(Oscillator(1.0, 0.5, 20.0), t, force, noise=2e-3, seed=14)
    r = np.vectorize(lambda v: float(f"{v:.7g}"))
    return Measurements(t, r(meas.force), x=r(meas.x))


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


def _check_osc(osc) -> Oscillator:
    if not isinstance(osc, Oscillator):
        raise ParameterError(f"osc = {osc!r:.60} is not an Oscillator: allowed Oscillator(m, c, k)")
    return osc


def _grid_size(duration: float, dt: float, what: str = "duration") -> int:
    """Samples of ``arange(round(duration / dt) + 1) * dt``, refused above ``N_POINTS_MAX`` before allocating."""
    n = round(duration / dt) + 1
    if n > N_POINTS_MAX:
        raise ParameterError(
            f"{what} = {duration!r} s with dt = {dt!r} s makes {n:.3g} samples: allowed at most {N_POINTS_MAX} "
            f"({what} / dt <= {N_POINTS_MAX - 1})"
        )
    return int(n)


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


# --------------------------------------------------------------------------- exact discretisation


@dataclass(frozen=True)
class Discretization:
    """Exact first-order-hold step: ``z[n+1] = phi z[n] + gamma0 F[n] + gamma1 F[n+1]``, ``z = (x, v)``."""

    dt: float  # step, s
    phi: np.ndarray  # (2, 2) state transition, (1, s; 1/s, 1)
    gamma0: np.ndarray  # (2,) weight of F[n], (m/N, m/(s N))
    gamma1: np.ndarray  # (2,) weight of F[n+1], (m/N, m/(s N))


_PADE13 = (
    64764752532480000.0,
    32382376266240000.0,
    7771770303897600.0,
    1187353796428800.0,
    129060195264000.0,
    10559470521600.0,
    670442572800.0,
    33522128640.0,
    1323241920.0,
    40840800.0,
    960960.0,
    16380.0,
    182.0,
    1.0,
)


def expm_batch(a: np.ndarray) -> np.ndarray:
    """Matrix exponential of a stack of small matrices, shape (..., n, n).

    Degree-13 Padé approximant with scaling and squaring (Higham 2005), in
    NumPy's stacked ``matmul`` and ``solve``: the same algorithm as
    ``scipy.linalg.expm`` (to which the tests compare it, relative 1e-13), without
    its per-call BLAS thread start-up, which dominates for 4 x 4 matrices on a
    busy machine.

    Examples
    --------
    >>> x = np.array([[0.0, 1.0], [-1.0, 0.0]])
    >>> bool(np.allclose(expm_batch(x), [[np.cos(1), np.sin(1)], [-np.sin(1), np.cos(1)]], rtol=0, atol=1e-15))
    True
    """
    a = _real_array("a", a, max_size=N_POINTS_MAX)
    if a.ndim < 2 or a.shape[-1] != a.shape[-2]:
        raise ParameterError(f"a has shape {a.shape}: allowed a stack of square matrices, shape (..., n, n)")
    n = a.shape[-1]
    norm = np.max(np.sum(np.abs(a), axis=-2), axis=-1)
    if not np.all(np.isfinite(norm)):
        raise ParameterError("a has a matrix whose 1-norm overflows: allowed matrices of finite 1-norm")
    s = np.maximum(0, np.ceil(np.log2(np.maximum(norm, 1e-300) / 5.371920351148152))).astype(int)
    a = a / (2.0**s)[..., None, None]
    b = _PADE13
    eye = np.broadcast_to(np.eye(n), a.shape)
    a2 = a @ a
    a4 = a2 @ a2
    a6 = a4 @ a2
    u = a @ (a6 @ (b[13] * a6 + b[11] * a4 + b[9] * a2) + b[7] * a6 + b[5] * a4 + b[3] * a2 + b[1] * eye)
    v = a6 @ (b[12] * a6 + b[10] * a4 + b[8] * a2) + b[6] * a6 + b[4] * a4 + b[2] * a2 + b[0] * eye
    r = np.linalg.solve(v - u, v + u)
    smax = int(np.max(s)) if s.size else 0
    with np.errstate(over="ignore", invalid="ignore"):
        for j in range(smax):
            sq = r @ r
            r = np.where((s > j)[..., None, None], sq, r)
    if not np.all(np.isfinite(r)):
        raise ParameterError(
            f"a has a matrix whose exponential overflows (1-norm up to {float(np.max(norm)):.3g}): allowed "
            "matrices whose exponential is a finite float"
        )
    return r


def _foh(m, c, k, h):
    """Batched exact FOH matrices for arrays of (m, c, k): phi (P,2,2), gamma0 (P,2), gamma1 (P,2)."""
    m, c, k = (np.atleast_1d(np.asarray(v, dtype=float)) for v in (m, c, k))
    p = m.size
    big = np.zeros((p, 4, 4))
    big[:, 0, 1] = h
    big[:, 1, 0] = -k / m * h
    big[:, 1, 1] = -c / m * h
    big[:, 1, 2] = h / m
    big[:, 2, 3] = 1.0
    try:
        e = expm_batch(big)
    except ParameterError:
        raise ParameterError(
            f"the step h = {h!r} s with c/m up to {float(np.max(np.abs(c / m))):.3g} 1/s and k/m up to "
            f"{float(np.max(k / m)):.3g} 1/s^2 overflows the exact step (exp(A h) is not a finite float): allowed "
            "a smaller step or a stable oscillator"
        ) from None
    phi = e[:, :2, :2]
    p0, p1 = e[:, :2, 2], e[:, :2, 3]
    return phi, p0 - p1, p1


def discretize(osc: Oscillator, dt: float) -> Discretization:
    """Exact discretisation of the oscillator for a force linear between samples (first-order hold).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    dt : float
        Sampling step, s (> 0).

    Examples
    --------
    >>> d = discretize(Oscillator(1.0, 0.0, 1.0), 0.5)
    >>> bool(np.allclose(d.phi, [[np.cos(0.5), np.sin(0.5)], [-np.sin(0.5), np.cos(0.5)]]))
    True
    >>> float(np.round(d.gamma0.sum() + d.gamma1.sum() - (1 - np.cos(0.5)) - np.sin(0.5), 12))  # constant F = 1 N
    0.0
    """
    _check_osc(osc)
    dt = check_real("dt", dt, low=0.0, low_open=True, unit="s")
    phi, g0, g1 = _foh(osc.m, osc.c, osc.k, dt)
    return Discretization(dt, phi[0], g0[0], g1[0])


def _filters(phi, g0, g1, row, feed):
    """Second-order IIR coefficients of output ``row @ z + feed F`` and of the free response basis.

    Returns ``(b, a, free_b)``: ``lfilter(b, a, F)`` is the output from ``w[0] = 0``
    (``w = z - gamma1 F``), and ``free_b[j]`` gives ``row @ phi^n e_j`` as
    ``free_b[j][0] y[n] + free_b[j][1] y[n-1]`` with ``y = lfilter([1], a, delta)``.
    """
    tr = phi[0, 0] + phi[1, 1]
    det = phi[0, 0] * phi[1, 1] - phi[0, 1] * phi[1, 0]
    a = np.array([1.0, -tr, det])
    adj = np.array([[-phi[1, 1], phi[0, 1]], [phi[1, 0], -phi[0, 0]]])
    e = phi @ g1 + g0
    d = row @ g1 + feed
    b = np.array([d, row @ e + d * a[1], row @ adj @ e + d * a[2]])
    free_b = [(row[j], (row @ adj)[j]) for j in range(2)]
    return b, a, free_b


def _run(phi, g0, g1, row, feed, force, z0):
    """Output ``row @ z[n] + feed F[n]`` from state ``z0`` at the first sample (exact FOH)."""
    b, a, free_b = _filters(phi, g0, g1, row, feed)
    n = force.size
    delta = np.zeros(n)
    delta[0] = 1.0
    y = signal.lfilter([1.0], a, delta)
    y1 = np.concatenate([[0.0], y[:-1]])
    w0 = np.asarray(z0, float) - g1 * force[0]
    free = sum(w0[j] * (free_b[j][0] * y + free_b[j][1] * y1) for j in range(2))
    return signal.lfilter(b, a, force) + free


@dataclass(frozen=True)
class SampledResponse:
    """Response at the samples: ``t`` (s), ``x`` (m), ``v`` (m/s), ``a`` (m/s^2)."""

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray


def sampled_response(osc: Oscillator, t, force, x0: float = 0.0, v0: float = 0.0) -> SampledResponse:
    """Exact response to a sampled force held linear between samples (first-order hold).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    t : array_like
        Uniform, increasing sample times, s.
    force : array_like
        Force at ``t``, N.
    x0, v0 : float
        State at ``t[0]``: displacement (m) and velocity (m/s).

    Returns
    -------
    SampledResponse
        ``x`` (m), ``v`` (m/s) and ``a = (F - c v - k x) / m`` (m/s^2) at ``t``.

    Examples
    --------
    >>> from vibration import SineForce, exact_response
    >>> osc, f = Oscillator(1.0, 0.5, 20.0), SineForce(5.0, 3.0)
    >>> t = np.linspace(0.0, 10.0, 2001)
    >>> r = sampled_response(osc, t, f(t))
    >>> bool(np.max(np.abs(r.x - exact_response(osc, f, t).x)) < 2e-5)    # m: h^2 omega^2 F0 / 8 force interpolation
    True
    """
    _check_osc(osc)
    t = _signal("t", t)
    if t.size < 2:
        raise ParameterError(f"t has {t.size} samples: allowed at least 2")
    h = _sampling(t, lambda i: f"t[{i}]")
    force = _signal("force", force, t.size)
    z0 = (check_real("x0", x0, unit="m"), check_real("v0", v0, unit="m/s"))
    phi, g0, g1 = (v[0] for v in _foh(osc.m, osc.c, osc.k, h))
    with np.errstate(over="ignore", invalid="ignore"):
        x = _run(phi, g0, g1, np.array([1.0, 0.0]), 0.0, force, z0)
        v = _run(phi, g0, g1, np.array([0.0, 1.0]), 0.0, force, z0)
        acc = (force - osc.c * v - osc.k * x) / osc.m
    for arr in (x, v, acc):
        _finite_output(
            arr,
            "the sampled response",
            f"the oscillator {osc} grows without bound over {float(t[-1] - t[0]):.3g} s, or the force or initial "
            "state is too large: allowed a response that stays a finite float",
        )
    return SampledResponse(t, x, v, acc)


# --------------------------------------------------------------------------- synthetic data


def random_force(t, band: tuple[float, float] = (0.1, 2.0), rms: float = 2.0, seed: int = 0) -> np.ndarray:
    """Band-limited random force: a multisine with a flat spectrum in ``band`` and random phases.

    Parameters
    ----------
    t : array_like
        Uniform sample times, s.
    band : (float, float)
        Lowest and highest frequency, Hz (0 < low < high).
    rms : float
        Root-mean-square force, N (> 0).
    seed : int
        Seed of the phases.

    Returns
    -------
    numpy.ndarray
        Force at ``t``, N.

    Examples
    --------
    >>> t = np.arange(0.0, 100.0, 0.01)
    >>> round(float(np.sqrt(np.mean(random_force(t, rms=3.0) ** 2))), 6)   # N
    3.0
    """
    t = _signal("t", t)
    if t.size < 2 or not t[-1] > t[0]:
        raise ParameterError(f"t = {t!r:.60} spans no time: allowed at least 2 samples, t[-1] > t[0]")
    lo, hi = _check_band(band)
    rms = check_real("rms", rms, low=0.0, low_open=True, unit="N")
    seed = _check_seed(seed)
    span = float(t[-1] - t[0])
    df = 1.0 / span
    n_freqs = max(math.floor(hi / df) - math.ceil(lo / df) + 1, 1)
    _work(
        "band",
        (lo, hi),
        float(n_freqs) * t.size,
        MAX_MULTISINE_TERMS,
        f"cosine evaluations ({n_freqs} lines x {t.size} samples)",
    )
    freqs = np.arange(math.ceil(lo / df), math.floor(hi / df) + 1) * df
    if freqs.size == 0:
        freqs = np.array([0.5 * (lo + hi)])
    rng = np.random.default_rng(seed)
    phases = rng.uniform(0.0, 2.0 * np.pi, freqs.size)
    f = np.zeros_like(t)
    tt = t - t[0]
    for k0 in range(0, freqs.size, 256):  # bounded memory
        sl = slice(k0, k0 + 256)
        f += np.cos(2.0 * np.pi * np.outer(tt, freqs[sl]) + phases[sl]).sum(axis=1)
    power = float(np.mean(f**2))
    if not power > 0.0:  # pragma: no cover - a sum of cosines with random phases vanishing at every sample
        raise ParameterError(f"t = {t!r:.60} samples the multisine only at its zeros: allowed more samples")
    return f * (rms / math.sqrt(power))


def stiffness_profile(
    t, k0: float, decline_start: float, decline_rate: float, drop_time: float | None = None, drop: float = 0.0
) -> np.ndarray:
    """A fatigue-like stiffness history: constant, then a linear decline, optionally a sudden drop.

    Parameters
    ----------
    t : array_like
        Times, s.
    k0 : float
        Healthy stiffness, N/m (> 0).
    decline_start : float
        Time the slow decline starts, s.
    decline_rate : float
        Relative decline rate, 1/s (fraction of ``k0`` lost per second, >= 0).
    drop_time : float, optional
        Time of the sudden drop, s (None: no drop).
    drop : float
        Fraction of the stiffness lost at ``drop_time``, 1 (0 to 0.9).

    Examples
    --------
    >>> stiffness_profile([0.0, 10.0, 20.0, 30.0], 20.0, 10.0, 0.001, drop_time=25.0, drop=0.1)
    array([20.  , 20.  , 19.8 , 17.64])
    """
    t = _signal("t", t)
    k0 = check_real("k0", k0, low=0.0, low_open=True, unit="N/m")
    decline_start = check_real("decline_start", decline_start, unit="s")
    decline_rate = check_real("decline_rate", decline_rate, low=0.0, unit="1/s")
    drop = check_real("drop", drop, low=0.0, high=0.9)
    k = k0 * (1.0 - decline_rate * np.clip(t - decline_start, 0.0, None))
    if drop_time is not None:
        drop_time = check_real("drop_time", drop_time, unit="s")
        k = np.where(t >= drop_time, k * (1.0 - drop), k)
    if np.any(k <= 0.0):
        raise ParameterError(f"decline_rate = {decline_rate!r} 1/s makes k <= 0 inside t: allowed k(t) > 0")
    return k


def synthetic_measurements(
    osc: Oscillator,
    t,
    force,
    *,
    sensor: str = "x",
    noise: float = 0.0,
    seed: int | None = 0,
    stiffness=None,
    x0: float = 0.0,
    v0: float = 0.0,
) -> Measurements:
    """A simulated record: exact FOH response plus white Gaussian noise on the sensor.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    t : array_like
        Uniform sample times, s.
    force : array_like
        Force at ``t``, N.
    sensor : {"x", "a"}
        Displacement (m) or acceleration (m/s^2).
    noise : float
        Standard deviation of the sensor noise, m or m/s^2 (>= 0).
    seed : int or None
        Seed of the noise.
    stiffness : array_like, optional
        Stiffness at each sample, N/m, held over the step that follows (a fault);
        ``osc.k`` is ignored then.
    x0, v0 : float
        Initial displacement (m) and velocity (m/s).

    Examples
    --------
    >>> t = np.arange(0.0, 10.0, 0.01)
    >>> a = synthetic_measurements(Oscillator(1.0, 0.5, 20.0), t, np.ones_like(t))
    >>> b = synthetic_measurements(Oscillator(1.0, 0.5, 20.0), t, np.ones_like(t), stiffness=np.full(t.size, 20.0))
    >>> bool(np.allclose(a.x, b.x, rtol=0, atol=1e-12))
    True
    """
    _check_osc(osc)
    sensor = _check_sensor(sensor)
    noise = check_real("noise", noise, low=0.0, high=MAX_ABS, unit="m" if sensor == "x" else "m/s^2")
    seed = _check_seed(seed, none=True)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    t = _signal("t", t)
    if t.size < 2:
        raise ParameterError(f"t has {t.size} samples: allowed at least 2")
    force = _signal("force", force, t.size)
    if stiffness is None:
        r = sampled_response(osc, t, force, x0, v0)
        y = r.x if sensor == "x" else r.a
    else:
        ks = _signal("stiffness", stiffness, t.size)
        if np.any(ks <= 0.0):
            raise ParameterError("stiffness has values <= 0: allowed k(t) > 0 N/m")
        h = _sampling(t, lambda i: f"t[{i}]")
        uniq, inv = np.unique(ks[:-1], return_inverse=True)
        phi, g0, g1 = _foh(np.full(uniq.size, osc.m), np.full(uniq.size, osc.c), uniq, h)
        z = np.empty((t.size, 2))
        z[0] = (x0, v0)
        with np.errstate(over="ignore", invalid="ignore"):
            for n in range(t.size - 1):
                j = inv[n]
                z[n + 1] = phi[j] @ z[n] + g0[j] * force[n] + g1[j] * force[n + 1]
            y = z[:, 0] if sensor == "x" else (force - osc.c * z[:, 1] - ks * z[:, 0]) / osc.m
    if noise > 0.0:
        y = y + noise * np.random.default_rng(seed).standard_normal(t.size)
    _finite_output(
        y,
        "the simulated record",
        f"the oscillator {osc} grows without bound, or the force, initial state or noise is too large: allowed a "
        "record that stays a finite float",
    )
    return Measurements(t, force, x=y) if sensor == "x" else Measurements(t, force, a=y)


# --------------------------------------------------------------------------- identification


@dataclass(frozen=True)
class Identification:
    """Least-squares estimate of the oscillator from one record, with its uncertainty."""

    m: float  # mass, kg
    c: float  # damping, N s/m
    k: float  # stiffness, N/m
    stderr: np.ndarray  # (3,) standard errors of m, c, k (kg, N s/m, N/m)
    ci95: np.ndarray  # (3, 2) 95 % confidence intervals of m, c, k
    cov: np.ndarray  # (3, 3) covariance of (m, c, k)
    x0: float  # initial displacement, m
    v0: float  # initial velocity, m/s
    sigma: float  # noise standard deviation estimated from the residual (m or m/s^2)
    n: int  # samples
    dt: float  # sampling step, s
    sensor: str  # "x" or "a"
    force_hold_error: float  # estimate of max |F - FOH(F)| / rms F, 1 (should be far below the noise)
    residual: np.ndarray = field(repr=False)  # measured minus model, m or m/s^2

    @property
    def oscillator(self) -> Oscillator:
        """The identified oscillator."""
        return Oscillator(self.m, self.c, self.k)

    @property
    def natural_frequency(self) -> float:
        """sqrt(k / m), rad/s."""
        return math.sqrt(self.k / self.m)

    @property
    def damping_ratio(self) -> float:
        """c / (2 sqrt(k m)), 1."""
        return self.c / (2.0 * math.sqrt(self.k * self.m))

    @property
    def dof(self) -> int:
        """Residual degrees of freedom, N - 5 (m, c, k and the initial state)."""
        return self.n - 5


def _varpro(force, y, h, sensor):
    """Variable projection on (ln omega_n, ln zeta): columns, linear solve, residual and batched grid cost."""
    n = force.size
    delta = np.zeros(n)
    delta[0] = 1.0
    yy = float(y @ y)
    lo_psi = (math.log(2.0 * np.pi / (h * n) / 100.0), math.log(1e-6))
    hi_psi = (math.log(4.0 * np.pi / h), math.log(100.0))

    def _columns(phi, g0, g1, wn, zeta):
        cc, kk = 2.0 * zeta * wn, wn * wn
        r = np.array([1.0, 0.0]) if sensor == "x" else np.array([-kk, -cc])
        feed = 0.0 if sensor == "x" else 1.0
        b, a, free_b = _filters(phi, g0, g1, r, feed)
        yi = signal.lfilter([1.0], a, delta)
        yi1 = np.concatenate([[0.0], yi[:-1]])
        basis = [free_b[j][0] * yi + free_b[j][1] * yi1 for j in range(2)]
        w0 = -g1 * force[0]
        forced = signal.lfilter(b, a, force) + w0[0] * basis[0] + w0[1] * basis[1]
        return np.column_stack([forced, basis[0], basis[1]])

    def columns(theta):
        wn, zeta = np.exp(theta)
        phi, g0, g1 = (v[0] for v in _foh(1.0, 2.0 * zeta * wn, wn * wn, h))
        return _columns(phi, g0, g1, wn, zeta)

    def solve(theta):
        g = columns(theta)
        scale = np.sqrt(np.sum(g * g, axis=0))
        scale[scale == 0.0] = 1.0
        gs = g / scale
        if not np.all(np.isfinite(gs)):
            return None, None
        coef, *_ = np.linalg.lstsq(gs, y, rcond=None)
        return coef / scale, g

    def residual(theta):
        if not (lo_psi[0] <= theta[0] <= hi_psi[0] and lo_psi[1] <= theta[1] <= hi_psi[1]):
            return np.full(n, 1e3 * math.sqrt(yy / n) + 1e-300)  # outside the physical box: a flat wall
        coef, g = solve(theta)
        if coef is None:
            return np.full(n, 1e10)
        return g @ coef - y

    def grid_cost(wns, zetas):
        """Residual sum of squares at each (omega_n, zeta) pair (normal equations, scaled columns)."""
        wns, zetas = np.asarray(wns, float), np.asarray(zetas, float)
        phi, g0, g1 = _foh(np.ones(wns.size), 2.0 * zetas * wns, wns * wns, h)
        out = np.empty(wns.size)
        for i in range(wns.size):
            g = _columns(phi[i], g0[i], g1[i], wns[i], zetas[i])
            scale = np.sqrt(np.sum(g * g, axis=0))
            if not np.all(np.isfinite(scale)) or np.any(scale == 0.0):
                out[i] = np.inf
                continue
            gs = g / scale
            gram, rhs = gs.T @ gs, gs.T @ y
            try:
                coef = np.linalg.solve(gram, rhs)
            except np.linalg.LinAlgError:
                out[i] = np.inf
                continue
            out[i] = yy - float(coef @ rhs)
        return out

    return columns, solve, residual, grid_cost


def _levy_start(force, y, h, sensor):
    """(omega_n, zeta) from a linear fit of 1/H on the Welch H1 estimate, or None."""
    try:
        frf = _frf(force, y, h, sensor)
    except (ValueError, ParameterError):
        return None
    w, hh, coh, pff = frf
    sel = (coh > 0.5) & (w > 0) & (pff >= 1e-2 * np.max(pff))
    if np.count_nonzero(sel) < 4:
        return None
    w, hh = w[sel], hh[sel]
    # minimise |H (k - m w^2 + i c w) - 1|^2: linear in (k, m, c)
    rows = np.concatenate(
        [
            np.column_stack([hh.real, -(w**2) * hh.real, -w * hh.imag]),
            np.column_stack([hh.imag, -(w**2) * hh.imag, w * hh.real]),
        ]
    )
    rhs = np.concatenate([np.ones(w.size), np.zeros(w.size)])
    try:
        (k, m, c), *_ = np.linalg.lstsq(rows, rhs, rcond=None)
    except np.linalg.LinAlgError:
        return None
    if not (k > 0 and m > 0 and c > 0):
        return None
    return math.sqrt(k / m), c / (2.0 * math.sqrt(k * m))


def _frf(force, y, h, sensor, nperseg=None):
    """Welch H1 receptance estimate: (omega rad/s, H m/N, coherence)."""
    n = force.size
    if nperseg is None:
        nperseg = int(min(n, max(64, n // 4)))
    f, pff = signal.welch(force, fs=1.0 / h, nperseg=nperseg, detrend="constant")
    _, pfy = signal.csd(force, y, fs=1.0 / h, nperseg=nperseg, detrend="constant")
    _, pyy = signal.welch(y, fs=1.0 / h, nperseg=nperseg, detrend="constant")
    w = 2.0 * np.pi * f
    with np.errstate(divide="ignore", invalid="ignore"):
        coh = np.abs(pfy) ** 2 / (pff * pyy)
        hh = pfy / pff
        if sensor == "a":
            hh = -hh / w**2
    ok = np.isfinite(hh) & (w > 0) & (pff > 1e-9 * np.max(pff))
    return w[ok], hh[ok], coh[ok], pff[ok]


def identify(t, force, x=None, a=None, *, search: str = "global") -> Identification:
    """Estimate m, c, k from a broadband test, with standard errors and 95 % confidence intervals.

    Output-error nonlinear least squares on the exact first-order-hold model
    (see the module docstring for the method and its assumptions: force
    measured without noise and band-limited below the Nyquist frequency, white
    Gaussian noise on the response, unknown initial state estimated too).

    Parameters
    ----------
    t : array_like
        Uniform, increasing sample times, s (at least ``MIN_SAMPLES``).
    force : array_like
        Measured force, N; it must vary (chirp, random or impulse test).
    x : array_like, optional
        Measured displacement, m.
    a : array_like, optional
        Measured acceleration, m/s^2 (give exactly one of ``x`` and ``a``).
    search : {"global", "local"}
        ``"global"``: a grid over the natural frequency (5 % steps from one
        period per record to 0.9 of the Nyquist frequency, two damping ratios)
        plus the frequency-domain (Levy) start, the best few polished.
        ``"local"``: the Levy start only (falls back to global if it fails);
        used by the Monte Carlo experiments for speed.

    Returns
    -------
    Identification
        ``m`` (kg), ``c`` (N s/m), ``k`` (N/m), ``stderr`` (3,), ``ci95`` (3, 2),
        the covariance, the initial state, the noise estimate and the residual.

    Raises
    ------
    ParameterError
        Bad input (as :func:`load_measurements`), or a record the method cannot
        use: natural frequency not resolved by the sampling or the record, or a
        force that does not separate m, c and k.

    Examples
    --------
    >>> t = np.arange(0.0, 40.0, 0.01)
    >>> meas = synthetic_measurements(Oscillator(2.0, 1.0, 50.0), t, random_force(t, (0.2, 3.0)),
    ...                               sensor="a", noise=0.05, seed=3)
    >>> fit = identify(meas.t, meas.force, a=meas.a)
    >>> [round(v, 1) for v in (fit.m, fit.c, fit.k)], fit.ci95.shape        # kg, N s/m, N/m
    ([2.0, 1.0, 50.0], (3, 2))
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    if not isinstance(search, str) or search not in ("global", "local"):
        raise ParameterError(f"search = {search!r}: allowed 'global' or 'local'")
    if search == "local":
        try:
            fit = _identify(t, h, force, y, sensor, local=True)
            if np.all(np.isfinite(fit.stderr)):
                return fit
        except ParameterError:
            pass
    return _identify(t, h, force, y, sensor, local=False)


def _identify(t, h, force, y, sensor, local: bool) -> Identification:
    n = t.size
    span = float(t[-1] - t[0])
    w_lo, w_hi = 2.0 * np.pi / span, 0.9 * np.pi / h
    if w_lo >= w_hi / 2:
        raise ParameterError(f"t spans {span:g} s with step {h:g} s: allowed a record of many samples")

    # global search on at most 20000 samples, then a polish on the whole record
    m_search = min(n, 20000)
    *_, grid_cost = _varpro(force[:m_search], y[:m_search], h, sensor)
    lo_s = max(w_lo, 2.0 * np.pi / (h * (m_search - 1)))
    grid_w = np.geomspace(lo_s, w_hi, int(np.ceil(np.log(w_hi / lo_s) / GRID_STEP)) + 1)
    starts = []
    levy = _levy_start(force, y, h, sensor)
    if local:
        if levy is None or not w_lo <= levy[0] <= w_hi:
            raise ParameterError("no frequency-domain start: allowed a global search")
        grid_w = grid_w[:0]
    for zeta in GRID_ZETAS if grid_w.size else ():
        costs = grid_cost(grid_w, np.full(grid_w.size, zeta))
        for i in np.argsort(costs)[:2]:
            starts.append((costs[i], (grid_w[i], zeta)))
    if levy is not None and w_lo <= levy[0] <= w_hi:
        levy = (levy[0], min(max(levy[1], 1e-4), 5.0))
        starts.append((float(grid_cost([levy[0]], [levy[1]])[0]), levy))
    starts.sort(key=lambda s: s[0])
    columns, solve, residual, _ = _varpro(force, y, h, sensor)
    best = None
    seen = []
    for _, (wv, zeta) in starts:
        th0 = np.log([wv, min(max(zeta, 1e-4), 5.0)])
        if any(np.all(np.abs(th0 - s) < [0.02, 0.3]) for s in seen):
            continue
        seen.append(th0)
        sol = least_squares(residual, th0, method="lm", x_scale=[0.01, 0.1], xtol=1e-10, ftol=1e-12, gtol=1e-12)
        if best is None or sol.cost < best.cost:
            best = sol
        if len(seen) >= 3:
            break
    psi = best.x
    wn, zeta = np.exp(psi)
    coef, g = solve(psi)
    if coef is None or not coef[0] > 0.0:
        raise ParameterError(
            "x or a does not fit the oscillator model (best fit has 1/m <= 0): allowed a response measured "
            "along the force (check sign and units) of an oscillator the sampling resolves"
        )
    if wn > 0.8 * np.pi / h:
        raise ParameterError(
            f"t: step {h:g} s does not resolve the estimated natural frequency {wn:.4g} rad/s: allowed "
            f"sampling at least 2.5 samples per period (step <= {0.8 * np.pi / wn:.3g} s)"
        )
    if wn < 2.0 * np.pi / span:
        raise ParameterError(
            f"t spans {span:g} s, less than one period of the estimated natural frequency {wn:.4g} rad/s: "
            f"allowed a record of several periods (> {2 * np.pi / wn:.3g} s)"
        )
    m = 1.0 / coef[0]
    c, k = 2.0 * zeta * wn * m, wn * wn * m
    # the forced column already holds the -gamma1 F[0] part of w[0], so the free coefficients are z[0]
    z0 = coef[1:]
    res = g @ coef - y

    # Gauss-Newton covariance of (ln omega_n, ln zeta, 1/m, x0, v0), mapped to (m, c, k) (delta method)
    jac = np.empty((n, 5))
    for j in range(2):
        step = 1e-6
        dp = np.zeros(2)
        dp[j] = step
        jac[:, j] = (columns(psi + dp) @ coef - columns(psi - dp) @ coef) / (2.0 * step)
    jac[:, 2:] = g
    dof = n - 5
    s2 = float(res @ res) / dof
    scale = np.sqrt(np.sum(jac * jac, axis=0))
    scale[scale == 0.0] = 1.0
    js = jac / scale
    _, sv, vt = np.linalg.svd(js, full_matrices=False)
    if sv[-1] <= 1e-10 * sv[0]:
        raise ParameterError(
            "force does not separate m, c and k (information matrix singular): allowed a broadband force "
            "exciting below, at and above the natural frequency (chirp or random)"
        )
    cov_full = (vt.T / sv**2) @ vt / np.outer(scale, scale) * s2
    d = np.array([[0.0, 0.0, -m * m, 0, 0], [c, c, -c * m, 0, 0], [2.0 * k, 0.0, -k * m, 0, 0]])
    cov = d @ cov_full @ d.T
    stderr = np.sqrt(np.diag(cov))
    q = float(student_t.ppf(0.975, dof))
    est = np.array([m, c, k])
    ci = np.column_stack([est - q * stderr, est + q * stderr])
    hold = float(np.max(np.abs(np.diff(force, 2))) / 8.0 / max(np.sqrt(np.mean(force**2)), 1e-300))
    return Identification(
        float(m),
        float(c),
        float(k),
        stderr,
        ci,
        cov,
        float(z0[0]),
        float(z0[1]),
        math.sqrt(s2),
        int(n),
        h,
        sensor,
        hold,
        -res,
    )


# --------------------------------------------------------------------------- frequency domain


@dataclass(frozen=True)
class FrequencyResponse:
    """Measured receptance (Welch H1 estimate): ``omega`` (rad/s), ``H`` (m/N, complex), ``coherence`` (1)."""

    omega: np.ndarray
    H: np.ndarray
    coherence: np.ndarray
    force_psd: np.ndarray  # one-sided PSD of the force, N^2/Hz


@dataclass(frozen=True)
class FrequencyEstimate:
    """m (kg), c (N s/m), k (N/m), omega_n (rad/s), zeta (1) from the measured FRF; nan and a reason if none."""

    method: str
    m: float
    c: float
    k: float
    omega_n: float
    zeta: float
    reason: str = ""


def frf_estimate(t, force, x=None, a=None, nperseg: int | None = None) -> FrequencyResponse:
    """Receptance estimate ``H1 = S_Fy / S_FF`` (Welch, Hann window, 50 % overlap).

    Parameters
    ----------
    t : array_like
        Uniform sample times, s.
    force : array_like
        Force, N.
    x, a : array_like, optional
        Displacement (m) or acceleration (m/s^2); acceleration is turned into
        receptance by dividing by ``-omega^2``.
    nperseg : int, optional
        Samples per segment (default a quarter of the record: seven averages).

    Examples
    --------
    >>> t = np.arange(0.0, 200.0, 0.02)
    >>> meas = synthetic_measurements(Oscillator(1.0, 0.5, 20.0), t, random_force(t))
    >>> frf = frf_estimate(**meas)
    >>> i = int(np.argmin(np.abs(frf.omega - 2.0)))
    >>> bool(abs(abs(frf.H[i]) * abs(20 - frf.omega[i] ** 2 + 0.5j * frf.omega[i]) - 1) < 0.02)
    True
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    if nperseg is not None:
        nperseg = check_int("nperseg", nperseg, low=16, high=t.size)
    return FrequencyResponse(*_frf(force, y, h, sensor, nperseg))


def _nan_estimate(method: str, reason: str) -> FrequencyEstimate:
    return FrequencyEstimate(method, math.nan, math.nan, math.nan, math.nan, math.nan, reason)


def frequency_estimates(frf: FrequencyResponse) -> tuple[FrequencyEstimate, FrequencyEstimate]:
    """Half-power and circle-fit estimates of m, c, k from a measured receptance.

    * **Half-power**: peak of ``|H|`` (parabolic interpolation of the bins), the
      exact half-power relation for zeta (as :func:`vibration.half_power_points`),
      ``k = 1 / (2 zeta sqrt(1 - zeta^2) |H|max)``, ``m = k / omega_n^2``.
    * **Circle fit**: the mobility ``i omega H = 1 / (c + i (m omega - k / omega))``
      of a viscous oscillator is a circle of diameter ``1/c`` through the origin;
      an algebraic circle fit on the bins above half the peak gives ``c``, and
      the angle ``theta`` of each point seen from the centre gives
      ``m omega^2 - k = -c omega tan(theta / 2)``, linear in ``m, k``.

    Only bins where the force is strong (PSD above 1 % of its peak) and the
    coherence above 0.5 are used. Both need a resolved resonance peak (zeta
    below about 0.3 and several bins inside the half-power band); otherwise the
    estimate is nan with a reason.

    Examples
    --------
    >>> t = np.arange(0.0, 400.0, 0.02)
    >>> meas = synthetic_measurements(Oscillator(1.0, 0.5, 20.0), t, random_force(t))
    >>> hp, cf = frequency_estimates(frf_estimate(**meas, nperseg=10000))
    >>> float(round(hp.k, 0)), float(round(cf.m, 1))                                  # N/m, kg
    (20.0, 1.0)
    """
    if not isinstance(frf, FrequencyResponse):
        raise ParameterError(f"frf = {frf!r:.60} is not a FrequencyResponse: allowed the output of frf_estimate")
    if frf.omega.size == 0:
        r = "no frequency bins"
        return _nan_estimate("half-power", r), _nan_estimate("circle fit", r)
    keep = (frf.force_psd >= 1e-2 * np.max(frf.force_psd)) & (frf.coherence > 0.5)
    first, last = np.nonzero(keep)[0][[0, -1]] if np.any(keep) else (0, -1)
    w, hh = frf.omega[first : last + 1], frf.H[first : last + 1]
    if w.size < 5:
        r = "fewer than 5 frequency bins with force and coherence"
        return _nan_estimate("half-power", r), _nan_estimate("circle fit", r)
    mag = np.abs(hh)
    i = int(np.argmax(mag))
    if i == 0 or i == w.size - 1:
        r = "no resonance peak inside the measured band"
        return _nan_estimate("half-power", r), _nan_estimate("circle fit", r)
    # parabolic interpolation of the peak
    y0, y1, y2 = mag[i - 1], mag[i], mag[i + 1]
    den = y0 - 2 * y1 + y2
    d = 0.5 * (y0 - y2) / den if den < 0 else 0.0
    w_pk = w[i] + d * (w[i + 1] - w[i - 1]) / 2.0
    h_pk = y1 - 0.25 * (y0 - y2) * d
    level = h_pk / math.sqrt(2.0)
    left = np.nonzero(mag[:i] < level)[0]
    right = np.nonzero(mag[i:] < level)[0]
    if left.size == 0 or right.size == 0 or (right[0] + (i - left[-1]) - 1) < 5:
        hp = _nan_estimate("half-power", "half-power band not resolved by the frequency bins")
    else:
        j = left[-1]
        lo = float(np.interp(level, [mag[j], mag[j + 1]], [w[j], w[j + 1]]))
        j = i + right[0]
        hi = float(np.interp(level, [mag[j], mag[j - 1]], [w[j], w[j - 1]]))
        ratio = (hi**2 - lo**2) / (hi**2 + lo**2)
        if ratio >= 1.0:
            hp = _nan_estimate("half-power", "damping too high for a half-power estimate")
        else:
            # 2 z sqrt(1 - z^2) / (1 - 2 z^2) = ratio  ->  z^2 = (1 - 1/sqrt(1 + ratio^2)) / 2
            zeta = math.sqrt(0.5 * (1.0 - 1.0 / math.sqrt(1.0 + ratio * ratio)))
            wn = w_pk / math.sqrt(1.0 - 2.0 * zeta**2)
            k = 1.0 / (2.0 * zeta * math.sqrt(1.0 - zeta**2) * h_pk)
            m = k / wn**2
            hp = FrequencyEstimate(
                "half-power", float(m), 2.0 * zeta * math.sqrt(k * m), float(k), float(wn), float(zeta)
            )
    lo_i, hi_i = i, i
    while lo_i - 1 >= 0 and mag[lo_i - 1] >= 0.5 * h_pk:
        lo_i -= 1
    while hi_i + 1 < w.size and mag[hi_i + 1] >= 0.5 * h_pk:
        hi_i += 1
    sel = slice(lo_i, hi_i + 1)
    if hi_i - lo_i + 1 < 5:
        return hp, _nan_estimate("circle fit", "fewer than 5 frequency bins near the resonance")
    yv = 1j * w[sel] * hh[sel]
    u, v = yv.real, yv.imag
    g = np.column_stack([u, v, np.ones_like(u)])
    (dd, ee, ff), *_ = np.linalg.lstsq(g, -(u * u + v * v), rcond=None)
    centre = complex(-dd / 2.0, -ee / 2.0)
    radius = math.sqrt(max(abs(centre) ** 2 - ff, 0.0))
    if radius == 0.0 or abs(centre) == 0.0:
        return hp, _nan_estimate("circle fit", "degenerate circle")
    c = 1.0 / (2.0 * radius)
    theta = np.angle((yv - centre) / centre)
    ws = w[sel]
    (m, k), *_ = np.linalg.lstsq(np.column_stack([ws**2, -np.ones_like(ws)]), -c * ws * np.tan(theta / 2.0), rcond=None)
    if not (m > 0 and k > 0):
        return hp, _nan_estimate("circle fit", "circle fit gave m or k <= 0")
    cf = FrequencyEstimate("circle fit", float(m), float(c), float(k), math.sqrt(k / m), c / (2 * math.sqrt(k * m)))
    return hp, cf


# --------------------------------------------------------------------------- tracking and detection


def _reference(reference, t, force, y, sensor, n_cal, name="reference"):
    """(Oscillator, Identification or None) of the healthy asset."""
    if reference is None:
        fit = identify(t[:n_cal], force[:n_cal], **{sensor: y[:n_cal]})
        return fit.oscillator, fit
    if isinstance(reference, Identification):
        return reference.oscillator, None
    if isinstance(reference, Oscillator):
        return reference, None
    try:
        m, c, k = (float(v) for v in reference)
    except (TypeError, ValueError):
        raise ParameterError(
            f"{name} = {reference!r:.60}: allowed None, an Identification, an Oscillator or (m kg, c N s/m, k N/m)"
        ) from None
    return Oscillator(m, c, k), None


def _calibration(calibration, n):
    calibration = check_real("calibration", calibration, low=0.0, high=0.9, low_open=True)
    n_cal = int(round(calibration * n))
    if n_cal < MIN_SAMPLES or n - n_cal < 2:
        raise ParameterError(
            f"calibration = {calibration!r} leaves {n_cal} calibration samples of {n}: allowed at least "
            f"{MIN_SAMPLES} calibration samples and some to monitor"
        )
    return n_cal


def _reference_output(osc, force, y, h, sensor, n_cal):
    """Output of the reference model with its initial state fitted on the first n_cal samples; and sigma^2."""
    phi, g0, g1 = (v[0] for v in _foh(osc.m, osc.c, osc.k, h))
    row = np.array([1.0, 0.0]) if sensor == "x" else np.array([-osc.k, -osc.c]) / osc.m
    feed = 0.0 if sensor == "x" else 1.0 / osc.m
    forced = _run(phi, g0, g1, row, feed, force, (0.0, 0.0))
    b1 = _run(phi, g0, g1, row, 0.0, np.zeros_like(force), (1.0, 0.0))
    b2 = _run(phi, g0, g1, row, 0.0, np.zeros_like(force), (0.0, 1.0))
    basis = np.column_stack([b1, b2])
    scale = np.sqrt(np.sum(basis[:n_cal] ** 2, axis=0))
    scale[scale == 0.0] = 1.0
    z0, *_ = np.linalg.lstsq(basis[:n_cal] / scale, (y - forced)[:n_cal], rcond=None)
    z0 = z0 / scale
    model = forced + basis @ z0
    r = y - model
    s2 = float(r[:n_cal] @ r[:n_cal]) / max(n_cal - 5, 1)
    return model, s2, z0


@dataclass(frozen=True)
class StiffnessTrack:
    """Online stiffness estimate: ``t`` (s), ``k`` (N/m) and its standard deviation ``k_std`` (N/m)."""

    t: np.ndarray
    k: np.ndarray
    k_std: np.ndarray
    reference: Oscillator  # m and c held at these values, k started here
    walk: float  # random-walk intensity of k, fraction of k per sqrt(s)
    sigma: float  # sensor noise standard deviation used, m or m/s^2


def track_stiffness(
    t, force, x=None, a=None, reference=None, *, walk: float = 0.02, calibration: float = CALIBRATION
) -> StiffnessTrack:
    """Track the stiffness online with an extended Kalman filter on the augmented state ``(x, v, k)``.

    Why a Kalman filter rather than recursive least squares with forgetting: the
    noise is on the measured response, not on a regressor, so an equation-error
    regression (``m x'' + c x' + k x = F``) would need derivatives (or integrals)
    of the noisy signal and be biased; the filter uses the exact model, works
    the same for displacement and acceleration, and gives a standard deviation
    of ``k`` at every sample. The random walk ``walk`` plays the role of the
    forgetting factor: larger follows faster and is noisier.

    Parameters
    ----------
    t, force, x, a : array_like
        As :func:`identify` (s, N, m or m/s^2).
    reference : Identification, Oscillator, (m, c, k) or None
        Healthy model; m (kg) and c (N s/m) are held, k (N/m) is tracked. None:
        identified on the first ``calibration`` fraction of the record.
    walk : float
        Random-walk intensity of k, fraction of the reference k per sqrt(s) (> 0).
    calibration : float
        Fraction of the record that estimates the noise (and the reference), 1.

    Examples
    --------
    >>> t = np.arange(0.0, 120.0, 0.02)
    >>> ks = stiffness_profile(t, 20.0, 1e9, 0.0, drop_time=60.0, drop=0.2)
    >>> meas = synthetic_measurements(Oscillator(1.0, 0.5, 20.0), t, random_force(t), noise=2e-3, stiffness=ks)
    >>> tr = track_stiffness(**meas, reference=(1.0, 0.5, 20.0))
    >>> round(float(tr.k[t < 60][-1])), round(float(tr.k[-1]))          # N/m
    (20, 16)
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    _work("t", f"{t.size} samples", t.size, MAX_TRACK_SAMPLES, "filter steps (one per sample)")
    walk = check_real("walk", walk, low=0.0, low_open=True, high=1e6, unit="1/sqrt(s)")
    n = t.size
    n_cal = _calibration(calibration, n)
    osc, _ = _reference(reference, t, force, y, sensor, n_cal)
    _, s2, z0 = _reference_output(osc, force, y, h, sensor, n_cal)
    m, c, k_ref = osc.m, osc.c, osc.k
    q = (walk * k_ref) ** 2 * h
    r_var = max(s2, 1e-30)
    # state (x, v, k) and the symmetric covariance as plain floats: 3 x 3 algebra written out
    x_, v_, k_ = float(z0[0]), float(z0[1]), k_ref
    p00, p01, p02 = 1e-6 * max(abs(x_), 1e-9) ** 2, 0.0, 0.0
    p11, p12, p22 = 1e-6 * max(abs(v_), 1e-9) ** 2, 0.0, (0.02 * k_ref) ** 2
    ks = np.empty(n)
    kstd = np.empty(n)
    fl, yl = force.tolist(), y.tolist()
    quantum = K_QUANTUM * k_ref
    cache: dict[int, tuple] = {}
    for i in range(n):
        # update with sample i
        if sensor == "x":
            h0, h1, h2, pred = 1.0, 0.0, 0.0, x_
        else:
            h0, h1, h2 = -k_ / m, -c / m, -x_ / m
            pred = (fl[i] - c * v_ - k_ * x_) / m
        ph0 = p00 * h0 + p01 * h1 + p02 * h2
        ph1 = p01 * h0 + p11 * h1 + p12 * h2
        ph2 = p02 * h0 + p12 * h1 + p22 * h2
        sv = h0 * ph0 + h1 * ph1 + h2 * ph2 + r_var
        innov = (yl[i] - pred) / sv
        x_, v_, k_ = x_ + ph0 * innov, v_ + ph1 * innov, max(k_ + ph2 * innov, 1e-6 * k_ref)
        p00, p01, p02 = p00 - ph0 * ph0 / sv, p01 - ph0 * ph1 / sv, p02 - ph0 * ph2 / sv
        p11, p12, p22 = p11 - ph1 * ph1 / sv, p12 - ph1 * ph2 / sv, p22 - ph2 * ph2 / sv
        ks[i], kstd[i] = k_, math.sqrt(max(p22, 0.0))
        if i == n - 1:
            break
        # predict to sample i + 1 with the exact FOH step at the current k (quantised to K_QUANTUM k_ref)
        key = int(round(k_ / quantum))
        mats = cache.get(key)
        if mats is None:
            phi, g0, g1 = (v[0] for v in _foh(m, c, key * quantum, h))
            mats = (*phi.ravel().tolist(), *g0.tolist(), *g1.tolist())
            cache[key] = mats
        f00, f01, f10, f11, a0, a1, b0, b1 = mats
        xn = f00 * x_ + f01 * v_ + a0 * fl[i] + b0 * fl[i + 1]
        vn = f10 * x_ + f11 * v_ + a1 * fl[i] + b1 * fl[i + 1]
        s0, s1 = -(a0 * x_ + b0 * xn), -(a1 * x_ + b1 * xn)  # d(x, v)[i+1] / dk, the -k x term held linear
        q00 = f00 * p00 + f01 * p01 + s0 * p02
        q01 = f00 * p01 + f01 * p11 + s0 * p12
        q02 = f00 * p02 + f01 * p12 + s0 * p22
        q10 = f10 * p00 + f11 * p01 + s1 * p02
        q11 = f10 * p01 + f11 * p11 + s1 * p12
        q12 = f10 * p02 + f11 * p12 + s1 * p22
        p00 = q00 * f00 + q01 * f01 + q02 * s0
        p01 = q00 * f10 + q01 * f11 + q02 * s1
        p11 = q10 * f10 + q11 * f11 + q12 * s1
        p02, p12, p22 = q02, q12, p22 + q
        x_, v_ = xn, vn
    return StiffnessTrack(t, ks, kstd, osc, walk, math.sqrt(r_var))


@dataclass(frozen=True)
class ChangeDetection:
    """CUSUM on the normalised squared residual of the reference model.

    ``alarm_time`` (s) is None when the statistic never crosses the threshold.
    """

    alarm_time: float | None  # first time the CUSUM exceeds the threshold, s
    alarm_index: int | None  # its sample index
    change_time: float | None  # estimated onset: the last restart of the CUSUM before the alarm, s
    t: np.ndarray = field(repr=False)  # time, s
    statistic: np.ndarray = field(repr=False)  # CUSUM g_n, 1 (0 on the calibration window)
    residual: np.ndarray = field(repr=False)  # measured minus reference model, m or m/s^2
    threshold: float = CUSUM_THRESHOLD  # alarm level of g, 1
    drift: float = CUSUM_DRIFT  # allowance subtracted from r^2/sigma^2 - 1, 1
    sigma: float = math.nan  # noise standard deviation from the calibration window, m or m/s^2
    reference: Oscillator | None = None  # healthy model
    calibration_end: float = math.nan  # end of the calibration window, s


def _cusum(z):
    s = np.cumsum(z)
    return s - np.minimum(np.minimum.accumulate(s), 0.0)


def detect_change(
    t,
    force,
    x=None,
    a=None,
    reference=None,
    *,
    threshold: float = CUSUM_THRESHOLD,
    drift: float = CUSUM_DRIFT,
    calibration: float = CALIBRATION,
) -> ChangeDetection:
    """Raise an alarm when the asset stops behaving like its reference model.

    Statistic: the output-error residual ``r = y - y_ref`` of the reference model
    driven by the measured force (its initial state and the noise variance
    ``sigma^2`` fitted on the first ``calibration`` fraction of the record, taken
    as healthy). Under no change ``r`` is white with variance ``sigma^2``; a change
    of m, c or k adds the response difference to it. The one-sided CUSUM
    ``g[n] = max(0, g[n-1] + r[n]^2 / sigma^2 - 1 - drift)`` starts at the end of
    the calibration window; the alarm is the first ``g > threshold``. ``drift = 1``
    reacts to a doubling of the residual power; the threshold sets the false
    alarm rate (about one per ``exp(threshold / 2)``-ish samples for white
    Gaussian noise; measured in the chapter).

    Parameters
    ----------
    t, force, x, a : array_like
        As :func:`identify` (s, N, m or m/s^2).
    reference : Identification, Oscillator, (m, c, k) or None
        Healthy model (kg, N s/m, N/m). None: identified on the calibration window.
    threshold : float
        Alarm level of the CUSUM, 1 (> 0).
    drift : float
        Allowance per sample, in units of the noise variance, 1 (> 0).
    calibration : float
        Fraction of the record taken as healthy, 1 (0 to 0.9).

    Returns
    -------
    ChangeDetection
        ``alarm_time`` (s, or None), the estimated onset ``change_time`` (s), the
        statistic, the residual and the settings.

    Examples
    --------
    >>> t = np.arange(0.0, 200.0, 0.02)
    >>> osc, f = Oscillator(1.0, 0.5, 20.0), random_force(t, seed=4)
    >>> ks = stiffness_profile(t, 20.0, 1e9, 0.0, drop_time=120.0, drop=0.05)
    >>> healthy = detect_change(**synthetic_measurements(osc, t, f, noise=2e-3, seed=5))
    >>> faulty = detect_change(**synthetic_measurements(osc, t, f, noise=2e-3, seed=5, stiffness=ks))
    >>> healthy.alarm_time is None, 120.0 < faulty.alarm_time < 125.0         # s
    (True, True)
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    threshold = check_real("threshold", threshold, low=0.0, low_open=True)
    drift = check_real("drift", drift, low=0.0, low_open=True)
    n = t.size
    n_cal = _calibration(calibration, n)
    osc, _ = _reference(reference, t, force, y, sensor, n_cal)
    model, s2, _ = _reference_output(osc, force, y, h, sensor, n_cal)
    r = y - model
    s2 = max(s2, 1e-300)
    g = np.zeros(n)
    g[n_cal:] = _cusum(r[n_cal:] ** 2 / s2 - 1.0 - drift)
    over = np.nonzero(g > threshold)[0]
    alarm = int(over[0]) if over.size else None
    onset = None
    if alarm is not None:
        zeros = np.nonzero(g[n_cal:alarm] == 0.0)[0]
        onset = float(t[n_cal + zeros[-1] + 1]) if zeros.size else float(t[n_cal])
    return ChangeDetection(
        float(t[alarm]) if alarm is not None else None,
        alarm,
        onset,
        t,
        g,
        r,
        threshold,
        drift,
        math.sqrt(s2),
        osc,
        float(t[n_cal]),
    )


# --------------------------------------------------------------------------- Monte Carlo experiments


@dataclass(frozen=True)
class CoverageExperiment:
    """Repeated identification of one oscillator from noisy records (seeded)."""

    truth: np.ndarray  # (3,) m (kg), c (N s/m), k (N/m)
    estimates: np.ndarray  # (R, 3)
    stderr: np.ndarray  # (R, 3)
    ci95: np.ndarray  # (R, 3, 2)
    noise: float  # noise standard deviation / rms of the noise-free response, 1
    duration: float  # record length, s
    dt: float  # sampling step, s
    sensor: str  # "x" or "a"

    @property
    def runs(self) -> int:
        return int(self.estimates.shape[0])

    @property
    def covered(self) -> np.ndarray:
        """(R, 3) whether each 95 % interval contains the truth."""
        return (self.ci95[:, :, 0] <= self.truth) & (self.truth <= self.ci95[:, :, 1])

    @property
    def coverage(self) -> np.ndarray:
        """(3,) fraction of the 95 % intervals that contain the truth."""
        return self.covered.mean(axis=0)

    @property
    def coverage_halfwidth(self) -> np.ndarray:
        """(3,) 95 % binomial half-width of the coverage for R runs at 0.95 (1.96 sqrt(0.95 * 0.05 / R))."""
        return np.full(3, 1.96 * math.sqrt(0.95 * 0.05 / self.runs))

    @property
    def rel_rmse(self) -> np.ndarray:
        """(3,) root-mean-square relative error of m, c, k, 1."""
        return np.sqrt(np.mean(((self.estimates - self.truth) / self.truth) ** 2, axis=0))

    @property
    def rel_bias(self) -> np.ndarray:
        """(3,) mean relative error of m, c, k, 1."""
        return np.mean((self.estimates - self.truth) / self.truth, axis=0)

    @property
    def rel_stderr(self) -> np.ndarray:
        """(3,) root-mean-square of the reported relative standard errors, 1."""
        return np.sqrt(np.mean((self.stderr / self.truth) ** 2, axis=0))


def identification_experiment(
    osc: Oscillator,
    *,
    duration: float = 60.0,
    dt: float = 0.02,
    noise: float = 0.05,
    runs: int = 200,
    seed: int = 0,
    sensor: str = "x",
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
) -> CoverageExperiment:
    """Identify ``osc`` from ``runs`` records that differ only in their noise (seeded).

    One band-limited random force (seed ``seed``) drives the oscillator from
    rest; every run adds fresh white Gaussian noise (seeds ``seed + 1 + i``) of
    standard deviation ``noise`` times the rms of the noise-free response, and
    :func:`identify` (``search="local"``) estimates m, c, k and their intervals.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    duration : float
        Record length, s.
    dt : float
        Sampling step, s.
    noise : float
        Noise standard deviation relative to the rms response, 1 (> 0).
    runs : int
        Realisations (2 to 10000).
    seed : int
        Seed of the force; the noise seeds follow it.
    sensor : {"x", "a"}
        Displacement or acceleration.
    band : (float, float)
        Force band, Hz.
    rms : float
        Force rms, N.

    Examples
    --------
    >>> ex = identification_experiment(Oscillator(1.0, 0.5, 20.0), duration=20.0, runs=20)
    >>> ex.estimates.shape, bool(np.all(ex.coverage >= 0.8))
    ((20, 3), True)
    """
    _check_osc(osc)
    duration = check_real("duration", duration, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, high=duration / MIN_SAMPLES, unit="s")
    noise = check_real("noise", noise, low=0.0, low_open=True, high=10.0)
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    sensor = _check_sensor(sensor)
    n = _grid_size(duration, dt)
    _work("runs", runs, runs * n, MAX_EXPERIMENT_SAMPLES, f"samples to identify ({runs} runs x {n} samples)")
    t = np.arange(n) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    clean = synthetic_measurements(osc, t, force, sensor=sensor)
    sd = noise * float(np.sqrt(np.mean(clean.response**2)))
    est = np.empty((runs, 3))
    se = np.empty((runs, 3))
    ci = np.empty((runs, 3, 2))
    for i in range(runs):
        y = clean.response + sd * np.random.default_rng(seed + 1 + i).standard_normal(t.size)
        fit = identify(t, force, **{sensor: y}, search="local")
        est[i] = (fit.m, fit.c, fit.k)
        se[i] = fit.stderr
        ci[i] = fit.ci95
    truth = np.array([osc.m, osc.c, osc.k])
    return CoverageExperiment(truth, est, se, ci, noise, float(t[-1]), dt, sensor)


@dataclass(frozen=True)
class DetectionExperiment:
    """Seeded healthy and faulty records run through :func:`detect_change`, for many thresholds."""

    thresholds: np.ndarray  # (T,) CUSUM thresholds, 1
    change_time: float  # time the fault starts, s
    monitored: float  # monitored time per record (after calibration), s
    healthy_peak: np.ndarray = field(repr=False)  # (R,) max of the CUSUM over each healthy record
    first_crossing: np.ndarray = field(repr=False)  # (R, T) alarm time of each faulty record (nan: none), s
    drift: float = CUSUM_DRIFT

    @property
    def runs(self) -> int:
        return int(self.healthy_peak.size)

    @property
    def false_alarm_probability(self) -> np.ndarray:
        """(T,) fraction of healthy records that raise an alarm, plus faulty records alarmed before the fault."""
        early = np.nan_to_num(self.first_crossing, nan=np.inf) < self.change_time
        healthy = self.healthy_peak[:, None] > self.thresholds[None, :]
        return (healthy.sum(axis=0) + early.sum(axis=0)) / (2.0 * self.runs)

    @property
    def false_alarm_rate(self) -> np.ndarray:
        """(T,) alarms per hour of healthy monitoring (healthy records only), 1/h."""
        alarms = (self.healthy_peak[:, None] > self.thresholds[None, :]).sum(axis=0)
        return alarms / (self.runs * self.monitored / 3600.0)

    @property
    def detection_probability(self) -> np.ndarray:
        """(T,) fraction of faulty records alarmed at or after the fault start."""
        late = np.nan_to_num(self.first_crossing, nan=-np.inf) >= self.change_time
        return late.mean(axis=0)

    @property
    def mean_delay(self) -> np.ndarray:
        """(T,) mean of alarm time minus fault start over the detected faulty records, s (nan: none)."""
        d = self.first_crossing - self.change_time
        d = np.where(d >= 0.0, d, np.nan)
        with np.errstate(invalid="ignore"):
            cnt = np.sum(np.isfinite(d), axis=0)
            return np.where(cnt > 0, np.nansum(d, axis=0) / np.maximum(cnt, 1), np.nan)


def detection_experiment(
    osc: Oscillator,
    t,
    force,
    stiffness,
    change_time: float,
    *,
    noise: float,
    runs: int = 200,
    seed: int = 0,
    thresholds=(10.0, 20.0, 40.0, 80.0),
    drift: float = CUSUM_DRIFT,
    calibration: float = CALIBRATION,
    sensor: str = "x",
    reference=None,
) -> DetectionExperiment:
    """Run :func:`detect_change` on ``runs`` healthy and ``runs`` faulty records (same force, fresh noise).

    Parameters
    ----------
    osc : Oscillator
        Healthy oscillator: m (kg), c (N s/m), k (N/m).
    t, force : array_like
        Sample times (s) and force (N) shared by every record.
    stiffness : array_like
        Stiffness history of the faulty records, N/m (see :func:`stiffness_profile`).
    change_time : float
        When the fault starts, s (after the calibration window).
    noise : float
        Sensor noise standard deviation, m or m/s^2.
    runs : int
        Records of each kind (2 to 10000).
    seed : int
        First noise seed (healthy ``seed + i``, faulty ``seed + runs + i``).
    thresholds : array_like
        CUSUM thresholds to evaluate, 1.
    drift, calibration : float
        As :func:`detect_change`.
    sensor : {"x", "a"}
        Displacement or acceleration.
    reference : optional
        As :func:`detect_change` (None: identified on each record's calibration window).

    Examples
    --------
    >>> t = np.arange(0.0, 120.0, 0.02)
    >>> osc, f = Oscillator(1.0, 0.5, 20.0), random_force(t)
    >>> ks = stiffness_profile(t, 20.0, 1e9, 0.0, drop_time=60.0, drop=0.05)
    >>> ex = detection_experiment(osc, t, f, ks, 60.0, noise=2e-3, runs=5, reference=osc, thresholds=[40, 80])
    >>> ex.detection_probability.tolist(), ex.false_alarm_probability.tolist()
    ([1.0, 1.0], [0.0, 0.0])
    """
    _check_osc(osc)
    t = _signal("t", t)
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    sensor = _check_sensor(sensor)
    _work(
        "runs",
        runs,
        2 * runs * t.size,
        MAX_EXPERIMENT_SAMPLES,
        f"samples to monitor (2 x {runs} runs x {t.size} samples)",
    )
    change_time = check_real("change_time", change_time, low=float(t[0]), high=float(t[-1]), unit="s")
    thr = _signal("thresholds", thresholds) if np.ndim(thresholds) == 1 else None
    if thr is None or np.any(thr <= 0.0):
        raise ParameterError(f"thresholds = {thresholds!r}: allowed a 1-D array of positive numbers")
    noise = check_real("noise", noise, low=0.0, low_open=True)
    stiffness = _signal("stiffness", stiffness, t.size)
    healthy = synthetic_measurements(osc, t, force, sensor=sensor)
    faulty = synthetic_measurements(osc, t, force, sensor=sensor, stiffness=stiffness)
    peaks = np.empty(runs)
    first = np.full((runs, thr.size), np.nan)
    monitored = math.nan
    for i in range(runs):
        for kind, clean, sd in ((0, healthy, seed + i), (1, faulty, seed + runs + i)):
            y = clean.response + noise * np.random.default_rng(sd).standard_normal(t.size)
            det = detect_change(
                t,
                force,
                **{sensor: y},
                reference=reference,
                threshold=float(np.max(thr)),
                drift=drift,
                calibration=calibration,
            )
            monitored = float(t[-1] - det.calibration_end)
            g = det.statistic
            if kind == 0:
                peaks[i] = float(np.max(g))
            else:
                run_max = np.maximum.accumulate(g)
                idx = np.searchsorted(run_max, thr, side="right")
                ok = idx < t.size
                first[i, ok] = t[idx[ok]]
    return DetectionExperiment(thr, change_time, monitored, peaks, first, drift)


def identification_sweep(
    osc: Oscillator,
    *,
    noises=(0.01, 0.03, 0.1, 0.3),
    durations=(15.0, 30.0, 60.0, 120.0),
    noise: float = 0.05,
    duration: float = 60.0,
    runs: int = 40,
    seed: int = 0,
    **kwargs,
) -> tuple[list[CoverageExperiment], list[CoverageExperiment]]:
    """Error scaling: :func:`identification_experiment` over noise levels (at ``duration``) and record lengths
    (at ``noise``).

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    noises : sequence of float
        Noise standard deviations relative to the rms response, 1.
    durations : sequence of float
        Record lengths, s.
    noise, duration : float
        The value held fixed in the other sweep (1, s).
    runs, seed : int
        Realisations per point and the first seed.
    **kwargs
        Passed to :func:`identification_experiment` (``dt``, ``sensor``, ``band``, ``rms``).

    Examples
    --------
    >>> by_noise, by_length = identification_sweep(Oscillator(1.0, 0.5, 20.0), noises=(0.01, 0.1),
    ...                                            durations=(20.0, 40.0), runs=5)
    >>> float(by_noise[1].rel_rmse[2] / by_noise[0].rel_rmse[2]) > 5      # error grows with the noise
    True
    """
    noises, durations = _signal("noises", noises), _signal("durations", durations)
    runs = check_int("runs", runs, low=2, high=10_000)
    dt = check_real("dt", kwargs.get("dt", 0.02), low=0.0, low_open=True, unit="s")
    total = runs * (noises.size * (duration / dt + 1) + float(np.sum(durations / dt + 1)))
    _work("runs", runs, total, MAX_EXPERIMENT_SAMPLES, "samples to identify over both sweeps")
    by_noise = [
        identification_experiment(osc, duration=duration, noise=s, runs=runs, seed=seed, **kwargs) for s in noises
    ]
    by_length = [
        identification_experiment(osc, duration=d, noise=noise, runs=runs, seed=seed, **kwargs) for d in durations
    ]
    return by_noise, by_length


@dataclass(frozen=True)
class EstimateGrid:
    """One seeded identification per (noise, record length): what the slider panels show."""

    truth: np.ndarray  # (3,) m (kg), c (N s/m), k (N/m)
    noises: np.ndarray  # (I,) noise / rms response, 1
    durations: np.ndarray  # (J,) record lengths, s
    estimates: np.ndarray  # (I, J, 3)
    ci95: np.ndarray  # (I, J, 3, 2)


def estimate_grid(
    osc: Oscillator,
    noises=(0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5),
    durations=(10.0, 20.0, 40.0, 80.0, 160.0),
    *,
    dt: float = 0.02,
    seed: int = 0,
    sensor: str = "x",
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
) -> EstimateGrid:
    """Identify one record per (noise, record length); the records share the force and the noise draw.

    The longest record is simulated once (force seed ``seed``, standard normal
    noise draw seed ``seed + 1``); shorter records are its first samples and each
    noise level scales the same draw, so moving one slider changes one thing.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    noises : sequence of float
        Noise standard deviation / rms of the noise-free response, 1.
    durations : sequence of float
        Record lengths, s.
    dt : float
        Sampling step, s.
    seed : int
        Seed of the force; the noise draw uses ``seed + 1``.
    sensor, band, rms
        As :func:`identification_experiment`.

    Examples
    --------
    >>> g = estimate_grid(Oscillator(1.0, 0.5, 20.0), noises=(0.01, 0.1), durations=(20.0, 40.0))
    >>> g.estimates.shape, g.ci95.shape
    ((2, 2, 3), (2, 2, 3, 2))
    """
    _check_osc(osc)
    noises = _signal("noises", noises)
    durations = _signal("durations", durations)
    if np.any(noises <= 0) or np.any(durations <= 0) or np.any(noises > 10.0):
        raise ParameterError(
            f"noises = {noises!r:.60} and durations = {durations!r:.60}: allowed 0 < noise <= 10 and durations > 0 s"
        )
    dt = check_real("dt", dt, low=0.0, low_open=True, unit="s")
    seed = _check_seed(seed)
    sensor = _check_sensor(sensor)
    n_max = _grid_size(float(np.max(durations)), dt, "durations")
    total = noises.size * float(np.sum(np.round(durations / dt) + 1))
    _work("noises x durations", (noises.size, durations.size), total, MAX_EXPERIMENT_SAMPLES, "samples to identify")
    t = np.arange(n_max) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    clean = synthetic_measurements(osc, t, force, sensor=sensor).response
    draw = np.random.default_rng(seed + 1).standard_normal(t.size)
    est = np.empty((noises.size, durations.size, 3))
    ci = np.empty((noises.size, durations.size, 3, 2))
    for j, d in enumerate(durations):
        n = int(round(d / dt)) + 1
        rms_y = float(np.sqrt(np.mean(clean[:n] ** 2)))
        for i, s in enumerate(noises):
            fit = identify(t[:n], force[:n], **{sensor: clean[:n] + s * rms_y * draw[:n]}, search="local")
            est[i, j] = (fit.m, fit.c, fit.k)
            ci[i, j] = fit.ci95
    return EstimateGrid(np.array([osc.m, osc.c, osc.k]), noises, durations, est, ci)


# --------------------------------------------------------------------------- chapter scenarios

#: CUSUM thresholds the chapter's trade-off curves run through, 1.
THRESHOLDS = tuple(float(v) for v in np.geomspace(4.0, 400.0, 15))


def simulated_test(
    osc: Oscillator,
    duration: float,
    dt: float,
    noise: float,
    *,
    seed: int = 0,
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
    sensor: str = "x",
    stiffness=None,
) -> Measurements:
    """A broadband test record from rest with noise given relative to the rms noise-free response.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    duration, dt : float
        Record length and sampling step, s.
    noise : float
        Noise standard deviation / rms of the noise-free response, 1 (>= 0).
    seed : int
        Force seed; the noise uses ``seed + 1``.
    band, rms, sensor, stiffness
        As :func:`random_force` and :func:`synthetic_measurements` (Hz, N, -, N/m).

    Examples
    --------
    >>> rec = simulated_test(Oscillator(1.0, 0.5, 20.0), 10.0, 0.02, 0.1)
    >>> len(rec), rec.sensor
    (501, 'x')
    """
    _check_osc(osc)
    duration = check_real("duration", duration, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, high=duration / MIN_SAMPLES, unit="s")
    noise = check_real("noise", noise, low=0.0, high=10.0)
    seed = _check_seed(seed)
    sensor = _check_sensor(sensor)
    t = np.arange(_grid_size(duration, dt)) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    clean = synthetic_measurements(osc, t, force, sensor=sensor, stiffness=stiffness).response
    y = clean + noise * float(np.sqrt(np.mean(clean**2))) * np.random.default_rng(seed + 1).standard_normal(t.size)
    return Measurements(t, force, x=y) if sensor == "x" else Measurements(t, force, a=y)


@dataclass(frozen=True)
class FaultScenario:
    """The monitored record's stiffness history: decline from ``decline_start``, drop at ``drop_time``."""

    t: np.ndarray  # s
    k: np.ndarray  # true stiffness, N/m
    decline_start: float  # s
    drop_time: float  # s


def fault_scenario(k: float, t_monitor: float, dt: float, decline_rate: float, drop: float) -> FaultScenario:
    """Healthy for the first 40 % of the window, then a slow decline, and a sudden drop at 70 %.

    Parameters
    ----------
    k : float
        Healthy stiffness, N/m.
    t_monitor, dt : float
        Window length and sampling step, s.
    decline_rate : float
        Fraction of k lost per second during the decline, 1/s.
    drop : float
        Fraction of k lost at the drop, 1.

    Examples
    --------
    >>> sc = fault_scenario(20.0, 100.0, 0.5, 0.001, 0.1)
    >>> sc.decline_start, sc.drop_time, round(float(sc.k[-1]), 3)
    (40.0, 70.0, 16.92)
    """
    t_monitor = check_real("t_monitor", t_monitor, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, high=t_monitor / MIN_SAMPLES, unit="s")
    t = np.arange(_grid_size(t_monitor, dt, "t_monitor")) * dt
    start, when = 0.4 * t_monitor, 0.7 * t_monitor
    return FaultScenario(t, stiffness_profile(t, k, start, decline_rate, drop_time=when, drop=drop), start, when)


def detection_study(
    osc: Oscillator,
    reference,
    t_monitor: float,
    dt: float,
    noise: float,
    decline_rate: float,
    drop: float,
    *,
    runs: int = 100,
    seed: int = 0,
    thresholds=THRESHOLDS,
) -> dict[str, DetectionExperiment]:
    """Two seeded detection experiments on ``t_monitor``-long records: a sudden drop alone and a slow decline alone.

    Both faults start at 40 % of the window (after the 25 % calibration). The noise is
    ``noise`` times the rms of the healthy noise-free response (1); the force is a fresh
    band-limited random force (seed ``seed``).

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> st = detection_study(osc, osc, 100.0, 0.02, 0.01, 0.001, 0.05, runs=3, thresholds=(40.0,))
    >>> sorted(st), [float(e.detection_probability[0]) for e in st.values()]
    (['slow decline', 'sudden drop'], [1.0, 1.0])
    """
    _check_osc(osc)
    t_monitor = check_real("t_monitor", t_monitor, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, high=t_monitor / MIN_SAMPLES, unit="s")
    noise = check_real("noise", noise, low=0.0, low_open=True, high=10.0)
    decline_rate = check_real("decline_rate", decline_rate, low=0.0, unit="1/s")
    drop = check_real("drop", drop, low=0.0, high=0.9)
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    n = _grid_size(t_monitor, dt, "t_monitor")
    _work("runs", runs, 4 * runs * n, MAX_EXPERIMENT_SAMPLES, f"samples to monitor (2 faults x 2 x {runs} runs x {n})")
    t = np.arange(n) * dt
    start = 0.4 * t_monitor
    force = random_force(t, seed=seed)
    clean = synthetic_measurements(osc, t, force).x
    sd = noise * float(np.sqrt(np.mean(clean**2)))
    profiles = {
        "sudden drop": stiffness_profile(t, osc.k, start, 0.0, drop_time=start, drop=drop),
        "slow decline": stiffness_profile(t, osc.k, start, decline_rate),
    }
    return {
        label: detection_experiment(
            osc,
            t,
            force,
            ks,
            start,
            noise=sd,
            runs=runs,
            seed=seed + 1 + 7919 * j,
            thresholds=thresholds,
            reference=reference,
        )
        for j, (label, ks) in enumerate(profiles.items())
    }


def discretisation_checks(osc: Oscillator, F0: float, omega: float, t_end: float, n: int) -> dict:
    """Differences of :func:`sampled_response` from three independent references, with their bounds.

    Returns ``{name: (difference, bound)}`` (both in m):

    * the closed form :func:`vibration.exact_response` for ``F0 sin(omega t)`` on ``n``
      samples: the FOH interpolation error, bounded by ``h^2 omega^2 F0 / 8`` times the
      integral of ``|impulse response|`` (itself bounded by ``2 / (c omega_d)``, or
      ``t_end / m`` for the undamped case),
    * ``scipy.signal.cont2discrete(method="foh")`` with ``dlsim``: rounding level,
    * ``solve_ivp`` (DOP853, rtol 1e-12) sample by sample with the force held linear:
      integrator tolerance level (on the first 200 samples).

    Examples
    --------
    >>> ch = discretisation_checks(Oscillator(1.0, 0.5, 20.0), 5.0, 4.47, 50.0, 5001)
    >>> all(v < b for v, b in ch.values())
    True
    """
    from scipy.integrate import solve_ivp

    from .exact import exact_response
    from .model import SineForce

    _check_osc(osc)
    F0 = check_real("F0", F0, low=0.0, high=MAX_ABS, unit="N")
    omega = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n = check_int("n", n, low=2, high=N_POINTS_MAX)
    t = np.linspace(0.0, t_end, n)
    h = float(t[1] - t[0])
    # the solve_ivp reference: DOP853 (12 evaluations a step) needs h lambda within its stability interval
    # (about 6) and, at rtol 1e-12, steps of at most about a tenth of the fastest period
    wn = osc.natural_frequency
    lam = max(abs(osc.c) / osc.m, wn, omega)
    m_ = min(200, n)
    need = 12.0 * (m_ - 1) * max(h * lam / 6.0, 1.0)
    if not need <= MAX_RHS_EVALUATIONS:
        raise ParameterError(
            f"n = {n} samples over t_end = {t_end!r} s (step {h:.3g} s) with the fastest rate {lam:.3g} 1/s "
            f"(|c|/m = {abs(osc.c) / osc.m:.3g} 1/s, omega_n = {wn:.3g} rad/s, omega = {omega:.3g} rad/s) need at "
            f"least {need:.3g} right-hand-side evaluations for the solve_ivp reference: allowed at most "
            f"{MAX_RHS_EVALUATIONS} (more samples n, a shorter t_end or a less stiff oscillator)"
        )
    budget = _Counted(None, MAX_RHS_EVALUATIONS)
    force = SineForce(F0, omega)
    f = force(t)
    ours = sampled_response(osc, t, f)
    exact = exact_response(osc, force, t)
    wd = osc.damped_natural_frequency
    integral = 2.0 / (osc.c * wd) if osc.c > 0 and wd > 0 else t_end / osc.m * max(t_end, 1.0)
    if osc.c > 0 and wd == 0.0:
        integral = 1.0 / osc.k * 4.0
    bound_sine = h * h * omega * omega * F0 / 8.0 * integral
    a = np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]])
    b = np.array([[0.0], [1.0 / osc.m]])
    ad, bd, cd, dd, _ = signal.cont2discrete((a, b, np.eye(2), np.zeros((2, 1))), h, method="foh")
    with np.errstate(over="ignore", invalid="ignore"):
        _, yd, _ = signal.dlsim((ad, bd, cd, dd, h), f, x0=-dd[:, 0] * f[0])
    _finite_output(yd, "the cont2discrete + dlsim reference", "allowed a response that stays a finite float")
    scale = max(float(np.max(np.abs(ours.x))), 1e-300)
    z = np.zeros(2)
    ref = [0.0]
    for i in range(m_ - 1):
        slope = (f[i + 1] - f[i]) / h
        budget.fun = lambda s, y, i=i, slope=slope: [y[1], (f[i] + slope * s - osc.c * y[1] - osc.k * y[0]) / osc.m]
        try:
            sol = solve_ivp(budget, (0.0, h), z, method="DOP853", rtol=1e-12, atol=1e-14 * scale)
        except _OverBudget:
            raise ParameterError(
                f"discretisation_checks spent its budget of {MAX_RHS_EVALUATIONS} right-hand-side evaluations on the "
                f"solve_ivp reference at sample {i} of {m_} (step {h:.3g} s, |c|/m = {abs(osc.c) / osc.m:.3g} 1/s, "
                f"omega_n = {wn:.3g} rad/s): allowed more samples n, a shorter t_end or a less stiff oscillator"
            ) from None
        z = sol.y[:, -1]
        ref.append(z[0])
    out = {
        "sine: closed form (interpolation error of the force)": (
            float(np.max(np.abs(ours.x - exact.x))),
            bound_sine,
        ),
        "scipy cont2discrete FOH + dlsim (relative to max |x|)": (
            float(np.max(np.abs(ours.x - yd[:, 0]))) / scale,
            1e-10,
        ),
        "solve_ivp, force linear between samples (relative)": (
            float(np.max(np.abs(ours.x[:m_] - np.array(ref)))) / scale,
            1e-8,
        ),
    }
    _finite_output(
        list(out.values()), "a difference or bound", "allowed an oscillator and force whose responses stay finite"
    )
    return out
