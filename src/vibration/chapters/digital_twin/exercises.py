"""Chapter 10's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.model import Oscillator
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="Can a twin identify the oscillator from noisy records and detect a loss of stiffness in time?",
    level="advanced",
    objectives=(
        "Compute what a sampled record can resolve: its Nyquist frequency and its frequency resolution.",
        "Compute how a loss of stiffness moves the natural frequency a twin tracks.",
        "Identify m, c and k from a record by least squares and state their intervals.",
        "Explain how a CUSUM test trades detection delay against false alarms.",
    ),
    prerequisites=("chapter 4: ω<sub>n</sub> and ζ from the parameters", "least squares and confidence intervals"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    nyq = 0.5 / p.dt
    df = 1.0 / p.t_record
    healthy = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    damaged = Oscillator(m=p.m, c=p.c_nominal, k=p.k * (1 - p.drop))
    f0, f1 = healthy.natural_frequency / (2 * math.pi), damaged.natural_frequency / (2 * math.pi)
    return (
        SHEET.numerical(
            "10.1",
            text=(
                f"The sensors sample every Δt = {g(p.dt)} s for T<sub>rec</sub> = {g(p.t_record)} s. Compute the "
                "Nyquist frequency "
                "(Hz) and the frequency resolution 1/T<sub>rec</sub> (Hz) of one record."
            ),
            worked=(
                f"f<sub>Nyquist</sub> = 1/(2Δt) = 1/(2 × {g(p.dt)}) = {g(nyq)} Hz; 1/T<sub>rec</sub> = "
                f"1/{g(p.t_record)} = "
                f"{g(df)} Hz. The natural frequency ω<sub>n</sub>/(2π) = {g(f0)} Hz is "
                + ("below" if f0 < nyq else "above")
                + " the Nyquist frequency."
            ),
            answers=(
                Answer(quantity="f_nyquist", symbol="f<sub>Nyquist</sub>", value=nyq, unit="Hz", rtol=2e-3),
                Answer(quantity="df", symbol="1/T<sub>rec</sub>", value=df, unit="Hz", rtol=2e-3),
            ),
        ),
        SHEET.explore(
            "10.2",
            text=(
                f"A sudden loss of {g(100 * p.drop)} % of the stiffness (`-p drop {g(p.drop)}`) moves the natural "
                "frequency. Compute it after the loss (Hz); rerun the chapter with another drop and watch the "
                "detection delay move."
            ),
            worked=(
                f"f<sub>n</sub> = √(k/m)/(2π) = {g(f0)} Hz healthy; after the loss √((1 − {g(p.drop)}) k/m)/(2π) = "
                f"{g(f1)} Hz, a shift of {g(100 * (1 - f1 / f0), 3)} % (half the stiffness loss, for small losses)."
            ),
            answers=Answer(quantity="f_n", symbol="f<sub>n</sub>", value=f1, unit="Hz", rtol=2e-3),
        ),
    )
