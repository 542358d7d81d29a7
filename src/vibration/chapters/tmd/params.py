"""Chapter 8, tuned mass dampers: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import damping_ratio_at_most, paper_window, shared
from vibration.presentation.schema import Param, Schema

SCHEMA = Schema(
    "08_tmd",
    (
        shared("m", meaning="primary mass"),
        shared("k", meaning="primary spring stiffness"),
        shared("F0"),
        shared("c_nominal", meaning="primary damping coefficient"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("t_end", meaning="end of the simulated window"),
        shared("n_points"),
        Param("mu", "μ", 0.05, "", 0.0, 1.0, "absorber mass over primary mass", low_open=True),
        Param("mistuning", "δ_k", 0.1, "", 0.0, 0.5, "largest relative error of the primary's stiffness"),
        Param("n_storeys", "n", 5, "", 1, 30, "storeys of the shear building"),
        Param(
            "storey_mass",
            "m_s",
            45359.237,
            "kg",
            0.001,
            1000000000.0,
            "floor mass (Chopra's 100 kips/g converted to SI)",
        ),
        Param(
            "storey_stiffness",
            "k_s",
            5523500.0,
            "N/m",
            0.001,
            1000000000000.0,
            "storey stiffness (Chopra's 31.54 kips/in converted to SI)",
        ),
        Param("zeta_building", "ζ_b", 0.05, "", 0.0, 0.99, "modal damping ratio of the building"),
        Param("mu_building", "μ_b", 0.02, "", 0.0, 1.0, "roof absorber mass over the first modal mass", low_open=True),
    ),
    together=(paper_window, damping_ratio_at_most(0.5)),
)

Params = SCHEMA.record_type()
