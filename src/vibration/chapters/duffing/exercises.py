"""Chapter 9's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.duffing import Duffing, backbone, linear_trust_amplitude
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="What changes when the spring is not linear: jumps, folds and chaos?",
    level="advanced",
    objectives=(
        "Compute the backbone frequency of a cubic spring at a given amplitude.",
        "Compute the amplitude up to which the linear model's resonance can be trusted.",
        "Explain the jumps of a frequency sweep from the folds of the response curve.",
        "Tell periodic from chaotic motion by a Poincaré section and a Lyapunov exponent.",
    ),
    prerequisites=("chapter 4: the resonance curve", "harmonic balance (one-term Fourier approximation)"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    d = Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=p.k3_hard)
    wn = math.sqrt(p.k / p.m)
    amp = 1.0  # m
    wb = backbone(d, amp)
    out = [
        SHEET.numerical(
            "09.1",
            text=(
                f"The hardening spring adds k<sub>3</sub> x³ with k<sub>3</sub> = {g(p.k3_hard)} N/m³ to "
                f"k = {g(p.k)} N/m (m = {g(p.m)} kg). At which frequency (rad/s) does it oscillate freely with an "
                f"amplitude of {g(amp)} m, by one-harmonic balance?"
            ),
            worked=(
                f"With x = A cos ωt, the cubic term's first harmonic is (3/4) k<sub>3</sub> A³ cos ωt, so "
                f"ω² = k/m + (3/4)(k<sub>3</sub>/m) A² = {g(p.k / p.m)} + {g(0.75 * p.k3_hard / p.m * amp**2)} and "
                f"ω = {g(wb)} rad/s, against ω<sub>n</sub> = {g(wn)} rad/s."
            ),
            answers=Answer(quantity="omega_b", symbol="ω<sub>b</sub>", value=wb, unit="rad/s", rtol=2e-3),
        ),
        SHEET.conceptual(
            "09.2",
            text="A slow upward frequency sweep of the hardening oscillator suddenly drops in amplitude. Why?",
            worked=(
                "Past the upper fold of the response curve the large-amplitude branch ends; the only steady "
                "motion left at that frequency is on the small-amplitude branch, and the sweep jumps down to it."
            ),
            options={
                "a": "the large-amplitude branch ends at a fold and the motion jumps to the lower one",
                "b": "the damping grows with the amplitude",
                "c": "the motion becomes chaotic",
            },
            correct="a",
        ),
    ]
    if p.c_nominal > 0:
        a_lin = linear_trust_amplitude(d)
        d2 = Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=min(2 * p.k3_hard, 1000.0))
        a2 = linear_trust_amplitude(d2)
        out.append(
            SHEET.explore(
                "09.3",
                text=(
                    "Up to which amplitude (m) does the backbone stay within one half-power bandwidth c/m of "
                    f"ω<sub>n</sub>? Rerun the chapter with a doubled cubic stiffness (`-p k3_hard "
                    f"{g(min(2 * p.k3_hard, 1000.0))}`) and give that amplitude again."
                ),
                worked=(
                    f"Solve ω<sub>b</sub>(A) = ω<sub>n</sub> + c/m: "
                    f"A² = (4m/(3k<sub>3</sub>))((ω<sub>n</sub> + c/m)² − "
                    f"ω<sub>n</sub>²). With k<sub>3</sub> = {g(p.k3_hard)} N/m³, A = {g(a_lin)} m; with "
                    f"k<sub>3</sub> = {g(d2.k3)} N/m³, A = {g(a2)} m (a factor 1/√2)."
                ),
                answers=(
                    Answer(quantity="A", symbol="A", value=a_lin, unit="m", rtol=5e-3),
                    Answer(quantity="A_doubled", symbol="A (doubled k<sub>3</sub>)", value=a2, unit="m", rtol=5e-3),
                ),
            )
        )
    return tuple(out)
