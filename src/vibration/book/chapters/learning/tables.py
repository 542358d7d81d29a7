"""Tables of the learning chapter, each a function of a :class:`LearningStudy`.

Every number column has one number of significant figures (:func:`.notation.sig`, trailing zeros
kept); a quantity that does not exist reads "—" with the reason as a footnote.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.learning.notation import num, power, sig
from vibration.book.chapters.learning.study import ACTIVE, SEMI, TARGETS, LearningStudy
from vibration.book.presentation.numbers import integer
from vibration.book.presentation.tables import Column, Missing, Table, bound, columns
from vibration.physics.learning import Comparison

METHOD_NAMES = {"ars": "ARS (augmented random search, V1-t)", "cma": "CMA-ES"}
SHORT_NAMES = {"ars": "ARS", "cma": "CMA-ES"}
#: Excess costs below this are the optimiser's rounding level (machine-dependent digits): printed as a bound.
EXCESS_FLOOR = 1e-6
#: Tolerance the self-checks are printed against.
CHECK_TOL = 1e-12

NO_EPISODES = Missing(reason="computed from the model, no episodes")


def _episodes(e: float, never: str):
    """Episodes (a whole number, or a half for a median of an even count), or "—" with the reason."""
    if not math.isfinite(e):
        return Missing(reason=never)
    return int(e) if e == int(e) else f"{e:.1f}"


def decay_rates(st: LearningStudy) -> np.ndarray:
    """Closed-loop decay rates of the LQR loop, ascending, 1/s."""
    return np.sort(-np.log(st.ref.poles.astype(complex)).real / st.task.dt)


def lqr_table(st: LearningStudy) -> Table:
    """The optimum: LQR gains, closed-loop decay rates, expected cost and the force it needs."""
    ref, task = st.ref, st.task
    row = {
        "kx": sig(ref.gains[0], 4),
        "kv": sig(ref.gains[1], 4),
        "rates": ", ".join(sig(r, 4) for r in decay_rates(st)),
        "J": sig(ref.expected_cost, 4),
        "Jinf": sig(ref.infinite_horizon_cost, 4),
        "peak": sig(ref.peak_force, 3),
        "umax": sig(task.u_max, 3),
    }
    return Table(
        rows=[row],
        columns=columns(
            """
            kx     K_x (N/m)
            kv     K_v (N s/m)
            rates  decay rates (1/s)
            J      J* (s)
            Jinf   J*_∞ (s)
            peak   max |u| (N)
            umax   u_max (N)
            """
        ),
        caption="Discrete-time LQR of the sampled task: gains of u = −K [x, v], closed-loop decay rates, "
        "expected episode cost J* and its value over an infinite horizon, largest force over every initial state.",
        name="tab-learning-lqr",
    )


def learning_table(st: LearningStudy) -> Table:
    """Per learner: training episodes, learned gains, expected cost, ratio to LQR, episodes to each target."""
    rows = []
    for res in st.learners:
        row = {
            "method": METHOD_NAMES[res.method],
            "episodes": res.episodes,
            "steps": res.episodes * st.task.n_steps,
            "kx": sig(res.gains[0], 4),
            "kv": sig(res.gains[1], 4),
            "J": sig(res.expected_cost, 6),
            "ratio": sig(st.ratio(res), 6),
        }
        for i, target in enumerate(TARGETS):
            e = st.episodes_to(res, target)
            row[f"e{i}"] = int(e) if math.isfinite(e) else Missing(reason=f"not within {target:.0%} of J* in this run")
        rows.append(row)
    lqr = {"method": "LQR (Riccati)", "episodes": NO_EPISODES, "steps": NO_EPISODES, "ratio": sig(1.0, 6)}
    lqr |= {"kx": sig(st.ref.gains[0], 4), "kv": sig(st.ref.gains[1], 4), "J": sig(st.ref.expected_cost, 6)}
    lqr |= {f"e{i}": NO_EPISODES for i in range(len(TARGETS))}
    rows.append(lqr)
    targets = " and ".join(f"{100 * t:g} %" for t in TARGETS)
    return Table(
        rows=rows,
        columns=columns(
            """
            method    learner
            episodes  episodes
            steps     steps
            kx        K_x (N/m)
            kv        K_v (N s/m)
            J         J (s)
            ratio     J / J*
            """
        )
        + [Column(key=f"e{i}", header=f"episodes to {100 * t:g} %") for i, t in enumerate(TARGETS)],
        caption="What the learners found from episodes alone: gains, exact expected cost J of the learned law, "
        f"its ratio to the LQR optimum J*, and the training episodes each needed to come within {targets} of J*.",
        name="tab-learning-learners",
    )


def _excess(v: float):
    """J/J* − 1 at 3 significant figures, or a bound below the optimiser's rounding level (machine-dependent)."""
    return sig(v, 3) if abs(v) >= EXCESS_FLOOR else f"< {power(round(math.log10(EXCESS_FLOOR)))}"


def seed_table(st: LearningStudy) -> Table:
    """Every learner over many seeds: median and worst final J/J* − 1, and episodes to the target."""
    rows = []
    for sd in st.seeds:
        rows.append(
            {
                "method": METHOD_NAMES[sd.method],
                "seeds": sd.seeds.size,
                "iters": sd.iterations,
                "episodes": sd.episodes,
                "med": _excess(sd.median_ratio - 1.0),
                "worst": _excess(sd.worst_ratio - 1.0),
                "reached": f"{sd.reached}/{sd.seeds.size}",
                "emed": _episodes(sd.median_episodes, "most seeds never"),
                "eworst": _episodes(sd.worst_episodes, "a seed never"),
            }
        )
    tgt = 100 * st.seeds[0].target
    return Table(
        rows=rows,
        columns=columns(
            f"""
            method    learner
            seeds     seeds
            iters     iterations
            episodes  episodes per seed
            med       median J/J* − 1
            worst     worst J/J* − 1
            reached   seeds within {tgt:g} %
            emed      median episodes to {tgt:g} %
            eworst    worst episodes to {tgt:g} %
            """
        ),
        caption=f"Each learner trained from seeds {st.params.seed} to {st.params.seed + st.params.n_seeds - 1} on the "
        f"task without disturbance: final exact cost over the LQR optimum J*, and the training episodes to come "
        f"within {tgt:g} % of J*.",
        name="tab-learning-seeds",
        notes=(
            f"Values below {num(EXCESS_FLOOR, 1)} print as a bound: their digits are the optimiser's rounding and "
            "differ between machines.",
        ),
    )


# ----------------------------------------------------------------------------- the tasks without a closed form


def _realised(cmp: Comparison, i: int) -> str:
    """The law as the device realises it: a damping, or the gains."""
    g, t = cmp.gains[i], cmp.task
    if g[0] == 0.0:
        c = g[1] if t.mode == "force" else min(max(g[1], t.c_min), t.c_max)
        return f"c = {num(c, 3)} N s/m" if t.mode == "damping" else f"added c = {num(c, 3)} N s/m"
    return f"K = [{num(g[0], 3)}, {num(g[1], 3)}]"


def comparison_table(cmp: Comparison, caption: str, name: str, *, reference: int) -> Table:
    """Cost, peak and RMS displacement and control effort of each controller on the same episodes."""
    rows = []
    for i, run in enumerate(cmp.runs):
        rows.append(
            {
                "name": cmp.names[i],
                "law": _realised(cmp, i),
                "J": sig(run.mean_cost, 4),
                "sem": sig(run.cost_sem, 2),
                "exact": sig(cmp.exact[i], 4)
                if math.isfinite(cmp.exact[i])
                else Missing(reason="not linear on this task"),
                "rel": sig(run.mean_cost / cmp.runs[reference].mean_cost, 4),
                "xpk": sig(run.peak_x, 3),
                "xrms": sig(run.rms_x, 3),
                "urms": sig(run.rms_u, 3),
                "upk": sig(run.peak_u, 3),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            name   controller
            law    law
            J      J (s)
            sem    ± (s)
            exact  J exact (s)
            rel    J / J_ref
            xpk    max |x| (m)
            xrms   x_rms (m)
            urms   u_rms (N)
            upk    max |u| (N)
            """
        ),
        caption=caption,
        name=name,
        notes=(
            f"Mean over the same {cmp.runs[0].cost.size} seeded episodes (seed {cmp.seed}), "
            "± its standard error; the exact expected cost where the law is linear on the task.",
            f"Reference cost: the mean cost J of {cmp.names[reference]}.",
        ),
    )


#: The two plants the controllers are compared on under the resonance force: the study's field, the caption's
#: name of the device, its controllers and the reference controller of the "J / J_ref" column.
DEVICES = {
    "active": ("Force actuator", ACTIVE, "LQR"),
    "semi": ("Semi-active damper", SEMI, "best constant damping"),
}


def controllers_table(st: LearningStudy, device: str) -> Table:
    """Every controller of ``device`` (a key of :data:`DEVICES`) on the same episodes under the resonance force."""
    if device not in DEVICES:
        raise ValueError(f"device = {device!r}: allowed {', '.join(map(repr, DEVICES))}")
    what, names, reference = DEVICES[device]
    return comparison_table(
        getattr(st, device),
        f"{what} under the resonance force: controllers on the same episodes.",
        f"tab-learning-{device}",
        reference=names.index(reference),
    )


def references_table(st: LearningStudy) -> Table:
    """The force-actuator task under the disturbance: its exact optimum, the best fixed gain, LQR, and the learner's
    excess over each."""
    t, exo, fixed = st.res_task, st.exo, st.fixed
    g_exo, se_exo = st.excess_over_optimum
    rows = [
        {
            "name": "exact optimum (forcing phase known)",
            "info": "x, v and the phase of F(t)",
            "J": sig(exo.expected_cost, 4),
            "peak": sig(exo.peak_force, 3),
            "gap": sig(100 * g_exo, 3),
            "gse": sig(100 * se_exo, 2),
        }
    ]
    lqr_exact = st.active.exact[st.a("LQR")]
    nonlinear = Missing(reason="the force bound binds: not linear on the task")
    for label, name, exact, peak in (
        ("best fixed gain on [x, v]", "best fixed gain", fixed.expected_cost, fixed.peak_force),
        ("LQR (designed without F(t))", "LQR", lqr_exact, st.active.runs[st.a("LQR")].peak_u),
    ):
        p = st.learned_vs(name)
        rows.append(
            {
                "name": label,
                "info": "x, v",
                "J": sig(exact, 4) if math.isfinite(exact) else nonlinear,
                "peak": sig(peak, 3),
                "gap": sig(100 * p.rel, 3),
                "gse": sig(100 * p.rel_se, 2),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            name  reference
            info  what the law uses
            J     J exact (s)
            peak  max |u| (N)
            gap   learned law's excess (%)
            gse   ± (%)
            """
        ),
        caption=f"The force-actuator task under F_0 sin(ωt) (F_0 = {num(t.F0, 4)} N, ω = {num(t.omega, 4)} rad/s): "
        "its exact optimum, the best fixed gain, LQR, and how much more the learned law costs than each.",
        name="tab-learning-references",
        notes=(
            "Learned law's excess: its mean cost over the reference's, minus one. Over the fixed-gain laws it is "
            f"paired on the same {st.active.runs[0].cost.size} seeded episodes (force bound {num(t.u_max, 4)} N "
            "applied); over the exact optimum it is against the exact cost; ± one standard error. The best fixed "
            "gain's exact cost ignores the force bound.",
        ),
    )


def robustness_table(st: LearningStudy) -> Table:
    """Each law's cost on each changed plant over that plant's exact optimum (forcing phase known)."""
    rb = st.robust
    rows = []
    for v, name in enumerate(rb.variations):
        row = {"var": name, "opt": sig(rb.optimum[v], 4)}
        for j in range(len(rb.laws)):
            row[f"r{j}"] = sig(rb.cost[v, j] / rb.optimum[v], 4)
            row[f"s{j}"] = sig(rb.stderr[v, j] / rb.optimum[v], 2)
        rows.append(row)
    cols = [Column(key="var", header="plant change"), Column(key="opt", header="J_opt (s)")]
    for j, law in enumerate(rb.laws):
        cols += [Column(key=f"r{j}", header=f"{law}: J / J_opt"), Column(key=f"s{j}", header="±")]
    return Table(
        rows=rows,
        columns=cols,
        caption="Laws designed on the nominal plant, run unchanged on changed plants: cost over the changed plant's "
        "exact optimum (forcing phase known).",
        name="tab-learning-robustness",
        notes=(
            f"Mean over the same {integer(rb.n_episodes)} seeded episodes per plant (force bound applied), ± one "
            "standard error; optimum: the exact finite-horizon LQ optimum of the changed task.",
        ),
    )


CHECK_LABELS = {
    "lqr_vs_control": ("LQR gains", "a second discrete LQR design routine"),
    "riccati": ("Riccati equation residual", "substitution, relative to |P|"),
    "cost_vs_cubature": ("exact expected cost J*", "Gauss–Legendre cubature of episode costs"),
    "env_vs_loop": ("episode of the environment's step map", "compiled batched loop, relative to the initial box"),
}


def checks_table(st: LearningStudy) -> Table:
    """Residuals against independent methods, printed as bounds."""
    rows = []
    for key, value in st.checks.items():
        what, against = CHECK_LABELS[key]
        rows.append({"what": what, "against": against, "bound": bound(value, CHECK_TOL)})
    return Table(
        rows=rows,
        columns=columns(
            """
            what     quantity
            against  independent method
            bound    relative difference
            """
        ),
        caption="Self-checks of the optimum and of the simulators (relative differences, printed as bounds).",
        name="tab-learning-checks",
    )
