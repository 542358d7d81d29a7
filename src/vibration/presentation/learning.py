"""Figures, tables and sentences of the learning chapter (Part II).

Everything shown is computed by :mod:`vibration.physics.learning`; the functions here only arrange
it: one call per table or figure, and every sentence that states a number is rendered from results.

Examples
--------
>>> from vibration.physics.learning import OscillatorTask, lqr_reference
>>> print(repr(lqr_table(OscillatorTask(), lqr_reference())).splitlines()[1])
K_x (N/m)  K_v (N s/m)  decay rates (1/s)  J* (s)  J*_∞ (s)  max |u| (N)  u_max (N)
"""

from __future__ import annotations

import math

import numpy as np

from ..physics.learning import Comparison, LQRReference, OscillatorTask, TrainingResult, _moments
from ..physics.learning.disturbance import CostCurvature, ExosystemOptimum, FixedGainOptimum
from ..physics.learning.studies import IdentifyDesign, Robustness, SeedStudy
from .style import figure, place_legend
from .tables import Column, Missing, Table, bound

__all__ = [
    "bound_fraction",
    "checks_table",
    "curvature_sentence",
    "identify_design_sentence",
    "references_sentence",
    "references_table",
    "robustness_sentence",
    "robustness_table",
    "seed_sentence",
    "seed_table",
    "closing_note",
    "comparison_figure",
    "comparison_sentence",
    "comparison_table",
    "learning_figure",
    "learning_sentence",
    "learning_table",
    "lqr_sentence",
    "lqr_table",
]

METHOD_NAMES = {"ars": "ARS (augmented random search, V1-t)", "cma": "CMA-ES"}
SHORT_NAMES = {"ars": "ARS", "cma": "CMA-ES"}


def _decay_rates(task: OscillatorTask, ref: LQRReference) -> np.ndarray:
    return np.sort(-np.log(ref.poles.astype(complex)).real / task.dt)


def lqr_table(task: OscillatorTask, ref: LQRReference) -> Table:
    """The optimum: LQR gains, closed-loop decay rates, expected cost and the force it needs."""
    rates = _decay_rates(task, ref)
    row = {
        "kx": float(ref.gains[0]),
        "kv": float(ref.gains[1]),
        "rates": ", ".join(f"{r:.4g}" for r in rates),
        "J": ref.expected_cost,
        "Jinf": ref.infinite_horizon_cost,
        "peak": ref.peak_force,
        "umax": task.u_max,
    }
    return Table(
        [row],
        [
            Column("kx", "K_x (N/m)", 4),
            Column("kv", "K_v (N s/m)", 4),
            Column("rates", "decay rates (1/s)"),
            Column("J", "J* (s)", 4),
            Column("Jinf", "J*_∞ (s)", 4),
            Column("peak", "max |u| (N)", 3),
            Column("umax", "u_max (N)", 3),
        ],
        caption="Discrete-time LQR of the sampled task: gains of u = −K [x, v], closed-loop decay rates, "
        "expected episode cost J* and over an infinite horizon, largest force over every initial state.",
        name="tab-learning-lqr",
    )


def _law(g) -> str:
    """``u = -K_x x - K_v v`` with the signs written out."""
    kx, kv = (float(z) for z in g)
    first = f"{-kx:.4g}\\,x"
    second = f"{'-' if kv >= 0 else '+'} {abs(kv):.4g}\\,v"
    return f"u = {first} {second}"


def lqr_sentence(task: OscillatorTask, ref: LQRReference) -> str:
    """The optimum in words: the law, its closed-loop modes, its cost, whether the force bound binds."""
    poles = np.log(ref.poles.astype(complex)) / task.dt
    if np.any(np.abs(poles.imag) > 1e-9 * np.abs(poles).max()):
        p = poles[np.argmax(poles.imag)]
        modes = f"a damped oscillation decaying at {-p.real:.3g} 1/s with frequency {abs(p.imag):.3g} rad/s"
    else:
        rates = np.sort(-poles.real)
        modes = f"two real modes decaying at {rates[0]:.3g} and {rates[1]:.3g} 1/s"
    stiff = abs(ref.gains[0]) / task.k
    kind = (
        f"mostly damping (the displacement gain changes the spring stiffness by {100 * stiff:.2g} %)"
        if stiff < 0.1
        else f"damping and stiffness (the displacement gain changes the spring stiffness by {100 * stiff:.3g} %)"
    )
    binds = "never reaches" if ref.peak_force <= task.u_max else "exceeds"
    return (
        f"The optimal law is ${_law(ref.gains)}$ (N): {kind}, which gives the closed loop {modes}. "
        f"Its expected cost over an episode is $J^* = {ref.expected_cost:.4g}$ s, and its largest force over every "
        f"initial state, {ref.peak_force:.3g} N, {binds} the bound of {task.u_max:g} N, so the bound does "
        f"{'not ' if ref.peak_force <= task.u_max else ''}change the problem."
    )


def _first_within(res: TrainingResult, target: float, rel: float):
    ok = np.nonzero(res.curve_cost <= (1.0 + rel) * target)[0]
    return int(res.curve_episodes[ok[0]]) if ok.size else Missing(f"not within {rel:.0%} of J* in this run")


def learning_table(task: OscillatorTask, ref: LQRReference, results: list[TrainingResult]) -> Table:
    """Per learner: training episodes, learned gains, expected cost, ratio to LQR, episodes to 5 % and 1 %."""
    rows = []
    for res in results:
        rows.append(
            {
                "method": METHOD_NAMES[res.method],
                "episodes": res.episodes,
                "steps": res.episodes * task.n_steps,
                "kx": float(res.gains[0]),
                "kv": float(res.gains[1]),
                "J": res.expected_cost,
                "ratio": res.expected_cost / ref.expected_cost,
                "e5": _first_within(res, ref.expected_cost, 0.05),
                "e1": _first_within(res, ref.expected_cost, 0.01),
            }
        )
    rows.append(
        {
            "method": "LQR (Riccati)",
            "episodes": Missing("computed from the model, no episodes"),
            "steps": Missing("computed from the model, no episodes"),
            "kx": float(ref.gains[0]),
            "kv": float(ref.gains[1]),
            "J": ref.expected_cost,
            "ratio": 1.0,
            "e5": Missing("computed from the model, no episodes"),
            "e1": Missing("computed from the model, no episodes"),
        }
    )
    return Table(
        rows,
        [
            Column("method", "learner"),
            Column("episodes", "episodes"),
            Column("steps", "steps"),
            Column("kx", "K_x (N/m)", 4),
            Column("kv", "K_v (N s/m)", 4),
            Column("J", "J (s)", 6),
            Column("ratio", "J / J*", 6),
            Column("e5", "episodes to 5 %"),
            Column("e1", "episodes to 1 %"),
        ],
        caption="What the learners found from episodes alone: gains, exact expected cost J of the learned law, "
        "its ratio to the LQR optimum J*, and the training episodes each needed to come within 5 % and 1 % of J*.",
        name="tab-learning-learners",
    )


def learning_sentence(task: OscillatorTask, ref: LQRReference, results: list[TrainingResult]) -> str:
    """The headline: learned-to-LQR cost ratio of every learner and what it took."""
    parts = []
    for res in results:
        ratio = res.expected_cost / ref.expected_cost
        parts.append(
            f"{METHOD_NAMES[res.method]} reaches $J/J^* = {ratio:.5f}$ after {res.episodes} episodes "
            f"({res.episodes * task.n_steps / 1e6:.3g} million steps), with gains "
            f"$K = [{res.gains[0]:.3g}, {res.gains[1]:.4g}]$"
        )
    ok = all(r.expected_cost <= 1.05 * ref.expected_cost for r in results)
    verdict = "All are within the 5 % target." if ok else "Not every learner met the 5 % target in this run."
    worst = max(results, key=lambda r: r.expected_cost)
    err = np.abs(worst.gains - ref.gains)
    return (
        "; ".join(parts)
        + f". {verdict} {METHOD_NAMES[worst.method]}'s gains differ from LQR's by {err[0]:.2g} N/m in $K_x$ and "
        f"{err[1]:.2g} N s/m in $K_v$, for {100 * (worst.expected_cost / ref.expected_cost - 1):.2g} % more cost."
    )


def learning_figure(task: OscillatorTask, ref: LQRReference, results: list[TrainingResult]):
    """Learning curves against the LQR cost line, their excess over it, and the paths over the cost surface."""
    fig, _ = figure(1, 1, height=6.4)
    fig.clf()
    axd = fig.subplot_mosaic([["cost", "excess"], ["surface", "surface"]], height_ratios=[1.0, 1.15])
    colors = {"ars": "C0", "cma": "C1"}
    ax0, ax1, ax2 = axd["cost"], axd["excess"], axd["surface"]
    for res in results:
        e, c = res.curve_episodes[1:], res.curve_cost[1:]
        ax0.plot(e, c, color=colors[res.method], label=SHORT_NAMES[res.method])
        ax1.plot(e, np.maximum(c / ref.expected_cost - 1.0, 1e-16), color=colors[res.method])
    ax0.axhline(ref.expected_cost, color="k", ls="--", lw=1.0, label="LQR optimum $J^*$")
    ax0.set_xscale("log")
    ax0.set_yscale("log")
    ax0.set_xlabel("training episodes")
    ax0.set_ylabel("expected cost $J$ (s)")
    place_legend(ax0)
    ax1.axhline(0.05, color="0.4", ls=":", lw=1.0)
    ax1.annotate("5 % target", (0.98, 0.05), xycoords=("axes fraction", "data"), ha="right", va="bottom", fontsize=8)
    ax1.set_yscale("log")
    ax1.set_xlabel("training episodes")
    ax1.set_ylabel(r"$J/J^* - 1$")
    # cost surface of the unclipped linear law, exact
    kx_all = np.concatenate([r.curve_gains[:, 0] for r in results] + [[ref.gains[0]]])
    kv_all = np.concatenate([r.curve_gains[:, 1] for r in results] + [[ref.gains[1]]])
    kx = np.linspace(min(kx_all.min(), -2.0) - 1.0, max(kx_all.max(), 4.0) + 1.0, 61)
    kv = np.linspace(min(kv_all.min(), 0.0) - 1.0, max(kv_all.max(), 12.0) + 1.0, 61)
    cost = np.array([[_moments(task, np.array([a, b]))[0] for a in kx] for b in kv])
    excess = np.log10(np.clip(cost / ref.expected_cost - 1.0, 1e-6, 1e6))
    cs = ax2.contourf(kx, kv, excess, levels=np.arange(-6, 3.5, 0.5), cmap="viridis")
    cb = fig.colorbar(cs, ax=ax2)
    cb.set_label(r"$\log_{10}(J/J^* - 1)$")
    for res in results:
        ax2.plot(res.curve_gains[:, 0], res.curve_gains[:, 1], color=colors[res.method], lw=1.0, marker=".", ms=2)
    ax2.plot(*ref.gains, marker="*", color="w", mec="k", ms=11, ls="none")
    ax2.set_xlabel(r"$K_x$ (N/m)")
    ax2.set_ylabel(r"$K_v$ (N s/m)")
    ax2.grid(False)
    return fig


# ----------------------------------------------------------------------------- comparisons


def _realised(cmp: Comparison, i: int) -> str:
    g = cmp.gains[i]
    t = cmp.task
    if g[0] == 0.0:
        c = g[1] if t.mode == "force" else min(max(g[1], t.c_min), t.c_max)
        return f"c = {c:.3g} N s/m" if t.mode == "damping" else f"added c = {c:.3g} N s/m"
    return f"K = [{g[0]:.3g}, {g[1]:.3g}]"


def comparison_table(cmp: Comparison, caption: str, name: str, reference: int = 0) -> Table:
    """Cost, peak and RMS displacement and control effort of each controller on the same episodes."""
    rows = []
    for i, run in enumerate(cmp.runs):
        rows.append(
            {
                "name": cmp.names[i],
                "law": _realised(cmp, i),
                "J": run.mean_cost,
                "sem": run.cost_sem,
                "exact": cmp.exact[i] if math.isfinite(cmp.exact[i]) else Missing("not linear on this task"),
                "rel": run.mean_cost / cmp.runs[reference].mean_cost,
                "xpk": run.peak_x,
                "xrms": run.rms_x,
                "urms": run.rms_u,
                "upk": run.peak_u,
            }
        )
    return Table(
        rows,
        [
            Column("name", "controller"),
            Column("law", "law"),
            Column("J", "J (s)", 4),
            Column("sem", "± (s)", 2),
            Column("exact", "J exact (s)", 4),
            Column("rel", "J / J_ref", 4),
            Column("xpk", "max |x| (m)", 3),
            Column("xrms", "x_rms (m)", 3),
            Column("urms", "u_rms (N)", 3),
            Column("upk", "max |u| (N)", 3),
        ],
        caption=caption,
        name=name,
        notes=(
            f"Mean over the same {cmp.runs[0].cost.size} seeded episodes (seed {cmp.seed}), "
            "± its standard error; the exact expected cost where the law is linear on the task.",
            f"J_ref: the mean cost J of {cmp.names[reference]}.",
        ),
    )


def comparison_sentence(cmp: Comparison, learned: int, others: dict[str, int]) -> str:
    """How much the learned law saves against each named controller, paired on the same episodes."""
    parts = []
    for label, j in others.items():
        d, se = cmp.paired_gain(learned, j)
        pct = 100.0 * d / cmp.runs[j].mean_cost
        word = "less" if d > 0 else "more"
        sig = "" if abs(d) > 3 * se else " (within the sampling error)"
        parts.append(f"{abs(pct):.3g} % {word} than {label}{sig}")
    return "On the same episodes the learned law costs " + ", ".join(parts) + "."


def _color(name: str) -> str:
    if name.startswith("learned"):
        return "C2"
    if "passive" in name or "constant" in name:
        return "C0"
    if "skyhook" in name:
        return "C4"
    if "LQR" in name:
        return "C1"
    return "C7"


def bound_fraction(cmp: Comparison, i: int) -> float:
    """Fraction of the steps (v != 0) at which the damping of controller i sits on c_min or c_max, 1."""
    run, t = cmp.runs[i], cmp.task
    v = run.v.ravel()
    ok = v != 0.0
    c = -run.u.ravel()[ok] / v[ok]
    tol = 1e-9 * t.c_max
    return float(np.mean((np.abs(c - t.c_min) <= tol) | (np.abs(c - t.c_max) <= tol)))


def comparison_figure(active: Comparison, semi: Comparison, show: dict, episode: int = 0, t_zoom: float = 3.0):
    """One episode of each task: x(t) of the chosen controllers, and the learned damping c(t)."""
    fig, axes = figure(3, 1, height=6.8, sharex=False)
    t = active.runs[0].t
    for ax, cmp, key in ((axes[0], active, "active"), (axes[1], semi, "semi")):
        for i in show[key]:
            ax.plot(t, cmp.runs[i].x[episode], label=cmp.names[i], lw=1.1, color=_color(cmp.names[i]))
        ax.set_ylabel(r"$x$ (m)")
        ax.set_xlim(t[0], t[-1] + active.task.dt)
        place_legend(ax, outside=True)
    axes[0].set_title("force actuator, resonance disturbance", loc="left")
    axes[1].set_title("semi-active damper, resonance disturbance", loc="left")
    sel = t <= t_zoom
    for i in show["damping"]:
        run = semi.runs[i]
        v = run.v[episode]
        u = run.u[episode]
        with np.errstate(divide="ignore", invalid="ignore"):
            c = np.where(v != 0.0, -u / v, np.nan)
        axes[2].plot(t[sel], c[sel], label=semi.names[i], lw=1.0, drawstyle="steps-post", color=_color(semi.names[i]))
    axes[2].set_ylabel(r"damping $c$ (N s/m)")
    axes[2].set_xlabel(r"$t$ (s)")
    axes[2].set_title(f"semi-active damping commanded, first {t_zoom:g} s", loc="left")
    place_legend(axes[2], outside=True)
    for ax in axes[:2]:
        ax.set_xlabel(r"$t$ (s)")
    return fig


def checks_table(checks: dict[str, float]) -> Table:
    """Residuals against independent methods, printed as bounds."""
    labels = {
        "lqr_vs_control": ("LQR gains", "python-control dlqr"),
        "riccati": ("Riccati equation residual", "substitution, relative to |P|"),
        "cost_vs_cubature": ("exact expected cost J*", "Gauss–Legendre cubature of episode costs"),
        "env_vs_loop": ("episode of the environment's step map", "compiled batched loop, relative to x0_max"),
    }
    rows = []
    for key, value in checks.items():
        what, against = labels[key]
        rows.append({"what": what, "against": against, "bound": bound(value, 1e-12)})
    return Table(
        rows,
        [Column("what", "quantity"), Column("against", "independent method"), Column("bound", "relative difference")],
        caption="Self-checks of the optimum and of the simulators (relative differences, printed as bounds).",
        name="tab-learning-checks",
    )


def closing_note(
    task: OscillatorTask,
    ref: LQRReference,
    results: list[TrainingResult],
    active: Comparison,
    semi: Comparison,
    learned_active: int,
    lqr_active: int,
    learned_semi: int,
    passive_semi: int,
    *,
    exo: ExosystemOptimum | None = None,
    fixed_active: int | None = None,
    studies: list[SeedStudy] | None = None,
) -> str:
    """The chapter's closing note: each result read against the best alternative and the optimum."""
    ratios = ", ".join(
        f"{METHOD_NAMES[r.method]} {r.expected_cost / ref.expected_cost:.5f} ({r.episodes} episodes)" for r in results
    )
    if studies:
        ratios += ". " + seed_sentence(studies)[:-1]
    da, sa = active.paired_gain(learned_active, lqr_active)
    ds, ss = semi.paired_gain(learned_semi, passive_semi)
    c_best = semi.gains[passive_semi][1]
    ka = active.gains[learned_active]
    saturates = active.runs[learned_active].peak_u >= active.task.u_max * (1.0 - 1e-9)
    at_bound = (
        "at the bound" if c_best >= semi.task.c_max * (1 - 1e-6) or c_best <= semi.task.c_min * (1 + 1e-6) else ""
    )
    word_a = "less" if da > 0 else "more"
    word_s = "less" if ds > 0 else "more"
    return (
        f"* **Against the optimum.** Learned-to-LQR expected-cost ratio of the runs shown: {ratios} (target: within "
        "5 %).\n"
        + (
            _resonance_bullet(active, learned_active, lqr_active, fixed_active, exo)
            if exo is not None and fixed_active is not None
            else f"* **Resonance disturbance, force actuator.** LQR is optimal only for the task it was designed for; "
            f"with the disturbance the learned linear law costs "
            f"{100 * abs(da) / active.runs[lqr_active].mean_cost:.3g} % {word_a} than LQR "
            f"(± {100 * sa / active.runs[lqr_active].mean_cost:.2g} %) on the same episodes, with "
            f"gains K = [{ka[0]:.3g}, {ka[1]:.3g}]"
            + (f" that drive the force to its bound of {active.task.u_max:g} N.\n" if saturates else ".\n")
        )
        + f"* **Semi-active damper.** The learned clipped law costs "
        f"{100 * abs(ds) / semi.runs[passive_semi].mean_cost:.3g} % {word_s} than the best constant damping "
        f"(c = {c_best:.3g} N s/m{', ' + at_bound if at_bound else ''}) on the same episodes "
        f"(± {100 * ss / semi.runs[passive_semi].mean_cost:.2g} %); its damping sits on {semi.task.c_min:g} or "
        f"{semi.task.c_max:g} N s/m {100 * bound_fraction(semi, learned_semi):.3g} % of the time."
    )


# ----------------------------------------------------------------------------- the disturbed task's references


def _pct(x: float) -> str:
    return f"{100 * x:.3g} %"


def references_table(
    cmp: Comparison, exo: ExosystemOptimum, fixed: FixedGainOptimum, learned: int, fixed_i: int, lqr_i: int
) -> Table:
    """The force-actuator task under the disturbance: its exact optimum, the best fixed gain, LQR, the learner."""
    t = cmp.task
    run_l = cmp.runs[learned]
    rows = [
        {
            "name": "exact optimum (forcing phase known)",
            "info": "x, v and the phase of F(t)",
            "J": exo.expected_cost,
            "Jrun": Missing("a time-varying law; its cost is exact"),
            "peak": exo.peak_force,
            "gap": (run_l.mean_cost - exo.expected_cost) / exo.expected_cost,
            "gse": run_l.cost_sem / exo.expected_cost,
        }
    ]
    for label, i, exact, peak in (
        ("best fixed gain on [x, v]", fixed_i, fixed.expected_cost, fixed.peak_force),
        ("LQR (designed without F(t))", lqr_i, cmp.exact[lqr_i], cmp.runs[lqr_i].peak_u),
    ):
        d, se = cmp.paired_gain(i, learned)
        rows.append(
            {
                "name": label,
                "info": "x, v",
                "J": exact if math.isfinite(exact) else Missing("the force bound binds: not linear on the task"),
                "Jrun": cmp.runs[i].mean_cost,
                "peak": peak,
                "gap": d / cmp.runs[i].mean_cost,
                "gse": se / cmp.runs[i].mean_cost,
            }
        )
    rows.append(
        {
            "name": cmp.names[learned],
            "info": "x, v (episodes only)",
            "J": Missing("the force bound binds: not linear on the task"),
            "Jrun": run_l.mean_cost,
            "peak": run_l.peak_u,
            "gap": Missing("the learner itself"),
            "gse": Missing("the learner itself"),
        }
    )
    return Table(
        rows,
        [
            Column("name", "reference"),
            Column("info", "what the law uses"),
            Column("J", "J exact (s)", 4),
            Column("Jrun", "J on the episodes (s)", 4),
            Column("peak", "max |u| (N)", 3),
            Column("gap", "learner's excess, J_learned / J − 1", 3),
            Column("gse", "±", 2),
        ],
        caption=f"The force-actuator task under F0 sin(ωt) (F0 = {t.F0:g} N, ω = {t.omega:g} rad/s): its exact "
        "optimum, the best fixed gain, LQR, and the learner's excess cost over each.",
        name="tab-learning-references",
        notes=(
            f"J on the episodes: mean over the same {run_l.cost.size} seeded episodes (force bound "
            f"{t.u_max:g} N applied); the learner's excess over the fixed-gain laws is paired on those episodes, "
            "over the exact optimum it is against the exact cost; ± one standard error.",
        ),
    )


def references_sentence(
    cmp: Comparison, exo: ExosystemOptimum, fixed: FixedGainOptimum, learned: int, fixed_i: int, lqr_i: int
) -> str:
    """The learner against the three references, and what its observation lacks to reach the optimum."""
    t = cmp.task
    run_l = cmp.runs[learned]
    g_exo = (run_l.mean_cost - exo.expected_cost) / exo.expected_cost
    se_exo = run_l.cost_sem / exo.expected_cost
    d_f, se_f = cmp.paired_gain(fixed_i, learned)
    d_q, se_q = cmp.paired_gain(lqr_i, learned)
    rel_f, rel_q = d_f / cmp.runs[fixed_i].mean_cost, d_q / cmp.runs[lqr_i].mean_cost
    rel_fs = se_f / cmp.runs[fixed_i].mean_cost
    if abs(d_f) <= 3 * se_f:
        vs_fixed = f"the same as the best fixed gain within the sampling error ({rel_f:+.2%} ± {rel_fs:.1g})"
    else:
        vs_fixed = f"{_pct(abs(rel_f))} {'more' if d_f > 0 else 'less'} than the best fixed gain (± {_pct(rel_fs)})"
    bound_exo = (
        f"its largest force, {exo.peak_force:.3g} N, stays within the bound of {t.u_max:g} N, so it is the task's "
        "optimum"
        if exo.within_bound
        else f"its largest force, {exo.peak_force:.3g} N, exceeds the bound of {t.u_max:g} N, so it is a lower bound"
    )
    bound_fixed = (
        f"its force would reach {fixed.peak_force:.3g} N at the corners of the box, so the bound of {t.u_max:g} N "
        "binds there"
        if not fixed.within_bound
        else f"its largest force, {fixed.peak_force:.3g} N, stays within the bound"
    )
    return (
        f"The task has an exact optimum: with the forcing phase known, the finite-horizon LQ law on "
        f"$[x, v, \\sin\\omega t, \\cos\\omega t]$ costs $J = {exo.expected_cost:.4g}$ s ({bound_exo}). The best fixed "
        f"gain on $[x, v]$, $K = [{fixed.gains[0]:.3g}, {fixed.gains[1]:.3g}]$, costs {fixed.expected_cost:.4g} s "
        f"({bound_fixed}); LQR, designed for the task without the disturbance, costs "
        f"{cmp.runs[lqr_i].mean_cost:.4g} s on the episodes. The learned law costs {run_l.mean_cost:.4g} s "
        f"± {run_l.cost_sem:.2g} s: {_pct(g_exo)} above the exact optimum (± {_pct(se_exo)}), {vs_fixed}, "
        f"and {_pct(abs(rel_q))} {'less' if d_q < 0 else 'more'} than LQR, a law designed for another task. "
        "What separates the fixed-gain laws from the optimum is the forcing phase: the observation $[x, v]$ does "
        "not contain it, so a memoryless law of $[x, v]$ can only react to the disturbance's effect, never cancel it "
        "ahead of time; with $\\sin\\omega t$ and $\\cos\\omega t$ added to the observation the optimum is a linear "
        "(time-varying) law of it."
    )


def _excess(v: float, floor: float = 1e-6) -> str | Missing:
    """J/J* − 1 at 3 significant figures, or "< floor" below the optimiser-noise level (machine-dependent)."""
    return f"{v:.3g}" if abs(v) >= floor else bound(v, floor)


def seed_table(studies: list[SeedStudy]) -> Table:
    """Every learner over many seeds: median and worst final J/J* − 1, and episodes to the target."""
    rows = []
    for st in studies:
        rows.append(
            {
                "method": METHOD_NAMES[st.method],
                "seeds": st.seeds.size,
                "iters": st.iterations,
                "episodes": st.episodes,
                "med": _excess(st.median_ratio - 1.0),
                "worst": _excess(st.worst_ratio - 1.0),
                "reached": f"{st.reached}/{st.seeds.size}",
                "emed": st.median_episodes if math.isfinite(st.median_episodes) else Missing("most seeds never"),
                "eworst": st.worst_episodes if math.isfinite(st.worst_episodes) else Missing("a seed never"),
            }
        )
    tgt = 100 * (studies[0].target if studies else 0.05)
    return Table(
        rows,
        [
            Column("method", "learner"),
            Column("seeds", "seeds"),
            Column("iters", "iterations"),
            Column("episodes", "episodes per seed"),
            Column("med", "median J/J* − 1"),
            Column("worst", "worst J/J* − 1"),
            Column("reached", f"seeds within {tgt:g} %"),
            Column("emed", f"median episodes to {tgt:g} %"),
            Column("eworst", f"worst episodes to {tgt:g} %"),
        ],
        caption="Each learner trained from every seed on the task without disturbance: final exact cost over the "
        f"LQR optimum J*, and the training episodes to come within {tgt:g} % of J*.",
        name="tab-learning-seeds",
        notes=("Values below 1e-6 are the optimiser's own rounding level and are printed as a bound.",),
    )


def seed_sentence(studies: list[SeedStudy]) -> str:
    """Median and worst outcome of each learner over its seeds."""
    parts = []
    for st in studies:
        parts.append(
            f"over {st.seeds.size} seeds {METHOD_NAMES[st.method]} ends at a median $J/J^* - 1$ of "
            f"{_fmt_excess(st.median_ratio - 1)} and a worst of {_fmt_excess(st.worst_ratio - 1)}; "
            f"{st.reached} of {st.seeds.size} seeds come within {100 * st.target:g} %"
            + (
                f", after {st.median_episodes:.0f} episodes (median; worst {st.worst_episodes:.0f})"
                if math.isfinite(st.worst_episodes)
                else ""
            )
        )
    out = "; ".join(parts)
    return out[:1].upper() + out[1:] + "."


def _fmt_excess(v: float) -> str:
    return f"{v:.2g}" if abs(v) >= 1e-6 else "below $10^{-6}$"


def curvature_sentence(curv: CostCurvature, studies: list[SeedStudy]) -> str:
    """Why CMA-ES converges to rounding level and ARS does not: the valley and common random numbers."""
    ars = next((s for s in studies if s.method == "ars"), None)
    cma_ = next((s for s in studies if s.method == "cma"), None)
    out = (
        f"At the optimum the Hessian of $J$ in $(K_x, K_v)$ has eigenvalues in the ratio {curv.ratio:.3g} : 1; the "
        f"flat direction, the valley, is $(\\Delta K_x, \\Delta K_v) \\propto ({curv.valley[0]:.3f}, "
        f"{curv.valley[1]:.3f})$, {curv.valley_angle:.3g}° from the $K_x$ axis, so along it both gains change "
        "together and the cost barely moves. "
    )
    out += (
        "Each training objective is the mean cost over the iteration's initial states, the same states for every "
        "candidate (common random numbers). Without a disturbance the episode cost from any one initial state "
        "$s_0$ is $s_0^\\top M(K) s_0$, and the LQR gain minimises $M(K)$ for every $s_0$ at once: every sampled "
        "objective has the same minimiser. The sampling noise therefore vanishes at the optimum, and a method that "
        "shrinks its steps, CMA-ES, can converge to rounding level"
    )
    if cma_ is not None:
        out += f" (worst $J/J^* - 1$ over its seeds {_fmt_excess(cma_.worst_ratio - 1)})"
    out += "; augmented random search keeps a fixed step and wanders along the valley"
    if ars is not None:
        out += f" (worst {_fmt_excess(ars.worst_ratio - 1)})"
    return out + "."


def robustness_table(rb: Robustness) -> Table:
    """Each law's cost on each changed plant over that plant's exact optimum (forcing phase known)."""
    rows = []
    for v, name in enumerate(rb.variations):
        row = {"var": name, "opt": float(rb.optimum[v])}
        for j in range(len(rb.laws)):
            row[f"r{j}"] = float(rb.cost[v, j] / rb.optimum[v])
            row[f"s{j}"] = float(rb.stderr[v, j] / rb.optimum[v])
        rows.append(row)
    cols = [Column("var", "plant change"), Column("opt", "J_opt (s)", 4)]
    for j, law in enumerate(rb.laws):
        cols += [Column(f"r{j}", f"{law}: J / J_opt", 4), Column(f"s{j}", "±", 2)]
    return Table(
        rows,
        cols,
        caption="Laws designed on the nominal plant, run on changed plants: cost over the changed plant's exact "
        "optimum (forcing phase known).",
        name="tab-learning-robustness",
        notes=(
            f"Mean over the same {rb.n_episodes} seeded episodes per plant (force bound applied), ± one standard "
            "error; J_opt: exact finite-horizon LQ optimum of the changed task.",
        ),
    )


def robustness_sentence(rb: Robustness) -> str:
    """The worst plant change for each law."""
    parts = []
    ratio = rb.cost / rb.optimum[:, None]
    for j, law in enumerate(rb.laws):
        v = int(np.argmax(ratio[:, j]))
        parts.append(f"{law} from {ratio[0, j]:.3g} to at worst {ratio[v, j]:.3g} ({rb.variations[v]})")
    return (
        "Over the plant changes the cost over each plant's own optimum moves: " + "; ".join(parts) + ". "
        "No law was redesigned for the changed plant."
    )


def identify_design_sentence(d: IdentifyDesign, cmp: Comparison, learned: int, id_i: int, train_steps: int) -> str:
    """Identify-then-design against the learner: data used and cost on the same episodes."""
    dd, se = cmp.paired_gain(learned, id_i)
    rel, rse = dd / cmp.runs[learned].mean_cost, se / cmp.runs[learned].mean_cost
    same = abs(dd) <= 3 * se
    verdict = (
        f"the same as the learned law's within the sampling error ({rel:+.2%} ± {rse:.1g})"
        if same
        else f"{_pct(abs(rel))} {'more' if dd > 0 else 'less'} than the learned law's (± {_pct(rse)})"
    )
    return (
        f"Identify, then design: one {d.duration:g} s broadband test record ({d.samples} samples, noise "
        f"{d.noise:.0%} of the response) gives $m = {d.fitted[0]:.4g} \\pm {d.stderr[0]:.1g}$ kg, "
        f"$c = {d.fitted[1]:.3g} \\pm {d.stderr[1]:.1g}$ N s/m and $k = {d.fitted[2]:.4g} \\pm {d.stderr[2]:.1g}$ N/m "
        f"(chapter 10's method); the best fixed gain designed on that fit, "
        f"$K = [{d.fixed_gains[0]:.3g}, {d.fixed_gains[1]:.3g}]$, costs {cmp.runs[id_i].mean_cost:.4g} s on the "
        f"episodes, {verdict}, from {d.samples} samples of data against the learner's "
        f"{train_steps / 1e6:.3g} million simulated steps."
    )


def _resonance_bullet(active: Comparison, learned: int, lqr: int, fixed: int, exo: ExosystemOptimum) -> str:
    run = active.runs[learned]
    g_exo = (run.mean_cost - exo.expected_cost) / exo.expected_cost
    d_f, se_f = active.paired_gain(fixed, learned)
    d_q, _ = active.paired_gain(lqr, learned)
    rel_f = d_f / active.runs[fixed].mean_cost
    vs_fixed = (
        "matches the best fixed gain on $[x, v]$ within the sampling error"
        if abs(d_f) <= 3 * se_f
        else f"costs {_pct(abs(rel_f))} {'more' if d_f > 0 else 'less'} than the best fixed gain on $[x, v]$"
    )
    kind = "optimum" if exo.within_bound else "lower bound"
    return (
        f"* **Resonance disturbance, force actuator.** The learned law {vs_fixed} (± "
        f"{_pct(se_f / active.runs[fixed].mean_cost)}), the best linear law of its observation, and costs "
        f"{_pct(g_exo)} "
        f"(± {_pct(run.cost_sem / exo.expected_cost)}) more than the exact {kind}, which needs the forcing phase. "
        f"LQR, designed for the task without the disturbance, costs {_pct(-d_q / run.mean_cost)} more than the "
        "learner; that gap measures the mismatch of LQR's task, not the learner's skill.\n"
    )
