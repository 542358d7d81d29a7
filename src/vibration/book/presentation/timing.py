"""Timing for the benchmarks (``make bench``): one median timer and one table layout for every chapter.

Nothing here asserts a time; the tables are for reading, ratios measured side by side in one run.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable


def median_time(fn: Callable[[], object], repeats: int) -> float:
    """Median wall time of ``fn()`` over ``repeats`` calls (one warm-up call first), s."""
    fn()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def table(title: str, rows: list[tuple[str, float, float | None, str]]) -> None:
    """Print ``(case, seconds, ratio or None, target)`` rows under a title."""
    print(f"\n{title}")
    print(f"  {'case':58s} {'median':>12s} {'ratio':>10s}  target")
    for name, t, ratio, target in rows:
        r = f"{ratio:10.1f}x" if ratio is not None else " " * 11
        print(f"  {name:58s} {t * 1e3:9.3f} ms {r}  {target}")
