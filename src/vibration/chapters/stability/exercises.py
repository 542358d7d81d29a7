"""Chapter 6's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.model import Oscillator
from vibration.physics.stability import step_metrics, transmissibility
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="Is light damping a risk to stability, and what does a designer trade by adding damping?",
    level="advanced",
    objectives=(
        "Decide stability from the poles of m s² + c s + k, and tell bounded resonance from instability.",
        "Compute the overshoot and the settling time of the step response from ζ.",
        "Compute the transmissibility of a base-excited mount and the frequency above which it isolates.",
        "Explain the trade-off damping brings in isolation, shock and random loads.",
    ),
    prerequisites=("Part I (chapters 1-5)", "the roots of a quadratic in the complex plane"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    zeta, wn = nom.damping_ratio, nom.natural_frequency
    out = []
    if 0 < zeta < 1:
        sm = step_metrics(nom)
        os_closed = math.exp(-math.pi * zeta / math.sqrt(1 - zeta**2))
        out.append(
            SHEET.numerical(
                "06.1",
                text=(
                    f"A constant force is switched on at rest on the nominal oscillator (c = {g(p.c_nominal)} N s/m). "
                    "Compute the overshoot (a fraction of the final deflection) and the time of the first peak (s)."
                ),
                worked=(
                    f"ζ = {g(zeta)}, ω<sub>d</sub> = ω<sub>n</sub>√(1 − ζ²) = {g(nom.damped_natural_frequency)} rad/s. "
                    f"Overshoot = exp(−πζ/√(1 − ζ²)) = {g(os_closed)}; first peak at t<sub>p</sub> = π/ω<sub>d</sub> "
                    f"= {g(sm.peak_time)} s."
                ),
                answers=(
                    Answer(quantity="overshoot", symbol="overshoot", value=sm.overshoot, unit="", rtol=5e-3),
                    Answer(quantity="t_p", symbol="t<sub>p</sub>", value=sm.peak_time, unit="s", rtol=5e-3),
                ),
            )
        )
    sigma = -p.c_unstable / (2 * p.m)
    key = "a" if p.c_unstable < 0 else "b" if p.c_unstable == 0 else "c"
    out.append(
        SHEET.conceptual(
            "06.2",
            text=(
                f"A damping c = {g(p.c_unstable)} N s/m is applied with no force at all, from a small displacement. "
                "What does the motion do?"
            ),
            worked=(
                f"The poles are s = −c/(2m) ± i√(k/m − (c/2m)²), real part {g(sigma)} 1/s. "
                + (
                    f"It is positive: the oscillation grows like e<sup>{g(sigma)} t</sup> with no force at all, "
                    "a true instability (flutter's linear model), unlike forced resonance."
                    if key == "a"
                    else "It is zero: the motion neither grows nor decays."
                    if key == "b"
                    else "It is negative: the motion decays."
                )
            ),
            options={"a": "it grows exponentially: unstable", "b": "it keeps a constant amplitude", "c": "it decays"},
            correct=key,
        )
    )
    if p.c_nominal >= 0:
        w = p.isolation_ratio * wn
        tr = float(transmissibility(nom, w))
        out.append(
            SHEET.explore(
                "06.3",
                text=(
                    f"In the sliders, set the damping ratio to ζ = {g(zeta)} (the nominal damping) and the base "
                    f"frequency to {g(p.isolation_ratio)} ω<sub>n</sub>. Compute the "
                    "transmissibility T the panel shows, "
                    "and the frequency (rad/s) above which the mount isolates (T < 1)."
                ),
                worked=(
                    f"r = {g(p.isolation_ratio)}: T = √((1 + (2ζr)²)/((1 − r²)² + (2ζr)²)) = {g(tr)}. "
                    f"T < 1 above r = √2 for every ζ, that is ω > √2 ω<sub>n</sub> = {g(math.sqrt(2) * wn)} rad/s."
                ),
                answers=(
                    Answer(quantity="T", symbol="T", value=tr, unit="", rtol=5e-3),
                    Answer(
                        quantity="omega_iso",
                        symbol="√2 ω<sub>n</sub>",
                        value=math.sqrt(2) * wn,
                        unit="rad/s",
                        rtol=2e-3,
                    ),
                ),
            )
        )
    return tuple(out)
