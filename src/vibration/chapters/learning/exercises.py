"""Chapter 11's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.control import lqr
from vibration.physics.model import Oscillator
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="Does a controller learned by trial and error come close to the optimal linear one?",
    level="advanced",
    objectives=(
        "Compute an episode's length in time and in samples per natural period.",
        "Compute the continuous-time LQR gains that a learning controller is scored against.",
        "Compare a learned policy with LQR and with the best passive damper by expected cost.",
        "Explain why a seed-to-seed spread must be reported with a learned result.",
    ),
    prerequisites=("chapter 7: LQR and the closed loop", "expectation and variance of a random cost"),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    plant = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn = plant.natural_frequency
    t_ep = p.n_steps * p.dt
    per = 2 * math.pi / (wn * p.dt)
    res = lqr(plant, 1.0, 1.0, p.r_weight)
    k1, k2 = float(res.K[0]), float(res.K[1])
    return (
        SHEET.numerical(
            "11.1",
            text=(
                f"An episode has {p.n_steps} steps of Δt = {g(p.dt)} s. How long is it (s), and how many steps fall "
                "in one natural period 2π/ω<sub>n</sub>?"
            ),
            worked=(
                f"The episode lasts N Δt = {p.n_steps} × {g(p.dt)} = {g(t_ep)} s. ω<sub>n</sub> = {g(wn)} rad/s, so "
                "2π/ω<sub>n</sub> "
                f"= {g(2 * math.pi / wn)} s holds {g(per)} steps."
            ),
            answers=(
                Answer(quantity="T", symbol="N Δt", value=t_ep, unit="s", rtol=2e-3),
                Answer(quantity="steps", symbol="steps per period", value=per, unit="", rtol=2e-3),
            ),
        ),
        SHEET.explore(
            "11.2",
            text=(
                "The stage cost is x² + v² + q<sub>u</sub> u² with q<sub>u</sub> = "
                f"{g(p.r_weight)} 1/N². Compute the continuous-time LQR gains k<sub>x</sub> (N/m) and k<sub>v</sub> "
                "(N s/m) of u = −k<sub>x</sub> x − k<sub>v</sub> v. Rerun the chapter with ten times the weight "
                f"(`-p r_weight {g(10 * p.r_weight)}`): do the gains rise or fall?"
            ),
            worked=(
                "The Riccati equation S'P + PS − PB q<sub>u</sub>⁻¹ B'P + diag(q<sub>x</sub>, q<sub>v</sub>) = 0 "
                "with the state matrix S = [[0, 1], [−k/m, −c/m]], "
                f"the input B = [0, 1/m]', q<sub>x</sub> = q<sub>v</sub> = 1 and q<sub>u</sub> = {g(p.r_weight)} gives "
                f"K = q<sub>u</sub>⁻¹B'P = [{g(k1)} N/m, {g(k2)} N s/m]. A larger q<sub>u</sub> "
                "makes force dearer: the gains fall."
            ),
            answers=(
                Answer(quantity="k_x", symbol="k<sub>x</sub>", value=k1, unit="N/m", rtol=5e-3, atol=1e-6),
                Answer(quantity="k_v", symbol="k<sub>v</sub>", value=k2, unit="N s/m", rtol=5e-3, atol=1e-6),
            ),
        ),
    )
