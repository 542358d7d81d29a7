"""Chapter 12's objectives, prerequisites and exercises, whose answers come from the folder's own data.

The words are in ``exercises.toml``; :func:`values` computes the numbers they name from the run's ``lab_data``
folder and parameters (no answer is typed in), so a run on another laboratory's wheel gets exercises about
that wheel.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.real_oscillator.params import Params
from vibration.book.chapters.real_oscillator.study import driven_run, lab_folder
from vibration.book.presentation.exercises import ChapterExercises
from vibration.book.presentation.narrative import g
from vibration.physics.lab import damping_vs_amplitude, load_lab_data
from vibration.physics.model import ParameterError

#: The tolerance of the explore exercise's ``-p`` run (a looser steadiness test than the default).
EXPLORE_TOLERANCE = 0.05


def values(params: Params) -> dict[str, object]:
    """The numbers the sheet's templates name, for ``params`` (from the folder ``params.lab_data``)."""
    data = load_lab_data(lab_folder(params.lab_data))
    free = data.select(kind="free")
    if not free:
        raise ParameterError("lab_data: no free decay in the manifest, so no exercise can be set")
    run = free[0]
    curve = damping_vs_amplitude(run.t, run.angle)
    if curve.n < 3:
        raise ParameterError(f"lab_data: free decay {run.file} run {run.run} has fewer than 3 half periods")
    x0, loss = float(curve.amplitude[0]), float(curve.loss[0])
    losses = np.concatenate(
        [damping_vs_amplitude(r.t, r.angle).loss for r in data.select(kind="free", brake=run.brake)]
    )
    median = float(np.median(losses))
    driven = data.select(kind="driven")
    out = {
        **params.as_dict(),
        "file": run.file,
        "run": run.run,
        "brake": run.brake,
        "x0": x0,
        "x1": x0 - loss,
        "loss": loss,
        "delta": math.log(x0 / (x0 - loss)),
        "zeta_eq": float(curve.zeta_eq[0]),
        "median_loss": median,
        "friction": median / 2.0,
        "driven": bool(driven),
    }
    if driven:
        loose = Params.from_values({**params.as_dict(), "tolerance": EXPLORE_TOLERANCE})
        base = [d for d in (driven_run(r, params) for r in driven) if d is not None]
        wide = [d for d in (driven_run(r, loose) for r in driven) if d is not None]
        n_loose = sum(d.steady.steady for d in wide)
        out |= {
            "tolerance_percent": 100 * params.tolerance,
            "n_steady": sum(d.steady.steady for d in base),
            "n_driven": len(base),
            "explore_tolerance": EXPLORE_TOLERANCE,
            "explore_tolerance_percent": 100 * EXPLORE_TOLERANCE,
            "n_steady_loose": n_loose,
            "steady_runs": float(n_loose),
        }
    return out


exercises = ChapterExercises.read(__package__, Params, values, number=g)
SHEET = exercises.sheet
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()
