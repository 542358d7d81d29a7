"""Absorber tunings: Den Hartog's rule, the H∞ and H2 optima (closed form and numerical), and mistuning."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np
from scipy.optimize import fsolve, minimize

from ..checks import check_array
from ..model import ParameterError, check_int, check_real
from ._limits import F_MAX, MISTUNED_MAX, ZETA_MAX, ZETA_P_OPT_MAX, _f, _mu, _no_nan, _zeta
from .magnification import _outer_peaks, _peak, h2_norm


@dataclass(frozen=True, kw_only=True)
class TMDTuning:
    """One absorber tuning and the peak it gives (dimensionless groups, see the module docstring)."""

    rule: str  # which rule gave it ("Den Hartog", "H∞ closed form", "H∞ numerical", "H2 closed form", ...)
    mu: float  # mass ratio m_a / m_p, 1
    f: float  # tuning ratio ω_a / ω_p, 1
    zeta_a: float  # absorber damping ratio c_a / (2 m_a ω_a), 1 (absorber's own frequency)
    zeta_p: float  # primary damping ratio for which peak was evaluated, 1
    peak: float  # max_r |X_p| / (F0 / k_p) on that primary, 1
    r_peak: float  # forcing ratio ω/ω_p of the peak (one of two at an H∞ optimum), 1
    converged: bool = True  # the numerical optimiser met its tolerances within its iteration limit (closed forms: True)

    def __post_init__(self) -> None:
        if not isinstance(self.rule, str) or not self.rule:
            raise ParameterError(f"rule = {self.rule!r:.80} is not a name: allowed a non-empty string")
        object.__setattr__(self, "mu", _mu(self.mu))
        object.__setattr__(self, "f", _f(self.f))
        object.__setattr__(self, "zeta_a", _zeta("zeta_a", self.zeta_a))
        object.__setattr__(self, "zeta_p", _zeta("zeta_p", self.zeta_p))
        peak = self.peak
        if isinstance(peak, bool) or not isinstance(peak, numbers.Real) or not float(peak) >= 0.0:
            raise ParameterError(
                f"peak = {peak!r:.80} is not a peak magnification: allowed a real number peak >= 0 (inf at an "
                "undamped absorber)"
            )
        object.__setattr__(self, "peak", float(peak))
        object.__setattr__(self, "r_peak", check_real("r_peak", self.r_peak, low=0.0, unit="(ω/ω_p)"))
        if not isinstance(self.converged, bool | np.bool_):
            raise ParameterError(f"converged = {self.converged!r:.80} is not a boolean: allowed True or False")
        object.__setattr__(self, "converged", bool(self.converged))

    def _finite_fields(self) -> list[float]:
        """The numbers a nan check covers (see ``_no_nan``)."""
        return [self.f, self.zeta_a, self.peak]

    @property
    def zeta_a_primary(self) -> float:
        """The same damping in the other convention, c_a / (2 m_a ω_p) = f ζ_a, 1."""
        return self.f * self.zeta_a

    @property
    def h2(self) -> float:
        """∫_0^∞ |H(r)|² dr on the primary of :attr:`zeta_p`, 1 (see :func:`h2_norm`)."""
        return h2_norm(self.mu, self.f, self.zeta_a, zeta_p=self.zeta_p)

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


def _record(rule, mu, f, za, zp, converged: bool = True) -> TMDTuning:
    peak, r_peak = _peak(mu, f, za, zp)
    return TMDTuning(rule=rule, mu=mu, f=f, zeta_a=za, zeta_p=zp, peak=peak, r_peak=r_peak, converged=bool(converged))


#: Largest Nelder-Mead iteration limit a caller may ask for.
MAXITER_MAX = 100_000


def _maxiter(maxiter, default: int) -> int:
    return default if maxiter is None else check_int("maxiter", maxiter, low=1, high=MAXITER_MAX)


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


#: Residual of the equal-peak conditions (log peaks, gradient determinant) that counts as solved.
EQUAL_PEAK_RESIDUAL = 1e-8


def _hinf_numerical(mu: float, zp: float, f0: float, z0: float, maxiter: int = 400) -> tuple[float, float, bool]:
    """Min over (f, ζ_a) of the peak: Nelder-Mead, then the equal-peak optimality conditions.

    At a two-peak optimum the low and high peaks are equal and their gradients
    in (f, ln ζ_a) are opposite: G_low = G_high and det[∇G_low, ∇G_high] = 0.
    Those two smooth equations are solved by ``scipy.optimize.fsolve`` from the
    Nelder-Mead point (central differences, step 1e-6); the solution is kept
    only when the gradients are indeed opposite and the peak is not higher. Converged: Nelder-Mead met
    its tolerances within ``maxiter`` iterations, or the equal-peak conditions were solved.
    """

    def cost(x):
        f, lz = x
        if not (0.0 < f <= F_MAX and lz < math.log(ZETA_MAX)):
            return math.inf
        return math.log(_peak(mu, f, math.exp(lz), zp)[0])

    nm = minimize(
        cost, [f0, math.log(z0)], method="Nelder-Mead", options={"xatol": 1e-9, "fatol": 1e-13, "maxiter": maxiter}
    )
    best, converged = nm.x, bool(nm.success)
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
    # fsolve's own flag asks for a step below xtol, which the differenced gradients (noise ~ eps / h) may deny
    # on one machine and grant on another: a residual at that noise level counts as solved too
    solved = ier == 1 or bool(np.all(np.abs(equations(sol)) < EQUAL_PEAK_RESIDUAL))
    if solved and 0.0 < sol[0] <= F_MAX:
        g = grads(sol)
        opposite = float(np.dot(g[0], g[1])) < 0.0
        if opposite and cost(sol) <= cost(best) + 1e-12:
            best, converged = sol, True
    return float(best[0]), math.exp(float(best[1])), converged


def _closed_form(method, zp: float) -> bool:
    """Check an optimiser's ``method`` against ``zp``; True when the closed form applies."""
    if method not in ("auto", "closed form", "numerical"):
        raise ParameterError(f"method = {method!r} is not known: allowed 'auto', 'closed form', 'numerical'")
    if method == "closed form" and zp != 0.0:
        raise ParameterError(f"zeta_p = {zp!r}: the closed form needs an undamped primary, allowed zeta_p = 0")
    return method == "closed form" or (method == "auto" and zp == 0.0)


@_no_nan
def hinf_tuning(mu, zeta_p=0.0, method="auto", *, maxiter=None) -> TMDTuning:
    """The H∞ optimum: (f, ζ_a) minimising the primary's largest magnification.

    For an undamped primary the closed form of Nishihara and Asami (2002,
    J. Vib. Acoust. 124:576–582) is used (ζ_a relative to the absorber's own
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
    maxiter : int, optional
        Nelder-Mead's iteration limit (1 to 100 000; default 400, scipy's for two variables).

    Returns
    -------
    TMDTuning
        With ``.peak`` the minimised largest magnification; ``.converged`` is False when
        Nelder-Mead stopped at ``maxiter`` and the equal-peak conditions were not solved.

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
        return TMDTuning(
            rule="H∞ closed form", mu=mu, f=f, zeta_a=za, zeta_p=0.0, peak=peak, r_peak=_peak(mu, f, za, 0.0)[1]
        )
    maxiter = _maxiter(maxiter, 400)
    f0, z0 = 1.0 / (1.0 + mu), math.sqrt(3.0 * mu / (8.0 * (1.0 + mu)))
    f, za, converged = _hinf_numerical(mu, zp, f0, z0, maxiter)
    return _record("H∞ numerical", mu, f, za, zp, converged)


@_no_nan
def h2_tuning(mu, zeta_p=0.0, method="auto", *, maxiter=None) -> TMDTuning:
    """The H2 optimum: (f, ζ_a) minimising ∫_0^∞ |H(r)|² dr (white-noise force).

    For an undamped primary Warburton's closed form (1982, Earthquake Eng.
    Struct. Dyn. 10:381–401, force excitation, primary displacement; ζ_a relative
    to the absorber's own frequency): f = sqrt(1 + μ/2)/(1 + μ),
    ζ_a = sqrt(μ (1 + 3μ/4) / (4 (1 + μ)(1 + μ/2))). For a damped primary, or with
    ``method="numerical"``, Nelder-Mead on the exact Lyapunov value
    (:func:`h2_norm`) from Warburton's point.

    Parameters
    ----------
    mu, zeta_p, method
        As in :func:`hinf_tuning`: mass ratio (1), primary damping ratio (1) and the method.
    maxiter : int, optional
        Nelder-Mead's iteration limit (1 to 100 000; default 2000).

    Returns
    -------
    TMDTuning
        ``.peak`` is the largest magnification this tuning gives (not the criterion); ``.converged``
        is False when Nelder-Mead stopped at ``maxiter`` before its tolerances.

    Examples
    --------
    >>> t = h2_tuning(0.02)
    >>> round(t.f, 6), round(t.zeta_a, 6), round(t.h2, 4)
    (0.985282, 0.070187, 22.1599)
    """
    mu = _mu(mu)
    zp = _zeta("zeta_p", zeta_p, ZETA_P_OPT_MAX)
    closed = _closed_form(method, zp)
    maxiter = _maxiter(maxiter, 2000)
    f = math.sqrt(1.0 + mu / 2.0) / (1.0 + mu)
    za = math.sqrt(mu * (1.0 + 0.75 * mu) / (4.0 * (1.0 + mu) * (1.0 + mu / 2.0)))
    if closed:
        return _record("H2 closed form", mu, f, za, 0.0)

    def cost(x):
        ff, lz = x
        if not (0.0 < ff <= F_MAX and lz < math.log(ZETA_MAX)):
            return math.inf
        return math.log(h2_norm(mu, ff, math.exp(lz), zeta_p=zp))

    res = minimize(
        cost, [f, math.log(za)], method="Nelder-Mead", options={"xatol": 1e-9, "fatol": 1e-14, "maxiter": maxiter}
    )
    return _record("H2 numerical", mu, float(res.x[0]), math.exp(float(res.x[1])), zp, res.success)


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
    eps = check_array("stiffness_error", stiffness_error, low=-0.9, high=9.0, ndim=(0, 1), max_size=MISTUNED_MAX)
    flat = eps.ravel()
    out = np.empty(flat.shape)
    for i, e in enumerate(flat):
        g = math.sqrt(1.0 + e)
        out[i] = _peak(tuning.mu, _f(tuning.f / g), tuning.zeta_a, zp / g)[0] / (1.0 + e)
    return out.reshape(eps.shape)
