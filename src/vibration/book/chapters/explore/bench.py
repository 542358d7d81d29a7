"""Chapter 5's benchmark: a slider update of the live explorer against rebuilding its figure.

``vibration.bench`` finds :func:`run`, which times :func:`benchmark_updates` and prints its medians with the
caller's ``table`` (target: an update within 30 ms); a chapter may not import the publishing layer.
"""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable

from vibration.book.chapters.explore.widget import explorer
from vibration.physics.model import check_int


def benchmark_updates(repeats: int = 30) -> dict:
    """Time a slider update against rebuilding the figure, side by side in one run.

    Each repeat moves a slider of one explorer by one step, alternating the
    forcing frequency (+0.01 rad/s) and the damping (one log step), through
    the widget callback (new artist data, relim/autoscale, Agg draw or blit,
    PNG encoding), then gives a second explorer the same values and times
    what a naive callback would do: build a new figure from scratch, fill it,
    draw it and encode it. Afterwards the first explorer's update is timed
    with the full redraw forced.

    Parameters
    ----------
    repeats : int
        Number of timed updates and of timed rebuilds (>= 1).

    Returns
    -------
    dict
        ``update_median_s`` and ``rebuild_median_s`` (s, medians);
        ``full_draw_median_s`` (s, the update path forced to redraw the
        whole figure); ``full_draw_fraction`` (share of the timed updates
        that had to redraw the background); ``repeats``; ``n_points``.
    """
    repeats = check_int("repeats", repeats, low=1, high=10_000)
    live, naive = explorer(), explorer()
    t_update, t_rebuild, t_full = [], [], []
    full0 = live.n_full_draws
    for i in range(repeats):
        start = time.perf_counter()
        if i % 2 == 0:
            live.omega_slider.value = round(live.omega_slider.value + live.omega_slider.step, 10)
        else:
            live.c_slider.value = 10.0 ** (math.log10(live.c_slider.value) + live.c_slider.step)
        t_update.append(time.perf_counter() - start)
        if live.error is not None:  # pragma: no cover - the sweep stays in range
            raise RuntimeError(live.error)
        naive._active = True  # copy the values without triggering an update
        naive.omega_slider.value, naive.c_slider.value = live.omega_slider.value, live.c_slider.value
        naive._active = False
        start = time.perf_counter()
        naive._rebuild()
        t_rebuild.append(time.perf_counter() - start)
    fraction = (live.n_full_draws - full0) / repeats
    for _ in range(repeats):
        start = time.perf_counter()
        live.update(force_full=True)
        t_full.append(time.perf_counter() - start)
    for ex in (live, naive):
        ex.close()
    return {
        "update_median_s": statistics.median(t_update),
        "rebuild_median_s": statistics.median(t_rebuild),
        "full_draw_median_s": statistics.median(t_full),
        "full_draw_fraction": fraction,
        "repeats": repeats,
        "n_points": live.n_points,
    }


def run(quick: bool, table: Callable) -> None:
    """Time a slider update against rebuilding the figure and print both with ``table`` (target: <= 30 ms)."""
    res = benchmark_updates(repeats=10 if quick else 30)
    upd, rebuild = res["update_median_s"], res["rebuild_median_s"]
    table(
        f"slider update with {res['n_points']} samples (kernel side, Agg draw included)",
        [
            ("update the artists' data", upd, None, "<= 30 ms"),
            ("rebuild the figure each time", rebuild, rebuild / upd, ""),
            ("update forced to redraw the whole figure", res["full_draw_median_s"], None, ""),
        ],
    )
