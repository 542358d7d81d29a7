"""Poles, the three notions of stability, and the growth envelope of a forced response from rest."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_oscillator
from ..checks import like_input as _out
from ..model import Oscillator, ParameterError, SineForce
from ._common import _times

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
    >>> np.round(poles(Oscillator(m=1.0, c=0.5, k=20.0)), 4)          # 1/s
    array([-0.25+4.4651j, -0.25-4.4651j])
    >>> np.round(poles(Oscillator(m=1.0, c=15.0, k=20.0)), 4)
    array([ -1.4792+0.j, -13.5208+0.j])
    >>> poles(Oscillator(m=1.0, c=0.0, k=4.0))
    array([0.+2.j, 0.-2.j])
    """
    osc = check_oscillator(osc)
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


@dataclass(frozen=True, kw_only=True)
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
        As in :func:`poles`.

    Returns
    -------
    Stability

    Examples
    --------
    >>> stability_class(Oscillator(m=1.0, c=0.1, k=20.0)).verdict
    'asymptotically stable'
    >>> s = stability_class(Oscillator(m=1.0, c=0.0, k=20.0))
    >>> s.verdict, s.lyapunov, s.bibo
    ('marginally stable', True, False)
    >>> stability_class(Oscillator(m=1.0, c=-0.2, k=20.0)).spectral_abscissa     # 1/s
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
    osc, force
        The oscillator, m (kg), c (N s/m, any sign), k (N/m), and the force, F0 (N), omega (rad/s).
    t : array_like
        Times, s (finite, >= 0).

    Returns
    -------
    float or numpy.ndarray
        Envelope at ``t``, m (same shape as ``t``).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.0, k=4.0)
    >>> round(growth_envelope(osc, SineForce(F0=1.0, omega=2.0), 10.0), 6)       # m: (1/8) sqrt(1 + 400)
    2.503123
    >>> osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    >>> round(growth_envelope(osc, force, 1e3), 4)   # steady amplitude, m
    0.4504
    """
    check_oscillator(osc)
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
