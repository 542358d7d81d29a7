r"""Chapter 8's sentences (Markdown), each rendered from a :class:`~vibration.book.chapters.tmd.study.TMDStudy`.

Every comparison word ("higher", "falls", "keeps most of it") is chosen from the numbers it states, so
a run with other parameters never contradicts its own tables. Symbols are typeset as Markdown maths
(``$\zeta_p$``); numbers print to fixed significant figures, never in e-notation.
"""

from __future__ import annotations

import math

from vibration.book.chapters.tmd.designs import (
    CLOSED,
    DEN_HARTOG,
    DESIGNS,
    H2,
    HINF,
    HINF_CLOSED,
    ROBUST,
    RULES,
    TUNINGS,
    Design,
)
from vibration.book.chapters.tmd.digits import pct, sig
from vibration.book.chapters.tmd.keyresults import worst_peak
from vibration.book.chapters.tmd.study import TMDStudy
from vibration.book.presentation.numbers import signed

ZP, ZA, F, R = r"$\zeta_p$", r"$\zeta_a$", "$f$", r"$r = \omega/\omega_p$"
__all__ = [
    "building_sentence",
    "chapter_texts",
    "design_sentence",
    "key_results",
    "response_sentence",
    "robustness_sentence",
    "stroke_sentence",
    "takeaways",
    "tuning_sentence",
]


def _rel(a: float, b: float) -> str:
    """|a/b − 1| in per cent, 3 significant figures, with "higher" or "lower" (or "equal")."""
    d = a / b - 1.0
    if abs(d) < 5e-6:
        return "equal to within 0.001 %"
    return f"{pct(abs(d))} {'higher' if d > 0 else 'lower'}"


def _change(before: float, after: float, unit: str) -> str:
    """ "falls from 2.000 to 1.000 m (50.0 % lower)", or "rises ..." when it grows, from the numbers themselves."""
    verb = "falls" if after <= before else "rises"
    return f"{verb} from {sig(before)} to {sig(after)} {unit} ({_rel(after, before)})"


def _the(design: Design) -> str:
    words = design.prose
    return words if words.startswith(("Den Hartog", "Warburton")) else f"the {words}"


def _band(st: TMDStudy) -> str:
    return f"±{100 * st.mistuning:g} %"


# ----------------------------------------------------------------------------- the front


def key_results(st: TMDStudy) -> str:
    """The key-results box: the chapter's headline numbers as a Markdown block quote."""
    return "\n".join(["> **Key results**", ">"] + [f"> * {s}" for s in key_findings(st)])


def key_findings(st: TMDStudy) -> list[str]:
    """Four or five computed one-sentence findings (the key-results box)."""
    h = st.scores[HINF]
    closed = {r: st.peaks_actual[st.mu][r] for r in CLOSED}
    alt = min(closed, key=closed.get)
    out = [
        f"An absorber of {100 * st.mu:g} % of the primary's mass, tuned for the primary's damping, makes the steady "
        f"amplitude at the paper's forcing frequency ω = {st.omega_res:g} rad/s "
        f"{_rel(st.amp_with, st.amp_without)} than without it ({sig(st.amp_without)} m → {sig(st.amp_with)} m).",
        f"The tuning that accounts for the primary's damping ({ZP} = {sig(st.zeta_p, 3)}) holds the peak "
        f"magnification to {sig(h.nominal_peak)}, {_rel(h.nominal_peak, closed[alt])} than the best tuning derived "
        f"for an undamped primary (here {alt.noun}).",
    ]
    if st.mistuning > 0.0:
        rb = st.scores[ROBUST]
        out.append(
            f"If the primary's stiffness may be off by up to {_band(st)}, the robust min-max design's worst peak is "
            f"{sig(worst_peak(st, ROBUST))}, {_rel(worst_peak(st, ROBUST), worst_peak(st, HINF))} than "
            f"the H∞ optimum's, for a nominal peak "
            f"{_rel(rb.nominal_peak, h.nominal_peak)}."
        )
    out.append(
        f"The absorber's travel relative to the primary is {sig(h.stroke_force * st.x_static / st.amp_with, 3)} "
        f"times the primary's own amplitude at the paper's forcing frequency ({sig(h.stroke_force * st.x_static)} m "
        f"for F₀ = {st.F0:g} N)."
    )
    force, ground = st.load_cases
    out.append(
        f"On the {st.building.n}-storey shear building a roof absorber of {100 * st.mu_building:g} % of the first "
        f"modal mass leaves the roof's largest response near the first mode {_rel(1 - force.reduction, 1.0)} under a "
        f"roof force and {_rel(1 - ground.reduction, 1.0)} under ground acceleration."
    )
    return out


# ----------------------------------------------------------------------------- body


def tuning_sentence(st: TMDStudy) -> str:
    """The rules compared at the run's mass ratio, on an undamped and on the actual primary."""
    r = st.tunings[st.mu]
    dh, hinf, h2, num = (r[x] for x in RULES)
    pa = st.peaks_actual[st.mu]
    return (
        f"At μ = {st.mu:g} on an undamped primary, the closed-form H∞ optimum ({F} = {sig(hinf.f)}, "
        f"{ZA} = {sig(hinf.zeta_a)}) holds the peak magnification to {sig(hinf.peak, 5)}, against "
        f"{sig(dh.peak, 5)} for Den Hartog's rule ({_rel(dh.peak, hinf.peak)}) and {sig(h2.peak, 5)} for "
        f"Warburton's H2 tuning ({_rel(h2.peak, hinf.peak)}). On the actual primary ({ZP} = "
        f"{sig(st.zeta_p, 3)}) the H∞ optimum moves to {F} = {sig(num.f)}, {ZA} = {sig(num.zeta_a)} and a peak "
        f"of {sig(num.peak)}; there Den Hartog's tuning gives {sig(pa[DEN_HARTOG])} and the closed-form H∞ tuning "
        f"{sig(pa[HINF_CLOSED])}."
    )


def response_sentence(st: TMDStudy) -> str:
    """The reduction at the paper's forcing frequency, steady and over the window."""
    return (
        f"At ω = {st.omega_res:g} rad/s the primary's steady amplitude {_change(st.amp_without, st.amp_with, 'm')} "
        f"with an absorber of {st.mu:g} times its mass, which itself swings {sig(st.amp_absorber)} m; the largest "
        f"displacement in the {st.t_end:g} s window {_change(st.peak_without, st.peak_with, 'm')}."
    )


def robustness_sentence(st: TMDStudy) -> str:
    """How much of its benefit the H∞ optimum keeps off-nominal, against the min-max optimum of that criterion."""
    h, rb = st.scores[HINF], st.scores[ROBUST]
    e = f"{100 * st.mistuning:g}"
    if st.mistuning == 0.0:
        return (
            "With no stiffness error to guard against there is nothing to be robust against: the min-max design is "
            f"the H∞ optimum, whose worst peak is its nominal peak, {sig(h.nominal_peak)}."
        )
    if math.isfinite(h.kept_low):
        kept = min(h.kept_low, h.kept_high)
        text = (
            f"When the primary's stiffness is {e} % low, the H∞ optimum keeps {pct(h.kept_low)} of its benefit (the "
            f"bare primary's peak minus its own, against the nominal benefit), and {pct(h.kept_high)} when it is "
            f"{e} % high: "
            + (
                "it degrades, it does not collapse. "
                if kept >= 0.5
                else "it loses most of it. "
                if kept >= 0.0
                else "it does worse than no absorber at one end. "
            )
        )
    else:
        text = "The bare primary is undamped (its peak is infinite), so the share of the benefit kept is not defined. "
    bare = float(st.robust_none.max())
    text += (
        f"Over the whole {_band(st)} band its worst peak is {sig(h.worst_peak)} (at $k_p$ "
        f"{signed(100 * h.eps_worst, 3)} %), against "
        f"{sig(bare) if math.isfinite(bare) else 'an unbounded peak'} without "
        f"an absorber. The robust min-max design ({F} = {sig(rb.tuning.f)}, {ZA} = {sig(rb.tuning.zeta_a)}) holds "
        f"the worst peak to {sig(rb.worst_peak)} ({_rel(rb.worst_peak, h.worst_peak)}) at the price of a nominal "
        f"peak of {sig(rb.nominal_peak)} instead of {sig(h.nominal_peak)} ({_rel(rb.nominal_peak, h.nominal_peak)})."
    )
    best = min(TUNINGS, key=lambda n: st.scores[n].worst_peak)
    if best != ROBUST and st.scores[best].worst_peak < rb.worst_peak * (1 - 1e-9):
        text += (
            f" The min-max search fell short: {_the(best)} has a lower worst peak ({sig(st.scores[best].worst_peak)})."
        )
    return text


def _optimum_words(st: TMDStudy, key: str, owner: Design, what: str) -> str:
    """Which design wins one criterion, and whether it is the design that optimises it."""
    vals = {n: getattr(st.scores[n], key) for n in DESIGNS if math.isfinite(getattr(st.scores[n], key))}
    if not vals:
        return ""
    best = min(vals, key=vals.get)
    if best == owner or math.isclose(vals[best], vals[owner], rel_tol=1e-9):
        return f"the {owner.prose} has the lowest {what} ({sig(vals[owner])})"
    return (
        f"the lowest {what} is that of {_the(best)} ({sig(vals[best])}), not the {owner.prose}'s "
        f"({sig(vals[owner])}): its optimisation did not reach the optimum"
    )


def design_sentence(st: TMDStudy) -> str:
    """Each criterion's optimum on its own criterion, and what it costs on the others."""
    h, h2, rb = (st.scores[n] for n in (HINF, H2, ROBUST))
    wins = [
        _optimum_words(st, "nominal_peak", HINF, "nominal peak"),
        _optimum_words(st, "worst_peak", ROBUST, f"worst peak over {_band(st)}") if st.mistuning > 0 else "",
        _optimum_words(st, "rms_ratio", H2, "rms displacement under white noise"),
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
    if st.mistuning > 0.0:
        text += (
            f"; the robust min-max design accepts a nominal peak {_rel(rb.nominal_peak, h.nominal_peak)} than the "
            f"H∞ optimum's for a worst peak {_rel(rb.worst_peak, h.worst_peak)}."
        )
    else:
        text += "; with no stiffness error to guard against, the min-max design is the H∞ optimum."
    return text


def stroke_sentence(st: TMDStudy) -> str:
    """The absorber's stroke at the load case and at its largest, which none of the designs limits."""
    xs = st.x_static
    h = st.scores[HINF]
    zmin = min(DESIGNS, key=lambda n: st.scores[n].stroke_peak)
    return (
        "What the peak magnification does not show is the absorber's stroke, its travel relative to the primary: "
        f"at ω = {st.omega_res:g} rad/s ({R} = {sig(st.r_force)}) the H∞ optimum's absorber travels "
        f"{sig(xs * h.stroke_force)} m for $F_0$ = {st.F0:g} N, {sig(h.stroke_force * xs / st.amp_with, 3)} times "
        f"the primary's own amplitude, and {sig(xs * h.stroke_peak)} m at the worst frequency. Of the four designs "
        f"{_the(zmin)} has the smallest largest stroke ({sig(xs * st.scores[zmin].stroke_peak)} m); none of them "
        "limits the stroke, so an absorber with little room to move needs a stroke-constrained design, which this "
        "chapter does not compute."
    )


def building_sentence(st: TMDStudy) -> str:
    """The roof absorber and the reduction of the roof's resonant response under both loads."""
    a = st.absorber
    force, ground = st.load_cases
    tuned = (
        f"for the mode's damping ratio {sig(a.zeta, 3)}"
        if math.isclose(a.tuning.zeta_p, a.zeta, rel_tol=1e-12)
        else f"for a damping ratio of {sig(a.tuning.zeta_p, 3)} (the optimiser's limit; the mode's is {sig(a.zeta, 3)})"
    )
    classical = (
        "The building's damping is classical; with the absorber it is not, so its modes are complex and the poles "
        "take over from modal damping ratios."
        if st.building.is_classically_damped and not st.building_tmd.is_classically_damped
        else "The building keeps classical damping with the absorber."
        if st.building_tmd.is_classically_damped
        else "The building's damping is not classical, so its poles are used throughout."
    )
    return (
        f"A roof absorber of {sig(a.m_a)} kg ({st.mu_building:g} of the first modal mass, {sig(a.modal_mass)} kg), "
        f"tuned by the numerical H∞ rule {tuned} ({F} = {sig(a.tuning.f)}, {ZA} = {sig(a.tuning.zeta_a)}; "
        f"$k_a$ = {sig(a.k_a)} N/m, $c_a$ = {sig(a.c_a)} N s/m): the largest roof displacement per roof force near "
        f"the first mode {_change(force.scale * force.peak_without, force.scale * force.peak_with, force.unit)}. "
        "Under ground acceleration the roof's largest displacement relative to the ground "
        f"{_change(ground.scale * ground.peak_without, ground.scale * ground.peak_with, ground.unit)}; the first "
        f"mode carries {pct(st.effective_mass_share)} of the building's mass as effective modal mass under ground "
        f"motion. {classical}"
    )


# ----------------------------------------------------------------------------- the end


def takeaways(st: TMDStudy) -> str:
    """What a designer takes away: conclusions in new words, as a Markdown list."""
    h = st.scores[HINF]
    closed = {r: st.peaks_actual[st.mu][r] for r in CLOSED}
    alt = min(closed, key=closed.get)
    gain = 1.0 - h.nominal_peak / closed[alt]
    items = [
        (
            f"**Tune for the primary you have.** Formulas derived for an undamped primary leave "
            f"{pct(gain)} of peak magnification on the table at {ZP} = {sig(st.zeta_p, 3)}; a two-parameter "
            "numerical search removes it."
            if gain >= 0.01
            else f"**The closed forms suffice here.** At {ZP} = {sig(st.zeta_p, 3)} tuning for the damping gains "
            f"only {pct(gain)} on the peak, so a closed-form rule is as good as the search."
        ),
    ]
    mus = sorted(st.tunings)
    peaks = [st.peaks_actual[x][HINF] for x in mus]
    slopes = [(peaks[i] - peaks[i + 1]) / math.log(mus[i + 1] / mus[i]) for i in range(len(mus) - 1)]
    diminishing = all(a >= b for a, b in zip(slopes, slopes[1:], strict=False))
    verb = "falls" if peaks[-1] <= peaks[0] else "rises"
    items.append(
        f"**Mass buys reduction{', with diminishing returns' if diminishing else ''}.** From μ = {mus[0]:g} to "
        f"μ = {mus[-1]:g}, {mus[-1] / mus[0]:g} times the absorber mass, the optimal peak on this primary {verb} "
        f"from {sig(peaks[0])} to {sig(peaks[-1])}"
        + (", and each further doubling of the mass gains less than the one before." if diminishing else ".")
    )
    if st.mistuning > 0.0:
        rb = st.scores[ROBUST]
        kept = min(h.kept_low, h.kept_high)
        verdict = (
            "An absorber tuned for the nominal primary tolerates the stiffness error"
            if math.isfinite(kept) and kept >= 0.5
            else "An absorber tuned for the nominal primary loses much of its benefit under the stiffness error"
        )
        items.append(
            f"**Buy robustness only for real uncertainty.** {verdict}; designing for the whole {_band(st)} band "
            f"trades {pct(rb.nominal_peak / h.nominal_peak - 1.0)} on the nominal peak for "
            f"{pct(1.0 - rb.worst_peak / h.worst_peak)} on the worst one."
        )
    travel = h.stroke_force * st.x_static / st.amp_with
    items.append(
        "**Size the rattle space first.** The absorber moves "
        f"{'several times as far as' if travel >= 2 else 'farther than'} the structure it protects, and none of the "
        "tunings here limits that travel."
        if travel > 1
        else "**Check the rattle space.** Here the absorber moves less than the primary, so its travel is no limit."
    )
    force, ground = st.load_cases
    items.append(
        "**One absorber serves both loads of a building.** Tuned to the first mode, it acts on a roof force and on "
        f"ground shaking alike, because that mode carries {pct(st.effective_mass_share, 2)} of the mass under "
        "ground motion."
        if force.reduction > 0 and ground.reduction > 0
        else "**Check every load of a building.** The roof absorber does not lower the roof's response under both "
        "loads here."
    )
    return "\n".join(f"* {i}" for i in items)


def chapter_texts(st: TMDStudy) -> dict[str, str]:
    """Every sentence of the chapter by name (the key results and take-aways one entry per bullet)."""
    out = {f"key result {i + 1}": s for i, s in enumerate(key_findings(st))}
    out |= {
        "tuning": tuning_sentence(st),
        "response": response_sentence(st),
        "robustness": robustness_sentence(st),
        "design": design_sentence(st),
        "stroke": stroke_sentence(st),
        "building": building_sentence(st),
    }
    out |= {f"take-away {i + 1}": line[2:] for i, line in enumerate(takeaways(st).splitlines())}
    return out
