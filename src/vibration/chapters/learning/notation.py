"""Numbers as the chapter prints them: significant figures, powers of ten written ×10ⁿ, percentages.

>>> num(0.000123456, 3), num(2.5e-9, 2), num(1e-6, 1), num(246.3, 4)
('0.000123', '2.5 × 10⁻⁹', '10⁻⁶', '246.3')
>>> sig(1.13, 4), sig(0.02, 2), sig(3200.0, 3), sig(9.96, 2), sig(0.0, 3)
('1.130', '0.020', '3200', '10', '0')
>>> pct(0.11276), pct(-0.303, 2), pct(0.997, 2), pct(1.12, 2)
('11.3 %', '−30 %', '99.7 %', '112 %')
"""

from __future__ import annotations

import math

_SUP = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
MINUS = "−"


def power(exponent: int) -> str:
    """``10ⁿ`` in superscript digits."""
    return "10" + str(exponent).translate(_SUP)


def num(x: float, digits: int = 3) -> str:
    """A number for prose: ``digits`` significant figures, ×10ⁿ instead of e-notation, "∞" for infinity."""
    x = float(x)
    if math.isnan(x):
        return "—"
    if math.isinf(x):
        return "∞" if x > 0 else MINUS + "∞"
    text = f"{x:.{digits}g}"
    if "e" not in text:
        return text.replace("-", MINUS)
    mant, exp = text.split("e")
    sign = MINUS if mant.startswith("-") else ""
    mant = mant.lstrip("-")
    return f"{sign}{power(int(exp))}" if mant == "1" else f"{sign}{mant} × {power(int(exp))}"


def sig(x: float, digits: int) -> str:
    """A table cell with exactly ``digits`` significant figures (trailing zeros kept), no e-notation.

    Numbers of ``digits`` or more integer digits are rounded to an integer; below 10⁻⁴ the cell reads ×10ⁿ.
    """
    x = float(x)
    if not math.isfinite(x):
        return num(x)
    if x == 0.0:
        return "0"
    x = float(f"{x:.{digits}g}")
    e = math.floor(math.log10(abs(x)))
    if e < -4:
        mant = x / 10.0**e
        return f"{mant:.{digits - 1}f} × {power(e)}".replace("-", MINUS)
    return f"{x:.{max(digits - 1 - e, 0)}f}".replace("-", MINUS)


def pct(x: float, digits: int = 3) -> str:
    """A fraction as a percentage for prose: ``0.113 -> "11.3 %"`` (at least every integer digit: "112 %")."""
    v = 100.0 * float(x)
    if math.isfinite(v) and abs(v) >= 1.0:
        digits = max(digits, math.floor(math.log10(abs(v))) + 1)
        if "e" in f"{v:.{digits}g}":  # 99.7 at two digits rounds to 1e+02
            digits += 1
    return f"{num(v, digits)} %"
