"""Chapter 1's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.exact import steady_state
from vibration.physics.model import Oscillator, SineForce

from .params import Params

#: The option of exercise 01.4 that names each regime of the high damping ("d" for the others).
REGIME_OPTIONS = {"underdamped": "a", "critically damped": "b", "overdamped": "c"}


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn, wd = nom.natural_frequency, nom.damped_natural_frequency
    ss = steady_state(nom, SineForce(F0=p.F0, omega=p.omega_ref))
    high = Oscillator(m=p.m, c=p.c_high, k=p.k)
    regime = REGIME_OPTIONS.get(high.regime, "d")
    out = {
        **p.as_dict(),
        "wn": wn,
        "cc": nom.critical_damping,
        "zeta": nom.damping_ratio,
        "sigma": nom.decay_rate,
        "wd": wd,
        "wd_atol": 1e-6 * wn,
        "free": "oscillates" if wd > 0 else "creeps",
        "den": math.hypot(p.k - p.m * p.omega_ref**2, p.c_nominal * p.omega_ref),
        "X": ss.amplitude,
        "phi": ss.phase,
        "phi_deg": math.degrees(ss.phase),
        "c_omega": p.c_nominal * p.omega_ref,
        "k_minus_m_omega2": p.k - p.m * p.omega_ref**2,
        "zeta_high": high.damping_ratio,
        "regime": regime,
        "reason": regime,
        "damped": p.c_nominal > 0,
    }
    if out["damped"]:
        force = SineForce(F0=p.F0, omega=p.omega_res)
        x1 = steady_state(nom, force).amplitude
        x2 = steady_state(Oscillator(m=p.m, c=2 * p.c_nominal, k=p.k), force).amplitude
        out |= {"c_doubled": 2 * p.c_nominal, "x_res": x1, "x_res_doubled": x2, "ratio": x1 / x2}
    return out


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
