"""Tuned mass dampers and multi-degree-of-freedom structures (Part II).

A package by concept: :mod:`.magnification` (the two-mass absorber's frequency response, exact peak,
H2 integral, fixed points), :mod:`.tuning` (Den Hartog, H∞ and H2 tunings, mistuning), :mod:`.mdof`
(the MDOF record, modes, frequency and time responses), :mod:`.structures` (modal damping, the
shear building, absorbers on a structure, ground acceleration) and :mod:`.robust` (the worst peak over
an error band of the primary's stiffness, the min-max design, every design scored on every criterion).
Two parts share it.

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
  magnification factors)", J. Vib. Acoust. 124:576–582: the exact H∞ optimum
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
  10:381–401, H2 optimum (mean-square primary displacement under white-noise
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

import math  # noqa: F401  (the module docstring's examples use it)

from ._limits import (  # noqa: F401  (limits and validators stay reachable at the old paths)
    ENTRIES_MAX,
    F_MAX,
    MISTUNED_MAX,
    MU_MAX,
    MU_MIN,
    N_DOF_MAX,
    SYM_TOL,
    WORK_MAX,
    ZETA_MAX,
    ZETA_P_OPT_MAX,
    _f,
    _mu,
    _no_nan,
    _ratios,
    _zeta,
)
from .magnification import (  # noqa: F401
    _factors,
    _h2,
    _outer_peaks,
    _peak,
    _stationary,
    h2_norm,
    stroke_peak,
    tmd_fixed_points,
    tmd_magnification,
    tmd_peak,
    tmd_stroke,
)
from .mdof import MDOF, DampingNotClassical, MDOFResponse, _finite_response, _matrix, _positive_definite  # noqa: F401
from .robust import BAND_MAX, DesignScore, bare_peak, robust_tuning, score_design, worst_peak  # noqa: F401
from .structures import (  # noqa: F401
    ModeAbsorber,
    add_absorber,
    first_mode_absorber,
    frf_peak,
    ground_acceleration_load,
    modal_damping_matrix,
    shear_building,
    tmd_system,
)
from .tuning import (  # noqa: F401
    TMDTuning,
    _closed_form,
    _hinf_closed,
    _hinf_numerical,
    _record,
    den_hartog,
    h2_tuning,
    hinf_tuning,
    mistuned_peak,
)

__all__ = [
    "MDOF",
    "DampingNotClassical",
    "DesignScore",
    "MDOFResponse",
    "TMDTuning",
    "add_absorber",
    "bare_peak",
    "den_hartog",
    "first_mode_absorber",
    "frf_peak",
    "ground_acceleration_load",
    "h2_norm",
    "h2_tuning",
    "hinf_tuning",
    "mistuned_peak",
    "modal_damping_matrix",
    "robust_tuning",
    "score_design",
    "shear_building",
    "stroke_peak",
    "tmd_fixed_points",
    "tmd_magnification",
    "tmd_peak",
    "tmd_stroke",
    "tmd_system",
    "worst_peak",
]
