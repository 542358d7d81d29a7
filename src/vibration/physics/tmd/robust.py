"""Robustness to an error in the primary's stiffness, and every design scored on every criterion.

The absorber (m_a, k_a, c_a) is built for the nominal primary; the primary's stiffness is
k_p (1 + ε) with ε anywhere in a band ±b. Its frequency grows by g = sqrt(1 + ε), so the true
tuning ratio is f / g and the primary's damping ratio ζ_p / g; peaks are divided by the
nominal static deflection F0 / k_p (as :func:`mistuned_peak`).

* :func:`worst_peak`: max over ε in [−b, b] of the peak (41-point grid of ε, every interior
  local maximum of the grid refined by bounded Brent).
* :func:`robust_tuning`: the min-max design, (f, ζ_a) minimising that worst peak, by an exchange
  method: Nelder-Mead (restarted until it stops improving) on the largest peak over a finite set
  of ε (−b, 0, b to start), then the worst ε of the dense search joins the set, until the dense
  worst exceeds the set's by less than 1e-9 (relative).
* :func:`score_design`: one design judged on each criterion of the chapter: nominal peak (H∞),
  worst peak over the band (robust), the share of its benefit kept at ±b, the H2 integral
  (mean-square primary displacement under white-noise force) and the absorber's stroke.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize, minimize_scalar

from ..checks import check_array
from ..model import ParameterError, check_real
from ._limits import F_MAX, ZETA_MAX, ZETA_P_OPT_MAX, _mu, _no_nan, _zeta
from .magnification import _peak, h2_norm, stroke_peak, tmd_stroke
from .tuning import TMDTuning, _maxiter, hinf_tuning

#: Largest stiffness band ±b of the robustness functions, 1.
BAND_MAX = 0.5
#: Points of the ε grid of the inner maximum (then refined).
N_BAND = 41
#: Largest number of exchange rounds of :func:`robust_tuning` (each adds one ε to the finite set).
EXCHANGE_MAX = 8
#: Largest number of Nelder-Mead restarts per exchange round.
RESTARTS_MAX = 6


def _band(band) -> float:
    return check_real("band", band, low=0.0, high=BAND_MAX)


def _mistuned(mu: float, f: float, za: float, zp: float, e: float) -> float:
    """Peak with the primary's stiffness off by e, over the nominal static deflection (validated inputs)."""
    g = math.sqrt(1.0 + e)
    return _peak(mu, f / g, za, zp / g)[0] / (1.0 + e)


def _worst(mu: float, f: float, za: float, zp: float, band: float) -> tuple[float, float]:
    """(max over |ε| <= band of the mistuned peak, the ε where it is reached)."""
    if band == 0.0:
        return _mistuned(mu, f, za, zp, 0.0), 0.0
    eps = np.linspace(-band, band, N_BAND)
    v = np.array([_mistuned(mu, f, za, zp, e) for e in eps])
    i = int(np.argmax(v))
    best, e_best = float(v[i]), float(eps[i])
    interior = [j for j in range(1, N_BAND - 1) if v[j] >= v[j - 1] and v[j] >= v[j + 1]]
    for j in interior:
        res = minimize_scalar(
            lambda e: -_mistuned(mu, f, za, zp, e),
            bounds=(eps[j - 1], eps[j + 1]),
            method="bounded",
            options={"xatol": 1e-12 * band},
        )
        if -res.fun > best:
            best, e_best = float(-res.fun), float(res.x)
    return best, e_best


def bare_peak(zeta_p, stiffness_error=0.0) -> np.ndarray:
    """Peak magnification of the primary without absorber, over the nominal static deflection, 1.

    With ζ = ζ_p / sqrt(1 + ε): 1 / (2 ζ sqrt(1 − ζ²)) / (1 + ε) when ζ < 1/√2, else 1 / (1 + ε).

    Parameters
    ----------
    zeta_p : float
        Nominal primary damping ratio, 1 (0 to 10).
    stiffness_error : float or array_like
        ε, relative error of the primary's stiffness, 1 (−0.9 to 9).

    Returns
    -------
    numpy.ndarray
        Shape of ``stiffness_error``; ``inf`` for an undamped primary.

    Examples
    --------
    >>> round(float(bare_peak(0.5 / (2 * 20**0.5))), 4)           # the paper's oscillator
    8.9583
    """
    zp = _zeta("zeta_p", zeta_p)
    eps = check_array("stiffness_error", stiffness_error, low=-0.9, high=9.0, ndim=(0, 1))
    z = zp / np.sqrt(1.0 + eps)
    with np.errstate(divide="ignore"):
        h = np.where(z < 2**-0.5, 1.0 / (2.0 * z * np.sqrt(np.maximum(1.0 - z * z, 0.0))), 1.0)
    return h / (1.0 + eps)


@_no_nan
def worst_peak(tuning: TMDTuning, band, zeta_p=None) -> tuple[float, float]:
    """Worst peak magnification when the primary's stiffness is off by any ε in [−band, band].

    Parameters
    ----------
    tuning : TMDTuning
        The absorber, built for the nominal primary.
    band : float
        b, largest relative error of the primary's stiffness, 1 (0 to 0.5).
    zeta_p : float, optional
        Nominal primary damping ratio, 1; by default ``tuning.zeta_p``.

    Returns
    -------
    (float, float)
        max over ε of max_ω |X_p| / (F0 / k_p nominal), 1, and the ε where it is reached, 1.

    Examples
    --------
    >>> w, e = worst_peak(hinf_tuning(0.05, 0.0559), 0.1)
    >>> round(w, 3), e
    (5.091, -0.1)
    """
    if not isinstance(tuning, TMDTuning):
        raise ParameterError(f"tuning = {tuning!r} is not a TMDTuning: allowed den_hartog(...), hinf_tuning(...)")
    zp = tuning.zeta_p if zeta_p is None else _zeta("zeta_p", zeta_p)
    return _worst(tuning.mu, tuning.f, tuning.zeta_a, zp, _band(band))


@_no_nan
def robust_tuning(mu, zeta_p=0.0, band=0.1, *, maxiter=None) -> TMDTuning:
    """The min-max design: (f, ζ_a) minimising the worst peak over a ±band error of the primary's stiffness.

    Exchange method from the H∞ optimum of the nominal primary (see the module docstring); the
    design equals that optimum when band is 0.

    Parameters
    ----------
    mu : float
        Mass ratio m_a / m_p, 1 (0 < mu <= 10).
    zeta_p : float
        Nominal primary damping ratio, 1 (0 to 0.5).
    band : float
        b, largest relative error of the primary's stiffness, 1 (0 to 0.5).
    maxiter : int, optional
        Nelder-Mead's iteration limit per run (1 to 100 000; default 2000).

    Returns
    -------
    TMDTuning
        ``.peak`` is the nominal peak (not the criterion: see :func:`worst_peak`); ``.converged`` is
        False when a Nelder-Mead run stopped at ``maxiter`` or the exchange did not close in 8 rounds.

    Examples
    --------
    >>> t = robust_tuning(0.05, 0.0559, 0.1)
    >>> round(t.f, 4), round(t.zeta_a, 4), round(worst_peak(t, 0.1)[0], 3), t.converged
    (0.9011, 0.1615, 4.614, True)
    """
    mu = _mu(mu)
    zp = _zeta("zeta_p", zeta_p, ZETA_P_OPT_MAX)
    band = _band(band)
    maxiter = _maxiter(maxiter, 2000)
    start = hinf_tuning(mu, zp)
    rule = f"robust min-max, ±{100 * band:g} %"
    if band == 0.0:
        return TMDTuning(
            rule=rule,
            mu=mu,
            f=start.f,
            zeta_a=start.zeta_a,
            zeta_p=zp,
            peak=start.peak,
            r_peak=start.r_peak,
            converged=start.converged,
        )
    f_top = F_MAX * math.sqrt(1.0 - band)

    def cost(x, eps):
        f, lz = x
        if not (0.0 < f <= f_top and lz < math.log(ZETA_MAX)):
            return math.inf
        za = math.exp(lz)
        return math.log(max(_mistuned(mu, f, za, zp, e) for e in eps))

    eps = [-band, 0.0, band]
    x = np.array([start.f, math.log(start.zeta_a)])
    converged = False
    for _ in range(EXCHANGE_MAX):
        value, ok = cost(x, eps), True
        for _ in range(RESTARTS_MAX):  # a restart resets the simplex, which can stall on the kink of a max
            res = minimize(
                cost, x, args=(eps,), method="Nelder-Mead", options={"xatol": 1e-10, "fatol": 1e-14, "maxiter": maxiter}
            )
            ok = bool(res.success)
            improved = res.fun < value - 1e-13
            if res.fun <= value:
                x, value = res.x, float(res.fun)
            if not (improved and ok):
                break
        w, e_w = _worst(mu, float(x[0]), math.exp(float(x[1])), zp, band)
        if math.log(w) <= value + 1e-9:
            converged = ok
            break
        eps.append(e_w)
    f, za = float(x[0]), math.exp(float(x[1]))
    peak, r_peak = _peak(mu, f, za, zp)
    return TMDTuning(rule=rule, mu=mu, f=f, zeta_a=za, zeta_p=zp, peak=peak, r_peak=r_peak, converged=converged)


@dataclass(frozen=True, kw_only=True)
class DesignScore:
    """One absorber design judged on every criterion, on the actual primary (ratios to F0 / k_p, nominal)."""

    tuning: TMDTuning  # the design (f, ζ_a; its own rule)
    zeta_p: float  # nominal primary damping ratio on which it is judged, 1
    band: float  # ± relative error of the primary's stiffness, 1
    r_force: float  # forcing ratio ω/ω_p of the load case, 1
    nominal_peak: float  # max_r |X_p| / (F0/k_p), nominal primary (the H∞ criterion), 1
    worst_peak: float  # max over |ε| <= band of the peak (the robust criterion), 1
    eps_worst: float  # ε of the worst peak, 1
    peak_low: float  # peak at ε = −band, 1
    peak_high: float  # peak at ε = +band, 1
    kept_low: float  # share of the benefit kept at ε = −band, 1 (nan for an undamped primary)
    kept_high: float  # share of the benefit kept at ε = +band, 1 (nan for an undamped primary)
    h2: float  # ∫_0^∞ |H(r)|² dr, nominal primary (the H2 criterion), 1
    rms_ratio: float  # rms primary displacement under white-noise force over the bare primary's, 1 (nan if undamped)
    stroke_peak: float  # max_r |X_a − X_p| / (F0/k_p), 1
    stroke_force: float  # |X_a − X_p| / (F0/k_p) at r_force, 1


def score_design(tuning: TMDTuning, zeta_p, band, *, r_force) -> DesignScore:
    """Score one design on the nominal peak, the worst peak over ±band, the benefit kept, H2 and stroke.

    The benefit at ε is the bare primary's peak minus the design's (both over the nominal F0/k_p);
    the share kept at ±band is that benefit over the nominal one. The bare primary's H2 integral is
    π / (4 ζ_p), so the rms ratio is sqrt(4 ζ_p h2 / π).

    Parameters
    ----------
    tuning : TMDTuning
    zeta_p : float
        Nominal primary damping ratio, 1 (0 to 0.5).
    band : float
        ± relative error of the primary's stiffness, 1 (0 to 0.5).
    r_force : float
        Forcing ratio ω/ω_p of the load case, 1 (>= 0).

    Returns
    -------
    DesignScore

    Examples
    --------
    >>> s = score_design(hinf_tuning(0.05, 0.0559), 0.0559, 0.1, r_force=0.9995)
    >>> round(s.kept_low, 3), round(s.kept_high, 3), round(s.stroke_force, 2)
    (0.874, 0.856, 12.79)
    """
    if not isinstance(tuning, TMDTuning):
        raise ParameterError(f"tuning = {tuning!r} is not a TMDTuning: allowed den_hartog(...), hinf_tuning(...)")
    zp = _zeta("zeta_p", zeta_p, ZETA_P_OPT_MAX)
    band = _band(band)
    r_force = check_real("r_force", r_force, low=0.0, unit="(ω/ω_p)")
    mu, f, za = tuning.mu, tuning.f, tuning.zeta_a
    nominal = _mistuned(mu, f, za, zp, 0.0)
    worst, e_w = _worst(mu, f, za, zp, band)
    lo, hi = _mistuned(mu, f, za, zp, -band), _mistuned(mu, f, za, zp, band)
    bare = bare_peak(zp, np.array([-band, 0.0, band]))
    with np.errstate(invalid="ignore", divide="ignore"):
        kept = (bare - np.array([lo, nominal, hi])) / (bare[1] - nominal)
    if not np.isfinite(bare[1]):
        kept = np.full(3, math.nan)
    h2 = h2_norm(mu, f, za, zeta_p=zp)
    rms = math.sqrt(4.0 * zp * h2 / math.pi) if zp > 0.0 else math.nan
    return DesignScore(
        tuning=tuning,
        zeta_p=zp,
        band=band,
        r_force=r_force,
        nominal_peak=nominal,
        worst_peak=worst,
        eps_worst=e_w,
        peak_low=lo,
        peak_high=hi,
        kept_low=float(kept[0]),
        kept_high=float(kept[2]),
        h2=h2,
        rms_ratio=rms,
        stroke_peak=stroke_peak(mu, f, za, zeta_p=zp)[0],
        stroke_force=float(tmd_stroke(mu, f, za, r=r_force, zeta_p=zp)),
    )
