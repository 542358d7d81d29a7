"""Tuned mass dampers and multi-degree-of-freedom structures (Part II).

Two parts share this module.

**The tuned mass damper (TMD) on a single-degree-of-freedom primary.** A primary
mass m_p on a spring k_p and dashpot c_p carries an absorber mass m_a on a spring
k_a and dashpot c_a; the force F0 sin(ω t) acts on the primary. Everything is in
the dimensionless groups

* mass ratio μ = m_a / m_p,
* tuning ratio f = ω_a / ω_p with ω_a = sqrt(k_a / m_a), ω_p = sqrt(k_p / m_p),
* absorber damping ratio ζ_a = c_a / (2 m_a ω_a) (**the absorber's own frequency**,
  used everywhere in this API),
* primary damping ratio ζ_p = c_p / (2 m_p ω_p),
* forcing ratio r = ω / ω_p,

and the primary's magnification |X_p| / (F0 / k_p) is

    H(r) = (f² − r² + 2i ζ_a f r) /
           [(1 − r² + 2i ζ_p r)(f² − r² + 2i ζ_a f r) − μ r² (f² + 2i ζ_a f r)].

Some of the literature normalises the absorber's damping by the primary's
frequency instead, ζ'_a = c_a / (2 m_a ω_p) = f ζ_a. The three rules here, with
the convention of each source and the conversion applied:

* Den Hartog (Mechanical Vibrations, 4th ed., McGraw-Hill 1956, section 3.3):
  f = 1 / (1 + μ) and (c / c_c)² = 3μ / (8 (1 + μ)³) with c_c = 2 m_a ω_p, i.e.
  the primary's frequency; converted, ζ_a = (c / c_c) / f = sqrt(3μ / (8 (1 + μ))).
* Nishihara and Asami (2002), "Closed-form solutions to the exact optimizations
  of dynamic vibration absorbers (minimizations of the maximum amplitude
  magnification factors)", J. Vib. Acoust. 124:576-582: the exact H∞ optimum
  for an undamped primary, with s = sqrt(4 + 3μ),
  f = 2/(1+μ) sqrt(2 (16 + 23μ + 9μ² + 2 (2+μ) s) / (3 (64 + 80μ + 27μ²))),
  ζ_a = ¼ sqrt((8 + 9μ − 4 s) / (1 + μ)); their damping ratio is the absorber's
  own (no conversion; the numerical min-max of the tests lands on it). The
  minimum peak is algebraic too (proved there); the form used here,
  1/H∞² = μ (1024 + 2880μ + 2592μ² + 729μ³ + 128 s³) / (64 + 80μ + 27μ²)²,
  was identified from 70-digit evaluations of the peak at the closed-form
  tuning and is checked in the tests against the stationary-point peak.
* Warburton (1982), "Optimum absorber parameters for various combinations of
  response and excitation parameters", Earthquake Eng. Struct. Dyn.
  10:381-401, H2 optimum (mean-square primary displacement under white-noise
  force) for an undamped primary: f = sqrt(1 + μ/2) / (1 + μ),
  ζ_a = sqrt(μ (1 + 3μ/4) / (4 (1 + μ)(1 + μ/2))), absorber's own frequency
  (no conversion; the numerical minimum of the integral lands on it).

For a damped primary (ζ_p > 0) the H∞ and H2 optima are computed numerically
(:func:`hinf_tuning`, :func:`h2_tuning`).

**General linear MDOF structures.** :class:`MDOF` holds symmetric mass, damping
and stiffness matrices (SI) and gives natural frequencies, mass-normalised modes,
modal damping ratios when the damping is classical, the complex frequency
response and the exact response to ``load * sin(ω t)`` from any initial state.
:func:`tmd_system`, :func:`shear_building`, :func:`add_absorber` and
:func:`modal_damping_matrix` build the models of the chapter.

Examples
--------
>>> t = hinf_tuning(0.05)
>>> round(t.f, 6), round(t.zeta_a, 6), round(t.peak, 5)
(0.952372, 0.133938, 6.40792)
>>> round(den_hartog(0.05).zeta_a, 6), round(h2_tuning(0.05).f, 6)
(0.133631, 0.964212)
"""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg as sla
from scipy.optimize import fsolve, minimize

from .checks import check_array
from .model import ParameterError, check_real

__all__ = [
    "MDOF",
    "DampingNotClassical",
    "MDOFResponse",
    "TMDTuning",
    "add_absorber",
    "den_hartog",
    "first_mode_absorber",
    "h2_norm",
    "h2_tuning",
    "hinf_tuning",
    "mistuned_peak",
    "modal_damping_matrix",
    "shear_building",
    "tmd_fixed_points",
    "tmd_magnification",
    "tmd_peak",
    "tmd_system",
]

#: Largest mass ratio accepted, 1.
MU_MAX = 10.0
#: Smallest mass ratio accepted, 1 (below it the fixed points merge at r = 1 in floating point).
MU_MIN = 1e-9
#: Largest tuning ratio accepted, 1.
F_MAX = 10.0
#: Largest damping ratio accepted (absorber or primary) in the magnification, 1.
ZETA_MAX = 10.0
#: Largest primary damping ratio for which the optimal tunings are computed, 1.
ZETA_P_OPT_MAX = 0.5
#: Relative tolerance of the symmetry of M, C, K and of the classical-damping test.
SYM_TOL = 1e-10
#: Largest number of degrees of freedom of an MDOF model.
N_DOF_MAX = 500
#: Largest number of stiffness errors :func:`mistuned_peak` evaluates (one peak search each).
MISTUNED_MAX = 10_000
#: Largest work of one frequency-response or time-response call, in units of n³ (one n x n solve each):
#: ``len(omegas) n³`` for :meth:`MDOF.frf`, ``len(t) (2n + 2)³`` for the matrix exponentials of :meth:`MDOF.response`.
WORK_MAX = 2e9
#: Largest number of entries (len(t) times 2n) of one response array.
ENTRIES_MAX = 20_000_000


# ----------------------------------------------------------------------------- validation
def _no_nan(fn):
    """Run ``fn`` with numpy's floating-point warnings off and refuse a nan anywhere in its result.

    ``inf`` stays where it is documented (an undamped resonance); a nan would be an overflow or an
    undefined value coming out silently, so it is a :class:`ParameterError` instead.
    """

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with np.errstate(all="ignore"):
            out = fn(*args, **kwargs)
        values = [out.f, out.zeta_a, out.peak] if isinstance(out, TMDTuning) else out
        try:
            arr = np.asarray(values, dtype=float)
        except (TypeError, ValueError):  # a tuple of arrays of different shapes
            arr = np.concatenate([np.ravel(np.asarray(v, dtype=float)) for v in values])
        if np.any(np.isnan(arr)):
            raise ParameterError(
                f"{fn.__name__}{args!r}: the result is not defined in floating point (overflow or underflow of "
                "the inputs' products); allowed inputs well inside their ranges"
            )
        return out

    return wrapper


def _mu(mu) -> float:
    return check_real("mu", mu, low=MU_MIN, high=MU_MAX, unit="(m_a/m_p)")


def _f(f) -> float:
    return check_real("f", f, low=0.0, low_open=True, high=F_MAX, unit="(ω_a/ω_p)")


def _zeta(name: str, z, high: float = ZETA_MAX) -> float:
    return check_real(name, z, low=0.0, high=high)


def _ratios(r) -> np.ndarray:
    return check_array("r", r, low=0.0, ndim=(0, 1, 2), unit="(ω/ω_p)")


# ----------------------------------------------------------------------------- the TMD on an SDOF primary
@_no_nan
def tmd_magnification(mu, f, zeta_a, r, zeta_p=0.0) -> np.ndarray:
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
    >>> float(tmd_magnification(0.05, 1.0, 0.1, 0.0))       # static: 1
    1.0
    >>> float(tmd_magnification(0.05, 1.0, 0.0, 1.0))       # undamped absorber tuned to r: 0
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
def tmd_peak(mu, f, zeta_a, zeta_p=0.0) -> float:
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
def h2_norm(mu, f, zeta_a, zeta_p=0.0) -> float:
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


@dataclass(frozen=True)
class TMDTuning:
    """One absorber tuning and the peak it gives (dimensionless groups, see the module docstring)."""

    rule: str  # which rule gave it ("Den Hartog", "H∞ closed form", "H∞ numerical", "H2 closed form", ...)
    mu: float  # mass ratio m_a / m_p, 1
    f: float  # tuning ratio ω_a / ω_p, 1
    zeta_a: float  # absorber damping ratio c_a / (2 m_a ω_a), 1 (absorber's own frequency)
    zeta_p: float  # primary damping ratio for which peak was evaluated, 1
    peak: float  # max_r |X_p| / (F0 / k_p) on that primary, 1
    r_peak: float  # forcing ratio ω/ω_p of the peak (one of two at an H∞ optimum), 1

    @property
    def zeta_a_primary(self) -> float:
        """The same damping in the other convention, c_a / (2 m_a ω_p) = f ζ_a, 1."""
        return self.f * self.zeta_a

    @property
    def h2(self) -> float:
        """∫_0^∞ |H(r)|² dr on the primary of :attr:`zeta_p`, 1 (see :func:`h2_norm`)."""
        return h2_norm(self.mu, self.f, self.zeta_a, self.zeta_p)

    def absorber(self, m_p: float, k_p: float) -> tuple[float, float, float]:
        """Absorber (m_a kg, k_a N/m, c_a N s/m) for a primary of mass m_p (kg) and stiffness k_p (N/m).

        Examples
        --------
        >>> [round(v, 4) for v in den_hartog(0.05).absorber(1.0, 20.0)]
        [0.05, 0.907, 0.0569]
        """
        m_p = check_real("m_p", m_p, low=0.0, low_open=True, unit="kg")
        k_p = check_real("k_p", k_p, low=0.0, low_open=True, unit="N/m")
        m_a = self.mu * m_p
        w_a = self.f * math.sqrt(k_p / m_p)
        return m_a, m_a * w_a * w_a, 2.0 * self.zeta_a * m_a * w_a


def _record(rule, mu, f, za, zp) -> TMDTuning:
    peak, r_peak = _peak(mu, f, za, zp)
    return TMDTuning(rule, mu, f, za, zp, peak, r_peak)


def den_hartog(mu, zeta_p=0.0) -> TMDTuning:
    """Den Hartog's tuning: f = 1/(1+μ), ζ_a = sqrt(3μ / (8 (1+μ))).

    Den Hartog (Mechanical Vibrations, 1956) states the damping as
    (c/c_c)² = 3μ / (8 (1+μ)³) with c_c = 2 m_a ω_p (primary's frequency); it is
    converted here to the absorber's own frequency, ζ_a = (c/c_c) / f. The rule
    ignores primary damping; ``zeta_p`` only sets the primary on which
    :attr:`TMDTuning.peak` is evaluated.

    Parameters
    ----------
    mu : float
        Mass ratio m_a / m_p, 1 (0 < mu <= 10).
    zeta_p : float
        Primary damping ratio for the peak, 1 (0 to 0.5).

    Returns
    -------
    TMDTuning

    Examples
    --------
    >>> t = den_hartog(0.05)
    >>> round(t.f, 6), round(t.zeta_a, 6), round(t.zeta_a_primary, 6), round(t.peak, 4)
    (0.952381, 0.133631, 0.127267, 6.4084)
    """
    mu = _mu(mu)
    zp = _zeta("zeta_p", zeta_p, ZETA_P_OPT_MAX)
    return _record("Den Hartog", mu, 1.0 / (1.0 + mu), math.sqrt(3.0 * mu / (8.0 * (1.0 + mu))), zp)


def _hinf_closed(mu: float) -> tuple[float, float, float]:
    s = math.sqrt(4.0 + 3.0 * mu)
    q = 64.0 + 80.0 * mu + 27.0 * mu * mu
    f = 2.0 / (1.0 + mu) * math.sqrt(2.0 * (16.0 + 23.0 * mu + 9.0 * mu * mu + 2.0 * (2.0 + mu) * s) / (3.0 * q))
    za = 0.25 * math.sqrt((8.0 + 9.0 * mu - 4.0 * s) / (1.0 + mu))
    inv2 = mu * (1024.0 + mu * (2880.0 + mu * (2592.0 + 729.0 * mu)) + 128.0 * s**3) / (q * q)
    return f, za, 1.0 / math.sqrt(inv2)


def _hinf_numerical(mu: float, zp: float, f0: float, z0: float) -> tuple[float, float]:
    """Min over (f, ζ_a) of the peak: Nelder-Mead, then the equal-peak optimality conditions.

    At a two-peak optimum the low and high peaks are equal and their gradients
    in (f, ln ζ_a) are opposite: G_low = G_high and det[∇G_low, ∇G_high] = 0.
    Those two smooth equations are solved by ``scipy.optimize.fsolve`` from the
    Nelder-Mead point (central differences, step 1e-6); the solution is kept
    only when the gradients are indeed opposite and the peak is not higher.
    """

    def cost(x):
        f, lz = x
        if not (0.0 < f <= F_MAX and lz < math.log(ZETA_MAX)):
            return math.inf
        return math.log(_peak(mu, f, math.exp(lz), zp)[0])

    nm = minimize(cost, [f0, math.log(z0)], method="Nelder-Mead", options={"xatol": 1e-9, "fatol": 1e-13})
    best = nm.x
    h = 1e-6

    def logs(x):
        return np.log(_outer_peaks(mu, x[0], math.exp(x[1]), zp))

    def grads(x):
        g = np.empty((2, 2))
        for j in range(2):
            e = np.zeros(2)
            e[j] = h
            g[:, j] = (logs(x + e) - logs(x - e)) / (2.0 * h)
        return g  # rows: low, high peak

    def equations(x):
        g = grads(x)
        lo, hi = logs(x)
        return [lo - hi, g[0, 0] * g[1, 1] - g[0, 1] * g[1, 0]]

    sol, _, ier, _ = fsolve(equations, best, xtol=1e-13, full_output=True)
    if ier == 1 and 0.0 < sol[0] <= F_MAX:
        g = grads(sol)
        opposite = float(np.dot(g[0], g[1])) < 0.0
        if opposite and cost(sol) <= cost(best) + 1e-12:
            best = sol
    return float(best[0]), math.exp(float(best[1]))


def _closed_form(method, zp: float) -> bool:
    """Check an optimiser's ``method`` against ``zp``; True when the closed form applies."""
    if method not in ("auto", "closed form", "numerical"):
        raise ParameterError(f"method = {method!r} is not known: allowed 'auto', 'closed form', 'numerical'")
    if method == "closed form" and zp != 0.0:
        raise ParameterError(f"zeta_p = {zp!r}: the closed form needs an undamped primary, allowed zeta_p = 0")
    return method == "closed form" or (method == "auto" and zp == 0.0)


@_no_nan
def hinf_tuning(mu, zeta_p=0.0, method="auto") -> TMDTuning:
    """The H∞ optimum: (f, ζ_a) minimising the primary's largest magnification.

    For an undamped primary the closed form of Nishihara and Asami (2002,
    J. Vib. Acoust. 124:576-582) is used (ζ_a relative to the absorber's own
    frequency, as in the paper); for a damped primary, or with
    ``method="numerical"``, a nested bounded min-max: Brent over f of Brent over
    log ζ_a of the exact peak (:func:`tmd_peak`), each bracketed by a grid
    around Den Hartog's values.

    Parameters
    ----------
    mu : float
        Mass ratio m_a / m_p, 1 (0 < mu <= 10).
    zeta_p : float
        Primary damping ratio, 1 (0 to 0.5).
    method : {"auto", "closed form", "numerical"}
        "auto": closed form when zeta_p is 0, numerical otherwise.

    Returns
    -------
    TMDTuning
        With ``.peak`` the minimised largest magnification.

    Examples
    --------
    >>> t = hinf_tuning(0.05, zeta_p=0.0559)
    >>> t.rule, round(t.f, 4), round(t.zeta_a, 4), round(t.peak, 4)
    ('H∞ numerical', 0.9331, 0.142, 3.9789)
    """
    mu = _mu(mu)
    zp = _zeta("zeta_p", zeta_p, ZETA_P_OPT_MAX)
    if _closed_form(method, zp):
        f, za, peak = _hinf_closed(mu)
        return TMDTuning("H∞ closed form", mu, f, za, 0.0, peak, _peak(mu, f, za, 0.0)[1])
    f0, z0 = 1.0 / (1.0 + mu), math.sqrt(3.0 * mu / (8.0 * (1.0 + mu)))
    f, za = _hinf_numerical(mu, zp, f0, z0)
    return _record("H∞ numerical", mu, f, za, zp)


@_no_nan
def h2_tuning(mu, zeta_p=0.0, method="auto") -> TMDTuning:
    """The H2 optimum: (f, ζ_a) minimising ∫_0^∞ |H(r)|² dr (white-noise force).

    For an undamped primary Warburton's closed form (1982, Earthquake Eng.
    Struct. Dyn. 10:381-401, force excitation, primary displacement; ζ_a relative
    to the absorber's own frequency): f = sqrt(1 + μ/2)/(1 + μ),
    ζ_a = sqrt(μ (1 + 3μ/4) / (4 (1 + μ)(1 + μ/2))). For a damped primary, or with
    ``method="numerical"``, Nelder-Mead on the exact Lyapunov value
    (:func:`h2_norm`) from Warburton's point.

    Parameters
    ----------
    mu : float
        Mass ratio m_a / m_p, 1 (0 < mu <= 10).
    zeta_p : float
        Primary damping ratio, 1 (0 to 0.5).
    method : {"auto", "closed form", "numerical"}
        "auto": closed form when zeta_p is 0, numerical otherwise.

    Returns
    -------
    TMDTuning
        ``.peak`` is the largest magnification this tuning gives (not the criterion).

    Examples
    --------
    >>> t = h2_tuning(0.02)
    >>> round(t.f, 6), round(t.zeta_a, 6), round(t.h2, 4)
    (0.985282, 0.070187, 22.1599)
    """
    mu = _mu(mu)
    zp = _zeta("zeta_p", zeta_p, ZETA_P_OPT_MAX)
    closed = _closed_form(method, zp)
    f = math.sqrt(1.0 + mu / 2.0) / (1.0 + mu)
    za = math.sqrt(mu * (1.0 + 0.75 * mu) / (4.0 * (1.0 + mu) * (1.0 + mu / 2.0)))
    if closed:
        return _record("H2 closed form", mu, f, za, 0.0)

    def cost(x):
        ff, lz = x
        if not (0.0 < ff <= F_MAX and lz < math.log(ZETA_MAX)):
            return math.inf
        return math.log(h2_norm(mu, ff, math.exp(lz), zp))

    res = minimize(
        cost, [f, math.log(za)], method="Nelder-Mead", options={"xatol": 1e-9, "fatol": 1e-14, "maxiter": 2000}
    )
    return _record("H2 numerical", mu, float(res.x[0]), math.exp(float(res.x[1])), zp)


@_no_nan
def mistuned_peak(tuning: TMDTuning, stiffness_error, zeta_p=None) -> np.ndarray:
    """Largest primary magnification when the primary's stiffness is off by a fraction.

    The absorber (m_a, k_a, c_a) is kept; the primary's stiffness becomes
    k_p (1 + ε), so ω_p grows by sqrt(1 + ε), the true tuning ratio is
    f / sqrt(1 + ε) and the primary's damping ratio ζ_p / sqrt(1 + ε). The peak is
    divided by the nominal static deflection F0 / k_p.

    Parameters
    ----------
    tuning : TMDTuning
        The nominal tuning.
    stiffness_error : float or array_like
        ε, relative error of the primary's stiffness, 1 (−0.9 to 9).
    zeta_p : float, optional
        Nominal primary damping ratio, 1; by default ``tuning.zeta_p``.

    Returns
    -------
    numpy.ndarray
        max_ω |X_p| / (F0 / k_p nominal), 1, shape of ``stiffness_error``.

    Examples
    --------
    >>> t = den_hartog(0.05)
    >>> round(float(mistuned_peak(t, 0.0)), 4) == round(t.peak, 4)
    True
    """
    if not isinstance(tuning, TMDTuning):
        raise ParameterError(f"tuning = {tuning!r} is not a TMDTuning: allowed den_hartog(...), hinf_tuning(...)")
    zp = tuning.zeta_p if zeta_p is None else _zeta("zeta_p", zeta_p)
    eps = check_array("stiffness_error", stiffness_error, low=-0.9, high=9.0, ndim=(0, 1, 2), max_size=MISTUNED_MAX)
    flat = eps.ravel()
    out = np.empty(flat.shape)
    for i, e in enumerate(flat):
        g = math.sqrt(1.0 + e)
        out[i] = _peak(tuning.mu, _f(tuning.f / g), tuning.zeta_a, zp / g)[0] / (1.0 + e)
    return out.reshape(eps.shape)


# ----------------------------------------------------------------------------- MDOF
class DampingNotClassical(ParameterError):
    """The damping matrix is not uncoupled by the undamped modes: modal damping ratios do not exist."""


@dataclass(frozen=True)
class MDOFResponse:
    """Response of an :class:`MDOF` model on a time grid."""

    t: np.ndarray  # time, s, shape (n_t,)
    x: np.ndarray  # displacements, m, shape (n_t, n)
    v: np.ndarray  # velocities, m/s, shape (n_t, n)


def _matrix(name: str, A, n: int | None) -> np.ndarray:
    arr = check_array(name, A, ndim=(0, 2), max_size=N_DOF_MAX * N_DOF_MAX)
    if arr.ndim == 0 and n in (None, 1):
        arr = arr.reshape(1, 1)
    if arr.ndim != 2 or arr.shape[0] != arr.shape[1] or arr.shape[0] == 0:
        raise ParameterError(f"{name} has shape {arr.shape}: allowed a square matrix (n, n), 1 <= n <= {N_DOF_MAX}")
    if n is not None and arr.shape[0] != n:
        raise ParameterError(f"{name} has shape {arr.shape}: allowed ({n}, {n}), the shape of M")
    if arr.shape[0] > N_DOF_MAX:
        raise ParameterError(f"{name} has {arr.shape[0]} rows: allowed 1 <= n <= {N_DOF_MAX}")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} = {arr.tolist()!r} has non-finite entries: allowed finite entries")
    scale = float(np.max(np.abs(arr))) if arr.size else 0.0
    asym = float(np.max(np.abs(arr - arr.T)))
    if asym > SYM_TOL * scale:
        raise ParameterError(
            f"{name} is not symmetric (max |{name} - {name}ᵀ| = {asym:.3g}): allowed a symmetric matrix"
        )
    arr = 0.5 * (arr + arr.T)
    arr.setflags(write=False)
    return arr


def _positive_definite(name: str, A: np.ndarray, semi: bool = False) -> None:
    w = np.linalg.eigvalsh(A)
    scale = max(float(np.max(np.abs(w))), np.finfo(float).tiny)
    ok = w.min() >= -SYM_TOL * scale if semi else w.min() > 0.0
    if not ok:
        what = "positive semi-definite" if semi else "positive definite"
        raise ParameterError(f"{name} has eigenvalue {w.min():.6g} (smallest): allowed a symmetric {what} matrix")


@dataclass(frozen=True, eq=False)
class MDOF:
    """Linear structure M x'' + C x' + K x = F(t), SI units.

    Parameters
    ----------
    M : array_like
        Mass matrix, kg, symmetric positive definite (n, n).
    C : array_like
        Viscous damping matrix, N s/m, symmetric positive semi-definite (n, n).
    K : array_like
        Stiffness matrix, N/m, symmetric positive definite (n, n).

    Examples
    --------
    >>> s = MDOF([[1.0, 0], [0, 1.0]], [[0.0, 0], [0, 0.0]], [[2.0, -1.0], [-1.0, 2.0]])
    >>> s.natural_frequencies.round(6).tolist()             # rad/s
    [1.0, 1.732051]
    >>> s.modal_damping_ratios.tolist()
    [0.0, 0.0]
    """

    M: np.ndarray  # mass matrix, kg
    C: np.ndarray  # damping matrix, N s/m
    K: np.ndarray  # stiffness matrix, N/m

    def __post_init__(self) -> None:
        M = _matrix("M", self.M, None)
        n = M.shape[0]
        C, K = _matrix("C", self.C, n), _matrix("K", self.K, n)
        _positive_definite("M", M)
        _positive_definite("K", K)
        _positive_definite("C", C, semi=True)
        object.__setattr__(self, "M", M)
        object.__setattr__(self, "C", C)
        object.__setattr__(self, "K", K)

    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return self.M.shape[0]

    @cached_property
    def _eig(self):
        w2, phi = sla.eigh(self.K, self.M)  # phiᵀ M phi = I
        w = np.sqrt(np.maximum(w2, 0.0))
        if self.is_classically_damped:  # rotate within repeated frequencies so that phiᵀ C phi is diagonal
            i = 0
            while i < len(w):
                j = i + 1
                while j < len(w) and w[j] - w[i] <= 1e-9 * max(w[j], 1e-300):
                    j += 1
                if j - i > 1:
                    block = phi[:, i:j].T @ self.C @ phi[:, i:j]
                    _, rot = np.linalg.eigh(0.5 * (block + block.T))
                    phi[:, i:j] = phi[:, i:j] @ rot
                i = j
        big = np.argmax(np.abs(phi), axis=0)  # sign: largest component of each mode positive
        phi = phi * np.sign(phi[big, np.arange(phi.shape[1])])
        w.setflags(write=False)
        phi.setflags(write=False)
        return w, phi

    @property
    def natural_frequencies(self) -> np.ndarray:
        """Undamped natural frequencies ω_i, rad/s, ascending."""
        return self._eig[0]

    @property
    def modes(self) -> np.ndarray:
        """Mass-normalised mode shapes as columns (Φᵀ M Φ = I, 1/sqrt(kg)); largest entry of each positive."""
        return self._eig[1]

    @cached_property
    def classical_mismatch(self) -> float:
        """Caughey and O'Kelly's test: ||C M⁻¹ K − K M⁻¹ C|| / (||C|| ||M⁻¹|| ||K||), 1 (0 when classical)."""
        Minv = np.linalg.inv(self.M)
        a = self.C @ Minv @ self.K
        norm = np.linalg.norm(self.C, 2) * np.linalg.norm(Minv, 2) * np.linalg.norm(self.K, 2)
        return 0.0 if norm == 0.0 else float(np.linalg.norm(a - a.T, 2) / norm)

    @property
    def is_classically_damped(self) -> bool:
        """Whether the undamped modes uncouple C (C M⁻¹ K = K M⁻¹ C to 1e-10 relative)."""
        return self.classical_mismatch <= SYM_TOL

    @property
    def damping_note(self) -> str:
        """One sentence saying whether modal damping ratios exist."""
        if self.is_classically_damped:
            return "The damping is classical: the undamped modes uncouple it, and each mode has a damping ratio."
        return (
            f"The damping is not classical (C M⁻¹K ≠ K M⁻¹C, relative mismatch {self.classical_mismatch:.2g}): "
            "the undamped modes do not uncouple it, so modal damping ratios do not exist; "
            "the complex poles give each mode's decay instead."
        )

    @property
    def modal_damping_ratios(self) -> np.ndarray:
        """ζ_i = (Φᵀ C Φ)_ii / (2 ω_i), 1; raises :class:`DampingNotClassical` when they do not exist."""
        if not self.is_classically_damped:
            raise DampingNotClassical(
                f"C: {self.damping_note} Allowed: C with C M⁻¹K = K M⁻¹C (e.g. Rayleigh or modal damping)"
            )
        w, phi = self._eig
        c = np.einsum("ij,ik,kj->j", phi, self.C, phi)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(w > 0.0, c / (2.0 * w), np.inf)

    @cached_property
    def state_matrix(self) -> np.ndarray:
        """First-order matrix A of z' = A z + [0; M⁻¹ F], z = [x; v], 1/s blocks."""
        n = self.n
        Minv = np.linalg.inv(self.M)
        A = np.zeros((2 * n, 2 * n))
        A[:n, n:] = np.eye(n)
        A[n:, :n] = -Minv @ self.K
        A[n:, n:] = -Minv @ self.C
        A.setflags(write=False)
        return A

    @property
    def poles(self) -> np.ndarray:
        """Eigenvalues λ of the state matrix, rad/s, sorted by |λ| (complex modes; exist for any damping)."""
        lam = np.linalg.eigvals(self.state_matrix)
        return lam[np.lexsort((lam.imag, np.abs(lam)))]

    def _load(self, load) -> np.ndarray:
        p = check_array("load", load, ndim=(0, 1, 2), max_size=N_DOF_MAX, unit="N").reshape(-1)
        if p.shape != (self.n,):
            raise ParameterError(f"load = {np.asarray(load).tolist()!r}: allowed {self.n} finite force amplitudes, N")
        return p

    def frf(self, omegas, load) -> np.ndarray:
        """Complex amplitudes X (m) of the steady response to ``load * sin(ω t)``.

        X = (K − ω² M + iω C)⁻¹ load, so that x(t) = Re X sin(ωt) + Im X cos(ωt)
        and |X| is the amplitude; with a unit load it is the receptance, m/N.

        Parameters
        ----------
        omegas : float or array_like
            Forcing frequencies, rad/s (>= 0).
        load : array_like
            Force amplitude on each degree of freedom, N, shape (n,).

        Returns
        -------
        numpy.ndarray
            Complex, shape (len(omegas), n), m; ``inf`` where K − ω² M + iω C is singular.

        Examples
        --------
        >>> s = MDOF([[1.0]], [[0.5]], [[20.0]])
        >>> round(float(abs(s.frf([4.47], [5.0])[0, 0])), 4)     # the paper's resonance amplitude, m
        2.2371
        """
        p = self._load(load)
        w = np.atleast_1d(check_array("omegas", omegas, low=0.0, ndim=(0, 1), unit="rad/s"))
        if not w.size * self.n**3 <= WORK_MAX:
            raise ParameterError(
                f"omegas has {w.size} frequencies: with n = {self.n} degrees of freedom that is "
                f"{w.size * self.n**3:.3g} units of n³ work, allowed at most {WORK_MAX:g} "
                f"(len(omegas) <= {int(WORK_MAX // self.n**3)})"
            )
        out = np.empty((w.size, self.n), dtype=complex)
        for i in range(w.size):
            with np.errstate(over="ignore", invalid="ignore"):
                D = self.K - (w[i] * w[i]) * self.M + 1j * w[i] * self.C
            if not np.all(np.isfinite(D)):
                raise ParameterError(
                    f"omegas contains {w[i]!r} rad/s: the dynamic stiffness K - ω² M + iω C overflows there; "
                    "allowed frequencies at which it is finite"
                )
            try:
                out[i] = np.linalg.solve(D, p)
            except np.linalg.LinAlgError:
                out[i] = np.inf
        return out

    def response(self, t, load, omega, x0=None, v0=None, method="auto") -> MDOFResponse:
        """Exact response to ``load * sin(omega t)`` from x(0) = x0, v(0) = v0.

        "modal": steady state from the complex solve (:meth:`frf`) plus the free
        response exp(A t) z_h(0) by complex modal superposition of the state
        matrix A (its eigenvectors V, exp(A t) = V exp(Λ t) V⁻¹). "expm": the
        matrix exponential of the first-order system augmented with the two
        states of the harmonic load, valid also at an undamped resonance
        (secular growth). "auto" uses "modal" unless V is ill-conditioned
        (cond > 1e8, near-defective, e.g. critical damping) or the dynamic
        stiffness is near-singular (cond > 1e10), then "expm".

        Parameters
        ----------
        t : array_like
            Times, s (finite, >= 0, any order).
        load : array_like
            Force amplitudes, N, shape (n,).
        omega : float
            Forcing frequency, rad/s (>= 0).
        x0, v0 : array_like, optional
            Initial displacements (m) and velocities (m/s); rest by default.
        method : {"auto", "modal", "expm"}

        Returns
        -------
        MDOFResponse
            ``x`` (m) and ``v`` (m/s), shape (len(t), n).

        Examples
        --------
        >>> s = MDOF([[1.0]], [[0.5]], [[20.0]])
        >>> r = s.response([0.0, 50.0], [5.0], 4.47)
        >>> round(float(r.x[0, 0]), 12), round(float(r.x[1, 0]), 4)
        (0.0, 2.009)
        """
        p = self._load(load)
        omega = check_real("omega", omega, low=0.0, unit="rad/s")
        t = np.atleast_1d(check_array("t", t, low=0.0, ndim=(0, 1), unit="s"))
        n = self.n
        if not t.size * 2 * n <= ENTRIES_MAX:
            raise ParameterError(
                f"t has {t.size} samples: with n = {n} degrees of freedom the response has {t.size * 2 * n} entries, "
                f"allowed at most {ENTRIES_MAX} (memory)"
            )
        z0 = np.zeros(2 * n)
        if x0 is not None:
            z0[:n] = self._state("x0", x0)
        if v0 is not None:
            z0[n:] = self._state("v0", v0)
        if method not in ("auto", "modal", "expm"):
            raise ParameterError(f"method = {method!r} is not known: allowed 'auto', 'modal', 'expm'")
        if method != "expm":
            with np.errstate(over="ignore", invalid="ignore"):
                D = self.K - omega * omega * self.M + 1j * omega * self.C
            if not np.all(np.isfinite(D)):
                raise ParameterError(
                    f"omega = {omega!r} rad/s: the dynamic stiffness K - ω² M + iω C overflows; allowed a smaller omega"
                )
            lam, V = np.linalg.eig(self.state_matrix)
            well = np.linalg.cond(V) <= 1e8 and np.linalg.cond(D) <= 1e10
            if well or method == "modal":
                try:
                    with np.errstate(all="ignore"):  # a non-finite result is refused below
                        X = np.linalg.solve(D, p)
                        st, ct = np.sin(omega * t), np.cos(omega * t)
                        xs = np.outer(st, X.real) + np.outer(ct, X.imag)
                        vs = omega * (np.outer(ct, X.real) - np.outer(st, X.imag))
                        zh0 = z0 - np.concatenate([X.imag, omega * X.real])
                        q0 = np.linalg.solve(V, zh0.astype(complex))
                        zh = ((np.exp(np.outer(t, lam)) * q0) @ V.T).real
                        x, v = xs + zh[:, :n], vs + zh[:, n:]
                except np.linalg.LinAlgError:
                    raise ParameterError(
                        f"omega = {omega!r} rad/s is a natural frequency of the undamped model: the modal method has "
                        "no steady state there; allowed method='expm' or 'auto' (secular growth)"
                    ) from None
                return _finite_response(MDOFResponse(t, x, v))
        Minv_p = np.linalg.solve(self.M, p)
        Aa = np.zeros((2 * n + 2, 2 * n + 2))
        Aa[: 2 * n, : 2 * n] = self.state_matrix
        Aa[n : 2 * n, 2 * n] = Minv_p  # load * s, with s = sin(ω t), c = cos(ω t)
        Aa[2 * n, 2 * n + 1] = omega  # s' = ω c
        Aa[2 * n + 1, 2 * n] = -omega  # c' = −ω s
        za = np.concatenate([z0, [0.0, 1.0]])
        if not t.size * (2 * n + 2) ** 3 <= WORK_MAX:
            raise ParameterError(
                f"t has {t.size} samples: the matrix exponential of size {2 * n + 2} at each is "
                f"{t.size * (2 * n + 2) ** 3:.3g} units of work, allowed at most {WORK_MAX:g} "
                f"(len(t) <= {int(WORK_MAX // (2 * n + 2) ** 3)} here)"
            )
        with np.errstate(all="ignore"):  # a non-finite result is refused below
            z = sla.expm(Aa[None] * t[:, None, None]) @ za
        return _finite_response(MDOFResponse(t, z[:, :n], z[:, n : 2 * n]))

    def _state(self, name: str, value) -> np.ndarray:
        a = check_array(name, value, ndim=(0, 1, 2), max_size=N_DOF_MAX).reshape(-1)
        if a.shape != (self.n,):
            raise ParameterError(f"{name} = {np.asarray(value).tolist()!r}: allowed {self.n} finite values")
        return a


def _finite_response(r: MDOFResponse) -> MDOFResponse:
    if not (np.all(np.isfinite(r.x)) and np.all(np.isfinite(r.v))):
        bad = float(r.t[~(np.all(np.isfinite(r.x), axis=1) & np.all(np.isfinite(r.v), axis=1))][0])
        raise ParameterError(
            f"t contains {bad!r} s: the response is not finite there (overflow, or a load at an undamped "
            "resonance the modal method cannot represent: use method='expm'); allowed times where it is finite"
        )
    return r


def modal_damping_matrix(M, K, zeta) -> np.ndarray:
    """Classical damping matrix C = M Φ diag(2 ζ_i ω_i) Φᵀ M with given modal damping ratios.

    Parameters
    ----------
    M, K : array_like
        Mass (kg) and stiffness (N/m) matrices, symmetric positive definite.
    zeta : float or array_like
        Damping ratio of every mode (or one per mode, ascending frequency), 1 (0 to 10).

    Returns
    -------
    numpy.ndarray
        C, N s/m.

    Examples
    --------
    >>> C = modal_damping_matrix([[1.0]], [[20.0]], 0.0559)
    >>> round(float(C[0, 0]), 3)
    0.5
    """
    model = MDOF(M, np.zeros_like(_matrix("M", M, None)), K)
    z = check_array("zeta", zeta, low=0.0, high=ZETA_MAX, ndim=(0, 1), max_size=N_DOF_MAX)
    if z.size not in (1, model.n):
        raise ParameterError(f"zeta has {z.size} values: allowed 1 or one per mode ({model.n})")
    z = np.broadcast_to(z, (model.n,))
    w, phi = model.natural_frequencies, model.modes
    Mphi = model.M @ phi
    C = Mphi @ np.diag(2.0 * z * w) @ Mphi.T
    return 0.5 * (C + C.T)


def shear_building(masses, stiffnesses, zeta=0.05) -> MDOF:
    """Shear building: floor masses on storeys of given lateral stiffness, classical modal damping.

    Degree of freedom i is floor i + 1 counted from the ground (the last is the roof);
    storey i joins floor i to the floor below (the ground for i = 0).

    Parameters
    ----------
    masses : array_like
        Floor masses, kg (> 0), ground floor first.
    stiffnesses : array_like
        Storey stiffnesses, N/m (> 0), same length.
    zeta : float or array_like
        Modal damping ratio of every mode (or one per mode), 1.

    Returns
    -------
    MDOF

    Examples
    --------
    >>> b = shear_building([1.0, 1.0], [1.0, 1.0], zeta=0.0)
    >>> b.K.tolist()
    [[2.0, -1.0], [-1.0, 1.0]]
    """
    m = np.atleast_1d(check_array("masses", masses, low=0.0, low_open=True, max_size=N_DOF_MAX, unit="kg"))
    k = np.atleast_1d(check_array("stiffnesses", stiffnesses, low=0.0, low_open=True, max_size=N_DOF_MAX, unit="N/m"))
    if k.shape != m.shape:
        raise ParameterError(
            f"masses has {m.size} values and stiffnesses {k.size}: "
            f"allowed two 1-D arrays of equal length 1..{N_DOF_MAX}"
        )
    n = m.size
    K = np.zeros((n, n))
    for i in range(n):
        K[i, i] += k[i]
        if i + 1 < n:
            K[i, i] += k[i + 1]
            K[i, i + 1] = K[i + 1, i] = -k[i + 1]
    M = np.diag(m)
    return MDOF(M, modal_damping_matrix(M, K, zeta), K)


def add_absorber(model: MDOF, dof: int, m_a, k_a, c_a) -> MDOF:
    """The model with an absorber (mass, spring, dashpot) attached to degree of freedom ``dof``.

    The absorber is the new last degree of freedom.

    Parameters
    ----------
    model : MDOF
    dof : int
        Index of the degree of freedom carrying it (negative counts from the end).
    m_a, k_a, c_a : float
        Absorber mass (kg, > 0), stiffness (N/m, > 0), damping (N s/m, >= 0).

    Returns
    -------
    MDOF

    Examples
    --------
    >>> s = add_absorber(MDOF([[1.0]], [[0.0]], [[20.0]]), 0, 0.05, 0.9, 0.01)
    >>> s.n, s.is_classically_damped
    (2, False)
    """
    if not isinstance(model, MDOF):
        raise ParameterError(f"model = {model!r} is not an MDOF: allowed MDOF(M, C, K)")
    n = model.n
    if isinstance(dof, bool) or not isinstance(dof, int | np.integer) or not -n <= dof < n:
        raise ParameterError(f"dof = {dof!r} is out of range: allowed an integer -{n} <= dof < {n}")
    j = int(dof) % n
    m_a = check_real("m_a", m_a, low=0.0, low_open=True, unit="kg")
    k_a = check_real("k_a", k_a, low=0.0, low_open=True, unit="N/m")
    c_a = check_real("c_a", c_a, low=0.0, unit="N s/m")
    M, C, K = (np.zeros((n + 1, n + 1)) for _ in range(3))
    M[:n, :n], C[:n, :n], K[:n, :n] = model.M, model.C, model.K
    M[n, n] = m_a
    for A, v in ((C, c_a), (K, k_a)):
        A[j, j] += v
        A[n, n] += v
        A[j, n] -= v
        A[n, j] -= v
    return MDOF(M, C, K)


def tmd_system(m, c, k, tuning: TMDTuning) -> MDOF:
    """Two-degree-of-freedom model: the primary (m kg, c N s/m, k N/m) and the absorber of ``tuning``.

    Degree of freedom 0 is the primary, 1 the absorber.

    Examples
    --------
    >>> s = tmd_system(1.0, 0.5, 20.0, den_hartog(0.05))
    >>> s.n, round(float(s.M[1, 1]), 3)
    (2, 0.05)
    """
    if not isinstance(tuning, TMDTuning):
        raise ParameterError(f"tuning = {tuning!r} is not a TMDTuning: allowed den_hartog(...), hinf_tuning(...)")
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    c = check_real("c", c, low=0.0, unit="N s/m")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    return add_absorber(MDOF([[m]], [[c]], [[k]]), 0, *tuning.absorber(m, k))


@dataclass(frozen=True)
class ModeAbsorber:
    """An absorber tuned to one mode of an MDOF structure through its equivalent single-degree-of-freedom system."""

    tuning: TMDTuning  # tuning on the equivalent primary (mass ratio to the modal mass)
    modal_mass: float  # generalised mass of the mode normalised to 1 at the carrying degree of freedom, kg
    omega: float  # natural frequency of the mode, rad/s
    zeta: float  # damping ratio of the mode, 1
    m_a: float  # absorber mass, kg
    k_a: float  # absorber stiffness, N/m
    c_a: float  # absorber damping, N s/m


def first_mode_absorber(model: MDOF, mu, dof: int = -1, rule: str = "H∞") -> ModeAbsorber:
    """Absorber at ``dof`` tuned to the first mode (equivalent SDOF: modal mass, frequency, damping).

    The first mode φ is scaled to 1 at ``dof``; the equivalent primary has mass
    M1 = φᵀ M φ, stiffness ω1² M1 and the mode's damping ratio, and the absorber
    mass is μ M1. The rule ("H∞": :func:`hinf_tuning` on the damped equivalent
    primary, "Den Hartog", or "H2": :func:`h2_tuning`) gives f and ζ_a.

    Parameters
    ----------
    model : MDOF
        Classically damped structure.
    mu : float
        Absorber mass over the first modal mass, 1 (0 < mu <= 10).
    dof : int
        Degree of freedom carrying the absorber (default: the last, the roof).
    rule : {"H∞", "Den Hartog", "H2"}

    Returns
    -------
    ModeAbsorber

    Examples
    --------
    >>> a = first_mode_absorber(MDOF([[1.0]], [[0.5]], [[20.0]]), 0.05)
    >>> round(a.modal_mass, 3), round(a.zeta, 4), round(a.tuning.f, 4)
    (1.0, 0.0559, 0.9331)
    """
    if not isinstance(model, MDOF):
        raise ParameterError(f"model = {model!r} is not an MDOF: allowed MDOF(M, C, K)")
    n = model.n
    if isinstance(dof, bool) or not isinstance(dof, int | np.integer) or not -n <= dof < n:
        raise ParameterError(f"dof = {dof!r} is out of range: allowed an integer -{n} <= dof < {n}")
    rules = {"H∞": hinf_tuning, "Den Hartog": den_hartog, "H2": h2_tuning}
    if rule not in rules:
        raise ParameterError(f"rule = {rule!r} is not known: allowed 'H∞', 'Den Hartog', 'H2'")
    phi = model.modes[:, 0]
    if phi[dof] == 0.0:
        raise ParameterError(f"dof = {dof}: the first mode does not move there, allowed a moving degree of freedom")
    phi = phi / phi[dof]
    m1 = float(phi @ model.M @ phi)
    w1 = float(model.natural_frequencies[0])
    z1 = float(model.modal_damping_ratios[0])
    tuning = rules[rule](mu, zeta_p=min(z1, ZETA_P_OPT_MAX))
    m_a, k_a, c_a = tuning.absorber(m1, w1 * w1 * m1)
    return ModeAbsorber(tuning, m1, w1, z1, m_a, k_a, c_a)
