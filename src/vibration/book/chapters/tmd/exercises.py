"""Chapter 8's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.tmd import den_hartog

from .params import Params


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    dh = den_hartog(p.mu)
    m_a, k_a, c_a = dh.absorber(p.m, p.k)
    wn = math.sqrt(p.k / p.m)
    dh2 = den_hartog(min(2 * p.mu, 1.0))
    return {
        **p.as_dict(),
        "nu": dh.f,
        "zeta_a": dh.zeta_a,
        "one_plus_mu": 1 + p.mu,
        "three_mu": 3 * p.mu,
        "eight_one_plus_mu": 8 * (1 + p.mu),
        "m_a": m_a,
        "k_a": k_a,
        "c_a": c_a,
        "wn": wn,
        "omega_a": dh.f * wn,
        "mu_heavy": dh2.mu,
        "peak_formula": math.sqrt(1 + 2 / dh2.mu),
        "peak_heavy": dh2.peak,
        "peak": dh.peak,
    }


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
