"""The front page's figure: the exact response at the paper's resonance against the amplitude it reports."""

from __future__ import annotations

import numpy as np

from vibration.book.chapters.overview.study import PAPER_SAYS, OverviewStudy
from vibration.book.presentation.captions import Captioned
from vibration.book.presentation.narrative import g
from vibration.book.presentation.style import case_style, figure, place_legend


def headline_figure(st: OverviewStudy) -> Captioned:
    """x(t) at the paper's resonance, exact, with the exact steady amplitude and the paper's ±5 m."""
    p = st.params
    fig, ax = figure(height=3.2)
    ax.plot(st.t, st.x, lw=0.9, **case_style("c_nominal"), label=rf"exact $x(t)$, $c$ = {g(p.c_nominal)} N s/m")
    paper_x = PAPER_SAYS["resonance_amplitude"][1]
    has_steady = bool(np.isfinite(st.x_res))
    if has_steady:
        ax.axhline(st.x_res, lw=1.2, **case_style("exact"), label=rf"exact steady amplitude $\pm${g(st.x_res, 4)} m")
        ax.axhline(-st.x_res, lw=1.2, **case_style("exact"))
    ax.axhline(paper_x, lw=1.5, **case_style("threshold"), label=rf"the paper's $\pm${g(paper_x)} m")
    ax.axhline(-paper_x, lw=1.5, **case_style("threshold"))
    ax.set_xlabel("$t$ (s)")
    ax.set_ylabel("$x$ (m)")
    top = max(paper_x, float(np.max(np.abs(st.x)))) * 1.6
    ax.set_ylim(-top, top)
    place_legend(ax, ncols=3)
    steady = f", the exact steady amplitude ±{g(st.x_res)} m (black, dashed)" if has_steady else ""
    caption = (
        f"The exact displacement at the paper's resonance, ω = {g(p.omega_res)} rad/s and c = {g(p.c_nominal)} N s/m "
        f"(blue), from rest over {g(p.t_end)} s{steady} and the amplitude the paper reports, ±{g(paper_x)} m "
        "(grey, dotted)."
    )
    peak = float(np.max(np.abs(st.x)))
    alt = (
        f"Displacement against time at resonance: the oscillation builds up to {g(peak, 3)} m and stays inside the "
        f"paper's ±{g(paper_x)} m lines."
        if peak < paper_x
        else f"Displacement against time at resonance: the oscillation reaches {g(peak, 3)} m, beyond the paper's "
        f"±{g(paper_x)} m lines."
    )
    return Captioned(fig, caption, "fig-front-resonance", alt)
