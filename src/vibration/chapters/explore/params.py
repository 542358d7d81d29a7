"""Chapter 5, explore the parameters: its parameters (where the sliders start), declared once."""

from __future__ import annotations

from vibration.presentation.parameters import paper_window, shared, shared_params
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="05_explore",
    params=(
        *shared_params("m", "k", "F0"),
        shared("t_end", meaning="end of the time window, from rest at time zero"),
        shared("omega_res", meaning='starting forcing frequency, the paper\'s "resonant" one'),
        shared("c_nominal", meaning="starting damping coefficient, the paper's nominal one"),
    ),
    together=(paper_window,),
)

Params = SCHEMA.record_type(module=__name__)
