"""Exact costs of linear laws and the references a learner is scored against (LQR, the best passive damper)."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np
import scipy.linalg

from ..model import ParameterError
from .task import OscillatorTask, _check_gains, _check_task, _increments, _zoh, zoh

# ----------------------------------------------------------------------------- exact costs and the optimum


def _moments(task: OscillatorTask, g: np.ndarray) -> tuple[float, float]:
    """Exact expected cost (s) and exact largest |u| over the box (N) of the unclipped law g (force mode).

    The state is ``s_k = A_cl^k s_0 + mu_k`` with ``mu_k`` the forced response from rest; ``E s_0 = 0`` so
    ``E s_k s_k' = A_cl^k S_0 A_cl'^k + mu_k mu_k'``, and ``max |K s_k|`` over the box is
    ``|K A_cl^k| [x0_max, v0_max] + |K mu_k|``.
    """
    a_d, b_d = _zoh(task.m, task.c, task.k, task.dt)
    d = _increments(task)
    with np.errstate(over="ignore", invalid="ignore"):  # huge gains: inf weights, and the kernel returns inf
        acl = a_d - np.outer(b_d, g)
        w = task.state_weight + task.dt * task.r * np.outer(g, g)
    if not (np.all(np.isfinite(acl)) and np.all(np.isfinite(w))):
        return math.inf, math.inf
    return _moments_from(task, acl, w, d, g)


def peak_force(task: OscillatorTask | None, gains) -> float:
    """Largest ``|K s_k|`` of the unclipped law ``u = -K s`` over every step and every initial state of the box, N.

    Exact: ``s_k = A_cl^k s_0 + mu_k`` and the box is symmetric, so the largest value is
    ``|K A_cl^k| [x0_max, v0_max] + |K mu_k|``. When it is at most ``u_max`` the force bound never
    binds and :func:`expected_cost` is the law's exact expected cost. Force mode.

    Examples
    --------
    >>> ref = lqr_reference()
    >>> round(peak_force(None, ref.gains), 2)                 # N, from a corner of the box
    14.76
    """
    task = _check_task(task)
    _force_mode(task, "peak_force")
    g = _check_gains(gains)
    peak = _moments(task, g)[1]
    if not math.isfinite(peak):
        raise ParameterError(
            f"gains = {g.tolist()!r} destabilise the plant: the force overflows within {task.n_steps} steps: "
            "allowed gains whose force stays finite"
        )
    return peak


def _force_mode(task: OscillatorTask, what: str) -> None:
    if task.mode != "force":
        raise ParameterError(f"mode = {task.mode!r} is not supported by {what}: allowed mode = 'force'")


def expected_cost(task: OscillatorTask | None, gains) -> float:
    """Exact expected episode cost of the linear law ``u = -K [x, v]`` in force mode, s.

    The expected cost is the mean, over the initial states uniform in the task's box, of the
    episode's summed cost ``sum_{k=0}^{n_steps-1} (q_x x_k**2 + q_v v_k**2 + r u_k**2) dt``
    (the negative of the gymnasium return). Evaluated without sampling: the second moment
    of the state is propagated exactly (``E s_0 s_0' = diag(x0_max**2, v0_max**2) / 3``) and the
    disturbance's deterministic forced response is added.

    Parameters
    ----------
    task : OscillatorTask or None
        A force-mode task (default task if None).
    gains : array_like, shape (2,)
        ``[K_x, K_v]`` in N/m and N s/m, for ``u = -K_x x - K_v v``.

    Returns
    -------
    float
        The expected cost, s.

    Raises
    ------
    ParameterError
        If the force bound ``u_max`` could bind for some initial state (then the law is not
        linear on the task; use :func:`episode_costs` on sampled states), or in damping mode.

    Examples
    --------
    >>> round(expected_cost(None, lqr_reference().gains), 4)                  # s
    0.7663
    """
    task = _check_task(task)
    _force_mode(task, "expected_cost")
    g = _check_gains(gains)
    cost, peak = _moments(task, g)
    if not peak <= task.u_max:
        raise ParameterError(
            f"gains = {g.tolist()!r} is out of range: allowed gains whose largest force over the box "
            f"({peak:.4g} N) stays within u_max = {task.u_max:g} N; sample episodes instead"
        )
    return cost


def _passive_cost(task: OscillatorTask, c: float) -> float:
    """Exact expected cost of a constant damping c: total c (damping mode) or added c (force mode), s."""
    if task.mode == "force":
        return expected_cost(task, [0.0, c])
    sub = replace(task, mode="force", c=c)
    # a damper c is the plant with damping c and no actuator; its force -c v is costed like u
    a_d, _ = _zoh(sub.m, sub.c, sub.k, sub.dt)
    d = _increments(sub)
    w = task.state_weight + task.dt * task.r * np.diag([0.0, c * c])
    return _moments_from(task, a_d, w, d, np.array([0.0, c]))[0]


def _moments_from(task, acl, w, d, g):
    """Expected cost and largest |g s_k| over the box for ``s_{k+1} = acl s_k + d_k``, stage ``s'w s``."""
    total, peak = _moment_kernel()(
        np.ascontiguousarray(acl, dtype=float), np.ascontiguousarray(w, dtype=float), d,
        np.ascontiguousarray(g, dtype=float), task.x0_max, task.v0_max,
    )  # fmt: skip
    return float(total), float(peak)


@functools.cache
def _moment_kernel():
    """Compile (once per process, cached on disk) the exact moment recursion; numba is imported lazily."""
    import numba

    @numba.njit(cache=True)
    def kernel(acl, w, d, g, xb, vb):  # pragma: no cover - compiled
        a00, a01, a10, a11 = acl[0, 0], acl[0, 1], acl[1, 0], acl[1, 1]
        w00, w01, w11 = w[0, 0], w[0, 1], w[1, 1]
        s00, s01, s11 = xb * xb / 3.0, 0.0, vb * vb / 3.0  # E s s' of the uniform box
        mx = mv = 0.0  # forced response from rest
        kx, kv = g[0], g[1]  # row g A_cl^k
        total, peak = 0.0, 0.0
        for kk in range(d.shape[0]):
            total += w00 * (s00 + mx * mx) + 2.0 * w01 * (s01 + mx * mv) + w11 * (s11 + mv * mv)
            pk = abs(kx) * xb + abs(kv) * vb + abs(g[0] * mx + g[1] * mv)
            if pk > peak:
                peak = pk
            t00 = a00 * s00 + a01 * s01
            t01 = a00 * s01 + a01 * s11
            t10 = a10 * s00 + a11 * s01
            t11 = a10 * s01 + a11 * s11
            s00, s01, s11 = t00 * a00 + t01 * a01, t00 * a10 + t01 * a11, t10 * a10 + t11 * a11
            mx, mv = a00 * mx + a01 * mv + d[kk, 0], a10 * mx + a11 * mv + d[kk, 1]
            kx, kv = kx * a00 + kv * a10, kx * a01 + kv * a11
            if not np.isfinite(total):
                return np.inf, np.inf
        return total, peak

    return kernel


@dataclass(frozen=True, kw_only=True)
class PassiveOptimum:
    """The best constant damping for a task and its exact expected cost.

    ``c`` is the damper's coefficient (N s/m): in damping mode the oscillator's whole damping, in
    force mode a damper added to the passive ``task.c`` (its force ``-c v`` is the control force).
    """

    c: float  # optimal damping, N s/m
    expected_cost: float  # exact expected cost, s
    at_bound: bool  # the optimum sits on c_min or c_max


def _largest_damper(task: OscillatorTask) -> float:
    """Largest added damping whose force stays within u_max for every initial state of the box, N s/m."""
    lo, hi = 0.0, task.u_max / task.v0_max if task.v0_max > 0.0 else 1e3 * task.c_max

    def peak(c):
        return _moments(task, np.array([0.0, c]))[1]  # inf when the damper destabilises the sampled loop

    while peak(hi) <= task.u_max and hi < 1e12:
        lo, hi = hi, 2.0 * hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if peak(mid) <= task.u_max else (lo, mid)
    return lo


def best_passive_damping(task: OscillatorTask | None = None) -> PassiveOptimum:
    """Best constant damping: the semi-active damper held fixed, or a damper added to the plant.

    Damping mode: the best constant ``c`` in ``[c_min, c_max]``. Force mode: the best damper
    added in parallel to the plant's ``c``, ``u = -c_add v``, among those whose force stays
    within ``u_max`` for every initial state (the actuator's force budget). Exact expected cost of
    each constant damping; a 121-point geometric grid, then a bounded Brent search around the
    best grid point.

    Examples
    --------
    >>> from vibration.physics.learning import semi_active_task
    >>> opt = best_passive_damping(semi_active_task(F0=0.0))
    >>> round(opt.c, 2), round(opt.expected_cost, 4)                     # N s/m, s
    (9.17, 0.803)
    """
    import scipy.optimize

    task = _check_task(task)
    if task.mode == "damping":
        lo, hi = task.c_min, task.c_max
    else:
        lo, hi = 0.0, _largest_damper(task)
    grid = np.concatenate([[lo], np.geomspace(max(lo, 1e-3 * hi), hi, 120)])
    grid = np.unique(grid)
    costs = np.array([_passive_cost(task, float(c)) for c in grid])
    i = int(np.argmin(costs))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    res = scipy.optimize.minimize_scalar(
        lambda c: _passive_cost(task, float(c)), bounds=(a, b), method="bounded", options={"xatol": 1e-9 * hi}
    )
    c, cost = (float(res.x), float(res.fun)) if res.fun <= costs[i] else (float(grid[i]), float(costs[i]))
    return PassiveOptimum(c=c, expected_cost=cost, at_bound=bool(c <= lo + 1e-6 * hi or c >= hi * (1 - 1e-6)))


@dataclass(frozen=True, kw_only=True)
class LQRReference:
    """Discrete-time LQR of the sampled task: gains, Riccati solution, exact expected cost.

    ``gains = [K_x, K_v]`` (N/m, N s/m) for ``u = -K [x, v]``; ``P`` solves the discrete algebraic
    Riccati equation with ``Q = dt diag(q_x, q_v)`` and ``R = dt r``, so ``s' P s`` is the optimal
    infinite-horizon cost from ``s`` (s); ``expected_cost`` is the exact mean episode cost of the
    task with these gains (n_steps steps, the disturbance included); ``infinite_horizon_cost`` is
    ``trace(P E[s_0 s_0'])`` (no disturbance); ``poles`` are the closed-loop eigenvalues (z-plane).
    """

    gains: np.ndarray  # [K_x (N/m), K_v (N s/m)]
    P: np.ndarray  # Riccati solution, s (SI units of the state)
    expected_cost: float  # exact expected episode cost, s
    infinite_horizon_cost: float  # trace(P E s0 s0'), s
    poles: np.ndarray  # closed-loop eigenvalues of A_d - B_d K, 1
    peak_force: float  # largest |u| over the box and the episode, N


def lqr_reference(task: OscillatorTask | None = None) -> LQRReference:
    """Discrete-time LQR gains and expected cost of the task (force mode), from the Riccati equation.

    The stage cost of the environment, ``(q_x x**2 + q_v v**2 + r u**2) dt`` on the sampled state
    and the held force, is ``s'Q s + u'R u`` with ``Q = dt diag(q_x, q_v)``, ``R = dt r``: exactly
    the discrete LQR problem of the ZOH plant ``(A_d, B_d)``. Its stationary optimal law is
    ``u = -K s``, ``K = (R + B_d' P B_d)^-1 B_d' P A_d`` (:func:`scipy.linalg.solve_discrete_are`).
    For an episode of ``n_steps`` steps the exact optimum varies with time near the end of the
    episode; with the default task the stationary gains lose less than 1e-12 of the cost to it.
    A disturbance does not change the gains (LQR does not know it), only the expected cost.

    Parameters
    ----------
    task : OscillatorTask, optional
        A force-mode task; the default task if omitted.

    Returns
    -------
    LQRReference

    Examples
    --------
    >>> ref = lqr_reference()
    >>> np.round(ref.gains, 4)                                 # N/m, N s/m
    array([1.2977, 9.2676])
    >>> round(ref.expected_cost, 4), round(ref.infinite_horizon_cost, 4)   # s, s
    (0.7663, 0.7663)
    """
    task = _check_task(task)
    _force_mode(task, "lqr_reference")
    a_d, b_d = zoh(task)
    b = b_d[:, None]
    q, r = task.state_weight, np.array([[task.dt * task.r]])
    try:
        p = scipy.linalg.solve_discrete_are(a_d, b, q, r)
        k = np.linalg.solve(r + b.T @ p @ b, b.T @ p @ a_d).ravel()
    except (ValueError, np.linalg.LinAlgError) as exc:
        raise ParameterError(
            f"the Riccati equation of the task has no stabilising solution ({exc}): allowed a task whose weights "
            f"q_x = {task.q_x!r}, q_v = {task.q_v!r}, r = {task.r!r} and plant make it solvable"
        ) from None
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(k))):
        raise ParameterError("the Riccati solution of the task is not finite: allowed a better scaled task")
    cost, peak = _moments(task, k)
    return LQRReference(
        gains=k,
        P=p,
        expected_cost=cost,
        infinite_horizon_cost=float(np.trace(p @ task.initial_covariance)),
        poles=np.linalg.eigvals(a_d - b @ k[None, :]),
        peak_force=peak,
    )
