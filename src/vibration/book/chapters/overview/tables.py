"""The front page's tables, each a function of an :class:`OverviewStudy`: the paper's headline words beside the exact
values of this run, and the count of the claims audit's verdicts. The findings are written in the notebook.
"""

from __future__ import annotations

import math

from vibration.book.chapters.overview.study import PAPER_SAYS, OverviewStudy
from vibration.book.presentation.narrative import fixed, g, sig
from vibration.book.presentation.tables import Column, Missing, Table, columns

NO_STEADY = "no steady state exists when c < 0"


def stability_word(st: OverviewStudy) -> str:
    """The low damping's stability from its least stable pole: "stable", "marginally stable" or "unstable"."""
    if st.growth_low < 0:
        return "stable"
    return "marginally stable" if st.growth_low == 0 else "unstable"


def _cell(value: float, unit: str, digits: int = 4):
    if not math.isfinite(value):
        return Missing(reason=NO_STEADY)
    return f"{fixed(value, digits)} {unit}".strip()


def headline_table(st: OverviewStudy) -> Table:
    """The paper's headline numbers beside the exact values of this run."""
    p, say = st.params, PAPER_SAYS
    low = f"{stability_word(st)}, real part of the poles {sig(st.growth_low, 3)} 1/s"
    rows = [
        {
            "q": f"steady amplitude, ω = {g(p.omega_ref)} rad/s, c = {g(p.c_nominal)} N s/m",
            "paper": say["reference_amplitude"][0],
            "exact": _cell(st.x_ref, "m"),
        },
        {
            "q": f"steady amplitude, ω = {g(p.omega_res)} rad/s, c = {g(p.c_nominal)} N s/m",
            "paper": say["resonance_amplitude"][0],
            "exact": _cell(st.x_res, "m"),
        },
        {"q": "ratio of the two amplitudes", "paper": say["ratio"][0], "exact": _cell(st.ratio, "")},
        {
            "q": f"steady velocity amplitude, ω = {g(p.omega_res)} rad/s",
            "paper": say["resonance_velocity"][0],
            "exact": _cell(st.v_res, "m/s"),
        },
        {"q": f"c = {g(p.c_low)} N s/m at ω = {g(p.omega_res)} rad/s", "paper": say["low_damping"][0], "exact": low},
        {
            "q": f"largest |x| in {g(p.t_end)} s, c = {g(p.c_low)} N s/m",
            "paper": "exceeding the ±10.0 meter limit",
            "exact": _cell(st.peak_low, "m"),
        },
        {
            "q": f"largest |x| in {g(p.t_end)} s, c = {g(p.c_high)} N s/m",
            "paper": say["high_damping"][0],
            "exact": _cell(st.peak_high, "m"),
        },
    ]
    return Table(
        rows=rows,
        columns=columns(
            """
            q      quantity
            paper  the paper says
            exact  exact, this run
            """
        ),
        caption="The paper's headline numbers beside the exact solution of its own equation.",
        name="tab-front-headline",
        notes=(
            "The paper's words are quoted from its Findings; they refer to its parameters (m = 1 kg, k = 20 N/m, "
            "F₀ = 5 N, c = 0.1, 0.5 and 15 N s/m).",
        ),
    )


def verdict_table(st: OverviewStudy) -> Table:
    """How many of the audited claims got each verdict, most frequent first."""
    counts = sorted(((v, n) for v, n in st.verdicts.items() if n), key=lambda vn: (-vn[1], vn[0]))
    rows = [{"verdict": v, "n": n} for v, n in counts] + [{"verdict": "total", "n": st.n_claims}]
    return Table(
        rows=rows,
        columns=[Column(key="verdict", header="verdict"), Column(key="n", header="claims")],
        caption="Verdicts of the claims audit (chapter 2) for this run.",
        name="tab-front-verdicts",
    )
