"""Chapter 6 (stability and damping as a design choice): the chapter's heaviest computations.

* White-noise Monte Carlo (the paper's light damping, c = 0.1 N s/m, 200 paths): the chapter's
  exact-transition simulation at a fixed number of samples per path, against the same exact
  simulation at the old step (a tenth of the natural period) and against a naive per-step loop
  (Euler-Maruyama, vectorised over paths, at the same fine step). No target: the ratio is read.
* Settling-optimal damping ratio: the closed form against a bounded scalar minimisation of the
  exact settling time (``scipy.optimize.minimize_scalar`` over ``step_metrics``) and a dense sweep.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.optimize import minimize_scalar

from vibration.book.presentation.timing import median_time, table
from vibration.physics.model import Oscillator
from vibration.physics.stability import settling_optimal_zeta, step_metrics, white_noise_monte_carlo
from vibration.physics.stability.random_load import _default_dt

#: A row of a benchmark table: case, median time (s), ratio to the first row (or None), target.
Row = tuple[str, float, float | None, str]


def _euler_maruyama(osc: Oscillator, S0: float, n_paths: int, t_end: float, dt: float, seed: int) -> float:
    """Mean of x^2 after 12 time constants, by the explicit Euler-Maruyama loop a user would write."""
    rng = np.random.default_rng(seed)
    x = np.zeros(n_paths)
    v = np.zeros(n_paths)
    q = math.sqrt(2.0 * math.pi * S0 * dt) / osc.m
    burn = 12.0 * osc.time_constant
    acc, count = 0.0, 0
    for j in range(int(t_end / dt)):
        x, v = x + v * dt, v + (-osc.k * x - osc.c * v) / osc.m * dt + q * rng.standard_normal(n_paths)
        if j * dt >= burn:
            acc += float(np.mean(x * x))
            count += 1
    return acc / max(count, 1)


def run(quick: bool, table: Callable[[str, list[Row]], None] = table) -> None:
    """Time the Monte Carlo and the settling-optimal search against naive alternatives, side by side.

    ``table(title, rows)`` reports each table (default: printed like ``vibration.bench``'s own tables).
    """
    osc, S0 = Oscillator(m=1.0, c=0.1, k=20.0), 0.1
    n_paths = 200
    k = 1 if quick else 3
    tau = osc.time_constant
    t_fast = median_time(lambda: white_noise_monte_carlo(osc, S0, n_paths=n_paths, seed=1), 3 * k)
    t_fine = median_time(lambda: white_noise_monte_carlo(osc, S0, n_paths=n_paths, dt=_default_dt(osc), seed=1), k)
    # the naive loop over a tenth of the window (its cost is linear in the number of steps), scaled by 10
    dt = _default_dt(osc) / 10.0  # explicit Euler needs a step well below the period
    t_em = median_time(lambda: _euler_maruyama(osc, S0, n_paths, 11.2 * tau, dt, 1), 1) * 10
    table(
        f"white-noise Monte Carlo, c = 0.1 N s/m, {n_paths} paths over 112 time constants",
        [
            ("exact transition, 2000 samples per path (chapter)", t_fast, None, ""),
            ("exact transition at a tenth of the period (old default)", t_fine, t_fine / t_fast, ""),
            ("Euler-Maruyama loop, a hundredth of the period (10 x a tenth)", t_em, t_em / t_fast, ""),
        ],
    )
    t_closed = median_time(lambda: settling_optimal_zeta(0.02), 1000 * k)

    def settle(z: float) -> float:
        return step_metrics(Oscillator(m=1.0, c=2.0 * z * math.sqrt(20.0), k=20.0)).settling_time

    t_min = median_time(
        lambda: minimize_scalar(settle, bounds=(0.5, 1.0), method="bounded", options={"xatol": 1e-6}), k
    )
    zetas = np.linspace(0.5, 1.0, 2001)
    t_sweep = median_time(lambda: min(zetas, key=settle), 1)
    table(
        "settling-optimal damping ratio (2 % band)",
        [
            ("closed form |ln b| / sqrt(pi^2 + ln^2 b)", t_closed, None, ""),
            ("bounded minimisation of the exact settling time", t_min, t_min / t_closed, ""),
            ("dense sweep, 2001 ratios", t_sweep, t_sweep / t_closed, ""),
        ],
    )


if __name__ == "__main__":
    run(quick=True)
