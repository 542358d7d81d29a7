"""How chapter 9 writes numbers: fixed significant figures (trailing zeros kept), powers of ten as ×10ⁿ.

A table column keeps one number of significant figures for every row (``5.10450`` next to ``3.95920``,
never ``3.9592``), and neither prose nor tables use e-notation.

Examples
--------
>>> sig(3.9592029, 5), sig(2.24, 4), sig(8.1e-5, 2), sig(125663.7, 3), sig(-0.02493, 3)
('3.9592', '2.240', '8.1×10⁻⁵', '1.26×10⁵', '−0.0249')
>>> pm(0.10417, 0.00093), pm(-0.0249, float("nan"))
('0.1042 ± 0.0009', '−0.0249')
>>> power(1e-12)
'10⁻¹²'
"""

from __future__ import annotations

import math

MINUS = "−"
_SUPER = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
#: Below 10 to this power a number is written ×10ⁿ.
SMALLEST_FIXED = -4


def power(value: float) -> str:
    """An exact power of ten as ``10ⁿ``."""
    return "10" + str(round(math.log10(value))).translate(_SUPER)


def sig(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures, trailing zeros kept; ×10ⁿ below 10⁻⁴ or beyond the digits.

    ``nan`` reads "—", infinity "∞"; the minus sign is typeset (U+2212).
    """
    v = float(value)
    if math.isnan(v):
        return "—"
    if math.isinf(v):
        return "∞" if v > 0 else MINUS + "∞"
    if v == 0.0:
        return "0"
    mant, exp = f"{v:.{digits - 1}e}".split("e")
    e = int(exp)
    if SMALLEST_FIXED <= e < digits:
        text = f"{v:.{max(digits - 1 - e, 0)}f}"
    else:
        text = f"{mant}×10{str(e).translate(_SUPER)}"
    return text.replace("-", MINUS)


def signed(value: float, digits: int = 2) -> str:
    """``sig`` with an explicit sign: ``+0.0038``, ``−0.014``."""
    text = sig(value, digits)
    return text if text.startswith((MINUS, "—")) or value == 0 else "+" + text


def pm(value: float, se: float) -> str:
    """``value ± se`` with the decimals the standard error supports (down to its leading digit)."""
    if not (math.isfinite(se) and se > 0):
        return sig(value, 3)
    decimals = max(0, -math.floor(math.log10(se)))
    return f"{value:.{decimals}f} ± {se:.{decimals}f}".replace("-", MINUS)


def apm(value: float, se: float) -> str:
    """:func:`pm` of machine-dependent digits, each marked "≈" (the nbval sanitizer masks ≈-numbers).

    >>> apm(0.10417, 0.00093)
    '≈0.1042 ± ≈0.0009'
    """
    return "≈" + pm(value, se).replace(" ± ", " ± ≈")


def count(n: float) -> str:
    """A whole number, thousands set off by a thin space from five digits on: ``4300``, ``27 000``."""
    n = round(n)
    return f"{n:,}".replace(",", "\u2009") if abs(n) >= 10_000 else str(n)


def within(fraction: float, floor: float = 1e-3) -> str:
    """A relative difference as a round bound for a caption: the smallest of 0.1, 0.2, 0.5, 1, 2, 5, ... %
    at or above it (at least ``floor``), so the words do not move with the last digits.

    >>> within(0.00037), within(0.0042), within(0.03)
    ('0.1 %', '0.5 %', '5 %')
    """
    step = floor
    while step < fraction:
        for factor in (2.0, 2.5, 2.0):  # 1 -> 2 -> 5 -> 10
            step *= factor
            if step >= fraction:
                break
    return f"{100 * step:g} %"


def forcing_term(p) -> str:
    """Ueda's forcing as the captions write it: ``F cos t`` at 1 rad/s, else ``F cos(ω t)`` with its value."""
    return "F cos t" if p.omega_ueda == 1.0 else f"F cos({p.omega_ueda:g} t)"
