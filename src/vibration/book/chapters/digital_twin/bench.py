"""Digital twin (chapter 10): time of the Monte Carlo parts and of the pieces they repeat.

Targets (issue 13): the chapter's Monte Carlo parts in well under a minute. Ratios are measured side by side:
the exact FOH response as an IIR filter against the plain state loop, the variable-projection identification
against ``scipy.optimize.curve_fit`` on the full model, and the chapter's batch identification
(:mod:`vibration.book.chapters.digital_twin.montecarlo`) against one :func:`identify` call per record.
``run(quick)`` prints its tables; it imports nothing from the publishing layer.
"""

from __future__ import annotations

import time

import numpy as np
from scipy.optimize import curve_fit

from vibration.book.chapters.digital_twin import montecarlo
from vibration.book.presentation.timing import median_time, table
from vibration.physics.model import Oscillator
from vibration.physics.twin import (
    detection_study,
    discretize,
    estimate_grid,
    identify,
    sampled_response,
    simulated_test,
)


def _once(fn) -> float:
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def run(quick: bool) -> None:
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    rec = simulated_test(osc, 60.0, 0.02, noise=0.05, seed=13)
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
        return sampled_response(Oscillator(m=m, c=c, k=k), t, f, x0=x0, v0=v0).x

    t_cf = median_time(lambda: curve_fit(full, t, rec.x, p0=[1.2, 0.4, 22.0, 0.0, 0.0]), reps)
    table(
        "twin: one 60 s record at 50 Hz (3001 samples)",
        [
            ("exact FOH response (IIR filter)", t_filter, None, ""),
            ("same recursion as a Python state loop", t_loop, t_loop / t_filter, ""),
            ("identify, global search (grid + polish + covariance)", t_global, None, ""),
            ("identify, local search (Levy start)", t_local, None, ""),
            ("curve_fit on the full model from a near start", t_cf, t_cf / t_local, ""),
        ],
    )
    runs, det = (100, 20) if quick else (500, 100)
    tt, force, clean = montecarlo.design(osc, 60.0, 0.02, seed=13, band=(0.1, 2.0), rms=2.0)
    sd = 0.05 * float(np.sqrt(np.mean(clean**2)))
    t_batch = _once(lambda: montecarlo.experiment(osc, tt, force, clean=clean, noise_sd=sd, runs=runs, seed=13,
                                                  stream=0, noise=0.05))  # fmt: skip
    t_one = _once(lambda: [identify(tt, force, x=clean + sd * np.random.default_rng([13, 0, i]).standard_normal(
        tt.size), search="local") for i in range(20)]) * runs / 20  # fmt: skip
    t_det = _once(
        lambda: detection_study(osc, osc, 240.0, dt=0.02, noise=0.05, decline_rate=0.0005, drop=0.1, runs=det, seed=17)
    )
    t_grid = _once(lambda: estimate_grid(osc, seed=13))
    table(
        "twin: the chapter's Monte Carlo parts (single runs, wall time)",
        [
            (f"coverage: {runs} identifications of 60 s, batch (with residual tests)", t_batch, None, ""),
            (f"same, one identify() per record (20 timed, scaled to {runs})", t_one, t_one / t_batch, ""),
            (f"detection: 2 faults x {det} healthy + {det} faulty 240 s records", t_det, None, ""),
            ("slider grid: 35 identifications", t_grid, None, ""),
        ],
    )
