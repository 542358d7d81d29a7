"""Chapter 6, stability and damping as a design choice: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import shared
from vibration.presentation.schema import Param, Schema

SCHEMA = Schema(
    "06_stability",
    (
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("c_low", meaning="low damping coefficient"),
        shared("c_nominal"),
        shared("c_high"),
        Param("c_unstable", "c_u", -0.1, "N s/m", -10000.0, 0.0, "damping of the flutter model (negative, or 0)"),
        Param("t_growth", "t_g", 200.0, "s", 0.0, 2000.0, "window of the growth comparison", low_open=True),
        Param(
            "isolation_ratio",
            "r_iso",
            3.0,
            "",
            1.4142135623730951,
            100.0,
            "frequency ratio at which isolation is judged",
            low_open=True,
        ),
        Param(
            "S0",
            "S_0",
            0.1,
            "N² s/rad",
            0.0,
            1000000.0,
            "two-sided spectral density of the white-noise force",
            low_open=True,
        ),
        Param("n_paths", "N_paths", 200, "", 2, 5000, "Monte Carlo paths per damping"),
        Param("seed", "s", 1, "", 0, 2147483647, "seed of the Monte Carlo generator"),
    ),
    together=(),
)

Params = SCHEMA.record_type()
