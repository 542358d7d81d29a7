"""Digital twin (chapter 10): time of the Monte Carlo parts and of the pieces they repeat.

Targets (issue 13): the Monte Carlo parts of the chapter "in well under a minute". Ratios are
measured side by side: the exact FOH response as an IIR filter against the plain state loop, and
the variable-projection identification against ``scipy.optimize.curve_fit`` on the full model.
"""

from __future__ import annotations

import time

import numpy as np
from scipy.optimize import curve_fit

from ...physics.model import Oscillator
from ...physics.twin import (
    detection_study,
    discretize,
    estimate_grid,
    identification_experiment,
    identification_sweep,
    identify,
    sampled_response,
    simulated_test,
)
from ..bench import median_time, table


def _once(fn) -> float:
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def run(quick: bool) -> None:
    osc = Oscillator(1.0, 0.5, 20.0)
    rec = simulated_test(osc, 60.0, 0.02, 0.05, seed=13)
    t, f = rec.t, rec.force
    d = discretize(osc, 0.02)

    def loop():
        z = np.zeros(2)
        for i in range(t.size - 1):
            z = d.phi @ z + d.gamma0 * f[i] + d.gamma1 * f[i + 1]

    reps = 3 if quick else 10
    t_filter = median_time(lambda: sampled_response(osc, t, f), 10 * reps)
    t_loop = median_time(loop, reps)
    t_global = median_time(lambda: identify(t, f, x=rec.x), reps)
    t_local = median_time(lambda: identify(t, f, x=rec.x, search="local"), reps)

    def full(_, m, c, k, x0, v0):
        return sampled_response(Oscillator(m, c, k), t, f, x0, v0).x

    t_cf = median_time(lambda: curve_fit(full, t, rec.x, p0=[1.2, 0.4, 22.0, 0.0, 0.0]), reps)
    table(
        "twin: one 60 s record at 50 Hz (3001 samples)",
        [
            ("exact FOH response (IIR filter)", t_filter, None, ""),
            ("same recursion as a Python state loop", t_loop, t_loop / t_filter, ""),
            ("identify, global search (grid + polish + covariance)", t_global, None, ""),
            ("identify, local search (Levy start), Monte Carlo mode", t_local, None, ""),
            ("curve_fit on the full model from a near start", t_cf, t_cf / t_local, ""),
        ],
    )
    runs, sweep, det = (50, 10, 20) if quick else (200, 30, 100)
    t_mc = _once(lambda: identification_experiment(osc, duration=60.0, noise=0.05, runs=runs, seed=13))
    t_sw = _once(lambda: identification_sweep(osc, runs=sweep, seed=13))
    t_det = _once(lambda: detection_study(osc, osc, 240.0, 0.02, 0.05, 0.0005, 0.1, runs=det, seed=17))
    t_grid = _once(lambda: estimate_grid(osc, seed=13))
    total = t_mc + t_sw + t_det + t_grid
    table(
        "twin: the chapter's Monte Carlo parts (single runs, wall time)",
        [
            (f"coverage: {runs} identifications of 60 s", t_mc, None, ""),
            (f"error scaling: 8 points x {sweep} identifications", t_sw, None, ""),
            (f"detection: 2 faults x {det} healthy + {det} faulty 240 s records", t_det, None, ""),
            ("slider grid: 35 identifications", t_grid, None, ""),
            ("all Monte Carlo parts", total, None, "well under 60 s"),
        ],
    )
