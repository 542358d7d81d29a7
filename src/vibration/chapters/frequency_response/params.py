"""Chapter 4, frequency response and design map: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import ordered, paper_window, shared
from vibration.presentation.schema import Param, Schema

SCHEMA = Schema(
    "04_frequency_response",
    (
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("t_end"),
        shared("omega_ref"),
        shared("omega_res", meaning='the paper\'s "resonant" forcing frequency'),
        shared("c_low"),
        shared("c_nominal"),
        shared("c_high"),
        shared("n_points"),
        Param("n_omega", "N_ω", 200, "", 2, 2000, "design-map frequencies"),
        Param("n_damping", "N_c", 200, "", 2, 2000, "design-map dampings"),
        Param(
            "omega_max", "ω_max", 10.0, "rad/s", 0.0, 1000.0, "upper forcing frequency of the design map", low_open=True
        ),
        Param("c_min", "c_min", 0.01, "N s/m", 0.001, 10000.0, "lowest damping of the design map"),
        Param("c_max", "c_max", 20.0, "N s/m", 0.001, 10000.0, "highest damping of the design map"),
    ),
    together=(
        paper_window,
        ordered("c_min", "c_max", "N s/m"),
    ),
)

Params = SCHEMA.record_type()
