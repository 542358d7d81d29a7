"""Chapter 9, the Duffing oscillator: its parameters, declared once."""

from __future__ import annotations

from vibration.presentation.parameters import (
    above,
    below,
    count,
    frequency,
    ordered,
    paper_window,
    positive,
    quantity,
    shared,
    shared_params,
)
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="09_duffing",
    params=(
        *shared_params("m", "k", "F0", "c_nominal"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("t_end"),
        positive("k3_hard", "k_3", 2.0, unit="N/m³", high=1e3, meaning="cubic stiffness of the hardening spring"),
        quantity(
            "k3_soft", "k_3", -1.0, unit="N/m³", low=-1e3, high=0.0, meaning="cubic stiffness of the softening spring"
        ),
        frequency("omega_sweep_min", "ω_lo", 3.0, high=1e3, meaning="lowest frequency of the stepped sweeps"),
        frequency("omega_sweep_max", "ω_hi", 6.5, high=1e3, meaning="highest frequency of the stepped sweeps"),
        count("n_sweep", "N_sweep", 200, low=10, high=400, meaning="frequencies in each sweep"),
        positive("c_ueda", "c_U", 0.05, unit="N s/m", high=10.0, meaning="damping of Ueda's oscillator"),
        frequency("omega_ueda", "ω_U", 1.0, high=10.0, meaning="forcing frequency of Ueda's oscillator"),
        positive(
            "F0_ueda", "F_U", 7.5, unit="N", high=100.0, meaning="forcing of Ueda's oscillator in the chaotic case"
        ),
        positive(
            "F0_ueda_periodic",
            "F_U",
            2.0,
            unit="N",
            high=100.0,
            meaning="forcing of Ueda's oscillator in the periodic case",
        ),
        count(
            "n_lyapunov",
            "N_λ",
            20000,
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

Params = SCHEMA.record_type(module=__name__)
