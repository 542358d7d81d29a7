"""Chapter 4's computation, run once: frequency response, damping estimates, decomposition, energy, design map.

:func:`frequency_response_study` evaluates the magnification and phase lag of the run's dampings (the list
``dampings``, by default the paper's three), their resonant peaks and exact half-power bands, three
independent damping-ratio estimates, the split of the resonance case into steady state and transient, its
energy balance, and the window's peak displacement over a grid of forcing frequency and damping. The figures
and tables only read the one :class:`FrequencyStudy` it returns, so a run with other parameters never
contradicts itself. Differences at rounding level are kept as :class:`Check` records.

Examples
--------
>>> st = frequency_response_study(n_points=2001, n_omega=20, n_damping=10)
>>> [(c.name, c.inside) for c in st.cases]
[('c = 0.1 N s/m', True), ('c = 0.5 N s/m', True), ('c = 15 N s/m', None)]
>>> round(st.decomposition.X, 4), all(c.ok for c in st.checks)      # m
(2.2371, True)
>>> st.design.peaks.shape, [round(p, 3) for p in st.design.at_res]     # m
((10, 20), [10.251, 2.237, 0.105])
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.frequency_response.params import Params
from vibration.book.presentation.findings import scenarios_of
from vibration.book.presentation.numbers import sig
from vibration.physics import frequency as fr
from vibration.physics.audit import half_power_band, resonant_peak
from vibration.physics.exact import Response, exact_response, steady_state
from vibration.physics.model import Oscillator, ParameterError, SineForce
from vibration.physics.numerics import simulate
from vibration.physics.paper import Scenario

#: Samples of the magnification curve within ±20 ζ ωₙ of the peak from which the half-power points are read
#: (the chapter's prose states this count).
HALF_POWER_SAMPLES = 200_001

#: Largest damping ratio at which the log decrement of six free periods is fitted.
ZETA_DECREMENT_MAX = 0.3

#: Tolerances of the checks (relative differences).
TOL_ESTIMATE = 1e-7  # damping-ratio estimates against c / (2 sqrt(k m))
TOL_CLOSED = 1e-10  # closed forms against each other, and the energy quadrature on the exact response

#: Fraction of the undamped (or of the damping-only) magnification within which one term "sets" the amplitude.
CONTROL = 0.9

#: Samples of the magnification and phase curves, over omega_n / SPAN to omega_n * SPAN.
N_CURVE, SPAN = 2001, 20.0


@dataclass(frozen=True, kw_only=True)
class Check:
    """Two independent routes to one quantity: their relative difference and the bound it must stay under."""

    check: str  # what is compared, in words
    value: float  # relative difference, 1
    tol: float  # bound, 1

    @property
    def ok(self) -> bool:
        """True when the difference is within the bound."""
        return bool(self.value < self.tol)


@dataclass(frozen=True, eq=False, kw_only=True)
class DampingCase:
    """One of the paper's three dampings at the run's forcing frequencies (SI units, magnifications in 1)."""

    case: int  # its place in the run's list of dampings (its colour), -1 for the nominal damping outside the list
    name: str  # "c = 0.1 N s/m"
    osc: Oscillator  # kg, N s/m, N/m
    omega_ref: float  # reference forcing frequency, rad/s
    omega_res: float  # the paper's "resonant" forcing frequency, rad/s
    omega_peak: float | None  # frequency of the magnification's peak, rad/s (None: no peak)
    M_peak: float | None  # its height (inf when undamped)
    lo: float | None  # lower half-power frequency, rad/s (None: it does not exist)
    hi: float | None  # upper half-power frequency, rad/s
    M_ref: float  # magnification at omega_ref
    M_res: float  # magnification at omega_res
    zeta_hp: float | None  # damping ratio from the half-power points of the computed curve
    zeta_ld: float | None  # damping ratio from the log decrement of an integrated free decay
    magnification: np.ndarray  # on FrequencyStudy.omegas
    phase: np.ndarray  # phase lag on FrequencyStudy.omegas, rad

    @property
    def c(self) -> float:
        """Damping coefficient, N s/m."""
        return self.osc.c

    @property
    def zeta(self) -> float:
        """Damping ratio c / (2√(km))."""
        return self.osc.damping_ratio

    @property
    def regime(self) -> str:
        """Regime word (underdamped, overdamped, ...)."""
        return self.osc.regime

    @property
    def steady(self) -> bool:
        """True when a steady state exists (c > 0)."""
        return self.osc.c > 0

    @property
    def inside(self) -> bool | None:
        """Whether omega_res lies in the half-power band (None when there is no band)."""
        if self.hi is None:
            return None
        return bool((self.lo is None or self.lo <= self.omega_res) and self.omega_res <= self.hi)


@dataclass(frozen=True, kw_only=True)
class Decomposition:
    """The resonance case from rest split into steady state and transient (SI units)."""

    X: float  # steady amplitude, m
    phase: float  # steady phase lag, rad
    x_h0: float  # transient at t = 0, m
    x_h_end: float  # transient at t_end, m
    t_s: float  # 2 % settling time, s (inf when it never settles)


@dataclass(frozen=True, kw_only=True)
class Control:
    """Which term sets the nominal damping's steady amplitude at one forcing frequency."""

    omega: float  # forcing frequency, rad/s
    r: float  # frequency ratio omega / omega_n
    M: float  # magnification
    undamped: float  # 1 / |1 - r^2|, the magnification without damping (inf at r = 1)
    damping_only: float  # 1 / (2 zeta r), the magnification set by damping alone (inf when c <= 0)
    doubled: float  # steady amplitude with twice the damping over the amplitude with the damping, 1

    @property
    def setter(self) -> str:
        """ "stiffness" (and mass), "damping", or "all" when neither limit is within CONTROL of M."""
        if self.M >= CONTROL * self.undamped:
            return "stiffness"
        if self.M >= CONTROL * self.damping_only:
            return "damping"
        return "all"


def control(osc: Oscillator, w: float) -> Control:
    """Which term sets the steady amplitude of ``osc`` forced at ``w`` rad/s (c > 0)."""
    r = w / osc.natural_frequency
    undamped = 1.0 / abs(1.0 - r * r) if r != 1.0 else math.inf
    damping_only = 1.0 / (2.0 * osc.damping_ratio * r) if osc.c > 0 else math.inf
    twice = Oscillator(m=osc.m, c=2.0 * osc.c, k=osc.k)
    return Control(
        omega=w,
        r=r,
        M=_mag(osc, w),
        undamped=undamped,
        damping_only=damping_only,
        doubled=_mag(twice, w) / _mag(osc, w),
    )


@dataclass(frozen=True, eq=False, kw_only=True)
class DesignMap:
    """Largest |x| in the window from rest over a grid of forcing frequency and damping."""

    omegas: np.ndarray  # rad/s
    dampings: np.ndarray  # N s/m, geometric
    peaks: np.ndarray  # m, indexed [damping, omega]
    at_res: tuple[float, ...]  # m: peak at omega_res for the three dampings, by the map's kernel

    @property
    def largest(self) -> tuple[float, float, float]:
        """The grid's largest peak: (omega rad/s, c N s/m, peak m)."""
        i, j = np.unravel_index(np.argmax(self.peaks), self.peaks.shape)
        return float(self.omegas[j]), float(self.dampings[i]), float(self.peaks[i, j])

    @property
    def danger_band(self) -> tuple[float, float]:
        """At the grid's lowest damping: the frequencies (rad/s) whose peak exceeds half the largest there."""
        low = self.peaks[0]
        above = self.omegas[low >= 0.5 * low.max()]
        return float(above.min()), float(above.max())

    @property
    def danger_width(self) -> float:
        """Width of :attr:`danger_band` counting whole grid cells (one frequency step each), rad/s."""
        lo, hi = self.danger_band
        step = float(self.omegas[1] - self.omegas[0]) if self.omegas.size > 1 else 0.0
        return hi - lo + step

    @property
    def flatness(self) -> float:
        """At the grid's highest damping: largest over smallest peak across the frequencies."""
        high = self.peaks[-1]
        return float(high.max() / high.min())


@dataclass(frozen=True, eq=False, kw_only=True)
class FrequencyStudy:
    """Everything chapter 4 computes, once (SI units)."""

    params: Params
    scenarios: dict[str, Scenario]  # the paper's five, from the run's parameters
    omegas: np.ndarray  # frequency grid of the magnification and phase curves, rad/s
    cases: tuple[DampingCase, ...]  # low, nominal, high
    t: np.ndarray  # output grid of the resonance case, s
    total: Response  # exact response from rest of the resonance case (s, m, m/s)
    steady: np.ndarray  # its steady state on t, m
    transient: Response  # its transient (free response from what the steady state leaves over), s, m, m/s
    decomposition: Decomposition
    energy: tuple[tuple[str, fr.EnergyBalance], ...]  # (response name, balance): exact, then the paper's RK45
    energy_t: np.ndarray  # times of the energy balances, s
    design: DesignMap
    checks: tuple[Check, ...]
    controls: tuple[Control, ...]  # nominal damping at omega_ref and omega_res (empty when c_nominal <= 0)
    nominal_case: DampingCase | None = None  # the nominal damping, when the list of dampings leaves it out

    @property
    def omega_n(self) -> float:
        """Natural frequency, rad/s."""
        return self.resonance.oscillator.natural_frequency

    @property
    def resonance(self) -> Scenario:
        """The resonance scenario (nominal damping at omega_res)."""
        return self.scenarios["resonance"]

    @property
    def nominal(self) -> DampingCase:
        """The nominal damping case (the resonance run's damping, in the list or not)."""
        return next((c for c in self.cases if c.c == self.params.c_nominal), self.nominal_case)

    def energy_residual(self, index: int) -> float:
        """Worst |W − D − ΔE| over the window relative to the largest |W|, of energy balance ``index``."""
        eb = self.energy[index][1]
        return float(np.max(np.abs(eb.residual)) / np.max(np.abs(eb.work)))


def _mag(osc: Oscillator, w: float) -> float:
    return float(fr.magnification(osc, [w])[0])


def _case(osc: Oscillator, case: int, p: Params, omegas: np.ndarray) -> tuple[DampingCase, list[Check]]:
    z, wn = osc.damping_ratio, osc.natural_frequency
    w_pk, m_pk = resonant_peak(osc)
    lo, hi = half_power_band(osc)
    zeta_hp = zeta_ld = None
    if lo is not None:
        w = wn * np.linspace(max(0.0, 1 - 20 * z), 1 + 20 * z, HALF_POWER_SAMPLES)
        try:
            zeta_hp = fr.half_power_points(w, fr.magnification(osc, w)).damping_ratio
        except ParameterError:  # the lower point closer to 0 than one grid step
            zeta_hp = None
    if 0.0 < z < ZETA_DECREMENT_MAX:
        t_free = 6 * 2 * np.pi / osc.damped_natural_frequency
        decay = simulate(
            osc, SineForce(F0=0.0, omega=0.0), t_free, n_points=20001, x0=1.0, method="DOP853", rtol=1e-10, atol=1e-13
        )
        zeta_ld = fr.log_decrement(decay.t, decay.x)[1]
    name = f"c = {sig(osc.c)} N s/m"
    row = DampingCase(
        case=case,
        name=name,
        osc=osc,
        omega_ref=p.omega_ref,
        omega_res=p.omega_res,
        omega_peak=w_pk,
        M_peak=m_pk,
        lo=lo,
        hi=hi,
        M_ref=_mag(osc, p.omega_ref),
        M_res=_mag(osc, p.omega_res),
        zeta_hp=zeta_hp,
        zeta_ld=zeta_ld,
        magnification=fr.magnification(osc, omegas),
        phase=fr.phase_lag(osc, omegas),
    )
    checks = [
        Check(check=f"ζ from the {what}, {name}, against c/(2√(km))", value=abs(est / z - 1), tol=TOL_ESTIMATE)
        for est, what in ((zeta_hp, "half-power points"), (zeta_ld, "log decrement"))
        if est is not None
    ]
    ss = steady_state(osc, SineForce(F0=p.F0, omega=p.omega_res))
    if math.isfinite(ss.magnification):
        checks.append(
            Check(
                check=f"magnification at the resonant forcing, {name}, against the steady amplitude X/(F₀/k)",
                value=abs(row.M_res / ss.magnification - 1),
                tol=TOL_CLOSED,
            )
        )
    return row, checks


def _design(p: Params, study_t: np.ndarray, cases: tuple[DampingCase, ...]) -> tuple[DesignMap, list[Check]]:
    omegas = np.linspace(p.omega_max / p.n_omega, p.omega_max, p.n_omega)
    dampings = np.geomspace(p.c_min, p.c_max, p.n_damping)
    n = study_t.size
    peaks = fr.peak_displacement_map(p.m, p.k, p.F0, omegas=omegas, dampings=dampings, t_end=p.t_end, n_points=n)
    cs = [c.c for c in cases]
    at = fr.peak_displacement_map(p.m, p.k, p.F0, omegas=[p.omega_res], dampings=cs, t_end=p.t_end, n_points=n)[:, 0]
    force = SineForce(F0=p.F0, omega=p.omega_res)
    direct = [float(np.max(np.abs(exact_response(Oscillator(m=p.m, c=c, k=p.k), force, study_t).x))) for c in cs]
    checks = [
        Check(
            check=f"design-map kernel against the exact response at the resonant forcing, {case.name}",
            value=abs(a / d - 1) if d > 0 else abs(a - d),
            tol=TOL_CLOSED,
        )
        for case, a, d in zip(cases, at, direct, strict=True)
    ]
    return DesignMap(omegas=omegas, dampings=dampings, peaks=peaks, at_res=tuple(float(a) for a in at)), checks


def frequency_response_study(params: Params | None = None, **values) -> FrequencyStudy:
    """Compute chapter 4 from the paper's parameters or a run's.

    Parameters
    ----------
    params : Params, optional
        The chapter's validated parameters (m kg, k N/m, F0 N, t_end s, omega_ref and omega_res rad/s,
        c_low, c_nominal and c_high N s/m, n_points; the design map's n_omega, n_damping, omega_max rad/s,
        c_min and c_max N s/m); or give some of them as keyword arguments (the rest keep their defaults).

    Returns
    -------
    FrequencyStudy
        Frozen record of every result of the chapter.

    Examples
    --------
    >>> frequency_response_study(c_min=0.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: c_min = 0.0 N s/m is out of range: allowed c_min >= 0.001 N s/m, ...
    """
    p = params if params is not None else Params.from_values(values)
    scenarios = scenarios_of(p)
    wn = scenarios["resonance"].oscillator.natural_frequency
    omegas = np.geomspace(wn / SPAN, wn * SPAN, N_CURVE)
    cases, checks = [], []
    for i, c in enumerate(p.dampings):
        row, chk = _case(Oscillator(m=p.m, c=c, k=p.k), i, p, omegas)
        cases.append(row)
        checks += chk
    nominal_case = None
    if p.c_nominal not in p.dampings:
        nominal_case, _ = _case(Oscillator(m=p.m, c=p.c_nominal, k=p.k), -1, p, omegas)
    res = scenarios["resonance"]
    osc, force = res.oscillator, res.force
    t = np.linspace(0.0, p.t_end, p.n_points)
    total = exact_response(osc, force, t)
    ss = steady_state(osc, force)
    steady = ss.amplitude * np.sin(force.omega * t - ss.phase)
    a, b = ss.amplitude * math.sin(ss.phase), -force.omega * ss.amplitude * math.cos(ss.phase)
    transient = exact_response(osc, SineForce(F0=0.0, omega=0.0), t, x0=a, v0=b)
    scale = max(float(np.max(np.abs(total.x))), 1e-300)
    checks.append(
        Check(
            check="exact response from rest against steady state + transient, resonance case",
            value=float(np.max(np.abs(total.x - steady - transient.x))) / scale,
            tol=TOL_CLOSED,
        )
    )
    decomposition = Decomposition(
        X=ss.amplitude, phase=ss.phase, x_h0=a, x_h_end=float(transient.x[-1]), t_s=fr.settling_time(osc, force)
    )
    fine = np.linspace(0.0, p.t_end, 5 * (p.n_points - 1) + 1)
    eb_exact = fr.energy_balance(osc, force, exact_response(osc, force, fine))
    eb_paper = fr.energy_balance(osc, force, simulate(osc, force, p.t_end, n_points=fine.size))
    checks.append(
        Check(
            check="energy balance W − D − ΔE on the exact response, resonance case (relative to max W)",
            value=float(np.max(np.abs(eb_exact.residual)) / np.max(np.abs(eb_exact.work))),
            tol=TOL_CLOSED,
        )
    )
    cases = tuple(cases)
    design, design_checks = _design(p, t, cases)
    return FrequencyStudy(
        params=p,
        scenarios=scenarios,
        omegas=omegas,
        cases=cases,
        t=t,
        total=total,
        steady=steady,
        transient=transient,
        decomposition=decomposition,
        energy=(("exact", eb_exact), ("RK45 at its default tolerances", eb_paper)),
        energy_t=fine,
        design=design,
        checks=tuple(checks + design_checks),
        nominal_case=nominal_case,
        controls=tuple(control(osc, w) for w in (p.omega_ref, p.omega_res)) if osc.c > 0 else (),
    )
