"""Chapter 11's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.control import lqr
from vibration.physics.model import Oscillator

from .params import Params


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    plant = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn = plant.natural_frequency
    gains = lqr(plant, 1.0, 1.0, r=p.r_weight).K  # q_x = q_v = 1
    return {
        **p.as_dict(),
        "wn": wn,
        "t_episode": p.n_steps * p.dt,
        "period": 2 * math.pi / wn,
        "steps_per_period": 2 * math.pi / (wn * p.dt),
        "r_weight_tenfold": 10 * p.r_weight,
        "k_x": float(gains[0]),
        "k_v": float(gains[1]),
    }


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
