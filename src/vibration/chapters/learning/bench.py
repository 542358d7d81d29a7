"""Learning chapter's benchmark: training time of each learner to its default budget (target: under a minute).

``run(quick, median_time=..., table=...)`` takes the report's timing and printing helpers
(``vibration.publishing.bench.median_time`` and ``table``) so that the chapter does not import the
publishing layer; without them it uses the plain versions below.
"""

from __future__ import annotations

import statistics
import time

from vibration.physics.learning import OscillatorTask, lqr_reference, resonance_task, semi_active_task, train


def _median_time(fn, repeats: int) -> float:
    """Median wall time of ``fn()`` over ``repeats`` calls (one warm-up call first), s."""
    fn()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def _table(title: str, rows: list[tuple[str, float, float | None, str]]) -> None:
    print(f"\n{title}")
    for name, t, ratio, target in rows:
        r = f"{ratio:10.1f}x" if ratio is not None else " " * 11
        print(f"  {name:58s} {t * 1e3:9.3f} ms {r}  {target}")


def cases(quick: bool, median_time=_median_time) -> list[tuple[str, float, float | None, str]]:
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


def run(quick: bool, median_time=_median_time, table=_table) -> None:
    """Time the learners and print the table (``make bench``)."""
    table(
        "learning: train() wall time to its default budget (ratio: ARS on the default task / this case)",
        cases(quick, median_time),
    )
