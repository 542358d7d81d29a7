"""Chapter 2's objectives, prerequisites and exercises, every answer computed from the run's parameters.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from vibration.book.presentation.exercises import ChapterExercises
from vibration.physics.exact import exact_response, steady_state
from vibration.physics.frequency import settling_time
from vibration.physics.model import Oscillator, SineForce

from .params import Params

#: The paper's resonance amplitude, m ("a level of ±5.0 meters in the resonance case").
PAPER_RESONANCE_AMPLITUDE = 5.0
#: Samples of the exact solution over the window, for the largest |x| of exercise 02.2.
WINDOW_SAMPLES = 20001


def _settle(p: Params, c: float) -> float:
    return settling_time(Oscillator(m=p.m, c=c, k=p.k), SineForce(F0=p.F0, omega=p.omega_res))


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params``."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    res = SineForce(F0=p.F0, omega=p.omega_res)
    ss = steady_state(nom, res)
    x = exact_response(nom, res, np.linspace(0.0, p.t_end, WINDOW_SAMPLES)).x
    readings = {"a": ss.amplitude, "b": 2 * ss.amplitude, "c": float(np.max(np.abs(x))), "d": ss.magnification}
    closest = min(readings, key=lambda k: abs(math.log(readings[k] / PAPER_RESONANCE_AMPLITUDE)))
    low = Oscillator(m=p.m, c=p.c_low, k=p.k)
    out = {
        **p.as_dict(),
        "static": ss.static_deflection,
        "wn": nom.natural_frequency,
        "r": p.omega_res / nom.natural_frequency,
        "zeta": nom.damping_ratio,
        "M": ss.magnification,
        "X": ss.amplitude,
        "paper_amplitude": PAPER_RESONANCE_AMPLITUDE,
        **{f"reading_{k}": v for k, v in readings.items()},
        "reading": closest,
        "reading_closest": readings[closest],
        "disc": p.c_low**2 - 4 * p.m * p.k,
        "real_part": -low.decay_rate,
        "envelope": "bounded" if p.c_low > 0 else "other",
        "roots": "a" if p.c_low > 0 else "b" if p.c_low == 0 else "c",
        "low_damped": p.c_low > 0,
        "settles_within_reach": False,
    }
    if out["low_damped"]:
        ts = _settle(p, p.c_low)
        hi = p.c_high if p.c_high > p.c_low else 10 * p.c_low
        out |= {
            "sigma_low": low.decay_rate,
            "X_low": steady_state(low, res).amplitude,
            "t_s": ts,
            "where": "inside" if ts <= p.t_end else "beyond",
            "settles_within_reach": _settle(p, hi) < p.t_end < ts,
        }
        if out["settles_within_reach"]:
            out["c_star"] = brentq(lambda c: _settle(p, c) - p.t_end, p.c_low, hi, xtol=1e-10)
    return out


exercises = ChapterExercises.read(__package__, Params, values)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
