"""Numbers as the chapter prints them: the book's format (:mod:`vibration.book.presentation.numbers`).

>>> num(0.000123456, 3), num(2.5e-9, 2), num(1e-6, 1), num(246.3, 4)
('0.000123', '2.5×10⁻⁹', '10⁻⁶', '246.3')
>>> sig(1.13, 4), sig(0.02, 2), sig(3200.0, 3), sig(9.96, 2), sig(0.0, 3)
('1.130', '0.020', '3.20×10³', '10', '0')
>>> pct(0.11276), pct(-0.303, 2), pct(0.997, 2), pct(1.12, 2)
('11.3 %', '−30 %', '99.7 %', '112 %')
"""

from __future__ import annotations

from vibration.book.presentation.numbers import MINUS, column, percent, superscript
from vibration.book.presentation.numbers import sig as _sig

__all__ = ["MINUS", "num", "pct", "power", "sig"]


def power(exponent: int) -> str:
    """``10ⁿ`` in superscript digits."""
    return "10" + superscript(exponent)


def num(x: float, digits: int = 3) -> str:
    """A number for prose (:func:`vibration.book.presentation.numbers.sig`), three significant figures unless told."""
    return _sig(x, digits)


def sig(x: float, digits: int) -> str:
    """A table cell with exactly ``digits`` significant figures (:func:`vibration.book.presentation.numbers.column`)."""
    return column(x, digits)


def pct(x: float, digits: int = 3) -> str:
    """A fraction as a percentage (:func:`vibration.book.presentation.numbers.percent`): every integer digit kept."""
    return percent(x, digits)
