"""The two-mass absorber's frequency response: magnification, exact peak, H2 integral, Den Hartog's fixed points.

Dimensionless groups and the magnification H(r) as in :mod:`vibration.physics.tmd`.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import scipy.linalg as sla

from ._limits import _f, _mu, _no_nan, _ratios, _zeta


@_no_nan
def tmd_magnification(mu, f, zeta_a, *, r, zeta_p=0.0) -> np.ndarray:
    """Primary's steady magnification |X_p| / (F0 / k_p) with a TMD, at ratios r = ω/ω_p.

    Parameters
    ----------
    mu : float
        Mass ratio m_a / m_p, 1 (0 < mu <= 10).
    f : float
        Tuning ratio ω_a / ω_p, 1 (0 < f <= 10).
    zeta_a : float
        Absorber damping ratio c_a / (2 m_a ω_a), 1, absorber's own frequency (0 to 10).
    r : float or array_like
        Forcing ratios ω / ω_p, 1 (>= 0).
    zeta_p : float
        Primary damping ratio c_p / (2 m_p ω_p), 1 (0 to 10).

    Returns
    -------
    numpy.ndarray
        |X_p| / (F0 / k_p), 1, shape of ``r``; ``inf`` at an undamped resonance.

    Examples
    --------
    >>> float(tmd_magnification(0.05, 1.0, 0.1, r=0.0))       # static: 1
    1.0
    >>> float(tmd_magnification(0.05, 1.0, 0.0, r=1.0))       # undamped absorber tuned to r: 0
    0.0
    """
    mu, f = _mu(mu), _f(f)
    za, zp = _zeta("zeta_a", zeta_a), _zeta("zeta_p", zeta_p)
    num, den = _factors(mu, f, za, zp, _ratios(r))
    with np.errstate(divide="ignore", invalid="ignore"):
        h = np.abs(num) / np.abs(den)
    return np.where(np.abs(den) == 0.0, np.inf, h)


def _stationary(mu: float, f: float, za: float, zp: float):
    """|H|² = P(s) / Q(s) with s = r² (ascending coefficients) and the real positive s where it is stationary."""
    pm, pd = np.polynomial.polynomial.polymul, np.polynomial.polynomial.polyder
    f2 = f * f
    num = np.array([f2 * f2, 4.0 * za * za * f2 - 2.0 * f2, 1.0])
    re = np.array([f2, -(1.0 + f2 + 4.0 * zp * za * f + mu * f2), 1.0])
    im = np.array([2.0 * zp * f2 + 2.0 * za * f, -(2.0 * zp + 2.0 * za * f * (1.0 + mu))])
    den = pm(re, re)
    den[1:4] += pm(im, im)
    stat = np.polynomial.polynomial.polysub(pm(pd(num), den), pm(num, pd(den)))
    roots = np.roots(stat[::-1])
    keep = (roots.real > 0.0) & (np.abs(roots.imag) <= 1e-6 * np.abs(roots))
    s = np.sort(roots.real[keep])
    pv, dstat = np.polynomial.polynomial.polyval, np.polynomial.polynomial.polyder(stat)
    for _ in range(2):  # Newton polish of the companion-matrix roots (sharp peaks need it)
        d = pv(s, dstat)
        step = np.divide(pv(s, stat), d, out=np.zeros_like(s), where=d != 0.0)
        s = np.where(np.abs(step) < 1e-3 * s, s - step, s)
    return num, den, s


def _peak(mu: float, f: float, za: float, zp: float) -> tuple[float, float]:
    """(max over r >= 0 of |H|, the r where it is reached), validated inputs."""
    if za == 0.0 and zp == 0.0:
        return math.inf, math.nan
    s = np.concatenate([[0.0], _stationary(mu, f, za, zp)[2]])
    g = _h2(mu, f, za, zp, np.sqrt(s))  # every candidate is a real r: a value of |H|², never above the supremum
    i = int(np.argmax(g))
    return math.sqrt(float(g[i])), math.sqrt(s[i])


def _factors(mu, f, za, zp, r):
    """Numerator and denominator of H(r) = X_p / (F0 / k_p), factored, complex, validated inputs."""
    num = f * f - r * r + 2j * za * f * r
    den = (1.0 - r * r + 2j * zp * r) * num - mu * r * r * (f * f + 2j * za * f * r)
    return num, den


def _h2(mu, f, za, zp, r):
    """|H(r)|² in the factored form (no cancellation of expanded polynomials near a sharp peak)."""
    num, den = _factors(mu, f, za, zp, r)
    return (num.real**2 + num.imag**2) / (den.real**2 + den.imag**2)


def _outer_peaks(mu: float, f: float, za: float, zp: float) -> tuple[float, float]:
    """|H|² at the lowest-frequency and at the highest-frequency local maximum (equal when there is one)."""
    s = _stationary(mu, f, za, zp)[2]
    g = _h2(mu, f, za, zp, np.sqrt(s))
    gp = _h2(mu, f, za, zp, np.sqrt(s * (1 + 1e-7)))
    maxima = g[(g >= gp)] if s.size else np.array([1.0])
    if maxima.size == 0:
        maxima = np.array([max(g.max(initial=1.0), 1.0)])
    return float(maxima[0]), float(maxima[-1])


@_no_nan
def tmd_peak(mu, f, zeta_a, *, zeta_p=0.0) -> float:
    """Largest magnification max_r |X_p| / (F0 / k_p) of the primary with a TMD, 1.

    Exact up to rounding: |H|² is a ratio of polynomials in s = r², so the
    maximum is at s = 0 or at a real positive root of the degree-5
    stationarity polynomial (``numpy`` companion-matrix roots).

    Parameters
    ----------
    mu, f, zeta_a, zeta_p : float
        As in :func:`tmd_magnification` (1; ζ_a relative to the absorber's own frequency).

    Returns
    -------
    float
        The peak, 1 (``inf`` when both dampings are zero).

    Examples
    --------
    >>> tmd_peak(0.05, 1 / 1.05, 0.0), round(tmd_peak(0.05, 1 / 1.05, 0.13), 3)   # undamped; near Den Hartog
    (inf, 6.425)
    """
    return _peak(_mu(mu), _f(f), _zeta("zeta_a", zeta_a), _zeta("zeta_p", zeta_p))[0]


@_no_nan
def h2_norm(mu, f, zeta_a, *, zeta_p=0.0) -> float:
    """Integral of |H(r)|² over 0 <= r < ∞, 1 (the H2 criterion of Warburton 1982).

    Computed exactly from the Lyapunov equation of the state-space model in
    the time τ = ω_p t: ∫_0^∞ |H|² dr = π C P Cᵀ with A P + P Aᵀ + B Bᵀ = 0.
    Proportional to the mean-square primary displacement under white-noise force.

    Parameters
    ----------
    mu, f, zeta_a, zeta_p : float
        As in :func:`tmd_magnification`.

    Returns
    -------
    float
        ∫_0^∞ |X_p / (F0/k_p)|² d(ω/ω_p), 1 (``inf`` when both dampings are zero).

    Examples
    --------
    >>> round(h2_norm(0.02, 0.985282, 0.070187), 4)
    22.1599
    """
    mu, f = _mu(mu), _f(f)
    za, zp = _zeta("zeta_a", zeta_a), _zeta("zeta_p", zeta_p)
    if za == 0.0 and zp == 0.0:
        return math.inf
    ka, ca, cp = mu * f * f, 2.0 * za * mu * f, 2.0 * zp
    A = np.array(
        [
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
            [-(1.0 + ka), ka, -(cp + ca), ca],
            [ka / mu, -ka / mu, ca / mu, -ca / mu],
        ]
    )
    B = np.array([[0.0], [0.0], [1.0], [0.0]])
    with warnings.catch_warnings():  # near-marginal modes: scipy perturbs and warns; the value is still its answer
        warnings.simplefilter("ignore", RuntimeWarning)
        Pm = sla.solve_continuous_lyapunov(A, -B @ B.T)
    return float(math.pi * Pm[0, 0])


@_no_nan
def tmd_fixed_points(mu, f) -> tuple[np.ndarray, np.ndarray]:
    """Den Hartog's fixed points: the two ratios where every absorber damping gives
    the same magnification of an undamped primary, and that magnification.

    They are the positive roots of (2 + μ) r⁴ − 2 (1 + f² (1 + μ)) r² + 2 f² = 0
    (the ζ_a = 0 and ζ_a = ∞ curves cross there), with height |1 / (1 − (1 + μ) r²)|.
    For a damped primary they are only approximate.

    Parameters
    ----------
    mu, f : float
        Mass ratio m_a/m_p and tuning ratio ω_a/ω_p, 1.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        Ratios r = ω/ω_p (ascending) and magnifications, 1, two each.

    Examples
    --------
    >>> r, h = tmd_fixed_points(0.05, 1 / 1.05)
    >>> [round(float(x), 6) for x in h], round(math.sqrt(1 + 2 / 0.05), 6)   # equal heights at Den Hartog's f
    ([6.403124, 6.403124], 6.403124)
    """
    mu, f = _mu(mu), _f(f)
    a, b, c = 2.0 + mu, -2.0 * (1.0 + f * f * (1.0 + mu)), 2.0 * f * f
    disc = math.sqrt(b * b - 4.0 * a * c)  # > 0 for every mu, f > 0
    big = (-b + disc) / (2.0 * a)
    small = c / (a * big)  # product of the roots, no cancellation
    r = np.sqrt(np.array([small, big]))
    return r, np.abs(1.0 / (1.0 - (1.0 + mu) * r * r))


# ----------------------------------------------------------------------------- the absorber's stroke
def _stroke_candidates(mu: float, f: float, za: float, zp: float) -> np.ndarray:
    """Real positive s = r² where |Z|² = s² / |den|² is stationary: the roots of 2 Q(s) − s Q'(s), Q = |den|²."""
    P = np.polynomial.polynomial
    den = _stationary(mu, f, za, zp)[1]  # |den|² in ascending powers of s (degree 4)
    stat = P.polysub(2.0 * den, P.polymulx(P.polyder(den)))
    roots = np.roots(np.trim_zeros(stat[::-1], "f"))
    keep = (roots.real > 0.0) & (np.abs(roots.imag) <= 1e-6 * np.abs(roots))
    s = np.sort(roots.real[keep])
    dstat = P.polyder(stat)
    for _ in range(2):  # Newton polish of the companion-matrix roots
        d = P.polyval(s, dstat)
        step = np.divide(P.polyval(s, stat), d, out=np.zeros_like(s), where=d != 0.0)
        s = np.where(np.abs(step) < 1e-3 * s, s - step, s)
    return s


def _stroke2(mu, f, za, zp, r):
    """|Z(r)|² with Z = (X_a − X_p) / (F0 / k_p) = r² / den, factored form."""
    den = _factors(mu, f, za, zp, r)[1]
    return r**4 / (den.real**2 + den.imag**2)


@_no_nan
def tmd_stroke(mu, f, zeta_a, *, r, zeta_p=0.0) -> np.ndarray:
    """Absorber stroke (its displacement relative to the primary) |X_a − X_p| / (F0 / k_p) at ratios r = ω/ω_p.

    From the absorber's equation, (X_a − X_p) / X_p = r² / (f² − r² + 2i ζ_a f r), so the stroke
    per static deflection is r² / |den| with the denominator of :func:`tmd_magnification`.

    Parameters
    ----------
    mu, f, zeta_a, r, zeta_p : float or array_like
        As in :func:`tmd_magnification` (1; ζ_a relative to the absorber's own frequency).

    Returns
    -------
    numpy.ndarray
        |X_a − X_p| / (F0 / k_p), 1, shape of ``r``; ``inf`` at an undamped resonance.

    Examples
    --------
    >>> float(tmd_stroke(0.05, 1.0, 0.1, r=0.0))                      # static: the absorber moves with the primary
    0.0
    >>> round(float(tmd_stroke(0.05, 1.0, 0.0, r=1.0)), 6)            # undamped, tuned: k_a Z = F0, Z k_p/F0 = 1/(μ f²)
    20.0
    """
    mu, f = _mu(mu), _f(f)
    za, zp = _zeta("zeta_a", zeta_a), _zeta("zeta_p", zeta_p)
    r = _ratios(r)
    den = _factors(mu, f, za, zp, r)[1]
    with np.errstate(divide="ignore", invalid="ignore"):
        z = (r * r) / np.abs(den)
    return np.where(np.abs(den) == 0.0, np.inf, z)


@_no_nan
def stroke_peak(mu, f, zeta_a, *, zeta_p=0.0) -> tuple[float, float]:
    """Largest stroke max_r |X_a − X_p| / (F0 / k_p) and the ratio r = ω/ω_p where it is reached.

    Exact up to rounding: |Z|² = s² / Q(s) with s = r², so the maximum is at a real positive root
    of 2 Q − s Q' (degree 4); it tends to 0 at r = 0 and as r → ∞.

    Parameters
    ----------
    mu, f, zeta_a, zeta_p : float
        Mass, tuning and damping ratios, 1, as in :func:`tmd_magnification`.

    Returns
    -------
    (float, float)
        The peak stroke per static deflection (1; ``inf`` when both dampings are zero) and its r (1).

    Examples
    --------
    >>> z, r = stroke_peak(0.05, 0.9524, 0.1339)
    >>> round(z, 3), round(r, 4)
    (21.673, 0.9232)
    """
    mu, f = _mu(mu), _f(f)
    za, zp = _zeta("zeta_a", zeta_a), _zeta("zeta_p", zeta_p)
    if za == 0.0 and zp == 0.0:
        return math.inf, math.nan
    s = _stroke_candidates(mu, f, za, zp)
    if s.size == 0:
        return 0.0, math.nan
    g = _stroke2(mu, f, za, zp, np.sqrt(s))
    i = int(np.argmax(g))
    return math.sqrt(float(g[i])), math.sqrt(float(s[i]))
