"""Chapter 11, a learning controller: its parameters, declared once (the sampling step checked against the plant)."""

from __future__ import annotations

import inspect
import math

from vibration.physics.learning.studies import identify_then_design
from vibration.physics.model import ParameterError
from vibration.physics.twin.measurements import MIN_SAMPLES
from vibration.presentation.parameters import (
    at_least,
    count,
    damping,
    ordered,
    positive,
    sampling,
    seed,
    shared,
    shared_params,
)
from vibration.presentation.schema import Schema

#: Length of the identification record of the identify-then-design study, s.
ID_DURATION = inspect.signature(identify_then_design).parameters["duration"].default


def sampling_step(p: dict) -> None:
    """The sampling step resolves the plant (below the Nyquist step π/ω_n) and the identification record."""
    dt, wn = p["dt"], math.sqrt(p["k"] / p["m"])
    if not dt < math.pi / wn:
        raise ParameterError(
            f"dt = {dt!r} s is not below half the natural period π/ω_n = {math.pi / wn:.4g} s (m = {p['m']!r} kg, "
            f"k = {p['k']!r} N/m): allowed dt < {math.pi / wn:.4g} s"
        )
    if dt > ID_DURATION / MIN_SAMPLES:
        raise ParameterError(
            f"dt = {dt!r} s leaves fewer than {MIN_SAMPLES} samples in the {ID_DURATION:g} s identification record: "
            f"allowed dt <= {ID_DURATION / MIN_SAMPLES:.4g} s"
        )


SCHEMA = Schema(
    notebook="11_learning",
    params=(
        *shared_params("m", "k"),
        shared("c_nominal", meaning="passive damping of the plant"),
        shared("F0", meaning="amplitude of the resonance disturbance"),
        shared("omega_res", meaning="angular frequency of the resonance disturbance"),
        positive("dt", "Δt", 0.01, unit="s", high=1.0, meaning="sampling period of the zero-order hold"),
        count("n_steps", "N_steps", 1000, low=1, high=3000, meaning="steps per episode"),
        positive("r_weight", "r", 0.01, unit="1/N²", high=1e6, meaning="weight of the force in the cost"),
        positive("u_max", "u_max", 50.0, unit="N", high=1e4, meaning="force bound of the actuator"),
        damping("c_semi_min", "c_min", 0.1, low=0.0, high=1e4, meaning="smallest damping of the semi-active damper"),
        positive(
            "c_semi_max", "c_max", 15.0, unit="N s/m", high=1e4, meaning="largest damping of the semi-active damper"
        ),
        seed(0, meaning="seed of training and of the evaluation episodes"),
        count("n_eval", "N_eval", 1000, low=2, high=20000, meaning="evaluation episodes per controller"),
        count("n_seeds", "N_seeds", 10, low=10, high=30, meaning="training seeds per learner in the seed study"),
    ),
    together=(
        ordered("c_semi_min", "c_semi_max", "N s/m"),
        at_least("c_nominal", 0.0, "N s/m", "a learner needs a passive plant"),
        sampling,
        sampling_step,
    ),
)

Params = SCHEMA.record_type(module=__name__)
