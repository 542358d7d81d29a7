"""Chapter 2's tables and the audit's counts, all from a :class:`ClaimsAuditStudy`; the prose is in the notebook.

The claims table (each claim's kind beside its value, the paper's method and the exact value with units, the
verdict), the readings tested for each discrepancy, the verdict counts and each claim quoted with its reason.
Symbols are typeset for the reader (:mod:`.notation`).
"""

from __future__ import annotations

import csv
import math
import os
from pathlib import Path

from vibration.book.chapters.claims_audit.notation import cell
from vibration.book.chapters.claims_audit.study import Claim, ClaimsAuditStudy
from vibration.book.presentation.findings import case_name
from vibration.book.presentation.narrative import fixed
from vibration.book.presentation.tables import TABLES_ENV, Column, Missing, Table, columns, fmt
from vibration.physics.audit import COLUMNS, PARTLY_FACTOR, VERDICTS, verdict

#: How the claims table names each audited quantity.
QUANTITY_TEXT = {
    "natural_frequency": "ωₙ",
    "frequency_ratio": "ω/ωₙ",
    "regime": "regime",
    "steady_in_window": "settles in the window",
    "steady_amplitude_x": "xₛₛ",
    "steady_amplitude_v": "vₛₛ",
    "peak_x": "peak |x|",
    "peak_v": "peak |v|",
    "amplitude_ratio_resonance_reference": "xₛₛ ratio to reference",
    "amplitude_ratio_high_nominal": "xₛₛ ratio to nominal",
    "growing_throughout": "peaks rise throughout",
    "stability": "stability",
    "rk45_pair": "RK45's pair",
}

#: Each verdict as the counting sentence says it (one claim; several claims).
VERDICT_PHRASE = {
    "reproduced": ("holds as written", "hold as written"),
    "partly reproduced": (
        f"holds only within a factor {PARTLY_FACTOR:g}",
        f"hold only within a factor {PARTLY_FACTOR:g}",
    ),
    "number differs": ("states a different number", "state a different number"),
    "name differs": ("misnames the method", "misname the method"),
    "physics contradicts": ("contradicts the equations", "contradict the equations"),
}

NOT_AFFECTED = "the integrator does not affect this value"
NOT_EXISTING = "does not exist in this run (no steady state when c < 0)"
#: Significant figures of the claims table's numbers and of the readings' (one precision per column; the
#: readings need five: 19.999 m/s is not "over 20.0").
DIGITS = 4
READING_DIGITS = 5


def _q(c: Claim) -> str:
    """The audited quantity's key, without its scenario."""
    return c.quantity.split(" [")[0]


def _quantity(c: Claim) -> str:
    q = _q(c)
    return QUANTITY_TEXT.get(q, cell(q)) + (f", {case_name(c.scenario_id)}" if c.scenario_id else "")


def _value(v, unit: str, digits: int = DIGITS):
    if v is None:
        return Missing(reason=NOT_EXISTING)
    if isinstance(v, str):
        return Missing(reason=NOT_AFFECTED) if v == "" else cell(v)
    u = "" if unit in ("", "1") else f" {unit}"
    return f"{fixed(float(v), digits)}{u}"


def _shown(v, unit: str, digits: int = DIGITS) -> str:
    """A value for a sentence (the text of :func:`_value`)."""
    out = _value(v, unit, digits)
    return "does not exist in this run" if isinstance(out, Missing) else out


def table_ref(name: str) -> str:
    """A MyST cross-reference to a table or figure label."""
    return "{numref}`" + name + "`"


def _ids(claims: list[Claim]) -> str:
    ids = [c.claim_id for c in claims]
    return ids[0] if len(ids) == 1 else ", ".join(ids[:-1]) + " and " + ids[-1]


# ----------------------------------------------------------------------------- tables


def claims_table(st: ClaimsAuditStudy) -> Table:
    """One row per claim: what the paper says (kind and value), RK45, exact, verdict."""
    out = [
        {
            "id": c.claim_id,
            "says": c.claim_kind,
            "q": _quantity(c),
            "rk45": _value(c.paper_method_value, c.unit),
            "exact": _value(c.exact_value, c.unit),
            "verdict": c.verdict,
            "case": "changed" if c.changed else "the paper's",
        }
        for c in st.claims
    ]
    notes = ()
    if any(c.changed for c in st.claims):
        notes = (
            "changed: this run's case differs from the one the paper's claim is about (see each claim below); "
            "its verdict is about this run's case, not the paper's.",
        )
    return Table(
        rows=out,
        columns=columns(
            """
            id       claim
            says     the paper says
            q        quantity, case
            rk45     paper's method (RK45)
            exact    exact
            verdict  verdict
            case     case run
            """
        ),
        notes=notes,
        caption="Every checkable claim of the paper: its kind and value, the value the paper's own method gives, "
        "the exact value, and the verdict of the stated rule.",
        name="tab-claims-audit",
    )


def readings_table(st: ClaimsAuditStudy) -> Table | None:
    """The readings tested for every claim that is not reproduced, with their numbers and verdicts."""
    out = []
    for c in st.claims:
        if c.verdict == "reproduced":
            continue
        for r in c.readings:
            out.append(
                {
                    "id": c.claim_id,
                    "reading": cell(r.description),
                    "value": _value(r.value, r.unit, READING_DIGITS),
                    "verdict": r.verdict if r.value is not None else Missing(reason=NOT_EXISTING),
                    "best": "best" if r.description == c.best_reading else "",
                }
            )
    if not out:
        return None
    return Table(
        rows=out,
        columns=columns(
            """
            id       claim
            reading  reading tested
            value    its value
            verdict  verdict of this reading
            best     fits best
            """
        ),
        caption="Readings that could explain each discrepancy, computed exactly and judged by the same rule; "
        "'best' marks the reading that fits best (which number matches, not what the authors meant).",
        name="tab-claims-readings",
    )


def verdict_table(st: ClaimsAuditStudy) -> Table:
    """How many claims got each verdict, with the verdicts' definitions."""
    counts = [{"verdict": v, "n": n} for v, n in st.counts.items()]
    return Table(
        rows=counts,
        columns=[Column(key="verdict", header="verdict"), Column(key="n", header="claims")],
        caption="Verdicts at a glance.",
        name="tab-claims-verdicts",
        notes=(
            f"partly reproduced: within a factor {PARTLY_FACTOR:g} of the paper's value (or of its bound)",
            "number differs: a number outside that factor",
            "name differs: the paper names its method wrongly",
            "physics contradicts: a word about the motion (regime, stability, growth, settling) that the "
            "equations refute, or a quantity that does not exist",
        ),
    )


def best_reading_cell(c: Claim) -> str:
    """Which reading fits a claim best, its value and its verdict (never which one the authors meant)."""
    best = c.best
    return f"{cell(best.description)}: {_shown(best.value, best.unit, READING_DIGITS)} ({best.verdict})"


def reasons_table(st: ClaimsAuditStudy) -> Table:
    """Each claim quoted, with its verdict, the audit's reason and, when it fails, the reading that fits best."""
    rows = [
        {
            "id": c.claim_id,
            "quote": f"“{c.quote}”",
            "verdict": c.verdict,
            "why": cell(c.reason) + (f" This run's case is not the paper's: {cell(c.changed)}." if c.changed else ""),
            "best": best_reading_cell(c) if c.verdict != "reproduced" else Missing(reason="the claim holds as written"),
        }
        for c in st.claims
    ]
    return Table(
        rows=rows,
        columns=columns(
            """
            id       claim
            quote    the paper's words
            verdict  verdict
            why      why
            best     reading that fits best
            """
        ),
        caption="Each claim in the paper's words, with its verdict, the audit's reason and the reading that fits best.",
        name="tab-claims-reasons",
    )


def solver_agreement(st: ClaimsAuditStudy) -> tuple[int, int, float]:
    """Claims the solver affects that get the same verdict on RK45's value; how many it affects; the largest
    relative gap between RK45's numbers and the exact ones."""
    judged = [c for c in st.claims if c.paper_method_value not in ("", None) and c.exact_value is not None]
    same = [c for c in judged if verdict(c.kind, c.paper_value, c.paper_method_value, quantity=_q(c)) == c.verdict]
    numeric = [c for c in judged if isinstance(c.exact_value, float | int) and c.exact_value != 0]
    worst = max((abs(float(c.paper_method_value) / float(c.exact_value) - 1) for c in numeric), default=0.0)
    return len(same), len(judged), worst


def largest_gap(st: ClaimsAuditStudy) -> Claim | None:
    """The failed claim whose number is farthest from the exact one (None when no numerical claim fails)."""
    failed = [c for c in st.claims if c.verdict != "reproduced" and math.isfinite(c.factor) and c.factor > 0]
    return max(failed, key=lambda c: abs(math.log(c.factor))) if failed else None


# ----------------------------------------------------------------------------- files


def write_claims_csv(st: ClaimsAuditStudy, folder=None) -> Path | None:
    """``claims.csv`` (columns :data:`COLUMNS`, full precision) and ``claims_summary.csv``.

    Into ``folder`` or ``$VIBRATION_TABLES_DIR``; nothing when neither is set.
    """
    folder = folder or os.environ.get(TABLES_ENV)
    if not folder:
        return None
    path = Path(folder) / "claims.csv"
    path.parent.mkdir(parents=True, exist_ok=True)

    def value(v):
        if v is None:
            return ""
        return fmt(v, 10) if not isinstance(v, str) else v

    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(COLUMNS)
        w.writerows([value(r[c]) for c in COLUMNS] for r in st.rows)
    with (Path(folder) / "claims_summary.csv").open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["verdict", "claims"])
        w.writerows([v, n] for v, n in st.counts.items())
    return path


__all__ = [
    "VERDICTS",
    "claims_table",
    "largest_gap",
    "readings_table",
    "reasons_table",
    "solver_agreement",
    "verdict_table",
    "write_claims_csv",
]
