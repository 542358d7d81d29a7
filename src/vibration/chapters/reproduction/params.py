"""Chapter 1, the paper reproduced: its parameters (the paper's model and window), declared once."""

from __future__ import annotations

from vibration.presentation.parameters import PAPER_MODEL, paper_window, shared_params
from vibration.presentation.schema import Schema

SCHEMA = Schema(notebook="01_reproduction", params=shared_params(*PAPER_MODEL), together=(paper_window,))

Params = SCHEMA.record_type(module=__name__)
