"""Chapter 9's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.duffing import Duffing, backbone, linear_trust_amplitude

from .params import Params

#: The free amplitude of exercise 09.1, m.
AMPLITUDE = 1.0


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    d = Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=p.k3_hard)
    out = {
        **p.as_dict(),
        "amp": AMPLITUDE,
        "k_over_m": p.k / p.m,
        "cubic_term": 0.75 * p.k3_hard / p.m * AMPLITUDE**2,
        "omega_b": backbone(d, AMPLITUDE),
        "wn": math.sqrt(p.k / p.m),
        "damped": p.c_nominal > 0,
        "k3_doubled": min(2 * p.k3_hard, 1000.0),
    }
    if p.c_nominal > 0:
        d2 = Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=min(2 * p.k3_hard, 1000.0))
        out |= {"a_lin": linear_trust_amplitude(d), "a_doubled": linear_trust_amplitude(d2)}
    return out


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
