r"""Free decays with viscous and Coulomb (dry) friction: exact response, peak analysis, least-squares fit.

The model, for an angle :math:`\theta(t)` in rad,

.. math::

    \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2(\theta - c) = -\omega_n^2\,\Delta\,\mathrm{sgn}(\dot\theta),

has the natural angular frequency :math:`\omega_n` (rad/s), the damping ratio :math:`\zeta`, the
resting angle :math:`c` (rad, ``offset``) and the Coulomb friction expressed as the equivalent angle
:math:`\Delta` (rad, ``friction``): the friction torque divided by the spring stiffness. Between two
velocity reversals the sign is constant and the motion is a viscous free oscillation about
:math:`c - \mathrm{sgn}(\dot\theta)\Delta`, so the exact solution is piecewise closed form. Every
half cycle lasts :math:`\pi/\omega_d` with :math:`\omega_d = \omega_n\sqrt{1-\zeta^2}`, and the
distances :math:`a_k = |\theta_k - c|` of consecutive extrema from the resting angle obey

.. math::

    a_{k+1} = q\,a_k - (1 + q)\Delta, \qquad q = e^{-\pi\zeta/\sqrt{1-\zeta^2}},

a loss per half period of :math:`(1-q)a_k + (1+q)\Delta`: proportional to the amplitude for
viscous damping, the constant :math:`2\Delta` for pure Coulomb friction. The wheel sticks for good
at the first extremum inside the dead band :math:`|\theta_k - c| \le \Delta`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize, stats

from vibration.physics.lab._checks import as_series, time_and_signal
from vibration.physics.lab.peaks import LAWS, MIN_HALF_PERIODS, PeakDecayFit, _peaks, _start, peak_decay_fit
from vibration.physics.model import ParameterError, check_real

#: Largest number of half cycles the exact response evaluates.
MAX_HALF_CYCLES = 100_000
#: Largest number of least-squares function evaluations per fit.
MAX_NFEV = 2_000
_KEYS = ("omega_n", "zeta", "friction", "offset")


# ----------------------------------------------------------------------------- exact response


def _extrema_sequence(theta0, offset, friction, q, n_half):
    """Extremum values e_k, centres and the index of the half cycle where the motion stops (or n_half)."""
    e = np.empty(n_half + 1)
    centre = np.empty(n_half)
    e[0] = theta0
    stop = n_half
    for k in range(n_half):
        d = e[k] - offset
        if abs(d) <= friction:  # inside the dead band: the spring cannot overcome static friction
            stop = k
            e[k + 1 :] = e[k]
            centre[k:] = e[k]
            break
        centre[k] = offset + math.copysign(friction, d)
        e[k + 1] = centre[k] - q * (e[k] - centre[k])
    return e, centre, stop


def _response(t, omega_n, zeta, friction, offset, theta0, t0):
    wd = omega_n * math.sqrt(1.0 - zeta * zeta)
    half = math.pi / wd
    q = math.exp(-zeta * omega_n * half)
    n_half = int(max(0.0, math.ceil((t[-1] - t0) / half))) + 1
    if n_half > MAX_HALF_CYCLES:
        raise ParameterError(
            f"t spans {n_half} half periods which is out of range: allowed at most {MAX_HALF_CYCLES} (omega_n * "
            "duration too large)"
        )
    e, centre, stop = _extrema_sequence(theta0, offset, friction, q, n_half)
    ratio = zeta / math.sqrt(1.0 - zeta * zeta)
    out = np.empty_like(t)
    before = t < t0
    if before.any():  # back from the first extremum, moving towards it: centre on the other side
        tau = t[before] - t0
        d = theta0 - offset
        c_prev = offset - math.copysign(friction, d) if d != 0 else offset
        h = np.exp(-zeta * omega_n * tau) * (np.cos(wd * tau) + ratio * np.sin(wd * tau))
        out[before] = c_prev + (theta0 - c_prev) * h
    after = ~before
    k = np.minimum(np.floor((t[after] - t0) / half).astype(np.int64), n_half - 1)
    tau = t[after] - t0 - k * half
    h = np.exp(-zeta * omega_n * tau) * (np.cos(wd * tau) + ratio * np.sin(wd * tau))
    val = centre[k] + (e[k] - centre[k]) * h
    val = np.where(k >= stop, e[min(stop, n_half)], val)
    out[after] = val
    return out


def free_decay_response(t, omega_n, zeta, friction, offset=0.0, theta0=1.0, t0=0.0) -> np.ndarray:
    r"""Exact free decay with viscous and Coulomb friction, starting at rest from an extremum.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing; times before ``t0`` are evaluated backwards along the half
        cycle that ends at the extremum.
    omega_n : float
        Natural angular frequency (rad/s), > 0.
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    friction : float
        Coulomb friction as an equivalent angle Delta (rad), >= 0.
    offset : float
        Resting angle c (rad) of the spring.
    theta0 : float
        Angle (rad) at the extremum at ``t0``, where the velocity is zero.
    t0 : float
        Time of that extremum (s).

    Returns
    -------
    numpy.ndarray
        Angle (rad) at ``t``.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.array([0.0, np.pi / 4.0, np.pi / 2.0])
    >>> free_decay_response(t, 2.0, 0.0, 0.1, theta0=1.0).round(12).tolist()  # 1 -> -(1 - 2*0.1) in pi/2 s
    [1.0, 0.1, -0.8]
    """
    ta = as_series("t", t, unit="s", min_size=1)
    if ta.size > 1 and not np.all(np.diff(ta) > 0):
        raise ParameterError("t is not strictly increasing: allowed strictly increasing time (s)")
    omega_n = check_real("omega_n", omega_n, low=0.0, low_open=True, high=1e6, unit="rad/s")
    zeta = check_real("zeta", zeta, low=0.0, high=0.999)
    friction = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    offset = check_real("offset", offset, low=-1e6, high=1e6, unit="rad")
    theta0 = check_real("theta0", theta0, low=-1e6, high=1e6, unit="rad")
    t0 = check_real("t0", t0, low=-1e9, high=1e9, unit="s")
    return _response(ta, omega_n, zeta, friction, offset, theta0, t0)


# ----------------------------------------------------------------------------- whole-trace fit


@dataclass(frozen=True, eq=False)
class FreeDecayFit:
    """Least-squares fit of the exact free-decay response to a whole trace.

    Attributes
    ----------
    law : str
        "viscous" (friction fixed at 0), "coulomb" (zeta fixed at 0) or "combined".
    omega_n : float
        Natural angular frequency (rad/s).
    zeta : float
        Damping ratio.
    friction : float
        Coulomb friction angle Delta (rad).
    offset : float
        Resting angle c (rad).
    theta0, t0 : float
        Angle (rad) and time (s) of the first extremum, where the fit starts.
    stderr : dict
        Standard errors reported, keyed "omega_n", "zeta", "friction", "offset", "theta0", "t0"
        (0 for a fixed parameter): the larger of ``stderr_naive`` and ``stderr_hac``.
    stderr_naive, stderr_hac : dict
        From ``s^2 (J^T J)^-1``, and the Newey-West (Bartlett, one half period of lags) sandwich
        that allows for correlated residuals.
    residual_rms : float
        Root mean square of the residuals (rad).
    aic, bic : float
        Akaike and Bayesian information criteria of the Gaussian likelihood, counting the fitted
        parameters and the noise variance.
    n : int
        Number of samples fitted; ``n_params`` the number of fitted parameters.
    n_half_periods : int
        Half periods between detected extrema inside the fitted window.
    t_start, t_end : float
        The fitted window (s).
    durbin_watson : float
        Durbin-Watson statistic of the residuals (about 2 for white residuals, towards 0 for
        positively correlated ones).
    ljung_box_p : float
        p-value of the Ljung-Box test of white residuals (20 lags or n/5).
    converged : bool
        Whether the least-squares solver reported convergence.
    residuals : numpy.ndarray
        Data minus model (rad) on the window.
    """

    law: str
    omega_n: float
    zeta: float
    friction: float
    offset: float
    theta0: float
    t0: float
    stderr: dict = field(repr=False)
    stderr_naive: dict = field(repr=False)
    stderr_hac: dict = field(repr=False)
    residual_rms: float
    aic: float
    bic: float
    n: int
    n_params: int
    n_half_periods: int
    t_start: float
    t_end: float
    durbin_watson: float
    ljung_box_p: float
    converged: bool
    residuals: np.ndarray = field(repr=False)

    def predict(self, t) -> np.ndarray:
        """Fitted angle (rad) at the times ``t`` (s), by :func:`free_decay_response`."""
        return free_decay_response(t, self.omega_n, self.zeta, self.friction, self.offset, self.theta0, self.t0)


_ALL = ("omega_n", "zeta", "friction", "offset", "theta0", "t0")
_FREE = {
    "combined": _ALL,
    "viscous": ("omega_n", "zeta", "offset", "theta0", "t0"),
    "coulomb": ("omega_n", "friction", "offset", "theta0", "t0"),
}


def _whiteness(r: np.ndarray) -> tuple[float, float]:
    dw = float(np.sum(np.diff(r) ** 2) / np.sum(r * r))
    n = r.size
    h = int(min(20, max(1, n // 5)))
    rc = r - r.mean()
    den = float(rc @ rc)
    acf = np.array([float(rc[k:] @ rc[:-k]) / den for k in range(1, h + 1)])
    q = n * (n + 2) * float(np.sum(acf**2 / (n - np.arange(1, h + 1))))
    return dw, float(stats.chi2.sf(q, h))


def _hac_cov(J: np.ndarray, r: np.ndarray, lags: int, bread: np.ndarray) -> np.ndarray:
    g = J * r[:, None]
    meat = g.T @ g
    for k in range(1, lags + 1):
        w = 1.0 - k / (lags + 1.0)
        gk = g[k:].T @ g[:-k]
        meat += w * (gk + gk.T)
    return bread @ meat @ bread


def fit_free_decay(t, theta, law: str = "combined") -> FreeDecayFit:
    r"""Fit the exact piecewise free decay with viscous and/or Coulomb friction to a whole trace.

    The model (module docstring) is evaluated in closed form half cycle by half cycle, with no
    numerical integrator, and fitted to every sample by nonlinear least squares
    (:func:`scipy.optimize.least_squares`, trust-region reflective, bounds zeta >= 0 and
    Delta >= 0). The fit starts at the first extremum after the sample of largest
    ``|theta - median(theta)|`` (so that a hand push before the release is left out); there the
    velocity is zero and the free parameters are omega_n, zeta, Delta, the offset c, and the angle
    and time of that extremum. The window ends half a half period after the last extremum detected
    by :func:`~vibration.physics.lab.peaks.free_decay_peaks`: the rest of the record, with the
    wheel (nearly) at rest, repeats one quantised value whose rounding error is the same in every
    sample; fitted, it biases zeta and Delta far beyond their standard errors (checked on
    synthetic quantised decays). The solver is started from the estimates of
    :func:`~vibration.physics.lab.peaks.peak_decay_fit` for each of the three laws and from the
    median half period, and the best of these local solutions is kept.

    Uncertainties. ``stderr_naive`` is ``s^2 (J^T J)^-1`` with ``s^2 = RSS / (n - p)``, valid for
    independent residuals. Encoder data are quantised (1 degree = 0.01745 rad here): the rounding
    error is a deterministic function of the angle, correlated from sample to sample where the
    wheel moves slowly (near the extrema and at rest), and the model is never exact; then the
    naive errors are too small. The reported ``stderr`` is therefore the larger of the naive and
    of a Newey-West (Bartlett kernel, one half period of lags) sandwich estimate. The Durbin-Watson
    statistic and the Ljung-Box p-value tell how far the residuals are from white.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing (uniform sampling not needed), at most 1 000 000 samples.
    theta : array_like
        Angles (rad), same length, finite, not constant.
    law : {"viscous", "coulomb", "combined"}
        Friction law: Delta fixed at 0, zeta fixed at 0, or both fitted.

    Returns
    -------
    FreeDecayFit
        Parameters (rad/s, rad, s), their standard errors, residual statistics, AIC and BIC
        (:math:`n\ln(2\pi\,RSS/n) + n + 2k` and :math:`\ldots + k\ln n`, k = fitted parameters + 1).

    Raises
    ------
    ParameterError
        Bad inputs (named), an unknown law, or fewer than 4 half periods after the largest
        excursion.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0.0, 10.0, 0.05)
    >>> y = free_decay_response(t, 4.5, 0.01, 0.02, offset=0.05, theta0=1.0)
    >>> f = fit_free_decay(t, y)
    >>> round(f.omega_n, 6), round(f.zeta, 6), round(f.friction, 6), round(f.offset, 6)
    (4.5, 0.01, 0.02, 0.05)
    """
    if law not in LAWS:
        raise ParameterError(f"law = {law!r} is out of range: allowed one of {LAWS}")
    ta, ya = time_and_signal(t, theta, t_name="t", y_name="theta", y_unit="rad")
    peaks = _peaks(ta, ya)
    k0 = _start(ta, ya, peaks)
    n_ext = peaks.n - k0
    if n_ext < MIN_HALF_PERIODS + 1:
        raise ParameterError(
            f"theta has {max(0, n_ext - 1)} half periods after its largest excursion which is out of range: allowed "
            f"at least {MIN_HALF_PERIODS} (a free decay of at least two periods after the release)"
        )
    half = float(np.median(np.diff(peaks.t[k0:])))
    guesses = []
    for g_law in ("combined", "coulomb", "viscous"):
        try:
            guesses.append(peak_decay_fit(ta, ya, law=g_law))
        except ParameterError:  # the extrema do not fit this law's recursion: not a usable start
            pass
    guesses.append(PeakDecayFit("combined", math.pi / half, 0.01, 0.0, float(np.median(ya)), {}, n_ext))
    t_start = float(ta[peaks.index[k0]])
    t_end = min(float(ta[-1]), float(peaks.t[-1]) + 0.5 * half)
    w = (ta >= t_start) & (ta <= t_end)
    tw, yw = ta[w], ya[w]
    span = float(np.ptp(ya))
    w_half = math.pi / half
    lo = {
        "omega_n": 0.5 * w_half,
        "zeta": 0.0,
        "friction": 0.0,
        "offset": float(ya.min()),
        "theta0": float(ya.min()) - span,
        "t0": float(peaks.t[k0]) - 0.25 * half,
    }
    hi = {
        "omega_n": 2.0 * w_half,
        "zeta": 0.5,
        "friction": span,
        "offset": float(ya.max()),
        "theta0": float(ya.max()) + span,
        "t0": float(peaks.t[k0]) + 0.25 * half,
    }
    free = _FREE[law]
    base = {"friction": 0.0, "zeta": 0.0}

    def params(x):
        p = dict(base)
        p.update(zip(free, x, strict=True))
        return p

    def resid(x):
        p = params(x)
        return _response(tw, p["omega_n"], p["zeta"], p["friction"], p["offset"], p["theta0"], p["t0"]) - yw

    lb = np.array([lo[k] for k in free])
    ub = np.array([hi[k] for k in free])
    sol = None
    for g in guesses:  # a few starts: the least-squares surface of an oscillation has local minima
        start = {
            "omega_n": g.omega_n,
            "zeta": min(max(g.zeta, 1e-4), 0.4),
            "friction": min(max(g.friction, 1e-3 * span), 0.4 * span),
            "offset": g.offset,
            "theta0": float(peaks.theta[k0]),
            "t0": float(peaks.t[k0]),
        }
        x0 = np.array([start[k] for k in free])
        x0 = np.clip(x0, lb + 1e-9 * (ub - lb), ub - 1e-9 * (ub - lb))
        trial = optimize.least_squares(resid, x0, bounds=(lb, ub), x_scale="jac", max_nfev=MAX_NFEV, method="trf")
        if sol is None or trial.cost < sol.cost:
            sol = trial
    x = sol.x
    r = resid(x)
    # central-difference Jacobian at the solution
    J = np.empty((r.size, x.size))
    scale = np.array([max(abs(v), 1e-3) for v in x])
    for j in range(x.size):
        h = 1e-6 * scale[j]
        xp, xm = x.copy(), x.copy()
        xp[j] += h
        xm[j] -= h
        J[:, j] = (resid(xp) - resid(xm)) / (2.0 * h)
    n, p_free = r.size, x.size
    rss = float(r @ r)
    s2 = rss / max(1, n - p_free)
    bread = np.linalg.pinv(J.T @ J)
    cov_naive = s2 * bread
    dt_med = float(np.median(np.diff(tw)))
    lags = int(min(max(1, round(half / dt_med)), n // 4))
    cov_hac = _hac_cov(J, r, lags, bread) * n / max(1, n - p_free)
    se_n = {k: 0.0 for k in _ALL}
    se_h = {k: 0.0 for k in _ALL}
    for j, k in enumerate(free):
        se_n[k] = float(math.sqrt(max(cov_naive[j, j], 0.0)))
        se_h[k] = float(math.sqrt(max(cov_hac[j, j], 0.0)))
    se = {k: max(se_n[k], se_h[k]) for k in _ALL}
    kpar = p_free + 1
    m2ll = n * math.log(2.0 * math.pi * max(rss, 1e-300) / n) + n
    dw, lb_p = _whiteness(r)
    p = params(x)
    in_window = (peaks.t >= t_start - 1e-12) & (peaks.t <= t_end)
    res = -r
    res.flags.writeable = False
    return FreeDecayFit(
        law=law,
        omega_n=float(p["omega_n"]),
        zeta=float(p["zeta"]),
        friction=float(p["friction"]),
        offset=float(p["offset"]),
        theta0=float(p["theta0"]),
        t0=float(p["t0"]),
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
