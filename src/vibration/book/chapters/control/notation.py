"""How the chapter writes its numbers and names its cases, in prose, tables and figures.

* :func:`num`, :func:`cell`, :func:`pct`: the book's number format
  (:mod:`vibration.book.presentation.numbers`) at this chapter's three significant figures.
* :data:`LABELS`: the designs' names in tables and sentences (plain text, no code names).

Examples
--------
>>> num(0.000059), num(2.2370381, 3), num(-1.106, 4), num(float("inf")), num(1e-12)
('5.9×10⁻⁵', '2.24', '−1.106', '∞', '10⁻¹²')
>>> cell(16.0, 4), cell(17.4166, 4), cell(293.2, 3), cell(0.0, 3), cell(-5.9e-6, 2)
('16.00', '17.42', '293', '0', '−5.9×10⁻⁶')
"""

from __future__ import annotations

from vibration.book.presentation.numbers import column, sig, signed_percent
from vibration.book.presentation.numbers import percent as pct

__all__ = ["LABELS", "cell", "num", "pct", "signed_pct"]


def num(value: float, digits: int = 3) -> str:
    """A number for prose, three significant figures unless told (:func:`vibration.book.presentation.numbers.sig`)."""
    return sig(value, digits)


def cell(value: float, digits: int = 3) -> str:
    """A table cell, three significant figures unless told (:func:`vibration.book.presentation.numbers.column`)."""
    return column(value, digits)


def signed_pct(fraction: float) -> str:
    """A relative error with its sign, whole percent: ``0.1`` -> ``+10 %``."""
    return signed_percent(fraction, 0)


#: The designs and runs as a reader reads them (tables, sentences).
LABELS = {
    "passive": "passive",
    "PD": "PD",
    "PD2": "PD with the PID's gains",
    "LQR": "LQR",
    "PID": "PID",
    "soft": "passive, soft",
    "firm": "passive, firm",
    "skyhook": "ideal skyhook (active)",
    "on-off": "on-off skyhook",
    "clipped": "clipped skyhook",
    "mr": "MR damper, on-off",
    "unlimited": "no force limit",
    "none": "limited, no anti-windup",
    "clamping": "limited, clamping",
    "back-calculation": "limited, back-calculation",
}
