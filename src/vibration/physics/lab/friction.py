r"""Steady forced response with Coulomb + viscous friction, and a stick-slip simulator for measured drives.

Dimensionless model (time in units of :math:`1/\omega_n`, angles in units of
:math:`X_{st} = F_0/k`):

.. math::

    x'' + 2\zeta x' + x + \delta\,\mathrm{sgn}(x') = \cos(r\tau + \varphi),
    \qquad r = \omega/\omega_n, \quad \delta = \theta_f / X_{st}.

Den Hartog (1931, "Forced vibrations with combined Coulomb and viscous friction", Trans. ASME
APM-53-9, 107-115) solved it exactly for the steady motion with two velocity reversals per
period and no stops: in the half period :math:`0 < \tau < \pi/r` the velocity is positive, the
equation is linear with the constant :math:`-\delta` on the right, and the four conditions
:math:`x(0) = -X`, :math:`x'(0) = 0`, :math:`x(\pi/r) = X`, :math:`x'(\pi/r) = 0` fix the two
constants of the free solution and the force phase :math:`\varphi` for a given amplitude
:math:`X`; the phase must satisfy :math:`\cos^2\varphi + \sin^2\varphi = 1`, a quadratic in
:math:`X`. :func:`friction_forced_amplitude` solves exactly these equations (linear algebra plus
one quadratic, no simulation) and then checks Den Hartog's non-stop condition: the velocity must
stay positive over the whole half period (checked on 2000 points plus the start, where the
acceleration must be positive, i.e. the force overcomes the static friction). Where it fails the
motion has stops and the function returns NaN. For :math:`\zeta = 0` it reduces to Den Hartog's
1930 pure-Coulomb result :math:`X/X_{st} = \sqrt{V_0^2 - \delta^2 U^2}` with
:math:`V_0 = 1/(1-r^2)` and :math:`U = \sin(\pi/r) / (r(1+\cos(\pi/r)))`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from vibration.physics.lab._checks import as_series
from vibration.physics.model import ParameterError, check_real

#: Largest number of frequency ratios one call evaluates.
MAX_RATIOS = 100_000
#: Points per half period on which the non-stop condition is checked.
N_CHECK = 2000
#: Smallest frequency ratio accepted: below it the half period pi / r overflows.
MIN_RATIO = 1e-6
#: Largest number of integration steps of :func:`simulate_friction_oscillator`.
MAX_STEPS = 5_000_000


def _as_ratios(r):
    scalar = np.ndim(r) == 0
    if scalar:
        rv = np.array([check_real("r", r, low=MIN_RATIO, high=1e3)])
    else:
        rv = as_series("r", r, min_size=1)
        if rv.size > MAX_RATIOS:
            raise ParameterError(f"r has {rv.size} values which is out of range: allowed at most {MAX_RATIOS}")
        bad = ~((rv >= MIN_RATIO) & (rv <= 1e3))
        if bad.any():
            i = int(np.argmax(bad))
            raise ParameterError(f"r[{i}] = {rv[i]!r} is out of range: allowed {MIN_RATIO:g} <= r <= 1000")
    return rv, scalar


def _particular(r: float, hr: float, hi: float, tau: float) -> tuple[float, float, float, float]:
    """(x, x') coefficients of c and of s of the particular response to ``c cos(r tau) - s sin(r tau)``.

    The response is Re(H (c + i s) e^{i r tau}) with H = hr + i hi; returns (xc, xs, vc, vs).
    """
    ct, st = math.cos(r * tau), math.sin(r * tau)
    xc, xs = hr * ct - hi * st, -(hr * st + hi * ct)
    vc, vs = r * (-hr * st - hi * ct), -r * (hr * ct - hi * st)
    return xc, xs, vc, vs


def _free(zeta: float, wd: float, tau: float) -> tuple[float, float, float, float]:
    """(x, x') of the two free solutions e^{-zeta tau} cos(wd tau) and e^{-zeta tau} sin(wd tau): (x1, x2, v1, v2)."""
    e = math.exp(-zeta * tau)
    c1, s1 = math.cos(wd * tau), math.sin(wd * tau)
    x1, x2 = e * c1, e * s1
    v1, v2 = e * (-zeta * c1 - wd * s1), e * (-zeta * s1 + wd * c1)
    return x1, x2, v1, v2


def _half_period_solutions(r, zeta, wd, hr, hi, half, delta):
    """The unknowns u = (c, s, A, B) as u0 + X u1 from the half period's four end conditions, or None if singular.

    The conditions are x(0) + X = 0, x'(0) = 0, x(half) - X = 0, x'(half) = 0, with x = part + free - delta.
    """
    M = np.zeros((4, 4))
    rhs_const = np.zeros(4)
    rhs_x = np.zeros(4)
    for row, (tau, which, sx) in enumerate([(0.0, 0, 1.0), (0.0, 1, 0.0), (half, 0, -1.0), (half, 1, 0.0)]):
        xc, xs, vc, vs = _particular(r, hr, hi, tau)
        x1, x2, v1, v2 = _free(zeta, wd, tau)
        if which == 0:
            M[row] = [xc, xs, x1, x2]
            rhs_const[row] = delta
            rhs_x[row] = -sx
        else:
            M[row] = [vc, vs, v1, v2]
    try:
        u0 = np.linalg.solve(M, rhs_const)
        u1 = np.linalg.solve(M, rhs_x)
    except np.linalg.LinAlgError:
        return None
    return u0, u1


def _phase_amplitude(u0, u1):
    """The positive root X of c^2 + s^2 = 1 with (c, s) = u0[:2] + X u1[:2], or None."""
    a = float(u1[:2] @ u1[:2])
    b = 2.0 * float(u0[:2] @ u1[:2])
    cc = float(u0[:2] @ u0[:2]) - 1.0
    disc = b * b - 4.0 * a * cc
    if a == 0.0 or disc < 0.0:
        return None
    X = (-b + math.sqrt(disc)) / (2.0 * a)
    if not X > 0.0:
        return None
    return X


def _slides_through(r, zeta, wd, hr, hi, half, u) -> bool:
    """Whether the velocity of the solution u = (c, s, A, B) stays > 0 inside the half period (N_CHECK points)."""
    c, s, A, B = u
    tau = np.linspace(0.0, half, N_CHECK + 1)[1:-1]
    ct, st = np.cos(r * tau), np.sin(r * tau)
    e = np.exp(-zeta * tau)
    v = (
        c * r * (-hr * st - hi * ct)
        + s * (-r) * (hr * ct - hi * st)
        + A * e * (-zeta * np.cos(wd * tau) - wd * np.sin(wd * tau))
        + B * e * (-zeta * np.sin(wd * tau) + wd * np.cos(wd * tau))
    )
    return not np.any(v <= 0.0)


def _den_hartog_one(r: float, zeta: float, delta: float) -> float:
    """Exact two-reversal steady amplitude X/X_st at one frequency ratio, NaN when it has stops."""
    half = math.pi / r
    # particular response to cos(r tau) and sin(r tau): H = 1 / (1 - r^2 + 2 i zeta r)
    den = (1.0 - r * r) ** 2 + (2.0 * zeta * r) ** 2
    if den == 0.0:  # undamped resonance: the force's work per cycle (pi F0 X) outgrows friction's (4 F X)
        return math.inf if 4.0 * delta / math.pi < 1.0 else math.nan
    hr, hi = (1.0 - r * r) / den, -2.0 * zeta * r / den
    if not zeta < 1.0:
        return math.nan
    wd = math.sqrt(1.0 - zeta * zeta)
    solutions = _half_period_solutions(r, zeta, wd, hr, hi, half, delta)
    if solutions is None:
        return math.nan
    u0, u1 = solutions
    X = _phase_amplitude(u0, u1)
    if X is None:
        return math.nan
    u = u0 + X * u1
    # non-stop condition: velocity > 0 inside the half period; force overcomes friction at the start
    if not _slides_through(r, zeta, wd, hr, hi, half, u):
        return math.nan
    if u[0] + X - delta <= 0.0:  # x''(0+) = cos(phi) - x(0) - delta must be > 0 (x(0) = -X, x'(0) = 0)
        return math.nan
    return float(X)


def friction_forced_amplitude(r, zeta, friction_ratio):
    r"""Exact steady amplitude ratio X / X_st with combined Coulomb and viscous friction (Den Hartog 1931).

    Parameters
    ----------
    r : float or array_like
        Frequency ratio omega / omega_n (1e-6 <= r <= 1000; up to 100 000 values).
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    friction_ratio : float
        Coulomb friction over the static deflection, Delta / X_st = F_friction / F0 (>= 0).

    Returns
    -------
    float or numpy.ndarray
        X / X_st (dimensionless; X in rad when X_st is): NaN where the steady motion is not
        continuous (Den Hartog's non-stop condition fails, or the force cannot overcome friction);
        ``inf`` at ``r = 1`` without viscous damping (``zeta = 0``, or so small that
        ``(2 zeta r)^2`` underflows) when ``4 friction_ratio / pi < 1`` (the force's work per cycle
        then outgrows friction's at every amplitude: no steady state); a float for a scalar ``r``.

    Notes
    -----
    Exact for the two-reversal, non-stop steady motion (module docstring). With
    ``friction_ratio = 0`` it is the linear magnification ``1 / sqrt((1 - r^2)^2 + (2 zeta r)^2)``.
    Near ``r = 1/n`` for odd ``n`` without damping the pure-Coulomb formula has resonances of its
    own; the value is returned as computed.

    Examples
    --------
    >>> round(friction_forced_amplitude(0.5, 0.1, 0.0), 12) == round(1 / ((1 - 0.25) ** 2 + 0.01) ** 0.5, 12)
    True
    >>> round(friction_forced_amplitude(1.5, 0.0, 0.2), 4)  # Den Hartog's pure Coulomb result
    0.7659
    >>> friction_forced_amplitude(1.0, 0.0, 0.2), friction_forced_amplitude(1.0, 0.0, 0.9)
    (inf, nan)
    """
    rv, scalar = _as_ratios(r)
    z = check_real("zeta", zeta, low=0.0, high=0.999)
    d = check_real("friction_ratio", friction_ratio, low=0.0, high=1e6)
    out = np.array([_den_hartog_one(float(x), z, d) for x in rv])
    if d == 0.0:  # linear: closed form, exact (the non-stop check is trivially true)
        den = np.sqrt((1.0 - rv * rv) ** 2 + (2.0 * z * rv) ** 2)
        out = np.divide(1.0, den, out=np.full_like(den, np.inf), where=den > 0)
    return float(out[0]) if scalar else out


def friction_forced_amplitude_hb(r, zeta, friction_ratio):
    r"""Harmonic-balance (equivalent viscous damping) amplitude ratio X / X_st.

    Coulomb friction is replaced by the viscous damping that dissipates the same energy per
    cycle at amplitude X, :math:`c_{eq} = 4F/(\pi\omega X)`, which gives
    :math:`(1-r^2)^2 X^2 + (2\zeta r X + 4\delta/\pi)^2 = 1` (X in units of X_st). NaN where no
    positive root exists (:math:`4\delta/\pi \ge 1`: the force cannot keep the motion going).

    Parameters
    ----------
    r : float or array_like
        Frequency ratio omega / omega_n (1e-6 <= r <= 1000).
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    friction_ratio : float
        Delta / X_st (>= 0).

    Returns
    -------
    float or numpy.ndarray
        X / X_st, NaN where there is no continuous motion, ``inf`` where
        :func:`friction_forced_amplitude` gives it.

    Examples
    --------
    >>> round(friction_forced_amplitude_hb(1.5, 0.0, 0.2), 4)
    0.7736
    >>> friction_forced_amplitude_hb(1.0, 0.0, 0.2)
    inf
    """
    rv, scalar = _as_ratios(r)
    z = check_real("zeta", zeta, low=0.0, high=0.999)
    d = check_real("friction_ratio", friction_ratio, low=0.0, high=1e6)
    g = 4.0 * d / math.pi
    a = (1.0 - rv * rv) ** 2 + (2.0 * z * rv) ** 2
    b = 2.0 * (2.0 * z * rv) * g
    c = g * g - 1.0
    disc = b * b - 4.0 * a * c
    with np.errstate(invalid="ignore", divide="ignore"):
        X = (-b + np.sqrt(np.where(disc >= 0, disc, np.nan))) / (2.0 * a)
    X = np.where((X > 0) & (c < 0), X, np.nan)
    X = np.where((a == 0.0) & (c < 0), np.inf, X)  # undamped resonance that friction cannot hold
    return float(X[0]) if scalar else X


def _time_and_drive(t, drive) -> tuple[np.ndarray, np.ndarray]:
    """The sample times (s), strictly increasing, and the drive signal at them, checked."""
    ta = as_series("t", t, unit="s", min_size=2)
    da = as_series("drive", drive, min_size=2)
    if da.size != ta.size:
        raise ParameterError(f"drive has {da.size} samples and t has {ta.size}: allowed the same number of samples")
    if not np.all(np.diff(ta) > 0):
        raise ParameterError("t is not strictly increasing: allowed strictly increasing time (s)")
    return ta, da


def _check_substeps(substeps, n_samples: int) -> None:
    """Refuse a number of substeps outside 1 to 1000, or more than ``MAX_STEPS`` steps over ``n_samples`` samples."""
    if isinstance(substeps, bool) or not isinstance(substeps, int) or not 1 <= substeps <= 1000:
        raise ParameterError(f"substeps = {substeps!r} is out of range: allowed integer 1 <= substeps <= 1000")
    if (n_samples - 1) * substeps > MAX_STEPS:
        raise ParameterError(
            f"t has {n_samples} samples which with substeps = {substeps} is out of range: allowed at most "
            f"{MAX_STEPS} steps in all"
        )


class _FrictionModel(NamedTuple):
    """The checked inputs of :func:`simulate_friction_oscillator` as its integrator uses them."""

    ta: np.ndarray  # sample times, s
    da: np.ndarray  # drive at the sample times
    w: float  # omega_n, rad/s
    w2: float  # omega_n^2
    z: float  # zeta
    fr: float  # friction angle, rad
    g: float  # gain
    c: float  # offset, rad


def _drive_at(m: _FrictionModel, time, k):
    """The drive at ``time`` inside sample interval ``k``, interpolated linearly."""
    t0, t1 = m.ta[k], m.ta[k + 1]
    return m.da[k] + (m.da[k + 1] - m.da[k]) * (time - t0) / (t1 - t0)


def _friction_acceleration(m: _FrictionModel, x, vel, s, time, k):
    """Angular acceleration while sliding in direction ``s`` (+1 or -1)."""
    return -2.0 * m.z * m.w * vel - m.w2 * (x - m.c) - m.w2 * m.fr * s + m.w2 * m.g * _drive_at(m, time, k)


def _net_torque(m: _FrictionModel, x, time, k):
    """Spring + drive torque per inertia, without friction."""
    return -m.w2 * (x - m.c) + m.w2 * m.g * _drive_at(m, time, k)


def _friction_rk4(m: _FrictionModel, x, vel, s, time, h, k):
    """One classical Runge-Kutta step of length ``h`` sliding in direction ``s``: (angle, velocity)."""
    a1 = _friction_acceleration(m, x, vel, s, time, k)
    x2, v2 = x + 0.5 * h * vel, vel + 0.5 * h * a1
    a2 = _friction_acceleration(m, x2, v2, s, time + 0.5 * h, k)
    x3, v3 = x + 0.5 * h * v2, vel + 0.5 * h * a2
    a3 = _friction_acceleration(m, x3, v3, s, time + 0.5 * h, k)
    x4, v4 = x + h * v3, vel + h * a3
    a4 = _friction_acceleration(m, x4, v4, s, time + h, k)
    return x + h / 6.0 * (vel + 2 * v2 + 2 * v3 + v4), vel + h / 6.0 * (a1 + 2 * a2 + 2 * a3 + a4)


def _reversal_step(m: _FrictionModel, th, v, s, time, remaining, k):
    """The step length (at most ``remaining``) to the velocity reversal, by bisection to 1e-12 of ``remaining``."""
    lo_h, hi_h = 0.0, remaining
    for _ in range(60):
        mid = 0.5 * (lo_h + hi_h)
        _, vm = _friction_rk4(m, th, v, s, time, mid, k)
        if vm * s > 0.0:
            lo_h = mid
        else:
            hi_h = mid
        if hi_h - lo_h <= 1e-12 * remaining:
            break
    return hi_h


def _friction_substep(m: _FrictionModel, th, v, time, h, k):
    """Advance (angle, velocity, time) by one substep ``h``: stuck, sliding, or sliding to a reversal and on."""
    remaining = h
    guard = 0
    while remaining > 0.0 and guard < 8:
        guard += 1
        if v == 0.0:
            f = _net_torque(m, th, time, k)
            if abs(f) <= m.w2 * m.fr:  # stuck for this (sub)step
                return th, v, time + remaining
            s = 1.0 if f > 0 else -1.0
        else:
            s = 1.0 if v > 0 else -1.0
        x1, v1 = _friction_rk4(m, th, v, s, time, remaining, k)
        if v1 * s >= 0.0 or (v == 0.0 and v1 * s > 0.0):
            return x1, v1, time + remaining
        hi_h = _reversal_step(m, th, v, s, time, remaining, k)  # velocity reverses inside
        th, _ = _friction_rk4(m, th, v, s, time, hi_h, k)
        v = 0.0
        time += hi_h
        remaining -= hi_h
    return th, v, time


def _integrate_friction(m: _FrictionModel, th, v, substeps) -> tuple[np.ndarray, np.ndarray]:
    """Angle and velocity at the sample times from (th, v) at the first, ``substeps`` steps per interval."""
    out_th = np.empty(m.ta.size)
    out_v = np.empty(m.ta.size)
    out_th[0], out_v[0] = th, v
    for k in range(m.ta.size - 1):
        h = (m.ta[k + 1] - m.ta[k]) / substeps
        time = m.ta[k]
        for _ in range(substeps):
            th, v, time = _friction_substep(m, th, v, time, h, k)
        out_th[k + 1], out_v[k + 1] = th, v
    return out_th, out_v


def simulate_friction_oscillator(
    t, drive, omega_n, *, zeta, friction, gain, theta0=0.0, omega0=0.0, offset=0.0, substeps=20
) -> tuple[np.ndarray, np.ndarray]:
    r"""Integrate the oscillator with viscous + Coulomb friction (stick-slip) under a measured drive.

    .. math::

        \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2(\theta - \theta_0) + \omega_n^2\theta_f\,
        \mathrm{sgn}(\dot\theta) = \omega_n^2\,g\,d(t)

    with ``d(t)`` the drive sampled at ``t`` and interpolated linearly. Scheme: classical
    Runge-Kutta (4th order) with ``substeps`` steps per sample interval while the wheel slides;
    a velocity reversal inside a step is located by bisection on the step length (to 1e-12 of
    the step), and there the wheel sticks if the spring and drive torque are within the static
    friction, :math:`|\omega_n^2(\theta - \theta_0) - \omega_n^2 G d(t)| \le \omega_n^2\theta_f`, and
    stays stuck until that fails. Error: fourth order in the step between events, i.e. a
    relative error of about :math:`(\omega_n h)^4 / 100` per period for ``h = dt / substeps``
    (below 1e-6 for omega_n dt = 0.25 and 20 substeps); the test checks 1e-6 against the exact
    linear solution and the exact free decay.

    Parameters
    ----------
    t : array_like
        Sample times (s), strictly increasing; the output is at these times.
    drive : array_like
        Drive signal at ``t`` (rad, or any unit that ``gain`` turns into rad).
    omega_n : float
        Natural angular frequency (rad/s), > 0.
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    friction : float
        Coulomb friction angle Delta (rad), >= 0.
    gain : float
        Static angle per unit drive (rad per drive unit).
    theta0, omega0 : float
        Initial angle (rad) and angular velocity (rad/s) at ``t[0]``.
    offset : float
        Resting angle c of the spring (rad).
    substeps : int
        Runge-Kutta steps per sample interval (1 to 1000); at most 5 000 000 steps in all.

    Returns
    -------
    theta, velocity : numpy.ndarray
        Angle (rad) and angular velocity (rad/s) at ``t``.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0.0, 2 * np.pi / 4.5, 41)
    >>> th, _ = simulate_friction_oscillator(t, np.zeros_like(t), 4.5, zeta=0.0, friction=0.0, gain=1.0, theta0=1.0)
    >>> round(float(th[-1]), 8)  # one undamped period later
    1.0
    """
    ta, da = _time_and_drive(t, drive)
    w = check_real("omega_n", omega_n, low=0.0, low_open=True, high=1e6, unit="rad/s")
    z = check_real("zeta", zeta, low=0.0, high=0.999)
    fr = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    g = check_real("gain", gain, low=-1e9, high=1e9, unit="rad per drive unit")
    th = check_real("theta0", theta0, low=-1e9, high=1e9, unit="rad")
    v = check_real("omega0", omega0, low=-1e9, high=1e9, unit="rad/s")
    c = check_real("offset", offset, low=-1e9, high=1e9, unit="rad")
    _check_substeps(substeps, ta.size)
    model = _FrictionModel(ta=ta, da=da, w=w, w2=w * w, z=z, fr=fr, g=g, c=c)
    return _integrate_friction(model, th, v, substeps)
