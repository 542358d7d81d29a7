"""Figures of chapter 3, each a function of a :class:`SolverStudy` returning a :class:`Captioned` figure.

The caption of each figure is written from the figure's own layout (:func:`panel_words`) and the
study's numbers; the exact solution is drawn in the book's "exact" style (black, dashed), the
methods each keep one colour and marker in both figures.
"""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import LogFormatterSciNotation, LogLocator

from vibration.book.chapters.solver_accuracy.study import LATE, MACHINE_DEPENDENT, SolverStudy
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.narrative import listing
from vibration.book.presentation.numbers import integer
from vibration.book.presentation.numbers import sig as num
from vibration.book.presentation.style import OKABE_ITO, case_style, figure, place_legend

#: One colour and marker per method (the paper's RK45 in the nominal case's blue).
METHOD_STYLE = {
    "RK45": {"color": OKABE_ITO["blue"], "marker": "o"},
    "DOP853": {"color": OKABE_ITO["orange"], "marker": "s"},
    "LSODA": {"color": OKABE_ITO["bluish green"], "marker": "^"},
    "Radau": {"color": OKABE_ITO["reddish purple"], "marker": "D"},
}


def tightening_direction(study: SolverStudy) -> tuple[list[str], list[str]]:
    """Methods (machine-independent ones only) whose evaluations rise, and fall, as the tolerance tightens."""
    rising, other = [], []
    for method in study.methods:
        if method in MACHINE_DEPENDENT:
            continue
        nfev = [r.nfev for r in study.ladder(method)]  # loosest tolerance first
        (rising if all(b > a for a, b in zip(nfev, nfev[1:], strict=False)) else other).append(method)
    return rising, other


def work_precision_figure(study: SolverStudy) -> Captioned:
    """Worst displacement error against evaluations (deterministic) and against wall time (this machine)."""
    fig, (ax_n, ax_t) = figure(1, 2, height=3.4, sharey=True)
    for method in study.methods:
        runs = study.ladder(method)
        style = METHOD_STYLE.get(method, {"color": OKABE_ITO["grey"], "marker": "x"})
        err = [r.err_x for r in runs]
        ax_n.loglog([r.nfev for r in runs], err, ls="-", ms=4, label=method, **style)
        ax_t.loglog([r.time_s for r in runs], err, ls="-", ms=4, label=method, **style)
    ax_n.set_xlabel("right-hand-side evaluations")
    ax_t.set_xlabel("wall time (s)")
    ax_n.set_ylabel(r"max $|x - x_\mathrm{exact}|$ (m)")
    for ax in (ax_n, ax_t):
        ax.xaxis.set_major_locator(LogLocator(base=10.0, numticks=5))
        # label 2 and 5 times each power of ten only: every minor label collides with its neighbours
        ax.xaxis.set_minor_locator(LogLocator(base=10.0, subs=(2.0, 5.0), numticks=12))
        ax.xaxis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(3, 3)))
        ax.grid(True, which="major", alpha=0.3)
    place_legend(ax_n)
    left, right = panel_words(fig)
    rising, other = tightening_direction(study)
    direction = (
        f"Along the {listing(rising)} lines the tolerance tightens from left to right: each tighter tolerance costs "
        "more evaluations"
        if rising
        else "No method's evaluations rise steadily with its tolerance"
    )
    if other:
        direction += f" (not so for {listing(other)})"
    shaky = [m for m in study.methods if m in MACHINE_DEPENDENT]
    if shaky:
        direction += f"; {listing(shaky)}'s counts depend on the machine's rounding"
    caption = (
        f"Worst displacement error of each run against its right-hand-side evaluations ({left}) and its wall time on "
        f"the machine that built this page ({right}), logarithmic axes, one line per method "
        f"({listing(list(study.methods))}), {len(study.runs)} runs in all."
    )
    alt = (
        "Two log-log plots of the worst displacement error against the number of function evaluations and against "
        f"the run time for {len(study.methods)} integrators; the error falls as the work rises, fastest for "
        f"{study.reach.cheapest}."
    )
    return Captioned(fig, caption, "fig-solvers-work-precision", alt, remark=f"{direction}.")


def own_steps_figure(study: SolverStudy) -> Captioned:
    """The last forcing periods: the exact displacement on the output grid and RK45's own steps."""
    t0, t1 = study.step_window
    fig, ax = figure(1, 1, height=3.0)
    sel = study.exact.t >= t0
    ax.plot(study.exact.t[sel], study.exact.x[sel], lw=1.0, label="exact, on the output grid", **case_style("exact"))
    own = study.own.t >= t0
    style = METHOD_STYLE["RK45"]
    ax.plot(
        study.own.t[own],
        study.own.x[own],
        ls="-",
        lw=0.9,
        ms=3.5,
        label="RK45 at its default tolerances, its own steps only",
        **style,
    )
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"displacement $x$ (m)")
    ax.set_ylim(top=ax.get_ylim()[1] * 1.45)
    place_legend(ax, ncols=1)
    s = study.steps[0]
    n_periods = (t1 - t0) / study.period
    n_steps = int(np.count_nonzero(own))
    caption = (
        f"The last {num(n_periods, 2)} forcing periods of the resonance case (t from {num(t0, 3)} to {num(t1, 3)} s): "
        "the exact displacement on the output grid (black, dashed) and straight lines through the "
        f"{integer(n_steps)} steps RK45 takes there at its default tolerances (blue dots)."
    )
    remark = (
        f"The peaks of the line through RK45's steps fall short of the exact ones, by {num(100 * s.shortfall, 2)} % "
        f"on average over the last {num(100 * LATE, 2)} % of the window."
    )
    alt = (
        "Displacement against time over the last forcing periods: a dashed black exact sine wave and a blue line "
        f"through about {num(s.per_period, 2)} solver steps per period whose corners reach "
        f"{num(100 * (1 - s.shortfall), 3)} % of the exact peaks on average."
    )
    return Captioned(fig, caption, "fig-solvers-steps", alt, remark=remark)
