"""Chapter 2's sentences and tables, all from a :class:`ClaimsAuditStudy`.

The claims table (each claim's kind beside its value, the paper's method and the exact value
with units, the verdict), the readings tested for each discrepancy, the verdict counts, each
claim quoted with its reason, the key-results box and the summary. Symbols are typeset for the
reader (:mod:`.notation`); a claim is quoted once, in its own paragraph; the summary draws
conclusions across claims instead of repeating them.
"""

from __future__ import annotations

import csv
import math
import os
from pathlib import Path

from vibration.book.chapters.claims_audit.notation import cell, prose
from vibration.book.chapters.claims_audit.study import Claim, ClaimsAuditStudy
from vibration.book.presentation.findings import case_name
from vibration.book.presentation.narrative import fixed, g
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


# ----------------------------------------------------------------------------- sentences


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


def reading_sentence(c: Claim) -> str:
    """Which reading fits the claim best, with its number: never which one the authors meant."""
    best = c.best
    shown = _shown(best.value, best.unit, READING_DIGITS)
    if best.verdict == "reproduced":
        verdict_text = f'which matches "{c.claim_kind}" by the same rule'
    else:
        verdict_text = f'which is still "{best.verdict}" against "{c.claim_kind}": no reading tested matches'
    return f"Of the readings tested, **{prose(best.description)}** fits best: {shown}, {verdict_text}."


def claims_details_markdown(st: ClaimsAuditStudy) -> str:
    """Each claim quoted from the paper, then one paragraph: its verdict, the exact reason, the best reading."""
    parts = []
    for c in st.claims:
        text = [f"**{c.claim_id}** ({c.claim_kind}; {_quantity(c)}): *{c.verdict}*."]
        if c.changed:
            text.append(
                f"This run's case is not the paper's: {prose(c.changed)}; the verdict is about this run's case."
            )
        text.append(prose(c.reason))
        if c.verdict != "reproduced":
            text.append(reading_sentence(c))
        parts.append(f'> "{c.quote}" (the paper)\n\n' + " ".join(text))
    return "\n\n".join(parts)


def count_sentence(st: ClaimsAuditStudy) -> str:
    """How many claims got each verdict, in words."""
    parts = []
    for v, n in st.counts.items():
        if n:
            parts.append(f"{n} {VERDICT_PHRASE[v][0 if n == 1 else 1]}")
    listed = parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]
    return f"Of the paper's {len(st.claims)} checkable claims, {listed}."


def solver_sentence(st: ClaimsAuditStudy) -> str:
    """Whether any verdict depends on the solver: each claim judged on RK45's value instead of the exact one."""
    judged = [c for c in st.claims if c.paper_method_value not in ("", None) and c.exact_value is not None]
    same = [c for c in judged if verdict(c.kind, c.paper_value, c.paper_method_value, quantity=_q(c)) == c.verdict]
    numeric = [c for c in judged if isinstance(c.exact_value, float | int) and c.exact_value != 0]
    worst = max((abs(float(c.paper_method_value) / float(c.exact_value) - 1) for c in numeric), default=0.0)
    share = f"all {len(judged)}" if len(same) == len(judged) else f"{len(same)} of the {len(judged)}"
    head = (
        f"Judged on the paper's own solver (RK45) instead of the exact solution, {share} claims the solver affects "
        "get the same verdict"
    )
    return head + (f"; its numbers differ from the exact ones by {g(100 * worst, 2)} % at most." if numeric else ".")


def gap_sentence(st: ClaimsAuditStudy) -> str | None:
    """The claim whose number is farthest from the exact one (None when no numerical claim fails)."""
    failed = [c for c in st.claims if c.verdict != "reproduced" and math.isfinite(c.factor) and c.factor > 0]
    if not failed:
        return None
    c = max(failed, key=lambda c: abs(math.log(c.factor)))
    where = f", {case_name(c.scenario_id)}" if c.scenario_id else ""
    exact = _shown(c.exact_value, c.unit)
    if c.factor >= 1:
        size = f"the paper's number is {g(c.factor, 3)} times the exact {exact}"
    else:
        size = f"the exact {exact} is {g(1 / c.factor, 3)} times the paper's number"
    return f'The largest gap is {c.claim_id} ("{c.claim_kind}"{where}): {size}.'


def key_results(st: ClaimsAuditStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    items = [count_sentence(st), gap_sentence(st), solver_sentence(st)]
    lines = ["> **Key results**", ">"] + [f"> * {s}" for s in items if s]
    return "\n".join(lines)


def _group_by_reading(claims: list[Claim]) -> dict[str, list[Claim]]:
    groups: dict[str, list[Claim]] = {}
    for c in claims:
        groups.setdefault(c.best_reading, []).append(c)
    return groups


def audit_summary(st: ClaimsAuditStudy) -> str:
    """The summary: conclusions across claims (grouped by what explains them), in new words."""
    bullets = []
    changed = [c for c in st.claims if c.changed]
    if changed:
        bullets.append(
            f"{_ids(changed)} are about cases this run changed: their verdicts test the paper's words on another "
            "oscillator, not the paper's own numbers."
        )
    numbers = [c for c in st.claims if c.verdict in ("number differs", "partly reproduced") and not c.changed]
    for desc, group in _group_by_reading(numbers).items():
        pairs = "; ".join(
            f'{c.claim_id} {_shown(c.best.value, c.best.unit, READING_DIGITS)} against "{c.claim_kind}"' for c in group
        )
        matched = [c for c in group if c.best.verdict == "reproduced"]
        one = len(group) == 1
        if len(matched) == len(group):
            tail = "that reading matches it" if one else "that reading matches all of them"
        elif matched:
            tail = "that reading matches " + _ids(matched)
        else:
            tail = "even that reading stays outside the paper's rounding"
        verb = "comes" if one else "come"
        bullets.append(f"Read as **{prose(desc)}**, {_ids(group)} {verb} closest ({pairs}); {tail}.")
    contradicted = st.with_verdict("physics contradicts")
    missing = [c for c in contradicted if c.exact_value is None]
    if missing:
        bullets.append(
            f"{_ids(missing)} give numbers for steady amplitudes that do not exist in this run: with a damping "
            "c < 0 the response grows and never reaches a steady state."
        )
    for c in (c for c in contradicted if c.exact_value is not None):
        q = QUANTITY_TEXT.get(_q(c), cell(_q(c)))
        where = f", {case_name(c.scenario_id)}" if c.scenario_id else ""
        exact = cell(str(c.exact_value))
        text = f'{c.claim_id} ({q}{where}): the paper says "{c.paper_value}", the equations "{exact}"'
        rate = st.slowest_decay.get(c.scenario_id)
        if rate is not None and rate > 0 and "stability" in c.quantity:
            text += f", since the slowest free mode decays at {g(rate, 3)} 1/s"
        if c.best.verdict == "reproduced":
            text += f". The paper's word fits only the reading **{prose(c.best_reading)}**"
        bullets.append(text + ".")
    for c in st.with_verdict("name differs"):
        bullets.append(
            f'{c.claim_id} names the solver "{c.paper_value}"; the paper\'s RK45 is in fact "{c.exact_value}". A wrong '
            "name changes none of the numbers above."
        )
    held = st.with_verdict("reproduced")
    if held:
        bullets.append(f"The other claims, {_ids(held)}, hold as written for this run.")
    return "\n".join("- " + b for b in bullets)


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
    "audit_summary",
    "claims_details_markdown",
    "claims_table",
    "key_results",
    "reading_sentence",
    "readings_table",
    "verdict_rule_markdown",
    "verdict_table",
    "write_claims_csv",
]
