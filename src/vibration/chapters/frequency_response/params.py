"""Chapter 4, frequency response and design map: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import ordered, paper_window, shared
from vibration.presentation.schema import Param, Schema

SCHEMA = Schema(
    notebook="04_frequency_response",
    params=(
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
        Param(name="n_omega", symbol="N_ω", default=200, unit="", low=2, high=2000, meaning="design-map frequencies"),
        Param(name="n_damping", symbol="N_c", default=200, unit="", low=2, high=2000, meaning="design-map dampings"),
        Param(
            name="omega_max",
            symbol="ω_max",
            default=10.0,
            unit="rad/s",
            low=0.0,
            high=1000.0,
            meaning="upper forcing frequency of the design map",
            low_open=True,
        ),
        Param(
            name="c_min",
            symbol="c_min",
            default=0.01,
            unit="N s/m",
            low=0.001,
            high=10000.0,
            meaning="lowest damping of the design map",
        ),
        Param(
            name="c_max",
            symbol="c_max",
            default=20.0,
            unit="N s/m",
            low=0.001,
            high=10000.0,
            meaning="highest damping of the design map",
        ),
    ),
    together=(
        paper_window,
        ordered("c_min", "c_max", "N s/m"),
    ),
)

Params = SCHEMA.record_type()
