"""Chapter 1's figures, each a function of a :class:`ReproductionStudy` returning a :class:`Captioned`.

Colours come from the book's visual language: the reference run orange, the resonance run blue, the
dampings of the list by position (:func:`vibration.book.presentation.style.series_style`: the paper's three
keep vermillion, blue and green); the exact solution black and dashed, drawn as its envelope over the dense
oscillations of the paper's figures. Captions say what is drawn; the chapter's text says what it shows.
"""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from vibration.book.chapters.reproduction.study import ReproductionStudy
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.narrative import g
from vibration.book.presentation.style import case_style, colour_word, figure, place_legend, series_style
from vibration.physics.frequency import local_maxima


def run_style(st: ReproductionStudy, sid: str) -> dict:
    """Colour and line style of a run: reference orange, resonance blue, the dampings by their place in the list."""
    if sid == "reference":
        return case_style("reference")
    if sid == "resonance":
        return case_style("c_nominal")
    return series_style(st.dampings.index(sid))


def colour_of(st: ReproductionStudy, sid: str) -> str:
    """The caption's word for a run's colour."""
    return colour_word(run_style(st, sid)["color"])


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
    style = run_style(st, sid)
    exact_style = case_style("exact")
    for ax, y_paper, y_exact in ((ax_x, paper.x, exact.x), (ax_v, paper.v, exact.v)):
        ax.plot(paper.t, y_paper, lw=0.6, **style)
        t_top, top, t_low, low = envelope(exact.t, y_exact)
        ax.plot(t_top, top, lw=0.9, **exact_style)
        ax.plot(t_low, low, lw=0.9, **exact_style)


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
        Line2D([], [], lw=1.2, **run_style(st, sid), label=rf"{sid}, $\omega$ = {g(sc.force.omega)} rad/s, RK45")
        for sid, sc in (("resonance", res), ("reference", ref))
    ] + [Line2D([], [], lw=0.9, **case_style("exact"), label="exact closed form, envelope")]
    _legend_above(ax_x, handles, ncol=2)
    top, bottom = panel_words(fig)
    c = res.oscillator.c
    caption = (
        f"The resonance run (ω = {g(res.force.omega)} rad/s, {colour_of(st, 'resonance')}) and the reference "
        f"run (ω = {g(ref.force.omega)} rad/s, {colour_of(st, 'reference')}), both at c = {g(c)} N s/m and "
        f"from rest, by the paper's method (RK45, solid) within the exact solution's envelope (black, dashed). "
        f"{top.capitalize()}: displacement x(t); {bottom}: velocity v(t)."
    )
    alt = (
        f"Displacement and velocity against time over {g(st.t_end)} s: the resonance run builds up to an amplitude of "
        f"about {g(st.cases['resonance'].peak_x, 3)} m, the reference run stays near "
        f"{g(st.cases['reference'].peak_x, 3)} m."
    )
    return Captioned(fig, caption, "fig-reproduction-resonance", alt)


def damping_figure(st: ReproductionStudy) -> Captioned:
    """The paper's Figure 2 redrawn as small multiples: one column per damping, displacement above velocity."""
    ids = st.dampings
    fig, axes = figure(2, len(ids), height=4.6, sharex=True, squeeze=False)
    for j, sid in enumerate(ids):
        _draw_run(axes[0, j], axes[1, j], st, sid)
        axes[0, j].set_title(rf"$c$ = {g(st.cases[sid].c)} N s/m")
        axes[1, j].set_xlabel(r"$t$ (s)")
    axes[0, 0].set_ylabel(r"$x$ (m)")
    axes[1, 0].set_ylabel(r"$v$ (m/s)")
    handles = [Line2D([], [], lw=1.2, color="0.35", label="RK45"),
               Line2D([], [], lw=0.9, **case_style("exact"), label="exact, envelope")]  # fmt: skip
    fig.legend(handles=handles, loc="outside upper center", ncols=len(handles), frameon=False)
    w = st.scenarios[ids[0]].force.omega
    order = "" if len(ids) == 1 else " (columns in the list's order)"
    caption = (
        f"One column per damping{order}, forced at ω = {g(w)} rad/s from rest: RK45 (solid, in each damping's "
        "colour) within the exact solution's envelope (black, dashed); displacement above, velocity below, each "
        "panel on its own vertical scale."
    )
    peaks = ", ".join(f"{g(st.cases[s].peak_x, 3)} m" for s in ids)
    alt = (
        f"{2 * len(ids)} panels of displacement and velocity against time, one column per damping at resonance; "
        f"their largest displacements are {peaks}."
    )
    return Captioned(fig, caption, "fig-reproduction-damping", alt)


def error_figure(st: ReproductionStudy) -> Captioned:
    """RK45's largest displacement error so far, relative to each distinct run's peak, on a logarithmic axis."""
    fig, ax = figure(1, 1, height=3.2)
    labels = []
    for run in st.runs:
        sid = run[0]
        err = np.abs(st.paper[sid].x - st.exact[sid].x) / max(st.cases[sid].peak_x, 1e-300)
        so_far = np.maximum.accumulate(err)
        name = st.run_name(sid)
        shown = np.where(so_far > 0, so_far, np.nan)
        ax.semilogy(st.paper[sid].t, shown, lw=1.2, **run_style(st, sid), label=name)
        labels.append(f"{name} ({colour_of(st, sid)})")
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
    alt = (
        f"Rising curves of RK45's relative error against time on a logarithmic scale for {len(st.runs)} runs; all "
        f"end at or below {g(100 * worst.rel_err, 2)} % of their peak displacement."
    )
    return Captioned(fig, caption, "fig-reproduction-error", alt)
