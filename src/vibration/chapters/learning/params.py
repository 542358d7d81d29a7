"""Chapter 11, a learning controller: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import at_least, ordered, sampling, shared
from vibration.presentation.schema import Param, Schema

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
    ),
)

Params = SCHEMA.record_type()
