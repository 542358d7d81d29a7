"""The claims table: every checkable claim with its verdict, reason, readings and what the run changed."""

from __future__ import annotations

from ..numerics import DEFAULT_N_POINTS
from ..paper import Scenario, load_scenarios
from .evaluators import _evaluate
from .readings import readings
from .runs import ALSO_USES, _g, _Run
from .verdicts import _closeness, claim_kind_text, verdict

__all__ = ["COLUMNS", "audit_claims", "changed_text"]

#: Columns of :func:`audit_claims` rows (and of the report's ``claims.csv``).
COLUMNS = (
    "claim_id",
    "claim",
    "quantity",
    "unit",
    "kind",
    "claim_kind",
    "paper_value",
    "paper_method_value",
    "exact_value",
    "verdict",
    "reason",
    "best_reading",
    "best_reading_value",
    "best_reading_matches",
    "changed",
)


def changed_text(sc: Scenario, paper: Scenario | None) -> str:
    """What differs between a run's scenario and the paper's (empty when nothing does).

    Examples
    --------
    >>> sc = load_scenarios()
    >>> changed_text(sc["damping_low"], sc["damping_low"])
    ''
    >>> from dataclasses import replace
    >>> from vibration.physics.model import Oscillator
    >>> changed_text(replace(sc["damping_low"], oscillator=Oscillator(m=1.0, c=0.05, k=20.0)), sc["damping_low"])
    "c = 0.05 N s/m (the paper's: 0.1)"
    """
    if paper is None:
        return ""
    pairs = [
        ("m", sc.oscillator.m, paper.oscillator.m, "kg"),
        ("c", sc.oscillator.c, paper.oscillator.c, "N s/m"),
        ("k", sc.oscillator.k, paper.oscillator.k, "N/m"),
        ("F0", sc.force.F0, paper.force.F0, "N"),
        ("ω", sc.force.omega, paper.force.omega, "rad/s"),
        ("t_end", sc.t_end, paper.t_end, "s"),
    ]
    return "; ".join(f"{n} = {_g(a, 6)} {u} (the paper's: {_g(b, 6)})" for n, a, b, u in pairs if a != b)


def audit_claims(
    scenarios: dict[str, Scenario], claims: list[dict[str, str]], n_points: int = DEFAULT_N_POINTS
) -> list[dict[str, object]]:
    """The claims table: one row per claim, columns :data:`COLUMNS`.

    ``paper_method_value`` comes from RK45 at SciPy's default tolerances on
    ``n_points`` samples, ``exact_value`` from the closed form (None when the
    quantity does not exist in the run); the verdict follows :func:`verdict`;
    ``""`` marks a value the method does not affect. ``readings`` holds
    ``(description, value, unit, verdict)`` for every reading of the claim and
    ``best_reading`` the description of the one that fits best (by verdict, then
    by closeness to the paper's number).
    """
    cache: dict = {}
    runs = {sid: _Run(sc, n_points, cache) for sid, sc in scenarios.items()}
    try:
        paper_sc = load_scenarios()
    except OSError:  # pragma: no cover - data/ moved away: nothing to compare with
        paper_sc = {}
    rows = []
    for cl in claims:
        q, sid, kind = cl["quantity"], cl["scenario_id"], cl["kind"]
        pm, ex, reason = _evaluate(q, sid, runs)
        reads = [(d, v, u, verdict(kind, cl["paper_value"], v, quantity=q)) for d, v, u in readings(q, sid, runs)]
        best = min(reads, key=lambda r: _closeness(kind, cl["paper_value"], r[1]))
        rows.append(
            {
                "claim_id": cl["claim_id"],
                "claim": cl["claim"],
                "quantity": q + (f" [{sid}]" if sid else ""),
                "unit": cl["unit"],
                "kind": kind,
                "claim_kind": claim_kind_text(kind, cl["paper_value"], cl["unit"], quantity=q),
                "paper_value": cl["paper_value"],
                "paper_method_value": pm,
                "exact_value": ex,
                "verdict": verdict(kind, cl["paper_value"], ex, quantity=q),
                "reason": reason,
                "best_reading": best[0],
                "best_reading_value": best[1],
                "best_reading_matches": best[3] == "reproduced",
                "readings": reads,
                "scenario_id": sid,
                "changed": "; ".join(
                    t
                    for t in dict.fromkeys(
                        (f"{s}: " if s != sid else "") + changed_text(scenarios[s], paper_sc.get(s))
                        for s in ((sid, *ALSO_USES.get(q, ())) if sid else ())
                        if changed_text(scenarios[s], paper_sc.get(s))
                    )
                ),
            }
        )
    return rows
