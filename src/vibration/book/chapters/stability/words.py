"""How the chapter writes numbers, dampings and symbols: for sentences, captions and table cells.

Sentences and captions are MyST Markdown, so a symbol with a subscript is maths (``$\\omega_n$``);
table cells are escaped text, so they use Unicode (ωₙ). Numbers are the book's
(:mod:`vibration.book.presentation.numbers`): a power of ten reads ``1.27×10⁵``; a table column shows one
number of significant figures for every row (trailing zeros kept: 0.100, 15.0, 6.97).

Examples
--------
>>> num(127000.0, 3), num(-0.05), num(0.1, 3), sig(0.1, 3), sig(15.0, 3), sig(-2.5e-7, 2)
('1.27×10⁵', '−0.05', '0.1', '0.100', '15.0', '−2.5×10⁻⁷')
>>> join(["a"]), join(["a", "b", "c"])
('a', 'a, b and c')
"""

from __future__ import annotations

import numpy as np

from vibration.book.presentation.numbers import column
from vibration.book.presentation.numbers import sig as _sig

#: Symbols in sentences and captions (MyST maths).
WN = r"$\omega_n$"
F0 = r"$F_0$"
S0 = r"$S_0$"
ZSTAR = r"$\zeta^*$"
TS = r"$t_s$"
SX = r"$\sigma_x$"
#: Symbols in table cells (Unicode).
WN_CELL = "ωₙ"


def num(value: float, digits: int = 3) -> str:
    """A number for a sentence or caption (:func:`..presentation.numbers.sig`), three figures unless told."""
    return _sig(value, digits)


def sig(value: float, digits: int = 3) -> str:
    """A table cell, exactly ``digits`` significant figures (:func:`vibration.book.presentation.numbers.column`)."""
    return column(value, digits)


def c_text(c: float) -> str:
    """A damping in a sentence: ``c = 0.5 N s/m``."""
    return f"$c$ = {num(c, 4)} N s/m"


def join(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def pole_text(p: np.ndarray) -> str:
    """The two poles of an oscillator for a table cell: ``−0.25 ± 4.465i`` or two real numbers."""
    a, b = p
    if a.imag != 0.0:
        return f"{sig(a.real + 0.0, 4)} ± {sig(abs(a.imag), 4)}i"
    return f"{sig(a.real, 4)}, {sig(b.real, 4)}"
