"""Chapter 2's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from vibration.physics.exact import exact_response, steady_state
from vibration.physics.frequency import settling_time
from vibration.physics.model import Oscillator, SineForce
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="Which of the paper's quantitative claims hold, and which reading of its numbers explains the rest?",
    level="core",
    objectives=(
        "Compute the static deflection F<sub>0</sub>/k and the magnification M of a forced response.",
        "Decide whether a claimed amplitude is a steady amplitude, a peak-to-peak swing or a window peak.",
        "Explain why a bounded response that is still growing at the end of a window is not an instability.",
        "Compute the 2 % settling time and compare it with a simulated window.",
    ),
    prerequisites=(
        "chapter 1: ω<sub>n</sub>, ζ, the steady amplitude X and the phase φ",
        "the roots of m s² + c s + k",
    ),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()

#: The paper's resonance amplitude, m ("a level of ±5.0 meters in the resonance case").
PAPER_RESONANCE_AMPLITUDE = 5.0


def _settle(p: Params, c: float) -> float:
    return settling_time(Oscillator(m=p.m, c=c, k=p.k), SineForce(F0=p.F0, omega=p.omega_res))


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    res = SineForce(F0=p.F0, omega=p.omega_res)
    ss = steady_state(nom, res)
    out = [
        SHEET.numerical(
            "02.1",
            text=(
                f"Compute the static deflection F<sub>0</sub>/k (m) and the magnification M = X/(F<sub>0</sub>/k) "
                f"of the nominal damping c = {g(p.c_nominal)} N s/m at the paper's resonant forcing ω = "
                f"{g(p.omega_res)} rad/s."
            ),
            worked=(
                f"F<sub>0</sub>/k = {g(p.F0)}/{g(p.k)} = {g(ss.static_deflection)} m. With r = ω/ω<sub>n</sub> = "
                f"{g(p.omega_res)}/{g(nom.natural_frequency)} = {g(p.omega_res / nom.natural_frequency)} and ζ = "
                f"{g(nom.damping_ratio)}, M = 1/√((1 − r²)² + (2ζr)²) = {g(ss.magnification)}, so X = "
                f"{g(ss.amplitude)} m."
            ),
            answers=(
                Answer(quantity="static", symbol="F<sub>0</sub>/k", value=ss.static_deflection, unit="m", rtol=2e-3),
                Answer(quantity="M", symbol="M", value=ss.magnification, unit="", rtol=5e-3),
            ),
        )
    ]
    t = np.linspace(0.0, p.t_end, 20001)
    x = exact_response(nom, res, t).x
    readings = {
        "a": ("the steady amplitude X", ss.amplitude),
        "b": ("the peak-to-peak swing 2X", 2 * ss.amplitude),
        "c": (f"the largest |x| over the {g(p.t_end)} s window", float(np.max(np.abs(x)))),
        "d": ("the magnification M, read as metres", ss.magnification),
    }
    key = min(readings, key=lambda k: abs(math.log(readings[k][1] / PAPER_RESONANCE_AMPLITUDE)))
    out.append(
        SHEET.conceptual(
            "02.2",
            text=(
                "The paper reports a resonance amplitude of “±5.0 meters” for the nominal damping at the resonant "
                "forcing. Which reading of that number comes closest for this run's parameters?"
            ),
            worked=(
                "The four readings, computed from the exact solution: "
                + "; ".join(f"({k}) {d}: {g(v)}" for k, (d, v) in readings.items())
                + f". The closest to 5.0 (by ratio) is ({key}), {g(readings[key][1])}."
            ),
            options={k: d for k, (d, _) in readings.items()},
            correct=key,
        )
    )
    low = Oscillator(m=p.m, c=p.c_low, k=p.k)
    stable = p.c_low > 0
    roots = {
        "a": "both in the left half-plane: bounded",
        "b": "on the imaginary axis",
        "c": "a root in the right half-plane: growing",
    }
    key = "a" if p.c_low > 0 else "b" if p.c_low == 0 else "c"
    disc = p.c_low**2 - 4 * p.m * p.k
    out.append(
        SHEET.conceptual(
            "02.3",
            text=(
                f"The paper calls the low damping c = {g(p.c_low)} N s/m “unstable”. Where are the roots of "
                "m s² + c s + k?"
            ),
            worked=(
                f"s = (−c ± √(c² − 4mk))/(2m) with c² − 4mk = {g(disc)}: the real part is "
                f"−c/(2m) = {g(-low.decay_rate)} 1/s"
                + (
                    ", negative. The response stays bounded; a still-growing envelope only means the transient has "
                    "not settled inside the window."
                    if stable
                    else "."
                )
            ),
            options=roots,
            correct=key,
        )
    )
    if p.c_low > 0:
        ts = _settle(p, p.c_low)
        out.append(
            SHEET.numerical(
                "02.4",
                text=(
                    f"Compute the 2 % settling time (s) of the low damping c = {g(p.c_low)} N s/m forced at "
                    f"ω = {g(p.omega_res)} rad/s from rest. Does it fall inside the {g(p.t_end)} s window?"
                ),
                worked=(
                    f"The transient is a free motion with envelope R e<sup>−σt</sup>, σ = c/(2m) = {g(low.decay_rate)} "
                    "1/s, R set by the rest start (x(0) = 0, v(0) = 0 minus the steady state). It falls to 2 % of "
                    f"X = {g(steady_state(low, res).amplitude)} m at t<sub>s</sub> = ln(R/(0.02 X))/σ = {g(ts)} s, "
                    + ("inside" if ts <= p.t_end else "beyond")
                    + f" the {g(p.t_end)} s window."
                ),
                answers=Answer(quantity="t_s", symbol="t<sub>s</sub>", value=ts, unit="s", rtol=1e-2),
            )
        )
    if p.c_low > 0 and _settle(p, p.c_high if p.c_high > p.c_low else 10 * p.c_low) < p.t_end < _settle(p, p.c_low):
        hi = p.c_high if p.c_high > p.c_low else 10 * p.c_low
        c_star = brentq(lambda c: _settle(p, c) - p.t_end, p.c_low, hi, xtol=1e-10)
        out.append(
            SHEET.explore(
                "02.5",
                text=(
                    "Rerun the chapter with larger values of the low damping (`-p c_low VALUE`). Which smallest "
                    f"c<sub>low</sub> (N s/m) lets that run settle (2 %) inside the {g(p.t_end)} s window, so that "
                    "the audit stops seeing a growing envelope?"
                ),
                worked=(
                    f"The settling time falls as c grows: {g(_settle(p, p.c_low))} s at c = {g(p.c_low)} N s/m. "
                    f"Solving t<sub>s</sub>(c) = {g(p.t_end)} s for c (the settling time of exercise 02.4, root "
                    f"by bisection) gives c = {g(c_star)} N s/m."
                ),
                answers=Answer(quantity="c_low", symbol="c<sub>low</sub>", value=c_star, unit="N s/m", rtol=1e-2),
            )
        )
    return tuple(out)
