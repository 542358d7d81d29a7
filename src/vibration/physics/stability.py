"""Stability and damping as a design choice: poles, growth, isolation, shock and random loads.

Everything here is a closed form for the oscillator ``m x'' + c x' + k x = F(t)``
(:class:`~vibration.Oscillator`, SI units), with one seeded simulation for the
random-load check.

* **Stability.** :func:`poles` are the roots of ``m s^2 + c s + k``;
  :func:`stability_class` says which of the three usual notions hold (asymptotic:
  every free response decays, ``c > 0``; Lyapunov/marginal: every free response
  stays bounded, ``c >= 0``; bounded-input bounded-output: every bounded force
  gives a bounded displacement, ``c > 0``). :func:`growth_envelope` is the closed-form
  envelope of a response from rest under ``F0 sin(omega t)``: it approaches the
  steady amplitude when ``c > 0``, grows like ``F0 t / (2 m omega_n)`` at exact
  undamped resonance and like ``exp(-c t / (2 m))`` when ``c < 0``.
* **Base excitation.** :func:`transmissibility` is ``|X/Y|`` for a base motion
  ``y = Y sin(omega t)`` (equal to the force transmissibility ``|F_T/F0|``):
  ``sqrt((1 + (2 zeta r)^2) / ((1 - r^2)^2 + (2 zeta r)^2))``, ``r = omega/omega_n``.
  Every damping gives 1 at ``r = sqrt(2)`` (:func:`isolation_frequency`); above it
  more damping transmits more.
* **Shock.** :func:`step_metrics` gives overshoot, peak, rise and settling times
  of the step response; :func:`settling_optimal_zeta` the damping ratio with the
  shortest settling time.
* **Random load.** :func:`white_noise_variance` is the stationary displacement
  variance ``pi S0 / (k c)`` under a white force of two-sided spectral density
  ``S0`` (N^2 s/rad); :func:`white_noise_monte_carlo` estimates it by simulation.
* **Cost.** :func:`damper_load` gives the damper's force amplitude and mean power
  under harmonic force; :func:`design_metrics` collects one point of the design
  trade-off.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import expm
from scipy.optimize import brentq
from scipy.signal import lfilter

from .checks import check_array
from .model import N_POINTS_MAX, Oscillator, ParameterError, SineForce, check_int, check_real

__all__ = [
    "DamperLoad",
    "DesignMetrics",
    "MonteCarlo",
    "Stability",
    "StepMetrics",
    "damper_load",
    "design_metrics",
    "growth_envelope",
    "isolation_frequency",
    "peak_magnification",
    "peak_transmissibility",
    "poles",
    "settling_optimal_zeta",
    "simulate_white_noise",
    "stability_class",
    "step_metrics",
    "step_response",
    "transmissibility",
    "white_noise_monte_carlo",
    "white_noise_variance",
    "white_noise_velocity_variance",
]

#: Largest number of samples :func:`simulate_white_noise` and :func:`white_noise_monte_carlo` draw.
SAMPLES_MAX = 50_000_000
#: Recorded steps per path of :func:`white_noise_monte_carlo` by default.
MC_SAMPLES = 2000
#: Samples simulated at once by :func:`white_noise_monte_carlo` (memory of one chunk ~ 50 bytes each).
MC_CHUNK = 1_000_000

#: Largest total number of samples (paths times samples per path) of one Monte Carlo estimate (about 5 s).
MC_TOTAL_MAX = 100_000_000

#: Smallest settling band :func:`step_metrics` resolves (the crossings are found to rounding in 1 - y).
BAND_MIN = 1e-12

#: Largest number of times :func:`step_response` evaluates (one scalar closed form each).
STEP_SAMPLES_MAX = 1_000_000


def _check_osc(osc) -> Oscillator:
    if not isinstance(osc, Oscillator):
        raise ParameterError(f"osc = {osc!r} is not an Oscillator: allowed Oscillator(m, c, k)")
    return osc


def _check_stable(osc: Oscillator, what: str) -> None:
    if not osc.c > 0.0:
        raise ParameterError(
            f"c = {osc.c!r} N s/m is out of range: allowed c > 0 N s/m ({what} exists only for an "
            "asymptotically stable oscillator)"
        )


def _frequencies(omegas, name: str = "omegas") -> np.ndarray:
    return check_array(name, omegas, low=0.0, ndim=(0, 1, 2), unit="rad/s")


def _times(t, name: str = "t", max_size: int = N_POINTS_MAX) -> np.ndarray:
    return check_array(name, t, low=0.0, ndim=(0, 1, 2), max_size=max_size, unit="s")


def _out(values: np.ndarray, like: np.ndarray):
    return float(values) if like.ndim == 0 else values


# ----------------------------------------------------------------------------- stability


def poles(osc: Oscillator) -> np.ndarray:
    """Roots of the characteristic polynomial ``m s^2 + c s + k``, 1/s.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).

    Returns
    -------
    numpy.ndarray
        Two complex numbers (1/s). Oscillating roots come as ``-sigma + i omega_d``
        then ``-sigma - i omega_d`` (``sigma = c/(2m)``, ``omega_d = sqrt(k/m - sigma^2)``);
        real roots as the one with the larger real part (the slow, dominant one when
        stable) first. Real roots are formed without cancellation
        (``s1 s2 = k/m`` gives the small one from the large one).

    Examples
    --------
    >>> np.round(poles(Oscillator(1.0, 0.5, 20.0)), 4)          # 1/s
    array([-0.25+4.4651j, -0.25-4.4651j])
    >>> np.round(poles(Oscillator(1.0, 15.0, 20.0)), 4)
    array([ -1.4792+0.j, -13.5208+0.j])
    >>> poles(Oscillator(1.0, 0.0, 4.0))
    array([0.+2.j, 0.-2.j])
    """
    osc = _check_osc(osc)
    sigma = osc.decay_rate
    wn2 = osc.k / osc.m
    q = wn2 - sigma * sigma
    if q > 0.0:
        wd = math.sqrt(q)
        re = 0.0 - sigma  # 0.0 - 0.0 is +0.0
        return np.array([complex(re, wd), complex(re, -wd)])
    if q == 0.0:
        return np.array([complex(-sigma, 0.0)] * 2)
    mu = math.sqrt(-q)
    if sigma > 0.0:
        hi, lo = -wn2 / (sigma + mu), -(sigma + mu)
    else:
        hi, lo = -sigma + mu, wn2 / (-sigma + mu)
    return np.array([complex(hi, 0.0), complex(lo, 0.0)])


@dataclass(frozen=True)
class Stability:
    """Which notions of stability an oscillator has, and its slowest pole."""

    asymptotic: bool  # every free response decays to 0 (all poles in the open left half-plane)
    lyapunov: bool  # every free response stays bounded (marginal when not asymptotic)
    bibo: bool  # every bounded force gives a bounded displacement
    spectral_abscissa: float  # largest real part of the poles, 1/s (decay rate of the slowest mode if < 0)
    verdict: str  # "asymptotically stable", "marginally stable" or "unstable"


def stability_class(osc: Oscillator) -> Stability:
    """Asymptotic, Lyapunov (marginal) and bounded-input bounded-output stability.

    For ``m s^2 + c s + k`` with ``m, k > 0`` the three notions reduce to the sign of c:
    ``c > 0`` has all three; ``c = 0`` (poles ``+/- i omega_n``) is marginally stable,
    bounded free motion but no BIBO stability (a force at ``omega_n`` grows the
    response like t); ``c < 0`` has none (free motion grows like ``exp(-c t / 2m)``).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).

    Returns
    -------
    Stability

    Examples
    --------
    >>> stability_class(Oscillator(1.0, 0.1, 20.0)).verdict
    'asymptotically stable'
    >>> s = stability_class(Oscillator(1.0, 0.0, 20.0))
    >>> s.verdict, s.lyapunov, s.bibo
    ('marginally stable', True, False)
    >>> stability_class(Oscillator(1.0, -0.2, 20.0)).spectral_abscissa     # 1/s
    0.1
    """
    p = poles(osc)
    c = osc.c
    abscissa = float(np.max(p.real))
    if c > 0.0:
        verdict = "asymptotically stable"
    elif c == 0.0:
        verdict = "marginally stable"
    else:
        verdict = "unstable"
    return Stability(
        asymptotic=c > 0.0, lyapunov=c >= 0.0, bibo=c > 0.0, spectral_abscissa=abscissa + 0.0, verdict=verdict
    )


def growth_envelope(osc: Oscillator, force: SineForce, t):
    """Closed-form envelope of the response from rest to ``F0 sin(omega t)``, m.

    * Exact undamped resonance (``c = 0``, ``omega = omega_n``): the response is
      ``F0/(2k) (sin omega_n t - omega_n t cos omega_n t)`` and its envelope
      ``F0/(2k) sqrt(1 + omega_n^2 t^2)``: linear growth at ``F0 / (2 m omega_n)`` m/s.
    * For oscillating roots (``|zeta| < 1``, any sign of c): the response is
      the steady state ``Im(H exp(i omega t))`` plus the free transient
      ``Im(C exp((-sigma + i omega_d) t))``, ``sigma = c/(2m)``, so
      ``x = Im(Z(t) exp(i omega t))`` with ``Z = H + C exp((-sigma + i (omega_d - omega)) t)``
      and the envelope is ``|Z(t)|``: it beats at ``|omega_d - omega|`` between
      ``|H| - |C| exp(-sigma t)`` and ``|H| + |C| exp(-sigma t)``, approaches the steady
      amplitude ``|H|`` when ``c > 0``, keeps beating when ``c = 0`` and grows
      exponentially at the rate ``-sigma`` when ``c < 0``.

    * For real roots (``|zeta| >= 1``, any sign of c): the response is the steady state
      plus ``A exp(s1 t) + B exp(s2 t)`` (``(A + B t) exp(s t)`` at a double root), and
      the bound returned is ``|H| + |A exp(s1 t) + B exp(s2 t)|``; with ``c <= -2 sqrt(k m)``
      it grows like ``exp(s1 t)``, ``s1 > 0`` the larger pole, without oscillating.

    All are pointwise upper bounds of ``|x(t)|`` (for oscillating roots the modulus of the
    complex response whose imaginary part is x; x reaches it when the phase of
    ``Z exp(i omega t)`` passes ``pi/2``, about once per forcing period when ``Z`` varies slowly).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).
    force : SineForce
        F0 (N), omega (rad/s).
    t : array_like
        Times, s (finite, >= 0).

    Returns
    -------
    float or numpy.ndarray
        Envelope at ``t``, m (same shape as ``t``).

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.0, 4.0)
    >>> round(growth_envelope(osc, SineForce(1.0, 2.0), 10.0), 6)       # m: (1/8) sqrt(1 + 400)
    2.503123
    >>> round(growth_envelope(Oscillator(1.0, 0.5, 20.0), SineForce(5.0, 3.0), 1e3), 4)   # steady amplitude, m
    0.4504
    """
    _check_osc(osc)
    if not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed SineForce(F0, omega)")
    tt = _times(t)
    with np.errstate(over="ignore", invalid="ignore"):
        env = _growth_envelope(osc, force, tt)
    return _finite_envelope(env, tt, osc)


def _finite_envelope(env, tt: np.ndarray, osc: Oscillator):
    if not np.all(np.isfinite(env)):
        bad = float(np.asarray(tt)[~np.isfinite(np.asarray(env, dtype=float))].ravel()[0])
        raise ParameterError(
            f"t contains {bad!r} s: the envelope overflows there (c = {osc.c!r} N s/m grows it exponentially); "
            "allowed times at which it stays finite"
        )
    return env


def _growth_envelope(osc: Oscillator, force: SineForce, tt: np.ndarray):
    wn = osc.natural_frequency
    F0, w = force.F0, force.omega
    if osc.c == 0.0 and w == wn:
        env = F0 / (2.0 * osc.k) * np.hypot(1.0, wn * tt)
        return _out(env, tt)
    if F0 == 0.0 or w == 0.0:  # no force: the response from rest is 0
        return _out(np.zeros_like(tt), tt)
    h = F0 / complex(osc.m * (wn - w) * (wn + w), osc.c * w)  # steady state Im(h exp(i w t)), m
    x0, v0 = -h.imag, -w * h.real  # initial conditions left for the free transient, m, m/s
    if not abs(osc.damping_ratio) < 1.0:  # real roots: |x| <= |H| + |free part|
        # free = exp(s1 t) [x0 (1 + exp(-2 mu t)) / 2 + (v0 + sigma x0) (1 - exp(-2 mu t)) / (2 mu)],
        # s1 = -sigma + mu the larger pole (from poles(): no cancellation), written with expm1 so it
        # stays accurate at and near the double root (mu -> 0: the second term -> (v0 + sigma x0) t)
        s1 = float(poles(osc)[0].real)
        sigma = osc.decay_rate
        mu = math.sqrt(max(sigma * sigma - wn * wn, 0.0))
        em = np.expm1(-2.0 * mu * tt)
        ratio = -em / (2.0 * mu) if mu > 0.0 else tt
        with np.errstate(over="ignore", invalid="ignore"):
            free = np.exp(s1 * tt) * (x0 * (1.0 + 0.5 * em) + (v0 + sigma * x0) * ratio)
        return _out(abs(h) + np.abs(free), tt)
    sigma, wd = osc.decay_rate, osc.damped_natural_frequency
    big_c = complex((v0 + sigma * x0) / wd, x0)  # transient Im(C exp((-sigma + i wd) t)), m
    env = np.abs(h + big_c * np.exp(complex(-sigma, wd - w) * tt))
    return _out(env, tt)


# ----------------------------------------------------------------------------- base excitation


def transmissibility(osc: Oscillator, omegas):
    """Displacement transmissibility ``|X/Y|`` under base motion ``y = Y sin(omega t)``.

    ``T = sqrt((1 + (2 zeta r)^2) / ((1 - r^2)^2 + (2 zeta r)^2))``, ``r = omega/omega_n``;
    the same ratio is the force transmissibility ``|F_T / F0|`` of a force on the mass
    to the ground. ``T = 1`` at ``r = sqrt(2)`` for every damping; below it damping lowers
    T, above it damping raises T. Evaluated in scaled form for ``r > 1`` (no overflow);
    ``inf`` at exact undamped resonance. For ``c < 0`` the ratio of the particular
    solution is returned (never reached: the free response grows).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    omegas : float or array_like
        Excitation frequencies, rad/s (finite, >= 0), any shape.

    Returns
    -------
    float or numpy.ndarray
        T, dimensionless, same shape as ``omegas``.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> wn = osc.natural_frequency
    >>> np.round(transmissibility(osc, [0.0, wn, np.sqrt(2) * wn, 3 * wn]), 4)
    array([1.    , 9.    , 1.    , 0.1317])
    >>> round(transmissibility(Oscillator(1.0, 15.0, 20.0), 3 * wn), 4)
    0.7866
    """
    _check_osc(osc)
    w = _frequencies(omegas)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        r = w / osc.natural_frequency
        b = 2.0 * osc.damping_ratio * r  # 2 zeta r
        low = np.hypot(1.0, b) / np.hypot((1.0 - r) * (1.0 + r), b)
        inv = 1.0 / np.where(r > 1.0, r, 1.0)
        bz = 2.0 * osc.damping_ratio * inv  # (2 zeta r) / r^2
        high = np.hypot(inv * inv, bz) / np.hypot((inv - 1.0) * (inv + 1.0), bz)
        out = np.where(r > 1.0, high, low)
        out = np.where(np.isinf(b) & (r <= 1.0), 1.0, out)  # zeta -> inf below omega_n: T -> 1
    return _out(out, w)


def isolation_frequency(osc: Oscillator) -> float:
    """Frequency above which base motion is attenuated (T < 1) at any damping: ``sqrt(2) omega_n``, rad/s.

    Examples
    --------
    >>> round(isolation_frequency(Oscillator(1.0, 0.5, 20.0)), 4)     # rad/s
    6.3246
    """
    return math.sqrt(2.0) * _check_osc(osc).natural_frequency


def peak_transmissibility(osc: Oscillator) -> tuple[float, float]:
    """Largest transmissibility over frequency and where it occurs: ``(omega_peak rad/s, T_max)``.

    The maximum sits at ``r^2 = 2 / (1 + sqrt(1 + 8 zeta^2))`` (below 1 for every
    ``zeta > 0``, written without cancellation); ``(omega_n, inf)`` when undamped.

    Examples
    --------
    >>> w, t = peak_transmissibility(Oscillator(1.0, 0.5, 20.0))
    >>> round(w, 4), round(t, 4)          # rad/s, 1
    (4.4583, 9.0137)
    """
    _check_osc(osc)
    zeta = abs(osc.damping_ratio)
    wn = osc.natural_frequency
    if zeta == 0.0:
        return wn, math.inf
    r = math.sqrt(2.0 / (1.0 + math.sqrt(1.0 + 8.0 * zeta * zeta)))
    return r * wn, float(transmissibility(Oscillator(osc.m, abs(osc.c), osc.k), r * wn))


def peak_magnification(osc: Oscillator) -> tuple[float, float]:
    """Largest force-excited magnification ``|X|/(F0/k)`` and where: ``(omega_peak rad/s, value)``.

    ``1 / (2 zeta sqrt(1 - zeta^2))`` at ``omega_n sqrt(1 - 2 zeta^2)`` when
    ``zeta < 1/sqrt(2)``; otherwise the curve falls from 1 at ``omega = 0``.
    ``(omega_n, inf)`` when undamped; ``|zeta|`` is used when ``c < 0``.

    Examples
    --------
    >>> w, g = peak_magnification(Oscillator(1.0, 0.5, 20.0))
    >>> round(w, 4), round(g, 4)          # rad/s, 1
    (4.4581, 8.9583)
    >>> peak_magnification(Oscillator(1.0, 15.0, 20.0))
    (0.0, 1.0)
    """
    _check_osc(osc)
    zeta = abs(osc.damping_ratio)
    wn = osc.natural_frequency
    if zeta == 0.0:
        return wn, math.inf
    if zeta >= 1.0 / math.sqrt(2.0):
        return 0.0, 1.0
    return wn * math.sqrt((1.0 - zeta * math.sqrt(2.0)) * (1.0 + zeta * math.sqrt(2.0))), 1.0 / (
        2.0 * zeta * math.sqrt((1.0 - zeta) * (1.0 + zeta))
    )


# ----------------------------------------------------------------------------- shock: step response


@dataclass(frozen=True)
class StepMetrics:
    """Metrics of the response to a unit step force, normalised by its final value ``1/k``.

    The normalised response ``y(t) = k x(t) / F`` of ``m x'' + c x' + k x = F 1(t)``
    from rest rises from 0 to 1 whatever the force F, so the metrics do not depend on F.
    """

    zeta: float  # damping ratio, 1
    overshoot: float  # (y_max - 1), fraction of the final value; 0 when zeta >= 1
    peak_time: float  # time of the first (largest) peak, s; inf when zeta >= 1 (y rises monotonically)
    rise_time: float  # first time y reaches 0.9 minus first time it reaches 0.1, s
    settling_time: float  # last time |y - 1| equals the band (true last exit, not the envelope), s
    band: float  # settling band, fraction of the final value (0.02 = 2 %)
    final_value: float  # final displacement per newton of step force, 1/k, m/N

    @property
    def peak(self) -> float:
        """Largest normalised response, ``1 + overshoot``, dimensionless."""
        return 1.0 + self.overshoot


def _one_minus_y(osc: Oscillator):
    """``t -> 1 - y(t)`` (scalar, dimensionless) in a form stable in every regime.

    ``1 - y`` is the free response from ``x(0) = 1, v(0) = 0``:
    ``exp(-sigma t) (cos wd t + sigma/wd sin wd t)`` with oscillating roots,
    ``(1 + omega_n t) exp(-omega_n t)`` with a double root and
    ``(s_lo exp(s_hi t) - s_hi exp(s_lo t)) / (s_lo - s_hi)`` with real roots, the last
    written with ``expm1`` so it stays accurate near critical damping.
    """
    sigma = osc.decay_rate
    wn2 = osc.k / osc.m
    q = wn2 - sigma * sigma
    if q > 0.0:
        wd = math.sqrt(q)
        return lambda t: math.exp(-sigma * t) * (math.cos(wd * t) + sigma / wd * math.sin(wd * t))
    if q == 0.0:
        return lambda t: (1.0 + sigma * t) * math.exp(-sigma * t)
    mu = math.sqrt(-q)
    s_hi = -wn2 / (sigma + mu)

    def f(t: float) -> float:
        e_hi = math.exp(s_hi * t)
        em = math.expm1(-2.0 * mu * t)
        # kc + sigma g with kc = e_hi (2 + em) / 2, g = -e_hi em / (2 mu)
        return e_hi * (0.5 * (2.0 + em) - sigma * em / (2.0 * mu))

    return f


def step_response(osc: Oscillator, t):
    """Normalised response ``y = k x / F`` to a step force ``F 1(t)`` from rest, dimensionless.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).
    t : float or array_like
        Times, s (finite, >= 0).

    Returns
    -------
    float or numpy.ndarray
        ``y(t)``; the displacement is ``F y(t) / k`` m.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.0, 4.0)                    # undamped: y = 1 - cos(2 t)
    >>> np.round(step_response(osc, [0.0, np.pi / 2]), 12)
    array([0., 2.])
    """
    _check_osc(osc)
    tt = _times(t, max_size=STEP_SAMPLES_MAX)
    f = _one_minus_y(osc)

    def one_minus_y(s: float) -> float:
        try:
            return f(s)
        except OverflowError:  # math.exp of a growing (unstable) response
            return math.inf

    with np.errstate(over="ignore", invalid="ignore"):
        y = 1.0 - np.array([one_minus_y(float(s)) for s in tt.ravel()]).reshape(tt.shape)
    if not np.all(np.isfinite(y)):
        bad = float(tt[~np.isfinite(y)].ravel()[0])
        raise ParameterError(
            f"t contains {bad!r} s: the step response overflows there (c = {osc.c!r} N s/m, unstable); "
            "allowed times at which it stays finite"
        )
    return _out(y, tt)


def _solve(g, a: float, b: float) -> float:
    """Root of the scalar g on [a, b] where g changes sign, to full precision."""
    ga, gb = g(a), g(b)
    if ga == 0.0:
        return a
    if gb == 0.0:
        return b
    return float(brentq(g, a, b, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=500))


def step_metrics(osc: Oscillator, band: float = 0.02) -> StepMetrics:
    """Overshoot, peak time, 10-90 % rise time and settling time of the step response.

    The force is a step ``F 1(t)`` applied at rest; the response is normalised by
    its final value ``F/k`` (:func:`step_response`), so every metric is the same for
    every F.

    * **overshoot** ``exp(-pi zeta / sqrt(1 - zeta^2))`` (fraction of the final value)
      at **peak time** ``pi / omega_d`` when ``zeta < 1``. When ``zeta >= 1``
      (critical, overdamped) the response rises monotonically: overshoot 0 and peak
      time ``inf`` (the supremum 1 is approached, never reached).
    * **rise time**: from the first crossing of 0.1 to the first crossing of 0.9.
    * **settling time**: the true last exit from the band ``|y - 1| <= band``, not the
      envelope estimate. With ``zeta < 1`` the extrema of ``y - 1`` sit at
      ``n pi / omega_d`` with sizes ``overshoot^n``; after the last extremum larger
      than the band, ``y`` is monotone up to the next one, so the exit is the unique
      root there, found by bracketing (``brentq``, full precision). With real roots
      it is the crossing of ``1 - band``.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, > 0), k (N/m).
    band : float
        Settling band, fraction of the final value, ``0 < band < 1`` (default 2 %).

    Returns
    -------
    StepMetrics

    Raises
    ------
    ParameterError
        When ``c <= 0``: the step response of an undamped or negatively damped
        oscillator never settles (it oscillates for ever or grows), so no step metrics
        are returned for it.

    Examples
    --------
    >>> s = step_metrics(Oscillator(1.0, 0.5, 20.0))
    >>> round(s.overshoot, 4), round(s.peak_time, 4), round(s.rise_time, 4), round(s.settling_time, 3)
    (0.8387, 0.7036, 0.2382, 15.544)
    >>> s = step_metrics(Oscillator(1.0, 15.0, 20.0))
    >>> s.overshoot, s.peak_time, round(s.settling_time, 4)       # 1, s, s
    (0.0, inf, 2.723)
    """
    _check_osc(osc)
    _check_stable(osc, "a settling step response")
    band = check_real("band", band, low=BAND_MIN, high=1.0)
    if band == 1.0:
        raise ParameterError("band = 1.0 is out of range: allowed 0 < band < 1")
    f = _one_minus_y(osc)
    sigma = osc.decay_rate
    wn2 = osc.k / osc.m
    q = wn2 - sigma * sigma
    zeta = osc.damping_ratio

    def crossing(level: float, a: float, b: float) -> float:
        """First time y = level on [a, b], y increasing there (1 - y decreasing)."""
        return _solve(lambda t: f(t) - (1.0 - level), a, b)

    if q > 0.0:
        wd = math.sqrt(q)
        half = math.pi / wd  # time between extrema, s
        log_mp = -sigma * half  # ln(overshoot), written without underflow
        overshoot = math.exp(log_mp)
        rise = crossing(0.9, 0.0, half) - crossing(0.1, 0.0, half)
        # extrema |y - 1| = overshoot^n at n half; N = the last one above the band
        if log_mp >= math.log(band):
            n = max(1, math.ceil(math.log(band) / log_mp) - 1)
            while n > 1 and n * log_mp <= math.log(band):
                n -= 1
            while (n + 1) * log_mp > math.log(band):
                n += 1
            if n * log_mp <= math.log(band):  # overshoot exactly at the band
                n = 0
        else:
            n = 0
        # on [n half, (n + 1) half]: |y - 1| = overshoot^n (1 - y(tau)), tau = t - n half
        level = band * math.exp(-n * log_mp)
        tau = _solve(lambda t: f(t) - level, 0.0, half)
        settle = n * half + tau
        return StepMetrics(zeta, overshoot, half, rise, settle, band, 1.0 / osc.k)

    hi = osc.time_constant
    for _ in range(2100):  # doubling from any normal float reaches the overflow in < 2100 steps
        if not f(hi) > min(band, 0.1):
            break
        hi *= 2.0
    rise = crossing(0.9, 0.0, hi) - crossing(0.1, 0.0, hi)
    settle = crossing(1.0 - band, 0.0, hi)
    return StepMetrics(zeta, 0.0, math.inf, rise, settle, band, 1.0 / osc.k)


def settling_optimal_zeta(band: float = 0.02) -> float:
    """Damping ratio with the shortest step settling time ``omega_n t_s``.

    Below it the overshoot leaves the band and the response settles only after its
    first peak; at and above it the response settles when it first enters
    ``1 - band``, later the more it is damped. The optimum is where the overshoot
    equals the band: ``zeta* = |ln band| / sqrt(pi^2 + ln^2 band)``.

    Parameters
    ----------
    band : float
        Settling band, fraction of the final value (0 < band < 1).

    Examples
    --------
    >>> round(settling_optimal_zeta(0.02), 4), round(settling_optimal_zeta(0.05), 4)
    (0.7797, 0.6901)
    """
    band = check_real("band", band, low=0.0, high=1.0, low_open=True)
    if band == 1.0:
        raise ParameterError("band = 1.0 is out of range: allowed 0 < band < 1")
    lb = abs(math.log(band))
    return lb / math.hypot(math.pi, lb)


# ----------------------------------------------------------------------------- random load


def _check_S0(S0) -> float:
    return check_real("S0", S0, low=0.0, unit="N^2 s/rad")


def white_noise_variance(osc: Oscillator, S0: float) -> float:
    """Stationary displacement variance under a white-noise force, m^2.

    With the force's two-sided power spectral density ``S0`` (N^2 s/rad, over
    ``-inf < omega < inf``, so its autocorrelation is ``2 pi S0 delta(tau)``),
    ``var x = S0 integral |H(omega)|^2 d omega = pi S0 / (k c)``,
    ``H = 1 / (k - m omega^2 + i c omega)``. The mass drops out.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, > 0), k (N/m).
    S0 : float
        Two-sided force spectral density, N^2 s/rad (>= 0).

    Raises
    ------
    ParameterError
        When ``c <= 0``: there is no stationary response (the variance grows without bound).

    Examples
    --------
    >>> round(white_noise_variance(Oscillator(1.0, 0.5, 20.0), 1.0), 6)      # m^2
    0.314159
    """
    _check_osc(osc)
    S0 = _check_S0(S0)
    _check_stable(osc, "a stationary random response")
    return math.pi * S0 / osc.k / osc.c


def white_noise_velocity_variance(osc: Oscillator, S0: float) -> float:
    """Stationary velocity variance under a white-noise force, ``pi S0 / (m c)``, m^2/s^2.

    Same conventions as :func:`white_noise_variance`.

    Examples
    --------
    >>> round(white_noise_velocity_variance(Oscillator(1.0, 0.5, 20.0), 1.0), 6)     # m^2/s^2
    6.283185
    """
    _check_osc(osc)
    S0 = _check_S0(S0)
    _check_stable(osc, "a stationary random response")
    return math.pi * S0 / osc.m / osc.c


def _transition(osc: Oscillator, S0: float, dt: float):
    """Exact one-step transition of the state (x, v) over dt: ``Phi`` and the noise covariance ``Q``.

    Van Loan's method on a short step ``h = dt / 2^j`` (no longer than :func:`_default_dt`,
    so ``expm`` of the block ``[[-A, B q B^T], [0, A^T]] h`` never meets a large growth
    ``exp(|s| h)``): it gives ``Phi(h) = exp(A h)`` and
    ``Q(h) = integral_0^h exp(A s) B q B^T exp(A^T s) ds``, ``q = 2 pi S0`` (N^2 s). Then
    ``j`` exact doublings ``Q(2h) = Q(h) + Phi(h) Q(h) Phi(h)^T``, ``Phi(2h) = Phi(h)^2``
    reach any dt, however stiff or lightly damped the oscillator. Independent of the
    closed-form variance.
    """
    a = np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]])
    bqb = np.array([[0.0, 0.0], [0.0, 2.0 * math.pi * S0 / osc.m**2]])
    j = max(0, math.ceil(math.log2(dt / _default_dt(osc)))) if osc.c > 0.0 else 0
    h = math.ldexp(dt, -j)
    big = np.zeros((4, 4))
    big[:2, :2] = -a
    big[:2, 2:] = bqb
    big[2:, 2:] = a.T
    e = expm(big * h)
    phi = e[2:, 2:].T
    qd = phi @ e[:2, 2:]
    qd = 0.5 * (qd + qd.T)
    for _ in range(j):
        qd = qd + phi @ qd @ phi.T
        qd = 0.5 * (qd + qd.T)
        phi = phi @ phi
    return phi, qd


def _default_dt(osc: Oscillator) -> float:
    """Sample spacing: a tenth of the shorter of the natural period and the slow time constant, s."""
    period = 2.0 * math.pi / osc.natural_frequency
    tau = osc.time_constant
    fast = 1.0 / abs(poles(osc)[1].real) if osc.regime == "overdamped" else tau
    return min(period, tau, 10 * fast) / 10.0


def simulate_white_noise(
    osc: Oscillator,
    S0: float,
    t_end: float,
    dt: float | None = None,
    n_paths: int = 1,
    seed: int = 0,
):
    """Sample paths of the response from rest to a white-noise force, on ``0, dt, 2 dt, ...``.

    The state (x, v) is advanced by its exact Gaussian transition over each step
    (:func:`scipy.linalg.expm`, Van Loan's covariance integral), so the samples have
    exactly the distribution of the continuous process at the sample times, whatever
    dt: ``X_{n+1} = Phi X_n + w_n``, ``w_n ~ N(0, Q)``; the recursion runs as a linear
    filter (:func:`scipy.signal.lfilter`). Seeded (``numpy.random.default_rng(seed)``).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, > 0), k (N/m).
    S0 : float
        Two-sided force spectral density, N^2 s/rad (>= 0).
    t_end : float
        End of the window, s (> 0).
    dt : float, optional
        Sample spacing, s (> 0); default a tenth of the shorter of the natural period
        and the decay time constant.
    n_paths : int
        Independent paths (1 to 100000).
    seed : int
        Seed of the generator (>= 0).

    Returns
    -------
    (t, x, v)
        Times (s, shape ``(n,)``), displacement (m) and velocity (m/s), shape ``(n_paths, n)``.

    Examples
    --------
    >>> t, x, v = simulate_white_noise(Oscillator(1.0, 0.5, 20.0), 1.0, 10.0, dt=0.01, n_paths=2)
    >>> x.shape, float(x[0, 0]), float(v[1, 0])
    ((2, 1001), 0.0, 0.0)
    """
    _check_osc(osc)
    S0 = _check_S0(S0)
    _check_stable(osc, "a stationary random response")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    dt = _default_dt(osc) if dt is None else check_real("dt", dt, low=0.0, low_open=True, unit="s")
    n_paths = check_int("n_paths", n_paths, low=1, high=100_000)
    seed = check_int("seed", seed, low=0, high=2**63 - 1)
    if not n_paths * (t_end / dt + 1.0) <= SAMPLES_MAX:
        raise ParameterError(
            f"n_paths * (t_end/dt + 1) = {n_paths * (t_end / dt + 1.0):.6g} (n_paths = {n_paths}, t_end = {t_end!r} s, "
            f"dt = {dt!r} s) is out of range: allowed <= {SAMPLES_MAX} samples (memory)"
        )
    n = int(math.floor(t_end / dt + 1e-9)) + 1
    if n < 2:
        raise ParameterError(f"dt = {dt!r} s is out of range: allowed dt <= t_end = {t_end!r} s")
    if n * n_paths > SAMPLES_MAX:
        raise ParameterError(
            f"n_paths * (t_end/dt + 1) = {n * n_paths} is out of range: allowed <= {SAMPLES_MAX} samples (memory)"
        )
    phi, qd = _transition(osc, S0, dt)
    lower = np.linalg.cholesky(qd) if S0 > 0.0 else np.zeros((2, 2))
    rng = np.random.default_rng(seed)
    xi = rng.standard_normal((2, n_paths, n))  # the last draw is not used
    w1 = lower[0, 0] * xi[0]
    w2 = lower[1, 0] * xi[0] + lower[1, 1] * xi[1]
    # X_j = Phi X_{j-1} + w_{j-1}, X_0 = 0, as a filter (the leading 0 of b is the delay);
    # (zI - Phi)^-1 = adj / det: x = ((z - Phi22) W1 + Phi12 W2) / det, v = (Phi21 W1 + (z - Phi11) W2) / det
    den = [1.0, -(phi[0, 0] + phi[1, 1]), phi[0, 0] * phi[1, 1] - phi[0, 1] * phi[1, 0]]
    x = lfilter([0.0, 1.0, -phi[1, 1]], den, w1, axis=-1) + lfilter([0.0, 0.0, phi[0, 1]], den, w2, axis=-1)
    v = lfilter([0.0, 0.0, phi[1, 0]], den, w1, axis=-1) + lfilter([0.0, 1.0, -phi[0, 0]], den, w2, axis=-1)
    t = np.arange(n) * dt
    return t, x, v


@dataclass(frozen=True)
class MonteCarlo:
    """A seeded Monte Carlo estimate of the stationary displacement and velocity variances."""

    variance: float  # mean of x^2 over paths and samples after the burn-in, m^2
    standard_error: float  # of ``variance``, from the spread of the per-path means, m^2
    velocity_variance: float  # mean of v^2, m^2/s^2
    velocity_standard_error: float  # m^2/s^2
    n_paths: int  # independent paths, 1
    n_samples: int  # samples per path after the burn-in, 1
    dt: float  # sample spacing, s
    burn_in: float  # discarded start of each path (from rest), s
    seed: int  # generator seed


def white_noise_monte_carlo(
    osc: Oscillator,
    S0: float,
    n_paths: int = 200,
    duration: float | None = None,
    dt: float | None = None,
    seed: int = 0,
) -> MonteCarlo:
    """Estimate the stationary variances by simulation (:func:`simulate_white_noise`).

    Each path starts from rest; the first 12 decay time constants are discarded (the
    variance's start-up transient is then below ``exp(-24)`` of its value), and
    ``x^2``, ``v^2`` are averaged over the rest and over paths. The standard error
    comes from the spread of the per-path means (paths are independent, samples
    within a path are not).

    The transition over each step is exact (:func:`simulate_white_noise`), so the step
    only sets how many samples are averaged, not an error: by default a path records
    :data:`MC_SAMPLES` steps over 100 decay time constants (``dt = tau / 20``, about the
    samples that are not strongly correlated), so the cost is the same for every damping,
    however light (``tau = 2m/c`` long) or heavy (a stiff fast mode).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, > 0), k (N/m).
    S0 : float
        Two-sided force spectral density, N^2 s/rad (>= 0).
    n_paths : int
        Independent paths (2 to 100000).
    duration : float, optional
        Recorded time per path after the burn-in, s; default 100 time constants.
    dt : float, optional
        Sample spacing, s (> 0); default ``duration / MC_SAMPLES``.
    seed : int
        Seed (>= 0).

    Returns
    -------
    MonteCarlo

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> mc = white_noise_monte_carlo(osc, 1.0, n_paths=50)
    >>> bool(abs(mc.variance - white_noise_variance(osc, 1.0)) < 4 * mc.standard_error)
    True
    """
    _check_osc(osc)
    _check_stable(osc, "a stationary random response")
    n_paths = check_int("n_paths", n_paths, low=2, high=100_000)
    tau = osc.time_constant
    burn = 12.0 * tau
    duration = 100.0 * tau if duration is None else check_real("duration", duration, low=0.0, low_open=True, unit="s")
    dt = duration / MC_SAMPLES if dt is None else check_real("dt", dt, low=0.0, low_open=True, unit="s")
    total = n_paths * ((burn + duration) / dt + 1.0)
    if not total <= MC_TOTAL_MAX:
        raise ParameterError(
            f"n_paths * (burn-in + duration) / dt = {total:.3g} samples (n_paths = {n_paths}, "
            f"duration = {duration!r} s, dt = {dt!r} s, burn-in {burn:.3g} s): "
            f"allowed at most {MC_TOTAL_MAX:g} samples in all (run time)"
        )
    chunk = max(1, min(n_paths, MC_CHUNK // max(1, int((burn + duration) / dt) + 1)))
    ss = np.random.SeedSequence(check_int("seed", seed, low=0, high=2**63 - 1))
    mx, mv = [], []
    done = 0
    for child in ss.spawn(math.ceil(n_paths / chunk)):
        size = min(chunk, n_paths - done)
        t, x, v = simulate_white_noise(osc, S0, burn + duration, dt, size, int(child.generate_state(1)[0]))
        keep = t >= burn
        mx.append(np.mean(x[:, keep] ** 2, axis=1))
        mv.append(np.mean(v[:, keep] ** 2, axis=1))
        done += size
    px, pv = np.concatenate(mx), np.concatenate(mv)
    return MonteCarlo(
        variance=float(px.mean()),
        standard_error=float(px.std(ddof=1) / math.sqrt(px.size)),
        velocity_variance=float(pv.mean()),
        velocity_standard_error=float(pv.std(ddof=1) / math.sqrt(pv.size)),
        n_paths=n_paths,
        n_samples=int(np.count_nonzero(keep)),
        dt=dt,
        burn_in=burn,
        seed=seed,
    )


# ----------------------------------------------------------------------------- cost and design


@dataclass(frozen=True)
class DamperLoad:
    """Steady-state load on the damper under ``F0 sin(omega t)`` on the mass."""

    omega: np.ndarray  # forcing frequencies, rad/s
    amplitude: np.ndarray  # displacement amplitude |X|, m
    force_amplitude: np.ndarray  # damper force amplitude c omega |X|, N
    mean_power: np.ndarray  # mean power the damper dissipates, c omega^2 |X|^2 / 2, W


def damper_load(osc: Oscillator, F0: float, omegas) -> DamperLoad:
    """Damper force amplitude and mean dissipated power in the steady state, at each omega.

    ``|X| = F0 / sqrt((k - m omega^2)^2 + (c omega)^2)``, damper force ``c omega |X|``
    (N), mean power ``c omega^2 |X|^2 / 2`` (W), equal to the mean power the force
    delivers. At ``omega = omega_n`` the damper force equals F0 for every c (it balances
    the applied force) and the power is ``F0^2 / (2 c)``: at resonance less damping
    dissipates more power, through a larger velocity.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, >= 0), k (N/m).
    F0 : float
        Force amplitude, N (>= 0).
    omegas : float or array_like
        Forcing frequencies, rad/s (>= 0).

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> d = damper_load(osc, 5.0, [3.0, osc.natural_frequency])
    >>> np.round(d.force_amplitude, 4), np.round(d.mean_power, 4)     # N, W
    (array([0.6756, 5.    ]), array([ 0.4564, 25.    ]))
    """
    _check_osc(osc)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    if osc.c < 0.0:
        raise ParameterError(f"c = {osc.c!r} N s/m is out of range: allowed c >= 0 N s/m (a damper dissipates)")
    w = _frequencies(omegas)
    wn = osc.natural_frequency
    with np.errstate(all="ignore"):  # a non-finite result is refused below
        amp = F0 / np.hypot(osc.m * (wn - w) * (wn + w), osc.c * w)
        force = osc.c * w * amp
        if osc.c == 0.0:
            force = np.zeros_like(w)
        power = 0.5 * force * w * amp
        power = np.where(force == 0.0, 0.0, power)
    if not (np.all(np.isfinite(amp)) and np.all(np.isfinite(power))):
        bad = float(w[~(np.isfinite(amp) & np.isfinite(power))].ravel()[0])
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: with c = {osc.c!r} N s/m the steady amplitude there is not finite "
            "(undamped resonance or overflow); allowed frequencies with a finite steady state"
        )
    return DamperLoad(omega=w, amplitude=amp, force_amplitude=force, mean_power=power)


@dataclass(frozen=True)
class DesignMetrics:
    """One damping on the three axes of the trade-off, plus its random response.

    A field is ``None`` where the quantity does not exist for this damping (see
    :func:`design_metrics`).
    """

    c: float  # damping coefficient, N s/m
    zeta: float  # damping ratio, 1
    peak_magnification: float | None  # largest |X|/(F0/k) under force on the mass, 1; None if c <= 0
    isolation_ratio: float  # r = omega / omega_n where isolation is judged, 1
    transmissibility: float | None  # steady |X/Y| under base motion at that r, 1; None if c < 0
    overshoot: float | None  # step overshoot, fraction; 1 if c = 0, None if c < 0
    settling_time: float | None  # step 2 % settling time, s; None if c <= 0
    rms_per_sqrt_S0: float | None  # sqrt(pi / (k c)), m / sqrt(N^2 s/rad); None if c <= 0
    stability: str  # verdict of stability_class


def design_metrics(osc: Oscillator, isolation_ratio: float = 3.0, band: float = 0.02) -> DesignMetrics:
    """The damping's place on the trade-off: resonant peak, isolation at ``r``, step settling.

    Any sign of c. Where a quantity does not exist the field is ``None``:

    * ``c = 0``: no finite resonant peak (a force at ``omega_n`` grows the response like
      t), no settling (the step response ``1 - cos omega_n t`` oscillates for ever, its
      overshoot is exactly 1) and no stationary random response (the variance grows
      like t); the steady transmissibility ``1/|1 - r^2|`` exists away from ``r = 1``.
    * ``c < 0``: no steady state at all (every free motion grows), so none of the
      quantities exists.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).
    isolation_ratio : float
        Frequency ratio ``omega / omega_n`` at which the transmissibility is taken (> 0).
    band : float
        Settling band of the step response (fraction).

    Examples
    --------
    >>> d = design_metrics(Oscillator(1.0, 15.0, 20.0))
    >>> round(d.peak_magnification, 3), round(d.transmissibility, 4), round(d.settling_time, 3)
    (1.0, 0.7866, 2.723)
    >>> d = design_metrics(Oscillator(1.0, 0.0, 20.0))
    >>> d.peak_magnification, round(d.transmissibility, 12), d.overshoot, d.settling_time, d.stability
    (None, 0.125, 1.0, None, 'marginally stable')
    """
    _check_osc(osc)
    isolation_ratio = check_real("isolation_ratio", isolation_ratio, low=0.0, low_open=True)
    verdict = stability_class(osc).verdict
    t_r = float(transmissibility(osc, isolation_ratio * osc.natural_frequency))
    if osc.c > 0.0:
        step = step_metrics(osc, band)
        return DesignMetrics(
            c=osc.c,
            zeta=osc.damping_ratio,
            peak_magnification=peak_magnification(osc)[1],
            isolation_ratio=isolation_ratio,
            transmissibility=t_r,
            overshoot=step.overshoot,
            settling_time=step.settling_time,
            rms_per_sqrt_S0=math.sqrt(white_noise_variance(osc, 1.0)),
            stability=verdict,
        )
    undamped = osc.c == 0.0
    return DesignMetrics(
        c=osc.c,
        zeta=osc.damping_ratio,
        peak_magnification=None,
        isolation_ratio=isolation_ratio,
        transmissibility=t_r if undamped and math.isfinite(t_r) else None,
        overshoot=1.0 if undamped else None,
        settling_time=None,
        rms_per_sqrt_S0=None,
        stability=verdict,
    )
