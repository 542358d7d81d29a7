"""Chapter 9, the Duffing oscillator: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import above, below, ordered, paper_window, shared
from vibration.presentation.schema import Param, Schema

SCHEMA = Schema(
    "09_duffing",
    (
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("c_nominal"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("t_end"),
        Param("k3_hard", "k_3", 2.0, "N/m³", 0.0, 1000.0, "cubic stiffness of the hardening spring", low_open=True),
        Param("k3_soft", "k_3", -1.0, "N/m³", -1000.0, 0.0, "cubic stiffness of the softening spring"),
        Param(
            "omega_sweep_min",
            "ω_lo",
            3.0,
            "rad/s",
            0.0,
            1000.0,
            "lowest frequency of the stepped sweeps",
            low_open=True,
        ),
        Param(
            "omega_sweep_max",
            "ω_hi",
            6.5,
            "rad/s",
            0.0,
            1000.0,
            "highest frequency of the stepped sweeps",
            low_open=True,
        ),
        Param("n_sweep", "N_sweep", 200, "", 10, 400, "frequencies in each sweep"),
        Param("c_ueda", "c_U", 0.05, "N s/m", 0.0, 10.0, "damping of Ueda's oscillator", low_open=True),
        Param("omega_ueda", "ω_U", 1.0, "rad/s", 0.0, 10.0, "forcing frequency of Ueda's oscillator", low_open=True),
        Param(
            "F0_ueda", "F_U", 7.5, "N", 0.0, 100.0, "forcing of Ueda's oscillator in the chaotic case", low_open=True
        ),
        Param(
            "F0_ueda_periodic",
            "F_U",
            2.0,
            "N",
            0.0,
            100.0,
            "forcing of Ueda's oscillator in the periodic case",
            low_open=True,
        ),
        Param(
            "n_lyapunov",
            "N_λ",
            20000,
            "",
            100,
            100000,
            "forcing periods of the main Lyapunov run on the chaotic attractor",
        ),
    ),
    together=(
        paper_window,
        ordered("omega_sweep_min", "omega_sweep_max", "rad/s"),
        above("c_nominal", 0.0, "N s/m", "the slow flow and its folds need damping"),
        below("k3_soft", 0.0, "N/m³", "a softening spring softens"),
    ),
)

Params = SCHEMA.record_type()
