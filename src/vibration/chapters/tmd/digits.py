"""Numbers as the chapter prints them: a fixed count of significant figures, × 10ⁿ instead of e-notation.

Examples
--------
>>> sig(0.142, 4), sig(127300.0, 4), sig(0.00012, 2), sig(-0.919, 3), sig(2.0, 3)
('0.1420', '1.273 × 10⁵', '1.2 × 10⁻⁴', '−0.919', '2.00')
>>> sig(9.9996, 4), sig(0.0, 3), sig(float("inf"), 3)
('10.00', '0', '∞')
>>> pct(0.5789), power(1e-9)
('57.9 %', '10⁻⁹')
"""

from __future__ import annotations

import math
from dataclasses import dataclass

_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
#: Plain decimals between these powers of ten; × 10ⁿ outside.
LOW_EXP, HIGH_EXP = -3, 5


def power(x: float) -> str:
    """A power of ten as 10ⁿ (``x`` must be one)."""
    e = round(math.log10(x))
    return "10" + str(e).translate(_SUPERSCRIPT)


def sig(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant figures, trailing zeros kept; "a × 10ⁿ" below 10⁻³ or from 10⁵ on."""
    x = float(x)
    if math.isnan(x):
        return "—"
    if math.isinf(x):
        return "∞" if x > 0 else "−∞"
    if x == 0.0:
        return "0"
    e = math.floor(math.log10(abs(x)))
    rounded = round(x, digits - 1 - e)
    if rounded != 0.0:
        e = math.floor(math.log10(abs(rounded)))  # 9.9996 -> 10.00: one decade up
    if e < LOW_EXP or e >= HIGH_EXP:
        mant = rounded / 10.0**e
        text = f"{mant:.{digits - 1}f} × 10" + str(e).translate(_SUPERSCRIPT)
    else:
        text = f"{rounded:.{max(digits - 1 - e, 0)}f}"
    return text.replace("-", "−")


def pct(share: float, digits: int = 3) -> str:
    """A share (1) as per cent: ``0.5789 -> "57.9 %"``."""
    return f"{sig(100.0 * share, digits)} %"


@dataclass(frozen=True)
class Sig:
    """A table cell printed to a fixed count of significant figures (see :func:`sig`)."""

    value: float
    digits: int = 4

    def __str__(self) -> str:
        return sig(self.value, self.digits)
