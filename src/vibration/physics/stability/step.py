"""Shock: the step response, its metrics, and the damping ratio with the shortest settling time."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..checks import check_oscillator
from ..checks import like_input as _out
from ..model import Oscillator, ParameterError, check_real
from ._common import _check_stable, _times

#: Smallest settling band :func:`step_metrics` resolves (the crossings are found to rounding in 1 - y).
BAND_MIN = 1e-12

#: Largest number of times :func:`step_response` evaluates (one scalar closed form each).
STEP_SAMPLES_MAX = 1_000_000


# ----------------------------------------------------------------------------- shock: step response


@dataclass(frozen=True, kw_only=True)
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
    final_value: float  # displacement the step F0 settles at, F0/k, m

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
    >>> osc = Oscillator(m=1.0, c=0.0, k=4.0)                    # undamped: y = 1 - cos(2 t)
    >>> np.round(step_response(osc, [0.0, np.pi / 2]), 12)
    array([0., 2.])
    """
    check_oscillator(osc)
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


def step_metrics(osc: Oscillator, band: float = 0.02, *, F0: float = 1.0) -> StepMetrics:
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
    F0 : float
        Height of the step force, N (> 0; 1 N by default): it sets only ``final_value``, ``F0/k`` in m.

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
    >>> s = step_metrics(Oscillator(m=1.0, c=0.5, k=20.0))
    >>> round(s.overshoot, 4), round(s.peak_time, 4), round(s.rise_time, 4), round(s.settling_time, 3)
    (0.8387, 0.7036, 0.2382, 15.544)
    >>> s = step_metrics(Oscillator(m=1.0, c=15.0, k=20.0))
    >>> s.overshoot, s.peak_time, round(s.settling_time, 4)       # 1, s, s
    (0.0, inf, 2.723)
    >>> step_metrics(Oscillator(m=1.0, c=0.5, k=20.0), F0=5.0).final_value    # m
    0.25
    """
    check_oscillator(osc)
    _check_stable(osc, "a settling step response")
    band = check_real("band", band, low=BAND_MIN, high=1.0)
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    if band == 1.0:
        raise ParameterError("band = 1.0 is out of range: allowed 0 < band < 1")
    f = _one_minus_y(osc)
    sigma = osc.decay_rate
    wn2 = osc.k / osc.m
    q = wn2 - sigma * sigma
    if q > 0.0:
        overshoot, peak_time, rise, settle = _oscillating_metrics(f, sigma, math.sqrt(q), band)
    else:
        overshoot, peak_time = 0.0, math.inf
        rise, settle = _monotone_metrics(f, osc.time_constant, band)
    return StepMetrics(
        zeta=osc.damping_ratio,
        overshoot=overshoot,
        peak_time=peak_time,
        rise_time=rise,
        settling_time=settle,
        band=band,
        final_value=F0 / osc.k,
    )


def _crossing(f, level: float, a: float, b: float) -> float:
    """First time y = level on [a, b], y increasing there (1 - y decreasing); ``f`` is ``t -> 1 - y(t)``."""
    return _solve(lambda t: f(t) - (1.0 - level), a, b)


def _last_extremum_above(log_mp: float, band: float) -> int:
    """The last n whose extremum ``|y - 1| = overshoot^n`` (``log_mp = ln overshoot``) exceeds the band, 0 if none."""
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
    return n


def _oscillating_metrics(f, sigma: float, wd: float, band: float) -> tuple[float, float, float, float]:
    """Overshoot, peak time (s), rise time (s) and settling time (s) with oscillating roots ``-sigma +- i wd``."""
    half = math.pi / wd  # time between extrema, s
    log_mp = -sigma * half  # ln(overshoot), written without underflow
    overshoot = math.exp(log_mp)
    rise = _crossing(f, 0.9, 0.0, half) - _crossing(f, 0.1, 0.0, half)
    # extrema |y - 1| = overshoot^n at n half; N = the last one above the band
    n = _last_extremum_above(log_mp, band)
    # on [n half, (n + 1) half]: |y - 1| = overshoot^n (1 - y(tau)), tau = t - n half
    level = band * math.exp(-n * log_mp)
    tau = _solve(lambda t: f(t) - level, 0.0, half)
    return overshoot, half, rise, n * half + tau


def _monotone_metrics(f, hi: float, band: float) -> tuple[float, float]:
    """Rise time and settling time (s) of a monotone step response (real roots), bracketed from ``hi`` (s)."""
    for _ in range(2100):  # doubling from any normal float reaches the overflow in < 2100 steps
        if not f(hi) > min(band, 0.1):
            break
        hi *= 2.0
    rise = _crossing(f, 0.9, 0.0, hi) - _crossing(f, 0.1, 0.0, hi)
    settle = _crossing(f, 1.0 - band, 0.0, hi)
    return rise, settle


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
