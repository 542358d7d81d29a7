"""Learning chapter's benchmark: training time of each learner to its default budget (target: under a minute).

``run(quick, median_time=..., table=...)`` times and prints with :mod:`vibration.book.presentation.timing`
unless given others.
"""

from __future__ import annotations

from vibration.book.presentation.timing import median_time, table
from vibration.physics.learning import OscillatorTask, lqr_reference, resonance_task, semi_active_task, train


def cases(quick: bool, median_time=median_time) -> list[tuple[str, float, float | None, str]]:
    """Time ``train`` (ARS and CMA-ES, default budgets) on the default, resonance and semi-active tasks.

    Rows: case, median wall time (s), ratio (ARS on the default task over this case), target.
    """
    repeats = 1 if quick else 3
    base = OscillatorTask()
    ref = lqr_reference(base)
    train(base, seed=0, iterations=1)  # compile the kernels and import cma outside the timings
    train(base, seed=0, method="cma", iterations=1)
    t_ars = median_time(lambda: train(base, seed=0, method="ars"), repeats)
    t_cma = median_time(lambda: train(base, seed=0, method="cma"), repeats)
    ratio_ars = train(base, seed=0, method="ars").expected_cost / ref.expected_cost
    ratio_cma = train(base, seed=0, method="cma").expected_cost / ref.expected_cost
    rows = [
        (f"ARS, default task (J/J* = {ratio_ars:.5f})", t_ars, None, "< 60 s"),
        (f"CMA-ES, default task (J/J* = {ratio_cma:.5f})", t_cma, t_ars / t_cma, "< 60 s"),
    ]
    for name, task in (("resonance force", resonance_task()), ("semi-active damper", semi_active_task())):
        t = median_time(lambda task=task: train(task, seed=0, method="ars"), repeats)
        rows.append((f"ARS, {name}", t, t_ars / t, "< 60 s"))
    return rows


def run(quick: bool, median_time=median_time, table=table) -> None:
    """Time the learners and print the table (``make bench``)."""
    table(
        "learning: train() wall time to its default budget (ratio: ARS on the default task / this case)",
        cases(quick, median_time),
    )
