"""How the real-oscillator chapter writes its numbers: angles in rad and degrees, values with their errors,
missing values, and a detail fit for a CSV cell."""

from __future__ import annotations

import math
import re

from vibration.presentation.narrative import g
from vibration.presentation.tables import Missing

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
    """x ± s for a sentence (the error with two figures)."""
    if not math.isfinite(s):
        return g(x, digits)
    return f"{g(x, digits)} ± {g(s, 2)}"


def ascii_detail(text: str) -> str:
    """A detail for a CSV cell: ASCII minus, no ± (written out), degrees dropped (the radians stay)."""
    text = re.sub(r" \(-?[0-9.]+°\)", "", text.replace("−", "-"))
    return text.replace(" ± ", " with standard error ").replace("ωₙ", "omega_n")
