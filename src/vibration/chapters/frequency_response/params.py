"""Chapter 4, frequency response and design map: its parameters, declared once."""

from __future__ import annotations

from vibration.presentation.parameters import (
    PAPER_MODEL,
    count,
    damping,
    frequency,
    ordered,
    paper_window,
    shared_params,
)
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="04_frequency_response",
    params=(
        *shared_params(*PAPER_MODEL),
        count("n_omega", "N_ω", 200, low=2, high=2000, meaning="design-map frequencies"),
        count("n_damping", "N_c", 200, low=2, high=2000, meaning="design-map dampings"),
        frequency("omega_max", "ω_max", 10.0, high=1e3, meaning="upper forcing frequency of the design map"),
        damping("c_min", "c_min", 0.01, low=1e-3, high=1e4, meaning="lowest damping of the design map"),
        damping("c_max", "c_max", 20.0, low=1e-3, high=1e4, meaning="highest damping of the design map"),
    ),
    together=(paper_window, ordered("c_min", "c_max", "N s/m")),
)

Params = SCHEMA.record_type(module=__name__)
