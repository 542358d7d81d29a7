"""Chapter 7's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.control import pd_oscillator, stabilising_velocity_gain
from vibration.physics.model import Oscillator
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="How far can feedback, semi-active dampers and input shaping do better than a passive damper?",
    level="advanced",
    objectives=(
        "Compute the natural frequency and damping ratio of a PD-controlled oscillator.",
        "Compute the smallest velocity feedback that stabilises negative damping.",
        "Choose a gain for a given closed-loop damping ratio.",
        "Compare active, semi-active and feed-forward control by force, energy and robustness.",
    ),
    prerequisites=("chapter 6: poles and stability", "feedback and the closed loop of a linear system"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()

#: The damping ratio asked of the loop in exercise 07.3.
ZETA_TARGET = 0.7


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    plant = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    cl = pd_oscillator(plant, p.kp, p.kd)
    out = [
        SHEET.numerical(
            "07.1",
            text=(
                f"The force u = −k<sub>p</sub> x − k<sub>d</sub> ẋ with k<sub>p</sub> = {g(p.kp)} N/m and "
                f"k<sub>d</sub> = {g(p.kd)} N s/m acts on the plant (m = {g(p.m)} kg, c = {g(p.c_nominal)} N s/m, "
                f"k = {g(p.k)} N/m). Compute the closed loop's natural frequency (rad/s) and damping ratio."
            ),
            worked=(
                f"The loop is m ẍ + (c + k<sub>d</sub>) ẋ + (k + k<sub>p</sub>) x = F: c' = {g(cl.c)} N s/m, "
                f"k' = {g(cl.k)} N/m. ω<sub>n</sub>' = √(k'/m) = {g(cl.natural_frequency)} rad/s, "
                f"ζ' = c'/(2√(k'm)) = {g(cl.damping_ratio)}."
            ),
            answers=(
                Answer(
                    quantity="omega_n", symbol="ω<sub>n</sub>'", value=cl.natural_frequency, unit="rad/s", rtol=2e-3
                ),
                Answer(quantity="zeta", symbol="ζ'", value=cl.damping_ratio, unit="", rtol=2e-3),
            ),
        )
    ]
    flutter = Oscillator(m=p.m, c=p.c_flutter, k=p.k)
    kd_min = stabilising_velocity_gain(flutter)
    if kd_min > 0:
        out.append(
            SHEET.numerical(
                "07.2",
                text=(
                    f"A plant with negative damping c = {g(p.c_flutter)} N s/m (a flutter model) gets velocity "
                    "feedback u = −k<sub>d</sub> ẋ. Above which gain k<sub>d</sub> (N s/m) is the loop stable?"
                ),
                worked=(
                    f"The loop's damping is c + k<sub>d</sub>; its poles have real part −(c + k<sub>d</sub>)/(2m), "
                    f"negative exactly when k<sub>d</sub> > −c = {g(kd_min)} N s/m."
                ),
                answers=Answer(quantity="kd_min", symbol="k<sub>d</sub>", value=kd_min, unit="N s/m", rtol=2e-3),
            )
        )
    kd_t = 2 * ZETA_TARGET * math.sqrt((p.k + p.kp) * p.m) - p.c_nominal
    out.append(
        SHEET.explore(
            "07.3",
            text=(
                f"Which velocity gain k<sub>d</sub> (N s/m) gives the PD loop a damping ratio of {g(ZETA_TARGET)} "
                f"with k<sub>p</sub> = {g(p.kp)} N/m? Rerun the chapter with it (`-p kd VALUE`) and compare the "
                "loop's step response with the run's."
            ),
            worked=(
                f"ζ' = (c + k<sub>d</sub>)/(2√((k + k<sub>p</sub>)m)) = {g(ZETA_TARGET)} gives k<sub>d</sub> = "
                f"2 × {g(ZETA_TARGET)} × √({g(p.k + p.kp)} × {g(p.m)}) − {g(p.c_nominal)} = {g(kd_t)} N s/m."
            ),
            answers=Answer(quantity="kd", symbol="k<sub>d</sub>", value=kd_t, unit="N s/m", rtol=5e-3),
        )
    )
    return tuple(out)
