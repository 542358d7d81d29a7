"""Chapter 9's benchmark: a 200-frequency stepped sweep each way, compiled Dormand-Prince against SciPy's RK45.

Both integrate the same method with the same error control and tolerance (rtol 1e-8) and the same
steady criterion; the SciPy sweep calls ``solve_ivp(method="RK45")`` once per forcing period. The
SciPy sweep is timed on a sample of the frequencies (each started from the compiled sweep's state
before it, so it does the same work) and scaled to 200.

The timing and printing helpers come from the caller (``vibration.book.publishing.bench``: ``median_time`` and
``table``), since a chapter may not import the publishing layer.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from vibration.book.chapters.duffing.params import SCHEMA
from vibration.physics.duffing import Duffing, frequency_sweep


def run(quick: bool, median_time: Callable, table: Callable) -> None:
    """Time both sweeps at the chapter's defaults and print them with ``table`` (ratios side by side)."""
    p = SCHEMA.defaults()
    d, F0 = Duffing(m=p["m"], c=p["c_nominal"], k=p["k"], k3=p["k3_hard"]), p["F0"]  # kg, N s/m, N/m, N/m^3; N
    n_w = p["n_sweep"]
    w = np.linspace(p["omega_sweep_min"], p["omega_sweep_max"], n_w)  # rad/s

    def both():
        frequency_sweep(d, F0, w, direction="up")
        frequency_sweep(d, F0, w, direction="down")

    t_compiled = median_time(both, 3 if quick else 7)
    ref_up, ref_down = frequency_sweep(d, F0, w, direction="up"), frequency_sweep(d, F0, w, direction="down")
    rng = np.random.default_rng(0)
    n = 4 if quick else 16
    picks = rng.choice(np.arange(1, n_w), size=n, replace=False)

    def scipy_sample():
        for ref in (ref_up, ref_down):
            order = np.argsort(w) if ref.direction == "up" else np.argsort(w)[::-1]
            for i in picks:  # the i-th step of the sweep, from the state the step before ended in
                prev, cur = order[i - 1], order[i]
                frequency_sweep(d, F0, [w[cur]], direction=ref.direction, x0=float(ref.x_end[prev]),
                                v0=float(ref.v_end[prev]), integrator="scipy")  # fmt: skip

    scale = n_w / n
    t_scipy = median_time(scipy_sample, 1) * scale
    table(
        f"Duffing sweep, {n_w} frequencies up and down, rtol 1e-8 (SciPy timed on {n} steps each way, "
        f"scaled x{scale:g})",
        [
            ("compiled Dormand-Prince 5(4) (numba)", t_compiled, None, ""),
            ("solve_ivp RK45, one call per period", t_scipy, t_scipy / t_compiled, "(ratio)"),
        ],
    )
