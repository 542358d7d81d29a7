"""Chapter 7 (control): the heaviest simulation, the MR-damper frequency sweep, and its neighbours.

Reports the compiled fixed-step RK4 (numba) against the same loop written as a plain Python
callable integrated by ``solve_ivp`` (what a user of :func:`vibration.simulate_controlled`
would write), on a sample of frequencies, and the chapter's other sweeps. No assertions.
"""

from __future__ import annotations

import numpy as np

from ...physics.control import (
    SPENCER_1997,
    SPENCER_1997_STROKE,
    semi_active_controller,
    semi_active_sweep,
    simulate_controlled,
)
from ...physics.model import Oscillator
from ..bench import median_time, table


def run(quick: bool) -> None:
    """Time the semi-active sweeps of the chapter (41 + 2 frequencies, as the notebook runs them)."""
    osc = Oscillator(1.0, 0.5, 20.0)
    Y = 5.0 / 20.0
    wn = osc.natural_frequency
    ratios = np.unique(np.concatenate([np.geomspace(0.3, 4.0, 41), [1.0, np.sqrt(2.0)]]))
    w = ratios * wn
    damper = SPENCER_1997.scaled(Y / SPENCER_1997_STROKE, 10.0 / SPENCER_1997.yield_force)
    kw = {"c_sky": 8.0, "c_min": 0.5, "c_max": 15.0}
    reps = 1 if quick else 3
    t_mr = median_time(lambda: semi_active_sweep(osc, "mr", w, Y, damper=damper, **kw), reps)
    t_cl = median_time(lambda: semi_active_sweep(osc, "clipped", w, Y, **kw), reps)
    t_oo = median_time(lambda: semi_active_sweep(osc, "on-off", w, Y, **kw), reps)
    # the same clipped-skyhook steady state by solve_ivp on the Python callable, one frequency, scaled
    ctl = semi_active_controller("clipped", 8.0, 0.5, 15.0, Y, wn)
    t_end = 12.0 / 0.5 + 8 * 2 * np.pi / wn  # settle + measured periods, as the sweep runs them

    def ivp_one():
        simulate_controlled(osc, ctl, base=(Y, wn), t_end=t_end, n_points=2001, rtol=1e-8, atol=1e-10)

    t_ivp = median_time(ivp_one, 1) * w.size
    table(
        f"control: semi-active sweeps over {w.size} frequencies (numba RK4; parallel over frequencies)",
        [
            ("MR damper (modified Bouc-Wen), the chapter's heaviest", t_mr, None, "notebook <= 30 s in all"),
            ("clipped skyhook", t_cl, None, ""),
            ("on-off skyhook", t_oo, None, ""),
            ("clipped skyhook, solve_ivp DOP853 on the callable (scaled)", t_ivp, t_ivp / t_cl, ""),
        ],
    )
