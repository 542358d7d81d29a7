"""Chapter 4's tables, each a function of one :class:`FrequencyStudy`.

A quantity that does not exist for a damping (no peak when ζ ≥ 1/√2, no steady state when c ≤ 0)
is a :class:`~vibration.book.presentation.tables.Missing` cell with its reason as a footnote; differences
at rounding level print as bounds.

Examples
--------
>>> from vibration.book.chapters.frequency_response.study import frequency_response_study
>>> st = frequency_response_study(n_points=2001, n_omega=20, n_damping=10)
>>> print(repr(dampings_table(st)).splitlines()[-2])
c = 15 N s/m   15.0       1.68    overdamped   0.298  —a              —a      0.4317    0.2983
>>> print(repr(band_table(st)).splitlines()[3])
c = 0.1 N s/m  4.421        4.521        0.100              0.100        yes
"""

from __future__ import annotations

import math

from vibration.book.chapters.frequency_response.study import TOL_CLOSED, ZETA_DECREMENT_MAX, DampingCase, FrequencyStudy
from vibration.book.presentation.findings import NO_STEADY, at_least
from vibration.book.presentation.narrative import g
from vibration.book.presentation.tables import Missing, Table, columns, self_checks

NO_PEAK = "no resonant peak when ζ ≥ 1/√2: the magnification falls from 1 at ω = 0"
NO_BAND_UNDAMPED = "no half-power band when c = 0: the peak is infinite"
NO_LOWER = "no lower half-power point when ζ ≥ 0.383: the magnification stays above peak/√2 down to ω = 0"
NO_DECAY = "no decay and no finite peak to measure when c ≤ 0"


def _steady(c: DampingCase, value):
    return value if c.steady else Missing(reason=NO_STEADY)


def _peak(c: DampingCase, value):
    if not c.steady:
        return Missing(reason=NO_STEADY)
    return value if value is not None else Missing(reason=NO_PEAK)


def _band(c: DampingCase, value):
    if not c.steady:
        return Missing(reason=NO_STEADY)
    if c.c == 0:
        return Missing(reason=NO_BAND_UNDAMPED)
    if c.hi is None:
        return Missing(reason=NO_PEAK)
    return value if value is not None else Missing(reason=NO_LOWER)


def dampings_table(study: FrequencyStudy) -> Table:
    """Per damping: ζ, regime, Q, the resonant peak and the magnification at the two forcing frequencies."""
    rows = [
        {
            "case": c.name,
            "c": c.c,
            "zeta": c.zeta,
            "regime": c.regime,
            "Q": _steady(c, c.osc.quality_factor),
            "wp": _peak(c, c.omega_peak),
            "Mp": _peak(c, c.M_peak),
            "Mref": _steady(c, c.M_ref),
            "Mres": _steady(c, c.M_res),
        }
        for c in study.cases
    ]
    p = study.params
    return Table(
        rows=rows,
        columns=columns(
            """
            case    case
            c       c (N s/m)       3
            zeta    ζ               3
            regime  regime
            Q       Q               3
            wp      ω_peak (rad/s)  4
            Mp      M_peak          4
            Mref    M(ω_ref)        4
            Mres    M(ω_res)        4
            """
        ),
        caption=(
            "The dampings compared: damping ratio ζ, regime, quality factor Q = 1/(2ζ), the peak of the "
            f"magnification M = |X|/(F_0/k) and its value at ω_ref = {g(p.omega_ref)} rad/s and "
            f"ω_res = {g(p.omega_res)} rad/s."
        ),
        name="tab-frequency-dampings",
    )


def band_table(study: FrequencyStudy) -> Table:
    """Per damping: the exact half-power band of the displacement and whether ω_res lies in it."""
    rows = []
    for c in study.cases:
        lo, hi = _band(c, c.lo), _band(c, c.hi)
        if isinstance(hi, Missing):
            width = hi
        elif isinstance(lo, Missing):
            width = Missing(reason=NO_LOWER)
        else:
            width = hi - lo
        rows.append(
            {
                "case": c.name,
                "lo": lo,
                "hi": hi,
                "width": width,
                "cm": c.c / c.osc.m if c.c >= 0 else Missing(reason=NO_STEADY),
                "inside": c.inside if c.inside is not None else hi,
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            f"""
            case    case
            lo      ω_1 (rad/s)                                        4
            hi      ω_2 (rad/s)                                        4
            width   ω_2 − ω_1 (rad/s)                                  3
            cm      c/m (rad/s)                                        3
            inside  ω_res = {g(study.params.omega_res)} rad/s in band
            """
        ),
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
    for c in study.cases:
        z = c.zeta
        if z <= 0:
            hp = ld = Missing(reason=NO_DECAY)
        else:
            hp = c.zeta_hp if c.zeta_hp is not None else Missing(reason=NO_PEAK if z >= 2**-0.5 else NO_LOWER)
            ld = (
                c.zeta_ld
                if c.zeta_ld is not None
                else Missing(
                    reason="no oscillation to measure when ζ ≥ 1"
                    if z >= 1
                    else f"fitted only for ζ < {g(ZETA_DECREMENT_MAX)} (faster decays leave too few clean peaks)"
                )
            )
        rows.append({"case": c.name, "zeta": z, "hp": hp, "ld": ld})
    return Table(
        rows=rows,
        columns=columns(
            """
            case  case
            zeta  ζ = c/(2√(km))            4
            hp    ζ from half-power points  4
            ld    ζ from log decrement      4
            """
        ),
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
    ts = d.t_s if math.isfinite(d.t_s) else Missing(reason="the transient never decays when c ≤ 0")
    row = {"X": d.X, "phase": d.phase, "x0": d.x_h0, "x_end": d.x_h_end, "ts": ts}
    return Table(
        rows=[row],
        columns=columns(
            """
            X      X (m)           4
            phase  φ (rad)         4
            x0     x_h(0) (m)      4
            x_end  x_h(t_end) (m)  3
            ts     t_s (s)         3
            """
        ),
        caption=(
            f"The resonance case (c = {g(study.resonance.oscillator.c)} N s/m) from rest: steady amplitude X and "
            "phase lag φ, the transient x_h = x − x_ss at t = 0 and at the end of the window, "
            f"t_end = {g(study.params.t_end)} s, and the 2 % settling time t_s."
        ),
        name="tab-frequency-decomposition",
    )


def energy_table(study: FrequencyStudy) -> Table:
    """Work, dissipation, stored energy at the end of the window and the worst residual, exact and by RK45."""
    rows = []
    for i, (name, eb) in enumerate(study.energy):
        rel = study.energy_residual(i)
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
        rows=rows,
        columns=columns(
            """
            response  response
            W         W (J)                     5
            D         D (J)                     5
            E         ΔE (J)                    5
            res       max |W − D − ΔE| / max W  3
            """
        ),
        caption=(
            f"Energy of the resonance case at t_end = {g(study.params.t_end)} s: work of the force W, energy "
            "dissipated by the damper D, change of stored energy ΔE, and the worst residual of W = D + ΔE over the "
            "window (quadrature level on the exact response, printed as a bound)."
        ),
        name="tab-frequency-energy",
    )


def checks_table(study: FrequencyStudy) -> Table:
    """Differences at rounding level, printed as bounds: the self-checks of the chapter."""
    return self_checks(
        ((c.check, at_least(c.value, c.tol), c.ok) for c in study.checks),
        caption="Self-checks of the chapter: independent routes to the same quantity, with their relative differences.",
        name="tab-frequency-checks",
        headers=("check", "relative difference", "within bound"),
        digits=3,
    )


def design_table(study: FrequencyStudy) -> Table:
    """The grid's largest peak and the three dampings at ω_res."""
    dm = study.design
    w, c, peak = dm.largest
    rows = [{"point": "largest on the grid", "omega": w, "c": c, "peak": peak}]
    rows += [
        {"point": f"{case.name} at the resonant forcing", "omega": study.params.omega_res, "c": case.c, "peak": p}
        for case, p in zip(study.cases, dm.at_res, strict=True)
    ]
    return Table(
        rows=rows,
        columns=columns(
            """
            point  point
            omega  ω (rad/s)     4
            c      c (N s/m)     3
            peak   peak |x| (m)  4
            """
        ),
        caption=(
            f"Largest |x| in the window [0, {g(study.params.t_end)}] s from rest: the largest on the "
            f"{dm.dampings.size} × {dm.omegas.size} grid, and the paper's three dampings at ω_res."
        ),
        name="tab-frequency-design",
    )
