"""Chapter 3, solver accuracy: its parameters (the paper's nominal case and window), declared once."""

from __future__ import annotations

from vibration.presentation.parameters import paper_window, shared_params
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="03_solver_accuracy",
    params=shared_params("m", "k", "F0", "t_end", "omega_res", "c_nominal", "n_points"),
    together=(paper_window,),
)

Params = SCHEMA.record_type(module=__name__)
