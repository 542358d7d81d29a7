"""Numbers as the chapter prints them: the book's format (:mod:`vibration.book.presentation.numbers`).

Every number of the chapter, in prose and in tables, shows a fixed count of significant figures with
trailing zeros kept (one precision per column).

Examples
--------
>>> sig(0.142, 4), sig(127300.0, 4), sig(0.00012, 2), sig(-0.919, 3), sig(2.0, 3)
('0.1420', '1.273×10⁵', '0.00012', '−0.919', '2.00')
>>> sig(9.9996, 4), sig(0.0, 3), sig(float("inf"), 3)
('10.00', '0', '∞')
>>> pct(0.5789), power(1e-9)
('57.9 %', '10⁻⁹')
"""

from __future__ import annotations

from dataclasses import dataclass

from vibration.book.presentation.numbers import column, power
from vibration.book.presentation.numbers import percent as pct

__all__ = ["Sig", "pct", "power", "sig"]


def sig(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant figures, trailing zeros kept (:func:`..presentation.numbers.column`)."""
    return column(x, digits)


@dataclass(frozen=True, kw_only=True)
class Sig:
    """A table cell printed to a fixed count of significant figures (see :func:`sig`)."""

    value: float
    digits: int = 4

    def __str__(self) -> str:
        return sig(self.value, self.digits)
