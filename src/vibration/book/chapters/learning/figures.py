"""Figures of the learning chapter, each a function of a :class:`LearningStudy` returning :class:`Captioned`.

Styles come from the book's visual language (:func:`vibration.book.presentation.style.case_style`): the
optimum is black (dotted line, star), targets are grey dotted, the learned laws vermillion (ARS
dashed as the book's "learned" case, CMA-ES solid), LQR orange dashed, the best passive or constant
damper sky blue dashed, clipped skyhook green dashed. Captions name the panels from the layout
(:func:`vibration.book.presentation.captions.panel_words`) and say which curves coincide, measured.
"""

from __future__ import annotations

import numpy as np

from vibration.book.chapters.learning.study import METHODS, TARGETS, LearningStudy
from vibration.book.chapters.learning.text import SHORT_NAMES, num, pct
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.style import case_style, figure, place_legend

#: Two curves of one panel coincide when they differ by at most this fraction of the panel's largest value.
COINCIDE = 0.01
#: Seconds of the episode the damping panel shows.
T_ZOOM = 3.0
#: Floor of the excess J/J* - 1 drawn on its logarithmic axis.
DRAW_FLOOR = 1e-12
#: Range of the excess J/J* - 1 the cost map colours (clipped outside).
SURFACE_RANGE = (1e-6, 1e6)

LEARNER_STYLE = {
    "ars": case_style("learned"),
    "cma": {**case_style("learned"), "linestyle": "-"},
}
#: Controller name of a comparison -> case of the book's visual language.
CASE_OF = {
    "no control": "passive",
    "plant damping": "passive",
    "best passive damper": "best passive",
    "best constant damping": "best passive",
    "LQR": "LQR",
    "clipped LQR": "LQR",
    "clipped skyhook": "skyhook",
    "learned (ARS)": "learned",
    "best fixed gain": "PD",
    "identified, then designed": "robust",
}
STYLE_WORDS = {"-": "solid", "--": "dashed", ":": "dotted", "-.": "dash-dotted"}
COLOUR_WORDS = {
    "#000000": "black",
    "#E69F00": "orange",
    "#56B4E9": "sky blue",
    "#009E73": "green",
    "#0072B2": "blue",
    "#D55E00": "vermillion",
    "#CC79A7": "purple",
    "#7F7F7F": "grey",
}


def _look(style: dict) -> str:
    """'vermillion, dashed' for a case style."""
    return f"{COLOUR_WORDS[style['color']]}, {STYLE_WORDS[style['linestyle']]}"


def _panels(fig, parts: list[str]) -> str:
    """'Top left: ... Top right: ... Bottom: ...' from the figure's layout, one part per data axes."""
    words = panel_words(fig)
    if not words:
        return " ".join(parts)
    return " ".join(f"{w[:1].upper()}{w[1:]}: {p}" for w, p in zip(words, parts, strict=True))


def coinciding(curves: dict[str, np.ndarray], tol: float = COINCIDE) -> list[tuple[str, str]]:
    """Pairs of named curves (same samples) that differ by at most ``tol`` of the largest |value| of all."""
    names = list(curves)
    scale = max(float(np.nanmax(np.abs(c))) for c in curves.values())
    out = []
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            if float(np.nanmax(np.abs(curves[a] - curves[b]))) <= tol * scale:
                out.append((a, b))
    return out


def groups(names: list[str], pairs: list[tuple[str, str]]) -> list[list[str]]:
    """Groups of names joined by the pairs (connected components), each in ``names`` order, largest first."""
    group = {n: {n} for n in names}
    for a, b in pairs:
        merged = group[a] | group[b]
        for n in merged:
            group[n] = merged
    out, seen = [], set()
    for n in names:
        if n not in seen and len(group[n]) > 1:
            out.append([m for m in names if m in group[n]])
            seen |= group[n]
    return out


def _coincide_clause(curves: dict[str, np.ndarray]) -> str:
    """'; the A and B curves coincide to within 1 % of the largest value' for the groups that coincide."""
    found = groups(list(curves), coinciding(curves))
    if not found:
        return ""
    said = "; ".join(
        ("the " + ", ".join(g[:-1]) + f" and {g[-1]} curves" if len(g) > 2 else f"the {g[0]} and {g[1]} curves")
        for g in found
    )
    return f"; {said} coincide to within {pct(COINCIDE, 2)} of the largest value"


# ----------------------------------------------------------------------------- learning curves


def learning_figure(st: LearningStudy) -> Captioned:
    """Learning curves against the optimum: the cost itself, and its excess over the optimum."""
    fig, (ax0, ax1) = figure(1, 2, height=3.4)
    j_star = st.ref.expected_cost
    for res in st.learners:
        e, c = res.curve_episodes[1:], res.curve_cost[1:]
        ax0.plot(e, c, label=SHORT_NAMES[res.method], **LEARNER_STYLE[res.method])
        excess = c / j_star - 1.0
        ax1.plot(e, np.maximum(excess, DRAW_FLOOR), label=SHORT_NAMES[res.method], **LEARNER_STYLE[res.method])
    ax0.axhline(j_star, lw=1.0, label="LQR optimum $J^*$", **case_style("optimum"))
    ax0.set_xscale("log")
    ax0.set_xlabel("training episodes")
    ax0.set_ylabel("expected cost $J$ (s)")
    place_legend(ax0)
    for target in TARGETS:
        ax1.axhline(target, lw=1.0, **case_style("threshold"))
        ax1.annotate(
            f"{pct(target, 2)}", (0.01, target), xycoords=("axes fraction", "data"), ha="left", va="bottom", fontsize=8
        )
    ax1.set_xscale("log")
    ax1.set_yscale("log")
    ax1.set_xlabel("training episodes")
    ax1.set_ylabel(r"$J/J^* - 1$")
    place_legend(ax1)
    ars, cma = (LEARNER_STYLE[m] for m in METHODS)
    targets = " and ".join(pct(t, 2) for t in TARGETS)
    parts = [
        f"exact expected cost $J$ of each learner's current gains against the training episodes used, ARS "
        f"({_look(ars)}) and CMA-ES ({_look(cma)}), with the LQR optimum $J^*$ (black, dotted); logarithmic "
        "episode axis.",
        f"the excess over the optimum, $J/J^* - 1$, with the {targets} targets (grey, dotted); both axes logarithmic.",
    ]
    caption = _panels(fig, parts)
    meets = _meets(st)
    remark = (
        f"{meets[:1].upper()}{meets[1:]}. An excess below {num(DRAW_FLOOR, 1)} would be drawn at {num(DRAW_FLOOR, 1)}."
    )
    final = ", ".join(f"{SHORT_NAMES[r.method]} at {_ratio_words(st, r)}" for r in st.learners)
    onto = "falling onto" if all(settled_within(st, r) == settled_within(st, r) for r in st.learners) else "approaching"
    alt = (
        f"Learning curves of ARS and CMA-ES, expected cost against training episodes, {onto} the LQR optimum "
        f"line; final cost over the optimum: {final}."
    )
    return Captioned(fig, caption, "fig-learning-curves", alt, remark=remark)


def settled_within(st: LearningStudy, res, tol: float = COINCIDE) -> float:
    """Training episodes from which a learner's curve stays within ``tol`` of ``J*`` to the end (nan: never)."""
    ok = res.curve_cost <= (1.0 + tol) * st.ref.expected_cost
    if not ok[-1]:
        return float("nan")
    first = len(ok) - int(np.argmin(ok[::-1])) if not ok.all() else 0
    return float(res.curve_episodes[first])


def _meets(st: LearningStudy) -> str:
    """Which curves coincide with the optimum line, measured: "the ARS curve coincides with the optimum line to
    within 1 % from 192 episodes on"."""
    parts = []
    for res in st.learners:
        e = settled_within(st, res)
        name = SHORT_NAMES[res.method]
        if e == e:
            parts.append(
                f"the {name} curve coincides with the optimum line to within {pct(COINCIDE, 2)} from {int(e)} "
                "episodes on"
            )
        else:
            parts.append(f"the {name} curve ends above the optimum line by more than {pct(COINCIDE, 2)}")
    return "; ".join(parts)


def _ratio_words(st: LearningStudy, res) -> str:
    excess = st.ratio(res) - 1.0
    return f"{1 + excess:.5f}" if excess >= 1e-5 else f"1 within {num(1e-5, 1)}"


def surface_figure(st: LearningStudy) -> Captioned:
    """Each learner's path over the exact cost surface of the linear law, with the valley of the optimum."""
    fig, axes = figure(1, len(st.learners), height=3.6, sharey=True)
    sf, j_star = st.surface, st.ref.expected_cost
    with np.errstate(divide="ignore", invalid="ignore"):
        excess = np.log10(np.clip(sf.cost / j_star - 1.0, SURFACE_RANGE[0], SURFACE_RANGE[1]))
    levels = np.arange(np.log10(SURFACE_RANGE[0]), np.log10(SURFACE_RANGE[1]) + 0.25, 0.5)
    valley = st.curvature.valley
    span = 0.5 * max(np.ptp(sf.kx), np.ptp(sf.kv))
    line = st.ref.gains[:, None] + np.outer(valley, [-span, span])
    parts = []
    for ax, res in zip(axes, st.learners, strict=True):
        cs = ax.contourf(sf.kx, sf.kv, excess, levels=levels, cmap="viridis")
        style = LEARNER_STYLE[res.method]
        ax.plot(res.curve_gains[:, 0], res.curve_gains[:, 1], lw=1.2, marker=".", ms=3, label=SHORT_NAMES[res.method],
                **style)  # fmt: skip
        ax.plot(line[0], line[1], lw=1.0, label="valley", **case_style("threshold"))
        ax.plot(*st.ref.gains, ls="none", ms=12, mfc="white", mec="black", marker="*", label="LQR gain")
        ax.set_xlim(sf.kx[0], sf.kx[-1])
        ax.set_ylim(sf.kv[0], sf.kv[-1])
        ax.set_xlabel(r"$K_x$ (N/m)")
        ax.set_title(SHORT_NAMES[res.method], loc="left")
        ax.grid(False)
        place_legend(ax)
        parts.append(f"{SHORT_NAMES[res.method]} ({_look(style)}).")
    axes[0].set_ylabel(r"$K_v$ (N s/m)")
    cb = fig.colorbar(cs, ax=list(axes))
    cb.set_label(r"$\log_{10}(J/J^* - 1)$")
    caption = (
        "Each learner's gains, iteration by iteration from $K = [0, 0]$, over the exact expected cost of the linear "
        f"law, coloured by the excess over the optimum $J/J^* - 1$ in decades (from {num(SURFACE_RANGE[0], 1)} to "
        f"{num(SURFACE_RANGE[1], 1)}). {_panels(fig, parts)} The star is the LQR gain, the grey dotted line the "
        "cost's flattest direction at the optimum."
    )
    first, *rest = (f"{SHORT_NAMES[r.method]} {len(r.curve_gains) - 1}" for r in st.learners)
    runs = f"{first} iterations" + "".join(f", {r}" for r in rest)
    remark = (
        f"{runs.replace(' ', ' ran ', 1)}. The flattest direction lies "
        f"{num(st.curvature.valley_angle)}° from the $K_x$ axis."
    )
    alt = (
        "Two contour maps of the expected cost over the two gains, each with a long narrow valley through the LQR "
        "gain and one learner's path from the origin into the valley, ending "
        + ("at the star." if all(st.ratio(r) <= 1.0 + TARGETS[-1] for r in st.learners) else "short of the star.")
    )
    return Captioned(fig, caption, "fig-learning-surface", alt, remark=remark)


# ----------------------------------------------------------------------------- one episode of each task


def _damping(run, episode: int) -> np.ndarray:
    v, u = run.v[episode], run.u[episode]
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(v != 0.0, -u / v, np.nan)


#: Controllers drawn in each panel of the episode figure.
EPISODE_SHOW = {
    "active": ("best passive damper", "LQR", "learned (ARS)"),
    "semi": ("best constant damping", "clipped skyhook", "learned (ARS)"),
    "damping": ("clipped LQR", "learned (ARS)"),
}


def episode_figure(st: LearningStudy, episode: int = 0) -> Captioned:
    """One evaluation episode of each task: x(t) of chosen controllers, and the damping the clipped laws command."""
    fig, axes = figure(3, 1, height=6.8, sharex=False)
    t = st.active.runs[0].t
    sel = t <= T_ZOOM
    drawn: dict[str, dict[str, np.ndarray]] = {}
    for ax, cmp, key in ((axes[0], st.active, "active"), (axes[1], st.semi, "semi"), (axes[2], st.semi, "damping")):
        drawn[key] = {}
        for name in EPISODE_SHOW[key]:
            run = cmp.runs[cmp.names.index(name)]
            y = run.x[episode] if key != "damping" else _damping(run, episode)[sel]
            tt = t if key != "damping" else t[sel]
            style = case_style(CASE_OF[name], marker=True)
            ax.plot(
                tt, y, lw=1.1, label=name, markevery=max(1, len(tt) // 12), ms=4,
                drawstyle="steps-post" if key == "damping" else "default", **style,
            )  # fmt: skip
            drawn[key][name] = y
        ax.set_xlabel(r"$t$ (s)")
        place_legend(ax, outside=True)
    for ax in axes[:2]:
        ax.set_ylabel(r"$x$ (m)")
        ax.set_xlim(t[0], t[-1] + st.task.dt)
    axes[2].set_ylabel(r"damping $c$ (N s/m)")
    axes[0].set_title("force actuator, resonance force", loc="left")
    axes[1].set_title("semi-active damper, resonance force", loc="left")
    axes[2].set_title(f"semi-active damping commanded, first {T_ZOOM:g} s", loc="left")

    names = list(dict.fromkeys(n for key in EPISODE_SHOW for n in EPISODE_SHOW[key]))
    looks: dict[tuple[str, str], list[str]] = {}
    for n in names:
        style = case_style(CASE_OF[n])
        looks.setdefault((COLOUR_WORDS[style["color"]], STYLE_WORDS[style["linestyle"]]), []).append(n)
    one_style = len({ls for _, ls in looks}) == 1
    listed = "; ".join(
        " and ".join(group) + f", {colour}" + ("" if one_style else f" {ls}") for (colour, ls), group in looks.items()
    )
    lines = f"{next(iter(looks))[1].capitalize()} lines: {listed}." if one_style else f"Lines: {listed}."
    parts = [
        "displacement $x(t)$ with the force actuator.",
        "with the semi-active damper.",
        f"the damping $c(t)$ the clipped laws command, first {T_ZOOM:g} s.",
    ]
    first = "The first evaluation episode under the resonance force (one initial state for all)."
    caption = f"{first} {_panels(fig, parts)} {lines}"
    said = [
        (where + _coincide_clause(curves)[1:] + ".") if _coincide_clause(curves) else ""
        for where, curves in (
            ("With the force actuator,", drawn["active"]),
            ("With the semi-active damper,", drawn["semi"]),
            ("In the commanded damping,", {k: np.nan_to_num(v) for k, v in drawn["damping"].items()}),
        )
    ]
    remark = " ".join(s for s in said if s)
    switching = st.bound_fraction(st.s("learned (ARS)")) > 0.5
    alt = (
        "Three stacked time plots: the displacement under the resonance force with a force actuator and with a "
        "semi-active damper for three controllers each, and the damping coefficient two clipped laws command, the "
        + (
            "learned one mostly on the damper's bounds."
            if switching
            else "learned one mostly inside the damper's range."
        )
    )
    return Captioned(fig, caption, "fig-learning-episodes", alt, remark=remark)
