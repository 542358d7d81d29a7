"""The audit's verdict rule: a claim's number or word against the exact value, and its kind in words."""

from __future__ import annotations

import math
from decimal import Decimal

__all__ = ["PARTLY_FACTOR", "PHYSICAL_WORDS", "VERDICTS", "claim_kind_text", "half_unit", "verdict"]

#: A claim within this factor of the exact value (either way) is "partly reproduced".
PARTLY_FACTOR = 1.5

#: Every verdict, best first.
VERDICTS = ("reproduced", "partly reproduced", "number differs", "name differs", "physics contradicts")

#: Quantities whose words are about the motion (a mismatch is "physics contradicts").
PHYSICAL_WORDS = ("regime", "stability", "growing_throughout", "steady_in_window")


def half_unit(text: str) -> float:
    """Half a unit in the last stated digit of a number as written.

    Examples
    --------
    >>> half_unit("0.5"), half_unit("5.0"), half_unit("4.47"), half_unit("10")
    (0.05, 0.05, 0.005, 0.5)
    """
    exponent = Decimal(text.strip()).as_tuple().exponent
    return 0.5 * 10.0**exponent


def verdict(kind: str, paper_value: str, exact_value, *, quantity: str = "") -> str:
    """The verdict of one claim by the module's rule (one of :data:`VERDICTS`).

    ``exact_value`` None means the quantity does not exist in this run.

    Examples
    --------
    >>> verdict("approx", "0.5", 0.4504), verdict("approx", "1.5", 1.351), verdict("approx", "5.0", 2.237)
    ('reproduced', 'partly reproduced', 'number differs')
    >>> verdict("greater", "10.0", 10.26), verdict("category", "unstable", "stable", quantity="stability")
    ('reproduced', 'physics contradicts')
    >>> verdict("category", "Runge-Kutta-Fehlberg 4(5)", "Dormand-Prince 5(4)", quantity="rk45_pair")
    'name differs'
    """
    if exact_value is None:
        return "physics contradicts"
    if kind == "category":
        if str(exact_value) == paper_value:
            return "reproduced"
        return "physics contradicts" if quantity in PHYSICAL_WORDS else "name differs"
    claim, value = float(paper_value), float(exact_value)
    if kind == "approx":
        if abs(value - claim) <= half_unit(paper_value) * (1 + 1e-12):
            return "reproduced"
        lo, hi = sorted((abs(value), abs(claim)))
        return "partly reproduced" if lo > 0 and hi / lo <= PARTLY_FACTOR else "number differs"
    if kind == "greater":
        if value > claim:
            return "reproduced"
        return "partly reproduced" if value * PARTLY_FACTOR > claim else "number differs"
    if kind == "less":
        if value < claim:
            return "reproduced"
        return "partly reproduced" if value < claim * PARTLY_FACTOR else "number differs"
    raise ValueError(f"kind = {kind!r} is not known: allowed approx, greater, less, category")


def claim_kind_text(kind: str, paper_value: str, unit: str, *, quantity: str = "") -> str:
    """The claim's kind beside its value, in words.

    Examples
    --------
    >>> claim_kind_text("approx", "0.5", "m"), claim_kind_text("greater", "10.0", "m")
    ('about 0.5 m', 'over 10.0 m')
    >>> claim_kind_text("less", "0.1", "1", quantity="amplitude_ratio_high_nominal")
    'below 0.1 of nominal'
    >>> claim_kind_text("category", "unstable", "")
    'a word: unstable'
    """
    u = "" if unit in ("", "1") else f" {unit}"
    if kind == "category":
        return f"a word: {paper_value}"
    of = {"amplitude_ratio_high_nominal": " of nominal", "amplitude_ratio_resonance_reference": "-fold"}.get(
        quantity, u
    )
    word = {"approx": "about", "greater": "over", "less": "below"}[kind]
    return f"{word} {paper_value}{of}"


def _closeness(kind: str, paper_value: str, value) -> tuple:
    """Sort key of a reading: verdict rank, then |log(value / claim)| (numbers only)."""
    if value is None:
        return (len(VERDICTS), math.inf)
    rank = VERDICTS.index(verdict(kind, paper_value, value))
    if kind == "category":
        return (rank, 0.0)
    v, c = abs(float(value)), abs(float(paper_value))
    return (rank, abs(math.log(v / c)) if v > 0 and c > 0 else math.inf)
