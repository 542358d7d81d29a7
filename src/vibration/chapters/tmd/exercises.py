"""Chapter 8's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.tmd import den_hartog
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="How should a tuned mass damper be chosen, and how does it protect a building?",
    level="advanced",
    objectives=(
        "Compute Den Hartog's tuning ratio and absorber damping for a given mass ratio.",
        "Size an absorber's mass, stiffness and damper for a given primary.",
        "Compare Den Hartog, H∞ and H2 tunings by their peak and their sensitivity to mistuning.",
        "Explain why a tuned mass damper works on one mode of a multi-storey building.",
    ),
    prerequisites=("chapter 4: the magnification curve", "two-degree-of-freedom systems and their modes"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    dh = den_hartog(p.mu)
    m_a, k_a, c_a = dh.absorber(p.m, p.k)
    wn = math.sqrt(p.k / p.m)
    dh2 = den_hartog(min(2 * p.mu, 1.0))
    return (
        SHEET.numerical(
            "08.1",
            text=(
                f"For a mass ratio μ = {g(p.mu)}, compute Den Hartog's tuning ratio ν = ω<sub>a</sub>/ω<sub>p</sub> "
                "and the absorber's damping ratio ζ<sub>a</sub> (on its own frequency)."
            ),
            worked=(
                f"ν = 1/(1 + μ) = 1/{g(1 + p.mu)} = {g(dh.f)}. ζ<sub>a</sub> = √(3μ/(8(1 + μ))) = "
                f"√({g(3 * p.mu)}/{g(8 * (1 + p.mu))}) = {g(dh.zeta_a)}."
            ),
            answers=(
                Answer(quantity="nu", symbol="ν", value=dh.f, unit="", rtol=2e-3),
                Answer(quantity="zeta_a", symbol="ζ<sub>a</sub>", value=dh.zeta_a, unit="", rtol=2e-3),
            ),
        ),
        SHEET.numerical(
            "08.2",
            text=(
                f"Size that absorber for the primary m = {g(p.m)} kg, k = {g(p.k)} N/m: its mass (kg), stiffness (N/m) "
                "and damping coefficient (N s/m)."
            ),
            worked=(
                f"m<sub>a</sub> = μ m = {g(m_a)} kg; ω<sub>a</sub> = ν ω<sub>p</sub> = {g(dh.f)} × {g(wn)} = "
                f"{g(dh.f * wn)} rad/s; k<sub>a</sub> = m<sub>a</sub> ω<sub>a</sub>² = {g(k_a)} N/m; "
                f"c<sub>a</sub> = 2 ζ<sub>a</sub> m<sub>a</sub> ω<sub>a</sub> = {g(c_a)} N s/m."
            ),
            answers=(
                Answer(quantity="m_a", symbol="m<sub>a</sub>", value=m_a, unit="kg", rtol=2e-3),
                Answer(quantity="k_a", symbol="k<sub>a</sub>", value=k_a, unit="N/m", rtol=2e-3),
                Answer(quantity="c_a", symbol="c<sub>a</sub>", value=c_a, unit="N s/m", rtol=2e-3),
            ),
        ),
        SHEET.explore(
            "08.3",
            text=(
                f"Rerun the chapter with a heavier absorber (`-p mu {g(min(2 * p.mu, 1.0))}`). What is Den Hartog's "
                "peak magnification of the primary now (undamped primary)?"
            ),
            worked=(
                f"Den Hartog's fixed points give a peak of √(1 + 2/μ): with μ = {g(dh2.mu)} it is "
                f"√(1 + 2/{g(dh2.mu)}) = {g(math.sqrt(1 + 2 / dh2.mu))}; the computed peak of the tuned pair is "
                f"{g(dh2.peak)} (against {g(dh.peak)} at μ = {g(p.mu)})."
            ),
            answers=Answer(quantity="peak", symbol="M<sub>max</sub>", value=dh2.peak, unit="", rtol=1e-2),
        ),
    )
