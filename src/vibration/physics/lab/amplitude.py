r"""Damping as a function of amplitude, from the extrema of free decays, and the brake at matched amplitude.

Conventions, for successive extrema :math:`e_k` of a free decay (after the release):
the half-period amplitude :math:`X_k = |e_k - e_{k+1}|/2` (rad, independent of the resting angle),
the loss per half period :math:`X_k - X_{k+1}` and the equivalent viscous damping ratio
:math:`\zeta_{eq,k} = \delta_k/\sqrt{\pi^2 + \delta_k^2}` with :math:`\delta_k = \ln(X_k/X_{k+1})`.
Viscous damping gives a constant :math:`\zeta_{eq}`, Coulomb friction a constant loss
:math:`2\theta_f` (so :math:`\zeta_{eq} \approx 2\theta_f/(\pi X)`), a quadratic term a loss growing as
:math:`X^2`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize

from vibration.physics.lab._checks import time_and_signal
from vibration.physics.lab.logger import LoggerRun
from vibration.physics.lab.peaks import _peaks, _start
from vibration.physics.model import ParameterError, check_real

#: Bootstrap resamples of :func:`compare_damping`, and its fixed seed.
N_BOOTSTRAP = 2000
SEED = 20241210
#: Fewest runs per side for the bootstrap over runs (else over half periods).
MIN_RUNS_BOOTSTRAP = 3
#: Largest number of runs per side.
MAX_RUNS = 10_000


@dataclass(frozen=True, kw_only=True, eq=False)
class DampingCurve:
    """Loss per half period and equivalent damping ratio against the half-period amplitude.

    Attributes
    ----------
    amplitude : numpy.ndarray
        X_k (rad).
    zeta_eq : numpy.ndarray
        Equivalent viscous damping ratio of each half period.
    loss : numpy.ndarray
        X_k - X_{k+1} (rad).
    t : numpy.ndarray
        Time of the extremum e_k (s).
    """

    amplitude: np.ndarray
    zeta_eq: np.ndarray
    loss: np.ndarray
    t: np.ndarray

    @property
    def n(self) -> int:
        """Number of half periods."""
        return int(self.amplitude.size)


def _ro(a) -> np.ndarray:
    out = np.asarray(a, dtype=float).copy()
    out.flags.writeable = False
    return out


def _curve(ta: np.ndarray, ya: np.ndarray) -> DampingCurve:
    peaks = _peaks(ta, ya)
    k0 = _start(ta, ya, peaks)
    e = peaks.theta[k0:]
    te = peaks.t[k0:]
    if e.size < 3:
        return DampingCurve(amplitude=_ro([]), zeta_eq=_ro([]), loss=_ro([]), t=_ro([]))
    x = np.abs(np.diff(e)) / 2.0
    xa, xb = x[:-1], x[1:]
    keep = (xa > 0) & (xb > 0)
    delta = np.log(xa[keep] / xb[keep])
    z = delta / np.sqrt(math.pi**2 + delta**2)
    return DampingCurve(amplitude=_ro(xa[keep]), zeta_eq=_ro(z), loss=_ro(xa[keep] - xb[keep]), t=_ro(te[:-2][keep]))


def damping_vs_amplitude(t, theta) -> DampingCurve:
    r"""Loss per half period and equivalent damping ratio of a free decay against its amplitude.

    The extrema after the largest excursion are those of
    :func:`~vibration.physics.lab.peaks.free_decay_peaks` (refined by a local parabola); the
    conventions are those of the module.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing.
    theta : array_like
        Angles (rad), same length.

    Returns
    -------
    DampingCurve
        ``amplitude`` (rad), ``zeta_eq``, ``loss`` (rad) and ``t`` (s), of equal length (one per half
        period that has a next one; possibly empty).

    Examples
    --------
    >>> import numpy as np
    >>> from vibration.physics.lab.decay import free_decay_response
    >>> t = np.arange(0.0, 8.0, 0.01)
    >>> c = damping_vs_amplitude(t, free_decay_response(t, 4.5, 0.0, friction=0.05, theta0=2.0))
    >>> bool(np.allclose(c.loss, 0.1, atol=2e-3))  # Coulomb: 2 Delta per half period
    True
    """
    ta, ya = time_and_signal(t, theta, t_name="t", y_name="theta", y_unit="rad")
    return _curve(ta, ya)


@dataclass(frozen=True, kw_only=True)
class DampingDifference:
    """Difference of the mean equivalent damping ratio of two sets of runs inside an amplitude band.

    Attributes
    ----------
    delta_zeta : float
        Mean over runs of b minus that of a (per run: the mean zeta_eq of its half periods in the band).
    stderr : float
        Bootstrap standard error.
    ci_low, ci_high : float
        95 % percentile interval of the bootstrap.
    method : str
        "bootstrap over runs" or "bootstrap over half periods" (a side with fewer than 3 runs).
    band : tuple of float
        The amplitude band (rad).
    n_a, n_b : int
        Runs with at least one half period in the band.
    zeta_a, zeta_b : float
        The two means.
    """

    delta_zeta: float
    stderr: float
    ci_low: float
    ci_high: float
    method: str
    band: tuple
    n_a: int
    n_b: int
    zeta_a: float
    zeta_b: float

    @property
    def resolved(self) -> bool:
        """Whether the 95 % interval excludes 0."""
        return self.ci_low > 0.0 or self.ci_high < 0.0


def _as_runs(name: str, runs) -> list[tuple[np.ndarray, np.ndarray]]:
    if isinstance(runs, (str, bytes)) or not hasattr(runs, "__iter__"):
        raise ParameterError(f"{name} = {runs!r:.80} is not a sequence of runs: allowed (t, theta) pairs or LoggerRun")
    out = []
    for i, r in enumerate(runs):
        if i >= MAX_RUNS:
            raise ParameterError(f"{name} has more than {MAX_RUNS} runs: allowed at most {MAX_RUNS}")
        if isinstance(r, LoggerRun) or (hasattr(r, "data") and isinstance(r.data, LoggerRun)):
            t, y = r.t, r.angle
        elif isinstance(r, (tuple, list)) and len(r) == 2:
            t, y = r
        else:
            raise ParameterError(f"{name}[{i}] = {r!r:.80} is not a run: allowed a (t, theta) pair or a LoggerRun")
        out.append(time_and_signal(t, y, t_name=f"{name}[{i}] t", y_name=f"{name}[{i}] theta", y_unit="rad"))
    if not out:
        raise ParameterError(f"{name} is empty: allowed at least one run")
    return out


def check_band(band) -> tuple[float, float]:
    """Validate an amplitude band (low, high) in rad, 0 <= low < high."""
    if isinstance(band, (str, bytes)) or not hasattr(band, "__len__") or len(band) != 2:
        raise ParameterError(f"band = {band!r:.80} is not a pair: allowed (low, high) in rad")
    lo = check_real("band[0]", band[0], low=0.0, high=1e6, unit="rad")
    hi = check_real("band[1]", band[1], low=0.0, high=1e6, unit="rad")
    if not lo < hi:
        raise ParameterError(f"band = ({lo!r}, {hi!r}) is out of range: allowed low < high (rad)")
    return lo, hi


def band_values(curve: DampingCurve, band) -> np.ndarray:
    """zeta_eq of the half periods whose amplitude lies inside the band (rad, inclusive)."""
    lo, hi = band
    m = (curve.amplitude >= lo) & (curve.amplitude <= hi)
    return np.asarray(curve.zeta_eq[m])


def compare_damping(runs_a, runs_b, band) -> DampingDifference:
    r"""The brake (or any change) at matched amplitude: zeta_eq of b minus a inside an amplitude band.

    Per run, the mean :math:`\zeta_{eq}` of its half periods with amplitude inside ``band``; per
    side, the mean over the runs that have such half periods; the difference b − a. Its standard
    error and 95 % interval come from 2000 bootstrap resamples (fixed seed) of the runs of each side,
    or, when a side has fewer than 3 runs, of the half periods of each side.

    Parameters
    ----------
    runs_a, runs_b : sequence
        Free decays, each a ``(t, theta)`` pair (s, rad), a :class:`~vibration.physics.lab.logger.LoggerRun`
        or a :class:`~vibration.physics.lab.manifest.LabRun`.
    band : tuple of float
        Amplitude band (low, high) in rad.

    Returns
    -------
    DampingDifference

    Raises
    ------
    ParameterError
        Bad runs or band (named), or a side without any half period in the band.

    Examples
    --------
    >>> import numpy as np
    >>> from vibration.physics.lab.decay import free_decay_response
    >>> t = np.arange(0.0, 20.0, 0.01)
    >>> a = [(t, free_decay_response(t, 4.5, 0.01, friction=0.0, theta0=x)) for x in (3.0, 3.5, 4.0)]
    >>> b = [(t, free_decay_response(t, 4.5, 0.02, friction=0.0, theta0=x)) for x in (3.0, 3.5, 4.0)]
    >>> round(compare_damping(a, b, (0.5, 3.0)).delta_zeta, 4)
    0.01
    """
    ra = _as_runs("runs_a", runs_a)
    rb = _as_runs("runs_b", runs_b)
    lo, hi = check_band(band)
    sides = []
    for name, runs in (("runs_a", ra), ("runs_b", rb)):
        vals = [band_values(_curve(t, y), (lo, hi)) for t, y in runs]
        vals = [v for v in vals if v.size]
        if not vals:
            raise ParameterError(
                f"{name} has no half period with amplitude in band = ({lo:g}, {hi:g}) rad: allowed a band where both "
                "sides have data"
            )
        sides.append(vals)
    means = [float(np.mean([v.mean() for v in s])) for s in sides]
    rng = np.random.default_rng(SEED)
    by_runs = min(len(sides[0]), len(sides[1])) >= MIN_RUNS_BOOTSTRAP
    boot = np.empty(N_BOOTSTRAP)
    if by_runs:
        per = [np.array([v.mean() for v in s]) for s in sides]
        ia = rng.integers(0, per[0].size, size=(N_BOOTSTRAP, per[0].size))
        ib = rng.integers(0, per[1].size, size=(N_BOOTSTRAP, per[1].size))
        boot = per[1][ib].mean(axis=1) - per[0][ia].mean(axis=1)
    else:
        flat = [np.concatenate(s) for s in sides]
        ia = rng.integers(0, flat[0].size, size=(N_BOOTSTRAP, flat[0].size))
        ib = rng.integers(0, flat[1].size, size=(N_BOOTSTRAP, flat[1].size))
        boot = flat[1][ib].mean(axis=1) - flat[0][ia].mean(axis=1)
    lo_ci, hi_ci = np.percentile(boot, [2.5, 97.5])
    return DampingDifference(
        delta_zeta=means[1] - means[0],
        stderr=float(np.std(boot, ddof=1)),
        ci_low=float(lo_ci),
        ci_high=float(hi_ci),
        method="bootstrap over runs" if by_runs else "bootstrap over half periods",
        band=(lo, hi),
        n_a=len(sides[0]),
        n_b=len(sides[1]),
        zeta_a=means[0],
        zeta_b=means[1],
    )


@dataclass(frozen=True, kw_only=True)
class JointBrakeFit:
    """All half periods of two sets fitted with one amplitude law plus a viscous term for set b only.

    Attributes
    ----------
    delta_zeta : float
        The viscous damping ratio set b adds.
    stderr : float
        Bootstrap standard error (runs resampled within each set; half periods when a set has fewer than 3).
    friction, zeta, quadratic : float
        The shared law: Coulomb angle (rad), viscous ratio and quadratic coefficient (1/rad).
    n_a, n_b : int
        Runs of each set.
    """

    delta_zeta: float
    stderr: float
    friction: float
    zeta: float
    quadratic: float
    n_a: int
    n_b: int


def _joint_lsq(xa, la, xb, lb):
    x = np.concatenate([xa, xb])
    loss = np.concatenate([la, lb])
    brake = np.concatenate([np.zeros(xa.size), np.ones(xb.size)])
    X = np.column_stack([np.full_like(x, 2.0), x, 4.0 / 3.0 * x * x, x * brake])
    lo = np.array([0.0, 0.0, 0.0, -np.inf])
    c = optimize.lsq_linear(X, loss, bounds=(lo, np.full(4, np.inf)), method="bvls").x

    # viscous loss per half period is (1 - q) X with q = exp(-pi zeta / sqrt(1 - zeta^2)): back to ratios
    def ratio(v):
        v = min(max(v, -0.5), 0.99)
        d = -math.log(1.0 - v)
        return d / math.hypot(math.pi, d)

    z_shared = ratio(c[1])
    return np.array([c[0], z_shared, c[2], ratio(c[1] + c[3]) - z_shared])


def joint_brake_fit(runs_a, runs_b) -> JointBrakeFit:
    r"""Second estimate of the brake: one shared amplitude law and a brake-only viscous term, fitted jointly.

    Every half period of both sets is fitted by linear least squares with the energy-balance loss
    :math:`X_k - X_{k+1} = 2\theta_f + \pi\zeta X_k + \tfrac43 \beta X_k^2 + \pi\,\Delta\zeta\,X_k\,[\text{set } \beta]`
    (Coulomb, viscous and quadratic terms shared, each >= 0; the viscous losses converted to ratios
    exactly, through :math:`1 - q`). 2000 bootstrap resamples (fixed seed) give the
    standard error of :math:`\Delta\zeta`.

    Parameters
    ----------
    runs_a, runs_b : sequence
        Free decays (``(t, theta)`` pairs, LoggerRun or LabRun).

    Returns
    -------
    JointBrakeFit

    Examples
    --------
    >>> import numpy as np
    >>> from vibration.physics.lab.decay import free_decay_response
    >>> t = np.arange(0.0, 20.0, 0.01)
    >>> a = [(t, free_decay_response(t, 4.5, 0.005, friction=0.05, theta0=x)) for x in (3.0, 3.5, 4.0)]
    >>> b = [(t, free_decay_response(t, 4.5, 0.015, friction=0.05, theta0=x)) for x in (3.0, 3.5, 4.0)]
    >>> round(joint_brake_fit(a, b).delta_zeta, 3)
    0.01
    """
    ra = _as_runs("runs_a", runs_a)
    rb = _as_runs("runs_b", runs_b)
    ca = [_curve(t, y) for t, y in ra]
    cb = [_curve(t, y) for t, y in rb]
    for name, cs in (("runs_a", ca), ("runs_b", cb)):
        if sum(c.n for c in cs) < 3:
            raise ParameterError(f"{name} has fewer than 3 half periods in all: allowed free decays of a few periods")

    def stack(cs):
        return np.concatenate([c.amplitude for c in cs]), np.concatenate([c.loss for c in cs])

    coef = _joint_lsq(*stack(ca), *stack(cb))
    rng = np.random.default_rng(SEED)
    boot = np.empty(N_BOOTSTRAP)
    by_runs = min(len(ca), len(cb)) >= MIN_RUNS_BOOTSTRAP
    xa, la = stack(ca)
    xb, lb = stack(cb)
    for i in range(N_BOOTSTRAP):
        if by_runs:
            sa = stack([ca[j] for j in rng.integers(0, len(ca), len(ca))])
            sb = stack([cb[j] for j in rng.integers(0, len(cb), len(cb))])
        else:
            ia, ib = rng.integers(0, xa.size, xa.size), rng.integers(0, xb.size, xb.size)
            sa, sb = (xa[ia], la[ia]), (xb[ib], lb[ib])
        boot[i] = _joint_lsq(*sa, *sb)[3]
    return JointBrakeFit(
        delta_zeta=float(coef[3]),
        stderr=float(np.std(boot, ddof=1)),
        friction=float(coef[0]),
        zeta=float(coef[1]),
        quadratic=float(coef[2]),
        n_a=len(ra),
        n_b=len(rb),
    )
