"""Chapter 1's figures, each a function of a :class:`ReproductionStudy` returning a :class:`Captioned`.

Colours and line styles come from the book's visual language (:func:`vibration.book.presentation.style.case_style`):
the reference run orange, the nominal damping (the paper's resonance run) blue, the low damping
vermillion, the high damping green; the exact solution black and dashed, drawn as its envelope over the dense
oscillations of the paper's figures. Captions are built from
the drawn figure (its panel layout) and the study's numbers; each figure's remark says whether the
paper's method and the exact solution coincide, and by how much they differ.
"""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from vibration.book.chapters.reproduction.study import DAMPING_IDS, ReproductionStudy
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.findings import case_name
from vibration.book.presentation.narrative import g
from vibration.book.presentation.style import case_style, figure, place_legend
from vibration.physics.frequency import local_maxima

#: The book's case of each scenario (its colour and line style).
CASE_OF = {
    "reference": "reference",
    "resonance": "c_nominal",
    "damping_low": "c_low",
    "damping_nominal": "c_nominal",
    "damping_high": "c_high",
}
#: Colour words of those cases, for captions (checked against the drawing by Captioned).
COLOUR_WORD = {"reference": "orange", "c_nominal": "blue", "c_low": "vermillion", "c_high": "green"}
#: RK45 and the exact curve "coincide" in a caption when RK45's worst error is below this share of the peak.
COINCIDE = 0.05


def _legend_above(ax, handles, ncol: int):
    """A legend in a row above the axes (outside the data)."""
    return ax.legend(
        handles=handles, loc="lower left", bbox_to_anchor=(0.0, 1.02, 1.0, 0.1), ncol=ncol, borderaxespad=0.0,
        frameon=False,
    )  # fmt: skip


def envelope(t: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The curves through the successive maxima and through the successive minima of ``y(t)``, each starting at
    ``t[0]``: what a dense oscillation looks like from afar, drawn without the moiré of a dashed line over it.

    >>> t = np.linspace(0.0, 10.0, 2001)
    >>> tu, yu, tl, yl = envelope(t, np.sin(2 * np.pi * t))
    >>> len(tu), round(float(yu[1:].min()), 6), round(float(yl[1:].max()), 6)
    (11, 1.0, -1.0)
    """
    top, low = np.concatenate(([0], local_maxima(y))), np.concatenate(([0], local_maxima(-y)))
    return t[top], y[top], t[low], y[low]


def _draw_run(ax_x, ax_v, st: ReproductionStudy, sid: str) -> None:
    """RK45's displacement and velocity (the case's colour, solid), each under the exact solution's envelope."""
    paper, exact = st.paper[sid], st.exact[sid]
    style = case_style(CASE_OF[sid])
    exact_style = case_style("exact")
    for ax, y_paper, y_exact in ((ax_x, paper.x, exact.x), (ax_v, paper.v, exact.v)):
        ax.plot(paper.t, y_paper, lw=0.6, **style)
        t_top, top, t_low, low = envelope(exact.t, y_exact)
        ax.plot(t_top, top, lw=0.9, **exact_style)
        ax.plot(t_low, low, lw=0.9, **exact_style)


def coincidence(st: ReproductionStudy, ids, where: str) -> str:
    """The remark on RK45 and the exact curves of the runs ``ids`` (``where``: "In both runs"), from the worst error."""
    worst = max(st.cases[s].rel_err for s in ids)
    if worst < COINCIDE:
        return (
            f"{where} RK45 and the exact solution coincide at this scale: RK45's largest displacement error is "
            f"{g(100 * worst, 2)} % of the run's peak."
        )
    return (
        f"{where} RK45 and the exact solution differ visibly: RK45's largest displacement error reaches "
        f"{g(100 * worst, 2)} % of the run's peak."
    )


def resonance_figure(st: ReproductionStudy) -> Captioned:
    """The paper's Figure 1 redrawn: the resonance run against the reference run, by RK45 and exactly."""
    fig, (ax_x, ax_v) = figure(2, 1, height=5.0, sharex=True)
    ids = ("reference", "resonance")
    for sid in ids:
        _draw_run(ax_x, ax_v, st, sid)
    ax_x.set_ylabel(r"displacement $x$ (m)")
    ax_v.set_ylabel(r"velocity $v$ (m/s)")
    ax_v.set_xlabel(r"time $t$ (s)")
    res, ref = st.scenarios["resonance"], st.scenarios["reference"]
    handles = [
        Line2D([], [], lw=1.2, **case_style(CASE_OF[sid]), label=rf"{sid}, $\omega$ = {g(sc.force.omega)} rad/s, RK45")
        for sid, sc in (("resonance", res), ("reference", ref))
    ] + [Line2D([], [], lw=0.9, **case_style("exact"), label="exact closed form, envelope")]
    _legend_above(ax_x, handles, ncol=2)
    top, bottom = panel_words(fig)
    c = res.oscillator.c
    caption = (
        f"The resonance run (ω = {g(res.force.omega)} rad/s, {COLOUR_WORD[CASE_OF['resonance']]}) and the reference "
        f"run (ω = {g(ref.force.omega)} rad/s, {COLOUR_WORD[CASE_OF['reference']]}), both at c = {g(c)} N s/m and "
        f"from rest, by the paper's method (RK45, solid) within the exact solution's envelope (black, dashed). "
        f"{top.capitalize()}: displacement x(t); {bottom}: velocity v(t)."
    )
    alt = (
        f"Displacement and velocity against time over {g(st.t_end)} s: the resonance run builds up to an amplitude of "
        f"about {g(st.cases['resonance'].peak_x, 3)} m, the reference run stays near "
        f"{g(st.cases['reference'].peak_x, 3)} m."
    )
    return Captioned(fig, caption, "fig-reproduction-resonance", alt, remark=coincidence(st, ids, "In both runs"))


def damping_figure(st: ReproductionStudy) -> Captioned:
    """The paper's Figure 2 redrawn as small multiples: one column per damping, displacement above velocity."""
    fig, axes = figure(2, 3, height=4.6, sharex=True)
    for j, sid in enumerate(DAMPING_IDS):
        _draw_run(axes[0, j], axes[1, j], st, sid)
        axes[0, j].set_title(rf"{case_name(sid)}" + "\n" + rf"$c$ = {g(st.scenarios[sid].oscillator.c)} N s/m")
        axes[1, j].set_xlabel(r"$t$ (s)")
    axes[0, 0].set_ylabel(r"$x$ (m)")
    axes[1, 0].set_ylabel(r"$v$ (m/s)")
    handles = [
        Line2D([], [], lw=1.2, **case_style(CASE_OF[sid]), label=f"RK45, {case_name(sid)}") for sid in DAMPING_IDS
    ] + [Line2D([], [], lw=0.9, **case_style("exact"), label="exact, envelope")]
    fig.legend(handles=handles, loc="outside upper center", ncols=len(handles), frameon=False)
    words = panel_words(fig)
    cols = [words[j].split()[-1] for j in range(3)]  # left, middle, right
    rows = [words[0].split()[0], words[3].split()[0]]  # top, bottom
    w = st.scenarios["damping_low"].force.omega
    parts = []
    for col, sid in zip(cols, DAMPING_IDS, strict=True):
        c = st.scenarios[sid].oscillator.c
        extra = ", the resonance run above" if sid == "damping_nominal" and "resonance" in st.run_of(sid) else ""
        parts.append(f"{col}, {case_name(sid)} c = {g(c)} N s/m ({COLOUR_WORD[CASE_OF[sid]]}{extra})")
    caption = (
        f"RK45 (solid) within the exact solution's envelope (black, dashed), forced at ω = {g(w)} rad/s from rest: "
        f"{'; '.join(parts)}. {rows[0].capitalize()} row: displacement; {rows[1]} row: velocity; each panel on its "
        "own vertical scale."
    )
    peaks = ", ".join(f"{g(st.cases[s].peak_x, 3)} m" for s in DAMPING_IDS)
    alt = (
        f"Six panels of displacement and velocity against time for the low, nominal and high damping at resonance; "
        f"their largest displacements are {peaks}."
    )
    return Captioned(
        fig, caption, "fig-reproduction-damping", alt, remark=coincidence(st, DAMPING_IDS, "At the three dampings")
    )


def error_figure(st: ReproductionStudy) -> Captioned:
    """RK45's largest displacement error so far, relative to each distinct run's peak, on a logarithmic axis."""
    fig, ax = figure(1, 1, height=3.2)
    labels = []
    for run in st.runs:
        sid = run[0]
        err = np.abs(st.paper[sid].x - st.exact[sid].x) / max(st.cases[sid].peak_x, 1e-300)
        so_far = np.maximum.accumulate(err)
        name = " = ".join(case_name(s) for s in run)
        shown = np.where(so_far > 0, so_far, np.nan)
        ax.semilogy(st.paper[sid].t, shown, lw=1.2, **case_style(CASE_OF[sid]), label=name)
        labels.append(f"{name} ({COLOUR_WORD[CASE_OF[sid]]})")
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"$\max_{[0,\,t]}|x_\mathrm{RK45} - x|\ /\ \max|x|$")
    finals = [st.cases[run[0]].rel_err for run in st.runs if st.cases[run[0]].rel_err > 0]
    if finals:  # the first steps' errors at rounding level say nothing: show three decades below the smallest
        ax.set_ylim(bottom=max(min(finals) * 1e-3, 1e-16))
    place_legend(ax)
    worst = st.worst
    caption = (
        f"How far the paper's method strays from the exact solution: RK45's largest displacement error up to time "
        f"t, divided by the run's largest exact displacement, on a logarithmic axis, for each distinct run: "
        f"{', '.join(labels)}."
    )
    remark = (
        f"At the end of the window the largest of these errors is {g(100 * worst.rel_err, 2)} %, in the "
        f"{case_name(worst.scenario_id)} run."
    )
    alt = (
        f"Rising curves of RK45's relative error against time on a logarithmic scale for {len(st.runs)} runs; all "
        f"end at or below {g(100 * worst.rel_err, 2)} % of their peak displacement."
    )
    return Captioned(fig, caption, "fig-reproduction-error", alt, remark=remark)
