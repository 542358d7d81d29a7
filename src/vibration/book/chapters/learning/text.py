"""Sentences of the learning chapter, each a function of a :class:`LearningStudy`.

Word conventions (the tests check them against the numbers): a learner "meets" a target when its
expected cost is within that fraction of the optimum; two laws compared on the same episodes cost
"the same within the sampling error" unless their paired difference exceeds
:data:`~vibration.book.chapters.learning.study.RESOLVED_Z` standard errors, else one costs "more" or
"less"; the exact optimum of the disturbed task is "the task's optimum" when its force stays within
the bound, else "a lower bound"; the force bound "binds" when a law's largest force reaches it.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.learning.notation import num, pct, sig
from vibration.book.chapters.learning.study import METHODS, TARGETS, LearningStudy, Paired
from vibration.book.chapters.learning.tables import EXCESS_FLOOR, METHOD_NAMES, SHORT_NAMES, decay_rates
from vibration.book.presentation.numbers import integer, pm

#: The first target (5 %): the chapter's yardstick for "found the optimum".
TARGET = TARGETS[0]
#: A gain changes the plant "mostly by damping" when the displacement gain is below this fraction of k.
STIFFNESS_SMALL = 0.1
#: The finite-horizon and the infinite-horizon costs "agree" within this relative difference.
HORIZON_AGREE = 1e-3


def _law(g) -> str:
    """``u = -K_x x - K_v v`` with the signs written out (LaTeX)."""
    kx, kv = (float(z) for z in g)
    return f"u = {'-' if kx >= 0 else ''}{num(abs(kx), 4)}\\,x {'-' if kv >= 0 else '+'} {num(abs(kv), 4)}\\,v"


def _gains(g, digits: int = 3) -> str:
    return f"$K = [{num(g[0], digits)}, {num(g[1], digits)}]$"


def _steps(n: int) -> str:
    """Simulated steps in words: "3.2 million", or a count grouped by the book's rule, "960 000"."""
    return f"{num(n / 1e6, 3)} million" if n >= 1_000_000 else integer(n)


def compared(p: Paired, other: str, verb: str = "costs") -> str:
    """The learned law against ``other``: "costs 2.6 % less than X (± 0.5 %)" or "costs the same as X within the
    sampling error (+0.06 % ± 0.01 %)"."""
    if not p.resolved:
        return f"{verb} the same as {other} within the sampling error ({pct(p.rel, 2)} ± {pct(p.rel_se, 1)})"
    return f"{verb} {pct(abs(p.rel))} {'more' if p.diff > 0 else 'less'} than {other} (± {pct(p.rel_se, 2)})"


def _pm(x: float, se: float) -> str:
    """``x ± se`` in the book's format (:func:`vibration.book.presentation.numbers.pm`), for a formula."""
    return pm(x, se).replace("±", "\\pm")


def _cap(text: str) -> str:
    return text[:1].upper() + text[1:]


# ----------------------------------------------------------------------------- the model


def platform_text(st: LearningStudy) -> str:
    """The training platform: the sampled oscillator, its observation, action, cost and episodes."""
    t = st.task
    return (
        "The training platform is the paper's oscillator $m\\ddot x + c\\dot x + kx = u + F(t)$ as a standard "
        f"reinforcement-learning environment, sampled every $\\Delta t = {num(t.dt, 3)}$ s with an exact "
        "zero-order hold: the action is held over the step and the state is carried forward by the matrix "
        "exponential, so the environment has no integration error. The agent observes $s = [x, v]$ and applies a "
        "force $u$, bounded by "
        f"$u_\\mathrm{{max}} = {num(t.u_max, 4)}$ N; each step costs $(x^2 + v^2 + r u^2)\\,\\Delta t$ with "
        f"$r = {num(t.r, 3)}$ N⁻² (the reward is its negative). An episode lasts {integer(t.n_steps)} steps "
        f"({num(t.n_steps * t.dt, 4)} s) from a state drawn uniformly in $[-{num(t.x0_max, 3)}, {num(t.x0_max, 3)}]$ "
        f"m × $[-{num(t.v0_max, 3)}, {num(t.v0_max, 3)}]$ m/s, and the *expected cost* $J$ of a controller is the "
        "mean, over that distribution, of the episode's summed cost (in seconds: every term is dimensionless "
        "per second). A linear law is $u = -K s = -K_x x - K_v v$. Two options change the task: the resonance "
        "force $F_0 \\sin(\\omega t)$ on the mass, and a semi-active damper whose action is its damping coefficient "
        "$c \\in [c_\\mathrm{min}, c_\\mathrm{max}]$ instead of a force."
    )


def lqr_sentence(st: LearningStudy) -> str:
    """The optimum in words: the law, its closed-loop modes, its cost, whether the force bound binds."""
    task, ref = st.task, st.ref
    poles = np.log(ref.poles.astype(complex)) / task.dt
    if np.any(np.abs(poles.imag) > 1e-9 * np.abs(poles).max()):
        p = poles[np.argmax(poles.imag)]
        modes = f"a damped oscillation decaying at {num(-p.real)} s⁻¹ with frequency {num(abs(p.imag))} rad/s"
    else:
        rates = decay_rates(st)
        modes = f"two real modes decaying at {num(rates[0])} and {num(rates[1])} s⁻¹"
    stiff = abs(ref.gains[0]) / task.k
    change = f"the displacement gain changes the spring stiffness by {pct(stiff, 2)}"
    kind = f"mostly damping ({change})" if stiff < STIFFNESS_SMALL else f"damping and stiffness ({change})"
    within = ref.peak_force <= task.u_max
    return (
        f"The optimal law is ${_law(ref.gains)}$ (N): {kind}, which gives the closed loop {modes}. Its expected "
        f"cost over an episode is $J^* = {num(ref.expected_cost, 4)}$ s, and its largest force over every initial "
        f"state, {num(ref.peak_force)} N, {'stays below' if within else 'exceeds'} the bound of "
        f"{num(task.u_max, 4)} N, so the bound {'does not change' if within else 'changes'} the problem."
    )


def horizon_sentence(st: LearningStudy) -> str:
    """Why LQR is the task's optimum (or a lower bound when the force bound binds), and what the finite episode
    costs it."""
    ref, task = st.ref, st.task
    gap = ref.expected_cost / ref.infinite_horizon_cost - 1.0
    if abs(gap) <= HORIZON_AGREE:
        horizon = (
            f"over {integer(task.n_steps)} steps the stationary gain is as good as the time-varying finite-horizon "
            f"optimum: $J^*$ and its infinite-horizon value agree to better than {pct(HORIZON_AGREE, 1)}"
        )
    else:
        horizon = (
            f"over only {integer(task.n_steps)} steps the episode ends before the state has decayed, so $J^*$ and its "
            f"infinite-horizon value differ by {pct(abs(gap), 2)}, and the time-varying finite-horizon law could do "
            "slightly better than the stationary gain"
        )
    best = (
        "the discrete LQR gain is the best law for the task"
        if ref.peak_force <= task.u_max
        else "the discrete LQR gain would be the best law if the force were unbounded; since its force exceeds the "
        "bound, its cost $J^*$ is a lower bound that no law of the bounded task can beat"
    )
    return (
        "Because the environment's stage cost is exactly $s^\\top Q s + u^\\top R u$ with "
        "$Q = \\Delta t\\,\\mathrm{diag}(1, 1)$ and $R = \\Delta t\\, r$ on the sampled plant, "
        f"{best}, and its expected cost $J^*$ is computed without sampling (the second moment of the state propagated "
        f"from the uniform initial distribution); {horizon}."
    )


# ----------------------------------------------------------------------------- learning the gains


def learning_sentence(st: LearningStudy) -> str:
    """The headline: learned-to-LQR cost ratio of every learner and what it took."""
    parts = []
    for res in st.learners:
        parts.append(
            f"{METHOD_NAMES[res.method]} reaches $J/J^* = {sig(st.ratio(res), 6)}$ after {res.episodes} episodes "
            f"({_steps(res.episodes * st.task.n_steps)} steps), with gains {_gains(res.gains, 4)}"
        )
    ok = all(st.ratio(r) <= 1.0 + TARGET for r in st.learners)
    verdict = (
        f"Both meet the {pct(TARGET, 2)} target."
        if ok
        else f"Not every learner meets the {pct(TARGET, 2)} target in this run."
    )
    worst = max(st.learners, key=lambda r: r.expected_cost)
    err = np.abs(worst.gains - st.ref.gains)
    rel_gain = float(np.linalg.norm(worst.gains - st.ref.gains) / np.linalg.norm(st.ref.gains))
    excess = st.ratio(worst) - 1.0
    flat = (
        f": the cost is flat near the optimum, an error of {pct(rel_gain, 2)} in the gains costs {pct(excess, 2)}"
        if excess < rel_gain
        else ""
    )
    return (
        "; ".join(parts) + f". {verdict} The worse of the two, {SHORT_NAMES[worst.method]}, is off the LQR gains by "
        f"{num(err[0], 2)} N/m in $K_x$ and {num(err[1], 2)} N s/m in $K_v$ for {pct(excess, 2)} more cost{flat}."
    )


def _excess_words(v: float) -> str:
    return num(v, 2) if abs(v) >= EXCESS_FLOOR else f"below {num(EXCESS_FLOOR, 1)}"


def seed_sentence(st: LearningStudy) -> str:
    """Median and worst outcome of each learner over its seeds."""
    parts = []
    for sd in st.seeds:
        text = (
            f"over {sd.seeds.size} seeds {METHOD_NAMES[sd.method]} ends at a median $J/J^* - 1$ of "
            f"{_excess_words(sd.median_ratio - 1)} and a worst of {_excess_words(sd.worst_ratio - 1)}; "
            f"{sd.reached} of {sd.seeds.size} seeds come within {pct(sd.target, 2)}"
        )
        if math.isfinite(sd.worst_episodes):
            text += f", after {num(sd.median_episodes, 4)} episodes (median; worst {num(sd.worst_episodes, 4)})"
        parts.append(text)
    return _cap("; ".join(parts)) + "."


def curvature_sentence(st: LearningStudy) -> str:
    """How the cost's valley and common random numbers decide how close each learner gets."""
    curv = st.curvature
    ars, cma = (st.seed_result(m) for m in METHODS)
    out = (
        f"At the optimum the Hessian of $J$ in $(K_x, K_v)$ has eigenvalues in the ratio {num(curv.ratio)} : 1; the "
        f"flat direction, the valley, is $(\\Delta K_x, \\Delta K_v) \\propto ({num(curv.valley[0], 3)}, "
        f"{num(curv.valley[1], 3)})$, {num(curv.valley_angle)}° from the $K_x$ axis, so along it both gains change "
        "together and the cost changes least. Each training objective is the mean cost over the iteration's initial "
        "states, the same states for every candidate (common random numbers). "
    )
    if st.ref.peak_force <= st.task.u_max:
        out += (
            "Without a disturbance and with the force within its bound, the episode cost from any one initial state "
            "$s_0$ is $s_0^\\top M(K) s_0$, and the LQR gain minimises $M(K)$ for every $s_0$ at once: every sampled "
            "objective has the same minimiser, so the sampling noise vanishes at the optimum. "
        )
    else:
        out += (
            "Here the bound clips LQR's force, so the episode cost is no longer a quadratic form of the initial state "
            "and the sampled objectives need not share a minimiser: the sampling noise does not vanish at the "
            "optimum. "
        )
    worst_a, worst_c = ars.worst_ratio - 1.0, cma.worst_ratio - 1.0
    if worst_c < EXCESS_FLOOR <= worst_a:
        out += (
            "CMA-ES, which shrinks its steps, converges to rounding level (worst $J/J^* - 1$ over its seeds "
            f"{_excess_words(worst_c)}); augmented random search keeps a fixed step and wanders along the valley "
            f"(worst {_excess_words(worst_a)})."
        )
    else:
        closer = "CMA-ES" if worst_c < worst_a else "augmented random search"
        out += (
            f"Over the seeds {closer} ends closer to $J^*$ (worst $J/J^* - 1$: CMA-ES {_excess_words(worst_c)}, "
            f"augmented random search {_excess_words(worst_a)})."
        )
    return out


# ----------------------------------------------------------------------------- the tasks without a closed form


def active_sentence(st: LearningStudy) -> str:
    """The learned law under the resonance force against the simple alternatives, and whether it saturates."""
    run = st.active.runs[st.a("learned (ARS)")]
    u_max = st.res_task.u_max
    sat = run.peak_u >= u_max * (1.0 - 1e-9)
    tail = (
        f"Its gains, {_gains(st.learned_res.gains)}, drive the force to the bound of {num(u_max, 4)} N, where the law "
        "is no longer linear."
        if sat
        else f"Its gains are {_gains(st.learned_res.gains)}; its largest force, {num(run.peak_u)} N, stays below the "
        f"bound of {num(u_max, 4)} N."
    )
    passive = compared(st.learned_vs("best passive damper"), "the best passive damper")
    none = compared(st.learned_vs("no control"), "no control", verb="").strip()
    return f"On the same episodes the learned law {passive} and {none}. {tail}"


def references_sentence(st: LearningStudy) -> str:
    """The learner against the task's own references, and what its observation lacks to reach the optimum."""
    t, exo, fixed = st.res_task, st.exo, st.fixed
    g_exo, se_exo = st.excess_over_optimum
    bound_exo = (
        f"its largest force, {num(exo.peak_force)} N, stays within the bound of {num(t.u_max, 4)} N, so it is the "
        "task's optimum"
        if exo.within_bound
        else f"its largest force, {num(exo.peak_force)} N, exceeds the bound of {num(t.u_max, 4)} N, so it is a lower "
        "bound"
    )
    bound_fixed = (
        f"its force would reach {num(fixed.peak_force)} N at the corners of the box, so the bound binds there"
        if not fixed.within_bound
        else f"its largest force, {num(fixed.peak_force)} N, stays within the bound"
    )
    lqr = st.learned_vs("LQR")
    return (
        "The task has an exact optimum: with the forcing phase known, the finite-horizon LQ law on "
        f"$[x, v, \\sin\\omega t, \\cos\\omega t]$ costs $J = {num(exo.expected_cost, 4)}$ s ({bound_exo}). The best "
        f"fixed gain on $[x, v]$, {_gains(fixed.gains)}, costs {num(fixed.expected_cost, 4)} s ({bound_fixed}). "
        f"The learned law costs {pct(g_exo)} more than the exact optimum (± {pct(se_exo, 2)}), "
        f"{compared(st.learned_vs('best fixed gain'), 'the best fixed gain', verb='').strip()}, and "
        f"{compared(lqr, 'LQR', verb='').strip()}, a law designed for the task without the force. What separates "
        "the fixed-gain laws from the optimum is the forcing phase: the observation $[x, v]$ does not contain it, "
        "so a memoryless law of $[x, v]$ can only react to the disturbance's effect, never cancel it ahead of time; "
        "with $\\sin\\omega t$ and $\\cos\\omega t$ added to the observation the optimum is a linear (time-varying) "
        "law of it."
    )


def identify_design_sentence(st: LearningStudy) -> str:
    """Identify-then-design against the learner: data used and cost on the same episodes."""
    d = st.id_design
    p = st.identify_vs_learned
    cost = st.active.runs[st.a("identified, then designed")].mean_cost
    verdict = (
        f"the same as the learned law within the sampling error ({pct(p.rel, 2)} ± {pct(p.rel_se, 1)})"
        if not p.resolved
        else f"{pct(abs(p.rel))} {'more' if p.diff > 0 else 'less'} than the learned law (± {pct(p.rel_se, 2)})"
    )
    return (
        f"One {num(d.duration, 3)} s broadband test record ({integer(d.samples)} samples, noise {pct(d.noise, 2)} of "
        f"the response) gives $m = {_pm(d.fitted[0], d.stderr[0])}$ kg, $c = {_pm(d.fitted[1], d.stderr[1])}$ N s/m "
        "and "
        f"$k = {_pm(d.fitted[2], d.stderr[2])}$ N/m (chapter 10's method). The best fixed gain "
        f"designed on that fit, {_gains(d.fixed_gains)}, costs {num(cost, 4)} s "
        f"on the episodes, {verdict}: {integer(d.samples)} samples of data against the learner's "
        f"{_steps(st.training_steps)} simulated steps."
    )


def robustness_sentence(st: LearningStudy) -> str:
    """The worst plant change for each law."""
    rb, ratio = st.robust, st.robust_ratio()
    parts = []
    for j, law in enumerate(rb.laws):
        v = int(np.argmax(ratio[:, j]))
        at_worst = (
            "no change tried costs it more relative to the plant's optimum"
            if v == 0
            else f"at worst {num(ratio[v, j])} ({rb.variations[v]})"
        )
        parts.append(f"{law}, {num(ratio[0, j])} on the nominal plant, {at_worst}")
    return "No law was redesigned for the changed plants. Cost over each plant's own optimum: " + "; ".join(parts) + "."


def semi_sentence(st: LearningStudy) -> str:
    """The learned clipped law against the semi-active alternatives, and how often it sits on a bound."""
    t = st.semi_task
    best_c = st.passive_semi.c
    where = (
        f"the damper's {'largest' if best_c >= 0.5 * (t.c_min + t.c_max) else 'smallest'} value"
        if st.passive_semi.at_bound
        else f"inside the damper's range of {num(t.c_min)} to {num(t.c_max)} N s/m"
    )
    frac = st.bound_fraction(st.s("learned (ARS)"))
    return (
        f"The best constant damping is $c = {num(best_c)}$ N s/m, {where}. On the same episodes the learned clipped "
        f"law {compared(st.semi_vs('best constant damping'), 'the best constant damping')}, "
        f"{compared(st.semi_vs('clipped skyhook'), 'clipped skyhook', verb='').strip()} and "
        f"{compared(st.semi_vs('clipped LQR'), 'clipped LQR', verb='').strip()}. Its damping sits on "
        f"{num(t.c_min)} or {num(t.c_max)} N s/m {pct(frac)} of the time."
    )
