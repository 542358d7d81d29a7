"""Chapter 8, tuned mass dampers: its parameters, declared once."""

from __future__ import annotations

from vibration.book.presentation.parameters import (
    damping_ratio_at_most,
    declared,
    paper_window,
)

SCHEMA = declared(__package__, together=(paper_window, damping_ratio_at_most(0.5)))

Params = SCHEMA.record_type(module=__name__)
