"""Chapter 1's tables, each a function of a :class:`ReproductionStudy`, and its findings file.

One row per distinct run: a damping of the list that equals ``c_nominal`` is the resonance run, shown once.
"""

from __future__ import annotations

import csv
import math
import os
from pathlib import Path

from vibration.book.chapters.reproduction.study import CaseRun, ReproductionStudy
from vibration.book.presentation.findings import NO_STEADY
from vibration.book.presentation.narrative import fixed, g
from vibration.book.presentation.tables import TABLES_ENV, Missing, Table, columns, fmt


def _xss_cell(f: CaseRun, value: float, digits: int = 4):
    if f.c < 0:
        return Missing(reason=NO_STEADY)
    return fixed(value, digits) if math.isfinite(value) else Missing(reason="infinite at undamped exact resonance")


def _settle_cell(f: CaseRun):
    return fixed(f.t_settle, 3) if math.isfinite(f.t_settle) else Missing(reason=NO_STEADY)


def _tau_cell(f: CaseRun):
    if f.c < 0:
        return Missing(reason="the free vibration grows when c < 0: no decay time")
    return fixed(f.tau, 3) if math.isfinite(f.tau) else Missing(reason="the free vibration never decays when c = 0")


def _by_run(st: ReproductionStudy, cells) -> list[dict]:
    """One row per distinct run: its name, then the cells ``cells(findings)`` gives for its findings."""
    return [{"case": st.run_name(run[0]), **cells(st.cases[run[0]])} for run in st.runs]


def findings_table(st: ReproductionStudy) -> Table:
    """One row per distinct run: regime, steady amplitude, window peak, settling (exact)."""
    rows = _by_run(
        st,
        lambda f: {
            "c": f.c,
            "omega": f.omega,
            "zeta": fixed(f.zeta, 3),
            "regime": f.regime,
            "xss": _xss_cell(f, f.x_ss),
            "peak": fixed(f.peak_x, 4),
            "ts": _settle_cell(f),
            "settled": f.settles,
        },
    )
    shared = [run for run in st.runs if len(run) > 1]
    notes = tuple(
        f"{st.run_name(run[0])}: the resonance run and this damping of the list are the same damping at the same "
        "forcing, so one run, shown once."
        for run in shared
    )
    return Table(
        rows=rows,
        columns=columns(
            """
            case     case
            c        c (N s/m)         4  nozeros
            omega    ω (rad/s)         4  nozeros
            zeta     ζ
            regime   regime
            xss      x_ss (m)
            peak     peak |x| (m)
            ts       t_s (s)
            settled  settles by t_end
            """
        ),
        caption=(
            f"Findings per run, exact: steady amplitude x_ss, largest |x| in the window [0, {g(st.t_end)}] s from "
            "rest, and the 2 % settling time t_s (the transient stays below 2 % of x_ss after it)."
        ),
        name="tab-reproduction-findings",
        notes=notes,
    )


def methods_table(st: ReproductionStudy) -> Table:
    """The paper's method beside the exact solution: peaks of x and v, worst error, time constant."""
    rows = _by_run(
        st,
        lambda f: {
            "vss": _xss_cell(f, f.v_ss),
            "pv": fixed(f.peak_v, 4),
            "pv45": fixed(f.peak_v_rk45, 4),
            "px45": fixed(f.peak_x_rk45, 4),
            "err": fixed(100 * f.rel_err, 2),
            "tau": _tau_cell(f),
        },
    )
    return Table(
        rows=rows,
        columns=columns(
            """
            case  case
            vss   v_ss (m/s)
            pv    peak |v| (m/s)
            pv45  peak |v| RK45 (m/s)
            px45  peak |x| RK45 (m)
            err   max |x_RK45 − x| (% of peak |x|)
            tau   τ (s)
            """
        ),
        caption=(
            "The paper's method (RK45 at its default tolerances) beside the exact solution: velocity amplitude "
            "v_ss = ω x_ss, peaks in the window, RK45's worst displacement error, and the time constant τ of the "
            "slowest free mode."
        ),
        name="tab-reproduction-methods",
    )


def findings_rows(st: ReproductionStudy) -> list[dict]:
    """Every scenario's findings at full precision, one dict per scenario (the columns of ``findings.csv``)."""
    return [
        {
            "scenario": f.scenario_id,
            "omega_rad_s": f.omega,
            "c_Ns_m": f.c,
            "omega_n_rad_s": f.omega_n,
            "zeta": f.zeta,
            "regime": f.regime,
            "x_ss_m": f.x_ss,
            "v_ss_m_s": f.v_ss,
            "peak_x_rk45_m": f.peak_x_rk45,
            "peak_x_exact_m": f.peak_x,
            "peak_v_rk45_m_s": f.peak_v_rk45,
            "peak_v_exact_m_s": f.peak_v,
            "max_err_x_rk45_m": f.max_err_x,
            "tau_s": f.tau,
            "t_settle_2pct_s": f.t_settle,
            "steady_in_window": f.settles,
        }
        for f in st.cases.values()
    ]


def write_findings_csv(st: ReproductionStudy, folder=None) -> Path | None:
    """Write ``findings.csv`` (one row per scenario, 10 significant figures) into ``folder`` or the tables folder."""
    folder = folder or os.environ.get(TABLES_ENV)
    if not folder:
        return None
    rows = findings_rows(st)
    path = Path(folder) / "findings.csv"
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(list(rows[0]))
        writer.writerows([fmt(r[c], 10) for c in rows[0]] for r in rows)
    return path


__all__ = ["findings_table", "methods_table", "write_findings_csv"]
