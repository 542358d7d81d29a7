"""Chapter 3's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.frequency import settling_time
from vibration.physics.model import Oscillator, SineForce
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="How accurate is the paper's solver, and what does its accuracy cost?",
    level="core",
    objectives=(
        "Compute how many forcing periods and samples per period a simulated window holds.",
        "Explain what sets the error of an adaptive Runge-Kutta solver, and what does not.",
        "Measure a solver's error against the exact solution and read a work-precision diagram.",
        "Compute the 2 % settling time of the forced response from rest.",
    ),
    prerequisites=("chapter 1: the exact solution", "Taylor series and the order of a method"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    periods = p.omega_res * p.t_end / (2 * math.pi)
    dt = p.t_end / (p.n_points - 1)
    per_period = 2 * math.pi / (p.omega_res * dt)
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    out = [
        SHEET.numerical(
            "03.1",
            text=(
                f"The window [0, {g(p.t_end)}] s is sampled at {p.n_points} points and forced at ω = "
                f"{g(p.omega_res)} rad/s. How many forcing periods does it hold, and how many samples fall in one "
                "period?"
            ),
            worked=(
                f"The period is T<sub>f</sub> = 2π/ω = {g(2 * math.pi / p.omega_res)} s, so the window holds "
                "t<sub>end</sub>/T<sub>f</sub> = "
                f"{g(periods)} periods. The spacing is Δt = t<sub>end</sub>/(N − 1) = {g(dt)} s, so one period holds "
                f"T<sub>f</sub>/Δt = {g(per_period)} samples."
            ),
            answers=(
                Answer(quantity="periods", symbol="t<sub>end</sub>/T<sub>f</sub>", value=periods, unit="", rtol=2e-3),
                Answer(quantity="samples", symbol="T<sub>f</sub>/Δt", value=per_period, unit="", rtol=2e-3),
            ),
        ),
        SHEET.conceptual(
            "03.2",
            text=(
                "The chapter asks SciPy's RK45 for its solution at more output times. What does that change in "
                "the error of the solution at a given time?"
            ),
            worked=(
                "The step sizes are chosen from the relative and absolute tolerances alone; the output times are "
                "filled by the method's interpolant between the steps. More output samples neither shorten the steps "
                "nor lower the error: only tighter tolerances do."
            ),
            options={
                "a": "nothing: the tolerances set the steps, the output times are interpolated",
                "b": "it falls in proportion to the number of samples",
                "c": "it grows, because more steps add more rounding",
            },
            correct="a",
        ),
    ]
    if p.c_nominal > 0:
        ts = settling_time(nom, SineForce(F0=p.F0, omega=p.omega_res))
        out.append(
            SHEET.numerical(
                "03.3",
                text=(
                    f"Compute the 2 % settling time (s) of the nominal damping c = {g(p.c_nominal)} N s/m forced at "
                    f"ω = {g(p.omega_res)} rad/s from rest, and the time constant 2m/c it is a multiple of."
                ),
                worked=(
                    f"τ = 2m/c = {g(2 * p.m / p.c_nominal)} s (the envelope e<sup>−t/τ</sup>). The "
                    "transient's envelope "
                    f"falls to 2 % of the steady amplitude at t<sub>s</sub> = {g(ts)} s, "
                    f"that is {g(ts / nom.time_constant, 3)} "
                    "time constants."
                ),
                answers=(
                    Answer(quantity="t_s", symbol="t<sub>s</sub>", value=ts, unit="s", rtol=1e-2),
                    Answer(quantity="tau", symbol="τ", value=nom.time_constant, unit="s", rtol=1e-2),
                ),
            )
        )
    out.append(
        SHEET.explore(
            "03.4",
            text=(
                f"Rerun the chapter with a window twice as long (`-p t_end {g(2 * p.t_end)}`) and the same number of "
                "samples. How many samples fall in one forcing period now?"
            ),
            worked=(
                f"Δt doubles to {g(2 * p.t_end / (p.n_points - 1))} s, so one period "
                f"T<sub>f</sub> = {g(2 * math.pi / p.omega_res)} s "
                f"holds {g(per_period / 2)} samples, half as many; the solver's own steps do not change."
            ),
            answers=Answer(quantity="samples", symbol="T<sub>f</sub>/Δt", value=per_period / 2, unit="", rtol=2e-3),
        )
    )
    return tuple(out)
