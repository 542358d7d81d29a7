"""Chapter 8, tuned mass dampers: its parameters, declared once."""

from __future__ import annotations

from vibration.presentation.parameters import (
    count,
    damping_ratio_at_most,
    paper_window,
    positive,
    quantity,
    ratio,
    shared,
)
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="08_tmd",
    params=(
        shared("m", meaning="primary mass"),
        shared("k", meaning="primary spring stiffness"),
        shared("F0"),
        shared("c_nominal", meaning="primary damping coefficient"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("t_end", meaning="end of the simulated window"),
        shared("n_points"),
        positive("mu", "μ", 0.05, unit="", high=1.0, meaning="absorber mass over primary mass"),
        ratio("mistuning", "δ_k", 0.1, low=0.0, high=0.5, meaning="largest relative error of the primary's stiffness"),
        count("n_storeys", "n", 5, low=1, high=30, meaning="storeys of the shear building"),
        quantity(
            "storey_mass",
            "m_s",
            45359.237,
            unit="kg",
            low=1e-3,
            high=1e9,
            meaning="floor mass (Chopra's 100 kips/g converted to SI)",
        ),
        quantity(
            "storey_stiffness",
            "k_s",
            5523500.0,
            unit="N/m",
            low=1e-3,
            high=1e12,
            meaning="storey stiffness (Chopra's 31.54 kips/in converted to SI)",
        ),
        ratio("zeta_building", "ζ_b", 0.05, low=0.0, high=0.99, meaning="modal damping ratio of the building"),
        positive("mu_building", "μ_b", 0.02, unit="", high=1.0, meaning="roof absorber mass over the first modal mass"),
    ),
    together=(paper_window, damping_ratio_at_most(0.5)),
)

Params = SCHEMA.record_type(module=__name__)
