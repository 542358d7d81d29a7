"""Chapter 5's sentences and its readout table, each a function of one :class:`ExploreStudy`.

Every number is read from the study; every comparison word is decided from those numbers. The
description of what the explorer and the book's panel draw is read from the figure and the panel
themselves (:func:`vibration.book.chapters.explore.figure.figure_words`,
:func:`vibration.book.chapters.explore.panel.panel_facts`), so it cannot drift from the drawing.

Examples
--------
>>> from vibration.book.chapters.explore.study import explore_study
>>> st = explore_study()
>>> print(key_results(st).splitlines()[0])
> **Key results**
>>> print(repr(readout_table(st)).splitlines()[3].split())
['natural', 'frequency', 'ωₙ', '4.4721', 'rad/s']
"""

from __future__ import annotations

import math

from vibration.book.chapters.explore.figure import build_figure, figure_words
from vibration.book.chapters.explore.panel import OMEGA_STEP, panel_facts
from vibration.book.chapters.explore.study import C_MAX, C_MIN, ExploreStudy
from vibration.book.presentation.captions import web_only
from vibration.book.presentation.numbers import sig as num
from vibration.book.presentation.tables import Table, columns, text_rows

W_N = r"$\omega_n$"

#: Amplitude ratio (halved damping over starting damping) above which damping "sets" the amplitude.
DAMPING_SETS = 1.8
#: ... and below which it "hardly matters".
DAMPING_IRRELEVANT = 1.05


def _settles(r) -> str:
    return (
        f"settles (2 %) after {num(r.settling, 3)} s"
        if r.steady_reached == "yes"
        else f"has not settled (2 %) by the end of the {num(r.t_end)} s window"
    )


def key_results(study: ExploreStudy) -> str:
    """The key-results box: the starting point and what the sliders change, as a Markdown block quote."""
    s, h, far, far_h = study.start, study.halved, study.far, study.far_halved
    amp = h.amplitude / s.amplitude
    far_change = abs(far_h.amplitude / far.amplitude - 1)
    reach = [c for c in (study.c_no_peak, study.c_critical) if C_MIN <= c <= max(C_MAX, study.c_start)]
    bullets = [
        f"At the starting point, ω = {num(s.omega)} rad/s ({num(s.ratio, 4)} {W_N}) and c = {num(study.c_start)} N s/m "
        f"(ζ = {num(s.zeta, 3)}), the oscillator is {s.regime}; its steady amplitude is {num(s.amplitude)} m, "
        f"{num(s.magnification, 3)} times the static deflection, and it {_settles(s)}.",
        f"Halving the damping there multiplies the steady amplitude by {num(amp, 3)}; at half the natural frequency "
        f"the same change moves it by {num(100 * far_change, 2)} % only.",
        f"The resonant peak disappears from c = {num(study.c_no_peak)} N s/m (ζ = 1/√2) on, the oscillation of the "
        f"free motion from c = {num(study.c_critical)} N s/m (critical damping) on; "
        + (
            f"{'both lie' if len(reach) == 2 else 'the first lies' if reach == [study.c_no_peak] else 'one lies'} "
            f"within the damping slider's range."
            if reach
            else "both lie beyond the damping slider's range."
        ),
    ]
    return "\n".join(["> **Key results**", ">", *(f"> * {b}" for b in bullets)])


def start_text(study: ExploreStudy) -> str:
    """Where the sliders start, and why when the run's damping cannot be held by a logarithmic slider."""
    p = study.params
    if not study.clamped:
        return (
            f"The sliders start at this run's values: forcing frequency ω = {num(p.omega_res)} rad/s, damping "
            f"c = {num(study.c_start)} N s/m."
        )
    what = "undamped" if p.c_nominal == 0 else "negative damping"
    return (
        f"This run's damping is c = {num(p.c_nominal)} N s/m ({what}); the damping sliders are logarithmic and "
        f"cannot hold it, so they start at their lowest value, c = {num(study.c_start)} N s/m. Chapter 1 shows the "
        f"response at c = {num(p.c_nominal)} N s/m."
    )


def controls_text(study: ExploreStudy) -> str:
    """Which controls exist where: the notebook (all of them) and the online book (ω, c and reset)."""
    return (
        "* **In the notebook** (a running kernel): the forcing frequency ω (rad/s, the Hz value beside it) and the "
        f"damping c (N s/m, logarithmic, from {num(C_MIN)} to {num(C_MAX)} N s/m, through critical damping) redraw "
        "the figure while the slider moves; boxes for m (kg), k (N/m), $F_0$ (N) and the window "
        r"$t_\mathrm{end}$ (s) apply when Enter is pressed (a value out of range is reported in red and the figure "
        "keeps the last valid state); a check box overlays the paper's RK45 solution and its largest deviation "
        "from the exact displacement.\n"
        + "* "
        + web_only(
            "**In the online book** (no kernel)",
            print_text="**In the online book** (no kernel; this printed copy shows its starting state)",
        )
        + ": the same closed form runs in the browser with exactly three "
        f"controls, the forcing frequency ω (steps of {num(OMEGA_STEP)} rad/s), the damping c (logarithmic, at "
        f"least {num(C_MIN)} to {num(C_MAX)} N s/m) and a reset button; m, k, $F_0$, the window and the RK45 "
        "overlay stay at this run's values."
    )


def layout_text(study: ExploreStudy) -> str:
    """What the JupyterLab figure and the book's panel draw, read from the figure and from the panel's CSS."""
    fig, axes, art = build_figure()
    w = figure_words(fig, axes, art)
    f = panel_facts()
    freq_axis = "rad/s below, Hz above" if w["hz"] else "rad/s"
    panel_axis = "in rad/s and Hz" if f.hz_axis else "in rad/s only"
    same = (f.envelope, f.settle, f.natural) == (w["envelope"], w["settle"], w["natural"])
    styles = (
        "in the same line styles"
        if same
        else f"with the amplitudes {f.envelope}, the settling time {f.settle} and {W_N} {f.natural}"
    )
    log = " (logarithmic)" if f.log_magnification else ""
    return (
        f"In the notebook the figure shows the displacement x(t) ({w['x']}) and the velocity v(t) ({w['v']}) from "
        f"rest, the steady-state amplitudes ±|X| and ±ω|X| {w['envelope']} and the 2 % settling time {w['settle']} "
        f"when it falls inside the window; on the {w['m'].split(',')[0]} the magnification $|X|/(F_0/k)$ against "
        f"ω ({freq_axis}) with {W_N} {w['natural']} and the operating point as a dot; with the check box on, the "
        f"paper's RK45 solution is drawn {w['rk45']} over x(t) and v(t).\n\n"
        f"The book's panel draws the same three plots {styles}: the two time plots first, the magnification "
        f"plot{log} beside them"
        + web_only(f" on a page wider than {f.stack_below_px} px and below them on a narrower one")
        + f"; its frequency axis is {panel_axis}."
    )


#: The readout's lines: the quantity as the reader reads it, its field of the readout, its unit (none for a ratio).
_READOUT = text_rows(
    """
    natural frequency ωₙ                omega_n         rad/s
    natural frequency fₙ                f_n             Hz
    forcing frequency ω                 omega           rad/s
    forcing frequency f                 f               Hz
    frequency ratio ω/ωₙ                ratio
    damping ratio ζ                     zeta
    regime                              regime
    magnification |X|/(F₀/k)            magnification
    steady-state amplitude |X|          amplitude       m
    peak |x| in the window              peak            m
    2 % settling time                   settling        s
    steady state reached in the window  steady_reached
    time window                         t_end           s
    """
)


def readout_table(study: ExploreStudy) -> Table:
    """The explorer's readout at the starting point, five significant digits."""
    r = study.start
    rows = [{"q": q, "v": getattr(r, attr), "u": unit[0] if unit else ""} for q, attr, *unit in _READOUT]
    return Table(
        rows=rows,
        columns=columns(
            """
            q  quantity
            v  value     5
            u  unit
            """
        ),
        caption=(
            f"The explorer's readout at its starting point (ω = {num(r.omega)} rad/s, c = {num(study.c_start)} "
            "N s/m): what the live explorer shows before any slider moves."
        ),
        name="tab-explore-start",
    )


def lessons_text(study: ExploreStudy) -> str:
    """Experiments to make with the sliders, each with the numbers the readout will show."""
    s, h, d, far, far_h = study.start, study.halved, study.doubled, study.far, study.far_halved
    c = study.c_start
    ts = (
        f" and the settling time goes from {num(s.settling, 3)} s to {num(h.settling, 3)} s"
        if math.isfinite(s.settling) and math.isfinite(h.settling)
        else ""
    )
    bullets = [
        f"Set the damping to c = {num(c / 2)} N s/m: the steady amplitude at the starting frequency goes from "
        f"{num(s.amplitude)} m to {num(h.amplitude)} m{ts}. Double it instead, to {num(2 * c)} N s/m, and it falls "
        f"to {num(d.amplitude)} m.",
        f"Move the forcing frequency down to ω = {num(far.omega)} rad/s, half of {W_N}: the amplitude there is "
        f"{num(far.amplitude)} m with c = {num(c)} N s/m and {num(far_h.amplitude)} m with half of it.",
        f"Raise the damping past c = {num(study.c_no_peak)} N s/m and watch the peak of the magnification curve "
        f"flatten into a curve that falls from 1; past c = {num(study.c_critical)} N s/m the transient of x(t) stops "
        "oscillating.",
    ]
    return "\n".join("- " + b for b in bullets)


def takeaways(study: ExploreStudy) -> str:
    """What a designer takes away, in new words: the levers the sliders reveal at this run's parameters."""
    s, h, far, far_h = study.start, study.halved, study.far, study.far_halved
    amp, far_amp = h.amplitude / s.amplitude, far_h.amplitude / far.amplitude
    if amp >= DAMPING_SETS:
        near = (
            f"At this forcing frequency ({num(s.ratio, 4)} {W_N}) the damper is the lever: the amplitude is "
            "inversely proportional to c, so each halving of the damping doubles the motion."
        )
    elif amp <= DAMPING_IRRELEVANT:
        near = (
            f"At this forcing frequency ({num(s.ratio, 4)} {W_N}) the damper is no lever: stiffness and mass set the "
            "amplitude, so move the natural frequency instead."
        )
    else:
        near = (
            f"At this forcing frequency ({num(s.ratio, 4)} {W_N}) damping and the distance to resonance both set "
            "the amplitude: a stronger damper and a retuned natural frequency each help."
        )
    far_text = (
        "Well below resonance the spring carries the force and the damper hardly matters; designs that must run "
        "there need stiffness, not damping."
        if far_amp <= DAMPING_IRRELEVANT
        else "Even well below resonance the damping changes the amplitude noticeably here, a sign of heavy damping."
    )
    return "\n".join(
        [
            "- " + near,
            "- " + far_text,
            "- " + _heavy(study),
        ]
    )


def _heavy(study: ExploreStudy) -> str:
    """What heavy damping does to the settling time at the starting frequency, from three readouts."""
    s, crit, twice = study.start, study.critical, study.twice_critical
    if not all(math.isfinite(r.settling) for r in (s, crit, twice)):
        return "Without positive damping the transient never dies out: any real design needs some."
    trend = (
        f"and rises again to {num(twice.settling, 3)} s at twice that, because an overdamped motion creeps"
        if twice.settling > crit.settling
        else f"and keeps falling, to {num(twice.settling, 3)} s at twice that"
    )
    return (
        f"Damping also buys a quick steady state, up to a point: at the starting frequency the settling time "
        f"goes from {num(s.settling, 3)} s to {num(crit.settling, 3)} s at critical damping "
        f"(c = {num(study.c_critical)} N s/m) {trend}."
    )
