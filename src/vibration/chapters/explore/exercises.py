"""Chapter 5's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.exact import steady_state
from vibration.physics.model import Oscillator, SineForce
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="What happens to the response as the forcing frequency and the damping move?",
    level="core",
    objectives=(
        "Predict how the steady amplitude moves when the forcing frequency or the damping changes.",
        "Compute the damping needed to hold the resonant magnification below a limit.",
        "Read the phase lag at resonance and explain why it is 90° whatever the damping.",
        "Check a reading of the sliders against the closed-form steady amplitude.",
    ),
    prerequisites=("chapters 1 and 4: the steady amplitude, the magnification and the phase lag",),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()

#: The magnification a designer allows at resonance in exercise 05.2.
M_ALLOWED = 5.0


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn, cc = nom.natural_frequency, nom.critical_damping
    ss = steady_state(nom, SineForce(F0=p.F0, omega=p.omega_res))
    c_need = cc / (2 * M_ALLOWED)
    out = [
        SHEET.numerical(
            "05.1",
            text=(
                f"With the sliders at their start (ω = {g(p.omega_res)} rad/s, c = {g(p.c_nominal)} N s/m), compute "
                "the magnification M and the steady amplitude X (m)."
            ),
            worked=(
                f"ω<sub>n</sub> = √(k/m) = {g(wn)} rad/s, r = {g(p.omega_res / wn)}, ζ = {g(nom.damping_ratio)}: "
                f"M = 1/√((1 − r²)² + (2ζr)²) = {g(ss.magnification)} and X = M F<sub>0</sub>/k = {g(ss.amplitude)} m."
            ),
            answers=(
                Answer(quantity="M", symbol="M", value=ss.magnification, unit="", rtol=5e-3),
                Answer(quantity="X", symbol="X", value=ss.amplitude, unit="m", rtol=5e-3),
            ),
        ),
        SHEET.numerical(
            "05.2",
            text=(
                f"Forced exactly at ω<sub>n</sub>, which damping c (N s/m) holds the magnification at "
                f"M = {g(M_ALLOWED)}?"
            ),
            worked=(
                f"At r = 1, M = 1/(2ζ), so ζ = 1/(2 × {g(M_ALLOWED)}) = {g(1 / (2 * M_ALLOWED))} and "
                f"c = ζ c<sub>c</sub> = ζ × 2√(km) = {g(1 / (2 * M_ALLOWED))} × {g(cc)} = {g(c_need)} N s/m."
            ),
            answers=Answer(quantity="c", symbol="c", value=c_need, unit="N s/m", rtol=5e-3),
        ),
        SHEET.conceptual(
            "05.3",
            text="Move the damping slider while the forcing sits at ω = ω<sub>n</sub>. What does the phase lag do?",
            worked=(
                "φ = atan2(2ζr, 1 − r²); at r = 1 the denominator is zero, so φ = 90° (π/2 rad) for every ζ > 0: the "
                "displacement lags the force by a quarter period and the velocity is in phase with it."
            ),
            options={
                "a": "it stays at 90°",
                "b": "it grows with the damping towards 180°",
                "c": "it falls with the damping towards 0°",
            },
            correct="a",
        ),
    ]
    w_set = round(0.8 * wn, 2)
    c_set = float(f"{max(0.2 * cc, 1e-3):.2g}")
    sl = steady_state(Oscillator(m=p.m, c=c_set, k=p.k), SineForce(F0=p.F0, omega=w_set))
    out.append(
        SHEET.explore(
            "05.4",
            text=(
                f"Set the sliders to ω = {g(w_set)} rad/s and c = {g(c_set)} N s/m. What steady amplitude X (m) does "
                "the readout show? Compute it first, then read it."
            ),
            worked=(
                f"ζ = {g(c_set)}/{g(cc)} = {g(c_set / cc)}, r = {g(w_set)}/{g(wn)} = {g(w_set / wn)}: "
                f"X = (F<sub>0</sub>/k)/√((1 − r²)² + (2ζr)²) = {g(p.F0 / p.k)} × {g(sl.magnification)} = "
                f"{g(sl.amplitude)} m, with φ = {g(math.degrees(sl.phase), 3)}°."
            ),
            answers=Answer(quantity="X", symbol="X", value=sl.amplitude, unit="m", rtol=1e-2),
        )
    )
    return tuple(out)
