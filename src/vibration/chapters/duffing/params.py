"""Chapter 9, the Duffing oscillator: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import above, below, ordered, paper_window, shared
from vibration.presentation.schema import Param, Schema

SCHEMA = Schema(
    notebook="09_duffing",
    params=(
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("c_nominal"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("t_end"),
        Param(
            name="k3_hard",
            symbol="k_3",
            default=2.0,
            unit="N/m³",
            low=0.0,
            high=1000.0,
            meaning="cubic stiffness of the hardening spring",
            low_open=True,
        ),
        Param(
            name="k3_soft",
            symbol="k_3",
            default=-1.0,
            unit="N/m³",
            low=-1000.0,
            high=0.0,
            meaning="cubic stiffness of the softening spring",
        ),
        Param(
            name="omega_sweep_min",
            symbol="ω_lo",
            default=3.0,
            unit="rad/s",
            low=0.0,
            high=1000.0,
            meaning="lowest frequency of the stepped sweeps",
            low_open=True,
        ),
        Param(
            name="omega_sweep_max",
            symbol="ω_hi",
            default=6.5,
            unit="rad/s",
            low=0.0,
            high=1000.0,
            meaning="highest frequency of the stepped sweeps",
            low_open=True,
        ),
        Param(
            name="n_sweep",
            symbol="N_sweep",
            default=200,
            unit="",
            low=10,
            high=400,
            meaning="frequencies in each sweep",
        ),
        Param(
            name="c_ueda",
            symbol="c_U",
            default=0.05,
            unit="N s/m",
            low=0.0,
            high=10.0,
            meaning="damping of Ueda's oscillator",
            low_open=True,
        ),
        Param(
            name="omega_ueda",
            symbol="ω_U",
            default=1.0,
            unit="rad/s",
            low=0.0,
            high=10.0,
            meaning="forcing frequency of Ueda's oscillator",
            low_open=True,
        ),
        Param(
            name="F0_ueda",
            symbol="F_U",
            default=7.5,
            unit="N",
            low=0.0,
            high=100.0,
            meaning="forcing of Ueda's oscillator in the chaotic case",
            low_open=True,
        ),
        Param(
            name="F0_ueda_periodic",
            symbol="F_U",
            default=2.0,
            unit="N",
            low=0.0,
            high=100.0,
            meaning="forcing of Ueda's oscillator in the periodic case",
            low_open=True,
        ),
        Param(
            name="n_lyapunov",
            symbol="N_λ",
            default=20000,
            unit="",
            low=100,
            high=100000,
            meaning="forcing periods of the main Lyapunov run on the chaotic attractor",
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
