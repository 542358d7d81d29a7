"""Chapter 4's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.exact import steady_state
from vibration.physics.model import Oscillator, SineForce
from vibration.physics.stability import peak_magnification

from .params import Params


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn, zeta = nom.natural_frequency, nom.damping_ratio
    ss = steady_state(nom, SineForce(F0=p.F0, omega=p.omega_ref))
    r = p.omega_ref / wn
    out = {
        **p.as_dict(),
        "wn": wn,
        "zeta": zeta,
        "r": r,
        "stiffness_term": (1 - r * r) ** 2,
        "damping_term": (2 * zeta * r) ** 2,
        "M": ss.magnification,
        "static": p.F0 / p.k,
        "X": ss.amplitude,
        "phi": ss.phase,
        "damped": p.c_nominal > 0,
        "peaked": 0 < zeta < 1 / math.sqrt(2),
        "doubled_peaked": p.c_nominal > 0 and 2 * zeta < 1 / math.sqrt(2),
        "c_doubled": 2 * p.c_nominal,
    }
    if out["damped"]:
        bw = nom.half_power_bandwidth
        out |= {
            "bandwidth": bw,
            "bandwidth_hz": bw / (2 * math.pi),
            "sqrt_km": math.sqrt(p.k * p.m),
            "Q": nom.quality_factor,
            "wn_over_bandwidth": wn / bw,
        }
    if out["peaked"]:
        wp, mp = peak_magnification(nom)
        out |= {"r_peak_squared": 1 - 2 * zeta**2, "omega_p": wp, "M_max": mp}
    if out["doubled_peaked"]:
        _, m2 = peak_magnification(Oscillator(m=p.m, c=2 * p.c_nominal, k=p.k))
        ratio = out["M_max"] / m2
        out |= {"M_max_doubled": m2, "peak_ratio": ratio, "than_two": "less" if ratio < 2 else "more"}
    return out


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
