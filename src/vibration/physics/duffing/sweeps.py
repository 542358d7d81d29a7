"""Stepped frequency sweeps of the Duffing oscillator by time integration, and their jumps.

:func:`frequency_sweep` steps the forcing frequency up or down and integrates whole forcing periods
with a compiled Dormand-Prince 5(4) pair (SciPy's RK45 tableau and error control, numba) until the
stroboscopic state is steady; :func:`locate_jump` narrows a jump by re-sweeping its bracket.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_derived
from ..model import ParameterError, check_int, check_real
from .model import (
    MAX_SCIPY_SWEEP_STEPS,
    MAX_SWEEP_STEPS,
    XREF_MIN,
    Duffing,
    _check_damped,
    _check_duffing,
    _check_scales,
    _linear_rate,
    _rates,
    _real_array,
    _x_ref,
)
from .sweep_integrators import _sweep_kernel, _sweep_scipy

# ------------------------------------------------------------------------------- frequency sweeps


@dataclass(frozen=True, kw_only=True)
class SweepResult:
    """Steady responses of a stepped frequency sweep, aligned with the frequencies given."""

    omega: np.ndarray  # forcing frequencies, rad/s (in the order given)
    amplitude: np.ndarray  # half the peak-to-peak x over the last period, m (nan if the mass escaped)
    x_max: np.ndarray  # largest x over the last period, m
    x_min: np.ndarray  # smallest x over the last period, m
    steady: np.ndarray  # whether the steady criterion was met before max_periods
    periods: np.ndarray  # forcing periods integrated at each frequency
    x_end: np.ndarray  # stroboscopic state at the end (phase 0 of the forcing), m
    v_end: np.ndarray  # ..., m/s
    direction: str  # "up" or "down"
    n_steps: np.ndarray  # accepted integrator steps at each frequency

    def jumps(self, threshold: float = 0.25) -> list[tuple[float, float, float, float]]:
        """Jumps between consecutive steps of the sweep (in sweep order).

        A jump is a change of amplitude larger than ``threshold`` times the larger of the
        two. Returns ``(omega_before, omega_after, A_before, A_after)`` tuples, rad/s and m.
        """
        order = np.argsort(self.omega, kind="stable")
        if self.direction == "down":
            order = order[::-1]
        out = []
        for i, j in zip(order[:-1], order[1:], strict=True):
            a, b = self.amplitude[i], self.amplitude[j]
            if np.isfinite(a) and np.isfinite(b) and abs(b - a) > threshold * max(a, b):
                out.append((float(self.omega[i]), float(self.omega[j]), float(a), float(b)))
        return out

    @property
    def escaped(self) -> np.ndarray:
        """Whether the mass escaped (softening spring past its barrier) at each frequency: amplitude ``nan`` there."""
        return ~np.isfinite(self.amplitude)


def _check_omegas(omegas) -> np.ndarray:
    w = _real_array("omegas", omegas, unit="rad/s", max_size=1_000_000).reshape(-1)
    if np.any(w <= 0):
        raise ParameterError(
            f"omegas = {omegas!r:.60} is out of range: allowed non-empty, every omega > 0 rad/s, finite"
        )
    return w


def _sweep_work(d: Duffing, F0: float, ws: np.ndarray, x0: float, min_periods: int, max_steps: int, name: str) -> None:
    """Refuse up front a sweep whose first ``min_periods`` periods alone need more than ``max_steps`` steps.

    An explicit Runge-Kutta pair needs ``h lambda`` within its stability interval (about 3.3
    for Dormand-Prince 5(4)), ``lambda`` the fastest rate of the linearised oscillator, and at
    least 16 steps per period (its largest step).
    """
    lam = _linear_rate(d, max(abs(x0), _x_ref(d, F0) if F0 > 0 else 0.0))
    periods = 2.0 * np.pi / ws
    with np.errstate(over="ignore"):
        need = float(np.sum(min_periods * np.maximum(16.0, periods * lam / 3.3)))
    if not need <= max_steps:
        w_min = float(np.min(ws))
        raise ParameterError(
            f"{name} needs at least {need:.3g} integrator steps ({min_periods} forcing periods at each of "
            f"{ws.size} frequencies, the lowest omega = {w_min:.3g} rad/s with period {2 * np.pi / w_min:.3g} s, "
            f"step <= 3.3/lambda for the fastest rate lambda = {lam:.3g} 1/s: {_rates(d)}), more than "
            f"max_steps = {max_steps}: allowed fewer frequencies, higher omega or a less stiff oscillator "
            "(smaller c/m, k/m)"
        )


def frequency_sweep(
    duffing: Duffing,
    F0: float,
    omegas,
    *,
    direction: str,
    x0: float = 0.0,
    v0: float = 0.0,
    rtol: float = 1e-8,
    atol: float | None = None,
    steady_tol: float = 1e-6,
    max_periods: int = 5000,
    integrator: str = "compiled",
    max_steps: int | None = None,
) -> SweepResult:
    """Stepped frequency sweep by time integration, each step from the previous steady state.

    The frequencies are visited in ascending order (``"up"``) or descending (``"down"``);
    the first starts from ``(x0, v0)`` and each next one from the state the previous one
    ended in, at phase 0 of ``F0 cos(omega t)``. Whole forcing periods are integrated
    until the stroboscopic state ``P_n = (x, v/omega)`` is steady: with ``d_n = |P_n -
    P_{n-1}|`` and ``r`` the larger of the last two ratios ``d_n/d_{n-1}``, the geometric
    estimate of the remaining drift ``d_n max(1, r/(1-r))`` must stay below ``steady_tol``
    times the amplitude for two consecutive periods (``r < 1``). The amplitude is half the
    peak-to-peak displacement over the last period, its extrema located inside the steps
    by quintic Hermite interpolation. A frequency that does not settle within
    ``max_periods`` (near a fold, subharmonic or chaotic motion) is flagged ``steady =
    False``; a mass that escapes (softening spring past its barrier) gives ``nan`` and the
    next frequency starts from rest.

    Parameters
    ----------
    duffing : Duffing
        The oscillator (c > 0).
    F0 : float
        Force amplitude, N (>= 0).
    omegas : array_like
        Forcing frequencies, rad/s (> 0), in any order; results are aligned with them.
    direction : {"up", "down"}
        Sweep direction.
    x0, v0 : float
        Initial displacement (m) and velocity (m/s) at the first frequency.
    rtol : float
        Relative tolerance of the integrator (1e-13 to 1e-2).
    atol : float, optional
        Absolute tolerance, m and m/s; default ``rtol`` times the static deflection ``F0/k``.
    steady_tol : float
        Steady criterion, relative to the amplitude (1e-12 to 1e-1).
    max_periods : int
        Most periods integrated per frequency (3 to 10^6).
    integrator : {"compiled", "scipy"}
        The compiled Dormand-Prince 5(4) (numba) or ``scipy.integrate.solve_ivp`` with
        RK45 one period at a time (extrema from its events): the same method and error
        control, for checking and timing.
    max_steps : int, optional
        Work budget: most integrator steps (accepted and rejected, all frequencies together);
        default ``MAX_SWEEP_STEPS`` (compiled, a few seconds) or ``MAX_SCIPY_SWEEP_STEPS``
        (scipy). A sweep that clearly needs more (a stiff oscillator, c/m or k/m large
        against omega, or a very low omega) is refused before it starts; one that spends the
        budget stops with a :class:`ParameterError` naming the frequency it reached.

    Returns
    -------
    SweepResult
        ``escaped`` flags the frequencies where the mass escaped (amplitude ``nan``).

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> w = np.linspace(4.6, 5.4, 9)
    >>> up, down = frequency_sweep(d, 5.0, w, direction="up"), frequency_sweep(d, 5.0, w, direction="down")
    >>> np.round(up.amplitude, 2)       # m
    array([1.53, 1.65, 1.76, 1.86, 1.95, 1.97, 0.74, 0.63, 0.55])
    >>> np.round(down.amplitude, 2)     # m
    array([1.53, 1.65, 1.76, 1.86, 1.95, 0.94, 0.74, 0.63, 0.55])
    >>> bool(up.steady.all() and down.steady.all())
    True
    """
    d, F0, w, x0, v0, rtol, xr = _sweep_args(duffing, F0, omegas, direction, x0, v0, rtol)
    atol, steady_tol, max_periods, max_steps = _sweep_controls(
        rtol, xr, atol, steady_tol, max_periods, integrator, max_steps
    )
    _sweep_work(d, F0, w, x0, 3, max_steps, "frequency_sweep")
    order = np.argsort(w, kind="stable")
    if direction == "down":
        order = order[::-1]
    ws = np.ascontiguousarray(w[order])
    outs = _run_sweep(d, F0, ws, x0, v0, rtol, atol, steady_tol, max_periods, xr, integrator, max_steps)
    return _sweep_result(w, order, outs, direction)


def _sweep_args(duffing, F0, omegas, direction, x0, v0, rtol):
    """The checked model and start of :func:`frequency_sweep`: ``(d, F0, w, x0, v0, rtol, xr)``, xr its scale (m)."""
    d = _check_duffing(duffing)
    _check_damped(d)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = _check_omegas(omegas)
    if not isinstance(direction, str) or direction not in ("up", "down"):
        raise ParameterError(f"direction = {direction!r:.60} is not valid: allowed 'up' or 'down'")
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    rtol = check_real("rtol", rtol, low=1e-13, high=1e-2)
    xr = _x_ref(d, F0) if F0 > 0 else max(abs(x0), 1.0)
    _check_scales(d, F0, x0, v0, xr)
    check_derived(
        "the longest forcing period 2π/min(omegas) (s)", 2.0 * math.pi / max(float(np.min(w)), 1e-320),
        inputs={"min(omegas)": float(np.min(w))}, allowed="omegas >= 1e-300 rad/s (omegas > 0)",
    )  # fmt: skip
    return d, F0, w, x0, v0, rtol, xr


def _sweep_controls(rtol, xr, atol, steady_tol, max_periods, integrator, max_steps):
    """The checked integrator settings of :func:`frequency_sweep`: ``(atol, steady_tol, max_periods, max_steps)``."""
    atol = rtol * xr if atol is None else check_real("atol", atol, low=XREF_MIN * 1e-13, unit="m")
    steady_tol = check_real("steady_tol", steady_tol, low=1e-12, high=0.1)
    max_periods = check_int("max_periods", max_periods, low=3, high=1_000_000)
    if not isinstance(integrator, str) or integrator not in ("compiled", "scipy"):
        raise ParameterError(f"integrator = {integrator!r:.60} is not valid: allowed 'compiled' or 'scipy'")
    limit = MAX_SWEEP_STEPS if integrator == "compiled" else MAX_SCIPY_SWEEP_STEPS
    max_steps = limit if max_steps is None else check_int("max_steps", max_steps, low=1, high=limit)
    return atol, steady_tol, max_periods, max_steps


def _run_sweep(d, F0, ws, x0, v0, rtol, atol, steady_tol, max_periods, xr, integrator, max_steps):
    """Integrate the sweep over ``ws`` (in sweep order); returns its output arrays, in that order too.

    ``(amplitude, x_max, x_min, steady, periods, x_end, v_end, n_steps)``; a spent budget is a
    :class:`ParameterError`.
    """
    nw = ws.size
    amp, xmax, xmin = np.empty(nw), np.empty(nw), np.empty(nw)
    steady, periods, nsteps = np.zeros(nw, dtype=np.bool_), np.zeros(nw, dtype=np.int64), np.zeros(nw, np.int64)
    xs, vs = np.empty(nw), np.empty(nw)
    blow_up = 1e3 * max(xr, abs(x0), d.barrier if math.isfinite(d.barrier) else 0.0)
    args = (d.m, d.c, d.k, d.k3, F0, ws, x0, v0, rtol, atol, steady_tol, 3, max_periods, blow_up)
    outs = (amp, xmax, xmin, steady, periods, xs, vs, nsteps)
    if integrator == "compiled":
        status, j = _sweep_kernel()(*args, *outs, max_steps)
    else:
        status, j = _sweep_scipy(args, outs, max_steps)
    if status != 0:
        raise ParameterError(
            f"frequency_sweep spent its budget of max_steps = {max_steps} integrator steps at omega = {ws[j]:.6g} "
            f"rad/s (frequency {j + 1} of {nw} in sweep order, {periods[j]} periods there; {_rates(d)}): allowed "
            "fewer frequencies, a smaller max_periods, a looser steady_tol or rtol, or a less stiff oscillator"
        )
    return outs


def _sweep_result(w: np.ndarray, order: np.ndarray, outs: tuple, direction: str) -> SweepResult:
    """The :class:`SweepResult` of the output arrays ``outs`` (in sweep ``order``), aligned with ``w`` again."""
    amp, xmax, xmin, steady, periods, xs, vs, nsteps = outs
    inv = np.empty_like(order)
    inv[order] = np.arange(order.size)
    return SweepResult(
        omega=w.copy(),
        amplitude=amp[inv],
        x_max=xmax[inv],
        x_min=xmin[inv],
        steady=steady[inv],
        periods=periods[inv],
        x_end=xs[inv],
        v_end=vs[inv],
        direction=direction,
        n_steps=nsteps[inv],
    )


def sweep(duffing: Duffing, F0: float, omegas, *, direction: str) -> np.ndarray:
    """Steady amplitudes of a stepped frequency sweep by time integration, m.

    :func:`frequency_sweep` with its defaults (see there for the steady criterion);
    ``amplitude[i]`` belongs to ``omegas[i]`` whatever the direction.

    Parameters
    ----------
    duffing : Duffing
        The oscillator (c > 0).
    F0 : float
        Force amplitude of ``F0 cos(omega t)``, N (>= 0).
    omegas : array_like
        Forcing frequencies, rad/s (> 0).
    direction : {"up", "down"}
        Visit the frequencies in ascending or descending order.

    Returns
    -------
    numpy.ndarray
        Half the peak-to-peak displacement over the last period at each frequency, m.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> np.round(sweep(d, 5.0, [5.0, 5.1], direction="up"), 3)      # m: on the upper branch at 5.1 rad/s
    array([1.951, 1.968])
    >>> np.round(sweep(d, 5.0, [5.0, 5.1], direction="down"), 3)    # m: from rest onto the lower one, then up at 5.0
    array([1.951, 0.938])
    """
    return frequency_sweep(duffing, F0, omegas, direction=direction).amplitude


def locate_jump(
    duffing: Duffing,
    F0: float,
    result: SweepResult,
    *,
    which: int = 0,
    levels: int = 2,
    n: int = 10,
    max_periods: int = 5000,
):
    """Narrow a jump of a sweep down by re-sweeping its bracket on finer and finer grids.

    Starting from the steady state just before the jump, the bracket ``(omega_before,
    omega_after)`` is swept again in the same direction with ``n`` steps, the new bracket
    is the step where the amplitude jumps, and so on ``levels`` times: the bracket shrinks
    by ``n^levels``. Near a fold the response settles slowly (critical slowing down), so
    ``max_periods`` is raised to 20000 here.

    Parameters
    ----------
    duffing : Duffing
        The oscillator of the sweep.
    F0 : float
        Force amplitude of the sweep, N.
    result : SweepResult
        A sweep with at least one jump.
    which : int
        Which jump, in sweep order (0 first).
    levels : int
        Refinements (0 to 8).
    n : int
        Steps per refinement (2 to 1000).

    Returns
    -------
    tuple of float
        ``(omega_before, omega_after)``, rad/s: the last frequency on the old branch and the
        first on the new one; the jump lies between them.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> up = frequency_sweep(d, 5.0, np.linspace(4.6, 5.4, 9), direction="up")
    >>> lo, hi = locate_jump(d, 5.0, up)
    >>> round(lo, 3), round(hi - lo, 6)       # rad/s, rad/s
    (5.107, 0.001)
    """
    d, F0, jump, levels, n, max_periods = _jump_args(duffing, F0, result, which, levels, n, max_periods)
    w_before, w_after, *_ = jump
    i = int(np.flatnonzero(result.omega == w_before)[0])
    x, v = float(result.x_end[i]), float(result.v_end[i])
    budget = MAX_SWEEP_STEPS  # shared by every level
    for _ in range(levels):
        ws = np.linspace(w_before, w_after, n + 1)
        if budget < 1:
            raise ParameterError(
                f"locate_jump spent its budget of {MAX_SWEEP_STEPS} integrator steps with levels = {levels}, "
                f"n = {n}: allowed fewer levels or steps per level"
            )
        res = frequency_sweep(
            d, F0, ws, direction=result.direction, x0=x, v0=v, max_periods=max_periods, max_steps=budget
        )
        budget -= int(res.n_steps.sum())
        bracket = _jump_in(res, ws, n, result.direction)
        if bracket is None:  # the finer sweep crossed without jumping: keep the last bracket
            break
        w_before, w_after, x, v = bracket
    return w_before, w_after


def _jump_args(duffing, F0, result, which, levels, n, max_periods):
    """The checked arguments of :func:`locate_jump`: ``(d, F0, jump, levels, n, max_periods)``.

    ``jump`` is the chosen one (``which``) of ``result.jumps()``.
    """
    d = _check_duffing(duffing)
    _check_damped(d)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    if not isinstance(result, SweepResult):
        raise ParameterError(f"result = {result!r:.60} is not a SweepResult: allowed the output of frequency_sweep")
    max_periods = check_int("max_periods", max_periods, low=3, high=1_000_000)
    jumps = result.jumps()
    which = check_int("which", which, low=0, high=max(len(jumps) - 1, 0))
    if not jumps:
        raise ParameterError("result has no jump: allowed a sweep whose amplitude jumps")
    levels = check_int("levels", levels, low=0, high=8)
    n = check_int("n", n, low=2, high=1000)
    return d, F0, jumps[which], levels, n, max_periods


def _jump_in(res: SweepResult, ws: np.ndarray, n: int, direction: str):
    """The first jump of the sweep ``res`` over ``ws`` (``n + 1`` frequencies) in sweep order, or None.

    Returns ``(omega_before, omega_after, x, v)``: the bracket, rad/s, and the state the sweep ended in at
    ``omega_before``, m and m/s.
    """
    order = np.argsort(ws) if direction == "up" else np.argsort(ws)[::-1]
    amps = res.amplitude[order]
    a0 = amps[0]
    for j in range(1, n + 1):
        if abs(amps[j] - a0) > 0.25 * max(amps[j], a0) or not np.isfinite(amps[j]):
            k_prev = order[j - 1]
            return float(ws[k_prev]), float(ws[order[j]]), float(res.x_end[k_prev]), float(res.v_end[k_prev])
        a0 = amps[j]
    return None
