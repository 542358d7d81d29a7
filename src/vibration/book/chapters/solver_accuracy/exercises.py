"""Chapter 3's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.frequency import settling_time
from vibration.physics.model import Oscillator, SineForce

from .params import Params


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    dt = p.t_end / (p.n_points - 1)
    per_period = 2 * math.pi / (p.omega_res * dt)
    out = {
        **p.as_dict(),
        "period": 2 * math.pi / p.omega_res,
        "periods": p.omega_res * p.t_end / (2 * math.pi),
        "dt": dt,
        "per_period": per_period,
        "damped": p.c_nominal > 0,
        "t_end_doubled": 2 * p.t_end,
        "dt_doubled": 2 * p.t_end / (p.n_points - 1),
        "per_period_halved": per_period / 2,
    }
    if out["damped"]:
        nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
        ts = settling_time(nom, SineForce(F0=p.F0, omega=p.omega_res))
        tau = nom.time_constant
        out |= {"two_m_over_c": 2 * p.m / p.c_nominal, "t_s": ts, "tau": tau, "t_s_over_tau": ts / tau}
    return out


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
