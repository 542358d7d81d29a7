"""Chapter 9, the Duffing oscillator: its parameters, declared once."""

from __future__ import annotations

from vibration.book.presentation.parameters import (
    above,
    below,
    declared,
    ordered,
    paper_window,
)

SCHEMA = declared(
    __package__,
    together=(
        paper_window,
        ordered("omega_sweep_min", "omega_sweep_max", "rad/s"),
        above("c_nominal", 0.0, "N s/m", why="the slow flow and its folds need damping"),
        below("k3_soft", 0.0, "N/m³", why="a softening spring softens"),
    ),
)

Params = SCHEMA.record_type(module=__name__)
