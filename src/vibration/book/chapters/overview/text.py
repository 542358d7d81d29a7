"""The front page's sentences and tables, all from an :class:`OverviewStudy`.

:func:`part1_findings` states what Part I finds in a few computed sentences (the book's front page
lists them; further parts may add theirs); :func:`headline_table` sets the paper's headline words
beside the exact values of this run; :func:`verdict_table` counts the claims audit's verdicts.
"""

from __future__ import annotations

import math

from vibration.book.chapters.overview.study import PAPER_SAYS, OverviewStudy
from vibration.book.presentation.narrative import fixed, g, sig
from vibration.book.presentation.tables import Column, Missing, Table, columns

#: RK45's largest relative gap to the exact values below which the front page says the solver is not the cause.
SMALL_GAP = 0.05

NO_STEADY = "no steady state exists when c < 0"


def stability_word(st: OverviewStudy) -> str:
    """The low damping's stability from its least stable pole: "stable", "marginally stable" or "unstable"."""
    if st.growth_low < 0:
        return "stable"
    return "marginally stable" if st.growth_low == 0 else "unstable"


def _compare(value: float, paper: float) -> str:
    return "below" if value < paper else "above" if value > paper else "equal to"


def part1_findings(st: OverviewStudy | None = None, **values) -> list[str]:
    """What Part I finds, in five computed Markdown sentences (no bullets), each naming its chapter.

    ``st`` is the front page's study; without it the study is computed from ``values`` (the front page's
    parameters, the paper's where not given), e.g. ``part1_findings(c_low=0.05)``.
    """
    if st is None:
        from vibration.book.chapters.overview.study import overview_study

        st = overview_study(**values)
    p = st.params
    out = []
    paper_x = PAPER_SAYS["resonance_amplitude"][1]
    paper_ratio = PAPER_SAYS["ratio"][1]
    if math.isfinite(st.x_res) and math.isfinite(st.ratio):
        out.append(
            f"At the paper's resonance (ω = {g(p.omega_res)} rad/s, c = {g(p.c_nominal)} N s/m) the exact steady "
            f"amplitude is {g(st.x_res)} m, {_compare(st.x_res, paper_x)} the paper's {g(paper_x)} m, and "
            f"{g(st.ratio, 3)} times the amplitude at ω = {g(p.omega_ref)} rad/s, where the paper says about "
            f"{g(paper_ratio)} times (chapter 1)."
        )
    else:
        out.append(
            f"With c = {sig(p.c_nominal)} N s/m the resonance case has no steady state: the displacement grows "
            "without bound (chapter 1)."
        )
    word = stability_word(st)
    text = f"The low damping c = {sig(p.c_low)} N s/m, which the paper calls unstable, is {word}"
    if word == "stable":
        text += f": its poles have the real part {sig(st.growth_low, 3)} 1/s"
        if math.isfinite(st.bounded_low):
            where = "still below" if st.peak_low < st.bounded_low else "already at or above"
            text += (
                f", and its largest displacement in the {g(p.t_end)} s window, {g(st.peak_low)} m, is {where} its "
                f"bounded steady amplitude of {g(st.bounded_low)} m"
            )
    elif word == "unstable":
        text += f": a pole has the real part +{g(st.growth_low, 3)} 1/s and the displacement grows without bound"
    else:
        text += ": its poles lie on the imaginary axis and its free vibration never decays"
    out.append(text + " (chapter 2).")
    held = st.verdicts.get("reproduced", 0)
    out.append(
        f"Of the paper's {st.n_claims} checkable claims, {held} hold as written against the exact solution of its "
        f"own equation and {st.n_claims - held} do not (chapter 2)."
    )
    if st.solver_gap < SMALL_GAP:
        out.append(
            "None of the gaps comes from the paper's numerical method: each audited number that the paper's RK45 "
            f"at its default tolerances gives lies within {g(100 * st.solver_gap, 2)} % of its exact value (chapter 1 "
            "measures the whole trajectory instead, against its largest displacement; chapter 3 says why)."
        )
    else:
        out.append(
            "With these parameters the paper's numerical method itself strays: an audited number that RK45 gives "
            f"differs from its exact value by up to {g(100 * st.solver_gap, 2)} % (chapters 1 and 3)."
        )
    paper_high = PAPER_SAYS["high_damping"][1]
    close = abs(st.peak_high - paper_high) <= 0.5 * paper_high
    out.append(
        f"High damping (c = {sig(p.c_high)} N s/m) keeps the largest displacement at {g(st.peak_high)} m, "
        + ("close to" if close else "against")
        + f" the paper's ±{g(paper_high)} m (chapter 1)."
    )
    return out


def findings_markdown(st: OverviewStudy) -> str:
    """:func:`part1_findings` as a Markdown bullet list."""
    return "\n".join(f"* {s}" for s in part1_findings(st))


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
