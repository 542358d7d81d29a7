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
    notebook="11_learning",
    params=(
        shared("m"),
        shared("k"),
        shared("c_nominal", meaning="passive damping of the plant"),
        shared("F0", meaning="amplitude of the resonance disturbance"),
        shared("omega_res", meaning="angular frequency of the resonance disturbance"),
        Param(
            name="dt",
            symbol="Δt",
            default=0.01,
            unit="s",
            low=0.0,
            high=1.0,
            meaning="sampling period of the zero-order hold",
            low_open=True,
        ),
        Param(name="n_steps", symbol="N_steps", default=1000, unit="", low=1, high=3000, meaning="steps per episode"),
        Param(
            name="r_weight",
            symbol="r",
            default=0.01,
            unit="1/N²",
            low=0.0,
            high=1000000.0,
            meaning="weight of the force in the cost",
            low_open=True,
        ),
        Param(
            name="u_max",
            symbol="u_max",
            default=50.0,
            unit="N",
            low=0.0,
            high=10000.0,
            meaning="force bound of the actuator",
            low_open=True,
        ),
        Param(
            name="c_semi_min",
            symbol="c_min",
            default=0.1,
            unit="N s/m",
            low=0.0,
            high=10000.0,
            meaning="smallest damping of the semi-active damper",
        ),
        Param(
            name="c_semi_max",
            symbol="c_max",
            default=15.0,
            unit="N s/m",
            low=0.0,
            high=10000.0,
            meaning="largest damping of the semi-active damper",
            low_open=True,
        ),
        Param(
            name="seed",
            symbol="s",
            default=0,
            unit="",
            low=0,
            high=2147483647,
            meaning="seed of training and of the evaluation episodes",
        ),
        Param(
            name="n_eval",
            symbol="N_eval",
            default=1000,
            unit="",
            low=2,
            high=20000,
            meaning="evaluation episodes per controller",
        ),
        Param(
            name="n_seeds",
            symbol="N_seeds",
            default=10,
            unit="",
            low=10,
            high=30,
            meaning="training seeds per learner in the seed study",
        ),
    ),
    together=(
        ordered("c_semi_min", "c_semi_max", "N s/m"),
        at_least("c_nominal", 0.0, "N s/m", "a learner needs a passive plant"),
        sampling,
        sampling_step,
    ),
)

Params = SCHEMA.record_type()
