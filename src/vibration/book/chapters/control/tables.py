"""The chapter's tables, each a function of the :class:`~vibration.book.chapters.control.study.ControlStudy`.

Every number is pre-formatted with :func:`~vibration.book.chapters.control.notation.cell`, so a column
keeps one number of significant figures; quantities that do not exist read "—" with a footnote.
"""

from __future__ import annotations

import math

from vibration.book.chapters.control.notation import LABELS, cell, num, signed_pct
from vibration.book.chapters.control.study import (
    DESIGNS,
    MOVE_SCHEMES,
    SHAPER_LEVEL,
    STEADY_PERIODS,
    ControlStudy,
)
from vibration.book.presentation.numbers import integer
from vibration.book.presentation.tables import Missing, Table, bound, columns, self_checks
from vibration.physics.control import Metrics

NO_INTEGRATOR = Missing(reason="no integral term")
NO_CROSSOVER = Missing(reason="the loop gain never reaches 1: no crossover, and no delay destabilises the loop")
FIRST_ROW = Missing(reason="first row")
NO_SHAPER = Missing(reason="no shaper: the unshaped step is the reference")


def _metrics_table(metrics: dict[str, Metrics], reference: str, **table) -> Table:
    """One row per law, its steady RMS reduction against ``reference``; ``table``: caption, name and notes."""
    ref = metrics[reference].rms_x_ss
    rows = []
    for name, mt in metrics.items():
        rows.append(
            {
                "controller": LABELS[name],
                "peak_x": cell(mt.peak_x),
                "rms_x": cell(mt.rms_x),
                "peak_x_ss": cell(mt.peak_x_ss),
                "rms_x_ss": cell(mt.rms_x_ss),
                "reduction": cell(ref / mt.rms_x_ss) if mt.rms_x_ss > 0 else "∞",
                "peak_u": cell(mt.peak_u),
                "rms_u": cell(mt.rms_u),
                "energy": cell(mt.energy),
            }
        )
    return Table(rows=rows, columns=_METRIC_COLUMNS, **table)


_METRIC_COLUMNS = columns(
    """
    controller  controller
    peak_x      max|x| (m)
    rms_x       x_rms (m)
    peak_x_ss   max|x|, steady (m)
    rms_x_ss    x_rms, steady (m)
    reduction   RMS reduction, steady
    peak_u      max|u| (N)
    rms_u       u_rms (N)
    energy      E (J)
    """
)


def _at(study: ControlStudy) -> str:
    a = study.active
    return f"ω = {num(a.force.omega)} rad/s (ω/ω_n = {cell(a.forcing_ratio)})"


def gains_table(study: ControlStudy) -> Table:
    """Gains, closed-loop natural frequency, damping ratio, pole and steady amplitude of PD and LQR."""
    rows = []
    for name, cl in study.active.loops.items():
        rows.append(
            {
                "law": LABELS[name],
                "kx": cell(cl.kx, 4),
                "kv": cell(cl.kv, 4),
                "wn": cell(cl.osc.natural_frequency, 4),
                "zeta": cell(cl.osc.damping_ratio, 3),
                "re": cell(cl.pole.real, 4),
                "im": cell(abs(cl.pole.imag), 4),
                "X": cell(cl.amplitude, 4),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            law   law
            kx    K_x (N/m)
            kv    K_v (N s/m)
            wn    ω_n,cl (rad/s)
            zeta  ζ_cl
            re    Re s (1/s)
            im    |Im s| (rad/s)
            X     X_ss (m)
            """
        ),
        caption=(
            "The closed loop of u = −K_x x − K_v v is the oscillator (m, c + K_v, k + K_x): its natural frequency "
            f"ω_n,cl, damping ratio ζ_cl, pole pair s and steady amplitude X_ss at the forcing {_at(study)}."
        ),
        name="tab-control-gains",
    )


def costs_table(study: ControlStudy) -> Table:
    """The active designs on equal footing: amplitude, force against its floor, margins and noise."""
    a = study.active
    rows = []
    for name in DESIGNS:
        d = a.designs[name]
        lc = d.costs
        rows.append(
            {
                "law": LABELS[name],
                "kx": cell(d.kx, 4),
                "ki": cell(d.ki, 4) if d.ki > 0 else NO_INTEGRATOR,
                "kv": cell(d.kv, 4),
                "X": cell(d.amplitude),
                "u_rms": cell(d.u_rms),
                "floor": cell(d.floor),
                "L": cell(lc.loop_gain),
                "wc": cell(lc.crossover) if math.isfinite(lc.crossover) else NO_CROSSOVER,
                "pm": cell(math.degrees(lc.phase_margin)) if math.isfinite(lc.crossover) else NO_CROSSOVER,
                "dm": cell(lc.delay_margin) if math.isfinite(lc.delay_margin) else NO_CROSSOVER,
                "bn": cell(lc.noise_bandwidth),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            law    law
            kx     K_x, K_P (N/m)
            ki     K_I (N/(m s))
            kv     K_v, K_D (N s/m)
            X      X_ss (m)
            u_rms  u_rms (N)
            floor  least u_rms for X_ss (N)
            L      |L(iω)|
            wc     ω_c (rad/s)
            pm     phase margin (°)
            dm     delay margin (s)
            bn     B_n (rad/s)
            """
        ),
        caption=(
            f"The active laws at {_at(study)}: gains (K_x, K_v; K_P, K_I, K_D of the PID), the unlimited loop's "
            "steady amplitude X_ss, steady RMS force u_rms against the least any controller needs, loop gain "
            "|L(iω)| at the forcing, crossover ω_c, margins and noise bandwidth B_n."
        ),
        name="tab-control-costs",
        notes=(
            "The least RMS force that holds the steady amplitude Xₛₛ is (F₀ − |k − mω² + icω| Xₛₛ)/√2.",
            "The gain crossover sets the delay margin (it is the loop's bandwidth); the delay margin is the "
            "smallest time delay in the loop that destabilises it.",
            "Bₙ = ∫|T(iω)|² dω over ω > 0: white position-sensor noise of two-sided density Sₙ moves the mass with "
            "variance 2 Sₙ Bₙ.",
        ),
    )


def active_metrics_table(study: ControlStudy) -> Table:
    """Peak and RMS displacement (window and steady state), force and energy per active controller."""
    a = study.active
    return _metrics_table(
        a.metrics,
        "passive",
        caption=(
            f"Active control at {_at(study)} from rest over {num(a.t[-1])} s: displacement over the window and in "
            f"steady state (last {STEADY_PERIODS} forcing periods, from t = {num(a.t_steady, 4)} s), steady RMS "
            "reduction against the passive oscillator, control force and the energy ∫|u v| dt the actuator "
            "exchanges with the mass; the PID is force-limited with clamping."
        ),
        name="tab-control-active",
    )


def checks_table(study: ControlStudy) -> Table:
    """Rounding-level checks of the active designs, printed as bounds."""
    a = study.active
    checks = (
        ("PD loop simulated (DOP853) against the exact closed-loop oscillator, max |Δx| (m)", bound(a.pd_error, 1e-9)),
        (
            "LQR gains: the design routine against a general Riccati solver, relative",
            bound(a.lqr_check["scipy"], 1e-12),
        ),
        ("LQR gains: the design routine against the closed form, relative", bound(a.lqr_check["closed form"], 1e-12)),
        ("Riccati residual of the returned P, relative", bound(a.lqr_check["residual"], 1e-12)),
    )
    caption = "Self-checks of the active designs (rounding level, printed as bounds)."
    return self_checks(checks, caption=caption, name="tab-control-checks")


def move_table(study: ControlStudy) -> Table:
    """Overshoot, steady oscillation and saturation of the PID move per integrator treatment."""
    a = study.active
    rows = []
    for scheme in MOVE_SCHEMES:
        mv = a.moves[scheme]
        rows.append(
            {
                "scheme": LABELS[scheme],
                "over": cell(mv.overshoot),
                "amp": cell(mv.amplitude),
                "mean": cell(mv.mean_error, 2),
                "sat": cell(100.0 * mv.saturated, 3),
                "imax": cell(mv.integral_max),
                "peak_u": cell(mv.peak_u),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            scheme  force limit and integrator
            over    overshoot (m)
            amp     X_ss (m)
            mean    mean error, steady (m)
            sat     time at the limit (%)
            imax    max|I| (m s)
            peak_u  max|u| (N)
            """
        ),
        caption=(
            f"PID move to x_ref = {num(a.x_ref)} m under the disturbance at {_at(study)}, force limited to "
            f"±{num(a.u_max)} N (first row: no limit): overshoot, steady half peak-to-peak oscillation X_ss and mean "
            f"error (last {STEADY_PERIODS} periods), share of the window at the limit and the largest integrator "
            "state I."
        ),
        name="tab-control-windup",
    )


def flutter_table(study: ControlStudy) -> Table:
    """Poles of the negative-damping plant under velocity feedback below, at and above the stabilising gain."""
    a = study.active
    rows = []
    for fc in a.flutter_cases:
        verdict = "stable" if fc.re < 0 else ("marginal" if fc.re == 0 else "unstable")
        rows.append(
            {
                "case": {"no feedback": "none", "1": "the stabilising gain"}.get(
                    fc.label, f"{fc.label} × the stabilising gain"
                ),
                "kd": cell(fc.kv, 3),
                "re": cell(fc.re, 3),
                "im": cell(fc.im, 4),
                "verdict": verdict,
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            case     velocity gain
            kd       K_v (N s/m)
            re       max Re s (1/s)
            im       |Im s| (rad/s)
            verdict  loop
            """
        ),
        caption=(
            f"Negative damping c = {num(a.flutter.c)} N s/m (the linear galloping or stall-flutter model) under "
            "u = −K_v v: the poles have real part −(c + K_v)/(2m); the loop is stable exactly when "
            f"K_v > K_v* = −c = {num(a.kd_star)} N s/m."
        ),
        name="tab-control-flutter",
    )


def semi_active_metrics_table(study: ControlStudy) -> Table:
    """Displacement, device force and energy of every suspension law at the base frequency."""
    s = study.semi
    return _metrics_table(
        s.metrics,
        "soft",
        caption=(
            f"Semi-active suspension at ω = {num(s.omega)} rad/s (ω/ω_n = {cell(s.omega / s.osc.natural_frequency)}), "
            f"base amplitude Y = F_0/k = {num(s.Y)} m, from rest over {num(s.runs['soft'].t[-1])} s: the mass's "
            "displacement, the device force and the energy ∫|f v_rel| dt it exchanges, v_rel = v − v_b (for the "
            "ideal skyhook the gross exchange, split in {numref}`tab-control-skyhook-energy`)."
        ),
        name="tab-control-semiactive",
        notes=(
            f"Soft: damping c + cₘᵢₙ = {num(s.osc.c + s.c_min)} N s/m; firm: c + cₘₐₓ = {num(s.osc.c + s.c_max)} "
            "N s/m.",
            f"Steady state is the last {STEADY_PERIODS} periods; the RMS reduction is against the soft passive "
            "damper. The passive and semi-active dampers dissipate all the energy they exchange.",
        ),
    )


def skyhook_energy_table(study: ControlStudy) -> Table:
    """What the ideal skyhook removes and what an actuator between body and base must exchange, W."""
    s = study.semi
    p, r = s.power, s.power_run
    rows = [
        ("removed from the mass by the skyhook force", "removed"),
        ("net power of the actuator (force × relative velocity)", "net"),
        ("power the actuator supplies (the positive part)", "supplied"),
        ("gross power exchanged (its absolute value)", "gross"),
    ]
    return Table(
        rows=[{"what": what, "closed": cell(getattr(p, key), 4), "run": cell(r[key], 4)} for what, key in rows],
        columns=columns(
            """
            what    mean power
            closed  closed form (W)
            run     run, steady tail (W)
            """
        ),
        caption=(
            f"Mean steady powers of the ideal skyhook (c_sky = {num(s.c_sky)} N s/m) at ω = {num(s.omega)} rad/s, "
            f"base amplitude Y = {num(s.Y)} m, realised by an actuator between mass and base: the power c_sky v² "
            "removed from the mass and the actuator's power f v_rel (v_rel = v − v_b), in closed "
            f"form and on the RK4 run's last {STEADY_PERIODS} periods."
        ),
        name="tab-control-skyhook-energy",
        notes=("A negative net power means the actuator absorbs more than it supplies.",),
    )


def refinement_table(study: ControlStudy) -> Table:
    """On-off skyhook at omega_n under step refinement: the switching is what limits RK4's order."""
    s = study.semi
    rows, prev = [], None
    for spp, val in s.refine.items():
        rows.append(
            {
                "spp": spp,
                "dt": cell(2.0 * math.pi / s.osc.natural_frequency / spp, 3),
                "T": cell(val, 5),
                "d": FIRST_ROW if prev is None else cell(val - prev, 2),
            }
        )
        prev = val
    return Table(
        rows=rows,
        columns=columns(
            """
            spp  RK4 steps per period
            dt   Δt (s)
            T    max|x|/Y at ω_n
            d    change from the row above
            """
        ),
        caption=(
            "On-off skyhook transmissibility at ω = ω_n under step refinement. The law switches the damping "
            "discontinuously, so fixed-step RK4 loses its fourth order at each switch; the table shows how far "
            "the sweeps' value (1000 steps per period) is from the converged one."
        ),
        name="tab-control-onoff-refinement",
    )


def semi_active_checks_table(study: ControlStudy) -> Table:
    """The semi-active runs against closed forms and against themselves under refinement."""
    s = study.semi
    p, pr = s.power, s.power_run
    vals = list(s.refine.values())
    coarse, fine = list(s.refine)[-2:]
    power = max(abs(pr[f] - getattr(p, f)) / max(abs(p.gross), 1e-300) for f in ("removed", "net", "supplied", "gross"))
    checks = [
        (
            f"{LABELS[n]}: RK4 run's steady max|x|/Y against the closed form, relative",
            bound(s.closed_run_error[n], 1e-4),
        )
        for n in ("soft", "skyhook")
    ]
    checks += [
        ("ideal skyhook: mean powers of the run against the closed form, largest relative difference",
         bound(power, 1e-3)),
        (f"on-off skyhook at ωₙ: last refinement step ({integer(coarse)} to {integer(fine)} steps per period), "
         "absolute", bound(abs(vals[-1] - vals[-2]), 1e-4)),
        ("on-off and clipped dampers: largest instantaneous power they deliver (W)",
         "≤ 0" if s.worst_power <= 0.0 else bound(s.worst_power, 1e-12)),
    ]  # fmt: skip
    caption = "Self-checks of the semi-active runs (printed as bounds against stated tolerances)."
    return self_checks(checks, caption=caption, name="tab-control-semiactive-checks")


def shaping_table(study: ControlStudy) -> Table:
    """Delay, residual vibration (closed form and simulated), ringing and tolerance band of each shaper."""
    s = study.shaping
    rows = []
    for name in ("none", "ZV", "ZVD"):
        sh = s.shapers.get(name)
        lo, hi = s.bands[name] if sh is not None else (NO_SHAPER, NO_SHAPER)
        rows.append(
            {
                "shaper": "unshaped step" if name == "none" else name,
                "delay": cell(sh.duration, 3) if sh is not None else "0",
                "V": cell(100.0 * s.residual[name], 3),
                "Vsim": cell(100.0 * s.residual_sim[name], 3),
                "amp": cell(s.amplitude[name], 3),
                "lo": lo if sh is None else cell(lo, 4),
                "hi": hi if sh is None else cell(hi, 4),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            f"""
            shaper  command
            delay   added delay (s)
            V       V, closed form (%)
            Vsim    V, simulated (%)
            amp     ringing after the move (m)
            lo      V ≤ {num(100 * SHAPER_LEVEL)} % from ω/ω_model
            hi      to
            """
        ),
        caption=(
            f"Move of {num(s.move)} m on an oscillator whose natural frequency is {signed_pct(s.freq_error)} off the "
            "model the shapers were designed on: added delay, residual vibration V as a percentage of the unshaped "
            "step's (closed form and simulated on the exact response), ringing just after the last impulse, and the "
            f"frequency band where V stays below {num(100 * SHAPER_LEVEL)} %."
        ),
        name="tab-control-shaping",
        notes=(
            f"The band's edges are the ratios of real to model natural frequency where V = {num(100 * SHAPER_LEVEL)} "
            "%, solved to 10⁻¹² in the ratio.",
        ),
    )
