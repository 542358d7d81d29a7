"""Chapter 4's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.exact import steady_state
from vibration.physics.model import Oscillator, SineForce
from vibration.physics.stability import peak_magnification
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="How does the steady amplitude depend on the forcing frequency and the damping?",
    level="core",
    objectives=(
        "Compute the steady amplitude X and the phase lag φ at any forcing frequency.",
        "Compute the half-power bandwidth and the quality factor Q from the damping.",
        "Locate the peak of the magnification curve and compute its height.",
        "Explain which term (spring, damper or mass) limits the amplitude below, at and above ω<sub>n</sub>.",
    ),
    prerequisites=("chapter 1: ω<sub>n</sub>, ζ and the steady amplitude", "logarithms and decibels"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn, zeta = nom.natural_frequency, nom.damping_ratio
    ss = steady_state(nom, SineForce(F0=p.F0, omega=p.omega_ref))
    r = p.omega_ref / wn
    out = [
        SHEET.numerical(
            "04.1",
            text=(
                f"Compute the magnification M, the steady amplitude X (m) and the phase lag φ (rad) of the nominal "
                f"damping c = {g(p.c_nominal)} N s/m at ω = {g(p.omega_ref)} rad/s."
            ),
            worked=(
                f"r = ω/ω<sub>n</sub> = {g(p.omega_ref)}/{g(wn)} = {g(r)}, ζ = {g(zeta)}. "
                f"M = 1/√((1 − r²)² + (2ζr)²) = 1/√({g((1 - r * r) ** 2)} + {g((2 * zeta * r) ** 2)}) = "
                f"{g(ss.magnification)}; X = M F<sub>0</sub>/k = {g(ss.magnification)} × {g(p.F0 / p.k)} = "
                f"{g(ss.amplitude)} m; φ = atan2(2ζr, 1 − r²) = {g(ss.phase)} rad."
            ),
            answers=(
                Answer(quantity="M", symbol="M", value=ss.magnification, unit="", rtol=5e-3),
                Answer(quantity="X", symbol="X", value=ss.amplitude, unit="m", rtol=5e-3),
                Answer(quantity="phi", symbol="φ", value=ss.phase, unit="rad", rtol=5e-3, atol=1e-4),
            ),
        )
    ]
    if p.c_nominal > 0:
        bw, q = nom.half_power_bandwidth, nom.quality_factor
        out.append(
            SHEET.numerical(
                "04.2",
                text=(
                    f"Compute the half-power bandwidth Δω (rad/s) and the quality factor Q of the nominal damping "
                    f"c = {g(p.c_nominal)} N s/m."
                ),
                worked=(
                    f"Δω = 2ζω<sub>n</sub> = c/m = {g(p.c_nominal)}/{g(p.m)} = {g(bw)} rad/s "
                    f"({g(bw / (2 * math.pi))} Hz). Q = 1/(2ζ) = √(km)/c = {g(math.sqrt(p.k * p.m))}/{g(p.c_nominal)} "
                    f"= {g(q)}, also ω<sub>n</sub>/Δω = {g(wn / bw)}."
                ),
                answers=(
                    Answer(quantity="bandwidth", symbol="Δω", value=bw, unit="rad/s", rtol=5e-3),
                    Answer(quantity="Q", symbol="Q", value=q, unit="", rtol=5e-3),
                ),
            )
        )
    if 0 < zeta < 1 / math.sqrt(2):
        wp, mp = peak_magnification(nom)
        out.append(
            SHEET.numerical(
                "04.3",
                text=(
                    "At which forcing frequency ω<sub>p</sub> (rad/s) does the magnification of the nominal damping "
                    "peak, and how high is the peak M<sub>max</sub>?"
                ),
                worked=(
                    f"Setting the derivative of (1 − r²)² + (2ζr)² to zero gives r² = 1 − 2ζ² = {g(1 - 2 * zeta**2)}, "
                    f"so ω<sub>p</sub> = ω<sub>n</sub>√(1 − 2ζ²) = {g(wp)} rad/s and "
                    f"M<sub>max</sub> = 1/(2ζ√(1 − ζ²)) = {g(mp)}."
                ),
                answers=(
                    Answer(quantity="omega_p", symbol="ω<sub>p</sub>", value=wp, unit="rad/s", rtol=2e-3),
                    Answer(quantity="M_max", symbol="M<sub>max</sub>", value=mp, unit="", rtol=5e-3),
                ),
            )
        )
    out.append(
        SHEET.conceptual(
            "04.4",
            text="Far above ω<sub>n</sub> (ω ≫ ω<sub>n</sub>), which term of m ẍ + c ẋ + k x sets the amplitude?",
            worked=(
                "The terms of the steady response scale as k X, c ω X and m ω² X. For ω ≫ ω<sub>n</sub> the inertia "
                "term m ω² X dominates, so X ≈ F<sub>0</sub>/(m ω²): the mass carries the force and the amplitude "
                "falls as 1/ω²."
            ),
            options={"a": "the spring, k X", "b": "the damper, c ω X", "c": "the mass, m ω² X"},
            correct="c",
        )
    )
    if p.c_nominal > 0 and 2 * zeta < 1 / math.sqrt(2):
        _, m1 = peak_magnification(nom)
        _, m2 = peak_magnification(Oscillator(m=p.m, c=2 * p.c_nominal, k=p.k))
        out.append(
            SHEET.explore(
                "04.5",
                text=(
                    f"Rerun the chapter with twice the nominal damping (`-p c_nominal {g(2 * p.c_nominal)}`). By what "
                    "factor does the half-power bandwidth grow, and by what factor does the peak magnification fall "
                    "(old over new)?"
                ),
                worked=(
                    f"Δω = c/m doubles: factor 2. M<sub>max</sub> = 1/(2ζ√(1 − ζ²)) goes from {g(m1)} to {g(m2)}: "
                    f"a factor {g(m1 / m2)}, slightly {'less' if m1 / m2 < 2 else 'more'} than 2 because the factor "
                    "√(1 − ζ²) changes too."
                ),
                answers=(
                    Answer(quantity="bandwidth_ratio", symbol="Δω ratio", value=2.0, unit="", rtol=5e-3),
                    Answer(quantity="peak_ratio", symbol="M<sub>max</sub> ratio", value=m1 / m2, unit="", rtol=5e-3),
                ),
            )
        )
    return tuple(out)
