"""Chapter 5's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.exact import steady_state
from vibration.physics.model import Oscillator, SineForce

from .params import Params

#: The magnification a designer allows at resonance in exercise 05.2.
M_ALLOWED = 5.0


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn, cc = nom.natural_frequency, nom.critical_damping
    ss = steady_state(nom, SineForce(F0=p.F0, omega=p.omega_res))
    w_set = round(0.8 * wn, 2)
    c_set = float(f"{max(0.2 * cc, 1e-3):.2g}")
    sl = steady_state(Oscillator(m=p.m, c=c_set, k=p.k), SineForce(F0=p.F0, omega=w_set))
    return {
        **p.as_dict(),
        "wn": wn,
        "cc": cc,
        "r": p.omega_res / wn,
        "zeta": nom.damping_ratio,
        "M": ss.magnification,
        "X": ss.amplitude,
        "m_allowed": M_ALLOWED,
        "zeta_need": 1 / (2 * M_ALLOWED),
        "c_need": cc / (2 * M_ALLOWED),
        "w_set": w_set,
        "c_set": c_set,
        "zeta_set": c_set / cc,
        "r_set": w_set / wn,
        "static": p.F0 / p.k,
        "M_set": sl.magnification,
        "X_set": sl.amplitude,
        "phi_set_deg": math.degrees(sl.phase),
    }


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
