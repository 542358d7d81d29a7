r"""Steady forced amplitude of a damping law by harmonic balance (one harmonic, equivalent linearisation).

For :math:`\ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\theta_f\,\mathrm{sgn}\dot\theta
+ \beta\dot\theta|\dot\theta| + \alpha|\dot\theta|^n\mathrm{sgn}\dot\theta
+ \omega_n^2\theta = \omega_n^2 G U \sin\omega t` and
:math:`\theta \approx X\sin(\omega t - \varphi)`, the first harmonic of the damping force is
:math:`D(X)\cos(\omega t-\varphi)` with

.. math::

    D(X) = 2\zeta\omega_n\omega X + \frac{8 b\,\omega^2 X^2}{3\pi} + \frac{2 I_{p+1}}{\pi} a(\omega X)^p
    + \frac{4\omega_n^2\theta_f}{\pi}, \qquad I_m = \int_0^\pi \sin^m u\,du,

and the amplitude solves :math:`X^2(\omega_n^2-\omega^2)^2 + D(X)^2 = (\omega_n^2 G U)^2`. The wheel does
not move steadily (X = 0) when :math:`4\omega_n^2\theta_f/\pi \ge \omega_n^2 G U` (Den Hartog's
harmonic-balance limit).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy import optimize

from vibration.physics.checks import check_array
from vibration.physics.lab.decay import _sine_power_integral
from vibration.physics.model import ParameterError, check_real

#: Amplitudes above this (rad) count as unbounded.
X_MAX = 1e6


#: Largest drive frequency (rad/s) of :func:`law_forced_amplitude`: far above it the balance overflows.
MAX_OMEGA = 1e6


def law_forced_amplitude(
    omega, *, omega_n, force, zeta=0.0, friction=0.0, quadratic=0.0, power=0.0, power_exponent=2.0
) -> np.ndarray:
    """Steady amplitude (rad) by harmonic balance at each drive frequency.

    Parameters
    ----------
    omega : float or array_like
        Drive angular frequencies (rad/s), 0 < omega <= 1e6.
    omega_n : float
        Natural angular frequency (rad/s), > 0.
    force : float
        Static deflection g U (rad) the drive would give at zero frequency, >= 0.
    zeta, friction, quadratic, power, power_exponent : float
        The law's coefficients (-, rad, 1/rad, rad^(1-p) s^(p-2), -), all >= 0.

    Returns
    -------
    numpy.ndarray
        X (rad); 0 where friction holds the wheel; ``inf`` where no velocity term bounds it (at
        resonance with ``zeta = 0``, or ``zeta`` so small that the bounded amplitude overflows, and
        no quadratic or power term).

    Examples
    --------
    >>> float(law_forced_amplitude(4.5, omega_n=4.5, force=0.1, zeta=0.05)[0])  # F / (2 zeta)
    1.0
    """
    try:
        raw = np.asarray(omega)
        if raw.dtype.kind not in "iufb":
            raise TypeError(raw.dtype)
        w = np.atleast_1d(raw.astype(float))
    except (TypeError, ValueError):
        raise ParameterError(f"omega = {omega!r:.80} is not a number: allowed finite frequencies > 0 (rad/s)") from None
    if (
        isinstance(omega, (bool, np.bool_))
        or w.ndim != 1
        or not np.all(np.isfinite(w))
        or np.any(w <= 0)
        or np.any(w > MAX_OMEGA)
    ):
        raise ParameterError(
            f"omega = {omega!r:.80} is out of range: allowed frequencies 0 < omega <= {MAX_OMEGA:g} (rad/s)"
        )
    wn = check_real("omega_n", omega_n, low=0.0, low_open=True, high=1e6, unit="rad/s")
    f = check_real("force", force, low=0.0, high=1e6, unit="rad")
    z = check_real("zeta", zeta, low=0.0, high=10.0)
    d = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    b = check_real("quadratic", quadratic, low=0.0, high=1e6, unit="1/rad")
    a = check_real("power", power, low=0.0, high=1e6)
    p = check_real("power_exponent", power_exponent, low=0.0, high=20.0)
    big_f = wn * wn * f
    d0 = 4.0 * wn * wn * d / math.pi
    kp = 2.0 * _sine_power_integral(p + 1.0) / math.pi if a else 0.0
    out = np.empty(w.size)
    for i, om in enumerate(w):
        if d0 >= big_f:
            out[i] = 0.0
            continue
        det = (wn * wn - om * om) ** 2

        def h(x, om=om, det=det):
            dx = 2.0 * z * wn * om * x + 8.0 * b * om * om * x * x / (3.0 * math.pi) + d0
            if a:
                dx += kp * a * (om * x) ** p
            return x * x * det + dx * dx - big_f * big_f

        hi = 1.0
        while h(hi) < 0 and hi < X_MAX:
            hi *= 4.0
        if h(hi) < 0:
            out[i] = math.inf
            continue
        out[i] = optimize.brentq(h, 0.0, hi, xtol=1e-12, rtol=1e-12, maxiter=200)
    return out


#: Largest omega h (drive or natural frequency times the Runge-Kutta step) the simulator accepts.
MAX_OMEGA_STEP = 0.2


def _coefficient_array(name, value, n, *, low, high, unit=""):
    """``value`` (one number, or one per wheel) checked by the shared validator and spread over ``n`` wheels."""
    return np.broadcast_to(check_array(name, value, low=low, high=high, unit=unit), (n,)).copy()


#: Per-wheel arguments of :func:`simulate_driven` and their allowed ranges (low, high, unit).
_WHEEL_RANGES = {
    "omega_n": (1e-9, 1e6, "rad/s"),
    "force": (0.0, 1e6, "rad"),
    "omega": (1e-9, 1e6, "rad/s"),
    "phase": (-1e6, 1e6, "rad"),
    "zeta": (0.0, 10.0, ""),
    "friction": (0.0, 1e6, "rad"),
    "quadratic": (0.0, 1e6, "1/rad"),
    "power": (0.0, 1e6, ""),
    "power_exponent": (0.0, 20.0, ""),
    "theta0": (-1e6, 1e6, "rad"),
    "velocity0": (-1e6, 1e6, "rad/s"),
}


def _record_times(duration, sample_interval, substeps) -> tuple[float, float]:
    """The record's duration and sample interval (s), checked with the number of substeps."""
    dur = check_real("duration", duration, low=0.0, low_open=True, high=1e6, unit="s")
    dt = check_real("sample_interval", sample_interval, low=1e-9, unit="s")
    if dt > dur:
        raise ParameterError(
            f"sample_interval = {dt:g} s is longer than duration = {dur:g} s: allowed sample_interval <= duration"
        )
    if isinstance(substeps, bool) or not isinstance(substeps, (int, np.integer)) or not 1 <= substeps <= 1000:
        raise ParameterError(f"substeps = {substeps!r} is out of range: allowed an integer 1 <= substeps <= 1000")
    return dur, dt


def _wheel_coefficients(args: dict) -> tuple[int, dict]:
    """The number of wheels and every per-wheel argument checked and spread over them (keyed as ``args``)."""
    n = max(int(np.size(v)) for v in args.values())
    for k, v in args.items():
        if np.ndim(v) > 1 or np.size(v) not in (1, n):
            raise ParameterError(f"{k} has {np.size(v)} values: allowed one or {n} (one per wheel)")
    coefficients = {}
    for k, v in args.items():
        low, high, unit = _WHEEL_RANGES[k]
        coefficients[k] = _coefficient_array(k, v, n, low=low, high=high, unit=unit)
    return n, coefficients


def _step_length(wn, om, dt, substeps) -> float:
    """The Runge-Kutta step (s), refused where the drive or natural frequency times it exceeds ``MAX_OMEGA_STEP``."""
    h = dt / substeps
    worst = float(max(wn.max(), om.max())) * h
    if worst > MAX_OMEGA_STEP:
        raise ParameterError(
            f"substeps = {substeps} is out of range: omega h = {worst:.3g} exceeds {MAX_OMEGA_STEP}; allowed at least "
            f"{math.ceil(substeps * worst / MAX_OMEGA_STEP)} steps per sample interval"
        )
    return h


def _sample_count(dur, dt, substeps, n, max_evaluations) -> int:
    """The number of output samples, refused when the wheel-steps exceed ``max_evaluations``."""
    m = int(math.floor(dur / dt + 1e-9)) + 1
    steps = (m - 1) * substeps
    if steps * n > max_evaluations:
        raise ParameterError(
            f"max_evaluations = {max_evaluations} is out of range: {n} wheels over {steps} steps need {steps * n}"
        )
    return m


class _DrivenLaw(NamedTuple):
    """The coefficients of every wheel as the integrator uses them."""

    wn: np.ndarray
    w2: np.ndarray
    f: np.ndarray
    om: np.ndarray
    ph: np.ndarray
    z: np.ndarray
    fric: np.ndarray
    b: np.ndarray
    a: np.ndarray
    p: np.ndarray
    use_power: bool


def _driven_law(c: dict) -> _DrivenLaw:
    """The integrator's coefficients from the checked per-wheel arguments."""
    wn = c["omega_n"]
    w2 = wn * wn
    return _DrivenLaw(
        wn=wn,
        w2=w2,
        f=c["force"],
        om=c["omega"],
        ph=c["phase"],
        z=c["zeta"],
        fric=w2 * c["friction"],
        b=c["quadratic"],
        a=c["power"],
        p=c["power_exponent"],
        use_power=bool(np.any(c["power"] > 0)),
    )


def _drive_torque(law: _DrivenLaw, xx, time):
    """Spring and drive torque per inertia of every wheel (rad/s^2), without damping."""
    return law.w2 * (law.f * np.sin(law.om * time + law.ph) - xx)


def _driven_acceleration(law: _DrivenLaw, xx, vv, time):
    """Angular acceleration of every wheel; 0 for a wheel at rest that friction holds."""
    drive = _drive_torque(law, xx, time)
    s = np.where(vv > 0, 1.0, np.where(vv < 0, -1.0, np.sign(drive)))
    damp = 2.0 * law.z * law.wn * vv + law.b * vv * np.abs(vv)
    if law.use_power:
        damp = damp + law.a * np.abs(vv) ** law.p * s
    out = drive - law.fric * s - damp
    stuck = (vv == 0) & (np.abs(drive) <= law.fric)
    return np.where(stuck, 0.0, out)


def _driven_step(law: _DrivenLaw, x, v, time, h):
    """One Runge-Kutta step of every wheel; a wheel whose velocity reverses where friction holds it stops there."""
    a1 = _driven_acceleration(law, x, v, time)
    a2 = _driven_acceleration(law, x + 0.5 * h * v, v + 0.5 * h * a1, time + 0.5 * h)
    v2 = v + 0.5 * h * a1
    v3 = v + 0.5 * h * a2
    a3 = _driven_acceleration(law, x + 0.5 * h * v2, v3, time + 0.5 * h)
    v4 = v + h * a3
    a4 = _driven_acceleration(law, x + h * v3, v4, time + h)
    x_new = x + h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4)
    v_new = v + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
    time += h
    stop = (v_new * v < 0) & (np.abs(_drive_torque(law, x_new, time)) <= law.fric)
    return x_new, np.where(stop, 0.0, v_new), time


def _integrate_driven(law: _DrivenLaw, x, v, h, substeps, shape) -> np.ndarray:
    """Angles of every wheel (rows) at every sample (columns), ``substeps`` steps apart, from angle x, velocity v."""
    out = np.empty(shape)
    out[:, 0] = x
    time = 0.0
    for i in range(1, shape[1]):
        for _ in range(substeps):
            x, v, time = _driven_step(law, x, v, time, h)
        out[:, i] = x
    return out


def simulate_driven(
    duration,
    *,
    sample_interval,
    omega_n,
    force,
    omega,
    phase=0.0,
    zeta=0.0,
    friction=0.0,
    quadratic=0.0,
    power=0.0,
    power_exponent=2.0,
    theta0=0.0,
    velocity0=0.0,
    substeps=10,
    max_evaluations=50_000_000,
) -> tuple[np.ndarray, np.ndarray]:
    r"""Integrate many driven wheels of a damping law at once from their own start (a bounded simulation).

    .. math::

        \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\theta_f\,\mathrm{sgn}\dot\theta
        + \beta\dot\theta|\dot\theta| + \alpha|\dot\theta|^n\mathrm{sgn}\dot\theta
        + \omega_n^2\theta = \omega_n^2 F \sin(\omega t + \varphi)

    for the angle about the spring's centre, every argument but ``duration``, ``sample_interval``,
    ``substeps`` and ``max_evaluations`` a number or an array of one value per wheel. Scheme: classical
    Runge-Kutta (4th order) with ``substeps`` steps per sample interval, all wheels together; a wheel at
    rest sticks while the spring and drive torque are within the static friction
    (:math:`|\omega_n^2(F\sin(\omega t+\varphi) - \theta)| \le \omega_n^2\theta_f`), and a wheel whose velocity
    reverses inside a step with the torque inside that bound is stopped there. The friction's sign jump is
    not located inside a step, so the error is first order in the step at each reversal: about
    :math:`\omega_n^2\theta_f h` in velocity per reversal; the tests check it against the exact linear steady
    state, the exact Coulomb free decay and the event-located integration of :func:`damping_ode`.

    Parameters
    ----------
    duration : float
        Length of the record (s), > 0.
    sample_interval : float
        Time between output samples (s), > 0, at most ``duration``.
    omega_n : float or array_like
        Natural angular frequency (rad/s), > 0.
    force : float or array_like
        Static deflection F = g U (rad) of the drive, >= 0.
    omega, phase : float or array_like
        Drive angular frequency (rad/s, > 0) and phase (rad) at t = 0.
    zeta, friction, quadratic, power, power_exponent : float or array_like
        The law's coefficients (-, rad, 1/rad, rad^(1-p) s^(p-2), -), all >= 0.
    theta0, velocity0 : float or array_like
        Start angle about the centre (rad) and angular velocity (rad/s).
    substeps : int
        Runge-Kutta steps per sample interval, 1 to 1000; ``omega h`` must stay at most 0.2 for the drive
        and the natural frequency.
    max_evaluations : int
        Budget of wheel-steps (wheels times steps); a larger problem is refused before it starts.

    Returns
    -------
    t : numpy.ndarray
        Sample times (s) from 0, shape (m,).
    theta : numpy.ndarray
        Angle about the centre (rad), shape (wheels, m).

    Examples
    --------
    >>> t, th = simulate_driven(60.0, sample_interval=0.05, omega_n=4.5, force=0.1, omega=4.5, zeta=0.05)
    >>> round(float(np.max(np.abs(th[0, t > 50]))), 3)  # F / (2 zeta) at resonance
    1.0
    """
    dur, dt = _record_times(duration, sample_interval, substeps)
    n, c = _wheel_coefficients(
        {
            "omega_n": omega_n,
            "force": force,
            "omega": omega,
            "phase": phase,
            "zeta": zeta,
            "friction": friction,
            "quadratic": quadratic,
            "power": power,
            "power_exponent": power_exponent,
            "theta0": theta0,
            "velocity0": velocity0,
        }
    )
    h = _step_length(c["omega_n"], c["omega"], dt, substeps)
    m = _sample_count(dur, dt, substeps, n, max_evaluations)
    out = _integrate_driven(_driven_law(c), c["theta0"], c["velocity0"], h, substeps, (n, m))
    if not np.all(np.isfinite(out)):
        raise ParameterError("force is out of range: the simulation diverged; allowed a law that bounds the motion")
    return np.arange(m) * dt, out
