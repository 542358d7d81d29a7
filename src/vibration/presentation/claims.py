"""Chapter 2: the claims audit as tables and sentences for people.

The rows come from :func:`vibration.physics.audit.audit_claims`; this module only formats
them: the claims table (the claim's kind beside its value, the paper's method and the exact
value with units, the verdict), the readings tested for each discrepancy, the verdict counts,
and the Markdown that quotes each claim with its reason and its best-fitting reading.

Examples
--------
>>> from vibration.physics.audit import audit_claims
>>> from vibration.physics.paper import load_claims, load_scenarios
>>> rows = audit_claims(load_scenarios(), load_claims(), n_points=2001)
>>> print(repr(verdict_table(rows)).splitlines()[2:7])
['-------------------  ------', 'reproduced           12', 'partly reproduced    1', 'number differs       4', \
'name differs         1']
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

from ..physics.audit import COLUMNS, PARTLY_FACTOR, VERDICTS
from .findings import case_name
from .tables import TABLES_ENV, Column, Missing, Table, fmt

#: How the claims table names each audited quantity.
QUANTITY_TEXT = {
    "natural_frequency": "ω_n",
    "frequency_ratio": "ω/ω_n",
    "regime": "regime",
    "steady_in_window": "settles in the window",
    "steady_amplitude_x": "x_ss",
    "steady_amplitude_v": "v_ss",
    "peak_x": "peak |x|",
    "peak_v": "peak |v|",
    "amplitude_ratio_resonance_reference": "x_ss ratio to reference",
    "amplitude_ratio_high_nominal": "x_ss ratio to nominal",
    "growing_throughout": "peaks rise throughout",
    "stability": "stability",
    "rk45_pair": "RK45's pair",
}

NOT_AFFECTED = "the integrator does not affect this value"
NOT_EXISTING = "does not exist in this run (no steady state when c < 0)"


def _quantity(row: dict) -> str:
    q = row["quantity"].split(" [")[0]
    sid = row.get("scenario_id", "")
    return QUANTITY_TEXT.get(q, q) + (f", {case_name(sid)}" if sid else "")


def _value(v, unit: str, digits: int = 4):
    if v is None:
        return Missing(NOT_EXISTING)
    if isinstance(v, str):
        return Missing(NOT_AFFECTED) if v == "" else v
    u = "" if unit in ("", "1") else f" {unit}"
    return f"{fmt(float(v), digits)}{u}"


def claims_table(rows: list[dict]) -> Table:
    """One row per claim: what the paper says (kind and value), RK45, exact, verdict."""
    out = [
        {
            "id": r["claim_id"],
            "says": r["claim_kind"],
            "q": _quantity(r),
            "rk45": _value(r["paper_method_value"], r["unit"]),
            "exact": _value(r["exact_value"], r["unit"]),
            "verdict": r["verdict"],
            "case": "changed" if r["changed"] else "the paper's",
        }
        for r in rows
    ]
    notes = ()
    if any(r["changed"] for r in rows):
        notes = (
            "changed: this run's case differs from the one the paper's claim is about (see each claim below); "
            "its verdict is about this run's case, not the paper's.",
        )
    return Table(
        out,
        [
            Column("id", "claim"),
            Column("says", "the paper says"),
            Column("q", "quantity, case"),
            Column("rk45", "paper's method (RK45)"),
            Column("exact", "exact"),
            Column("verdict", "verdict"),
            Column("case", "case run"),
        ],
        notes=notes,
        caption="Every checkable claim of the paper: its kind and value, the value the paper's own method gives, "
        "the exact value, and the verdict of the stated rule.",
        name="tab-claims-audit",
    )


def readings_table(rows: list[dict]) -> Table | None:
    """The readings tested for every claim that is not reproduced, with their numbers and verdicts."""
    out = []
    for r in rows:
        if r["verdict"] == "reproduced":
            continue
        for desc, value, unit, v in r["readings"]:
            out.append(
                {
                    "id": r["claim_id"],
                    "reading": desc,
                    "value": _value(value, unit, 5),
                    "verdict": v if value is not None else Missing(NOT_EXISTING),
                    "best": "best" if desc == r["best_reading"] else "",
                }
            )
    if not out:
        return None
    return Table(
        out,
        [
            Column("id", "claim"),
            Column("reading", "reading tested"),
            Column("value", "its value"),
            Column("verdict", "verdict of this reading"),
            Column("best", "fits best"),
        ],
        caption="Readings that could explain each discrepancy, computed exactly and judged by the same rule; "
        "'best' marks the reading that fits best (which number matches, not what the authors meant).",
        name="tab-claims-readings",
    )


def verdict_table(rows: list[dict]) -> Table:
    """How many claims got each verdict."""
    counts = [{"verdict": v, "n": sum(r["verdict"] == v for r in rows)} for v in VERDICTS]
    return Table(
        counts,
        [Column("verdict", "verdict"), Column("n", "claims")],
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


def verdict_rule_markdown() -> str:
    """The verdict rule in words (with the run's factor)."""
    return (
        "* *about X*: **reproduced** when the exact value rounds to X at the precision X is written with (half "
        'a unit of its last digit, so "0.5" covers 0.45 to 0.55), **partly reproduced** within a factor '
        f"{PARTLY_FACTOR:g}, otherwise **number differs**;\n"
        "* *over / below X*: **reproduced** when the inequality holds, **partly reproduced** when it holds with "
        f"X relaxed by a factor {PARTLY_FACTOR:g}, otherwise **number differs**;\n"
        "* a word: **reproduced** only when equal; otherwise **physics contradicts** when the word is about the "
        "motion (regime, stability, growth, settling) and **name differs** for the method's name."
    )


def claims_details_markdown(rows: list[dict]) -> str:
    """Each claim quoted from the paper, its verdict, the exact reason and the best-fitting reading."""
    parts = []
    for r in rows:
        text = [f"**{r['claim_id']}** ({r['claim_kind']}): *{r['verdict']}*.", ""]
        text.append(f'> "{r["claim"]}" (the paper)')
        text.append("")
        if r["changed"]:
            text.append(f"This run's case is not the paper's: {r['changed']}. The verdict is about this run's case.")
            text.append("")
        text.append(r["reason"])
        if r["verdict"] != "reproduced":
            text.append("")
            text.append(reading_sentence(r))
        parts.append("\n".join(text))
    return "\n\n".join(parts)


def reading_sentence(row: dict) -> str:
    """Which reading fits the claim best, with its number: never which one the authors meant.

    Examples
    --------
    >>> row = {"claim_kind": "about 10-fold", "unit": "1", "best_reading": "ratio", "best_reading_value": 9.93,
    ...        "readings": [("ratio", 9.93, "1", "reproduced")]}
    >>> reading_sentence(row)
    'Of the readings tested, **ratio** fits best: 9.93, which matches "about 10-fold" by the same rule.'
    """
    best = next(r for r in row["readings"] if r[0] == row["best_reading"])
    desc, value, unit, v = best
    shown = _value(value, unit, 5)
    shown = "does not exist in this run" if isinstance(shown, Missing) else shown
    if v == "reproduced":
        verdict_text = f'which matches "{row["claim_kind"]}" by the same rule'
    else:
        verdict_text = f'which is still "{v}" against "{row["claim_kind"]}": no reading tested matches'
    return f"Of the readings tested, **{desc}** fits best: {shown}, {verdict_text}."


def audit_summary(rows: list[dict]) -> str:
    """The bullets of chapter 2's summary, from the verdicts and readings of this run."""
    by = {v: [r["claim_id"] for r in rows if r["verdict"] == v] for v in VERDICTS}
    bullets = [
        ", ".join(f"{len(ids)} {v}" for v, ids in by.items() if ids)
        + f" (of {len(rows)} claims; {table_ref('tab-claims-verdicts')})."
    ]
    for v in ("number differs", "partly reproduced"):
        for r in rows:
            if r["verdict"] == v:
                bullets.append(f"{r['claim_id']} ({r['claim_kind']}, {v}): " + reading_sentence(r))
    for r in rows:
        if r["verdict"] == "physics contradicts":
            bullets.append(f"{r['claim_id']} ({r['claim_kind']}, physics contradicts): {r['reason']}")
    for r in rows:
        if r["verdict"] == "name differs":
            bullets.append(f"{r['claim_id']} ({r['claim_kind']}, name differs): {r['reason']}")
    return "\n".join("- " + b for b in bullets)


def table_ref(name: str) -> str:
    """A MyST cross-reference to a table or figure label."""
    return "{numref}`" + name + "`"


def write_claims_csv(rows: list[dict], folder=None) -> Path | None:
    """``claims.csv`` (columns :data:`COLUMNS`, full precision) and ``claims_summary.csv``.

    Into ``folder`` or ``$VIBRATION_TABLES_DIR``; nothing when neither is set.
    """
    folder = folder or os.environ.get(TABLES_ENV)
    if not folder:
        return None
    path = Path(folder) / "claims.csv"
    path.parent.mkdir(parents=True, exist_ok=True)

    def cell(v):
        if v is None:
            return ""
        return fmt(v, 10) if not isinstance(v, str) else v

    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(COLUMNS)
        w.writerows([cell(r[c]) for c in COLUMNS] for r in rows)
    with (Path(folder) / "claims_summary.csv").open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["verdict", "claims"])
        w.writerows([v, sum(r["verdict"] == v for r in rows)] for v in VERDICTS)
    return path
