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
from vibration.physics.lab.peaks import MIN_HALF_PERIODS, PeakDecayFit, _peaks, _start, peak_decay_fit
from vibration.physics.model import ParameterError, check_real

#: Smallest natural angular frequency (rad/s) the responses accept: far below it the half period overflows.
MIN_OMEGA_N = 1e-6
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
        Natural angular frequency (rad/s), 1e-6 <= omega_n <= 1e6.
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
    omega_n = check_real("omega_n", omega_n, low=MIN_OMEGA_N, high=1e6, unit="rad/s")
    zeta = check_real("zeta", zeta, low=0.0, high=0.999)
    friction = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    offset = check_real("offset", offset, low=-1e6, high=1e6, unit="rad")
    theta0 = check_real("theta0", theta0, low=-1e6, high=1e6, unit="rad")
    t0 = check_real("t0", t0, low=-1e9, high=1e9, unit="s")
    return _response(ta, omega_n, zeta, friction, offset, theta0, t0)


# ----------------------------------------------------------------------------- amplitude-dependent laws

#: The damping terms a law may combine, in their canonical order.
TERMS = ("coulomb", "viscous", "quadratic", "power")
#: Aliases of laws kept from earlier versions.
ALIASES = {"combined": "coulomb+viscous"}
#: Bounds of the fitted exponent p of the power term.
POWER_EXPONENT_RANGE = (0.5, 8.0)


def parse_law(law) -> tuple[str, ...]:
    """The damping terms of a law string, in canonical order (``"combined"`` is ``"coulomb+viscous"``).

    Parameters
    ----------
    law : str
        ``+``-joined terms out of ``viscous``, ``coulomb``, ``quadratic``, ``power``; not both
        ``quadratic`` and ``power`` (the power term with p = 2 is the quadratic one).

    Returns
    -------
    tuple of str
        The terms, each once, in the order of :data:`TERMS`.

    Examples
    --------
    >>> parse_law("viscous+coulomb"), parse_law("combined")
    (('coulomb', 'viscous'), ('coulomb', 'viscous'))
    """
    if not isinstance(law, str):
        raise ParameterError(f"law = {law!r} is not a string: allowed '+'-joined terms out of {TERMS}")
    name = ALIASES.get(law.strip(), law.strip())
    parts = [p.strip() for p in name.split("+")]
    if not parts or any(p not in TERMS for p in parts) or len(set(parts)) != len(parts):
        raise ParameterError(
            f"law = {law!r} is out of range: allowed '+'-joined distinct terms out of {TERMS} (or 'combined')"
        )
    if "quadratic" in parts and "power" in parts:
        raise ParameterError(
            f"law = {law!r} is out of range: 'quadratic+power' is refused (the power term with p = 2 is the "
            "quadratic one, so the two are not identifiable together)"
        )
    return tuple(t for t in TERMS if t in parts)


def law_name(terms) -> str:
    """The canonical law string of a set of terms (``"coulomb+viscous"``, ...)."""
    return "+".join(t for t in TERMS if t in terms)


def _sine_power_integral(m: float) -> float:
    """int_0^pi sin(u)^m du for m > -1."""
    return math.sqrt(math.pi) * math.exp(math.lgamma((m + 1.0) / 2.0) - math.lgamma(m / 2.0 + 1.0))


def _coefficients_checked(amplitude, omega_n, zeta, quadratic, power, power_exponent) -> np.ndarray:
    if isinstance(amplitude, (str, bytes, bool)):
        raise ParameterError(f"amplitude = {amplitude!r} is not a number: allowed amplitudes >= 0 (rad)")
    try:
        raw = np.asarray(amplitude)
        if raw.dtype.kind not in "iuf" or raw.dtype == bool:
            raise TypeError(raw.dtype)
        x = raw.astype(float)
    except (TypeError, ValueError):
        raise ParameterError(
            f"amplitude = {amplitude!r:.80} is not a number: allowed real amplitudes >= 0 (rad)"
        ) from None
    if x.ndim > 1 or not np.all(np.isfinite(x)) or np.any(x < 0):
        raise ParameterError(f"amplitude = {amplitude!r:.80} is out of range: allowed finite amplitudes >= 0 (rad)")
    check_real("omega_n", omega_n, low=0.0, low_open=True, high=1e6, unit="rad/s")
    check_real("zeta", zeta, low=0.0, high=10.0)
    check_real("quadratic", quadratic, low=0.0, high=1e6, unit="1/rad")
    check_real("power", power, low=0.0, high=1e6)
    check_real("power_exponent", power_exponent, low=0.0, high=20.0)
    return x


def equivalent_zeta(amplitude, omega_n, *, zeta=0.0, quadratic=0.0, power=0.0, power_exponent=2.0):
    r"""Equivalent viscous damping ratio of the velocity-dependent terms at a half-period amplitude.

    Over a half period of :math:`\theta = X\cos\omega_n t` the terms
    :math:`2\zeta\omega_n\dot\theta + b\dot\theta|\dot\theta| + a|\dot\theta|^p\,\mathrm{sgn}\,\dot\theta`
    dissipate as much energy as a viscous term of ratio

    .. math::

        \zeta_{eq}(X) = \zeta + \frac{4 b X}{3\pi} + \frac{a\,\omega_n^{p-2} I_{p+1} X^{p-1}}{\pi},
        \qquad I_m = \int_0^\pi \sin^m u\,du .

    Parameters
    ----------
    amplitude : float or array_like
        Amplitude X (rad), >= 0.
    omega_n : float
        Natural angular frequency (rad/s), > 0.
    zeta, quadratic, power, power_exponent : float
        Viscous ratio, quadratic coefficient b (1/rad), power coefficient a (rad^(1-p) s^(p-2)) and
        its exponent p.

    Returns
    -------
    float or numpy.ndarray
        The equivalent damping ratio (the Coulomb term is not included: it has no viscous equivalent).

    Examples
    --------
    >>> round(float(equivalent_zeta(1.0, 4.5, power=9.0, power_exponent=1.0)), 12)  # a = 2 zeta omega_n
    1.0
    """
    x = _coefficients_checked(amplitude, omega_n, zeta, quadratic, power, power_exponent)
    out = zeta + 4.0 * quadratic * x / (3.0 * math.pi)
    if power:
        out = (
            out
            + power
            * omega_n ** (power_exponent - 2.0)
            * _sine_power_integral(power_exponent + 1.0)
            * np.power(x, power_exponent - 1.0)
            / math.pi
        )
    return out


def _half_cycles(theta0, offset, omega_n, zeta, friction, quad, power, p, t_span):
    """Half cycles of the energy-balance model: start times, extrema, centres, ratios and the stop index."""
    cap = 0.9
    n_max = MAX_HALF_CYCLES
    T = [0.0]
    e = [theta0]
    centre: list[float] = []
    zk: list[float] = []
    stop = None
    kp = _sine_power_integral(p + 1.0) * omega_n ** (p - 2.0) / math.pi if power else 0.0

    def z_of(a):
        z = zeta + 4.0 * quad * a / (3.0 * math.pi)
        if power:
            z += power * kp * a ** (p - 1.0)
        return min(z, cap)

    while T[-1] <= t_span:
        if len(centre) >= n_max:
            raise ParameterError(
                f"t spans more than {n_max} half periods which is out of range: allowed at most {n_max} (omega_n * "
                "duration too large)"
            )
        d = e[-1] - offset
        if abs(d) <= friction:
            stop = len(centre)
            break
        c = offset + math.copysign(friction, d)
        a = abs(e[-1] - c)
        z = z_of(a)
        q = math.exp(-math.pi * z / math.sqrt(1.0 - z * z))
        z = z_of(0.5 * (a + q * a))  # corrector: the ratio at the half period's mean amplitude
        q = math.exp(-math.pi * z / math.sqrt(1.0 - z * z))
        centre.append(c)
        zk.append(z)
        e.append(c - q * (e[-1] - c))
        T.append(T[-1] + math.pi / (omega_n * math.sqrt(1.0 - z * z)))
    n = len(centre)
    return np.asarray(T), np.asarray(e), np.asarray(centre), np.asarray(zk), (n if stop is None else stop)


#: The arguments of :func:`_response_general` after the times, in order.
_GENERAL_ARGS = ("omega_n", "zeta", "friction", "quadratic", "power", "power_exponent", "offset", "theta0", "t0")


def _response_general(t, omega_n, zeta, friction, quad, power, p, offset, theta0, t0):
    """The trace of the energy-balance model (exactly the closed form when quad = power = 0)."""
    if quad == 0.0 and power == 0.0:
        return _response(t, omega_n, zeta, friction, offset, theta0, t0)
    T, e, centre, zk, stop = _half_cycles(theta0, offset, omega_n, zeta, friction, quad, power, p, float(t[-1] - t0))
    out = np.empty_like(t)
    before = t < t0
    z0 = float(zk[0]) if zk.size else zeta
    if before.any():
        tau = t[before] - t0
        d = theta0 - offset
        c_prev = offset - math.copysign(friction, d) if d != 0 else offset
        wd = omega_n * math.sqrt(1.0 - z0 * z0)
        r = z0 / math.sqrt(1.0 - z0 * z0)
        h = np.exp(-z0 * omega_n * tau) * (np.cos(wd * tau) + r * np.sin(wd * tau))
        out[before] = c_prev + (theta0 - c_prev) * h
    after = ~before
    tau_all = t[after] - t0
    if zk.size == 0:
        out[after] = theta0
        return out
    k = np.clip(np.searchsorted(T, tau_all, side="right") - 1, 0, zk.size - 1)
    tau = tau_all - T[k]
    z = zk[k]
    wd = omega_n * np.sqrt(1.0 - z * z)
    r = z / np.sqrt(1.0 - z * z)
    h = np.exp(-z * omega_n * tau) * (np.cos(wd * tau) + r * np.sin(wd * tau))
    val = centre[k] + (e[k] - centre[k]) * h
    stopped = tau_all >= (T[stop] if stop < T.size else np.inf)
    out[after] = np.where(stopped, e[min(stop, e.size - 1)], val)
    return out


def damping_ode(
    t_eval,
    *,
    omega_n,
    zeta=0.0,
    friction=0.0,
    quadratic=0.0,
    power=0.0,
    power_exponent=2.0,
    offset=0.0,
    theta0=1.0,
    rtol=1e-10,
    atol=1e-12,
    max_steps=2_000_000,
):
    r"""The free decay of the full law integrated numerically (an independent check of the fits' model).

    Integrates :math:`\ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\Delta\,\mathrm{sgn}\dot\theta +
    b\dot\theta|\dot\theta| + a|\dot\theta|^p\mathrm{sgn}\dot\theta + \omega_n^2(\theta-\theta_0) = 0` from
    rest at ``theta0`` with :func:`scipy.integrate.solve_ivp` (DOP853), event by event between velocity
    reversals; the wheel sticks at a reversal inside the dead band.

    Parameters
    ----------
    t_eval : array_like
        Increasing times (s) from 0, at most 1 000 000.
    omega_n, zeta, friction, quadratic, power, power_exponent, offset, theta0 : float
        The law's coefficients (rad/s, -, rad, 1/rad, rad^(1-p) s^(p-2), -), the resting angle and
        the start angle (rad); 1e-6 <= omega_n <= 1e6.
    rtol, atol : float
        Tolerances of the integrator.
    max_steps : int
        Budget of right-hand-side evaluations over the whole run.

    Returns
    -------
    numpy.ndarray
        Angle (rad) at ``t_eval``.
    """
    from scipy import integrate

    te = as_series("t_eval", t_eval, unit="s", min_size=2)
    if not np.all(np.diff(te) > 0) or te[0] < 0:
        raise ParameterError("t_eval is not increasing from t >= 0: allowed increasing times (s) from 0")
    omega_n = check_real("omega_n", omega_n, low=MIN_OMEGA_N, high=1e6, unit="rad/s")
    _coefficients_checked(0.0, omega_n, zeta, quadratic, power, power_exponent)
    friction = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    offset = check_real("offset", offset, low=-1e6, high=1e6, unit="rad")
    theta0 = check_real("theta0", theta0, low=-1e6, high=1e6, unit="rad")
    w2 = omega_n * omega_n
    out = np.full(te.size, np.nan)
    t_now, y_now, v_now = 0.0, float(theta0), 0.0
    used = 0
    while t_now < te[-1]:
        d = y_now - offset
        if abs(v_now) < 1e-12 and abs(d) <= friction:
            out[te >= t_now] = y_now
            break
        s = -math.copysign(1.0, d) if abs(v_now) < 1e-12 else math.copysign(1.0, v_now)

        def rhs(_t, x, s=s):
            v = x[1]
            damp = 2.0 * zeta * omega_n * v + quadratic * v * abs(v) + power * abs(v) ** power_exponent * s
            return [v, -w2 * (x[0] - offset) - w2 * friction * s - damp]

        def reversal(_t, x, s=s, t_from=t_now):
            return x[1] if _t > t_from + 1e-9 else s

        reversal.terminal = True
        reversal.direction = -s
        mask = te >= t_now
        sol = integrate.solve_ivp(
            rhs,
            (t_now, float(te[-1])),
            [y_now, v_now],
            method="DOP853",
            rtol=rtol,
            atol=atol,
            events=reversal,
            dense_output=True,
        )
        used += sol.nfev
        if used > max_steps:
            raise ParameterError(f"max_steps = {max_steps} is out of range: the integration needed more")
        t_end = float(sol.t_events[0][0]) if sol.t_events[0].size else float(te[-1])
        seg = mask & (te <= t_end)
        out[seg] = sol.sol(te[seg])[0]
        t_now, y_now, v_now = t_end, float(sol.sol(t_end)[0]), 0.0
        if not sol.t_events[0].size:
            break
    return out


# ----------------------------------------------------------------------------- whole-trace fit


@dataclass(frozen=True, eq=False, kw_only=True)
class FreeDecayFit:
    """Least-squares fit of a damping law's free decay to a whole trace.

    Attributes
    ----------
    law : str
        Canonical ``+``-joined terms (``"coulomb+viscous"``, ``"coulomb+quadratic"``, ...).
    omega_n : float
        Natural angular frequency (rad/s).
    zeta : float
        Viscous damping ratio (0 when the law has no viscous term).
    friction : float
        Coulomb friction angle Delta (rad; 0 without the Coulomb term).
    offset : float
        Resting angle theta_0 of the spring (rad).
    theta0, t0 : float
        Angle (rad) and time (s) of the first extremum, where the fit starts.
    quadratic : float
        Quadratic coefficient b (1/rad) of b theta'|theta'| (0 when absent).
    power, power_exponent : float
        Coefficient a (rad^(1-p) s^(p-2)) and exponent p of a |theta'|^p sgn theta' (0 when absent).
    coefficients : dict
        The fitted terms only: "viscous" (zeta), "coulomb" (Delta, rad), "quadratic" (b, 1/rad),
        "power" (a) and "power_exponent" (p).
    stderr : dict
        Standard errors keyed "omega_n", "zeta", "friction", "offset", "theta0", "t0", "quadratic",
        "power", "power_exponent" (0 for a fixed parameter): the larger of ``stderr_naive`` and
        ``stderr_hac``.
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
        Durbin-Watson statistic of the residuals.
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
    quadratic: float = 0.0
    power: float = 0.0
    power_exponent: float = 0.0
    coefficients: dict = field(default_factory=dict, repr=False)

    def predict(self, t) -> np.ndarray:
        """Fitted angle (rad) at the times ``t`` (s)."""
        ta = as_series("t", t, unit="s", min_size=1)
        if ta.size > 1 and not np.all(np.diff(ta) > 0):
            raise ParameterError("t is not strictly increasing: allowed strictly increasing time (s)")
        return _response_general(
            ta,
            self.omega_n,
            self.zeta,
            self.friction,
            self.quadratic,
            self.power,
            self.power_exponent,
            self.offset,
            self.theta0,
            self.t0,
        )

    def zeta_eq(self, amplitude):
        """Equivalent viscous damping ratio at the half-period amplitude X (rad), Coulomb term included
        as its energy-balance equivalent 2 Delta / (pi X)."""
        x = np.asarray(amplitude, dtype=float)
        z = equivalent_zeta(
            x,
            self.omega_n,
            zeta=self.zeta,
            quadratic=self.quadratic,
            power=self.power,
            power_exponent=self.power_exponent or 2.0,
        )
        with np.errstate(divide="ignore"):
            return z + np.where(x > 0, 2.0 * self.friction / (math.pi * np.maximum(x, 1e-300)), np.inf)


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


def fit_free_decay(t, theta, law: str = "coulomb+viscous") -> FreeDecayFit:
    r"""Fit a damping law's free decay to a whole trace.

    The law is any sum of the terms of

    .. math::

        \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\Delta\,\mathrm{sgn}\dot\theta
        + b\,\dot\theta|\dot\theta| + a|\dot\theta|^p\mathrm{sgn}\dot\theta + \omega_n^2(\theta-\theta_0) = 0

    (viscous zeta, Coulomb Delta in rad, quadratic b in 1/rad, power a with p fitted; ``quadratic+power``
    is refused). Viscous and Coulomb terms alone have a piecewise closed-form solution, which is fitted
    exactly. With a quadratic or power term the trace is the half-period energy-balance model: every
    half cycle between velocity reversals is the closed-form viscous half cycle about the Coulomb
    centre, with the equivalent damping ratio :func:`equivalent_zeta` of the half cycle's mean
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
    >>> t = np.arange(0.0, 10.0, 0.05)
    >>> y = free_decay_response(t, 4.5, 0.01, 0.02, offset=0.05, theta0=1.0)
    >>> f = fit_free_decay(t, y)
    >>> round(f.omega_n, 6), round(f.zeta, 6), round(f.friction, 6), round(f.offset, 6)
    (4.5, 0.01, 0.02, 0.05)
    """
    terms = parse_law(law)
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
    free = _free_params(terms)
    base = {"friction": 0.0, "zeta": 0.0, "quadratic": 0.0, "power": 0.0, "power_exponent": 0.0}

    def params(x):
        p = dict(base)
        p.update(zip(free, x, strict=True))
        if "power" in terms:  # the fitted value is the power term's equivalent ratio at X = 1 rad
            pe = p["power_exponent"]
            p["power"] = p["power"] * math.pi / (_sine_power_integral(pe + 1.0) * p["omega_n"] ** (pe - 2.0))
        return p

    def misfit(p):
        return _response_general(tw, *(p[k] for k in _GENERAL_ARGS)) - yw

    def resid(x):
        return misfit(params(x))

    lb = np.array([lo[k] for k in free])
    ub = np.array([hi[k] for k in free])
    sol = None
    extra = [{}]
    if "power" in terms:
        extra = [{"power_exponent": pe} for pe in (2.0, 4.0)]
    for g in guesses:  # a few starts: the least-squares surface of an oscillation has local minima
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
            x0 = np.array([start[k] for k in free])
            x0 = np.clip(x0, lb + 1e-9 * (ub - lb), ub - 1e-9 * (ub - lb))
            trial = optimize.least_squares(resid, x0, bounds=(lb, ub), x_scale="jac", max_nfev=MAX_NFEV, method="trf")
            if sol is None or trial.cost < sol.cost:
                sol = trial
    x = sol.x
    r = resid(x)
    # central-difference Jacobian at the solution, in the physical parameters
    phys = params(x)
    xp0 = np.array([phys[k] for k in free])

    def resid_phys(v):
        return misfit({**base, **dict(zip(free, v, strict=True))})

    J = np.empty((r.size, xp0.size))
    scale = np.array([max(abs(v), 1e-3) for v in xp0])
    for j in range(xp0.size):
        h = 1e-6 * scale[j]
        xp, xm = xp0.copy(), xp0.copy()
        xp[j] += h
        xm[j] = max(xm[j] - h, 0.0) if free[j] in base else xm[j] - h
        J[:, j] = (resid_phys(xp) - resid_phys(xm)) / (xp[j] - xm[j])
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
    p = phys
    coefficients = {}
    for term, key in (("viscous", "zeta"), ("coulomb", "friction"), ("quadratic", "quadratic"), ("power", "power")):
        if term in terms:
            coefficients[term] = float(p[key])
    if "power" in terms:
        coefficients["power_exponent"] = float(p["power_exponent"])
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
        coefficients=coefficients,
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
