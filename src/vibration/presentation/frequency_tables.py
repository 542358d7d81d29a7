"""Chapter 4: frequency response and design, computed once, as tables, figures and sentences.

:func:`frequency_study` evaluates the magnification and phase of the three dampings, their
peaks and exact half-power bands, three independent damping-ratio estimates, the split of the
resonance case into steady state and transient, and its energy balance; :func:`design_map`
evaluates the window's peak displacement over a (ω, c) grid. The tables, figures and sentences
below only read those results, so a run with other parameters never contradicts itself.
Differences at rounding level go in :func:`checks_table`, printed as bounds.

Examples
--------
>>> st = frequency_study(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0, n_points=2001)
>>> [(b["case"], b["inside"]) for b in st.bands]
[('low damping', True), ('nominal damping', True), ('high damping', None)]
>>> print(band_text(st).splitlines()[2][:60])
- **high damping** (c = 15 N s/m): overdamped (ζ = 1.68 > 1:
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..physics.audit import half_power_band, resonant_peak
from ..physics.exact import Response, exact_response, steady_state
from ..physics.frequency import (
    energy_balance,
    half_power_points,
    log_decrement,
    magnification,
    peak_displacement_map,
    phase_lag,
    settling_time,
)
from ..physics.model import N_POINTS_MAX, Oscillator, ParameterError, SineForce, check_int, check_real
from ..physics.numerics import simulate
from .findings import NO_STEADY, at_least, case_name, scenarios_from
from .narrative import g, regime_clause
from .tables import Column, Missing, Table

#: The three dampings of the chapter, as scenario ids (their names are :func:`case_name`'s).
DAMPING_IDS = ("damping_low", "damping_nominal", "damping_high")

#: Largest damping ratio at which the log decrement of six free periods is fitted.
ZETA_DECREMENT_MAX = 0.3

#: Tolerances of the checks table (relative differences).
TOL_ESTIMATE = 1e-7  # damping-ratio estimates against c / (2 sqrt(k m))
TOL_CLOSED = 1e-10  # closed forms against each other, and the energy quadrature on the exact response

NO_PEAK = "no resonant peak when ζ ≥ 1/√2: the magnification falls from 1 at ω = 0"
NO_BAND_UNDAMPED = "no half-power band when c = 0: the peak is infinite"
NO_LOWER = "no lower half-power point when ζ ≥ 0.383: the magnification stays above peak/√2 down to ω = 0"

#: Fraction of the undamped (or of the damping-only) magnification within which one term "sets" the amplitude.
CONTROL = 0.9


@dataclass(frozen=True)
class FrequencyStudy:
    """Everything chapter 4 computes, once (SI units; magnifications dimensionless)."""

    scenarios: dict  # scenario_id -> Scenario (the paper's five, from the run's parameters)
    omegas: np.ndarray  # frequency grid of the magnification and phase curves, rad/s
    curves: list  # (case, c, magnification array, phase array in rad) per damping
    bands: list  # one dict per damping: case, c, zeta, regime, Q, peak, band, M at omega_ref/omega_res, inside
    estimates: list  # one dict per damping: zeta from parameters, half-power, log decrement
    t: np.ndarray  # output grid of the resonance case, s
    total: Response  # exact response from rest of the resonance case (s, m, m/s)
    steady: np.ndarray  # its steady state on t, m
    transient: Response  # its transient (free response from what the steady state leaves over), s, m, m/s
    decomposition: dict  # X (m), phase (rad), x_h(0) (m), x_h(t_end) (m), t_s (s)
    energy: list  # (response name, EnergyBalance)
    energy_t: np.ndarray  # times of the energy balances, s
    checks: list  # dicts: check, value (relative difference), tol

    @property
    def omega_n(self) -> float:
        """Natural frequency, rad/s."""
        return self.scenarios["resonance"].oscillator.natural_frequency

    @property
    def resonance(self):
        """The resonance scenario."""
        return self.scenarios["resonance"]


def _band_row(sc, omega_ref: float, omega_res: float) -> dict:
    osc = sc.oscillator
    w_pk, m_pk = resonant_peak(osc)
    lo, hi = half_power_band(osc)
    inside = None if hi is None else bool((lo is None or lo <= omega_res) and omega_res <= hi)

    def mag(w):
        return float(magnification(osc, [w])[0])

    return {
        "case": case_name(sc.scenario_id),
        "c": osc.c,
        "zeta": osc.damping_ratio,
        "regime": osc.regime,
        "Q": osc.quality_factor,
        "omega_peak": w_pk,
        "M_peak": m_pk,
        "lo": lo,
        "hi": hi,
        "M_ref": mag(omega_ref),
        "M_res": mag(omega_res),
        "omega_res": omega_res,
        "omega_ref": omega_ref,
        "inside": inside,
    }


def _estimate_row(sc) -> tuple[dict, list]:
    osc = sc.oscillator
    z, wn = osc.damping_ratio, osc.natural_frequency
    row = {"case": case_name(sc.scenario_id), "c": osc.c, "zeta": z, "hp": None, "ld": None}
    lo, hi = half_power_band(osc)
    if lo is not None:
        w = wn * np.linspace(max(0.0, 1 - 20 * z), 1 + 20 * z, 200001)
        try:
            row["hp"] = half_power_points(w, magnification(osc, w)).damping_ratio
        except ParameterError:  # the lower point closer to 0 than one grid step
            row["hp"] = None
    if 0.0 < z < ZETA_DECREMENT_MAX:
        t_free = 6 * 2 * np.pi / osc.damped_natural_frequency
        decay = simulate(osc, SineForce(0.0, 0.0), t_free, 20001, x0=1.0, method="DOP853", rtol=1e-10, atol=1e-13)
        row["ld"] = log_decrement(decay.t, decay.x)[1]
    checks = [
        {
            "check": f"ζ from the {what}, {row['case']}, against c/(2√(km))",
            "value": abs(row[key] / z - 1),
            "tol": TOL_ESTIMATE,
        }
        for key, what in (("hp", "half-power points"), ("ld", "log decrement"))
        if row[key] is not None
    ]
    return row, checks


def frequency_study(
    m: float,
    k: float,
    F0: float,
    t_end: float,
    omega_ref: float,
    omega_res: float,
    c_low: float,
    c_nominal: float,
    c_high: float,
    n_points: int = 5001,
) -> FrequencyStudy:
    """Compute chapter 4 (all but the design map) from the paper's parameters or a run's.

    Parameters
    ----------
    m, k, F0 : float
        Mass (kg), stiffness (N/m), force amplitude (N).
    t_end : float
        End of the window from rest, s (> 0).
    omega_ref, omega_res : float
        Reference and "resonant" forcing frequencies, rad/s.
    c_low, c_nominal, c_high : float
        Dampings, N s/m (0 undamped, negative self-excited).
    n_points : int
        Samples of the resonance case on ``[0, t_end]``, 1 (the energy balance uses 5 times as many).

    Examples
    --------
    >>> st = frequency_study(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0, n_points=2001)
    >>> round(st.decomposition["X"], 4), all(c["value"] < c["tol"] for c in st.checks)   # m
    (2.2371, True)
    >>> frequency_study(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0, n_points=1)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: n_points = 1 is out of range: allowed ...
    """
    n_points = check_int("n_points", n_points, low=3, high=N_POINTS_MAX // 5)
    scenarios = scenarios_from(m, k, F0, t_end, omega_ref, omega_res, c_low, c_nominal, c_high)
    wn = scenarios["resonance"].oscillator.natural_frequency
    omegas = np.geomspace(wn / 20, wn * 20, 2001)
    curves, bands, estimates, checks = [], [], [], []
    for sid in DAMPING_IDS:
        sc = scenarios[sid]
        osc = sc.oscillator
        curves.append((case_name(sid), osc.c, magnification(osc, omegas), phase_lag(osc, omegas)))
        bands.append(_band_row(sc, omega_ref, omega_res))
        row, chk = _estimate_row(sc)
        estimates.append(row)
        checks += chk
        ss = steady_state(osc, sc.force)
        if math.isfinite(ss.magnification):
            checks.append(
                {
                    "check": f"magnification at ω_res, {case_name(sid)}, against the steady amplitude X/(F0/k)",
                    "value": abs(bands[-1]["M_res"] / ss.magnification - 1),
                    "tol": TOL_CLOSED,
                }
            )
    res = scenarios["resonance"]
    osc, force = res.oscillator, res.force
    t = np.linspace(0.0, t_end, n_points)
    total = exact_response(osc, force, t)
    ss = steady_state(osc, force)
    steady = ss.amplitude * np.sin(force.omega * t - ss.phase)
    a, b = ss.amplitude * math.sin(ss.phase), -force.omega * ss.amplitude * math.cos(ss.phase)
    transient = exact_response(osc, SineForce(0.0, 0.0), t, x0=a, v0=b)
    scale = max(float(np.max(np.abs(total.x))), 1e-300)
    checks.append(
        {
            "check": "exact response from rest against steady state + transient, resonance case",
            "value": float(np.max(np.abs(total.x - steady - transient.x))) / scale,
            "tol": TOL_CLOSED,
        }
    )
    decomposition = {
        "X": ss.amplitude,
        "phase": ss.phase,
        "x0": a,
        "x_end": float(transient.x[-1]),
        "t_s": settling_time(osc, force),
        "t_end": t_end,
        "c": osc.c,
    }
    fine = np.linspace(0.0, t_end, 5 * (n_points - 1) + 1)
    eb_exact = energy_balance(osc, force, exact_response(osc, force, fine))
    eb_paper = energy_balance(osc, force, simulate(osc, force, t_end, fine.size))
    checks.append(
        {
            "check": "energy balance W − D − ΔE on the exact response, resonance case (relative to max W)",
            "value": float(np.max(np.abs(eb_exact.residual)) / np.max(np.abs(eb_exact.work))),
            "tol": TOL_CLOSED,
        }
    )
    return FrequencyStudy(
        scenarios,
        omegas,
        curves,
        bands,
        estimates,
        t,
        total,
        steady,
        transient,
        decomposition,
        [("exact", eb_exact), ("RK45 at SciPy's defaults", eb_paper)],
        fine,
        checks,
    )


# -- figures ---------------------------------------------------------------------------------


def response_curves(study: FrequencyStudy):
    """Magnification and phase of the three dampings, the scenarios' operating points marked."""
    from .plotting import frequency_response_figure

    curves = [(f"{name}: $c$ = {g(c)} N s/m", mag, ph) for name, c, mag, ph in study.curves]
    marks, seen = [], set()
    for sid, sc in study.scenarios.items():
        if sc.oscillator.c < 0:
            continue
        ss = steady_state(sc.oscillator, sc.force)
        key = (sc.force.omega, sc.oscillator.c)
        if key in seen or not math.isfinite(ss.magnification):
            continue
        seen.add(key)
        marks.append((case_name(sid), sc.force.omega, ss.magnification, ss.phase))
    return frequency_response_figure(curves, study.omegas, marks, omega_n=study.omega_n)


def decomposition(study: FrequencyStudy):
    """The resonance case split into its steady state and its transient."""
    from .plotting import decomposition_figure

    c = study.resonance.oscillator.c
    return decomposition_figure(
        study.t,
        study.total.x,
        study.steady,
        study.transient.x,
        rf"Resonance case, $c$ = {g(c)} N s/m: $x$ = steady state + transient",
    )


def energy(study: FrequencyStudy):
    """Work, dissipation and stored energy of the resonance case (exact), with the residual."""
    from .plotting import energy_figure

    c = study.resonance.oscillator.c
    return energy_figure(
        study.energy_t, study.energy[0][1], rf"Energy balance at resonance (exact), $c$ = {g(c)} N s/m"
    )


# -- tables ----------------------------------------------------------------------------------


def _steady_cell(row: dict, key: str):
    if row["c"] < 0:
        return Missing(NO_STEADY)
    return row[key]


def _peak_cell(row: dict, key: str):
    if row["c"] < 0:
        return Missing(NO_STEADY)
    return row[key] if row[key] is not None else Missing(NO_PEAK)


def _band_cell(row: dict, key: str):
    if row["c"] < 0:
        return Missing(NO_STEADY)
    if row["c"] == 0:
        return Missing(NO_BAND_UNDAMPED)
    if row["hi"] is None:
        return Missing(NO_PEAK)
    if row[key] is None:
        return Missing(NO_LOWER)
    return row[key]


def dampings_table(study: FrequencyStudy) -> Table:
    """Per damping: ζ, regime, Q, the resonant peak and the magnification at the two forcing frequencies.

    Examples
    --------
    >>> st = frequency_study(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0, n_points=2001)
    >>> print(repr(dampings_table(st)).splitlines()[-2])
    high damping     15         1.68    overdamped   0.298  —a              —a      0.4317    0.2983
    """
    rows = [
        {
            "case": b["case"],
            "c": b["c"],
            "zeta": b["zeta"],
            "regime": b["regime"],
            "Q": _steady_cell(b, "Q"),
            "wp": _peak_cell(b, "omega_peak"),
            "Mp": _peak_cell(b, "M_peak"),
            "Mref": _steady_cell(b, "M_ref"),
            "Mres": _steady_cell(b, "M_res"),
        }
        for b in study.bands
    ]
    b0 = study.bands[0]
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("c", "c (N s/m)", 3),
            Column("zeta", "ζ", 3),
            Column("regime", "regime"),
            Column("Q", "Q", 3),
            Column("wp", "ω_peak (rad/s)", 4),
            Column("Mp", "M_peak", 4),
            Column("Mref", "M(ω_ref)", 4),
            Column("Mres", "M(ω_res)", 4),
        ],
        caption=(
            "The three dampings: damping ratio ζ, regime, quality factor Q = 1/(2ζ), the peak of the "
            f"magnification M = |X|/(F0/k) and its value at ω_ref = {g(b0['omega_ref'])} rad/s and "
            f"ω_res = {g(b0['omega_res'])} rad/s."
        ),
        name="tab-frequency-dampings",
    )


def band_table(study: FrequencyStudy) -> Table:
    """Per damping: the exact half-power band of the displacement and whether ω_res lies in it.

    Examples
    --------
    >>> st = frequency_study(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0, n_points=2001)
    >>> print(repr(band_table(st)).splitlines()[3])
    low damping      4.421        4.521        0.1                0.1          yes
    """
    rows = []
    for b in study.bands:
        lo, hi = _band_cell(b, "lo"), _band_cell(b, "hi")
        width = hi - (lo if isinstance(lo, float) else 0.0) if isinstance(hi, float) else hi
        if isinstance(hi, float) and not isinstance(lo, float):
            width = Missing(NO_LOWER)
        rows.append(
            {
                "case": b["case"],
                "lo": lo,
                "hi": hi,
                "width": width,
                "cm": b["c"] / study.resonance.oscillator.m if b["c"] >= 0 else Missing(NO_STEADY),
                "inside": b["inside"] if b["inside"] is not None else _band_cell(b, "hi"),
            }
        )
    w = study.bands[0]["omega_res"]
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("lo", "ω_1 (rad/s)", 4),
            Column("hi", "ω_2 (rad/s)", 4),
            Column("width", "ω_2 − ω_1 (rad/s)", 3),
            Column("cm", "c/m (rad/s)", 3),
            Column("inside", f"ω_res = {g(w)} rad/s in band"),
        ],
        caption=(
            "Exact half-power band of the displacement: the frequencies ω_1 < ω_2 where the magnification is "
            "its peak over √2, its width beside the light-damping estimate c/m, and whether the paper's "
            "resonant forcing frequency ω_res lies inside it."
        ),
        name="tab-frequency-band",
    )


def estimates_table(study: FrequencyStudy) -> Table:
    """The damping ratio three ways: from the parameters, the half-power points, the log decrement."""
    rows = []
    for e in study.estimates:
        z = e["zeta"]
        if z <= 0:
            hp = ld = Missing("no decay and no finite peak to measure when c ≤ 0")
        else:
            hp = e["hp"] if e["hp"] is not None else Missing(NO_PEAK if z >= 2**-0.5 else NO_LOWER)
            ld = (
                e["ld"]
                if e["ld"] is not None
                else Missing(
                    "no oscillation to measure when ζ ≥ 1"
                    if z >= 1
                    else f"fitted only for ζ < {g(ZETA_DECREMENT_MAX)} (faster decays leave too few clean peaks)"
                )
            )
        rows.append({"case": e["case"], "zeta": z, "hp": hp, "ld": ld})
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("zeta", "ζ = c/(2√(km))", 4),
            Column("hp", "ζ from half-power points", 4),
            Column("ld", "ζ from log decrement", 4),
        ],
        caption=(
            "The damping ratio three independent ways: from the parameters, from the exact half-power relation "
            "on the computed magnification curve, and from the logarithmic decrement of a free decay integrated "
            "by DOP853. Their differences are in the checks table."
        ),
        name="tab-frequency-estimates",
    )


def decomposition_table(study: FrequencyStudy) -> Table:
    """The resonance case: steady amplitude and phase, transient at the start and the end, settling time."""
    d = study.decomposition
    ts = d["t_s"] if math.isfinite(d["t_s"]) else Missing("the transient never decays when c ≤ 0")
    row = {"X": d["X"], "phase": d["phase"], "x0": d["x0"], "x_end": d["x_end"], "ts": ts}
    return Table(
        [row],
        [
            Column("X", "X (m)", 4),
            Column("phase", "φ (rad)", 4),
            Column("x0", "x_h(0) (m)", 4),
            Column("x_end", "x_h(t_end) (m)", 3),
            Column("ts", "t_s (s)", 3),
        ],
        caption=(
            f"The resonance case (c = {g(d['c'])} N s/m) from rest: steady amplitude X and phase lag φ, the "
            f"transient x_h = x − x_ss at t = 0 and at t_end = {g(d['t_end'])} s, and the 2 % settling time t_s."
        ),
        name="tab-frequency-decomposition",
    )


def energy_table(study: FrequencyStudy) -> Table:
    """Work, dissipation, stored energy at t_end and the worst residual, exact and by RK45."""
    rows = []
    for name, eb in study.energy:
        rel = float(np.max(np.abs(eb.residual)) / np.max(np.abs(eb.work)))
        rows.append(
            {
                "response": name,
                "W": float(eb.work[-1]),
                "D": float(eb.dissipated[-1]),
                "E": float(eb.stored[-1]),
                "res": at_least(rel, TOL_CLOSED) if name == "exact" else rel,
            }
        )
    return Table(
        rows,
        [
            Column("response", "response"),
            Column("W", "W (J)", 5),
            Column("D", "D (J)", 5),
            Column("E", "ΔE (J)", 4),
            Column("res", "max |W − D − ΔE| / max W", 3),
        ],
        caption=(
            f"Energy of the resonance case at t_end = {g(study.decomposition['t_end'])} s: work of the force W, "
            "energy dissipated by the damper D, change of stored energy ΔE, and the worst residual of "
            "W = D + ΔE over the window (quadrature level on the exact response, printed as a bound)."
        ),
        name="tab-frequency-energy",
    )


def checks_table(study: FrequencyStudy, design=None) -> Table:
    """Differences at rounding level, printed as bounds: the self-checks of the chapter.

    Examples
    --------
    >>> st = frequency_study(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0, n_points=2001)
    >>> print(repr(checks_table(st)).splitlines()[3])
    ζ from the half-power points, low damping, against c/(2√(km))                        < 1e-7               yes
    """
    checks = list(study.checks) + (list(design.checks) if design is not None else [])
    rows = [
        {"check": c["check"], "value": at_least(c["value"], c["tol"]), "ok": bool(c["value"] < c["tol"])}
        for c in checks
    ]
    return Table(
        rows,
        [Column("check", "check"), Column("value", "relative difference", 3), Column("ok", "within bound")],
        caption="Self-checks of the chapter: independent routes to the same quantity, with their relative differences.",
        name="tab-frequency-checks",
    )


# -- design map ------------------------------------------------------------------------------


@dataclass(frozen=True)
class DesignMap:
    """Peak |x| in the window from rest over a grid of forcing frequency and damping."""

    omegas: np.ndarray  # rad/s
    dampings: np.ndarray  # N s/m
    peaks: np.ndarray  # m, indexed [damping, omega]
    at_res: list  # (case, c, peak at omega_res by the map's kernel) for the three dampings
    checks: list


def design_map(
    study: FrequencyStudy, omega_max: float, n_omega: int, c_min: float, c_max: float, n_damping: int
) -> DesignMap:
    """Evaluate the window's peak |x| on ``n_damping`` x ``n_omega`` (c, ω) pairs.

    Parameters
    ----------
    study : FrequencyStudy
        Gives m, k, F0, t_end, ω_res, the dampings and the sample count.
    omega_max : float
        Upper forcing frequency, rad/s (> 0); the grid is ``linspace(omega_max / n_omega, omega_max, n_omega)``.
    n_omega, n_damping : int
        Grid sizes, 1 (2 to 2000).
    c_min, c_max : float
        Damping range, N s/m (0 < c_min < c_max), geometric.

    Examples
    --------
    >>> st = frequency_study(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0, n_points=2001)
    >>> dm = design_map(st, 10.0, 20, 0.01, 20.0, 10)
    >>> dm.peaks.shape, [round(p, 3) for _, _, p in dm.at_res]     # m
    ((10, 20), [10.251, 2.237, 0.105])
    >>> design_map(st, 10.0, 20, 0.0, 20.0, 10)
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: c_min = 0.0 N s/m is out of range: allowed c_min > 0 N s/m, finite
    """
    n_omega = check_int("n_omega", n_omega, low=2, high=2000)
    n_damping = check_int("n_damping", n_damping, low=2, high=2000)
    omega_max = check_real("omega_max", omega_max, low=0.0, low_open=True, unit="rad/s")
    c_min = check_real("c_min", c_min, low=0.0, low_open=True, unit="N s/m")
    c_max = check_real("c_max", c_max, low=c_min, low_open=True, unit="N s/m")
    res = study.resonance
    osc = res.oscillator
    m, k, F0, t_end, n = osc.m, osc.k, res.force.F0, res.t_end, study.t.size
    omegas = np.linspace(omega_max / n_omega, omega_max, n_omega)
    dampings = np.geomspace(c_min, c_max, n_damping)
    peaks = peak_displacement_map(m, k, F0, omegas, dampings, t_end, n)
    cs = [study.scenarios[s].oscillator.c for s in DAMPING_IDS]
    at = peak_displacement_map(m, k, F0, [res.force.omega], cs, t_end, n)[:, 0]
    direct = [float(np.max(np.abs(exact_response(Oscillator(m, c, k), res.force, study.t).x))) for c in cs]
    checks = [
        {
            "check": f"design-map kernel against the exact response at ω_res, {case_name(s)}",
            "value": abs(a / d - 1) if d > 0 else abs(a - d),
            "tol": TOL_CLOSED,
        }
        for s, a, d in zip(DAMPING_IDS, at, direct, strict=True)
    ]
    at_res = [(case_name(s), c, float(p)) for s, c, p in zip(DAMPING_IDS, cs, at, strict=True)]
    return DesignMap(omegas, dampings, peaks, at_res, checks)


def design_figure(study: FrequencyStudy, dm: DesignMap):
    """Heat map of the design map with the paper's scenarios marked (those with c in the map's range)."""
    from .plotting import design_map_figure

    marks, seen = [], set()
    for sid, sc in study.scenarios.items():
        key = (sc.force.omega, sc.oscillator.c)
        c = sc.oscillator.c
        if key in seen or not (dm.dampings[0] <= c <= dm.dampings[-1]) or sc.force.omega > dm.omegas[-1]:
            continue
        seen.add(key)
        marks.append((case_name(sid), sc.force.omega, c))
    return design_map_figure(dm.omegas, dm.dampings, dm.peaks, marks, omega_n=study.omega_n)


def design_table(study: FrequencyStudy, dm: DesignMap) -> Table:
    """The grid's largest peak and the three dampings at ω_res."""
    i, j = np.unravel_index(np.argmax(dm.peaks), dm.peaks.shape)
    w = study.resonance.force.omega
    rows = [
        {
            "point": "largest on the grid",
            "omega": float(dm.omegas[j]),
            "c": float(dm.dampings[i]),
            "peak": float(dm.peaks[i, j]),
        }
    ]
    rows += [{"point": f"{name} at ω_res", "omega": w, "c": c, "peak": p} for name, c, p in dm.at_res]
    return Table(
        rows,
        [
            Column("point", "point"),
            Column("omega", "ω (rad/s)", 4),
            Column("c", "c (N s/m)", 3),
            Column("peak", "peak |x| (m)", 5),
        ],
        caption=(
            f"Largest |x| in the window [0, {g(study.decomposition['t_end'])}] s from rest: the largest on the "
            f"{dm.dampings.size} × {dm.omegas.size} grid, and the paper's three dampings at ω_res."
        ),
        name="tab-frequency-design",
    )


# -- sentences -------------------------------------------------------------------------------


def band_text(study: FrequencyStudy) -> str:
    """Per damping: regime, half-power band, and whether ω_res is inside or outside it."""
    lines = []
    for sid, b in zip(DAMPING_IDS, study.bands, strict=True):
        sc = study.scenarios[sid]
        head = f"**{b['case']}** (c = {g(b['c'])} N s/m): {regime_clause(sc.oscillator)}"
        w = f"ω_res = {g(b['omega_res'])} rad/s"
        if b["c"] < 0:
            tail = "no steady state and no half-power band: the response at any frequency grows."
        elif b["c"] == 0:
            tail = f"the peak is infinite at ω_n = {g(study.omega_n)} rad/s, so there is no half-power band."
        elif b["hi"] is None:
            tail = (
                f"no resonant peak and so no half-power band; at {w} the steady amplitude is "
                f"{g(b['M_res'], 3)} times the static deflection."
            )
        else:
            where = "inside" if b["inside"] else "outside"
            band = f"from {g(b['lo'])} to {g(b['hi'])} rad/s" if b["lo"] is not None else f"up to {g(b['hi'])} rad/s"
            tail = (
                f"half-power band {band}; {w} is **{where} the half-power band**, where the steady amplitude is "
                f"{g(b['M_res'], 3)} times the static deflection "
                f"(peak {g(b['M_peak'], 3)} at {g(b['omega_peak'])} rad/s)."
            )
        lines.append(f"- {head}; {tail}")
    return "\n".join(lines)


def _what_sets(osc: Oscillator, w: float) -> str:
    """Which term sets the steady amplitude at ``w``: stiffness and mass, damping, or both."""
    r = w / osc.natural_frequency
    M = float(magnification(osc, [w])[0])
    undamped = 1.0 / abs(1.0 - r * r) if r != 1.0 else math.inf
    damping_only = 1.0 / (2.0 * osc.damping_ratio * r) if osc.c > 0 else math.inf
    if M >= CONTROL * undamped:
        return (
            f"ω/ω_n = {g(r, 3)}: M = {g(M, 4)}, within {g(100 * (1 - M / undamped), 2)} % of the undamped "
            f"1/|1 − r²| = {g(undamped, 4)}, so stiffness and mass set the amplitude and damping hardly matters"
        )
    if M >= CONTROL * damping_only:
        return (
            f"ω/ω_n = {g(r, 4)}: M = {g(M, 4)}, within {g(100 * (1 - M / damping_only), 2)} % of "
            f"1/(2ζr) = {g(damping_only, 4)}, so damping sets the amplitude (X ≈ F0/(cω))"
        )
    return (
        f"ω/ω_n = {g(r, 3)}: M = {g(M, 4)}, against {g(undamped, 4)} undamped and {g(damping_only, 4)} from "
        "damping alone, so stiffness, mass and damping all matter"
    )


def control_text(study: FrequencyStudy) -> str:
    """What sets the steady amplitude at ω_ref and ω_res, for the nominal damping."""
    sc = study.scenarios["damping_nominal"]
    osc = sc.oscillator
    if osc.c <= 0:
        return (
            f"With the nominal damping c = {g(osc.c)} N s/m there is no finite steady amplitude to attribute "
            "at resonance; the other dampings are in the tables above."
        )
    ref, res = study.scenarios["reference"].force.omega, sc.force.omega
    return (
        f"For the nominal damping (c = {g(osc.c)} N s/m): at ω_ref = {g(ref)} rad/s, {_what_sets(osc, ref)}; at "
        f"ω_res = {g(res)} rad/s, {_what_sets(osc, res)}."
    )


def estimates_text(study: FrequencyStudy) -> str:
    """Whether the three damping-ratio estimates agree (from the checks), and which do not exist."""
    est = [c for c in study.checks if c["check"].startswith("ζ from")]
    worst = max((c["value"] for c in est), default=None)
    missing = [e["case"] for e in study.estimates if e["hp"] is None or e["ld"] is None]
    text = (
        f"Where they exist, the three estimates agree to better than {g(TOL_ESTIMATE)} in relative terms."
        if worst is not None and worst < TOL_ESTIMATE
        else (
            f"The estimates differ by up to {g(worst, 2)} in relative terms."
            if worst is not None
            else "No damping here has a peak and a decay to estimate from."
        )
    )
    if missing:
        text += (
            " "
            + ", ".join(f"**{m}**" for m in missing)
            + " lacks a peak or a clean decay for some estimates (footnotes)."
        )
    return text


def design_text(study: FrequencyStudy, dm: DesignMap) -> str:
    """How narrow the dangerous band is at the lowest damping of the grid, and how flat the highest is."""
    i, j = np.unravel_index(np.argmax(dm.peaks), dm.peaks.shape)
    low, high = dm.peaks[0], dm.peaks[-1]
    above = dm.omegas[low >= 0.5 * low.max()]
    wn = study.omega_n
    return (
        f"The largest peak on the grid is {g(dm.peaks[i, j])} m, at ω = {g(dm.omegas[j])} rad/s and "
        f"c = {g(dm.dampings[i], 3)} N s/m. At the lowest damping of the grid (c = {g(dm.dampings[0], 3)} N s/m) the "
        f"peak exceeds half its largest value only for ω from {g(above.min())} to {g(above.max())} rad/s "
        f"({g(100 * (above.max() - above.min()) / wn, 2)} % of ω_n wide on this grid); at the highest "
        f"(c = {g(dm.dampings[-1], 3)} N s/m) the peaks over ω stay within a factor "
        f"{g(high.max() / high.min(), 3)} of each other."
    )


def frequency_summary(study: FrequencyStudy, dm: DesignMap) -> str:
    """The bullets of chapter 4's summary."""

    def names(which):
        cases = [f"**{b['case']}**" for b in study.bands if b["inside"] is which]
        listed = " and ".join([", ".join(cases[:-1]), cases[-1]] if len(cases) > 1 else cases)
        return f"{listed} {'cases' if len(cases) > 1 else 'case'}" if cases else ""

    def have(which):
        return "have" if sum(b["inside"] is which for b in study.bands) > 1 else "has"

    w = f"ω_res = {g(study.resonance.force.omega)} rad/s"
    band = []
    if names(True):
        band.append(f"{w} lies inside the half-power band of the {names(True)}")
    if names(False):
        band.append(f"{w} lies outside the half-power band of the {names(False)}")
    if names(None):
        band.append(f"the {names(None)} {have(None)} no half-power band")
    eb = {name: eb for name, eb in study.energy}
    paper = next(v for k, v in eb.items() if k != "exact")
    rel = float(np.max(np.abs(paper.residual)) / np.max(np.abs(paper.work)))
    bullets = [
        "; ".join(band) + ".",
        control_text(study),
        estimates_text(study),
        f"The energy balance closes on the exact response to quadrature level; on the paper's RK45 output its "
        f"residual reaches {g(100 * rel, 2)} % of the work, the integrator's error made visible.",
        design_text(study, dm),
    ]
    return "\n".join("- " + b for b in bullets)
