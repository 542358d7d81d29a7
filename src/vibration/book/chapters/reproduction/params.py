"""Chapter 1, the paper reproduced: its parameters (the paper's model and window), declared once."""

from __future__ import annotations

from vibration.book.presentation.parameters import declared, paper_window

SCHEMA = declared(__package__, together=(paper_window,))

Params = SCHEMA.record_type(module=__name__)
