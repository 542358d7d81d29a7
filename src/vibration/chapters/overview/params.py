"""The front page: its parameters (the paper's model and window, without the sampling), declared once."""

from __future__ import annotations

from vibration.presentation.parameters import paper_window, shared, shared_params
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="00_overview",
    params=(
        *shared_params("m", "k", "F0"),
        shared("t_end", meaning="end of the window from rest"),
        shared("omega_ref"),
        shared("omega_res", meaning="the paper's resonant forcing frequency"),
        shared("c_low", meaning="low damping coefficient"),
        *shared_params("c_nominal", "c_high"),
    ),
    together=(paper_window,),
)

Params = SCHEMA.record_type(module=__name__)
