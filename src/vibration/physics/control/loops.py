"""What separates feedback laws beyond the amplitude they reach: loop margins, noise and force floors.

The loop of a PD or PID law ``C(s) = kp + kd s + ki / s`` around the plant
``P(s) = 1 / (m s^2 + c s + k)`` (force to displacement; SI units):

* :func:`loop_costs`: gain crossover frequencies, phase margin, **delay margin** (the smallest
  pure time delay in the loop that makes it unstable, s), the loop gain ``|L(i omega)|`` at the
  forcing frequency, and the **noise bandwidth** ``B_n = int_0^inf |T(i w)|^2 dw`` of the
  complementary sensitivity ``T = L / (1 + L)``: white position-sensor noise of two-sided density
  ``S_n`` (m^2 s/rad) moves the mass with variance ``2 S_n B_n``. The force the noise causes grows
  like ``kd w`` above crossover, so ``kd`` is the law's high-frequency noise gain.
* :func:`force_floor`: the least RMS force any controller needs to hold a steady amplitude X at the
  forcing frequency, ``(F0 - |k - m w^2 + i c w| X) / sqrt(2)`` (the fundamental of the force must
  supply what the plant does not): at X = 0 it is ``F0 / sqrt(2)``, the asymptote of every
  high-gain design.
* :func:`hold_force` and :func:`largest_holdable_reference`: the peak force that holds the mass
  exactly at a set point against ``F0 sin(omega t)`` is ``k |x_ref| + F0``.
* :func:`pid_poles`: the closed-loop poles of a PID law, described as a real pole and a pair.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, SineForce, check_real

__all__ = [
    "LoopCosts",
    "PIDPoles",
    "force_floor",
    "hold_force",
    "largest_holdable_reference",
    "loop_costs",
    "pid_poles",
]


@dataclass(frozen=True, kw_only=True)
class LoopCosts:
    """Robustness and noise costs of the loop ``C(s) = kp + kd s + ki/s`` around ``1/(m s^2 + c s + k)``."""

    kp: float  # proportional gain, N/m
    ki: float  # integral gain, N/(m s)
    kd: float  # derivative gain, N s/m
    stable: bool  # the closed loop without delay is asymptotically stable
    crossovers: np.ndarray  # gain crossover frequencies |L(i w)| = 1, rad/s
    crossover: float  # the crossover that sets the delay margin, rad/s (nan: none)
    phase_margin: float  # phase margin at that crossover, rad
    delay_margin: float  # smallest loop delay that destabilises, s (inf: none does)
    loop_gain: float  # |L(i omega)| at the forcing frequency, 1
    noise_bandwidth: float  # int_0^inf |T(i w)|^2 dw, rad/s
    hf_noise_gain: float  # kd: force per unit sensor-noise velocity at high frequency, N s/m


def _gains(osc, kp, ki, kd):
    check_oscillator(osc)
    kp = check_real("kp", kp, low=-osc.k, low_open=True, unit="N/m")
    ki = check_real("ki", ki, low=0.0, unit="N/(m s)")
    kd = check_real("kd", kd, unit="N s/m")
    return kp, ki, kd


def _closed_loop_den(osc, kp, ki, kd) -> np.ndarray:
    m, c, k = osc.m, osc.c, osc.k
    if ki > 0.0:
        return np.array([m, c + kd, k + kp, ki])
    return np.array([m, c + kd, k + kp])


def _loop(osc, kp, ki, kd, w):
    w = np.asarray(w, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        C = kp + 1j * kd * w + (ki / (1j * w) if ki > 0.0 else 0.0)
    return C / (osc.k - osc.m * w * w + 1j * osc.c * w)


def loop_costs(osc: Oscillator, kp: float, kd: float, *, ki: float = 0.0, omega: float = 0.0) -> LoopCosts:
    """Delay margin, phase margin, crossover, loop gain at ``omega`` and noise bandwidth of a PD/PID loop.

    The crossovers solve ``|C(i w)|^2 = |k - m w^2 + i c w|^2``, a cubic in ``w^2`` (a quadratic
    without the integrator). At each crossover ``w_i`` a delay ``tau`` turns ``L`` by ``-w_i tau``;
    the loop reaches ``-1`` first at ``tau_i = ((pi + arg L(i w_i)) mod 2 pi) / w_i``, and the delay
    margin is the smallest ``tau_i`` (infinite without a crossover: then ``|L| < 1`` everywhere and no
    delay destabilises). The noise bandwidth is ``pi ||T||_2^2`` from the controllability Gramian of
    ``T = N / D``, ``N = kd s^2 + kp s + ki``, ``D = s (m s^2 + c s + k) + N`` (divided by ``s`` without
    the integrator).

    Parameters
    ----------
    osc : Oscillator
        Plant: m (kg), c (N s/m), k (N/m).
    kp, kd, ki : float
        Gains: N/m (``k + kp > 0``), N s/m, N/(m s) (>= 0; 0 is a PD law).
    omega : float
        Forcing frequency at which the loop gain is reported, rad/s (> 0).

    Returns
    -------
    LoopCosts

    Examples
    --------
    >>> lc = loop_costs(Oscillator(m=1.0, c=0.5, k=20.0), kp=16.0, kd=5.5, omega=4.47)
    >>> round(lc.delay_margin, 3), round(lc.crossover, 3)      # s, rad/s
    (0.16, 8.239)
    """
    kp, ki, kd = _gains(osc, kp, ki, kd)
    omega = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    den = _closed_loop_den(osc, kp, ki, kd)
    if not np.all(np.isfinite(den)):
        raise ParameterError(f"kp = {kp!r}, ki = {ki!r}, kd = {kd!r}: the loop overflows; allowed finite gains")
    stable = bool(np.all(np.real(np.roots(den)) < 0.0))
    w_c = _crossovers(osc, kp, ki, kd)
    crossover, phase_margin, delay = _delay_margin(osc, kp, ki, kd, w_c)
    if not stable:
        delay = 0.0
    bn = _noise_bandwidth(kp, ki, kd, den, stable)
    return LoopCosts(
        kp=kp,
        ki=ki,
        kd=kd,
        stable=stable,
        crossovers=w_c,
        crossover=crossover,
        phase_margin=phase_margin,
        delay_margin=delay,
        loop_gain=float(np.abs(_loop(osc, kp, ki, kd, omega))),
        noise_bandwidth=bn,
        hf_noise_gain=kd,
    )


def _crossovers(osc, kp, ki, kd) -> np.ndarray:
    """The gain crossovers ``|L(i w)| = 1`` (rad/s, ascending): the positive real roots of the polynomial in ``w^2``,
    polished by Newton steps on ``log|L|``."""
    m, c, k = osc.m, osc.c, osc.k
    if ki > 0.0:
        poly = [m * m, c * c - 2.0 * k * m - kd * kd, k * k - kp * kp + 2.0 * ki * kd, -ki * ki]
    else:
        poly = [m * m, c * c - 2.0 * k * m - kd * kd, k * k - kp * kp]
    roots = np.roots(poly)
    u = np.sort(np.real(roots[(np.abs(np.imag(roots)) <= 1e-9 * np.abs(roots)) & (np.real(roots) > 0.0)]))
    w_c = np.sqrt(u)
    # polish on |L| = 1 with Newton steps on log|L| (a derivative by a complex step of the rational L)
    for _ in range(3):
        h = 1e-7 * w_c
        g = np.log(np.abs(_loop(osc, kp, ki, kd, w_c)))
        dg = (np.log(np.abs(_loop(osc, kp, ki, kd, w_c + h))) - np.log(np.abs(_loop(osc, kp, ki, kd, w_c - h)))) / (
            2 * h
        )
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(dg != 0.0, g / dg, 0.0)
        w_c = np.where(np.abs(step) < 0.1 * w_c, w_c - step, w_c)
    return w_c


def _delay_margin(osc, kp, ki, kd, w_c: np.ndarray) -> tuple[float, float, float]:
    """``(crossover, phase margin, delay margin)`` of the crossover that the least delay destabilises (rad/s, rad,
    s); ``(nan, inf, inf)`` without a crossover."""
    if w_c.size:
        pm = np.mod(math.pi + np.angle(_loop(osc, kp, ki, kd, w_c)), 2.0 * math.pi)
        tau = pm / w_c
        i = int(np.argmin(tau))
        return float(w_c[i]), float(pm[i]), float(tau[i])
    return math.nan, math.inf, math.inf


def _noise_bandwidth(kp, ki, kd, den: np.ndarray, stable: bool) -> float:
    """``pi ||T||_2^2`` of ``T = N / D`` from the controllability Gramian, rad/s (inf for an unstable loop)."""
    from scipy.linalg import solve_continuous_lyapunov
    from scipy.signal import tf2ss

    num = np.array([kd, kp, ki]) if ki > 0.0 else np.array([kd, kp])
    if stable:
        A, B, Cm, _ = tf2ss(num, den)
        W = solve_continuous_lyapunov(A, -B @ B.T)
        return math.pi * float((Cm @ W @ Cm.T)[0, 0])
    return math.inf


def force_floor(osc: Oscillator, force: SineForce, X) -> np.ndarray | float:
    """Least steady RMS force (N) with which any controller holds the amplitude ``X`` (m) at ``force.omega``.

    With ``x = X sin(omega t + phi)`` the force's fundamental must be ``Z X e^{i phi} - F0``,
    ``Z = k - m omega^2 + i c omega``; over the phase its least amplitude is ``|F0 - |Z| X|``, and no
    force has a smaller RMS than its fundamental: ``u_rms >= |F0 - |Z| X| / sqrt(2)``.

    Examples
    --------
    >>> round(force_floor(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47), 0.0), 4)   # F0/sqrt(2), N
    3.5355
    """
    check_oscillator(osc)
    if not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed SineForce(F0, omega)")
    X = np.asarray(X, dtype=float)
    if not np.all(np.isfinite(X)) or np.any(X < 0.0):
        raise ParameterError(f"X = {X!r} m: allowed finite amplitudes >= 0 m")
    w = force.omega
    z = abs(complex(osc.k - osc.m * w * w, osc.c * w))
    out = np.abs(force.F0 - z * X) / math.sqrt(2.0)
    return float(out) if out.ndim == 0 else out


def hold_force(osc: Oscillator, force: SineForce | None, x_ref: float) -> float:
    """Peak force (N) that holds the mass exactly at ``x_ref`` (m) against ``F0 sin(omega t)``: ``k |x_ref| + F0``.

    Examples
    --------
    >>> hold_force(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47), 0.5)
    15.0
    """
    check_oscillator(osc)
    x_ref = check_real("x_ref", x_ref, unit="m")
    F0 = 0.0 if force is None else abs(force.F0)
    return osc.k * abs(x_ref) + F0


def largest_holdable_reference(osc: Oscillator, force: SineForce | None, u_max: float) -> float:
    """Largest set point (m) a force limited to ``u_max`` (N) can hold exactly: ``(u_max - F0) / k`` (nan if < 0)."""
    check_oscillator(osc)
    u_max = check_real("u_max", u_max, low=0.0, low_open=True, unit="N")
    F0 = 0.0 if force is None else abs(force.F0)
    return (u_max - F0) / osc.k if u_max >= F0 else math.nan


@dataclass(frozen=True, kw_only=True)
class PIDPoles:
    """Closed-loop poles of ``m s^3 + (c + kd) s^2 + (k + kp) s + ki``."""

    poles: np.ndarray  # all three, 1/s (complex)
    real_pole: float  # the real pole, 1/s (nan: three real poles)
    pair_omega: float  # natural frequency of the complex pair, rad/s (nan: none)
    pair_zeta: float  # damping ratio of the complex pair, 1 (nan: none)


def pid_poles(osc: Oscillator, kp: float, ki: float, *, kd: float) -> PIDPoles:
    """Poles of the unlimited PID loop, as a real pole and a complex pair where there is one.

    Examples
    --------
    >>> p = pid_poles(Oscillator(m=1.0, c=0.5, k=20.0), 133.6, 512.0, kd=18.7)
    >>> round(p.real_pole, 6), round(p.pair_omega, 6), round(p.pair_zeta, 6)
    (-8.0, 8.0, 0.7)
    """
    kp, ki, kd = _gains(osc, kp, ki, kd)
    if not ki > 0.0:
        raise ParameterError(f"ki = {ki!r} N/(m s): allowed ki > 0 (a PID law)")
    p = np.roots(_closed_loop_den(osc, kp, ki, kd)).astype(complex)
    cx = p[np.abs(p.imag) > 1e-12 * np.abs(p)]
    if cx.size:
        pair = cx[0]
        real = p[np.argmin(np.abs(p.imag))]
        wn = abs(pair)
        return PIDPoles(poles=p, real_pole=float(real.real), pair_omega=float(wn), pair_zeta=float(-pair.real / wn))
    return PIDPoles(poles=p, real_pole=math.nan, pair_omega=math.nan, pair_zeta=math.nan)
