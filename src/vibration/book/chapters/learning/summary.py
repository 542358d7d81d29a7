"""The chapter's key-results box and its closing "what a designer takes away", from a :class:`LearningStudy`.

The box states the headline numbers; the summary states conclusions in other words, each against
the optimum and the best alternative (no sentence of the body is repeated).
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.learning.notation import num, pct
from vibration.book.chapters.learning.study import METHODS, TARGETS, LearningStudy
from vibration.book.chapters.learning.tables import SHORT_NAMES
from vibration.book.chapters.learning.text import TARGET, _steps, compared
from vibration.book.presentation.numbers import integer


def _best_learner(st: LearningStudy):
    return min(st.learners, key=lambda r: r.expected_cost)


def key_results(st: LearningStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    return "\n".join(["> **Key results**", ">"] + [f"> * {s}" for s in key_findings(st)])


def key_findings(st: LearningStudy) -> list[str]:
    """Four computed headline sentences."""
    ratios = " and ".join(
        f"{SHORT_NAMES[r.method]} {st.ratio(r):.5f} after {integer(r.episodes)} episodes" for r in st.learners
    )
    worst = max(sd.worst_ratio for sd in st.seeds) - 1.0
    n_seeds = st.seeds[0].seeds.size
    all_in = all(sd.reached == sd.seeds.size for sd in st.seeds)
    seeds = (
        f"every one of {n_seeds} seeds per learner ends within {pct(TARGET, 2)} (worst {pct(worst, 2)} above)"
        if all_in
        else f"not every one of {n_seeds} seeds per learner comes within {pct(TARGET, 2)} (worst {pct(worst, 2)} above)"
    )
    g_exo, _ = st.excess_over_optimum
    fixed = st.learned_vs("best fixed gain")
    lqr_vs_learned = st.paired(st.active, st.a("learned (ARS)"), st.a("LQR"))
    kind = "optimum" if st.exo.within_bound else "exact lower bound"
    reached = all(st.ratio(r) <= 1.0 + TARGET for r in st.learners)
    lower = "" if st.ref.peak_force <= st.task.u_max else " (with the force bound binding, a lower bound)"
    head = (
        f"From episodes alone the learners reach the LQR optimum{lower} of the undisturbed task"
        if reached
        else f"From episodes alone the learners do not all come within {pct(TARGET, 2)} of the LQR optimum{lower} "
        "of the undisturbed task"
    )
    return [
        f"{head}: learned cost over optimal cost {ratios}; {seeds}.",
        f"Under the resonance force the learned law {compared(fixed, 'the best fixed gain on $[x, v]$')} and lies "
        f"{pct(g_exo)} above the task's {kind}, which uses the forcing phase; LQR, designed without the force, "
        f"{compared(lqr_vs_learned, 'the learned law')}.",
        f"With a semi-active damper the learned clipped law "
        f"{compared(st.semi_vs('best constant damping'), 'the best constant damping')}.",
        f"A plant model identified from {integer(st.id_design.samples)} samples of one test record, then designed on, "
        f"{compared(st.identify_vs_learned, 'the learned law')}; the learner used {_steps(st.training_steps)} "
        "simulated steps.",
    ]


def summary_text(st: LearningStudy) -> str:
    """What a designer takes away: conclusions, each against the optimum and the best alternative."""
    return "\n".join(f"* {s}" for s in takeaways(st))


def takeaways(st: LearningStudy) -> list[str]:
    """Five conclusions in words, computed."""
    return [_compute_first(st), _fair_yardstick(st), _semi_takeaway(st), _robust_takeaway(st), _data_takeaway(st)]


def _compute_first(st: LearningStudy) -> str:
    fine = TARGETS[-1]
    reach = {r.method: st.episodes_to(r, fine) for r in st.learners}
    done = [m for m in METHODS if math.isfinite(reach[m])]
    if not done:
        return (
            "**Where the model is known, compute the optimum.** One Riccati solution gives $J^*$ exactly; neither "
            f"learner came within {pct(fine, 2)} of it on its training budget."
        )
    fast = min(done, key=lambda m: reach[m])
    rest = [m for m in METHODS if m != fast]
    other = ", ".join(
        f"{SHORT_NAMES[m]} {integer(int(reach[m]))}" if math.isfinite(reach[m]) else f"{SHORT_NAMES[m]} never did"
        for m in rest
    )
    return (
        "**Where the model is known, compute the optimum.** One Riccati solution gives $J^*$ exactly; the quicker "
        f"learner, {SHORT_NAMES[fast]}, spent {integer(int(reach[fast]))} training episodes "
        f"({_steps(int(reach[fast]) * st.task.n_steps)} simulated steps) to come within {pct(fine, 2)} of it "
        f"({other})."
    )


def _fair_yardstick(st: LearningStudy) -> str:
    lqr = st.learned_vs("LQR")
    fixed = st.learned_vs("best fixed gain")
    g_exo, se_exo = st.excess_over_optimum
    if lqr.resolved and lqr.diff < 0:
        flattering = f"Against LQR, a law designed for another task, the learner looks {pct(-lqr.rel, 2)} better"
    else:
        flattering = "Even LQR, a law designed for another task, is not beaten by the learner"
    if not fixed.resolved:
        fair = "the fair yardstick, the best fixed gain on $[x, v]$, is matched within the sampling error"
    else:
        word = "beaten" if fixed.diff < 0 else "missed"
        fair = f"the fair yardstick, the best fixed gain on $[x, v]$, is {word} by {pct(abs(fixed.rel), 2)}"
    if g_exo > 3.0 * se_exo:
        phase = (
            f" The {pct(g_exo, 2)} still separating it from the exact optimum is what knowing the forcing phase is "
            "worth: give the controller the phase rather than more training."
        )
    else:
        phase = " Nothing measurable is left to gain from the forcing phase."
    return f"**Judge a learner by the best law that sees the same signals.** {flattering}; {fair}.{phase}"


def _semi_takeaway(st: LearningStudy) -> str:
    p = st.semi_vs("best constant damping")
    frac = st.bound_fraction(st.s("learned (ARS)"))
    if p.resolved and p.diff < 0:
        head = f"**A learned semi-active law pays, modestly.** It saves {pct(-p.rel, 2)} against the best fixed damper"
    elif p.resolved:
        head = f"**Here a fixed damper is the better semi-active choice.** The learned law loses {pct(p.rel, 2)} to it"
    else:
        head = "**A learned semi-active law buys nothing here.** It ties with the best fixed damper"
    use = (
        "mostly a switch between the damper's two extremes"
        if frac > 0.5
        else "a continuous use of the range between the damper's extremes"
    )
    return f"{head}; what it learned is {use} ({pct(frac, 2)} of the time on a bound)."


def _robust_takeaway(st: LearningStudy) -> str:
    ratio = st.robust_ratio()
    laws = st.robust.laws
    j_l, j_q = laws.index("learned (ARS)"), laws.index("LQR")
    keeps = bool(np.all(ratio[:, j_l] < ratio[:, j_q]))
    verdict = (
        "keeps its advantage over LQR on every change tried"
        if keeps
        else "loses its advantage over LQR on at least one change"
    )
    head = (
        "Plant changes of the size tried do not undo the result."
        if keeps
        else "A changed plant can undo the learned law's advantage."
    )
    return (
        f"**{head}** Run unchanged, the learned law stays within "
        f"{num(ratio[:, j_l].max())} times each changed plant's optimum (LQR up to {num(ratio[:, j_q].max())} times) "
        f"and {verdict}."
    )


def _data_takeaway(st: LearningStudy) -> str:
    p = st.identify_vs_learned
    ratio = st.training_steps / st.id_design.samples
    if not p.resolved or p.diff < 0:
        how = "as good a law"
    else:
        how = f"a law within {pct(p.rel, 2)} of the learned one"
    return (
        f"**Measured data are cheaper than trials.** A short identification record gives {how} from "
        f"{num(ratio, 2)} times fewer samples than the learner's training."
    )
