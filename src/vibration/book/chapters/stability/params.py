"""Chapter 6, stability and damping as a design choice: its parameters (a growth window a float holds)."""

from __future__ import annotations

from vibration.book.presentation.parameters import (
    MAX_GROWTH,
    declared,
)
from vibration.physics.model import ParameterError


def growth_window(p: dict) -> None:
    """The growth comparison's window stays within what a float holds for the flutter model's negative damping."""
    c, m, t = p["c_unstable"], p["m"], p["t_growth"]
    exponent = -c / (2.0 * m) * t
    if exponent > MAX_GROWTH:
        raise ParameterError(
            f"t_growth = {t!r} s with c_unstable = {c!r} N s/m and m = {m!r} kg grows the response like "
            f"exp({exponent:.3g}): allowed (-c_unstable/2m) t_growth <= {MAX_GROWTH:g} "
            f"(t_growth <= {MAX_GROWTH * 2.0 * m / -c:.4g} s)"
        )


SCHEMA = declared(__package__, together=(growth_window,))

Params = SCHEMA.record_type(module=__name__)
