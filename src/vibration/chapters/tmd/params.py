"""Chapter 8, tuned mass dampers: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import damping_ratio_at_most, paper_window, shared
from vibration.presentation.schema import Param, Schema

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
        Param(
            name="mu",
            symbol="μ",
            default=0.05,
            unit="",
            low=0.0,
            high=1.0,
            meaning="absorber mass over primary mass",
            low_open=True,
        ),
        Param(
            name="mistuning",
            symbol="δ_k",
            default=0.1,
            unit="",
            low=0.0,
            high=0.5,
            meaning="largest relative error of the primary's stiffness",
        ),
        Param(
            name="n_storeys", symbol="n", default=5, unit="", low=1, high=30, meaning="storeys of the shear building"
        ),
        Param(
            name="storey_mass",
            symbol="m_s",
            default=45359.237,
            unit="kg",
            low=0.001,
            high=1000000000.0,
            meaning="floor mass (Chopra's 100 kips/g converted to SI)",
        ),
        Param(
            name="storey_stiffness",
            symbol="k_s",
            default=5523500.0,
            unit="N/m",
            low=0.001,
            high=1000000000000.0,
            meaning="storey stiffness (Chopra's 31.54 kips/in converted to SI)",
        ),
        Param(
            name="zeta_building",
            symbol="ζ_b",
            default=0.05,
            unit="",
            low=0.0,
            high=0.99,
            meaning="modal damping ratio of the building",
        ),
        Param(
            name="mu_building",
            symbol="μ_b",
            default=0.02,
            unit="",
            low=0.0,
            high=1.0,
            meaning="roof absorber mass over the first modal mass",
            low_open=True,
        ),
    ),
    together=(paper_window, damping_ratio_at_most(0.5)),
)

Params = SCHEMA.record_type()
