"""Chapter 8's computation: the absorber on the paper's primary, its tunings, designs and robustness, the building.

Pure computation, no prose. :func:`tmd_study` takes the chapter's validated :class:`Params` record
and returns one frozen :class:`TMDStudy`; every table, figure and sentence of the chapter is a
function of that record (modules ``tables``, ``figures``, ``text``), so a run with other parameters
never contradicts its own tables.

Names used throughout (the dimensionless groups of :mod:`vibration.physics.tmd`): mass ratio
μ = m_a/m_p, tuning ratio f = ω_a/ω_p, absorber damping ratio ζ_a = c_a/(2 m_a ω_a) on the
absorber's own frequency, primary damping ratio ζ_p = c_p/(2 m_p ω_p), forcing ratio r = ω/ω_p,
magnification |X_p|/(F0/k_p).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np

from vibration.book.chapters.tmd.designs import (
    DEN_HARTOG,
    DESIGNS,
    H2,
    H2_CLOSED,
    HINF,
    HINF_CLOSED,
    ROBUST,
    TUNINGS,
    Design,
)
from vibration.book.chapters.tmd.params import Params
from vibration.book.presentation.records import with_params
from vibration.physics.exact import exact_response, steady_state
from vibration.physics.model import Oscillator, SineForce, check_real
from vibration.physics.tmd import (
    MDOF,
    DesignScore,
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
    tmd_stroke,
    tmd_system,
    worst_peak,
)

#: Mass ratios of the tunings table (the run's μ is added when it is not among them), 1.
TABLE_MUS = (0.01, 0.02, 0.05, 0.1)
#: Largest primary damping ratio the numerical optimisations accept, 1.
ZETA_P_MAX = 0.5
#: Stiffness errors sampled across the band of the robustness figure and table.
N_EPS = 41
#: Chopra's uniform frame in SI: 100 kips/g floors (kg) and 31.54 kips/in storeys (N/m), converted.
CHOPRA_FLOOR_MASS = 100 * 4448.2216152605 / 9.80665
CHOPRA_STOREY_STIFFNESS = 31.54 * 4448.2216152605 / 0.0254
CHOPRA_STOREYS = 5


@dataclass(frozen=True, kw_only=True)
class LoadCase:
    """The building's largest roof response near the first mode under one load, without and with the absorber."""

    name: str  # the load, in words
    unit: str  # unit of the printed amplitudes
    scale: float  # printed unit per SI unit (m/N -> mm/kN: 10⁶; s² -> mm/(m/s²): 10³)
    peak_without: float  # largest roof amplitude without the absorber, SI (m/N or s²)
    omega_without: float  # its frequency, rad/s
    peak_with: float  # largest roof amplitude with the absorber, SI
    omega_with: float  # its frequency, rad/s
    omega_max: float  # upper end of the band searched, rad/s

    @property
    def reduction(self) -> float:
        """1 − with / without, 1."""
        return 1.0 - self.peak_with / self.peak_without


@dataclass(frozen=True, kw_only=True)
class Check:
    """One independent check of the chapter's numbers: what is compared, the difference, its tolerance."""

    name: str
    value: float
    tolerance: float

    @property
    def ok(self) -> bool:
        return self.value < self.tolerance


@with_params("m", "k", "F0", "omega_res", "t_end", "mu", "mistuning", "mu_building", c="c_nominal")
@dataclass(frozen=True, eq=False, kw_only=True)
class TMDStudy:
    """Every result of the chapter (SI units; ratios dimensionless).

    The run's parameters are readable by their physical names (``st.c`` for ``st.params.c_nominal``): see
    :func:`~vibration.book.presentation.records.with_params`.
    """

    params: Params
    zeta_p: float  # primary damping ratio c/(2 sqrt(k m)), 1
    tunings: dict = field(repr=False)  # μ -> rule (a Design of RULES) -> TMDTuning (.peak where optimised)
    peaks_actual: dict = field(repr=False)  # μ -> rule -> peak magnification on the actual primary, 1
    t: np.ndarray = field(repr=False)  # time grid, s
    x_without: np.ndarray = field(repr=False)  # primary displacement without the absorber, m
    x_with: np.ndarray = field(repr=False)  # primary displacement with the chosen absorber, m
    x_absorber: np.ndarray = field(repr=False)  # absorber displacement, m
    amp_without: float  # steady amplitude without, m
    amp_with: float  # steady amplitude with, m
    amp_absorber: float  # steady absorber amplitude, m
    eps: np.ndarray = field(repr=False)  # relative errors of the primary's stiffness, 1
    robust: dict = field(repr=False)  # tuning (a Design of TUNINGS) -> peak over eps, 1
    robust_none: np.ndarray = field(repr=False)  # peak without absorber over eps, 1
    scores: dict = field(repr=False)  # tuning (a Design of TUNINGS) -> DesignScore on the actual primary
    building: MDOF = field(repr=False)
    building_tmd: MDOF = field(repr=False)
    absorber: ModeAbsorber = field(repr=False)
    load_cases: tuple = field(repr=False)  # LoadCase: roof force, ground acceleration
    checks: tuple = field(repr=False)  # Check records

    # -- derived -----------------------------------------------------------------------------------
    @property
    def omega_p(self) -> float:
        """Natural frequency of the primary, rad/s."""
        return math.sqrt(self.k / self.m)

    @property
    def r_force(self) -> float:
        """Forcing ratio ω_res/ω_p of the time response and the stroke, 1."""
        return self.omega_res / self.omega_p

    @property
    def x_static(self) -> float:
        """Static deflection F0/k_p, m."""
        return self.F0 / self.k

    @property
    def designs(self) -> dict[Design, DesignScore]:
        """The four designs (DESIGNS) judged on every criterion."""
        return {d: self.scores[d] for d in DESIGNS}

    @property
    def chosen(self) -> TMDTuning:
        """The absorber of the time response: the H∞ optimum for the actual primary damping at μ."""
        return self.tunings[self.mu][HINF]

    @property
    def bare_peak(self) -> float:
        """Peak magnification of the nominal primary without absorber, 1 (inf when undamped)."""
        return float(bare_peak(self.zeta_p, 0.0))

    @property
    def peak_without(self) -> float:
        """Largest |x| of the primary in the window without absorber, m."""
        return float(np.max(np.abs(self.x_without)))

    @property
    def peak_with(self) -> float:
        """Largest |x| of the primary in the window with the chosen absorber, m."""
        return float(np.max(np.abs(self.x_with)))

    @property
    def is_chopra(self) -> bool:
        """Whether the building is Chopra's uniform five-storey frame (the chapter's default)."""
        p = self.params
        return (
            p.n_storeys == CHOPRA_STOREYS
            and math.isclose(p.storey_mass, CHOPRA_FLOOR_MASS, rel_tol=1e-4)
            and math.isclose(p.storey_stiffness, CHOPRA_STOREY_STIFFNESS, rel_tol=1e-4)
        )

    @property
    def first_period(self) -> float:
        """First natural period of the building, s."""
        return 2 * math.pi / float(self.building.natural_frequencies[0])

    @property
    def effective_mass_share(self) -> float:
        """Share of the building's mass that the first mode carries under ground motion, 1."""
        b = self.building
        gamma = b.modes.T @ b.M @ np.ones(b.n)
        return float(gamma[0] ** 2 / np.sum(np.diag(b.M)))


def tmd_study(params: Params | None = None, **values) -> TMDStudy:
    """Compute the chapter's results: tunings, responses, robustness, designs, building.

    Parameters
    ----------
    params : Params, optional
        The validated parameters; or give them as keyword arguments (checked by the schema).
        The primary's damping ``c_nominal`` must be >= 0 with a damping ratio of at most 0.5
        (the numerical optimisations' range).

    Returns
    -------
    TMDStudy

    Examples
    --------
    >>> st = tmd_study(n_storeys=3, n_points=201)
    >>> st.amp_with < st.amp_without, st.building.n
    (True, 3)
    """
    p = params if params is not None else Params.from_values(values)
    check_real("c_nominal", p.c_nominal, low=0.0, unit="N s/m")
    osc = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    zeta_p = osc.damping_ratio
    check_real(f"c_nominal (damping ratio ζ_p = {zeta_p:.4g} of m and k)", zeta_p, high=ZETA_P_MAX)
    mu, band = p.mu, p.mistuning
    mus = sorted(set(TABLE_MUS) | {mu})
    tunings = {x: _tunings(x, zeta_p) for x in mus}
    peaks_actual = {
        x: {r: (t.peak if r == HINF else float(mistuned_peak(t, 0.0, zeta_p))) for r, t in rules.items()}
        for x, rules in tunings.items()
    }
    chosen = tunings[mu][HINF]
    t = np.linspace(0.0, p.t_end, p.n_points)
    force = SineForce(F0=p.F0, omega=p.omega_res)
    x_without = exact_response(osc, force, t).x
    model = tmd_system(p.m, p.c_nominal, p.k, tuning=chosen)
    resp = model.response(t, [p.F0, 0.0], p.omega_res)
    X = model.frf([p.omega_res], [p.F0, 0.0])[0]
    r_force = p.omega_res / math.sqrt(p.k / p.m)
    robust_design = robust_tuning(mu, zeta_p, band)
    all_tunings = {**tunings[mu], H2: h2_tuning(mu, zeta_p), ROBUST: robust_design}
    scores = {name: score_design(all_tunings[name], zeta_p, band, r_force=r_force) for name in TUNINGS}
    eps = np.linspace(-band, band, N_EPS)
    robust = {name: mistuned_peak(all_tunings[name], eps, zeta_p) for name in TUNINGS}
    building = shear_building([p.storey_mass] * p.n_storeys, [p.storey_stiffness] * p.n_storeys, p.zeta_building)
    absorber = first_mode_absorber(building, p.mu_building)
    building_tmd = add_absorber(building, -1, absorber.m_a, k_a=absorber.k_a, c_a=absorber.c_a)
    load_cases = _load_cases(building, building_tmd)
    optimisations = [*(tn for x in mus for tn in tunings[x].values()), *all_tunings.values()]
    checks = _checks(p, osc, zeta_p, model, t, x_without, resp.x[:, 0], chosen, robust_design, building,
                     load_cases, optimisations)  # fmt: skip
    return TMDStudy(
        params=p,
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
        robust_none=bare_peak(zeta_p, eps),
        scores=scores,
        building=building,
        building_tmd=building_tmd,
        absorber=absorber,
        load_cases=load_cases,
        checks=checks,
    )


def _tunings(mu: float, zeta_p: float) -> dict[Design, TMDTuning]:
    return {
        DEN_HARTOG: den_hartog(mu),
        HINF_CLOSED: hinf_tuning(mu),
        H2_CLOSED: h2_tuning(mu),
        HINF: hinf_tuning(mu, zeta_p),
    }


def band_top(b: MDOF) -> float:
    """Upper end of the band "near the first mode", rad/s: 2.5 ω1, or halfway to ω2 when that is lower."""
    w = b.natural_frequencies
    return float(2.5 * w[0] if b.n == 1 else min(2.5 * w[0], 0.5 * (w[0] + w[1])))


def _load_cases(b: MDOF, bt: MDOF) -> tuple[LoadCase, LoadCase]:
    """Largest roof amplitude near the first mode under a roof force and under ground acceleration."""
    top = band_top(b)
    roof = np.zeros(b.n)
    roof[-1] = 1.0
    out = []
    for name, unit, scale, p0, p1 in (
        ("roof force", "mm/kN", 1e6, roof, np.r_[roof, 0.0]),
        ("ground acceleration", "mm/(m/s²)", 1e3, ground_acceleration_load(b), ground_acceleration_load(bt)),
    ):
        h0, w0 = frf_peak(b, p0, b.n - 1, omega_min=0.0, omega_max=top)
        h1, w1 = frf_peak(bt, p1, b.n - 1, omega_min=0.0, omega_max=top)  # the roof is still degree of freedom n - 1
        out.append(
            LoadCase(
                name=name,
                unit=unit,
                scale=scale,
                peak_without=h0,
                omega_without=w0,
                peak_with=h1,
                omega_with=w1,
                omega_max=top,
            )
        )
    return out[0], out[1]


def _checks(p, osc, zeta_p, model, t, x_without, x_with, chosen, robust_design, building, load_cases, optimisations):
    """The chapter's numbers against independent methods, each with its tolerance."""
    closed, numerical = hinf_tuning(p.mu), hinf_tuning(p.mu, method="numerical")
    Xs = model.frf([p.omega_res], [1.0, 0.0])[0]  # per newton, m
    one = MDOF(M=[[p.m]], C=[[p.c_nominal]], K=[[p.k]]).response(t, [p.F0], p.omega_res).x[:, 0]
    step = max(1, p.n_points // 50)
    expm_x = model.response(t[::step], [p.F0, 0.0], p.omega_res, method="expm").x[:, 0]
    r_force = p.omega_res / math.sqrt(p.k / p.m)
    stroke = float(tmd_stroke(p.mu, chosen.f, chosen.zeta_a, r=r_force, zeta_p=zeta_p))
    return (
        Check(name="H∞ closed form against the numerical min-max at ζₚ = 0: tuning ratio f (relative)",
              value=abs(numerical.f / closed.f - 1), tolerance=1e-6),
        Check(name="H∞ closed form against the numerical min-max at ζₚ = 0: ζₐ (relative)",
              value=abs(numerical.zeta_a / closed.zeta_a - 1), tolerance=1e-4),
        Check(name="H∞ closed form against the numerical min-max at ζₚ = 0: peak (relative)",
              value=abs(numerical.peak / closed.peak - 1), tolerance=1e-9),
        Check(name="one-mass MDOF response against the closed form of Part I: largest |Δx| (m)",
              value=float(np.max(np.abs(one - x_without))), tolerance=1e-9),
        Check(name="two-mass response: modal superposition against the matrix exponential, largest |Δx| (m)",
              value=float(np.max(np.abs(x_with[::step] - expm_x))), tolerance=1e-9),
        Check(name="stroke |Xₐ − Xₚ|: closed form against the two-mass complex solve (relative)",
              value=abs(stroke / (p.k * abs(Xs[1] - Xs[0])) - 1.0), tolerance=1e-9),
        Check(name="roof under ground acceleration: complex solve against modal superposition (relative)",
              value=_ground_modal_check(building, load_cases[1].omega_without), tolerance=1e-9),
        Check(name="robust design: lowest worst peak of its 8 neighbours at ±0.1 % in f and ζₐ, shortfall (relative)",
              value=_robust_neighbours(robust_design, zeta_p, p.mistuning), tolerance=1e-9),
        Check(name="numerical optimisations stopped at their iteration limit (count)",
              value=float(sum(not tn.converged for tn in [numerical, *optimisations])), tolerance=1.0),
    )  # fmt: skip


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
            n = TMDTuning(
                rule=t.rule,
                mu=t.mu,
                f=t.f * (1 + 1e-3 * a),
                zeta_a=t.zeta_a * (1 + 1e-3 * b),
                zeta_p=zeta_p,
                peak=t.peak,
                r_peak=t.r_peak,
            )
            best = min(best, worst_peak(n, band, zeta_p)[0])
    return max(0.0, 1.0 - best / w0)


__all__ = [
    "CHOPRA_FLOOR_MASS",
    "CHOPRA_STOREY_STIFFNESS",
    "TABLE_MUS",
    "Check",
    "LoadCase",
    "TMDStudy",
    "band_top",
    "tmd_study",
]
