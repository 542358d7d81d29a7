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
from .style import figure, place_legend
from .tables import Column, Missing, Table, bound

__all__ = [
    "bound_fraction",
    "checks_table",
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

METHOD_NAMES = {"ars": "ARS (random search)", "cma": "CMA-ES"}


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
    # curvature of the exact cost along each gain at the optimum (central differences)
    h = 1e-2
    j0 = ref.expected_cost
    curv = []
    for e in (np.array([h, 0.0]), np.array([0.0, h])):
        jp, jm = _moments(task, ref.gains + e)[0], _moments(task, ref.gains - e)[0]
        curv.append((jp - 2.0 * j0 + jm) / h**2)
    worst = max(results, key=lambda r: r.expected_cost)
    err = np.abs(worst.gains - ref.gains)
    return (
        "; ".join(parts)
        + f". {verdict} The cost is {curv[1] / curv[0]:.3g} times more curved along $K_v$ than along $K_x$ at "
        f"the optimum, so the displacement gain is the loosely determined one: "
        f"{METHOD_NAMES[worst.method]}'s gains differ from LQR's by {err[0]:.2g} N/m in $K_x$ and "
        f"{err[1]:.2g} N s/m in $K_v$, for {100 * (worst.expected_cost / j0 - 1):.2g} % more cost."
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
        ax0.plot(e, c, color=colors[res.method], label=METHOD_NAMES[res.method])
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
) -> str:
    """The chapter's closing note: the learned-to-LQR ratio and the results without a closed form."""
    ratios = ", ".join(
        f"{METHOD_NAMES[r.method]} {r.expected_cost / ref.expected_cost:.5f} ({r.episodes} episodes)" for r in results
    )
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
        f"* **Against the optimum.** Learned-to-LQR expected-cost ratio: {ratios}; the target was 1.05.\n"
        f"* **Resonance disturbance, force actuator.** LQR is optimal only for the task it was designed for; "
        f"with the disturbance the learned linear law costs {100 * abs(da) / active.runs[lqr_active].mean_cost:.3g} % "
        f"{word_a} than LQR (± {100 * sa / active.runs[lqr_active].mean_cost:.2g} %) on the same episodes, with "
        f"gains K = [{ka[0]:.3g}, {ka[1]:.3g}]"
        + (f" that drive the force to its bound of {active.task.u_max:g} N.\n" if saturates else ".\n")
        + f"* **Semi-active damper.** The learned clipped law costs "
        f"{100 * abs(ds) / semi.runs[passive_semi].mean_cost:.3g} % {word_s} than the best constant damping "
        f"(c = {c_best:.3g} N s/m{', ' + at_bound if at_bound else ''}) on the same episodes "
        f"(± {100 * ss / semi.runs[passive_semi].mean_cost:.2g} %); its damping sits on {semi.task.c_min:g} or "
        f"{semi.task.c_max:g} N s/m {100 * bound_fraction(semi, learned_semi):.3g} % of the time."
    )
