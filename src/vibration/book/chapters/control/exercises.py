"""Chapter 7's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.control import pd_oscillator, stabilising_velocity_gain
from vibration.physics.model import Oscillator

from .params import Params

#: The damping ratio asked of the loop in exercise 07.3.
ZETA_TARGET = 0.7


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    cl = pd_oscillator(Oscillator(m=p.m, c=p.c_nominal, k=p.k), p.kp, p.kd)
    kd_min = stabilising_velocity_gain(Oscillator(m=p.m, c=p.c_flutter, k=p.k))
    return {
        **p.as_dict(),
        "c_loop": cl.c,
        "k_loop": cl.k,
        "omega_n": cl.natural_frequency,
        "zeta": cl.damping_ratio,
        "kd_min": kd_min,
        "flutter_stabilisable": kd_min > 0,
        "zeta_target": ZETA_TARGET,
        "k_plus_kp": p.k + p.kp,
        "kd_target": 2 * ZETA_TARGET * math.sqrt((p.k + p.kp) * p.m) - p.c_nominal,
    }


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
