"""Chapter 11, a learning controller: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

import inspect
import math

from vibration.physics.learning.studies import identify_then_design
from vibration.physics.model import ParameterError
from vibration.physics.twin.measurements import MIN_SAMPLES
from vibration.presentation.parameters import at_least, ordered, sampling, shared
from vibration.presentation.schema import Param, Schema

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
    "11_learning",
    (
        shared("m"),
        shared("k"),
        shared("c_nominal", meaning="passive damping of the plant"),
        shared("F0", meaning="amplitude of the resonance disturbance"),
        shared("omega_res", meaning="angular frequency of the resonance disturbance"),
        Param("dt", "Δt", 0.01, "s", 0.0, 1.0, "sampling period of the zero-order hold", low_open=True),
        Param("n_steps", "N_steps", 1000, "", 1, 3000, "steps per episode"),
        Param("r_weight", "r", 0.01, "1/N²", 0.0, 1000000.0, "weight of the force in the cost", low_open=True),
        Param("u_max", "u_max", 50.0, "N", 0.0, 10000.0, "force bound of the actuator", low_open=True),
        Param("c_semi_min", "c_min", 0.1, "N s/m", 0.0, 10000.0, "smallest damping of the semi-active damper"),
        Param(
            "c_semi_max",
            "c_max",
            15.0,
            "N s/m",
            0.0,
            10000.0,
            "largest damping of the semi-active damper",
            low_open=True,
        ),
        Param("seed", "s", 0, "", 0, 2147483647, "seed of training and of the evaluation episodes"),
        Param("n_eval", "N_eval", 1000, "", 2, 20000, "evaluation episodes per controller"),
        Param("n_seeds", "N_seeds", 10, "", 10, 30, "training seeds per learner in the seed study"),
    ),
    together=(
        ordered("c_semi_min", "c_semi_max", "N s/m"),
        at_least("c_nominal", 0.0, "N s/m", "a learner needs a passive plant"),
        sampling,
        sampling_step,
    ),
)

Params = SCHEMA.record_type()
