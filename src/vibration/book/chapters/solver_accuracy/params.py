"""Chapter 3, solver accuracy: its parameters (the paper's nominal case and window), declared once."""

from __future__ import annotations

from vibration.book.presentation.parameters import declared, paper_window

SCHEMA = declared(__package__, together=(paper_window,))

Params = SCHEMA.record_type(module=__name__)
