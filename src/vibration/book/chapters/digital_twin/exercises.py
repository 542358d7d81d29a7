"""Chapter 10's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.model import Oscillator

from .params import Params


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    nyq = 0.5 / p.dt
    healthy = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    damaged = Oscillator(m=p.m, c=p.c_nominal, k=p.k * (1 - p.drop))
    f0, f1 = healthy.natural_frequency / (2 * math.pi), damaged.natural_frequency / (2 * math.pi)
    return {
        **p.as_dict(),
        "f_nyquist": nyq,
        "df": 1.0 / p.t_record,
        "f_healthy": f0,
        "side": "below" if f0 < nyq else "above",
        "drop_percent": 100 * p.drop,
        "f_damaged": f1,
        "shift_percent": 100 * (1 - f1 / f0),
    }


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
