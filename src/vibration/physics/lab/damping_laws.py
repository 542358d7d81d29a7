r"""Amplitude-dependent damping laws of a free decay: their terms, equivalent viscous ratio and response.

A law is a sum of the terms of

.. math::

    \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\theta_f\,\mathrm{sgn}\dot\theta
    + \beta\,\dot\theta|\dot\theta| + \alpha|\dot\theta|^n\mathrm{sgn}\dot\theta + \omega_n^2(\theta-\theta_0) = 0

(viscous, Coulomb, quadratic, power). Viscous and Coulomb terms alone have the piecewise closed form of
:mod:`~vibration.physics.lab.coulomb_decay`; with a quadratic or power term the trace is the half-period
energy-balance model (:func:`_response_general`), checked against the numerical integration
:func:`damping_ode`.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from vibration.physics.lab._checks import as_series
from vibration.physics.lab.coulomb_decay import MAX_HALF_CYCLES, MIN_OMEGA_N, _response
from vibration.physics.model import ParameterError, check_real

__all__ = ["ALIASES", "POWER_EXPONENT_RANGE", "TERMS", "damping_ode", "equivalent_zeta", "law_name", "parse_law"]

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
    :math:`2\zeta\omega_n\dot\theta + \beta\dot\theta|\dot\theta| + \alpha|\dot\theta|^n\,\mathrm{sgn}\,\dot\theta`
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
    """Half cycles of the energy-balance model: start times, extrema, centres, ratios and the stop index.

    Computed by the compiled :func:`_half_cycles_kernel` (a decay fit calls this some 10^5 times); the tests
    hold it to the same recurrence written in Python.
    """
    kp = _sine_power_integral(p + 1.0) * omega_n ** (p - 2.0) / math.pi if power else 0.0
    T, e, centre, zk, n, stop = _half_cycles_kernel()(
        float(theta0), float(offset), float(omega_n), float(zeta), float(friction), float(quad), float(power),
        float(p), kp, float(t_span), MAX_HALF_CYCLES,
    )  # fmt: skip
    if n < 0:
        raise ParameterError(
            f"t spans more than {MAX_HALF_CYCLES} half periods which is out of range: allowed at most "
            f"{MAX_HALF_CYCLES} (omega_n * duration too large)"
        )
    return T[: n + 1], e[: n + 1], centre[:n], zk[:n], (n if stop < 0 else stop)


@functools.cache
def _half_cycles_kernel():
    """Compile (once per process, cached on disk) the half-cycle recurrence; numba is imported lazily.

    The kernel returns its arrays with room to spare, the number n of half cycles (-1 when more than
    ``n_max`` were needed) and the stop index (-1 when the trace does not stop within the window).
    """
    import numba

    @numba.njit(cache=True)
    def kernel(theta0, offset, omega_n, zeta, friction, quad, power, p, kp, t_span, n_max):
        cap = 0.9
        size = 64
        T = np.empty(size + 1)
        e = np.empty(size + 1)
        centre = np.empty(size)
        zk = np.empty(size)
        T[0] = 0.0
        e[0] = theta0
        n = 0
        stop = -1
        while T[n] <= t_span:
            if n >= n_max:
                return T, e, centre, zk, -1, -1
            d = e[n] - offset
            if abs(d) <= friction:
                stop = n
                break
            if n == size:  # grow the arrays twofold
                size *= 2
                T2, e2, c2, z2 = np.empty(size + 1), np.empty(size + 1), np.empty(size), np.empty(size)
                T2[: n + 1] = T[: n + 1]
                e2[: n + 1] = e[: n + 1]
                c2[:n] = centre[:n]
                z2[:n] = zk[:n]
                T, e, centre, zk = T2, e2, c2, z2
            c = offset + math.copysign(friction, d)
            a = abs(e[n] - c)
            z = zeta + 4.0 * quad * a / (3.0 * math.pi)
            if power:
                z += power * kp * a ** (p - 1.0)
            z = min(z, cap)
            q = math.exp(-math.pi * z / math.sqrt(1.0 - z * z))
            am = 0.5 * (a + q * a)  # corrector: the ratio at the half period's mean amplitude
            z = zeta + 4.0 * quad * am / (3.0 * math.pi)
            if power:
                z += power * kp * am ** (p - 1.0)
            z = min(z, cap)
            q = math.exp(-math.pi * z / math.sqrt(1.0 - z * z))
            centre[n] = c
            zk[n] = z
            e[n + 1] = c - q * (e[n] - c)
            T[n + 1] = T[n] + math.pi / (omega_n * math.sqrt(1.0 - z * z))
            n += 1
        return T, e, centre, zk, n, stop

    return kernel


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

    Integrates :math:`\ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\theta_f\,\mathrm{sgn}\dot\theta +
    \beta\dot\theta|\dot\theta| + \alpha|\dot\theta|^n\mathrm{sgn}\dot\theta + \omega_n^2(\theta-\theta_0) = 0` from
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
    te = as_series("t_eval", t_eval, unit="s", min_size=2)
    if not np.all(np.diff(te) > 0) or te[0] < 0:
        raise ParameterError("t_eval is not increasing from t >= 0: allowed increasing times (s) from 0")
    omega_n = check_real("omega_n", omega_n, low=MIN_OMEGA_N, high=1e6, unit="rad/s")
    _coefficients_checked(0.0, omega_n, zeta, quadratic, power, power_exponent)
    friction = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    offset = check_real("offset", offset, low=-1e6, high=1e6, unit="rad")
    theta0 = check_real("theta0", theta0, low=-1e6, high=1e6, unit="rad")
    law = (omega_n, zeta, friction, quadratic, power, power_exponent, offset)
    out = np.full(te.size, np.nan)
    t_now, y_now, v_now = 0.0, float(theta0), 0.0
    used = 0
    while t_now < te[-1]:
        d = y_now - offset
        if abs(v_now) < 1e-12 and abs(d) <= friction:
            out[te >= t_now] = y_now
            break
        s = -math.copysign(1.0, d) if abs(v_now) < 1e-12 else math.copysign(1.0, v_now)
        mask = te >= t_now
        sol = _swing(law, s, t_now, float(te[-1]), y_now, v_now, rtol=rtol, atol=atol)
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


def _swing(law, s, t_now, t_stop, y_now, v_now, *, rtol, atol):
    """``solve_ivp`` (DOP853, dense) of one swing of :func:`damping_ode`, moving in direction ``s``, from ``t_now``.

    ``law`` is ``(omega_n, zeta, friction, quadratic, power, power_exponent, offset)``; the integration stops at
    the velocity reversal (a terminal event) or at ``t_stop``.
    """
    from scipy import integrate

    omega_n, zeta, friction, quadratic, power, power_exponent, offset = law
    w2 = omega_n * omega_n

    def rhs(_t, x, s=s):
        v = x[1]
        damp = 2.0 * zeta * omega_n * v + quadratic * v * abs(v) + power * abs(v) ** power_exponent * s
        return [v, -w2 * (x[0] - offset) - w2 * friction * s - damp]

    def reversal(_t, x, s=s, t_from=t_now):
        return x[1] if _t > t_from + 1e-9 else s

    reversal.terminal = True
    reversal.direction = -s
    return integrate.solve_ivp(
        rhs,
        (t_now, t_stop),
        [y_now, v_now],
        method="DOP853",
        rtol=rtol,
        atol=atol,
        events=reversal,
        dense_output=True,
    )
