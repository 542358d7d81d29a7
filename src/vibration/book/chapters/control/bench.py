"""Chapter 7 (control): the heaviest simulation, the MR-damper frequency sweep, and its neighbours.

Reports the compiled fixed-step RK4 (numba) against the same loop written as a plain Python
callable integrated by ``solve_ivp`` (what a user of :func:`vibration.simulate_controlled`
would write), on a sample of frequencies, and the chapter's other sweeps. No assertions.
``run(quick)`` prints the table (``vibration.bench`` calls it; pass its ``table`` printer to share
the layout); :func:`measure` returns the rows.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from vibration.book.chapters.control.params import Params
from vibration.book.presentation.timing import median_time, table
from vibration.physics.control import (
    SPENCER_1997,
    SPENCER_1997_STROKE,
    semi_active_controller,
    semi_active_sweep,
    simulate_controlled,
)
from vibration.physics.model import Oscillator

Row = tuple[str, float, float | None, str]


def measure(quick: bool) -> tuple[str, list[Row]]:
    """Time the semi-active sweeps at the chapter's default parameters, as the notebook runs them."""
    p = Params()
    osc = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    Y = p.F0 / p.k
    wn = osc.natural_frequency
    ratios = np.unique(np.concatenate([np.geomspace(0.3, 4.0, p.n_sweep), [1.0, np.sqrt(2.0)]]))
    w = ratios * wn
    damper = SPENCER_1997.scaled(Y / SPENCER_1997_STROKE, p.f_mr / SPENCER_1997.yield_force)
    kw = {"c_sky": p.c_sky, "c_min": p.c_sa_min, "c_max": p.c_sa_max}
    reps = 1 if quick else 3
    t_mr = median_time(lambda: semi_active_sweep(osc, "mr", w, Y=Y, damper=damper, **kw), reps)
    t_cl = median_time(lambda: semi_active_sweep(osc, "clipped", w, Y=Y, **kw), reps)
    t_oo = median_time(lambda: semi_active_sweep(osc, "on-off", w, Y=Y, **kw), reps)
    # the same clipped-skyhook steady state by solve_ivp on the Python callable, one frequency, scaled
    ctl = semi_active_controller("clipped", p.c_sky, p.c_sa_min, c_max=p.c_sa_max, Y=Y, omega=wn)
    sigma = (osc.c + p.c_sa_min) / (2.0 * osc.m)  # decay rate of the softest damping the sweep settles with, 1/s
    t_end = 12.0 / sigma + 8 * 2 * np.pi / wn  # settle + measured periods, as the sweep runs them

    def ivp_one():
        simulate_controlled(osc, ctl, base=(Y, wn), t_end=t_end, n_points=2001, rtol=1e-8, atol=1e-10)

    t_ivp = median_time(ivp_one, 1) * w.size
    return (
        f"control: semi-active sweeps over {w.size} frequencies (numba RK4; parallel over frequencies)",
        [
            ("MR damper (modified Bouc-Wen), the chapter's heaviest", t_mr, None, "notebook <= 30 s in all"),
            ("clipped skyhook", t_cl, None, ""),
            ("on-off skyhook", t_oo, None, ""),
            ("clipped skyhook, solve_ivp DOP853 on the callable (scaled)", t_ivp, t_ivp / t_cl, ""),
        ],
    )


def run(quick: bool, table: Callable[[str, list[Row]], None] = table) -> None:
    """Print the chapter's benchmark table."""
    title, rows = measure(quick)
    table(title, rows)
