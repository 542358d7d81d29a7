"""Shared helpers of the control package: input checks, the adaptive solver's work budget, grids."""

from __future__ import annotations

import math

import numpy as np

from ..checks import OverBudget, check_array
from ..model import N_POINTS_MAX, ParameterError, check_int, check_real


def _omegas(omegas, name: str = "omegas") -> np.ndarray:
    return check_array(name, omegas, low=0.0, ndim=(0, 1), unit="rad/s")


def _finite(name: str, value, what: str):
    """Refuse a non-finite result: an overflow is an error, never a silent nan or inf."""
    arr = np.asarray(value)
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} = {value!r}: {what} is not finite (overflow); allowed inputs that keep it finite")
    return value


MAX_NFEV = 250_000

#: Smooth pieces (between switching events) one run of :func:`pid_response` may have.
MAX_SEGMENTS = 20_000

#: Allowed relative tolerances of the adaptive solver (below 100 eps it warns and fails).
RTOL_MIN, RTOL_MAX = 1e-13, 1e-2

#: Samples :func:`pid_linear_response` evaluates with one matrix exponential each (repeated poles).
EXPM_SAMPLES_MAX = 20_000


def _counted(f, budget: list):
    """Wrap ``f`` so that every call spends one unit of ``budget[0]``; :class:`OverBudget` when spent."""

    def g(t, y):
        budget[0] -= 1
        if budget[0] < 0:
            raise OverBudget
        return f(t, y)

    return g


def _work_check(t_end: float, rate: float, rtol: float, what: str) -> None:
    """Refuse up front a window that spans too many of the loop's fastest time scales for DOP853."""
    # DOP853 at rtol 1e-10 needs about 100 evaluations per unit of t * rate on these loops (measured)
    est = 100.0 * t_end * rate * (1e-10 / rtol) ** 0.125
    if not est <= MAX_NFEV:
        raise ParameterError(
            f"t_end = {t_end!r} s spans {t_end * rate:.3g} time scales of the {what} (fastest rate {rate:.3g} 1/s): "
            f"about {est:.3g} right-hand-side evaluations, allowed at most {MAX_NFEV} "
            f"(t_end * rate <= {MAX_NFEV / 100.0 / (1e-10 / rtol) ** 0.125:.3g}); shorten t_end or soften the loop"
        )


def _over_budget(t: float, t_end: float, what: str) -> ParameterError:
    at = f" after t = {t:.6g} s" if math.isfinite(t) else ""
    return ParameterError(
        f"t_end = {t_end!r} s: the {what} used up its budget of {MAX_NFEV} right-hand-side evaluations{at} "
        f"(a stiff loop, a discontinuous controller or a tolerance too tight); allowed at most {MAX_NFEV} "
        "evaluations: shorten t_end or loosen rtol"
    )


def _limit(u_max) -> float:
    if u_max is None:
        return math.inf
    if isinstance(u_max, float) and u_max == math.inf:
        return math.inf
    return check_real("u_max", u_max, low=0.0, low_open=True, unit="N")


def _base(base) -> tuple[float, float]:
    if base is None:
        return 0.0, 0.0
    try:
        Y, w = base
    except (TypeError, ValueError):
        raise ParameterError(f"base = {base!r}: allowed None or (Y in m, omega in rad/s)") from None
    return check_real("Y", Y, low=0.0, unit="m"), check_real("omega", w, low=0.0, unit="rad/s")


def _grid(t_end, n_points) -> np.ndarray:
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    return np.linspace(0.0, t_end, n_points)


def _call(controller, t: float, x: float, v: float) -> float:
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # a non-finite force is refused below
        u = controller(t, x, v)
    try:
        val = float(u)
    except (TypeError, ValueError):
        raise ParameterError(f"controller returned {u!r} at t = {t!r} s: allowed a finite real force in N") from None
    if not math.isfinite(val):
        raise ParameterError(f"controller returned {val!r} at t = {t!r} s: allowed a finite real force in N")
    return val
