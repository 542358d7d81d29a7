"""Chaos in the forced Duffing oscillator: Poincaré sections and Lyapunov exponents (compiled RK4)."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_count, check_derived, check_start
from ..model import ParameterError, check_int, check_real
from .model import MAX_RK4_STEPS, RK4_STABILITY, Duffing, _check_duffing, _linear_rate, _rates, _x_ref

# ------------------------------------------------------------------------------ compiled kernel


@functools.cache
def _rk4_kernel():
    """Compile (once per process, cached on disk) the fixed-step RK4; numba is imported lazily."""
    import numba

    @numba.njit(cache=True)
    def accel(x, v, f, coef):  # pragma: no cover
        """Acceleration (m/s^2) of the oscillator ``coef = (m, c, k, k3)`` at ``(x, v)`` under the force ``f``."""
        m, c, k, k3 = coef
        return (f - c * v - k * x - k3 * x**3) / m

    @numba.njit(cache=True)
    def tangent(a, b, j, coef):  # pragma: no cover
        """Linearised acceleration of the tangent vector ``(a, b)``: ``j a - (c/m) b``, ``coef = (c/m,)``."""
        return j * a - coef[0] * b

    @numba.njit(cache=True)
    def rk4_step(rate, x, v, h, p1, p2, p3, p4, coef):  # pragma: no cover
        """One RK4 step of ``x' = v, v' = rate(x, v, p, coef)``, ``p`` being ``p1`` to ``p4`` at the four stages.

        Returns the new ``(x, v)`` and the stages' positions ``x + h/2 k1x``, ``x + h/2 k2x``, ``x + h k3x``.
        """
        k1x, k1v = v, rate(x, v, p1, coef)
        xa, va = x + 0.5 * h * k1x, v + 0.5 * h * k1v
        k2x, k2v = va, rate(xa, va, p2, coef)
        xb, vb = x + 0.5 * h * k2x, v + 0.5 * h * k2v
        k3x, k3v = vb, rate(xb, vb, p3, coef)
        xc, vc = x + h * k3x, v + h * k3v
        k4x, k4v = vc, rate(xc, vc, p4, coef)
        x_new = x + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x)
        v_new = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
        return x_new, v_new, xa, xb, xc

    @numba.njit(cache=True)
    def rk4_kernel(
        m, c, k, k3, F0, w, x0, v0, n_periods, steps_per_period, mode, d0, record, gs_every, blow_up
    ):  # pragma: no cover
        """mode 0: Poincare points; 1: QR on the variational equations; 2: two-trajectory renormalisation.

        The tangent vectors (mode 1) or the separation (mode 2) are renormalised at the end of
        every period and, when the damping contracts them strongly, also every ``gs_every`` steps.
        Returns (points (n_periods, 2), running largest exponent per period, tail): tail holds the
        sums of logs (2), the final state and tangent vectors (6), a status (0 done, 1 the state
        left ``|x| <= blow_up`` or stopped being finite, 2 a tangent vector or the separation
        underflowed to 0 or overflowed) and the period at which it stopped.
        """
        T = 2.0 * np.pi / w
        h = T / steps_per_period
        coef, tangent_coef = (m, c, k, k3), (c / m,)
        x, v = x0, v0
        # tangent vectors (mode 1) or the partner trajectory (mode 2)
        q11, q21, q12, q22 = 1.0, 0.0, 0.0, 1.0
        px, pv = x0 + d0, v0
        pts = np.empty((n_periods, 2))
        running = np.empty(n_periods)
        s1, s2 = 0.0, 0.0
        for n in range(n_periods):
            for i in range(steps_per_period):
                tau = i * h
                f0 = F0 * np.cos(w * tau)
                fh = F0 * np.cos(w * (tau + 0.5 * h))
                f1 = F0 * np.cos(w * (tau + h))
                x_new, v_new, xa, xb, xc = rk4_step(accel, x, v, h, f0, fh, fh, f1, coef)
                if mode == 1:  # the two tangent vectors along the same stages (Jacobian -(k + 3 k3 x^2)/m)
                    j1, ja = -(k + 3.0 * k3 * x * x) / m, -(k + 3.0 * k3 * xa * xa) / m
                    jb, jc = -(k + 3.0 * k3 * xb * xb) / m, -(k + 3.0 * k3 * xc * xc) / m
                    q11, q21, _, _, _ = rk4_step(tangent, q11, q21, h, j1, ja, jb, jc, tangent_coef)
                    q12, q22, _, _, _ = rk4_step(tangent, q12, q22, h, j1, ja, jb, jc, tangent_coef)
                x, v = x_new, v_new
                if mode == 2:  # partner trajectory, the same RK4 steps
                    px, pv, _, _, _ = rk4_step(accel, px, pv, h, f0, fh, fh, f1, coef)
                renorm = i == steps_per_period - 1 or (i + 1) % gs_every == 0
                if mode == 1 and renorm:  # Gram-Schmidt (QR) once per period (or every gs_every steps)
                    r11 = np.sqrt(q11 * q11 + q21 * q21)
                    if not (r11 > 0.0 and r11 < np.inf):
                        return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 2.0, n])
                    q11, q21 = q11 / r11, q21 / r11
                    dot = q11 * q12 + q21 * q22
                    q12, q22 = q12 - dot * q11, q22 - dot * q21
                    r22 = np.sqrt(q12 * q12 + q22 * q22)
                    if not (r22 > 0.0 and r22 < np.inf):
                        return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 2.0, n])
                    q12, q22 = q12 / r22, q22 / r22
                    if record:
                        s1 += np.log(r11)
                        s2 += np.log(r22)
                if mode == 2 and renorm:  # renormalise the separation to d0 along its current direction
                    dx, dv = px - x, pv - v
                    dist = np.sqrt(dx * dx + dv * dv)
                    if not (dist > 0.0 and dist < np.inf):
                        return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 2.0, n])
                    if record:
                        s1 += np.log(dist / d0)
                    px, pv = x + dx * d0 / dist, v + dv * d0 / dist
            if not (abs(x) <= blow_up and abs(v) < np.inf):
                return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 1.0, n])
            pts[n, 0] = x
            pts[n, 1] = v
            running[n] = s1 / ((n + 1) * T)
        return pts, running, np.array([s1, s2, x, v, q11, q21, q12, q22, 0.0, n_periods])

    return rk4_kernel


@dataclass(frozen=True, kw_only=True)
class LyapunovResult:
    """Lyapunov exponents of the forced oscillator (per unit time, 1/s)."""

    exponents: tuple[float, ...]  # largest first, 1/s (QR gives two, two-trajectory one)
    running: np.ndarray  # running estimate of the largest exponent after each period, 1/s
    method: str  # "qr" (variational equations) or "benettin" (two trajectories)
    time: float  # averaging time, s
    x_end: float  # final state, m
    v_end: float  # m/s


def _rk4_run(duffing, F0, omega, start, n_periods, n_transient, steps_per_period, mode=0, d0=1.0):
    """Check the arguments, discard ``n_transient`` periods, then run the compiled RK4 in ``mode``.

    Returns the averaging time ``n_periods T`` (s) and the kernel's ``(points, running, tail)``.
    """
    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    x0, v0 = check_start(start)
    n_periods = check_int("n_periods", n_periods, low=1, high=2_000_000)
    n_transient = check_int("n_transient", n_transient, low=0, high=10_000_000)
    spp = check_int("steps_per_period", steps_per_period, low=8, high=100_000)
    total = (n_periods + n_transient) * spp
    if total > MAX_RK4_STEPS:
        raise ParameterError(
            f"n_periods = {n_periods}, n_transient = {n_transient} and steps_per_period = {spp} make {total} RK4 "
            f"steps: allowed at most {MAX_RK4_STEPS} "
            "((n_periods + n_transient) steps_per_period)"
        )
    T = check_derived(
        "the forcing period 2π/omega (s)", 2.0 * math.pi / w, inputs={"omega": w}, allowed="omega >= 1e-300 rad/s"
    )
    h = T / spp
    lam = check_derived(
        "the linearised rate (1/s) at the amplitude max(|x0|, F0/k)",
        _linear_rate(d, max(abs(x0), _x_ref(d, F0) if F0 > 0 else 0.0)),
        inputs={"F0": F0, "x0": x0},
        allowed="F0 and |x0| whose cubic stiffness k3 x^2 stays finite (|x0|, F0/k below about 1e100)",
    )
    if h * lam > RK4_STABILITY:
        need = check_count(
            "steps_per_period for a stable RK4 step",
            T * lam / RK4_STABILITY,
            inputs={"omega": w, "F0": F0, "x0": x0},
            high=10**15,
            advice="a higher omega, a smaller F0 or |x0|, or a less stiff oscillator",
        )
        raise ParameterError(
            f"steps_per_period = {spp} at omega = {w!r} rad/s gives a step of {h:.3g} s, and the fixed-step RK4 is "
            f"unstable for h lambda > {RK4_STABILITY} with lambda = {lam:.3g} 1/s ({_rates(d)}): allowed "
            f"steps_per_period >= {need:.3g}"
            + (" (above its limit 100000: a higher omega or a less stiff oscillator)" if need > 100_000 else "")
        )
    blow_up = 1e3 * max(_x_ref(d, F0), abs(x0), d.barrier) if d.k3 < 0 else math.inf
    # renormalise at least every time the damping alone contracts by exp(-5): the second tangent vector
    # (QR) and the separation (two trajectories) must stay well above the rounding of the leading one
    contraction = d.c / d.m * T
    gs_every = spp if contraction <= 5.0 else max(1, int(spp * 5.0 / contraction))
    kern = _rk4_kernel()
    if n_transient:
        *_, tail = kern(d.m, d.c, d.k, d.k3, F0, w, x0, v0, n_transient, spp, 0, 1.0, False, spp, blow_up)
        _rk4_status(d, F0, w, x0, v0, tail, 0)
        x0, v0 = float(tail[2]), float(tail[3])
    out = kern(d.m, d.c, d.k, d.k3, F0, w, x0, v0, n_periods, spp, mode, d0, mode != 0, gs_every, blow_up)
    _rk4_status(d, F0, w, x0, v0, out[2], n_transient)
    time = n_periods * T
    return (time, *out)


def _rk4_status(d: Duffing, F0: float, w: float, x0: float, v0: float, tail: np.ndarray, offset: int) -> None:
    """Raise :class:`ParameterError` when the compiled RK4 stopped early (see its status codes)."""
    status, n = int(tail[8]), int(tail[9]) + offset
    if status == 1:
        what = (
            f"the mass escaped over the softening spring's barrier ({d.barrier:.3g} m; |x| passed "
            f"{1e3 * max(_x_ref(d, F0), abs(x0), d.barrier):.3g} m or overflowed)"
            if d.k3 < 0
            else "the fixed-step RK4 overflowed (the state is not finite: the step is too large for the cubic "
            "stiffness at this amplitude, or the motion is unbounded)"
        )
        raise ParameterError(
            f"{what} in forcing period {n + 1} (F0 = {F0!r} N, omega = {w!r} rad/s, x0 = {x0!r} m, v0 = {v0!r} "
            "m/s): allowed parameters whose motion stays bounded, or more steps_per_period"
        )
    if status == 2:
        raise ParameterError(
            f"the tangent vectors or the trajectories' separation underflowed or overflowed in forcing period "
            f"{n + 1} ({_rates(d)}, omega = {w!r} rad/s): allowed a less extreme damping or forcing period"
        )
    exps = tail[:2]
    if not np.all(np.isfinite(exps)):  # pragma: no cover - the kernel stops before
        raise ParameterError("the Lyapunov sums are not finite: allowed parameters whose motion stays bounded")


def _lyapunov_result(time, running, tail, method, n_exponents) -> LyapunovResult:
    return LyapunovResult(
        exponents=tuple(float(s / time) for s in tail[:n_exponents]),
        running=running,
        method=method,
        time=time,
        x_end=float(tail[2]),
        v_end=float(tail[3]),
    )


def poincare_section(
    duffing: Duffing,
    F0: float,
    omega: float,
    *,
    x0: float = 0.0,
    v0: float = 0.0,
    n_periods: int = 2000,
    n_transient: int = 200,
    steps_per_period: int = 400,
):
    """Stroboscopic Poincaré section: the state at phase 0 of the forcing, once per period.

    Integrated with a compiled fixed-step RK4 (``steps_per_period`` steps per period).

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    F0 : float
        Force amplitude, N.
    omega : float
        Forcing frequency, rad/s.
    x0, v0 : float
        Initial displacement (m) and velocity (m/s) at t = 0, as everywhere in the library.
    n_periods : int
        Points returned (after the transient).
    n_transient : int
        Periods discarded first.
    steps_per_period : int
        RK4 steps per forcing period (8 to 100000).

    Returns
    -------
    numpy.ndarray
        Shape ``(n_periods, 2)``: x (m) and v (m/s) at ``t = (n_transient + i + 1) T``.

    Examples
    --------
    >>> pts = poincare_section(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0), 5.0, 3.0, n_periods=3)
    >>> bool(np.ptp(pts[:, 0]) < 1e-9)           # a period-1 orbit: one point
    True
    """
    _, pts, _, _ = _rk4_run(duffing, F0, omega, (x0, v0), n_periods, n_transient, steps_per_period)
    return pts


def lyapunov_qr(
    duffing: Duffing,
    F0: float,
    omega: float,
    *,
    x0: float = 0.0,
    v0: float = 0.0,
    n_periods: int = 2000,
    n_transient: int = 100,
    steps_per_period: int = 400,
) -> LyapunovResult:
    """Both Lyapunov exponents from the variational equations with QR (Gram-Schmidt) re-orthonormalisation.

    The state and two tangent vectors are integrated together (compiled RK4); once per
    forcing period the tangent vectors are orthonormalised and the logarithms of the
    diagonal of R accumulated (Benettin et al. 1980; Wolf et al. 1985). The two exponents
    sum to ``-c/m`` (the trace of the Jacobian), whatever the motion.

    Parameters
    ----------
    duffing, F0, omega, x0, v0
        As in :func:`poincare_section`: the oscillator, force amplitude (N), forcing frequency
        (rad/s) and initial state (m, m/s).
    n_periods : int
        Periods averaged over (after the transient).
    n_transient : int
        Periods discarded first (the tangent vectors align meanwhile).
    steps_per_period : int
        RK4 steps per forcing period.

    Returns
    -------
    LyapunovResult
        ``exponents = (lambda_1, lambda_2)``, 1/s.

    Examples
    --------
    >>> r = lyapunov_qr(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0), 5.0, 3.0, n_periods=200)
    >>> round(sum(r.exponents), 6)        # = -c/m, 1/s
    -0.5
    """
    time, _, running, tail = _rk4_run(duffing, F0, omega, (x0, v0), n_periods, n_transient, steps_per_period, 1)
    return _lyapunov_result(time, running, tail, "qr", 2)


def lyapunov_benettin(
    duffing: Duffing,
    F0: float,
    omega: float,
    *,
    x0: float = 0.0,
    v0: float = 0.0,
    n_periods: int = 2000,
    n_transient: int = 100,
    steps_per_period: int = 400,
    d0: float = 1e-8,
) -> LyapunovResult:
    """Largest Lyapunov exponent from two nearby trajectories, renormalised once per period.

    A partner trajectory starts ``d0`` away; both are integrated with the same compiled RK4
    steps (no variational equations), and once per forcing period the logarithm of their
    separation over ``d0`` is accumulated and the partner pulled back to distance ``d0``
    along the separation (Benettin et al. 1976). Independent of :func:`lyapunov_qr` except
    for the stepper.

    Parameters
    ----------
    duffing, F0, omega, x0, v0
        As in :func:`poincare_section`: the oscillator, force amplitude (N), forcing frequency
        (rad/s) and initial state (m, m/s).
    n_periods, n_transient, steps_per_period : int
        As in :func:`lyapunov_qr`.
    d0 : float
        Separation kept between the trajectories, in (x m, v m/s) (1e-12 to 1e-4).

    Returns
    -------
    LyapunovResult
        ``exponents = (lambda_1,)``, 1/s.

    Examples
    --------
    >>> r = lyapunov_benettin(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0), 5.0, 3.0, n_periods=200)
    >>> r.exponents[0] < 0                # a stable periodic orbit
    True
    """
    d0 = check_real("d0", d0, low=1e-12, high=1e-4)
    time, _, running, tail = _rk4_run(duffing, F0, omega, (x0, v0), n_periods, n_transient, steps_per_period, 2, d0)
    return _lyapunov_result(time, running, tail, "benettin", 1)


# ------------------------------------------------------------------- uncertainty of the exponent


@dataclass(frozen=True, kw_only=True)
class LyapunovEstimate:
    """Largest Lyapunov exponent of one long run with its batch-means standard error (per unit time, 1/s).

    The run's per-period growth rates are correlated over a few periods only, so the means of
    ``n_blocks`` consecutive blocks of ``block_periods`` periods are nearly independent: their
    standard deviation over ``sqrt(n_blocks)`` is the standard error of the run's average
    (batch means; Flyvbjerg and Petersen, J. Chem. Phys. 91, 461, 1989).
    """

    exponent: float  # largest exponent averaged over the whole run, 1/s
    standard_error: float  # batch-means standard error of ``exponent``, 1/s
    block_means: np.ndarray  # each block's average exponent, 1/s
    block_periods: int  # forcing periods per block
    second: float  # the second exponent of the same run (QR), 1/s; nan for the two-trajectory method
    method: str  # "qr" or "benettin"
    x0: float  # initial state, m
    v0: float  # m/s
    steps_per_period: int  # RK4 steps per forcing period
    period: float  # forcing period, s
    increments: np.ndarray  # growth of log |separation| in each period (after the transient), 1

    @property
    def n_periods(self) -> int:
        """Forcing periods averaged over."""
        return int(self.increments.size)

    def at(self, n_periods: int, n_blocks: int = 20) -> tuple[float, float]:
        """The estimate and its batch-means standard error (1/s) from the first ``n_periods`` periods alone."""
        n_periods = check_int("n_periods", n_periods, low=n_blocks, high=self.n_periods)
        return _batch_means(self.increments[:n_periods], n_blocks, self.period)[:2]


def _batch_means(increments: np.ndarray, n_blocks: int, period: float) -> tuple[float, float, np.ndarray, int]:
    """Mean rate (1/s), its batch-means standard error (1/s), the block means and the block length (periods)."""
    b = increments.size // n_blocks
    blocks = increments[: b * n_blocks].reshape(n_blocks, b).sum(axis=1) / (b * period)
    mean = float(increments.sum() / (increments.size * period))
    return mean, float(blocks.std(ddof=1) / math.sqrt(n_blocks)), blocks, b


def lyapunov_estimate(
    duffing: Duffing,
    F0: float,
    omega: float,
    *,
    x0: float = 0.0,
    v0: float = 0.0,
    n_periods: int = 20_000,
    n_blocks: int = 20,
    n_transient: int = 300,
    steps_per_period: int = 400,
    method: str = "qr",
) -> LyapunovEstimate:
    """Largest Lyapunov exponent of a long run with its batch-means standard error.

    Runs :func:`lyapunov_qr` (``method="qr"``) or :func:`lyapunov_benettin` (``"benettin"``),
    recovers the growth of the logarithm of the leading tangent vector (or separation) in each
    forcing period, and splits the run into ``n_blocks`` equal blocks; the standard error is the
    standard deviation of the block means over ``sqrt(n_blocks)``. It is the error of this run's
    finite-time average, not of the integrator: the step-size error is checked by running again
    with other ``steps_per_period``.

    Parameters
    ----------
    duffing, F0, omega, x0, v0
        As in :func:`poincare_section`: the oscillator, force amplitude (N), forcing frequency
        (rad/s) and initial state (m, m/s).
    n_periods : int
        Periods averaged over after the transient (at least 10 per block).
    n_blocks : int
        Blocks of the batch means (5 to 1000).
    n_transient : int
        Periods discarded first.
    steps_per_period : int
        RK4 steps per forcing period.
    method : {"qr", "benettin"}
        Variational equations with QR, or two trajectories.

    Returns
    -------
    LyapunovEstimate

    Examples
    --------
    >>> u = Duffing(m=1.0, c=0.05, k=0.0, k3=1.0)                   # Ueda's oscillator
    >>> e = lyapunov_estimate(u, 7.5, 1.0, x0=3.0, v0=0.0, n_periods=4000)
    >>> 0.09 < e.exponent < 0.115 and 0.0005 < e.standard_error < 0.004   # 1/s
    True
    """
    x0, v0 = check_start((x0, v0))
    n_blocks = check_int("n_blocks", n_blocks, low=5, high=1000)
    n_periods = check_int("n_periods", n_periods, low=10 * n_blocks, high=2_000_000)
    if not isinstance(method, str) or method not in ("qr", "benettin"):
        raise ParameterError(f"method = {method!r:.60} is not valid: allowed 'qr' or 'benettin'")
    run = lyapunov_qr if method == "qr" else lyapunov_benettin
    r = run(
        duffing,
        F0,
        omega,
        x0=x0,
        v0=v0,
        n_periods=n_periods,
        n_transient=n_transient,
        steps_per_period=steps_per_period,
    )
    T = r.time / n_periods
    sums = r.running * (np.arange(1, r.running.size + 1) * T)  # cumulative log growth after each period
    increments = np.diff(sums, prepend=0.0)
    mean, se, blocks, b = _batch_means(increments, n_blocks, T)
    return LyapunovEstimate(
        exponent=r.exponents[0],
        standard_error=se,
        block_means=blocks,
        block_periods=b,
        second=r.exponents[1] if len(r.exponents) > 1 else math.nan,
        method=method,
        x0=x0,
        v0=v0,
        steps_per_period=int(steps_per_period),
        period=T,
        increments=increments,
    )


def pooled_exponent(estimates) -> tuple[float, float, float, int]:
    """Inverse-variance pooled exponent of independent runs, its standard error and their chi-square.

    Returns ``(mean, standard_error, chi2, dof)`` (1/s, 1/s, 1, 1): ``chi2`` is the sum of the
    squared deviations from the pooled mean in units of each run's standard error, ``dof`` the
    number of runs less one; runs that agree within their errors give ``chi2`` near ``dof``.
    """
    est = list(estimates)
    if len(est) < 2 or not all(isinstance(e, LyapunovEstimate) for e in est):
        raise ParameterError(f"estimates = {est!r:.60}: allowed two or more LyapunovEstimate records")
    m = np.array([e.exponent for e in est])
    floor = 1e-15 * max(float(np.max(np.abs(m))), 1e-300)  # a periodic orbit's blocks may agree to rounding
    w = 1.0 / np.maximum(np.array([e.standard_error for e in est]), floor) ** 2
    mean = float(np.sum(w * m) / np.sum(w))
    return mean, float(1.0 / math.sqrt(np.sum(w))), float(np.sum(w * (m - mean) ** 2)), len(est) - 1
