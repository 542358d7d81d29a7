"""Chapter 3's tables, each a function of one :class:`SolverStudy`.

A method whose steps change with the last bit of the arithmetic (:attr:`LadderRun.machine_dependent`) writes its
counts and errors with the tolerance the regression comparison allows them.

Examples
--------
>>> from vibration.book.chapters.solver_accuracy.study import solver_accuracy_study
>>> st = solver_accuracy_study(t_end=10.0, n_points=1001)
>>> [c.header for c in steps_table(st).columns][-3:]
['mean peak of the steps (m)', 'lowest peak of the steps (m)', 'exact peak |x| (m)']
"""

from __future__ import annotations

from vibration.book.chapters.solver_accuracy.study import LATE, SolverStudy
from vibration.book.presentation.narrative import g
from vibration.book.presentation.numbers import integer
from vibration.book.presentation.tables import Approx, Column, Table, columns

#: Tolerances of a machine-dependent method's cells in the regression comparison: evaluations within
#: 25 %, errors within a factor of 5 (a last-bit change of the input moves them by up to 10 % and 4 times).
NFEV_RTOL = 0.25
ERROR_FACTOR = 5.0

#: The pair the paper names ("Runge-Kutta-Fehlberg (RK45)", section 2.2).
PAPER_PAIR = "Runge-Kutta-Fehlberg 4(5)"


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


__all__ = ["ERROR_FACTOR", "NFEV_RTOL", "PAPER_PAIR", "ladder_table", "pair_table", "steps_table"]
