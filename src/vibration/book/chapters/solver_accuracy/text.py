"""Chapter 3's tables and sentences, each a function of one :class:`SolverStudy`.

Every number is read from the study; every comparison word ("within", "more than", "the fewest",
which pair) is decided from those numbers, so a run with other parameters says what its tables say.

Examples
--------
>>> from vibration.book.chapters.solver_accuracy.study import solver_accuracy_study
>>> st = solver_accuracy_study(t_end=10.0, n_points=1001)
>>> print(key_results(st).splitlines()[0])
> **Key results**
>>> [c.header for c in steps_table(st).columns][-3:]
['mean peak of the steps (m)', 'lowest peak of the steps (m)', 'exact peak |x| (m)']
"""

from __future__ import annotations

from vibration.book.chapters.solver_accuracy.study import LATE, SolverStudy
from vibration.book.presentation.narrative import g
from vibration.book.presentation.numbers import integer
from vibration.book.presentation.numbers import sig as num
from vibration.book.presentation.tables import Approx, Column, Table, columns, cross_reference

#: The paper's method's worst error, relative to the peak displacement, below which it is called small.
SMALL = 0.01

#: Tolerances of a machine-dependent method's cells in the regression comparison: evaluations within
#: 25 %, errors within a factor of 5 (a last-bit change of the input moves them by up to 10 % and 4 times).
NFEV_RTOL = 0.25
ERROR_FACTOR = 5.0

#: The pair the paper names ("Runge-Kutta-Fehlberg (RK45)", section 2.2).
PAPER_PAIR = "Runge-Kutta-Fehlberg 4(5)"


def listing(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``.

    >>> listing(["RK45"]), listing(["RK45", "DOP853", "Radau"])
    ('RK45', 'RK45, DOP853 and Radau')
    """
    items = list(items)
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _count(study: SolverStudy, method: str, n: int) -> str:
    """Evaluations for a sentence; a machine-dependent method's count carries its regression tolerance."""
    text = integer(n)
    return (
        Approx(value=n, rtol=NFEV_RTOL).html(text) if any(r.machine_dependent for r in study.ladder(method)) else text
    )


# -- tables ------------------------------------------------------------------------------------


def ladder_table(study: SolverStudy) -> Table:
    """Each method at each tolerance: evaluations and worst errors against the exact solution.

    Examples
    --------
    >>> from vibration.book.chapters.solver_accuracy.study import solver_accuracy_study
    >>> st = solver_accuracy_study(t_end=10.0, n_points=1001)
    >>> [c.header for c in ladder_table(st).columns][:3]
    ['method', 'relative tolerance', 'absolute tolerance (m, m/s)']
    """
    rows = []
    for r in study.runs:
        # A machine-dependent method's counts scatter by up to about 10 % and its errors by a factor of
        # up to 4 between machines (see MACHINE_DEPENDENT): the tolerances of the regression comparison.
        count = (lambda v: Approx(value=v, rtol=NFEV_RTOL)) if r.machine_dependent else (lambda v: v)
        error = (lambda v: Approx(value=v, factor=ERROR_FACTOR)) if r.machine_dependent else (lambda v: v)
        rows.append(
            {
                "method": r.method,
                "rtol": r.rtol,
                "atol": r.atol,
                "nfev": count(r.nfev),
                "ex": error(r.err_x),
                "ev": error(r.err_v),
                "rel": error(r.rel_err_x),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            method  method
            rtol    relative tolerance           2
            atol    absolute tolerance (m, m/s)  2
            nfev    evaluations
            ex      max |x − x_exact| (m)        3
            ev      max |v − v_exact| (m/s)      3
            rel     relative to peak |x|         3
            """
        ),
        caption=(
            f"Each method at a ladder of tolerances on the resonance case (c = {g(study.osc.c)} N s/m, "
            f"ω = {g(study.force.omega)} rad/s): right-hand-side evaluations and the worst errors over the "
            f"{integer(study.exact.t.size)} output samples, against the exact solution. The first RK45 row is the "
            "paper's method."
        ),
        name="tab-solvers-ladder",
        notes=tuple(
            f"{m} picks its formulas and order as it goes, so its steps change with the last bit of the "
            "arithmetic: on another computer its evaluations differ by up to about 10 % and its errors by up to a "
            "factor of 4."
            for m in sorted({r.method for r in study.runs if r.machine_dependent})
        ),
    )


def steps_table(study: SolverStudy) -> Table:
    """RK45 on its own steps (no output grid): step sizes and the peak a line through them reaches."""
    rows = [
        {
            "rtol": s.rtol,
            "atol": s.atol,
            "steps": s.steps,
            "h": s.max_step,
            "pp": s.per_period,
            "ps": s.late_mean_peak,
            "pl": s.late_low_peak,
            "pe": s.late_exact_peak,
        }
        for s in study.steps
    ]
    return Table(
        rows=rows,
        columns=columns(
            """
            rtol   relative tolerance            2
            atol   absolute tolerance (m, m/s)   2
            steps  steps
            h      largest step (s)              3
            pp     steps per period              3
            ps     mean peak of the steps (m)    4
            pl     lowest peak of the steps (m)  4
            pe     exact peak |x| (m)            4
            """
        ),
        caption=(
            f"RK45 without an output grid returns only its own steps. Peaks in the last part of the window "
            f"(t ≥ {g((1 - LATE) * study.t_end)} s): the largest |x| among the steps of each half forcing period "
            "(mean and lowest) against the exact peak |x|."
        ),
        name="tab-solvers-steps",
    )


def pair_table(study: SolverStudy) -> Table:
    """The nodes c_i of the paper's RK45 beside those of the two candidate pairs."""
    rows = [{"pair": "the paper's RK45", "nodes": ", ".join(str(c) for c in study.nodes)}]
    rows += [{"pair": name.replace("-", "–"), "nodes": ", ".join(str(c) for c in ref)} for name, ref in study.pairs]
    return Table(
        rows=rows,
        columns=[Column(key="pair", header="Runge–Kutta pair"), Column(key="nodes", header="nodes c_i")],
        caption="The nodes of the paper's RK45 tableau beside those of the Dormand–Prince and Fehlberg pairs.",
        name="tab-solvers-pair",
    )


# -- sentences ---------------------------------------------------------------------------------


def _pair_name(name: str) -> str:
    return name.replace("-", "–")


def key_results(study: SolverStudy) -> str:
    """The key-results box: the chapter's headline numbers as a Markdown block quote."""
    paper, reach, s = study.paper, study.reach, study.steps[0]
    cheapest = reach.cheapest
    rk45 = reach.evaluations("RK45")
    cost = f"{cheapest} needs the fewest evaluations, {_count(study, cheapest, reach.evaluations(cheapest))}" + (
        f", against {_count(study, 'RK45', rk45)} for RK45" if cheapest != "RK45" and rk45 is not None else ""
    )
    named = "the Fehlberg pair the paper names" if study.pair == PAPER_PAIR else "not the Fehlberg pair the paper names"
    bullets = [
        f"The paper's method, RK45 at its default tolerances, stays within {num(paper.err_x, 3)} m of the exact "
        f"displacement over the whole window: {num(100 * paper.rel_err_x, 2)} % of the {num(study.peak)} m peak.",
        f"Accuracy costs work: to bring the error below {num(reach.target, 2)} m, {cost}.",
        f"A line through RK45's own steps undershoots the late peaks by {num(100 * s.shortfall, 2)} % on average, "
        f"because it takes only {num(s.per_period, 3)} steps per forcing period.",
        f"The paper's RK45 is the {_pair_name(study.pair)} pair, {named}.",
    ]
    return "\n".join(["> **Key results**", ">", *(f"> * {b}" for b in bullets)])


def case_text(study: SolverStudy) -> str:
    """The test case in numbers: the resonance case from rest, its window and its output grid."""
    osc, w = study.osc, study.force.omega
    n = study.exact.t.size
    per_period = (n - 1) / (study.t_end / study.period)
    return (
        f"The test case is the paper's resonance case from rest: m = {g(osc.m)} kg, k = {g(osc.k)} N/m, "
        f"c = {g(osc.c)} N s/m (ζ = {g(osc.damping_ratio, 3)}), forced with $F_0$ = {g(study.force.F0)} N at "
        f"ω = {g(w)} rad/s, {g(w / osc.natural_frequency, 4)} times the natural frequency. The window of "
        f"{g(study.t_end)} s holds {g(study.t_end / study.period, 3)} forcing periods, sampled at {integer(n)} points "
        f"({g(per_period, 3)} per period); the exact peak displacement is {num(study.peak)} m."
    )


def ladder_text(study: SolverStudy) -> str:
    """What the ladder shows: the paper's errors, and which method reaches the common error cheapest."""
    paper, reach = study.paper, study.reach
    cheapest = reach.cheapest
    others = ", ".join(f"{m} {_count(study, m, n)}" for m, n in reach.cost if m != cheapest)
    missed = [m for m in study.methods if reach.evaluations(m) is None]
    text = (
        f"At the integrator's default tolerances (relative {num(paper.rtol)}, absolute {num(paper.atol)}) "
        "the paper's RK45 misses the exact displacement "
        f"by at most {num(paper.err_x, 3)} m and the exact velocity by at most {num(paper.err_v, 3)} m/s, with "
        f"{integer(paper.nfev)} evaluations of the right-hand side.\n\n"
        f"The smallest error that every method of the ladder reaches is {num(reach.target, 2)} m. **{cheapest}** "
        f"gets there with the fewest evaluations ({_count(study, cheapest, reach.evaluations(cheapest))})"
        + (f"; the others need {others}." if others else ".")
    )
    if missed:
        text += f" {listing(missed)} does not reach it on this machine."
    return text


def steps_text(study: SolverStudy) -> str:
    """What the own-steps comparison shows, at the paper's tolerance and a tight one."""
    s, tight, paper = study.steps[0], study.steps[-1], study.paper
    change = "drops" if tight.shortfall < s.shortfall else "does not drop"
    grid = (
        f"On the output grid the same loose solver is off by only {num(100 * paper.rel_err_x, 2)} % of the peak "
        f"({cross_reference('tab-solvers-ladder')}): the grid a curve is drawn on, not the solver, decides how "
        "faithfully its peaks show."
        if paper.rel_err_x < s.shortfall
        else f"On the output grid the solver's own error, {num(100 * paper.rel_err_x, 2)} % of the peak "
        f"({cross_reference('tab-solvers-ladder')}), is as large: here the solver, not only the grid, limits the peaks."
    )
    return (
        f"At the paper's tolerance RK45 takes {integer(s.steps)} steps, {num(s.per_period, 3)} per forcing period, the "
        f"largest {num(s.max_step, 3)} s. Joined by straight lines, those steps reach on average "
        f"{num(s.late_mean_peak)} m per half period late in the window, and {num(s.late_low_peak)} m at worst, "
        f"where the exact peak is {num(s.late_exact_peak)} m. At a relative tolerance of {num(tight.rtol)} the "
        f"solver takes {num(tight.per_period, 3)} steps per period and the shortfall {change} to "
        f"{num(100 * tight.shortfall, 2)} %. " + grid
    )


def pair_text(study: SolverStudy) -> str:
    """Which pair the paper's RK45 is, from its nodes."""
    others = [name for name, nodes in study.pairs if nodes != study.nodes]
    differ = f"; the {listing([_pair_name(o) for o in others])} nodes differ" if others else ""
    return (
        f"The nodes $c_i$ of the paper's RK45 are those of the **{_pair_name(study.pair)}** pair{differ}. "
        "The pair decides which formula estimates the error and which one advances the solution, so the paper's "
        f"method is a {_pair_name(study.pair)} integrator whatever its name."
    )


def takeaways(study: SolverStudy) -> str:
    """What a designer takes away, in new words: conclusions, not the body's numbers again."""
    paper, reach = study.paper, study.reach
    cheapest = reach.cheapest
    if paper.rel_err_x < SMALL:
        trust = (
            f"For this oscillator the default tolerances are good enough to read amplitudes: "
            f"the error is below {num(100 * SMALL)} % of the peak, so discrepancies in the paper have other causes."
        )
    else:
        trust = (
            f"With these parameters the default tolerances are not good enough to read amplitudes: the error exceeds "
            f"{num(100 * SMALL)} % of the peak, so tighten the tolerance before trusting a number."
        )
    rk45 = reach.evaluations("RK45")
    if cheapest != "RK45" and rk45 is not None:
        switch = (
            f"When more digits are needed, change the method before tightening the tolerance: {cheapest} reaches "
            f"the common error with {num(rk45 / reach.evaluations(cheapest), 2)} times fewer evaluations than RK45."
        )
    else:
        switch = "When more digits are needed, tighten RK45's tolerance: no other method of the ladder is cheaper."
    radau = reach.evaluations("Radau")
    implicit = (
        f"An implicit method does not pay here, the problem is not stiff: Radau needs "
        f"{num(radau / reach.evaluations(cheapest), 2)} times the evaluations of {cheapest}."
        if radau is not None and cheapest != "Radau"
        else "The implicit Radau is the cheapest here, a sign of stiffness."
        if cheapest == "Radau"
        else "Radau does not reach the common error within its ladder."
    )
    bullets = [
        trust,
        switch,
        implicit,
        "Draw and measure peaks on a dense output grid or the solver's dense output, never through the steps alone.",
    ]
    return "\n".join("- " + b for b in bullets)
