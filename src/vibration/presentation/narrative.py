"""Sentences from results: every statement of a number, a regime, a comparison or a verdict.

Each function takes the results a chapter already computed and returns Markdown, shown in
the notebook with ``display(Markdown(text))``; a papermill run with other parameters
therefore says what its own tables say. Prose about the paper is quoted from it and says so.

Word conventions (a test reads the executed chapters and checks them against their tables):

* a case is named in bold, ``**low damping**``, as in the tables' "case" column;
* its regime word is the table's ("underdamped", "undamped", "unstable", ...);
* "settles after T s" when the 2 % settling time is inside the window, "has not settled by
  t = T s" otherwise;
* "the largest response is the **case**" names the case with the largest peak |x|;
* "inside" / "outside the half-power band" as the half-power table says.

Examples
--------
>>> from vibration.presentation.findings import reproduce, scenarios_from
>>> rep = reproduce(scenarios_from(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 5.0), n_points=1001)
>>> print(largest_sentence(rep))
The largest response is the **low damping** case: peak |x| = 10.25 m in the window.
"""

from __future__ import annotations

import math

from ..physics.model import Oscillator, SineForce
from ..physics.paper import paper_defaults
from .findings import Reproduction, case_name
from .tables import fmt

#: Relative error of RK45 (against the window's peak) below which the summary calls it negligible.
SMALL_ERROR = 0.05

#: Meaning and unit of the paper's parameters, for the sentence that lists what a run changed.
PARAMETER_TEXT = {
    "m": ("m", "kg"),
    "k": ("k", "N/m"),
    "F0": ("F0", "N"),
    "t_end": ("t_end", "s"),
    "omega_ref": ("ω_ref", "rad/s"),
    "omega_res": ("ω_res", "rad/s"),
    "c_low": ("c_low", "N s/m"),
    "c_nominal": ("c_nominal", "N s/m"),
    "c_high": ("c_high", "N s/m"),
}


def g(value: float, digits: int = 4) -> str:
    """A number for a sentence: ``digits`` significant figures, "∞" for infinity.

    Examples
    --------
    >>> g(2.23703819), g(78.2345, 3), g(float("inf"))
    ('2.237', '78.2', '∞')
    """
    return fmt(float(value), digits)


def parameters_sentence(**values: float) -> str:
    """Which of the paper's parameters this run changed (keyword arguments: name = value).

    Examples
    --------
    >>> parameters_sentence(m=1.0, c_high=15.0)
    "This run uses the paper's parameters (m = 1 kg, c_high = 15 N s/m)."
    >>> parameters_sentence(m=1.0, c_high=5.0)
    "This run changes the paper's parameters: c_high = 5 N s/m (the paper's: 15 N s/m). Every number, regime \
and verdict below is computed with the run's values; quotations keep the paper's."
    """
    paper = paper_defaults()
    changed, same = [], []
    for name, value in values.items():
        sym, unit = PARAMETER_TEXT.get(name, (name, ""))
        text = f"{sym} = {g(value, 6)}{' ' + unit if unit else ''}"
        if name in paper and float(value) != paper[name]:
            changed.append(f"{text} (the paper's: {g(paper[name], 6)}{' ' + unit if unit else ''})")
        else:
            same.append(text)
    if not changed:
        return f"This run uses the paper's parameters ({', '.join(same)})."
    return (
        f"This run changes the paper's parameters: {'; '.join(changed)}. Every number, regime and verdict "
        "below is computed with the run's values; quotations keep the paper's."
    )


def regime_clause(osc: Oscillator, force: SineForce | None = None, t_end: float | None = None) -> str:
    """The regime word with what it means for this oscillator (and forcing, when given).

    Examples
    --------
    >>> regime_clause(Oscillator(1.0, 15.0, 20.0))
    'overdamped (ζ = 1.68 > 1: the free motion does not oscillate)'
    >>> regime_clause(Oscillator(1.0, -0.1, 20.0))
    'unstable (negative damping, ζ = -0.0112: the free vibration grows as exp(0.05 t/s))'
    """
    zeta = osc.damping_ratio
    reg = osc.regime
    if reg == "underdamped":
        return f"underdamped (ζ = {g(zeta, 3)} < 1: the free motion oscillates and decays)"
    if reg == "overdamped":
        return f"overdamped (ζ = {g(zeta, 3)} > 1: the free motion does not oscillate)"
    if reg == "critically damped":
        return "critically damped (ζ = 1)"
    if reg == "unstable":
        return (
            f"unstable (negative damping, ζ = {g(zeta, 3)}: the free vibration grows as "
            f"exp({g(-osc.decay_rate, 3)} t/s))"
        )
    # undamped
    text = "undamped (c = 0: the free vibration never decays"
    if force is not None and force.omega > 0:
        wn, w = osc.natural_frequency, force.omega
        if w == wn:
            text += "; at exact resonance the forced response grows without bound, as t cos(ω_n t)"
        else:
            beat = 2 * math.pi / abs(wn - w)
            text += f"; forced at ω/ω_n = {g(w / wn, 5)} the response beats with period {g(beat, 3)} s"
            if t_end is not None and beat > 4 * t_end:
                text += f", so over {g(t_end)} s it grows almost linearly, like the t cos(ω_n t) of exact resonance"
    return text + ")"


def settle_clause(f: dict, t_end: float) -> str:
    """ "it settles after T s" or "it has not settled by t = T s", from one findings row.

    Examples
    --------
    >>> settle_clause({"t_settle_2pct_s": 78.23, "steady_in_window": False, "c_Ns_m": 0.1}, 50.0)
    'it has not settled by t = 50 s (its 2 % settling time is 78.2 s)'
    """
    ts = f["t_settle_2pct_s"]
    if f["steady_in_window"]:
        return f"it settles after {g(ts, 3)} s, inside the {g(t_end)} s window"
    if f["c_Ns_m"] <= 0:
        why = "it has no steady state to settle to" if f["c_Ns_m"] < 0 else "its free vibration never decays"
        return f"it has not settled by t = {g(t_end)} s and never will: {why}"
    return f"it has not settled by t = {g(t_end)} s (its 2 % settling time is {g(ts, 3)} s)"


def case_sentence(rep: Reproduction, sid: str) -> str:
    """One scenario in a sentence: damping, regime, peak, settling.

    Examples
    --------
    >>> from vibration.presentation.findings import reproduce, scenarios_from
    >>> rep = reproduce(scenarios_from(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0), n_points=1001)
    >>> print(case_sentence(rep, "damping_high"))
    **high damping** (c = 15 N s/m, ω = 4.47 rad/s): overdamped (ζ = 1.68 > 1: the free motion does not \
oscillate); peak |x| = 0.1045 m in the window, steady amplitude x_ss = 0.07457 m; it settles after 2.72 s, \
inside the 50 s window.
    """
    sc, f = rep.scenarios[sid], rep.by_id[sid]
    osc, force = sc.oscillator, sc.force
    if osc.c < 0:
        amp = "no steady amplitude (it is never reached)"
    else:
        amp = f"steady amplitude x_ss = {g(f['x_ss_m'])} m"
    return (
        f"**{case_name(sid)}** (c = {g(osc.c)} N s/m, ω = {g(force.omega)} rad/s): "
        f"{regime_clause(osc, force, sc.t_end)}; peak |x| = {g(f['peak_x_exact_m'])} m in the window, {amp}; "
        f"{settle_clause(f, sc.t_end)}."
    )


def largest_sentence(rep: Reproduction, ids=("damping_low", "damping_nominal", "damping_high")) -> str:
    """Which of the cases ``ids`` has the largest peak |x| in the window."""
    best = max(ids, key=lambda s: rep.by_id[s]["peak_x_exact_m"])
    return (
        f"The largest response is the **{case_name(best)}** case: peak |x| = "
        f"{g(rep.by_id[best]['peak_x_exact_m'])} m in the window."
    )


def resonance_text(rep: Reproduction) -> str:
    """What Figure 1 shows: the resonance case against the reference case, from the run's numbers."""
    res, ref = rep.by_id["resonance"], rep.by_id["reference"]
    sc = rep.scenarios["resonance"]
    wn = sc.oscillator.natural_frequency
    lines = [
        f"The resonance case forces the oscillator at ω = {g(sc.force.omega)} rad/s, ω/ω_n = "
        f"{g(sc.force.omega / wn, 5)} of its natural frequency ω_n = √(k/m) = {g(wn)} rad/s.",
        "",
        "- " + case_sentence(rep, "resonance"),
        "- " + case_sentence(rep, "reference"),
    ]
    if res["c_Ns_m"] >= 0 and ref["c_Ns_m"] >= 0 and ref["x_ss_m"] > 0 and math.isfinite(res["x_ss_m"]):
        ratio = res["x_ss_m"] / ref["x_ss_m"]
        lines += [
            "",
            f"The steady amplitude at resonance is {g(ratio, 3)} times the reference one "
            f"({g(res['x_ss_m'])} m against {g(ref['x_ss_m'])} m); the window peaks are "
            f"{g(res['peak_x_exact_m'])} m and {g(ref['peak_x_exact_m'])} m.",
        ]
    return "\n".join(lines)


def damping_text(rep: Reproduction) -> str:
    """What Figure 2 shows: the three dampings at the resonant frequency, case by case."""
    ids = ("damping_low", "damping_nominal", "damping_high")
    lines = ["- " + case_sentence(rep, sid) for sid in ids]
    return "\n".join(lines) + "\n\n" + largest_sentence(rep, ids)


def reproduction_summary(rep: Reproduction) -> str:
    """The bullets of chapter 1's summary."""
    worst = max(rep.findings, key=lambda f: f["max_err_x_rk45_m"] / max(f["peak_x_exact_m"], 1e-300))
    rel = worst["max_err_x_rk45_m"] / max(worst["peak_x_exact_m"], 1e-300)
    text = (
        f"The paper's method (RK45 at SciPy's defaults) stays within {g(100 * rel, 2)} % of each case's "
        f"peak of the exact displacement (worst: **{case_name(worst['scenario'])}**, "
        f"{g(worst['max_err_x_rk45_m'], 3)} m); "
    )
    if rel < SMALL_ERROR:
        text += "differences between the paper's text and these tables are therefore not numerical."
    else:
        text += (
            f"that is more than {g(100 * SMALL_ERROR)} %, so with these parameters the default tolerances "
            "matter (chapter 3 measures them)."
        )
    bullets = [text + " Chapter 2 audits each claim."]
    t_end = rep.scenarios["damping_low"].t_end
    for sid in ("damping_low", "damping_nominal", "damping_high"):
        f = rep.by_id[sid]
        bullets.append(f"**{case_name(sid)}** is {f['regime']}; {settle_clause(f, t_end)}.")
    bullets.append(largest_sentence(rep))
    return "\n".join("- " + b for b in bullets)


def explorer_start(c: float) -> tuple[float, str]:
    """The damping the sliders start at (N s/m) and a sentence saying why, for a chapter's ``c``.

    The damping sliders are logarithmic, so they cannot hold c <= 0; such a run starts them at
    their lowest damping and says so.

    Examples
    --------
    >>> explorer_start(0.5)[0], explorer_start(-0.1)[0]
    (0.5, 0.01)
    """
    from .widgets import C_MIN

    if c > 0:
        return c, f"The sliders start at this run's damping, c = {g(c)} N s/m."
    what = "undamped" if c == 0 else "negative damping"
    return C_MIN, (
        f"This run's damping is c = {g(c)} N s/m ({what}); the damping sliders are logarithmic and cannot "
        f"hold it, so they start at their lowest value, c = {g(C_MIN)} N s/m. Chapter 1 shows the response "
        f"at c = {g(c)} N s/m."
    )


def explore_controls_markdown() -> str:
    """Which controls exist where: JupyterLab (all) and the rendered report (ω, c and reset)."""
    from . import static_page, widgets

    return (
        "* **In JupyterLab** (a running kernel): the forcing frequency ω (rad/s, the Hz value beside it) and "
        f"the damping c (N s/m, logarithmic, from {g(widgets.C_MIN)} to {g(widgets.C_MAX)} N s/m, through "
        "critical damping) redraw the figure while the slider moves; boxes for m (kg), k (N/m), F0 (N) and "
        "the window t_end (s) apply when Enter is pressed (a value out of range is reported in red and the "
        "figure keeps the last valid state); a check box overlays the paper's RK45 solution and its largest "
        "deviation from the exact displacement.\n"
        "* **In the rendered report** (no kernel): the same closed form runs in the browser with exactly "
        f"three controls, the forcing frequency ω (steps of {g(static_page.OMEGA_STEP)} rad/s), the damping c "
        f"(logarithmic, at least {g(static_page.C_MIN)} to {g(static_page.C_MAX)} N s/m) and a reset button; "
        "it draws x(t) and v(t) and the magnification curve like the JupyterLab figure, but m, k, F0, t_end "
        "and the RK45 overlay are fixed at this run's values."
    )


def explore_summary(values: dict) -> str:
    """Chapter 5's summary from the explorer's starting readout (``Explorer.values``)."""
    v = values
    settled = (
        f"it settles after {g(v['settling'], 3)} s, inside the {g(v['t_end'])} s window"
        if v["steady_reached"] == "yes"
        else f"it has not settled by t = {g(v['t_end'])} s"
    )
    bullets = [
        f"At the starting point ω/ω_n = {g(v['ratio'], 5)} and ζ = {g(v['zeta'], 3)}: the oscillator is "
        f"{v['regime']}, its steady amplitude is {g(v['amplitude'])} m ({g(v['magnification'], 3)} times the "
        f"static deflection) and {settled}.",
        "Near ω_n the steady amplitude is F0/(c ω): halving c doubles it and doubles the settling time; a few "
        "half-power bandwidths (c/m) away from ω_n the amplitude no longer depends on c.",
        "For ζ ≥ 1/√2 the magnification curve has no peak left to avoid; above ζ = 1 the transient no longer "
        "oscillates.",
    ]
    return "\n".join("- " + b for b in bullets)
