"""The whole-trace least-squares fit of a damping law's free decay (starts, bounds, multi-start solve)."""

from __future__ import annotations

import math

import numpy as np
from scipy import optimize

from vibration.physics.lab._checks import time_and_signal
from vibration.physics.lab.damping_laws import (
    _GENERAL_ARGS,
    POWER_EXPONENT_RANGE,
    TERMS,
    _response_general,
    _sine_power_integral,
    law_name,
    parse_law,
)
from vibration.physics.lab.decay_record import FreeDecayFit
from vibration.physics.lab.decay_uncertainty import central_jacobian, standard_errors, whiteness
from vibration.physics.lab.peaks import MIN_HALF_PERIODS, PeakDecayFit, _peaks, _start, peak_decay_fit
from vibration.physics.model import ParameterError

__all__ = ["MAX_NFEV", "fit_free_decay"]

#: Largest number of least-squares function evaluations per fit.
MAX_NFEV = 2_000
_ALL = ("omega_n", "zeta", "friction", "offset", "theta0", "t0", "quadratic", "power", "power_exponent")
_TERM_PARAMS = {
    "viscous": ("zeta",),
    "coulomb": ("friction",),
    "quadratic": ("quadratic",),
    "power": ("power", "power_exponent"),
}


def _free_params(terms) -> tuple[str, ...]:
    free = ["omega_n"]
    for term in TERMS:
        if term in terms:
            free.extend(_TERM_PARAMS[term])
    return tuple(free) + ("offset", "theta0", "t0")


def _curve_guess(peaks, k0, omega):
    """Starting values of Delta, zeta, b from the loss per half period against the amplitude (least squares)."""
    e = peaks.theta[k0:]
    if e.size < 4:
        return 0.0, 0.0, 0.0
    x = np.abs(np.diff(e)) / 2.0
    loss = x[:-1] - x[1:]
    xa = x[:-1]
    X = np.column_stack([np.full_like(xa, 2.0), math.pi * xa, 4.0 / 3.0 * xa * xa])
    try:
        coef, *_ = np.linalg.lstsq(X, loss, rcond=None)
    except np.linalg.LinAlgError:
        return 0.0, 0.0, 0.0
    return float(max(coef[0], 0.0)), float(max(coef[1], 0.0)), float(max(coef[2], 0.0))


def _guesses(ta, ya, peaks, k0: int, n_ext: int, half: float) -> tuple[list[PeakDecayFit], float]:
    """Starting estimates: the peak analyses that apply, the median half period, and the loss-curve line.

    Returns the estimates and the loss-curve line's quadratic coefficient b (1/rad).
    """
    guesses = []
    for g_law in ("combined", "coulomb", "viscous"):
        try:
            guesses.append(peak_decay_fit(ta, ya, law=g_law))
        except ParameterError:  # the extrema do not fit this law's recursion: not a usable start
            pass
    guesses.append(
        PeakDecayFit(
            law="combined",
            omega_n=math.pi / half,
            zeta=0.01,
            friction=0.0,
            offset=float(np.median(ya)),
            stderr={},
            n_peaks=n_ext,
        )
    )
    g_fric, g_zeta, g_quad = _curve_guess(peaks, k0, math.pi / half)
    guesses.append(
        PeakDecayFit(
            law="combined",
            omega_n=math.pi / half,
            zeta=g_zeta,
            friction=g_fric,
            offset=float(np.median(ya)),
            stderr={},
            n_peaks=n_ext,
        )
    )
    return guesses, g_quad


def _bounds(ya, peaks, k0: int, half: float, span: float) -> tuple[dict, dict]:
    """Lower and upper bounds of every parameter, from the trace's range and the median half period (s)."""
    w_half = math.pi / half
    lo = {
        "omega_n": 0.5 * w_half,
        "zeta": 0.0,
        "friction": 0.0,
        "quadratic": 0.0,
        "power": 0.0,
        "power_exponent": POWER_EXPONENT_RANGE[0],
        "offset": float(ya.min()),
        "theta0": float(ya.min()) - span,
        "t0": float(peaks.t[k0]) - 0.25 * half,
    }
    hi = {
        "omega_n": 2.0 * w_half,
        "zeta": 0.5,
        "friction": span,
        "quadratic": 10.0 / max(span, 1e-9),
        "power": 0.5,  # fitted as the equivalent ratio at 1 rad, below
        "power_exponent": POWER_EXPONENT_RANGE[1],
        "offset": float(ya.max()),
        "theta0": float(ya.max()) + span,
        "t0": float(peaks.t[k0]) + 0.25 * half,
    }
    return lo, hi


def _starts(guesses, terms, g_quad: float, span: float, peaks, k0: int) -> list[dict]:
    """The starting points of the multi-start solve, in the order they are tried."""
    extra = [{}]
    if "power" in terms:
        extra = [{"power_exponent": pe} for pe in (2.0, 4.0)]
    starts = []
    for g in guesses:
        for ex in extra:
            start = {
                "omega_n": g.omega_n,
                "zeta": min(max(g.zeta, 1e-4), 0.4),
                "friction": min(max(g.friction, 1e-3 * span), 0.4 * span),
                "quadratic": max(g_quad, 1e-4),
                "power": max(3.0 * g_quad / (4.0 * math.pi) * 4.0 / 3.0, 1e-4),
                "power_exponent": 2.0,
                "offset": g.offset,
                "theta0": float(peaks.theta[k0]),
                "t0": float(peaks.t[k0]),
            }
            start.update(ex)
            starts.append(start)
    return starts


def _best_of_starts(resid, starts, free, lb: np.ndarray, ub: np.ndarray):
    """The best local least-squares solution from the starts (the surface of an oscillation has local minima)."""
    sol = None
    for start in starts:
        x0 = np.array([start[k] for k in free])
        x0 = np.clip(x0, lb + 1e-9 * (ub - lb), ub - 1e-9 * (ub - lb))
        trial = optimize.least_squares(resid, x0, bounds=(lb, ub), x_scale="jac", max_nfev=MAX_NFEV, method="trf")
        if sol is None or trial.cost < sol.cost:
            sol = trial
    return sol


def _standard_errors(misfit, phys: dict, free, base: dict, r: np.ndarray, lags: int) -> tuple[dict, dict, dict]:
    """Standard errors keyed by every parameter (0 when fixed): reported, naive and Newey-West (``lags`` lags).

    The Jacobian is taken by central differences at the solution ``phys``, in the physical parameters.
    """
    xp0 = np.array([phys[k] for k in free])

    def resid_phys(v):
        return misfit({**base, **dict(zip(free, v, strict=True))})

    J = central_jacobian(resid_phys, xp0, r.size, nonnegative=[k in base for k in free])
    naive, hac = standard_errors(J, r, lags)
    se_n = {k: 0.0 for k in _ALL}
    se_h = {k: 0.0 for k in _ALL}
    se_n.update(zip(free, naive, strict=True))
    se_h.update(zip(free, hac, strict=True))
    return {k: max(se_n[k], se_h[k]) for k in _ALL}, se_n, se_h


def _coefficients(terms, p: dict) -> dict:
    """The fitted terms' coefficients keyed by term ("viscous", "coulomb", ...), and "power_exponent"."""
    coefficients = {}
    for term, key in (("viscous", "zeta"), ("coulomb", "friction"), ("quadratic", "quadratic"), ("power", "power")):
        if term in terms:
            coefficients[term] = float(p[key])
    if "power" in terms:
        coefficients["power_exponent"] = float(p["power_exponent"])
    return coefficients


def _release(ta, ya):
    """The extrema, the index of the first one after the release, and how many extrema follow from it on.

    Refused below ``MIN_HALF_PERIODS`` half periods after the release.
    """
    peaks = _peaks(ta, ya)
    k0 = _start(ta, ya, peaks)
    n_ext = peaks.n - k0
    if n_ext < MIN_HALF_PERIODS + 1:
        raise ParameterError(
            f"theta has {max(0, n_ext - 1)} half periods after its largest excursion which is out of range: allowed "
            f"at least {MIN_HALF_PERIODS} (a free decay of at least two periods after the release)"
        )
    return peaks, k0, n_ext


def _fit_window(ta, ya, peaks, k0: int, half: float):
    """The fitted window: from the release's extremum to half a half period after the last extremum.

    Returns its start and end (s) and the times and angles inside it.
    """
    t_start = float(ta[peaks.index[k0]])
    t_end = min(float(ta[-1]), float(peaks.t[-1]) + 0.5 * half)
    w = (ta >= t_start) & (ta <= t_end)
    return t_start, t_end, ta[w], ya[w]


def _physical_params(terms, free, base: dict, x) -> dict:
    """Every parameter from the fitted vector ``x`` (``free`` order) over ``base``, the power term made physical."""
    p = dict(base)
    p.update(zip(free, x, strict=True))
    if "power" in terms:  # the fitted value is the power term's equivalent ratio at X = 1 rad
        pe = p["power_exponent"]
        p["power"] = p["power"] * math.pi / (_sine_power_integral(pe + 1.0) * p["omega_n"] ** (pe - 2.0))
    return p


def _hac_lags(half: float, tw, n: int) -> int:
    """Newey-West lags: one half period of samples, at least 1 and at most a quarter of the ``n`` residuals."""
    return int(min(max(1, round(half / float(np.median(np.diff(tw))))), n // 4))


def _decay_record(terms, p: dict, sol, r, errors, peaks, window) -> FreeDecayFit:
    """The fit's record, with its residual statistics and information criteria.

    From the solution ``p``, the solver's result ``sol``, the residuals ``r`` (model minus data), the standard
    errors (reported, naive, Newey-West) and the fitted window's (start, end) (s).
    """
    se, se_n, se_h = errors
    t_start, t_end = window
    n, p_free = r.size, sol.x.size
    rss = float(r @ r)
    kpar = p_free + 1
    m2ll = n * math.log(2.0 * math.pi * max(rss, 1e-300) / n) + n
    dw, lb_p = whiteness(r)
    in_window = (peaks.t >= t_start - 1e-12) & (peaks.t <= t_end)
    res = -r
    res.flags.writeable = False
    return FreeDecayFit(
        law=law_name(terms),
        omega_n=float(p["omega_n"]),
        zeta=float(p["zeta"]),
        friction=float(p["friction"]),
        offset=float(p["offset"]),
        theta0=float(p["theta0"]),
        t0=float(p["t0"]),
        quadratic=float(p["quadratic"]),
        power=float(p["power"]),
        power_exponent=float(p["power_exponent"]),
        coefficients=_coefficients(terms, p),
        stderr=se,
        stderr_naive=se_n,
        stderr_hac=se_h,
        residual_rms=float(math.sqrt(rss / n)),
        aic=float(m2ll + 2 * kpar),
        bic=float(m2ll + kpar * math.log(n)),
        n=int(n),
        n_params=int(p_free),
        n_half_periods=int(max(0, np.count_nonzero(in_window) - 1)),
        t_start=t_start,
        t_end=t_end,
        durbin_watson=dw,
        ljung_box_p=lb_p,
        converged=bool(sol.success),
        residuals=res,
    )


def fit_free_decay(t, theta, law: str = "coulomb+viscous") -> FreeDecayFit:
    r"""Fit a damping law's free decay to a whole trace.

    The law is any sum of the terms of

    .. math::

        \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\theta_f\,\mathrm{sgn}\dot\theta
        + \beta\,\dot\theta|\dot\theta| + \alpha|\dot\theta|^n\mathrm{sgn}\dot\theta + \omega_n^2(\theta-\theta_0) = 0

    (viscous zeta, Coulomb Delta in rad, quadratic b in 1/rad, power a with p fitted; ``quadratic+power``
    is refused). Viscous and Coulomb terms alone have a piecewise closed-form solution, which is fitted
    exactly. With a quadratic or power term the trace is the half-period energy-balance model: every
    half cycle between velocity reversals is the closed-form viscous half cycle about the Coulomb
    centre, with the equivalent damping ratio
    :func:`~vibration.physics.lab.damping_laws.equivalent_zeta` of the half cycle's mean
    amplitude (first order in the damping; checked against :func:`damping_ode`). All samples are fitted
    by nonlinear least squares (:func:`scipy.optimize.least_squares`, trust-region reflective, every
    coefficient >= 0, p in [0.5, 8]).

    The fit starts at the first extremum after the sample of largest ``|theta - median(theta)|``
    (so that a hand push before the release is left out); there the velocity is zero and the free
    parameters are omega_n, the law's coefficients, the resting angle, and the angle and time of
    that extremum. The window ends half a half period after the last extremum detected by
    :func:`~vibration.physics.lab.peaks.free_decay_peaks` (the rest, at rest, repeats one quantised
    value whose rounding error would bias the fit). Starts: the estimates of
    :func:`~vibration.physics.lab.peaks.peak_decay_fit`, the least-squares line of the loss per half
    period against the amplitude, and the median half period; the best local solution is kept.

    Uncertainties. ``stderr_naive`` is ``s^2 (J^T J)^-1``; encoder rounding errors are correlated
    where the wheel moves slowly, so the reported ``stderr`` is the larger of it and a Newey-West
    (Bartlett kernel, one half period of lags) sandwich estimate.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing, at most 1 000 000 samples.
    theta : array_like
        Angles (rad), same length, finite, not constant.
    law : str
        ``+``-joined terms out of "viscous", "coulomb", "quadratic", "power" ("combined" is an alias of
        "coulomb+viscous").

    Returns
    -------
    FreeDecayFit
        Parameters (rad/s, rad, s), their standard errors, residual statistics, AIC and BIC
        (:math:`n\ln(2\pi\,RSS/n) + n + 2k` and :math:`\ldots + k\ln n`, k = fitted parameters + 1).

    Raises
    ------
    ParameterError
        Bad inputs (named), an unknown law, or fewer than 4 half periods after the largest excursion.

    Examples
    --------
    >>> import numpy as np
    >>> from vibration.physics.lab.coulomb_decay import free_decay_response
    >>> t = np.arange(0.0, 10.0, 0.05)
    >>> y = free_decay_response(t, 4.5, 0.01, friction=0.02, offset=0.05, theta0=1.0)
    >>> f = fit_free_decay(t, y)
    >>> round(f.omega_n, 6), round(f.zeta, 6), round(f.friction, 6), round(f.offset, 6)
    (4.5, 0.01, 0.02, 0.05)
    """
    terms = parse_law(law)
    ta, ya = time_and_signal(t, theta, t_name="t", y_name="theta", y_unit="rad")
    peaks, k0, n_ext = _release(ta, ya)
    half = float(np.median(np.diff(peaks.t[k0:])))
    guesses, g_quad = _guesses(ta, ya, peaks, k0, n_ext, half)
    t_start, t_end, tw, yw = _fit_window(ta, ya, peaks, k0, half)
    span = float(np.ptp(ya))
    lo, hi = _bounds(ya, peaks, k0, half, span)
    free = _free_params(terms)
    base = {"friction": 0.0, "zeta": 0.0, "quadratic": 0.0, "power": 0.0, "power_exponent": 0.0}

    def params(x):
        return _physical_params(terms, free, base, x)

    def misfit(p):
        return _response_general(tw, *(p[k] for k in _GENERAL_ARGS)) - yw

    def resid(x):
        return misfit(params(x))

    lb = np.array([lo[k] for k in free])
    ub = np.array([hi[k] for k in free])
    sol = _best_of_starts(resid, _starts(guesses, terms, g_quad, span, peaks, k0), free, lb, ub)
    r = resid(sol.x)
    phys = params(sol.x)
    errors = _standard_errors(misfit, phys, free, base, r, _hac_lags(half, tw, r.size))
    return _decay_record(terms, phys, sol, r, errors, peaks, (t_start, t_end))
