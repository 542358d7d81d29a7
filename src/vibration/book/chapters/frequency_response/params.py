"""Chapter 4, frequency response and design map: its parameters, declared once."""

from __future__ import annotations

from vibration.book.presentation.parameters import (
    declared,
    ordered,
    paper_window,
)

SCHEMA = declared(__package__, together=(paper_window, ordered("c_min", "c_max", "N s/m")))

Params = SCHEMA.record_type(module=__name__)
