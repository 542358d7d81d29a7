"""The two integrators of a stepped Duffing sweep: a compiled Dormand-Prince 5(4) kernel and its SciPy twin.

Both take the same arguments and fill the same output arrays: the sweep's frequencies in order, whole
forcing periods at each until the stroboscopic state is steady (SciPy's RK45 tableau and error control).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ..checks import OverBudget
from .model import _Counted

__all__: list[str] = []

# ------------------------------------------------------------------------------ compiled kernel


@functools.cache
def _sweep_kernel():
    """The compiled sweep integrator (:mod:`._sweep_kernels`, cached on disk); numba is imported lazily."""
    from ._sweep_kernels import sweep_kernel

    return sweep_kernel


def _sweep_scipy(args: tuple, outs: tuple, max_steps: int) -> tuple[int, int]:
    """The sweep of the compiled kernel with ``solve_ivp(method="RK45")``, one period per call.

    ``args`` and ``outs`` are the kernel's arguments and output arrays in its order (see :func:`_sweep_kernel`).
    Returns ``(status, j)`` as the kernel: status 1 when about ``max_steps`` steps (counted as
    right-hand-side evaluations / 6) are spent, at frequency j.
    """
    from scipy.integrate import solve_ivp

    m, c, k, k3, F0, omegas, x0, v0, rtol, atol, steady_tol, min_periods, max_periods, blow_up = args
    amp, xmax_out, xmin_out, steady, periods, xs, vs, nsteps = outs

    x, v = x0, v0
    budget = _Counted(None, 6 * max_steps)
    for j, w in enumerate(omegas):
        T = 2.0 * math.pi / w

        def rhs(t, y, w=w):
            budget.calls += 1
            if budget.calls > budget.limit:
                raise OverBudget
            return (y[1], (F0 * math.cos(w * t) - c * y[1] - k * y[0] - k3 * y[0] ** 3) / m)

        def turning(t, y):
            return y[1]

        d_prev, ok_prev, rho_prev, done, escaped, n, steps = -1.0, False, 1.0, False, False, 0, 0
        xmax = xmin = x
        while n < max_periods and not done:
            try:
                with np.errstate(over="ignore", invalid="ignore"):
                    sol = solve_ivp(
                        rhs, (0.0, T), (x, v), method="RK45", rtol=rtol, atol=atol, events=turning, max_step=T / 16
                    )
            except OverBudget:
                nsteps[j], periods[j] = steps, n
                return 1, j
            steps += sol.t.size - 1
            if sol.status != 0 or not np.all(np.isfinite(sol.y[:, -1])) or np.max(np.abs(sol.y[0])) > blow_up:
                escaped = True
                break
            xe = sol.y_events[0][:, 0] if sol.y_events[0].size else np.empty(0)
            allx = np.concatenate([sol.y[0], xe])
            xmax, xmin = float(allx.max()), float(allx.min())
            px, pv = x, v
            x, v = float(sol.y[0, -1]), float(sol.y[1, -1])
            n += 1
            dd = math.hypot(x - px, (v - pv) / w)
            scale = max(0.5 * (xmax - xmin), atol)
            rho = dd / d_prev if d_prev > 0 else (0.0 if dd == 0 else 1.0)
            r = max(rho, rho_prev)
            ok = dd == 0.0 or (r < 1.0 and dd * max(1.0, r / (1.0 - r)) <= steady_tol * scale)
            done = ok and ok_prev and n >= min_periods
            d_prev, ok_prev, rho_prev = dd, ok, rho
        nsteps[j], periods[j] = steps, n
        if escaped:
            amp[j] = xmax_out[j] = xmin_out[j] = xs[j] = vs[j] = math.nan
            steady[j] = False
            x, v = 0.0, 0.0
        else:
            amp[j], xmax_out[j], xmin_out[j], steady[j], xs[j], vs[j] = 0.5 * (xmax - xmin), xmax, xmin, done, x, v
    return 0, len(omegas)
