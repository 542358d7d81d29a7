r"""The chapter's sentences, the key-results box and the designer's summary, from a :class:`ControlStudy`.

Every comparison word ("cuts" or "raises", "shorter" or "longer", "can" or "cannot") is chosen from
the study's numbers, so a run with other parameters says what its own tables say. Symbols are
typeset as Markdown maths (``$\omega_n$``); numbers go through
:func:`~vibration.book.chapters.control.notation.num` (×10ⁿ, never e-notation).
"""

from __future__ import annotations

import math

from vibration.book.chapters.control.notation import LABELS, cell, num, pct, signed_pct
from vibration.book.chapters.control.study import (
    FEASIBLE_FRACTION,
    SHAPER_LEVEL,
    ActiveStudy,
    ControlStudy,
)
from vibration.book.presentation.tables import cross_reference

#: The chapter's three active designs (the PD with the PID's gains is a comparison, not a design).
ACTIVE = ("PD", "LQR", "PID")
#: A forcing within this relative distance of the natural frequency is called resonant.
RESONANT = 0.05
#: Two steady amplitudes within this relative difference are called the same.
SAME = 0.01
#: A move has settled when its steady mean error is below this fraction of the set point.
SETTLED = 1e-3
#: A design that uses less than this fraction above the least force for its amplitude wastes none.
WASTE = 0.1


# ----------------------------------------------------------------------------- verdicts


def forcing_phrase(a: ActiveStudy) -> str:
    r"""Where the forcing sits: "at resonance" only when it is within :data:`RESONANT` of $\omega_n$."""
    w = num(a.force.omega)
    if abs(a.forcing_ratio - 1.0) <= RESONANT:
        return f"at resonance ($\\omega$ = {w} rad/s, {cell(a.forcing_ratio)} $\\omega_n$)"
    side = "below" if a.forcing_ratio < 1.0 else "above"
    return f"at $\\omega$ = {w} rad/s ({cell(a.forcing_ratio)} $\\omega_n$, {side} resonance)"


def ranked_designs(a: ActiveStudy) -> list[str]:
    """The three active designs from the smallest steady amplitude to the largest."""
    return sorted(ACTIVE, key=lambda n: a.designs[n].amplitude)


def delay_ranking(a: ActiveStudy) -> list[str]:
    """The three active designs from the shortest tolerated loop delay to the longest."""
    return sorted(ACTIVE, key=lambda n: a.designs[n].costs.delay_margin)


def settled(a: ActiveStudy) -> bool:
    """Did the force-limited PID move with clamping settle: never at the limit in steady state, mean error tiny?"""
    cl = a.moves["clamping"]
    return cl.saturated_ss == 0.0 and abs(cl.mean_error) < SETTLED * max(abs(a.x_ref), 1e-300)


def force_excess(a: ActiveStudy) -> tuple[str, float]:
    """The design whose steady RMS force exceeds the least force for its amplitude the most, and by what factor."""
    ratios = {n: d.u_rms / d.floor for n, d in a.designs.items() if math.isfinite(d.u_rms) and d.floor > 0}
    worst = max(ratios, key=ratios.get)
    return worst, ratios[worst]


def _margin(x: float) -> str:
    """A delay margin in parentheses: seconds, or "any delay" when the loop gain never reaches 1."""
    return f"{num(x)} s" if math.isfinite(x) else "any delay: its loop gain never reaches 1"


def _delay(x: float) -> str:
    """A delay margin for a sentence: seconds, or unbounded when the loop gain never reaches 1."""
    return f"up to {num(x)} s" if math.isfinite(x) else "any length (its loop gain never reaches 1)"


def _than(x: float, y: float, smaller: str, larger: str) -> str:
    return smaller if x < y else larger if x > y else "equal to"


def _ratio_words(before: float, after: float) -> str:
    """'n times smaller' or 'n times larger' for after against before."""
    if after <= 0.0:
        return "to zero"
    r = before / after
    return f"{num(r)} times smaller" if r >= 1.0 else f"{num(1.0 / r)} times larger"


# ----------------------------------------------------------------------------- the opening


def key_results(study: ControlStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    return "\n".join(["> **Key results**", ">"] + [f"> * {s}" for s in key_findings(study)])


def key_findings(study: ControlStudy) -> list[str]:
    """Four to five computed sentences: the best design, its robustness, the set point, semi-active, shaping."""
    a, s, sh = study.active, study.semi, study.shaping
    best = ranked_designs(a)[0]
    X, Xp = a.designs[best].amplitude, a.passive_amplitude
    order = delay_ranking(a)
    h = a.hold
    cl = a.moves["clamping"]
    if not h.feasible:
        move = f"holding it needs $k|x_\\mathrm{{ref}}| + F_0$ = {num(h.needed)} N, so it cannot settle"
    elif settled(a):
        move = f"holding it needs {num(h.needed)} N, within the limit, and the run with clamping settles"
    else:
        move = (
            f"holding it needs {num(h.needed)} N, within the limit, yet the run with clamping spends "
            f"{pct(cl.saturated_ss, 2)} of the steady state at the limit"
        )
    t = s.findings.t_res
    if t["clipped"] < 1.0:
        iso = "below 1, where every passive damper transmits more than 1"
    elif t["clipped"] < min(t["soft"], t["firm"]):
        iso = f"more than 1 but less than either passive setting ({num(t['firm'])} and {num(t['soft'])})"
    else:
        iso = f"more than the firm passive setting's {num(t['firm'])}"
    limited = a.metrics["PID"].peak_x_ss
    limit = (
        f"; with its ±{num(a.u_max)} N force limit the PID holds {num(limited)} m"
        if best == "PID" and abs(limited / a.designs["PID"].amplitude - 1.0) > SAME
        else ""
    )
    return [
        f"Without a force limit, the **{LABELS[best]}** holds the smallest steady amplitude of the three active "
        f"designs {forcing_phrase(a)}: {num(X)} m, {_ratio_words(Xp, X)} than the {num(Xp)} m of the uncontrolled "
        f"plant{limit}.",
        f"Robustness to loop delay runs the other way round from stiffness: the **{LABELS[order[0]]}** tolerates the "
        f"shortest delay ({_margin(a.designs[order[0]].costs.delay_margin)}), the **{LABELS[order[-1]]}** the longest "
        f"({_margin(a.designs[order[-1]].costs.delay_margin)})."
        if order[0] == best
        else f"The **{LABELS[order[0]]}** tolerates the shortest loop delay "
        f"({_margin(a.designs[order[0]].costs.delay_margin)}), the **{LABELS[order[-1]]}** the longest "
        f"({_margin(a.designs[order[-1]].costs.delay_margin)}).",
        f"A PID move to $x_\\mathrm{{ref}}$ = {num(a.x_ref)} m with a ±{num(a.u_max)} N actuator: {move}.",
        "A clipped-skyhook damper, which needs power only to set its valve, never to drive the mass, transmits "
        f"{num(t['clipped'])} of the base motion at "
        f"$\\omega_n$: {iso}.",
        f"With the model's $\\omega_n$ {signed_pct(sh.freq_error)} off, a ZVD-shaped move keeps "
        f"{pct(sh.residual['ZVD'])} of the unshaped ringing (ZV: {pct(sh.residual['ZV'])}) and arrives "
        f"{num(sh.shapers['ZVD'].duration)} s later.",
    ]


# ----------------------------------------------------------------------------- active


def comparison_sentence(study: ControlStudy) -> str:
    """The PID against the PD with its own gains, how its gains were chosen, and what stiffness costs."""
    a = study.active
    X = {n: d.amplitude for n, d in a.designs.items()}
    pid, pd = a.designs["PID"], a.designs["PD"]
    pp = a.pid_poles
    if math.isfinite(pp.pair_omega):
        radii_equal = abs(abs(pp.real_pole) / pp.pair_omega - 1.0) < 1e-3
        poles = (
            f"The PID's gains place its three closed-loop poles, the roots of "
            f"$m s^3 + (c + K_D) s^2 + (k + K_P) s + K_I$, at s = {num(pp.real_pole, 4)} 1/s and a pair with "
            f"natural frequency {num(pp.pair_omega, 4)} rad/s and damping ratio {num(pp.pair_zeta)}"
            + (
                f": a pole placement with every pole {num(pp.pair_omega, 4)} rad/s from the origin. "
                if radii_equal
                else ". "
            )
        )
    else:
        poles = "The PID's gains give three real closed-loop poles. "
    integ = (
        f"A PD with the PID's $K_P$ = {num(pid.kx, 4)} N/m and $K_D$ = {num(pid.kv, 4)} N s/m and no integrator "
        f"holds X = {num(X['PD2'])} m against the PID's {num(X['PID'])} m: at this frequency the integral term "
        + ("costs amplitude, it does not buy it" if X["PD2"] < X["PID"] else "buys amplitude")
    )
    if X["PD2"] < X["PD"]:
        stiff = f"$k + K_P$ = {num(a.osc.k + pid.kx, 4)} N/m against {num(a.osc.k + pd.kx, 4)} N/m"
        integ += (
            f". The PID's advantage over the PD (X = {num(X['PD'])} m) is its stiffness, {stiff}, not its integral "
            "action"
            if X["PD2"] < X["PID"]
            else f". Most of the PID's advantage over the PD (X = {num(X['PD'])} m) is its stiffness, {stiff}; the "
            "integrator adds the rest"
        )
    dm = {n: a.designs[n].costs.delay_margin for n in ACTIVE}
    bn = {n: a.designs[n].costs.noise_bandwidth for n in ACTIVE}
    cost = (
        f". Loop delay and sensor noise: the PID tolerates a loop delay of {_delay(dm['PID'])}, "
        f"{_than(dm['PID'], dm['PD'], 'less than', 'more than')} the PD ({_margin(dm['PD'])}) and "
        f"{_than(dm['PID'], dm['LQR'], 'less than', 'more than')} the LQR ({_margin(dm['LQR'])}); position-sensor "
        f"noise reaches the mass through a noise bandwidth of {num(bn['PID'])} rad/s, "
        f"{_than(bn['PID'], bn['PD'], 'narrower than', 'wider than')} the PD's {num(bn['PD'])} rad/s, and the force "
        f"it causes at high frequency grows with $K_D$, {num(pid.kv / max(pd.kv, 1e-300))} times the PD's."
    )
    worst, ratio = force_excess(a)
    force = (
        f" No design wastes force: each uses at most {pct(ratio - 1.0, 2)} more than the least RMS force that can "
        f"hold its amplitude ({cross_reference('tab-control-costs')})."
        if ratio < 1.0 + WASTE
        else f" The {LABELS[worst]} spends {num(ratio)} times the least RMS force that could hold its amplitude "
        f"({cross_reference('tab-control-costs')}): force the disturbance does not require."
    )
    return poles + integ + cost + force


def active_sentences(study: ControlStudy) -> str:
    """What the runs from rest found: steady RMS displacement and force per design, the PID's limit."""
    a = study.active
    mp = a.metrics["passive"]
    parts = []
    for name in ACTIVE:
        mt = a.metrics[name]
        verb = "falls" if mt.rms_x_ss < mp.rms_x_ss else "rises"
        parts.append(
            f"with the {LABELS[name]} it {verb} to {num(mt.rms_x_ss)} m ({_ratio_words(mp.rms_x_ss, mt.rms_x_ss)}) "
            f"for an RMS force of {num(mt.rms_u)} N"
        )
    lim = a.metrics["PID"].peak_u
    reach = "never reaches" if lim < a.u_max else "reaches"
    return (
        f"Run from rest, the plant's steady RMS displacement is {num(mp.rms_x_ss)} m without control; "
        + "; ".join(parts)
        + f". While regulating about zero the force-limited PID {reach} its ±{num(a.u_max)} N limit (largest force "
        f"{num(lim)} N)."
    )


def lqr_sentence(study: ControlStudy) -> str:
    """The LQR weights read by Bryson's rule, how close the LQR gains are to the PD's, and the force floor."""
    a = study.active
    d = a.lqr
    pd = a.loops["PD"]
    xm = 1.0 / math.sqrt(d.q_x) if d.q_x > 0 else math.inf
    vpart = (
        "$q_v$ = 0 leaves the velocity unweighted"
        if d.q_v == 0
        else f"$q_v$ = {num(d.q_v)} s²/m² a velocity of {num(1.0 / math.sqrt(d.q_v))} m/s"
    )
    xpart = f"a displacement of {num(xm)} m" if math.isfinite(xm) else "any displacement (no weight)"
    gap = max(abs(d.K[0] - pd.kx) / max(abs(pd.kx), 1e-300), abs(d.K[1] - pd.kv) / max(abs(pd.kv), 1e-300))
    return (
        "Read by Bryson's rule (each weight is one over the square of the largest acceptable value) the weights "
        f"$q_x$ = {num(d.q_x)} 1/m² and r = {num(d.r)} 1/N² accept {xpart} and a force of {num(1.0 / math.sqrt(d.r))} "
        f"N; {vpart}. The resulting gains ($K_x$ = {num(d.K[0], 4)} N/m, $K_v$ = {num(d.K[1], 4)} N s/m) differ from "
        f"the PD's ({num(pd.kx, 4)} N/m, {num(pd.kv, 4)} N s/m) by at most {pct(gap, 2)}. As r falls the RMS force "
        f"tends to $F_0/\\sqrt{{2}}$ = {num(a.force.F0 / math.sqrt(2.0))} N. No choice of weights can do better: to "
        "hold the mass still the force must cancel the disturbance, and any controller holding an amplitude X needs "
        "at least $(F_0 - |k - m\\omega^2 + ic\\omega| X)/\\sqrt{2}$. Along the whole curve the LQR designs use at "
        f"most {num(a.tradeoff.excess)} times that least force."
    )


def move_sentence(study: ControlStudy) -> str:
    """Windup of the force-limited PID move and what clamping and back-calculation do about it."""
    a = study.active
    mv = a.moves
    none, cl, bc = mv["none"], mv["clamping"], mv["back-calculation"]

    def change(new: float, old: float, what: str) -> str:
        return f"{'cuts' if new < old else 'raises'} {what} to {num(new)} m"

    return (
        f"With the force limited to ±{num(a.u_max)} N and no anti-windup the integrator winds up to "
        f"{num(none.integral_max)} m s, the move overshoots by {num(none.overshoot)} m and the mass keeps oscillating "
        f"with {num(none.amplitude)} m in steady state (at the limit {pct(none.saturated, 2)} of the time). Clamping "
        f"{change(cl.overshoot, none.overshoot, 'the overshoot')} and "
        f"{change(cl.amplitude, none.amplitude, 'the steady oscillation')}; back-calculation gives "
        f"{num(bc.overshoot)} m and {num(bc.amplitude)} m. Without a limit the overshoot is "
        f"{num(mv['unlimited'].overshoot)} m."
    )


def hold_sentence(study: ControlStudy) -> str:
    """Whether the force limit can hold the PID's set point, and a move it can hold."""
    a = study.active
    h = a.hold
    k, F0 = a.osc.k, a.force.F0
    need = f"$k|x_\\mathrm{{ref}}| + F_0$ = {num(k * abs(a.x_ref))} + {num(F0)} = {num(h.needed)} N of peak force"
    if not h.feasible:
        fr = [100.0 * a.moves[n].saturated_ss for n in ("none", "clamping", "back-calculation")]
        head = (
            f"The move to $x_\\mathrm{{ref}}$ = {num(a.x_ref)} m cannot succeed with ±{num(a.u_max)} N: holding the "
            f"mass there against the disturbance needs {need}, more than the limit, so no integrator treatment can "
            "make the limited runs settle; "
            + (
                f"they spend {num(min(fr))} to {num(max(fr))} % of the steady state at the limit."
                if num(min(fr)) != num(max(fr))
                else f"all three spend {num(fr[0])} % of the steady state at the limit."
            )
        )
    else:
        head = (
            f"Holding $x_\\mathrm{{ref}}$ = {num(a.x_ref)} m against the disturbance needs {need}, within the "
            f"±{num(a.u_max)} N limit."
        )
    r = h.run
    if r is None:
        return head + f" No set point can be held with ±{num(a.u_max)} N: the disturbance alone needs {num(F0)} N."
    err = "below 10⁻⁴ m" if abs(r.mean_error) < 1e-4 else f"{num(r.mean_error)} m"
    same = abs(r.amplitude / a.designs["PID"].amplitude - 1.0) < SAME
    return head + (
        f" The largest set point the limit can hold is $(u_\\mathrm{{max}} - F_0)/k$ = {num(h.x_max)} m. A move to "
        f"{num(h.x_ok)} m ({num(100 * FEASIBLE_FRACTION)} % of it) with clamping spends {pct(r.saturated_ss, 2)} of "
        f"the steady state at the limit, settles with a mean error {err} and oscillates with {num(r.amplitude)} m, "
        + ("the same as" if same else "against")
        + f" the unlimited loop's {num(a.designs['PID'].amplitude)} m."
    )


def flutter_sentence(study: ControlStudy) -> str:
    """The negative-damping plant and the exact stabilising velocity gain."""
    a = study.active
    c = a.flutter.c
    state = (
        "the oscillator is self-excited, the single-mode model of galloping or stall flutter (classical flutter "
        "couples two modes, bending and torsion, and needs two degrees of freedom)"
        if c < 0
        else "the oscillator is undamped and rings for ever"
    )
    return (
        f"With c = {num(c)} N s/m {state}; velocity feedback adds $K_v$ to the damping, so the smallest stabilising "
        f"gain is exactly $K_v^*$ = {num(a.kd_star)} N s/m (an open bound: at $K_v^*$ the poles sit on the imaginary "
        f"axis at ±{num(a.flutter.natural_frequency, 4)} rad/s). This chapter's flutter plant has its own damping, "
        "$c_f$, set apart from chapter 6's $c_u$, so that the loop has a growth to remove that is clearly visible "
        "within the window; the two chapters' values therefore need not agree."
    )


# ----------------------------------------------------------------------------- semi-active


def mr_sentence(study: ControlStudy) -> str:
    """Where the MR damper's parameters come from and how they are scaled."""
    s = study.semi
    L, F = s.mr_scale
    d = s.damper
    return (
        "The MR damper is the modified Bouc-Wen model with the parameters Spencer, Dyke, Sain and Carlson (1997) "
        "identified for their prototype (about 3000 N capacity, tested at ±1.5 cm). Scaled here with lengths "
        f"×{num(L, 4)} (so the test stroke maps onto Y = {num(s.Y)} m) and forces ×{num(F, 4)} (so the full-voltage "
        f"yield force maps onto {num(d.yield_force)} N); damping and stiffness coefficients scale by the force factor "
        "over the length factor, γ and β by one over the length factor squared, A, n, η and the voltage are "
        f"unchanged; time is not scaled. At 0 V it still yields at {num(d.alpha_a * d.z_max)} N."
    )


def semi_active_sentence(study: ControlStudy) -> str:
    """What the sweeps show: the clipped skyhook against every passive damper, and what it costs."""
    f = study.semi.findings
    t = f.t_res
    lo, hi = f.band
    if math.isfinite(lo):
        near = "over the whole band" if f.all_near else "over part of the band" if f.any_near else "nowhere in the band"
        band = (
            f"It beats every passive damper from $\\omega/\\omega_n$ = {num(lo)} to {num(hi)} on the sweep grid "
            f"({near} $1/\\sqrt{{2}}$ to $\\sqrt{{2}}$)."
        )
    else:
        band = "It beats no passive damper anywhere on the sweep grid."
    soft = f"at most {num(f.loss_soft)} times what the soft passive damper transmits" + (
        " (it loses no isolation)" if f.loss_soft <= 1.0 else ""
    )
    firm = (
        f"and at least {num(f.gain_firm)} times less than the firm one"
        if f.gain_firm > 1.0
        else "but more than the firm one at some frequencies"
    )
    mr = (
        f", but the MR damper's yield force at zero field costs isolation above $\\sqrt{{2}}\\,\\omega_n$ (up to "
        f"{num(f.mr_loss_soft)} times the soft passive damper)"
        if f.mr_loss_soft > 1.0
        else ", and the MR damper keeps the soft damper's isolation above $\\sqrt{2}\\,\\omega_n$"
    )
    return (
        f"At $\\omega = \\omega_n$ the clipped skyhook transmits {num(t['clipped'])} of the base motion, where every "
        f"passive damper transmits more than 1 (soft: {num(t['soft'])}, firm: {num(t['firm'])}) and the ideal skyhook "
        f"{num(t['skyhook'])}. {band} Above $\\sqrt{{2}}\\,\\omega_n$ it transmits {soft}, {firm}. The on-off law "
        f"switches its damper {num(f.switches)} times per period; the clipped damper carries an RMS force of "
        f"{num(f.force_res)} N at $\\omega_n$ (the firm passive damper: {num(f.force_res_firm)} N) and supplies no "
        f"energy. At $\\omega_n$ the on-off law transmits {num(t['on-off'])}, the MR damper {num(t['mr'])}{mr}."
    )


def skyhook_energy_sentence(study: ControlStudy) -> str:
    """What the ideal skyhook removes from the mass and what an actuator between body and base must supply."""
    p = study.semi.power
    net = (
        f"absorbs {num(-p.net)} W more than it supplies"
        if p.net < 0
        else f"supplies {num(p.net)} W more than it absorbs"
    )
    supply = (
        f"must supply {num(p.supplied)} W during the phases where $f v_\\mathrm{{rel}} > 0$"
        if p.supplied > 0
        else "never has to supply power"
    )
    return (
        f"The skyhook force removes $c_\\mathrm{{sky}}\\langle v^2\\rangle$ = {num(p.removed)} W from the mass. An "
        "actuator that produces it between the body and the base does the work $\\int f v_\\mathrm{rel}\\,dt$: on "
        f"average it {net}, but it {supply} and exchanges {num(p.gross)} W in all. A semi-active damper cannot "
        "supply those phases; that is what the clipped and on-off laws give up."
    )


def passivity_sentence(study: ControlStudy) -> str:
    """The semi-active dampers never deliver power, so they cannot destabilise the suspension."""
    s = study.semi
    if s.worst_power <= 0.0:
        head = (
            "The on-off and clipped dampers never deliver power: their force opposes the relative velocity at every "
            "instant of the runs ($f v_\\mathrm{rel} \\le 0$), as a damper's must."
        )
    else:
        head = f"The on-off and clipped runs deliver at most {num(s.worst_power)} W at some instant."
    return head + (
        " A device that can only dissipate cannot add energy to the suspension, so no semi-active law, however badly "
        "tuned or fed by a faulty sensor, can destabilise it: the worst it can do is damp badly. The MR damper "
        "supplies no power to the suspension either (its coil only changes how hard it resists; "
        f"{num(s.metrics['mr'].energy)} J exchanged over the window). The ideal skyhook needs an actuator, which "
        "supplies energy, so its loop can be destabilised like any active loop."
    )


# ----------------------------------------------------------------------------- input shaping


def shaping_sentence(study: ControlStudy) -> str:
    """Residual vibration of the shaped moves with a wrong natural frequency, and the tolerated bands."""
    s = study.shaping
    zv, zvd = s.bands["ZV"], s.bands["ZVD"]
    design = (
        "less than 10⁻¹² of the unshaped ringing"
        if s.design_residual < 1e-12
        else f"{pct(s.design_residual)} of the unshaped ringing"
    )
    better = "ZVD" if s.residual["ZVD"] < s.residual["ZV"] else "ZV"
    return (
        f"On the model itself both shapers leave {design}. With the natural frequency {signed_pct(s.freq_error)} "
        f"off, the unshaped move rings with {num(s.amplitude['none'])} m; ZV leaves {pct(s.residual['ZV'])} of that "
        f"and ZVD {pct(s.residual['ZVD'])}, so {better} is the better shaper at this error. ZV keeps the residual "
        f"below {pct(SHAPER_LEVEL)} for a real natural frequency from {num(zv[0], 4)} to {num(zv[1], 4)} times the "
        f"model's, ZVD from {num(zvd[0], 4)} to {num(zvd[1], 4)}, at the price of {num(s.shapers['ZVD'].duration)} s "
        f"of added delay instead of {num(s.shapers['ZV'].duration)} s."
    )


# ----------------------------------------------------------------------------- what a designer takes away


def summary(study: ControlStudy) -> str:
    """What a designer takes away: conclusions in new words, each chosen by the numbers."""
    a, s, sh = study.active, study.semi, study.shaping
    X = {n: d.amplitude for n, d in a.designs.items()}
    lines = []
    if X["PD2"] <= X["PID"] * (1.0 + SAME):
        lines.append(
            "**Against a sinusoidal disturbance, buy stiffness, not integral action.** The integrator removes a "
            "constant error; against the sine it adds nothing a PD with the same proportional and derivative gains "
            "does not already do."
        )
    else:
        lines.append(
            "**Integral action earns its place here.** At this forcing the PID holds a smaller amplitude than a PD "
            "with its own proportional and derivative gains."
        )
    order = delay_ranking(a)
    stiffest = ranked_designs(a)[0]
    if order[0] == stiffest:
        lines.append(
            f"**The tightest loop is the most fragile.** The {LABELS[stiffest]}, which holds the mass closest, "
            "tolerates the least loop delay: measure the actuator's and the sensor's delays before raising the "
            "gains."
        )
    else:
        lines.append(
            f"**Tightness and fragility part ways here.** The {LABELS[order[0]]}, not the tightest loop, tolerates the "
            "least loop delay: rank designs by their delay margins, not by their gains."
        )
    worst, excess = force_excess(a)
    if excess < 1.0 + WASTE:
        lines.append(
            "**The disturbance, not the tuning, sets the force bill.** No design here pays noticeably more than the "
            "least force its amplitude needs, so retuning cannot save force; a smaller amplitude always costs a force "
            "closer to the disturbance's own."
        )
    else:
        lines.append(
            f"**Check the force against its floor.** The {LABELS[worst]} spends far more force than its amplitude "
            "requires; a design on the least-force curve would hold the same amplitude for less."
        )
    if a.hold.feasible:
        lines.append(
            "**Size the actuator for the set point plus the disturbance.** Here $k|x_\\mathrm{ref}| + F_0$ fits inside "
            "the force limit, so the move can settle; anti-windup still decides how far it overshoots on the way."
        )
    else:
        lines.append(
            "**Size the actuator for the set point plus the disturbance.** Here $k|x_\\mathrm{ref}| + F_0$ exceeds the "
            "force limit: anti-windup tames the overshoot, but no integrator treatment can make an impossible move "
            "settle. Lower the set point or buy a stronger actuator."
        )
    f = s.findings
    if f.t_res["clipped"] < 1.0:
        lines.append(
            "**Semi-active damping is the safe middle ground.** A clipped-skyhook damper does near resonance what no "
            "passive damper can, needs power only to set its valve, never to drive the mass, and, being unable to "
            "supply energy, can never destabilise the suspension."
        )
    else:
        lines.append(
            "**Semi-active damping does not pay here.** With these damper bounds the clipped skyhook does not get "
            "below what a passive damper transmits at resonance; widen the bounds or use an actuator."
        )
    half = {n: 0.5 * (sh.bands[n][1] - sh.bands[n][0]) for n in ("ZV", "ZVD")}
    slower = sh.shapers["ZVD"].duration / sh.shapers["ZV"].duration
    delay = "twice ZV's delay" if abs(slower - 2.0) < 1e-9 else f"{num(slower, 2)} times ZV's delay"
    lines.append(
        "**Shape the command for the natural frequency you are unsure of.** ZVD tolerates an error about "
        f"{num(half['ZVD'] / half['ZV'], 2)} times as wide as ZV's for {delay}; choose it "
        f"when $\\omega_n$ may be off by more than ZV's ±{pct(half['ZV'], 2)}."
    )
    return "\n".join(f"- {line}" for line in lines)


def all_text(study: ControlStudy) -> list[str]:
    """Every sentence block of the chapter in reading order (for the tests of repetition and wording)."""
    return [
        key_results(study),
        comparison_sentence(study),
        active_sentences(study),
        lqr_sentence(study),
        move_sentence(study),
        hold_sentence(study),
        flutter_sentence(study),
        mr_sentence(study),
        semi_active_sentence(study),
        skyhook_energy_sentence(study),
        passivity_sentence(study),
        shaping_sentence(study),
        summary(study),
    ]


__all__ = [
    "active_sentences",
    "all_text",
    "comparison_sentence",
    "delay_ranking",
    "flutter_sentence",
    "forcing_phrase",
    "hold_sentence",
    "key_findings",
    "key_results",
    "lqr_sentence",
    "move_sentence",
    "mr_sentence",
    "passivity_sentence",
    "ranked_designs",
    "semi_active_sentence",
    "shaping_sentence",
    "skyhook_energy_sentence",
    "summary",
]
