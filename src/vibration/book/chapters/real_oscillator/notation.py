"""How the real-oscillator chapter writes its numbers: angles in rad and degrees, values with their errors,
missing values, and a detail fit for a CSV cell."""

from __future__ import annotations

import math
import re

from vibration.book.presentation import numbers
from vibration.book.presentation.narrative import g
from vibration.book.presentation.tables import Missing

NONE = Missing(reason="not available with these data")


def deg(x: float) -> float:
    """Radians to degrees."""
    return math.degrees(x)


def angle(x: float, digits: int = 3) -> str:
    """An angle in rad and degrees for a sentence."""
    if not math.isfinite(x):
        return "unbounded"
    d = deg(float(f"{x:.{digits}g}"))  # the degrees of the radians as printed, so the two agree
    return f"{g(x, digits)} rad ({d:.0f}°)" if abs(d) >= 10 else f"{g(x, digits)} rad ({g(d, 2)}°)"


def pm(x: float, s: float, digits: int = 3) -> str:
    """x ± s in the book's format (:func:`vibration.book.presentation.numbers.pm`: the error to one figure, two when
    it starts with 1, the value to its last digit); ``x`` alone, to ``digits`` figures, when ``s`` is unknown.

    >>> pm(0.0449, 0.00101), pm(0.00113, 0.00078), pm(16.0, 0.054), pm(2.5, float("nan"))
    ('0.0449 ± 0.0010', '0.0011 ± 0.0008', '16.00 ± 0.05', '2.5')
    """
    if not math.isfinite(s):
        return g(x, digits)
    return numbers.pm(x, s)


def ascii_detail(text: str) -> str:
    """A detail for a CSV cell: ASCII minus, no ± (written out), degrees dropped (the radians stay)."""
    text = re.sub(r" \(-?[0-9.]+°\)", "", text.replace("−", "-"))
    return text.replace(" ± ", " with standard error ").replace("ωₙ", "omega_n")
