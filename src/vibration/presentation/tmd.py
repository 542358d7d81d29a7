"""Chapter 8: the tuned mass damper and n-storey structures (tables, figures, sentences, sliders).

:func:`tmd_chapter` computes every result of the chapter once from the notebook's
parameters (through :mod:`vibration.physics.tmd`); each table, figure and sentence
below is one call on that record, so a papermill run with other parameters never
contradicts its own tables.
"""

from __future__ import annotations

import base64
import hashlib
import html
import io
import itertools
import json
import math
from dataclasses import dataclass, field

import numpy as np

from ..physics.exact import exact_response, steady_state
from ..physics.model import Oscillator, SineForce, check_int, check_real
from ..physics.tmd import (
    MDOF,
    MU_MAX,
    ModeAbsorber,
    TMDTuning,
    add_absorber,
    bare_peak,
    den_hartog,
    first_mode_absorber,
    frf_peak,
    ground_acceleration_load,
    h2_tuning,
    hinf_tuning,
    mistuned_peak,
    robust_tuning,
    score_design,
    shear_building,
    tmd_fixed_points,
    tmd_magnification,
    tmd_peak,
    tmd_stroke,
    tmd_system,
    worst_peak,
)
from .static_page import _asset
from .style import figure, place_legend
from .tables import Column, Missing, Table, bound

__all__ = [
    "TMDChapter",
    "TMDExplorer",
    "building_frf_figure",
    "building_ground_figure",
    "building_load_table",
    "building_sentence",
    "building_source",
    "building_table",
    "checks_table",
    "design_sentence",
    "design_table",
    "fixed_points_figure",
    "magnification_figure",
    "modes_figure",
    "response_sentence",
    "response_table",
    "robustness_figure",
    "robustness_sentence",
    "robustness_table",
    "sliders_text",
    "stroke_sentence",
    "summary_sentence",
    "summary_table",
    "time_response_figure",
    "tmd_chapter",
    "tmd_explorer",
    "tmd_panel_html",
    "tuning_sentence",
    "tuning_table",
]

#: Mass ratios of the tunings table (the notebook's mu is added when it is not among them), 1.
TABLE_MUS = (0.01, 0.02, 0.05, 0.1)
#: Rules in the order of the tables and figures; the last is optimised for the actual primary damping.
RULES = ("Den Hartog", "H∞ exact, ζ_p = 0", "H2 (Warburton)", "H∞ numerical, actual ζ_p")
COLORS = {RULES[0]: "#ff7f0e", RULES[1]: "#2ca02c", RULES[2]: "#9467bd", RULES[3]: "#d62728"}
#: Legend labels of the rules in mathtext.
LABELS = {
    RULES[0]: "Den Hartog",
    RULES[1]: r"H$\infty$ exact, $\zeta_p = 0$",
    RULES[2]: "H2 (Warburton)",
    RULES[3]: r"H$\infty$ numerical, actual $\zeta_p$",
}


#: Designs of the comparison on the actual primary: the classical rule and the optimum of each criterion.
DESIGNS = ("Den Hartog", "H∞ optimum", "H2 optimum", "robust min-max")
DESIGN_COLORS = {DESIGNS[0]: COLORS[RULES[0]], DESIGNS[1]: COLORS[RULES[3]], DESIGNS[2]: "#8c564b",
                 DESIGNS[3]: "#17becf"}  # fmt: skip
#: The designs and the closed-form rules as a sentence names them.
PROSE = {DESIGNS[0]: "Den Hartog's rule", DESIGNS[1]: "H∞ optimum", DESIGNS[2]: "H2 optimum",
         DESIGNS[3]: "robust min-max design", RULES[1]: "closed-form H∞ tuning of an undamped primary",
         RULES[2]: "Warburton's H2 tuning"}  # fmt: skip


@dataclass(frozen=True)
class LoadCase:
    """The building's largest roof response near the first mode under one load, without and with the absorber."""

    name: str  # the load, in words
    unit: str  # unit of the printed amplitudes
    scale: float  # printed unit per SI unit (m/N -> mm/kN: 1e6; s² -> mm/(m/s²): 1e3)
    peak_without: float  # largest roof amplitude without the absorber, SI (m/N or s²)
    omega_without: float  # its frequency, rad/s
    peak_with: float  # largest roof amplitude with the absorber, SI
    omega_with: float  # its frequency, rad/s
    omega_max: float  # upper end of the band searched, rad/s

    @property
    def reduction(self) -> float:
        """1 − with / without, 1."""
        return 1.0 - self.peak_with / self.peak_without


def _tunings(mu: float, zeta_p: float) -> dict[str, TMDTuning]:
    return {
        RULES[0]: den_hartog(mu),
        RULES[1]: hinf_tuning(mu),
        RULES[2]: h2_tuning(mu),
        RULES[3]: hinf_tuning(mu, zeta_p),
    }


@dataclass(frozen=True)
class TMDChapter:
    """Every result of the chapter (SI units; ratios dimensionless)."""

    m: float  # primary mass, kg
    k: float  # primary stiffness, N/m
    c: float  # primary damping, N s/m
    F0: float  # force amplitude, N
    omega_res: float  # forcing frequency of the time response, rad/s
    t_end: float  # window, s
    mu: float  # mass ratio of the figures and the time response, 1
    mistuning: float  # ± relative stiffness error of the robustness study, 1
    zeta_p: float  # primary damping ratio, 1
    tunings: dict = field(repr=False)  # mu -> rule -> TMDTuning (.peak on the primary it was optimised for)
    peaks_actual: dict = field(repr=False)  # mu -> rule -> peak on the actual primary, 1
    t: np.ndarray = field(repr=False)  # time grid, s
    x_without: np.ndarray = field(repr=False)  # primary displacement without the TMD, m
    x_with: np.ndarray = field(repr=False)  # primary displacement with the chosen TMD, m
    x_absorber: np.ndarray = field(repr=False)  # absorber displacement, m
    amp_without: float = 0.0  # steady amplitude without, m
    amp_with: float = 0.0  # steady amplitude with, m
    amp_absorber: float = 0.0  # steady absorber amplitude, m
    eps: np.ndarray = field(default=None, repr=False)  # stiffness errors, 1
    robust: dict = field(default=None, repr=False)  # rule (RULES, then the min-max design) -> peaks over eps, 1
    robust_none: np.ndarray = field(default=None, repr=False)  # peak without TMD over eps, 1
    building: MDOF = field(default=None, repr=False)
    building_tmd: MDOF = field(default=None, repr=False)
    absorber: ModeAbsorber = field(default=None, repr=False)
    mu_building: float = 0.0  # absorber mass over the first modal mass, 1
    checks: dict = field(default=None, repr=False)  # name -> (value, bound)
    designs: dict = field(default=None, repr=False)  # design (DESIGNS) -> DesignScore on the actual primary
    robust_worst: dict = field(default=None, repr=False)  # rule -> worst peak over the band (refined), 1
    load_cases: tuple = field(default=(), repr=False)  # LoadCase: roof force, ground acceleration
    r_force: float = 0.0  # forcing ratio ω/ω_p of the load case, 1

    @property
    def chosen(self) -> TMDTuning:
        """The absorber of the time response: H∞ optimum for the actual primary damping at mu."""
        return self.tunings[self.mu][RULES[3]]


def tmd_chapter(
    m: float,
    k: float,
    c: float,
    F0: float,
    omega_res: float,
    t_end: float,
    mu: float,
    mistuning: float,
    n_storeys: int,
    storey_mass: float,
    storey_stiffness: float,
    zeta_building: float,
    mu_building: float,
    n_points: int = 5001,
) -> TMDChapter:
    """Compute the chapter's results (tunings, responses, robustness, building).

    Parameters
    ----------
    m, k, c : float
        Primary mass (kg), stiffness (N/m) and damping (N s/m; ζ_p = c/(2 sqrt(k m)) <= 0.5).
    F0 : float
        Force amplitude, N.
    omega_res : float
        Forcing frequency of the time response, rad/s.
    t_end : float
        Window of the time response, s.
    mu : float
        Mass ratio of the figures and the time response, 1 (0 < mu <= 1).
    mistuning : float
        Largest relative error of the primary's stiffness in the robustness study, 1 (0 to 0.5).
    n_storeys : int
        Storeys of the shear building (1 to 30).
    storey_mass, storey_stiffness : float
        Floor mass (kg) and storey stiffness (N/m) of the uniform building. The chapter's
        defaults are after the uniform five-storey shear frame of Chopra, Dynamics of
        Structures (100 kips/g floors, 31.54 kips/in storeys, T1 = 2 s); 45 359.237 kg and
        5.5235e6 N/m are SI conversions of those values.
    zeta_building : float
        Modal damping ratio of the building, 1.
    mu_building : float
        Roof absorber mass over the first modal mass, 1.
    n_points : int
        Samples of the time window.

    Examples
    --------
    >>> ch = tmd_chapter(1.0, 20.0, 0.5, 5.0, 4.47, 50.0, 0.05, 0.1, 3, 1e4, 1e7, 0.05, 0.02, n_points=201)
    >>> ch.amp_with < ch.amp_without
    True
    """
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    c = check_real("c", c, low=0.0, unit="N s/m")
    F0 = check_real("F0", F0, low=0.0, unit="N")
    omega_res = check_real("omega_res", omega_res, low=0.0, low_open=True, unit="rad/s")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    mu = check_real("mu", mu, low=0.0, low_open=True, high=1.0)
    mistuning = check_real("mistuning", mistuning, low=0.0, high=0.5)
    n_storeys = check_int("n_storeys", n_storeys, low=1, high=30)
    n_points = check_int("n_points", n_points, low=2, high=200_001)
    osc = Oscillator(m, c, k)
    zeta_p = osc.damping_ratio
    check_real("zeta_p (from c, k, m)", zeta_p, high=0.5)
    mus = sorted(set(TABLE_MUS) | {mu})
    tunings, peaks_actual = {}, {}
    for x in mus:
        tunings[x] = _tunings(x, zeta_p)
        peaks_actual[x] = {
            r: (t.peak if r == RULES[3] else float(mistuned_peak(t, 0.0, zeta_p))) for r, t in tunings[x].items()
        }
    chosen = tunings[mu][RULES[3]]
    t = np.linspace(0.0, t_end, n_points)
    force = SineForce(F0, omega_res)
    x_without = exact_response(osc, force, t).x
    model = tmd_system(m, c, k, chosen)
    resp = model.response(t, [F0, 0.0], omega_res)
    X = model.frf([omega_res], [F0, 0.0])[0]
    eps = np.linspace(-mistuning, mistuning, 41)
    robust = {r: mistuned_peak(tunings[mu][r], eps, zeta_p) for r in RULES}
    robust_none = bare_peak(zeta_p, eps)
    r_force = omega_res / math.sqrt(k / m)
    robust_design = robust_tuning(mu, zeta_p, mistuning)
    design_tunings = dict(
        zip(DESIGNS, (tunings[mu][RULES[0]], chosen, h2_tuning(mu, zeta_p), robust_design), strict=True)
    )
    designs = {d: score_design(t, zeta_p, mistuning, r_force) for d, t in design_tunings.items()}
    robust[DESIGNS[3]] = mistuned_peak(robust_design, eps, zeta_p)
    rob_tunings = {**{r: tunings[mu][r] for r in RULES}, DESIGNS[3]: robust_design}
    robust_worst = {r: worst_peak(t, mistuning, zeta_p)[0] for r, t in rob_tunings.items()}
    building = shear_building([storey_mass] * n_storeys, [storey_stiffness] * n_storeys, zeta_building)
    absorber = first_mode_absorber(building, mu_building)
    building_tmd = add_absorber(building, -1, absorber.m_a, absorber.k_a, absorber.c_a)
    load_cases = _load_cases(building, building_tmd)
    # self-checks, printed as bounds
    closed, numerical = hinf_tuning(mu), hinf_tuning(mu, method="numerical")
    optimisations = [numerical, *(t for x in mus for t in tunings[x].values()), *design_tunings.values()]
    Xs = model.frf([omega_res], [1.0, 0.0])[0]  # per newton, m
    one = MDOF([[m]], [[c]], [[k]]).response(t, [F0], omega_res).x[:, 0]
    expm_x = model.response(t[:: max(1, n_points // 50)], [F0, 0.0], omega_res, method="expm").x[:, 0]
    checks = {
        "H∞ closed form vs numerical min-max at ζ_p = 0, tuning ratio f (relative)": (
            abs(numerical.f / closed.f - 1),
            1e-6,
        ),
        "H∞ closed form vs numerical min-max at ζ_p = 0, ζ_a (relative)": (
            abs(numerical.zeta_a / closed.zeta_a - 1),
            1e-4,
        ),
        "H∞ closed form vs numerical min-max at ζ_p = 0, peak (relative)": (
            abs(numerical.peak / closed.peak - 1),
            1e-9,
        ),
        "one-mass MDOF response vs the closed form of Part I, max |Δx| (m)": (
            float(np.max(np.abs(one - x_without))),
            1e-9,
        ),
        "TMD response: modal superposition vs augmented matrix exponential, max |Δx| (m)": (
            float(np.max(np.abs(resp.x[:: max(1, n_points // 50), 0] - expm_x))),
            1e-9,
        ),
        "stroke |X_a − X_p|: closed form vs the two-mass complex solve (relative)": (
            abs(float(tmd_stroke(mu, chosen.f, chosen.zeta_a, r_force, zeta_p)) / (k * abs(Xs[1] - Xs[0])) - 1.0),
            1e-9,
        ),
        "roof under ground acceleration: complex solve vs modal superposition (relative)": (
            _ground_modal_check(building, load_cases[1].omega_without),
            1e-9,
        ),
        "robust design: lowest worst peak of the 8 neighbours at ±0.1 % in f and ζ_a, shortfall (relative)": (
            _robust_neighbours(robust_design, zeta_p, mistuning),
            1e-9,
        ),
        "numerical optimisations stopped at their iteration limit (count)": (
            float(sum(not t.converged for t in optimisations)),
            1.0,
        ),
    }
    return TMDChapter(
        m=m,
        k=k,
        c=c,
        F0=F0,
        omega_res=omega_res,
        t_end=t_end,
        mu=mu,
        mistuning=mistuning,
        zeta_p=zeta_p,
        tunings=tunings,
        peaks_actual=peaks_actual,
        t=t,
        x_without=x_without,
        x_with=resp.x[:, 0],
        x_absorber=resp.x[:, 1],
        amp_without=steady_state(osc, force).amplitude,
        amp_with=float(abs(X[0])),
        amp_absorber=float(abs(X[1])),
        eps=eps,
        robust=robust,
        robust_none=robust_none,
        building=building,
        building_tmd=building_tmd,
        absorber=absorber,
        mu_building=mu_building,
        checks=checks,
        designs=designs,
        robust_worst=robust_worst,
        load_cases=load_cases,
        r_force=r_force,
    )


def _band_top(b: MDOF) -> float:
    """Upper end of the band "near the first mode", rad/s: 2.5 ω1, or halfway to ω2 when that is lower."""
    w = b.natural_frequencies
    return float(2.5 * w[0] if b.n == 1 else min(2.5 * w[0], 0.5 * (w[0] + w[1])))


def _load_cases(b: MDOF, bt: MDOF) -> tuple[LoadCase, LoadCase]:
    """Largest roof amplitude near the first mode under a roof force and under ground acceleration."""
    top = _band_top(b)
    roof = np.zeros(b.n)
    roof[-1] = 1.0
    out = []
    for name, unit, scale, p0, p1 in (
        ("roof force", "mm/kN", 1e6, roof, np.r_[roof, 0.0]),
        ("ground acceleration", "mm/(m/s²)", 1e3, ground_acceleration_load(b), ground_acceleration_load(bt)),
    ):
        h0, w0 = frf_peak(b, p0, b.n - 1, 0.0, top)
        h1, w1 = frf_peak(bt, p1, b.n - 1, 0.0, top)  # the roof is still degree of freedom n - 1
        out.append(LoadCase(name, unit, scale, h0, w0, h1, w1, top))
    return out[0], out[1]


def _ground_modal_check(b: MDOF, omega: float) -> float:
    """Roof amplitude per ground acceleration: complex solve against classical modal superposition, relative."""
    w, phi, z = b.natural_frequencies, b.modes, b.modal_damping_ratios
    gamma = -(phi.T @ b.M @ np.ones(b.n))  # modal participation of −M ι (mass-normalised modes)
    modal = np.sum(phi[-1] * gamma / (w * w - omega * omega + 2j * z * w * omega))
    direct = b.frf([omega], ground_acceleration_load(b))[0, -1]
    return float(abs(direct / modal - 1.0))


def _robust_neighbours(t: TMDTuning, zeta_p: float, band: float) -> float:
    """How far below the robust design's worst peak the best of its 8 neighbours goes (0 at a local min-max)."""
    if band == 0.0:
        return 0.0
    w0 = worst_peak(t, band, zeta_p)[0]
    best = math.inf
    for a, b in itertools.product((-1, 0, 1), repeat=2):
        if a or b:
            n = TMDTuning(t.rule, t.mu, t.f * (1 + 1e-3 * a), t.zeta_a * (1 + 1e-3 * b), zeta_p, t.peak, t.r_peak)
            best = min(best, worst_peak(n, band, zeta_p)[0])
    return max(0.0, 1.0 - best / w0)


# ----------------------------------------------------------------------------- tables


def tuning_table(ch: TMDChapter) -> Table:
    """f, ζ_a (both conventions) and the peaks of every rule at every mass ratio."""
    rows = []
    for mu, rules in ch.tunings.items():
        best = min(ch.peaks_actual[mu].values())
        for rule, t in rules.items():
            rows.append(
                {
                    "mu": mu,
                    "rule": rule,
                    "f": t.f,
                    "za": t.zeta_a,
                    "zap": t.zeta_a_primary,
                    "peak0": _peak0(t),
                    "peak": ch.peaks_actual[mu][rule],
                    "excess": 100.0 * (ch.peaks_actual[mu][rule] / best - 1.0),
                }
            )
    return Table(
        rows,
        [
            Column("mu", "μ", 3),
            Column("rule", "rule"),
            Column("f", "f = ω_a / ω_p", 5),
            Column("za", "ζ_a on ω_a", 4),
            Column("zap", "ζ'_a = f ζ_a on ω_p", 4),
            Column("peak0", "peak, ζ_p = 0", 5),
            Column("peak", f"peak, ζ_p = {ch.zeta_p:.4g}", 5),
            Column("excess", "excess over best (%)", 2),
        ],
        caption=(
            "Absorber tunings and the largest magnification |X_p|/(F0/k_p) they give, on an undamped primary and on "
            "the actual primary; the last column compares the rules on the actual primary."
        ),
        name="tab-tmd-tunings",
        notes=("ζ_a = c_a/(2 m_a ω_a) throughout; Den Hartog's book states ζ'_a = c_a/(2 m_a ω_p) = f ζ_a.",),
    )


def summary_table(ch: TMDChapter) -> Table:
    """The closing note's table: each rule's tuning and its peak on the actual primary, every mass ratio."""
    rows = [
        {"mu": mu, "rule": rule, "f": t.f, "za": t.zeta_a, "peak": ch.peaks_actual[mu][rule]}
        for mu, rules in ch.tunings.items()
        for rule, t in rules.items()
    ]
    return Table(
        rows,
        [
            Column("mu", "μ", 3),
            Column("rule", "rule"),
            Column("f", "f = ω_a / ω_p", 4),
            Column("za", "ζ_a on ω_a", 3),
            Column("peak", f"peak, ζ_p = {ch.zeta_p:.4g}", 4),
        ],
        caption="Tunings of the chapter and the peak magnification each gives on the paper's primary.",
        name="tab-tmd-summary",
    )


def _peak0(t: TMDTuning) -> float:
    return float(mistuned_peak(t, 0.0, 0.0))


def response_table(ch: TMDChapter) -> Table:
    """Steady amplitude and window peak at the paper's resonance, with and without the absorber."""
    t = ch.chosen
    rows = [
        {
            "case": "primary without TMD",
            "amp": ch.amp_without,
            "peak": float(np.max(np.abs(ch.x_without))),
            "red": 0.0,
        },
        {
            "case": f"primary with H∞ TMD (μ = {ch.mu:g}, f = {t.f:.4f}, ζ_a = {t.zeta_a:.4f})",
            "amp": ch.amp_with,
            "peak": float(np.max(np.abs(ch.x_with))),
            "red": 100.0 * (1.0 - ch.amp_with / ch.amp_without),
        },
        {
            "case": "absorber (relative to ground)",
            "amp": ch.amp_absorber,
            "peak": float(np.max(np.abs(ch.x_absorber))),
            "red": _MISSING_RED,
        },
    ]
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("amp", "steady amplitude (m)", 4),
            Column("peak", f"max |x|, 0 ≤ t ≤ {ch.t_end:g} s (m)", 4),
            Column("red", "steady reduction (%)", 3),
        ],
        caption=f"Response from rest to F0 sin(ωt) at ω = {ch.omega_res:g} rad/s, F0 = {ch.F0:g} N.",
        name="tab-tmd-response",
    )


_MISSING_RED = Missing("a reduction of the absorber's own motion is not meaningful")


def robustness_table(ch: TMDChapter) -> Table:
    """Peak magnification at the ends and the middle of the mistuning range, per rule."""
    rows = []
    i0 = len(ch.eps) // 2
    for rule in ch.robust:
        p = ch.robust[rule]
        rows.append({"rule": rule, "lo": p[0], "mid": p[i0], "hi": p[-1], "worst": ch.robust_worst[rule]})
    p = ch.robust_none
    rows.append({"rule": "no TMD", "lo": p[0], "mid": p[i0], "hi": p[-1], "worst": float(np.max(p))})
    e = 100 * ch.mistuning
    return Table(
        rows,
        [
            Column("rule", "rule"),
            Column("lo", f"peak, k_p −{e:g} %", 4),
            Column("mid", "peak, nominal", 4),
            Column("hi", f"peak, k_p +{e:g} %", 4),
            Column("worst", "worst in range", 4),
        ],
        caption=(
            f"Largest magnification |X_p|/(F0/k_p, nominal) when the primary's stiffness is off by up to ±{e:g} % "
            f"(μ = {ch.mu:g}, absorber unchanged)."
        ),
        name="tab-tmd-robustness",
    )


def building_table(ch: TMDChapter) -> Table:
    """Periods, frequencies and damping of the building's modes, without and with the roof absorber."""
    b = ch.building
    w = b.natural_frequencies
    lam = ch.building_tmd.poles
    lam = lam[lam.imag > 0]
    rows = []
    for i, wi in enumerate(w):
        rows.append(
            {
                "mode": i + 1,
                "T": 2 * math.pi / wi,
                "fhz": wi / (2 * math.pi),
                "zeta": float(b.modal_damping_ratios[i]),
                "roof": float(b.modes[-1, i] / b.modes[:, i][np.argmax(np.abs(b.modes[:, i]))]),
            }
        )
    return Table(
        rows,
        [
            Column("mode", "mode"),
            Column("T", "T (s)", 4),
            Column("fhz", "f (Hz)", 4),
            Column("zeta", "ζ", 3),
            Column("roof", "roof / largest component", 3),
        ],
        caption=f"Modes of the {b.n}-storey shear building (classical modal damping).",
        name="tab-tmd-building",
        notes=(building_source(ch),),
    )


#: Chopra's uniform frame in SI: 100 kips/g floors (kg) and 31.54 kips/in storeys (N/m), converted.
CHOPRA_FLOOR_MASS = 100 * 4448.2216152605 / 9.80665
CHOPRA_STOREY_STIFFNESS = 31.54 * 4448.2216152605 / 0.0254


def _is_chopra(ch: TMDChapter) -> bool:
    b = ch.building
    k = float(b.K[-1, -1])
    m = float(b.M[-1, -1])
    uniform = np.allclose(np.diag(b.M), m, rtol=1e-12)
    return (
        b.n == 5
        and uniform
        and math.isclose(m, CHOPRA_FLOOR_MASS, rel_tol=1e-4)
        and math.isclose(k, CHOPRA_STOREY_STIFFNESS, rel_tol=1e-4)
    )


def building_source(ch: TMDChapter) -> str:
    """Where the building's values come from, and whether this run uses them."""
    T1 = 2 * math.pi / float(ch.building.natural_frequencies[0])
    if _is_chopra(ch):
        return (
            "After the uniform five-storey shear frame of Chopra, Dynamics of Structures (100 kips/g floors, "
            "31.54 kips/in storeys, T1 = 2 s); the SI values 45 359.237 kg and 5.5235e6 N/m are conversions, "
            f"and the first period computed from them is {T1:.4f} s. The higher periods are computed here."
        )
    return (
        "Illustrative values: the run's storey count, floor mass or storey stiffness differ from the uniform "
        "five-storey shear frame of Chopra, Dynamics of Structures (100 kips/g floors, 31.54 kips/in storeys, "
        f"T1 = 2 s), which the chapter follows by default; here T1 = {T1:.4g} s."
    )


def checks_table(ch: TMDChapter) -> Table:
    """Self-checks at rounding level, printed as bounds."""

    rows = [{"check": name, "bound": bound(value, tol), "ok": value < tol} for name, (value, tol) in ch.checks.items()]
    return Table(
        rows,
        [Column("check", "check"), Column("bound", "bound"), Column("ok", "within")],
        caption="Independent checks of the chapter's numbers.",
        name="tab-tmd-checks",
    )


# ----------------------------------------------------------------------------- sentences


def _pct(a: float, b: float) -> str:
    return f"{100.0 * (1.0 - a / b):.1f} %"


def _change(before: float, after: float, unit: str) -> str:
    """ "falls from 2 to 1 m (50 % lower)", or "rises ..." when it grows, from the numbers themselves."""
    verb = "falls" if after <= before else "rises"
    return f"{verb} from {before:.4g} to {after:.4g} {unit} ({_rel(after, before)})"


def tuning_sentence(ch: TMDChapter) -> str:
    """The rules compared at the notebook's mass ratio."""
    r = ch.tunings[ch.mu]
    dh, hinf, h2, num = (r[x] for x in RULES)
    pa = ch.peaks_actual[ch.mu]
    return (
        f"At μ = {ch.mu:g} on an undamped primary, the exact H∞ optimum (f = {hinf.f:.4f}, ζ_a = {hinf.zeta_a:.4f}) "
        f"holds the peak at {hinf.peak:.4f}, against {dh.peak:.4f} for Den Hartog's rule "
        f"({100 * (dh.peak / hinf.peak - 1):.3f} % higher) and {h2.peak:.4f} for Warburton's H2 tuning "
        f"({100 * (h2.peak / hinf.peak - 1):.2f} % higher). "
        f"On the paper's primary (ζ_p = {ch.zeta_p:.4f}) the numerical H∞ optimum moves to f = {num.f:.4f}, "
        f"ζ_a = {num.zeta_a:.4f} and a peak of {num.peak:.4f}; Den Hartog's tuning gives {pa[RULES[0]]:.4f} there "
        f"and the undamped-primary H∞ tuning {pa[RULES[1]]:.4f}."
    )


def response_sentence(ch: TMDChapter) -> str:
    """The measured reduction at the paper's resonance."""
    pk0, pk1 = float(np.max(np.abs(ch.x_without))), float(np.max(np.abs(ch.x_with)))
    return (
        f"At ω = {ch.omega_res:g} rad/s the steady amplitude of the primary "
        f"{_change(ch.amp_without, ch.amp_with, 'm')} with an absorber of {ch.mu:g} times its mass, which itself "
        f"swings {ch.amp_absorber:.4g} m; the largest |x| in the {ch.t_end:g} s window {_change(pk0, pk1, 'm')}."
    )


def _rel(a: float, b: float) -> str:
    """|a/b − 1| in per cent, 3 significant figures, with "higher"/"lower"."""
    d = 100.0 * (a / b - 1.0)
    return f"{abs(d):.3g} % {'higher' if d > 0 else 'lower'}"


_NO_BENEFIT = Missing("the bare primary is undamped: its peak, and so the benefit, is infinite")


def design_table(ch: TMDChapter) -> Table:
    """Each design on each criterion: nominal peak, worst peak over the band, benefit kept, rms, stroke."""
    e = 100 * ch.mistuning
    xs = ch.F0 / ch.k
    rows = []
    for name, d in ch.designs.items():
        kept = [100.0 * v if math.isfinite(v) else _NO_BENEFIT for v in (d.kept_low, d.kept_high)]
        rows.append(
            {
                "design": name,
                "f": d.tuning.f,
                "za": d.tuning.zeta_a,
                "nominal": d.nominal_peak,
                "worst": d.worst_peak,
                "lo": kept[0],
                "hi": kept[1],
                "rms": d.rms_ratio if math.isfinite(d.rms_ratio) else _NO_BENEFIT,
                "zmax": d.stroke_peak,
                "zf": xs * d.stroke_force,
            }
        )
    return Table(
        rows,
        [
            Column("design", "design"),
            Column("f", "f = ω_a / ω_p", 4),
            Column("za", "ζ_a on ω_a", 4),
            Column("nominal", "peak, nominal", 4),
            Column("worst", f"worst peak, k_p ±{e:g} %", 4),
            Column("lo", f"benefit kept, k_p −{e:g} % (%)", 3),
            Column("hi", f"benefit kept, k_p +{e:g} % (%)", 3),
            Column("rms", "rms / rms without absorber", 4),
            Column("zmax", "largest stroke / (F0/k_p)", 4),
            Column("zf", f"stroke at ω = {ch.omega_res:g} rad/s (m)", 4),
        ],
        caption=(
            f"Each design judged on each criterion, on the actual primary (ζ_p = {ch.zeta_p:.4g}, μ = {ch.mu:g}): "
            "Den Hartog's rule, and the optimum of each criterion — the H∞ optimum (nominal peak), the H2 optimum "
            f"(rms displacement under white-noise force) and the min-max design (worst peak over a ±{e:g} % error "
            "of the primary's stiffness, absorber unchanged)."
        ),
        name="tab-tmd-designs",
        notes=(
            "Peaks are |X_p|/(F0/k_p) with the nominal k_p. Benefit: the bare primary's peak minus the design's on "
            "the same primary; kept: that benefit at the band's end over the nominal one.",
            "rms ratio: sqrt(∫|H|² dr / (π/(4 ζ_p))), the H2 integral over the bare primary's. Stroke: the absorber's "
            f"displacement relative to the primary, |X_a − X_p|; in metres for F0 = {ch.F0:g} N, k_p = {ch.k:g} N/m.",
        ),
    )


def _optimum_words(ch: TMDChapter, key: str, owner: str, what: str) -> str:
    """Which design wins one criterion, and whether it is the design that optimises it."""
    vals = {n: getattr(d, key) for n, d in ch.designs.items() if math.isfinite(getattr(d, key))}
    if not vals:
        return ""
    best = min(vals, key=vals.get)
    if best == owner or math.isclose(vals[best], vals[owner], rel_tol=1e-9):
        return f"the {PROSE[owner]} has the lowest {what} ({vals[owner]:.4g})"
    return (
        f"the lowest {what} is that of {_the(best)} ({vals[best]:.4g}), not the {PROSE[owner]}'s "
        f"({vals[owner]:.4g}): its optimisation did not reach the optimum"
    )


def _the(name: str) -> str:
    """A design or rule's name with its article ("Den Hartog's rule", "the H∞ optimum")."""
    words = PROSE.get(name, name)
    return words if words.startswith(("Den Hartog", "Warburton")) else f"the {words}"


def design_sentence(ch: TMDChapter) -> str:
    """Each criterion's optimum on its own criterion, and what it costs on the others."""
    d = ch.designs
    h, h2, rb = d[DESIGNS[1]], d[DESIGNS[2]], d[DESIGNS[3]]
    wins = [
        _optimum_words(ch, "nominal_peak", DESIGNS[1], "nominal peak"),
        _optimum_words(ch, "worst_peak", DESIGNS[3], f"worst peak over ±{100 * ch.mistuning:g} %"),
        _optimum_words(ch, "rms_ratio", DESIGNS[2], "rms displacement under white noise"),
    ]
    text = "Each design wins on its own criterion: " + "; ".join(w for w in wins if w) + ". "
    if math.isfinite(h.rms_ratio) and math.isfinite(h2.rms_ratio):
        text += (
            f"Judged on the others, the H∞ optimum's rms is {_rel(h.rms_ratio, h2.rms_ratio)} than the H2 "
            f"optimum's, and the H2 optimum's nominal peak {_rel(h2.nominal_peak, h.nominal_peak)} than the H∞ "
            "optimum's"
        )
    else:
        text += "The bare primary is undamped, so the rms ratio is not defined"
    if ch.mistuning > 0.0:
        text += (
            f"; the robust min-max design accepts a nominal peak {_rel(rb.nominal_peak, h.nominal_peak)} than the "
            f"H∞ optimum's for a worst peak {_rel(rb.worst_peak, h.worst_peak)}."
        )
    else:
        text += "; with no stiffness error to guard against, the min-max design is the H∞ optimum."
    return text


def stroke_sentence(ch: TMDChapter) -> str:
    """The absorber's stroke, the binding design limit, at the load case and at its largest."""
    xs = ch.F0 / ch.k
    h = ch.designs[DESIGNS[1]]
    zmin = min(ch.designs, key=lambda n: ch.designs[n].stroke_peak)
    return (
        f"The binding design limit is the absorber's stroke, its travel relative to the primary: at "
        f"ω = {ch.omega_res:g} rad/s (r = ω/ω_p = {ch.r_force:.4f}) the H∞ absorber strokes "
        f"{xs * h.stroke_force:.4g} m for F0 = {ch.F0:g} N, {h.stroke_force * xs / ch.amp_with:.3g} times the "
        f"primary's own {ch.amp_with:.4g} m amplitude, and its largest stroke over frequency is "
        f"{xs * h.stroke_peak:.4g} m. Of the four designs {_the(zmin)} has the lowest peak stroke "
        f"({xs * ch.designs[zmin].stroke_peak:.4g} m); none of them limits the stroke, so a real absorber's "
        "travel would need a stroke-constrained design, which this chapter does not compute."
    )


def robustness_sentence(ch: TMDChapter) -> str:
    """How much of its benefit the H∞ optimum keeps off-nominal, against the min-max optimum of that criterion."""
    d = ch.designs
    h, rb = d[DESIGNS[1]], d[DESIGNS[3]]
    e = 100 * ch.mistuning
    if ch.mistuning == 0.0:
        return (
            "With a stiffness error band of ±0 % there is nothing to be robust against: the min-max design is the "
            f"H∞ optimum, whose worst peak is its nominal peak, {h.nominal_peak:.4g}."
        )
    if math.isfinite(h.kept_low):
        text = (
            f"When the primary's stiffness is {e:g} % low, the H∞ optimum still keeps {100 * h.kept_low:.3g} % of "
            f"its benefit (the bare primary's peak minus its own, against the nominal benefit), and "
            f"{100 * h.kept_high:.3g} % when it is {e:g} % high: "
            + (
                "it degrades, it does not collapse. "
                if min(h.kept_low, h.kept_high) >= 0.5
                else "it loses most of it. "
            )
        )
    else:
        text = "The bare primary is undamped (its peak is infinite), so the share of the benefit kept is not defined. "
    best = min(d, key=lambda n: d[n].worst_peak)
    text += (
        f"Over the whole ±{e:g} % band its worst peak is {h.worst_peak:.4g} (at k_p "
        f"{f'{100 * h.eps_worst:+.3g}'.replace('-', '−')} %), "
        f"against {_bare_words(float(np.max(ch.robust_none)))} without an absorber. The optimum of that criterion, the "
        f"robust min-max design (f = {rb.tuning.f:.4f}, ζ_a = {rb.tuning.zeta_a:.4f}), holds the worst peak to "
        f"{rb.worst_peak:.4g} ({_rel(rb.worst_peak, h.worst_peak)}) at the price of a nominal peak of "
        f"{rb.nominal_peak:.4g} instead of {h.nominal_peak:.4g} ({_rel(rb.nominal_peak, h.nominal_peak)})."
    )
    if best != DESIGNS[3] and d[best].worst_peak < rb.worst_peak * (1 - 1e-9):
        text += f" The min-max search fell short: {_the(best)} has a lower worst peak ({d[best].worst_peak:.4g})."
    return text


def _bare_words(peak: float) -> str:
    return f"{peak:.4g}" if math.isfinite(peak) else "an unbounded peak"


def building_load_table(ch: TMDChapter) -> Table:
    """Largest roof response near the first mode under a roof force and under ground acceleration."""
    top = ch.load_cases[0].omega_max / (2 * math.pi)
    rows = [
        {
            "load": c.name,
            "unit": c.unit,
            "h0": c.scale * c.peak_without,
            "f0": c.omega_without / (2 * math.pi),
            "h1": c.scale * c.peak_with,
            "f1": c.omega_with / (2 * math.pi),
            "red": 100.0 * c.reduction,
        }
        for c in ch.load_cases
    ]
    return Table(
        rows,
        [
            Column("load", "load"),
            Column("unit", "unit"),
            Column("h0", "largest roof amplitude, without absorber", 4),
            Column("f0", "at f (Hz)", 4),
            Column("h1", "with roof absorber", 4),
            Column("f1", "at f (Hz) ", 4),
            Column("red", "reduction (%)", 3),
        ],
        caption=(
            f"Largest steady roof amplitude between 0 and {top:.4g} Hz (near the first mode) per unit load: a "
            "harmonic roof force, and a harmonic ground acceleration (roof displacement relative to the ground)."
        ),
        name="tab-tmd-building-loads",
    )


def building_sentence(ch: TMDChapter) -> str:
    """The roof absorber and the reduction of the roof's resonant response under both loads."""
    a = ch.absorber
    force, ground = ch.load_cases
    b = ch.building
    gamma = b.modes.T @ b.M @ np.ones(b.n)
    share = float(gamma[0] ** 2 / np.sum(np.diag(b.M)))
    return (
        f"A roof absorber of {a.m_a:.4g} kg ({ch.mu_building:g} of the first modal mass {a.modal_mass:.4g} kg) "
        f"tuned by the numerical H∞ rule for the mode's {a.zeta:.3g} damping (f = {a.tuning.f:.4f}, "
        f"ζ_a = {a.tuning.zeta_a:.4f}; k_a = {a.k_a:.4g} N/m, c_a = {a.c_a:.4g} N s/m): the largest roof "
        f"receptance near the first mode "
        f"{_change(force.scale * force.peak_without, force.scale * force.peak_with, force.unit)}. Under ground "
        f"acceleration the roof's largest displacement relative to the ground "
        f"{_change(ground.scale * ground.peak_without, ground.scale * ground.peak_with, ground.unit)}; "
        f"the first mode carries {100 * share:.3g} % of the building's mass "
        "as effective modal mass under ground motion. The building's damping is classical; with the absorber it is "
        "not, and the complex poles take over from modal damping ratios."
    )


def summary_sentence(ch: TMDChapter) -> str:
    """The closing note: the chosen design against the best alternative of its class and each criterion's optimum."""
    d = ch.designs
    h, h2, rb = d[DESIGNS[1]], d[DESIGNS[2]], d[DESIGNS[3]]
    closed = {r: ch.peaks_actual[ch.mu][r] for r in RULES[:3]}
    alt = min(closed, key=closed.get)
    text = (
        f"For the paper's oscillator (ζ_p = {ch.zeta_p:.4f}) an absorber of μ = {ch.mu:g} tuned by the H∞ "
        f"optimum for the actual damping (f = {h.tuning.f:.4f}, ζ_a = {h.tuning.zeta_a:.4f}) caps the "
        f"magnification at {h.nominal_peak:.4g}, "
        + (
            f"the peak of the best closed-form rule on this primary ({_the(alt)}), which is exact here"
            if math.isclose(h.nominal_peak, closed[alt], rel_tol=1e-6)
            else f"{_rel(h.nominal_peak, closed[alt])} than the best closed-form rule on this primary "
            f"({_the(alt)}, {closed[alt]:.4g})"
        )
    )
    if math.isfinite(h.rms_ratio):
        text += f"; under white noise its rms displacement is {_rel(h.rms_ratio, h2.rms_ratio)} than the H2 optimum's"
    if ch.mistuning > 0.0:
        text += (
            f"; over a ±{100 * ch.mistuning:g} % stiffness error its worst peak, {h.worst_peak:.4g}, is "
            f"{_rel(h.worst_peak, rb.worst_peak)} than the min-max optimum's {rb.worst_peak:.4g}"
        )
    return text + (
        f". At ω = {ch.omega_res:g} rad/s the steady amplitude {_change(ch.amp_without, ch.amp_with, 'm')}, "
        "with an absorber stroke of "
        f"{ch.F0 / ch.k * h.stroke_force:.4g} m."
    )


def _omegas(ch: TMDChapter) -> np.ndarray:
    wp = math.sqrt(ch.k / ch.m)
    return wp * np.linspace(0.5, 1.5, 20001)


# ----------------------------------------------------------------------------- figures


def fixed_points_figure(ch: TMDChapter):
    """Undamped primary, Den Hartog's tuning: every absorber damping passes through the two fixed points."""
    mu = ch.mu
    t = ch.tunings[mu][RULES[0]]
    r = np.linspace(0.6, 1.4, 4001)
    fig, ax = figure(height=3.4)
    (rp, hp) = tmd_fixed_points(mu, t.f)
    top = 2.2 * float(hp.max())
    for za, label, style in (
        (0.0, "ζ_a = 0", dict(color="0.55", lw=1.0, ls="--")),
        (t.zeta_a / 3, f"ζ_a = {t.zeta_a / 3:.3f}", dict(color="#1f77b4")),
        (t.zeta_a, f"ζ_a = {t.zeta_a:.3f} (Den Hartog)", dict(color="#ff7f0e", lw=2.0)),
        (3 * t.zeta_a, f"ζ_a = {3 * t.zeta_a:.3f}", dict(color="#9467bd")),
    ):
        h = tmd_magnification(mu, t.f, za, r)
        ax.plot(r, np.where(h > top, np.nan, h), label=label.replace("ζ_a", r"$\zeta_a$"), **style)
    locked = np.abs(1.0 / (1.0 - (1.0 + mu) * r * r))
    ax.plot(r, np.where(locked > top, np.nan, locked), color="0.3", lw=1.0, ls=":", label=r"$\zeta_a \to \infty$")
    ax.plot(rp, hp, "o", color="k", ms=6, label="fixed points P, Q", zorder=5)
    ax.set_ylim(0, top)
    ax.set_xlim(r[0], r[-1])
    ax.set_xlabel(r"frequency ratio $r = \omega/\omega_p$ (1)")
    ax.set_ylabel(r"$|X_p|\,/\,(F_0/k_p)$ (1)")
    ax.set_title(rf"Undamped primary, $\mu$ = {mu:g}, $f = 1/(1+\mu)$ = {t.f:.4f}")
    place_legend(ax, outside=True)
    return fig


def magnification_figure(ch: TMDChapter):
    """The paper's primary with and without the absorber, for each rule."""
    r = np.linspace(0.6, 1.4, 4001)
    fig, ax = figure(height=3.6)
    none = 1.0 / np.sqrt((1 - r * r) ** 2 + (2 * ch.zeta_p * r) ** 2)
    ax.plot(r, none, color="0.4", lw=1.2, label="no TMD")
    for rule, t in ch.tunings[ch.mu].items():
        dashed = {"ls": (0, (4, 2)), "zorder": 3} if rule == RULES[0] else {}  # Den Hartog nearly hides under H∞
        h = tmd_magnification(ch.mu, t.f, t.zeta_a, r, ch.zeta_p)
        ax.plot(r, h, color=COLORS[rule], label=LABELS[rule], **dashed)
    r_res = ch.omega_res / math.sqrt(ch.k / ch.m)
    ax.axvline(r_res, color="0.5", lw=0.8, ls=":", label=rf"paper's $\omega$ = {ch.omega_res:g} rad/s")
    ax.set_ylim(0, 1.05 * float(none.max()))
    ax.set_xlim(r[0], r[-1])
    ax.set_xlabel(r"frequency ratio $r = \omega/\omega_p$ (1)")
    ax.set_ylabel(r"$|X_p|\,/\,(F_0/k_p)$ (1)")
    ax.set_title(rf"Paper's primary, $\zeta_p$ = {ch.zeta_p:.4f}, $\mu$ = {ch.mu:g}")
    place_legend(ax, outside=True)
    return fig


def time_response_figure(ch: TMDChapter):
    """Primary displacement from rest at the paper's resonance, with and without the absorber."""
    fig, ax = figure(height=3.4)
    ax.plot(ch.t, ch.x_without, color="0.45", lw=0.9, label="without TMD")
    ax.plot(ch.t, ch.x_with, color="#d62728", lw=0.9, label=rf"with H$\infty$ TMD, $\mu$ = {ch.mu:g}")
    for a, col in ((ch.amp_without, "0.45"), (ch.amp_with, "#d62728")):
        ax.axhline(a, color=col, lw=0.8, ls="--")
        ax.axhline(-a, color=col, lw=0.8, ls="--")
    ax.set_xlim(0, ch.t_end)
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"primary displacement $x_p$ (m)")
    place_legend(ax, outside=True)
    return fig


def robustness_figure(ch: TMDChapter):
    """Peak magnification against the error of the primary's stiffness, per rule."""
    fig, ax = figure(height=3.4)
    e = 100 * ch.eps
    for rule in ch.robust:
        color, label = COLORS.get(rule, DESIGN_COLORS[DESIGNS[3]]), LABELS.get(rule, "robust min-max")
        ax.plot(e, ch.robust[rule], color=color, label=label, ls="--" if rule not in COLORS else "-")
    ax.set_xlabel(r"error of the primary's stiffness $\Delta k_p/k_p$ (%)")
    ax.set_ylabel(r"peak $|X_p|\,/\,(F_0/k_p)$ (1)")
    ax.set_xlim(e[0], e[-1])
    place_legend(ax, outside=True)
    return fig


def modes_figure(ch: TMDChapter):
    """Mode shapes of the building (normalised to a largest component of 1) against the floor."""
    b = ch.building
    n = b.n
    floors = np.arange(0, n + 1)
    fig, ax = figure(height=3.6)
    for i in range(min(n, 5)):
        phi = b.modes[:, i] / np.max(np.abs(b.modes[:, i]))
        phi = phi * np.sign(phi[-1]) if phi[-1] != 0 else phi
        T = 2 * math.pi / b.natural_frequencies[i]
        ax.plot(np.r_[0.0, phi], floors, marker="o", ms=4, label=f"mode {i + 1}, T = {T:.3g} s")
    ax.axvline(0.0, color="0.5", lw=0.8)
    ax.set_yticks(floors)
    ax.set_ylabel("floor (0 = ground)")
    ax.set_xlabel("mode shape, scaled to a largest component of 1")
    place_legend(ax, outside=True)
    return fig


def building_frf_figure(ch: TMDChapter):
    """Roof receptance (roof displacement per roof force) with and without the roof absorber."""
    b, bt = ch.building, ch.building_tmd
    w1 = b.natural_frequencies[0]
    w = np.linspace(0.3 * w1, min(1.8 * w1, 0.5 * (w1 + b.natural_frequencies[1]) if b.n > 1 else 1.8 * w1), 3001)
    load = np.zeros(b.n)
    load[-1] = 1.0
    h0 = np.abs(b.frf(w, load)[:, -1]) * 1e6  # m/N -> mm/kN
    h1 = np.abs(bt.frf(w, np.r_[load, 0.0])[:, -2]) * 1e6
    fig, ax = figure(height=3.4)
    hz = w / (2 * math.pi)
    ax.plot(hz, h0, color="0.4", label="without TMD")
    ax.plot(hz, h1, color="#d62728", label=rf"with roof TMD, $\mu$ = {ch.mu_building:g} of modal mass")
    ax.set_xlabel(r"forcing frequency $f$ (Hz)")
    ax.set_ylabel("roof displacement / roof force (mm/kN)")
    ax.set_xlim(hz[0], hz[-1])
    place_legend(ax, outside=True)
    return fig


def building_ground_figure(ch: TMDChapter):
    """Roof displacement relative to the ground per ground acceleration, with and without the roof absorber."""
    b, bt = ch.building, ch.building_tmd
    w1 = b.natural_frequencies[0]
    w = np.linspace(0.3 * w1, min(1.8 * w1, _band_top(b)), 3001)
    h0 = np.abs(b.frf(w, ground_acceleration_load(b))[:, -1]) * 1e3  # s² -> mm/(m/s²)
    h1 = np.abs(bt.frf(w, ground_acceleration_load(bt))[:, -2]) * 1e3
    fig, ax = figure(height=3.4)
    hz = w / (2 * math.pi)
    ax.plot(hz, h0, color="0.4", label="without TMD")
    ax.plot(hz, h1, color="#d62728", label=rf"with roof TMD, $\mu$ = {ch.mu_building:g} of modal mass")
    ax.set_xlabel(r"frequency of the ground acceleration $f$ (Hz)")
    ax.set_ylabel(r"roof displacement / ground acceleration (mm per m/s$^2$)")
    ax.set_xlim(hz[0], hz[-1])
    place_legend(ax, outside=True)
    return fig


# ----------------------------------------------------------------------------- sliders

#: Ranges of the sliders (μ and ζ_a on logarithmic scales), 1.
MU_RANGE = (0.005, 0.25)
F_RANGE = (0.7, 1.3)
ZETA_A_RANGE = (0.005, 1.0)
ZETA_P_RANGE = (0.0, 0.3)
#: Frequency-ratio window of the slider plots, 1.
R_RANGE = (0.4, 1.6)
_SLIDER_RULES = (("dh", "Den Hartog"), ("hinf", "H∞ (Nishihara–Asami)"), ("h2", "H2 (Warburton)"))
_counter = itertools.count(1)


def _slider_values(mu, f, zeta_a, zeta_p) -> tuple[float, float, float, float]:
    """Validated slider values; f and ζ_a default to the H∞ closed form at mu."""
    mu = check_real("mu", mu, low=MU_RANGE[0], high=MU_RANGE[1])
    opt = hinf_tuning(mu)
    f = check_real("f", opt.f if f is None else f, low=F_RANGE[0], high=F_RANGE[1], unit="(ω_a/ω_p)")
    zeta_a = check_real("zeta_a", opt.zeta_a if zeta_a is None else zeta_a, low=ZETA_A_RANGE[0], high=ZETA_A_RANGE[1])
    zeta_p = check_real("zeta_p", zeta_p, low=ZETA_P_RANGE[0], high=ZETA_P_RANGE[1])
    return mu, f, zeta_a, zeta_p


def tmd_panel_html(mu=0.05, f=None, zeta_a=None, zeta_p=0.0, *, panel_id: str | None = None) -> str:
    """Self-contained HTML + JavaScript panel: μ, f, ζ_a and ζ_p sliders over the magnification curve.

    Draws |X_p|/(F0/k_p) against r = ω/ω_p for the slider values, the H∞ tuning of the
    same μ (dashed), the primary without absorber and Den Hartog's fixed points P and Q
    (exact for an undamped primary); reads out the peak, the fixed points and the
    tunings of Den Hartog, H∞ (Nishihara and Asami's closed form) and H2 (Warburton) for
    the current μ with the peaks they give; three buttons set f and ζ_a to a rule.
    Computed in the browser by ``assets/tmd.js`` (``window.vibrationTMD``), which the
    tests compare with :func:`~vibration.tmd_magnification`, :func:`~vibration.tmd_peak`,
    :func:`~vibration.tmd_fixed_points` and the three tuning functions.

    Parameters
    ----------
    mu : float
        Mass ratio m_a/m_p, 1 (0.005 to 0.25).
    f : float, optional
        Tuning ratio ω_a/ω_p, 1 (0.7 to 1.3); default the H∞ optimum at mu.
    zeta_a : float, optional
        Absorber damping ratio c_a/(2 m_a ω_a), 1 (0.005 to 1); default the H∞ optimum at mu.
    zeta_p : float
        Primary damping ratio, 1 (0 to 0.3).
    panel_id : str, optional
        Prefix of element ids (default: hash of the parameters and a counter).

    Examples
    --------
    >>> frag = tmd_panel_html()
    >>> frag.startswith('<div class="vtm-panel"'), "http" in frag, frag.count("<input")
    (True, False, 4)
    """
    mu, f, zeta_a, zeta_p = _slider_values(mu, f, zeta_a, zeta_p)
    params = {"mu": mu, "f": f, "zeta_a": zeta_a, "zeta_p": zeta_p}
    if panel_id is None:
        digest = hashlib.sha1(json.dumps(params, sort_keys=True).encode()).hexdigest()[:8]
        panel_id = f"vtm-{digest}-{next(_counter)}"
    e = html.escape
    pid = e(panel_id)
    lg = math.log10

    def slider(cls, label, lo, hi, value, log):
        a, b, v = (lg(lo), lg(hi), lg(value)) if log else (lo, hi, value)
        return (
            f'<label for="{pid}-{cls}">{label}</label>\n'
            f'<input type="range" class="vtm-{cls}" id="{pid}-{cls}" min="{a!r}" max="{b!r}" step="any" '
            f'value="{v!r}">\n<output class="vtm-{cls}-out" for="{pid}-{cls}"></output>\n'
        )

    rules = "".join(
        f'<tr><th>{e(name)}</th><td class="vtm-{key}-f"></td><td class="vtm-{key}-za"></td>'
        f'<td class="vtm-{key}-p0"></td><td class="vtm-{key}-p"></td></tr>\n'
        for key, name in _SLIDER_RULES
    )
    buttons = "".join(
        f'<button type="button" class="vtm-rule" data-rule="{key}">{e(name.split(" (")[0])}</button>'
        for key, name in _SLIDER_RULES
    )
    return f"""<div class="vtm-panel" id="{pid}" data-params="{e(json.dumps(params))}">
<style>
{_asset("tmd.css")}</style>
<h3 class="vtm-title">Tuned mass damper: the primary's magnification against the frequency ratio</h3>
<p class="vtm-sub">Move the mass ratio μ and the absorber damping ζ<sub>a</sub> (logarithmic), the tuning
f = ω<sub>a</sub>/ω<sub>p</sub> and the primary damping ζ<sub>p</sub>; computed in your browser from the
closed forms.</p>
<noscript>This panel needs JavaScript to draw its plot.</noscript>
<div class="vtm-controls">
{slider("mu", "mass ratio μ = m<sub>a</sub>/m<sub>p</sub> (log)", *MU_RANGE, mu, True)}\
{slider("f", "tuning f = ω<sub>a</sub>/ω<sub>p</sub>", *F_RANGE, f, False)}\
{
        slider(
            "za",
            "absorber damping ζ<sub>a</sub> = c<sub>a</sub>/(2 m<sub>a</sub> ω<sub>a</sub>) (log)",
            *ZETA_A_RANGE,
            zeta_a,
            True,
        )
    }\
{slider("zp", "primary damping ζ<sub>p</sub>", *ZETA_P_RANGE, zeta_p, False)}\
</div>
<div class="vtm-buttons">set f and ζ<sub>a</sub> to the rule for this μ: {buttons}</div>
<div class="vtm-body">
<figure><svg class="vtm-plot" viewBox="0 0 640 330" role="img"
aria-label="primary's magnification against the frequency ratio"></svg>
<figcaption><span class="vtm-key vtm-key-curve"></span>with the absorber of the sliders
<span class="vtm-key vtm-key-opt"></span>H∞ tuning for this μ
<span class="vtm-key vtm-key-bare"></span>without absorber
<span class="vtm-key vtm-key-dot"></span>fixed points P, Q of the undamped primary
<span class="vtm-key vtm-key-peak"></span>peak</figcaption></figure>
<div>
<table class="vtm-readout"><tbody>
<tr><th>peak |X<sub>p</sub>|/(F<sub>0</sub>/k<sub>p</sub>)</th><td class="vtm-r-peak"></td></tr>
<tr><th>peak without absorber</th><td class="vtm-r-bare"></td></tr>
<tr><th>fixed point P (ζ<sub>p</sub> = 0)</th><td class="vtm-r-p"></td></tr>
<tr><th>fixed point Q (ζ<sub>p</sub> = 0)</th><td class="vtm-r-q"></td></tr>
</tbody></table>
<table class="vtm-rules"><caption>Tunings for the current μ (ζ<sub>a</sub> on ω<sub>a</sub>)</caption>
<thead><tr><th>rule</th><th>f</th><th>ζ<sub>a</sub></th><th>peak, ζ<sub>p</sub> = 0</th>
<th>peak, current ζ<sub>p</sub></th></tr></thead>
<tbody>
{rules}</tbody></table>
</div>
</div>
<script>
{_asset("tmd.js")}</script>
<script>window.vibrationTMD.mount(document.getElementById({json.dumps(panel_id)}));</script>
</div>
"""


class TMDExplorer:
    """JupyterLab sliders (ipywidgets) for μ, f, ζ_a and ζ_p over the magnification curve.

    ``_repr_mimebundle_`` returns the widget view for JupyterLab and, for renderers
    without a kernel (the book), :func:`tmd_panel_html` at the current slider values.
    """

    def __init__(self, mu=0.05, f=None, zeta_a=None, zeta_p=0.0) -> None:
        import ipywidgets as widgets

        mu, f, zeta_a, zeta_p = _slider_values(mu, f, zeta_a, zeta_p)
        self.mu_slider = widgets.FloatLogSlider(
            value=mu, base=10.0, min=math.log10(MU_RANGE[0]), max=math.log10(MU_RANGE[1]), step=0.005,
            description="μ", readout_format=".4g",
        )  # fmt: skip
        self.f_slider = widgets.FloatSlider(
            value=f, min=F_RANGE[0], max=F_RANGE[1], step=0.0005, description="f = ω_a/ω_p", readout_format=".4f"
        )
        self.zeta_a_slider = widgets.FloatLogSlider(
            value=zeta_a, base=10.0, min=math.log10(ZETA_A_RANGE[0]), max=math.log10(ZETA_A_RANGE[1]), step=0.005,
            description="ζ_a", readout_format=".4g",
        )  # fmt: skip
        self.zeta_p_slider = widgets.FloatSlider(
            value=zeta_p, min=ZETA_P_RANGE[0], max=ZETA_P_RANGE[1], step=0.001, description="ζ_p",
            readout_format=".3f",
        )  # fmt: skip
        self.rule_buttons = widgets.ToggleButtons(
            options=["Den Hartog", "H∞", "H2"], value=None, description="set rule", tooltips=[]
        )
        self.image = widgets.Image(format="png")
        self.readout = widgets.HTML()
        sliders = (self.mu_slider, self.f_slider, self.zeta_a_slider, self.zeta_p_slider)
        self.widget = widgets.VBox(
            [widgets.HBox(sliders[:2]), widgets.HBox(sliders[2:]), self.rule_buttons, self.readout, self.image]
        )
        for s in sliders:
            s.observe(lambda _change: self.update(), names="value")
        self.rule_buttons.observe(self._apply_rule, names="value")
        self.update()

    def _apply_rule(self, change) -> None:
        rule = change["new"]
        if rule is None:
            return
        t = {"Den Hartog": den_hartog, "H∞": hinf_tuning, "H2": h2_tuning}[rule](float(self.mu_slider.value))
        with self.f_slider.hold_trait_notifications(), self.zeta_a_slider.hold_trait_notifications():
            self.f_slider.value = min(max(t.f, F_RANGE[0]), F_RANGE[1])
            self.zeta_a_slider.value = min(max(t.zeta_a, ZETA_A_RANGE[0]), ZETA_A_RANGE[1])
        self.rule_buttons.value = None
        self.update()

    def values(self) -> dict:
        """Current numbers: slider values, peak and its r, fixed points, the rules' tunings and peaks (all 1)."""
        mu, f = float(self.mu_slider.value), float(self.f_slider.value)
        za, zp = float(self.zeta_a_slider.value), float(self.zeta_p_slider.value)
        rules = {"Den Hartog": den_hartog(mu), "H∞": hinf_tuning(mu), "H2": h2_tuning(mu)}
        rp, hp = tmd_fixed_points(mu, f)
        return {
            "mu": mu,
            "f": f,
            "zeta_a": za,
            "zeta_p": zp,
            "peak": tmd_peak(mu, f, za, zp),
            "fixed": (rp, hp),
            "rules": rules,
            "rule_peaks": {n: tmd_peak(mu, t.f, t.zeta_a, zp) for n, t in rules.items()},
        }

    def update(self) -> None:
        v = self.values()
        fig = _explorer_figure(v)
        buf = io.BytesIO()
        fig.savefig(buf, format="png")
        self.image.value = buf.getvalue()
        rp, hp = v["fixed"]
        rows = "".join(
            f"<tr><td>{html.escape(n)}</td><td>{t.f:.4f}</td><td>{t.zeta_a:.4f}</td><td>{t.peak:.4g}</td>"
            f"<td>{v['rule_peaks'][n]:.4g}</td></tr>"
            for n, t in v["rules"].items()
        )
        self.readout.value = (
            f"<p>peak |X_p|/(F0/k_p) = {v['peak']:.4g}; fixed points P (r = {rp[0]:.4f}, {hp[0]:.4g}) and "
            f"Q (r = {rp[1]:.4f}, {hp[1]:.4g}) for ζ_p = 0; ζ'_a = f ζ_a = {v['f'] * v['zeta_a']:.4g}</p>"
            "<table><tr><th>rule</th><th>f</th><th>ζ_a</th><th>peak, ζ_p = 0</th><th>peak, current ζ_p</th></tr>"
            f"{rows}</table>"
        )

    def _repr_mimebundle_(self, **kwargs):
        data = self.widget._repr_mimebundle_(**kwargs) or {}
        data["text/html"] = tmd_panel_html(
            float(self.mu_slider.value),
            float(self.f_slider.value),
            float(self.zeta_a_slider.value),
            float(self.zeta_p_slider.value),
        )
        data["image/png"] = base64.b64encode(self.image.value).decode("ascii")
        data["text/plain"] = (
            f"TMDExplorer(mu={self.mu_slider.value:.4g}, f={self.f_slider.value:.4g}, "
            f"zeta_a={self.zeta_a_slider.value:.4g}, zeta_p={self.zeta_p_slider.value:.4g})"
        )
        return data


def _explorer_figure(v: dict):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.5, 3.6), dpi=90, layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.subplots()
    mu, f, za, zp = v["mu"], v["f"], v["zeta_a"], v["zeta_p"]
    r = np.linspace(*R_RANGE, 2401)
    rp, hp = v["fixed"]
    top = max(2.0 * math.sqrt(1.0 + 2.0 / mu), 1.15 * float(hp.max()))
    with np.errstate(divide="ignore"):
        bare = 1.0 / np.hypot((1.0 - r) * (1.0 + r), 2.0 * zp * r)
    opt = v["rules"]["H∞"]
    ax.plot(r, np.minimum(bare, 2 * top), color="0.5", lw=1.0, label="without absorber")
    ax.plot(r, tmd_magnification(mu, f, za, r, zp), color="#1f77b4", lw=1.8, label="with the sliders' absorber")
    ax.plot(r, tmd_magnification(mu, opt.f, opt.zeta_a, r, zp), color="#2ca02c", lw=1.2, ls="--",
            label=r"H$\infty$ tuning for this $\mu$")  # fmt: skip
    ax.plot(rp, hp, "o", color="k", ms=5, label=r"fixed points P, Q ($\zeta_p = 0$)")
    ax.set_xlim(*R_RANGE)
    ax.set_ylim(0.0, top)
    ax.set_xlabel(r"frequency ratio $r = \omega/\omega_p$ (1)")
    ax.set_ylabel(r"$|X_p|\,/\,(F_0/k_p)$ (1)")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    return fig


def sliders_text(ch: TMDChapter) -> str:
    """Which controls exist in JupyterLab and in the rendered book, and where they start (Markdown)."""
    mu = min(max(ch.mu, MU_RANGE[0]), MU_RANGE[1])
    moved = "" if mu == ch.mu else f" (the chapter's μ = {ch.mu:g} is outside the slider's range)"
    t = hinf_tuning(mu)
    return (
        "**In JupyterLab** (with a running kernel) the cell below shows live widgets: logarithmic sliders for the "
        f"mass ratio μ ({MU_RANGE[0]:g} to {MU_RANGE[1]:g}) and the absorber damping ratio ζ_a "
        f"({ZETA_A_RANGE[0]:g} to {ZETA_A_RANGE[1]:g}, on the absorber's own frequency), linear sliders for the "
        f"tuning ratio f = ω_a/ω_p ({F_RANGE[0]:g} to {F_RANGE[1]:g}) and the primary damping ratio ζ_p "
        f"({ZETA_P_RANGE[0]:g} to {ZETA_P_RANGE[1]:g}), three buttons that set f and ζ_a to Den Hartog's, the "
        "H∞ and the H2 tuning of the current μ, a readout (peak, fixed points, each rule's f, ζ_a and peak) and "
        "a plot computed by the package. **In the rendered book** there is no kernel: the same four sliders and "
        "three buttons drive a panel that computes the magnification in closed form in your browser, draws it "
        "against r = ω/ω_p with the H∞ curve of the same μ, the primary without absorber, the fixed points P "
        "and Q and the peak, and reads out the peak, P and Q and the three rules' tunings with the peaks they "
        f"give on an undamped and on the current primary. Both start at μ = {mu:g}{moved} with the H∞ tuning "
        f"f = {t.f:.4f}, ζ_a = {t.zeta_a:.4f} on an undamped primary (ζ_p = 0), where P and Q are exact; set "
        f"ζ_p to {ch.zeta_p:.4f} for the paper's primary, where they are only approximate."
    )


def tmd_explorer(mu=0.05, f=None, zeta_a=None, zeta_p=0.0) -> TMDExplorer:
    """The chapter's sliders: :class:`TMDExplorer` (ipywidgets in JupyterLab, HTML panel in the book).

    Starts at mass ratio mu, tuning f and absorber damping zeta_a (default: the H∞
    closed-form optimum at mu) and primary damping zeta_p, each moved into its slider's
    range when outside (μ 0.005 to 0.25, f 0.7 to 1.3, ζ_a 0.005 to 1, ζ_p 0 to 0.3).

    Parameters
    ----------
    mu : float
        Mass ratio m_a/m_p, 1 (> 0).
    f : float, optional
        Tuning ratio ω_a/ω_p, 1 (> 0).
    zeta_a : float, optional
        Absorber damping ratio c_a/(2 m_a ω_a), 1 (> 0).
    zeta_p : float
        Primary damping ratio c_p/(2 m_p ω_p), 1 (>= 0).

    Returns
    -------
    TMDExplorer

    Examples
    --------
    >>> ex = tmd_explorer(0.05)
    >>> round(ex.values()["peak"], 4)     # the H∞ optimum of an undamped primary
    6.4079
    """
    mu = check_real("mu", mu, low=0.0, low_open=True, high=MU_MAX)
    if f is not None:
        f = check_real("f", f, low=0.0, low_open=True, unit="(ω_a/ω_p)")
    if zeta_a is not None:
        zeta_a = check_real("zeta_a", zeta_a, low=0.0, low_open=True)
    zeta_p = check_real("zeta_p", zeta_p, low=0.0)

    def clip(x, lo_hi):
        return None if x is None else min(max(x, lo_hi[0]), lo_hi[1])

    mu = clip(mu, MU_RANGE)
    return TMDExplorer(mu, clip(f, F_RANGE), clip(zeta_a, ZETA_A_RANGE), clip(zeta_p, ZETA_P_RANGE))
