"""Chapter 2's computation: every checkable claim of the paper against its own method and the exact solution.

:func:`claims_audit_study` builds the paper's scenarios from the chapter's parameters and runs the
audit of :mod:`vibration.physics.audit` (its verdict rule and readings are stated there), and
returns one frozen :class:`ClaimsAuditStudy` of typed :class:`Claim` records. Tables and sentences
(:mod:`.text`) are functions of that record. No prose here beyond the audit's own reasons.

Examples
--------
>>> st = claims_audit_study(n_points=2001)
>>> st.counts["reproduced"], len(st.claims)
(12, 20)
>>> st.by_id["C14"].verdict, st.by_id["C14"].best.verdict
('physics contradicts', 'reproduced')
>>> round(st.slowest_decay["damping_low"], 6)
0.05
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

from vibration.book.chapters.claims_audit.params import Params
from vibration.book.presentation.findings import scenarios_of
from vibration.physics.audit import VERDICTS, audit_claims
from vibration.physics.paper import load_claims
from vibration.physics.stability import poles


@dataclass(frozen=True, kw_only=True)
class Reading:
    """One way to read a claim that is not reproduced, with the number it gives and its verdict."""

    description: str  # e.g. "2 × steady amplitude (peak-to-peak)"
    value: object  # float, a word, or None when the quantity does not exist in this run
    unit: str  # SI unit, "" or "1" when dimensionless
    verdict: str  # the verdict of the same rule applied to this reading


@dataclass(frozen=True, kw_only=True)
class Claim:
    """One audited claim (the fields of :func:`vibration.physics.audit.audit_claims`, typed)."""

    claim_id: str  # "C01" ...
    quote: str  # the paper's words
    quantity: str  # what the claim is about, e.g. "steady_amplitude_x [reference]"
    unit: str
    kind: str  # "approx", "greater", "less" or "category"
    claim_kind: str  # the claim's kind beside its value, e.g. "about 0.5 m"
    paper_value: str  # as written in the paper
    paper_method_value: object  # by RK45 at SciPy's defaults ("" when the integrator does not matter)
    exact_value: object  # exact (None when the quantity does not exist in this run)
    verdict: str
    reason: str  # the audit's explanation, plain text
    best_reading: str
    readings: tuple[Reading, ...]
    scenario_id: str  # "" for claims about no single scenario
    changed: str  # how this run's case differs from the paper's ("" when it does not)

    @property
    def best(self) -> Reading:
        """The reading that fits best (by verdict, then by closeness to the paper's number)."""
        return next(r for r in self.readings if r.description == self.best_reading)

    @property
    def factor(self) -> float:
        """The paper's number over the exact one (nan for words and for quantities that do not exist)."""
        try:
            paper, exact = float(self.paper_value), float(self.exact_value)
        except (TypeError, ValueError):
            return math.nan
        return paper / exact if exact else math.inf


@dataclass(frozen=True, kw_only=True)
class ClaimsAuditStudy:
    """The audit of every claim for one run's parameters."""

    params: Params
    claims: tuple[Claim, ...]
    rows: tuple[dict, ...]  # the audit's rows as computed (the columns of claims.csv)
    slowest_decay: dict  # scenario id -> -(largest real part of the poles), 1/s (negative: growth)

    @property
    def by_id(self) -> dict[str, Claim]:
        """The claims keyed by id."""
        return {c.claim_id: c for c in self.claims}

    @property
    def counts(self) -> dict[str, int]:
        """How many claims got each verdict, in the order of :data:`VERDICTS`."""
        return {v: sum(c.verdict == v for c in self.claims) for v in VERDICTS}

    def with_verdict(self, verdict: str) -> list[Claim]:
        """The claims with ``verdict``, in the paper's order."""
        return [c for c in self.claims if c.verdict == verdict]


#: The fields of a :class:`Claim` that the audit's row holds under the same name (all but the quote and readings).
_ROW_FIELDS = tuple(f.name for f in fields(Claim) if f.name not in ("quote", "readings"))


def _claim(row: dict) -> Claim:
    readings = tuple(Reading(description=d, value=v, unit=u, verdict=vd) for d, v, u, vd in row["readings"])
    return Claim(quote=row["claim"], readings=readings, **{name: row[name] for name in _ROW_FIELDS})


def claims_audit_study(params: Params | None = None, **values) -> ClaimsAuditStudy:
    """Every claim of the paper read off the paper's own runs and the exact solution, with its verdict.

    ``params`` are the validated parameters; without it, keyword arguments are checked by the schema.

    Returns
    -------
    ClaimsAuditStudy
        Frozen record of every claim's values, verdict, reason and readings.
    """
    p = params if params is not None else Params.from_values(values)
    scenarios = scenarios_of(p)
    rows = audit_claims(scenarios, load_claims(), p.n_points)
    decay = {sid: -float(max(s.real for s in poles(sc.oscillator))) for sid, sc in scenarios.items()}
    return ClaimsAuditStudy(params=p, claims=tuple(_claim(r) for r in rows), rows=tuple(rows), slowest_decay=decay)
