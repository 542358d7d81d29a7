"""Chapter 6's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.model import Oscillator
from vibration.physics.stability import step_metrics, transmissibility

from .params import Params


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    zeta, wn = nom.damping_ratio, nom.natural_frequency
    key = "a" if p.c_unstable < 0 else "b" if p.c_unstable == 0 else "c"  # grows, keeps, decays
    out = {
        **p.as_dict(),
        "zeta": zeta,
        "underdamped": 0 < zeta < 1,
        "sigma": -p.c_unstable / (2 * p.m),
        "key": key,
        "motion": key,
        "passive": p.c_nominal >= 0,
    }
    if out["underdamped"]:
        sm = step_metrics(nom)
        out |= {
            "wd": nom.damped_natural_frequency,
            "overshoot_formula": math.exp(-math.pi * zeta / math.sqrt(1 - zeta**2)),
            "overshoot": sm.overshoot,
            "peak_time": sm.peak_time,
        }
    if out["passive"]:
        out |= {"tr": float(transmissibility(nom, p.isolation_ratio * wn)), "omega_iso": math.sqrt(2) * wn}
    return out


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
