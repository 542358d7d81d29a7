"""Chapter 12's exercises: objectives, prerequisites and exercises whose answers come from the folder's own data.

Every answer is computed by the package from the run's ``lab_data`` folder and parameters (no answer is typed in),
so a run on another laboratory's wheel gets exercises about that wheel.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.chapters.real_oscillator.params import Params
from vibration.chapters.real_oscillator.study import driven_run, lab_folder
from vibration.physics.lab import damping_vs_amplitude, load_lab_data
from vibration.physics.model import ParameterError
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.narrative import g

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="Which of the paper's claims survive on a real, driven and damped torsional oscillator?",
    level="advanced",
    objectives=(
        "Compute the half-period amplitude, the loss per half period and the equivalent damping ratio from the "
        "extrema of a measured free decay.",
        "Estimate a Coulomb friction angle from the energy balance of a free decay (2Δ lost per half period).",
        "Explain why two damping settings must be compared at matched amplitude when the damping depends on it.",
        "Judge whether a driven run is steady from its late drift, with a tolerance fixed beforehand.",
    ),
    prerequisites=(
        "the free and forced responses of the linear oscillator (chapters 1 and 4)",
        "the logarithmic decrement",
        "least squares and standard errors",
    ),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()

#: The tolerance of the explore exercise's ``-p`` run (a looser steadiness test than the default).
EXPLORE_TOLERANCE = 0.05


def exercises(params: Params | None = None) -> tuple[Exercise, ...]:
    """The chapter's exercises for one parameter record (answers from the folder ``params.lab_data``)."""
    params = params or Params()
    data = load_lab_data(lab_folder(params.lab_data))
    free = data.select(kind="free")
    if not free:
        raise ParameterError("lab_data: no free decay in the manifest, so no exercise can be set")
    run = free[0]
    curve = damping_vs_amplitude(run.t, run.angle)
    if curve.n < 3:
        raise ParameterError(f"lab_data: free decay {run.file} run {run.run} has fewer than 3 half periods")
    x0, loss0, z0 = float(curve.amplitude[0]), float(curve.loss[0]), float(curve.zeta_eq[0])
    x1 = x0 - loss0
    delta = math.log(x0 / x1)
    out = [
        SHEET.numerical(
            "12.1",
            text=(
                f"In the first free decay of the folder (file `{run.file}`, run {run.run}, brake {run.brake}) "
                "the first "
                f"half-period amplitude after the release is X<sub>0</sub> = {g(x0, 5)} rad and the next is "
                f"X<sub>1</sub> = {g(x1, 5)} rad. Compute the loss per half period and the equivalent damping ratio "
                "ζ<sub>eq</sub>."
            ),
            worked=(
                f"Loss: X<sub>0</sub> − X<sub>1</sub> = {g(loss0, 4)} rad. Decrement "
                f"δ = ln(X<sub>0</sub>/X<sub>1</sub>) = {g(delta, 4)}; ζ<sub>eq</sub> = δ/√(π² + δ²) = {g(z0, 4)}."
            ),
            answers=(
                Answer(quantity="loss", symbol="loss per half period", value=loss0, unit="rad", rtol=1e-3, atol=1e-6),
                Answer(quantity="zeta_eq", symbol="ζ<sub>eq</sub>", value=z0, unit="", rtol=1e-3, atol=1e-6),
            ),
        )
    ]
    losses = np.concatenate(
        [damping_vs_amplitude(r.t, r.angle).loss for r in data.select(kind="free", brake=run.brake)]
    )
    med = float(np.median(losses))
    out.append(
        SHEET.numerical(
            "12.2",
            text=(
                f"The free decays with the brake {run.brake} lose a median {g(med, 4)} rad of half-period amplitude "
                "per half period. If dry friction alone caused the loss, what would its friction angle Δ be?"
            ),
            worked=(
                "Over a half period dry friction dissipates the energy of a constant loss of 2Δ in amplitude, whatever "
                f"the amplitude, so Δ = {g(med, 4)}/2 = {g(med / 2.0, 4)} rad."
            ),
            answers=Answer(quantity="friction", symbol="Δ", value=med / 2.0, unit="rad", rtol=1e-3),
        )
    )
    driven = data.select(kind="driven")
    if driven:
        loose = Params.from_values({**params.as_dict(), "tolerance": EXPLORE_TOLERANCE})
        base = [d for d in (driven_run(r, params) for r in driven) if d is not None]
        wide = [d for d in (driven_run(r, loose) for r in driven) if d is not None]
        n0, n1 = sum(d.steady.steady for d in base), sum(d.steady.steady for d in wide)
        out.append(
            SHEET.explore(
                "12.3",
                text=(
                    f"With the tolerance {g(100 * params.tolerance, 2)} %, {n0} of the {len(base)} driven runs are "
                    f"steady. Run the chapter with `-p tolerance {EXPLORE_TOLERANCE}`: how many driven runs count as "
                    "steady then, and why must the tolerance be fixed before looking at the runs?"
                ),
                worked=(
                    f"The late drift of each run does not change; only the threshold does: {n1} runs pass at "
                    f"{g(100 * EXPLORE_TOLERANCE, 2)} %. Choosing the tolerance after seeing the drifts would let the "
                    "analyst decide which runs count, and so what the steady amplitudes are."
                ),
                answers=(
                    Answer(
                        quantity="steady_runs",
                        symbol="number of steady runs",
                        value=float(n1),
                        unit="",
                        rtol=0.0,
                        atol=0.5,
                    ),
                ),
            )
        )
    out.append(
        SHEET.conceptual(
            "12.4",
            text=(
                "Braked decays that start at large amplitudes are compared with unbraked ones that start at small "
                "amplitudes, and the braked ones show more damping. Why is that not yet evidence for the brake?"
            ),
            worked=(
                "The equivalent damping of the wheel depends on the amplitude (dry friction dominates at small "
                "amplitudes, a loss growing with amplitude at large ones), so a difference between runs at different "
                "amplitudes mixes the brake with the amplitude. Only a comparison over an amplitude band both cover "
                "isolates the brake."
            ),
            options={
                "a": "Because the damping depends on the amplitude, so runs must be compared at matched amplitude.",
                "b": "Because braked runs always have a lower natural frequency.",
                "c": "Because the encoder's step is too coarse to measure damping.",
            },
            correct="a",
        )
    )
    return tuple(out)
