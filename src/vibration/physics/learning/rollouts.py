"""Compiled rollouts: batched episodes of linear laws, their costs and recorded trajectories."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..duffing import _real_array
from ..model import ParameterError, check_int
from .task import (
    MAX_EPISODE_STEPS,
    MAX_RECORDED_STEPS,
    MAX_STATES,
    MODES,
    OscillatorTask,
    _check_gain_rows,
    _check_gains,
    _check_task,
    _increments,
    _zoh,
)

# ----------------------------------------------------------------------------- compiled rollouts


@functools.cache
def _kernel():
    """Compile (once per process, cached on disk) the batched episode loop; numba is imported lazily."""
    import numba

    @numba.njit(parallel=True, cache=True)
    def kernel(
        mode, a_d, b_d, d, sw, cw, m, k, dt, f0, om, qx, qv, r, u_max, c_min, c_max, gains, x0, rec, xs, vs, us
    ):  # pragma: no cover - compiled
        n_pol, n_ep, n = gains.shape[0], x0.shape[0], d.shape[0]
        costs = np.empty((n_pol, n_ep))
        for job in numba.prange(n_pol * n_ep):
            i, j = job // n_ep, job % n_ep
            kx, kv = gains[i, 0], gains[i, 1]
            x, v = x0[j, 0], x0[j, 1]
            acc = 0.0
            c_last = -1.0
            p00 = p01 = p10 = p11 = h_re = h_im = 0.0
            for step in range(n):
                if mode == 0:
                    u = -(kx * x + kv * v)
                    if u > u_max:
                        u = u_max
                    elif u < -u_max:
                        u = -u_max
                    xn = a_d[0, 0] * x + a_d[0, 1] * v + b_d[0] * u + d[step, 0]
                    vn = a_d[1, 0] * x + a_d[1, 1] * v + b_d[1] * u + d[step, 1]
                else:
                    cc = kv + kx * x / v if v != 0.0 else kv
                    if not cc >= c_min:  # also NaN
                        cc = c_min
                    elif cc > c_max:
                        cc = c_max
                    u = -cc * v
                    if cc != c_last:  # the transition matrix and forced response of this damping
                        c_last = cc
                        sg = -cc / (2.0 * m)
                        disc = sg * sg - k / m
                        z = disc * dt * dt
                        if abs(z) < 1e-3:
                            ch = 1.0 + z / 2.0 * (1.0 + z / 12.0 * (1.0 + z / 30.0 * (1.0 + z / 56.0)))
                            sh = dt * (1.0 + z / 6.0 * (1.0 + z / 20.0 * (1.0 + z / 42.0 * (1.0 + z / 72.0))))
                        elif disc < 0.0:
                            wd = np.sqrt(-disc)
                            ch = np.cos(wd * dt)
                            sh = np.sin(wd * dt) / wd
                        else:
                            q = np.sqrt(disc)
                            ch = np.cosh(q * dt)
                            sh = np.sinh(q * dt) / q
                        e = np.exp(sg * dt)
                        p00, p01 = e * (ch - sg * sh), e * sh
                        p10, p11 = -e * (k / m) * sh, e * (ch + sg * sh)
                        den_re, den_im = k - m * om * om, om * cc
                        den2 = den_re * den_re + den_im * den_im
                        h_re, h_im = f0 * den_re / den2, -f0 * den_im / den2
                    if f0 != 0.0:
                        s0, c0, s1, c1 = sw[step], cw[step], sw[step + 1], cw[step + 1]
                        xp0, vp0 = h_re * s0 + h_im * c0, om * (h_re * c0 - h_im * s0)
                        xp1, vp1 = h_re * s1 + h_im * c1, om * (h_re * c1 - h_im * s1)
                        xh, vh = x - xp0, v - vp0
                        xn = p00 * xh + p01 * vh + xp1
                        vn = p10 * xh + p11 * vh + vp1
                    else:
                        xn = p00 * x + p01 * v
                        vn = p10 * x + p11 * v
                if rec:
                    xs[i, j, step] = x
                    vs[i, j, step] = v
                    us[i, j, step] = u
                acc += (qx * x * x + qv * v * v + r * u * u) * dt
                x, v = xn, vn
                if not acc < np.inf:  # overflow (inf or nan): the law destabilises the plant
                    acc = np.inf
                    if rec:
                        for rest in range(step + 1, n):
                            xs[i, j, rest] = np.nan
                            vs[i, j, rest] = np.nan
                            us[i, j, rest] = np.nan
                    break
            costs[i, j] = acc
        return costs

    return kernel


def _run(task: OscillatorTask, gains: np.ndarray, x0: np.ndarray, record: bool):
    mode = MODES.index(task.mode)
    if mode == 0:
        a_d, b_d = _zoh(task.m, task.c, task.k, task.dt)
        d = _increments(task)
    else:
        a_d, b_d, d = np.eye(2), np.zeros(2), np.zeros((task.n_steps, 2))
    phase = task.omega * np.arange(task.n_steps + 1) * task.dt
    sw, cw = np.sin(phase), np.cos(phase)
    shape = (gains.shape[0], x0.shape[0], task.n_steps) if record else (0, 0, 0)
    xs, vs, us = np.empty(shape), np.empty(shape), np.empty(shape)
    costs = _kernel()(
        mode, a_d, b_d, d, sw, cw, task.m, task.k, task.dt, task.F0, task.omega, task.q_x, task.q_v, task.r,
        task.u_max, task.c_min, task.c_max, np.ascontiguousarray(gains, dtype=float),
        np.ascontiguousarray(x0, dtype=float), record, xs, vs, us,
    )  # fmt: skip
    return costs, xs, vs, us


def _check_states(x0) -> np.ndarray:
    s = _real_array("x0", x0, max_size=2 * MAX_STATES)
    if s.ndim == 1:
        s = s[None, :]
    if s.ndim != 2 or s.shape[1] != 2 or s.shape[0] < 1:
        raise ParameterError(f"x0 has shape {np.shape(x0)}: allowed finite [x (m), v (m/s)] rows, shape (n, 2)")
    return s


def _check_work(task: OscillatorTask, n_laws: int, n_states: int, limit: int, what: str) -> None:
    work = n_laws * n_states * task.n_steps
    if work > limit:
        raise ParameterError(
            f"{n_laws} laws x {n_states} initial states x n_steps = {task.n_steps} make {work} {what}: allowed at "
            f"most {limit}"
        )


def sample_initial_states(task: OscillatorTask | None, n: int, seed: int | np.random.Generator = 0) -> np.ndarray:
    """``n`` initial states uniform in the task's box, shape (n, 2) (m, m/s), seeded.

    Examples
    --------
    >>> s = sample_initial_states(None, 4, seed=1)
    >>> s.shape, bool(np.all(np.abs(s) <= 1.0))
    ((4, 2), True)
    """
    task = _check_task(task)
    n = check_int("n", n, low=1, high=MAX_STATES)
    rng = (
        seed
        if isinstance(seed, np.random.Generator)
        else np.random.default_rng(check_int("seed", seed, low=0, high=2**63 - 1))
    )
    return rng.uniform(-1.0, 1.0, size=(n, 2)) * np.array([task.x0_max, task.v0_max])


def episode_costs(task: OscillatorTask | None, gains, x0) -> np.ndarray:
    """Episode cost of every linear law on every initial state, shape (n_laws, n_states) (s).

    Runs the environment's dynamics (exact ZOH, force bound, clipped damping) in one compiled
    loop, in parallel over laws and episodes.

    Parameters
    ----------
    task : OscillatorTask or None
        The task (default task if None).
    gains : array_like, shape (2,) or (n_laws, 2)
        ``[K_x, K_v]`` of ``u_des = -K [x, v]``, N/m and N s/m.
    x0 : array_like, shape (2,) or (n_states, 2)
        Initial states ``[x, v]``, m and m/s.

    Returns
    -------
    numpy.ndarray
        Costs, s; ``inf`` for an episode whose state overflows (a law that destabilises the plant).

    Examples
    --------
    >>> from vibration.physics.learning import lqr_reference
    >>> ref = lqr_reference()
    >>> float(episode_costs(None, ref.gains, [1.0, 0.0])[0, 0]) == float(rollout(None, ref.gains, [1.0, 0.0]).cost[0])
    True
    """
    task = _check_task(task)
    g = _check_gain_rows(gains)
    states = _check_states(x0)
    _check_work(task, g.shape[0], states.shape[0], MAX_EPISODE_STEPS, "simulated steps")
    return _run(task, g, states, record=False)[0]


@dataclass(frozen=True, kw_only=True)
class Rollouts:
    """Episodes of one linear law: sampled states and forces at the step starts, and costs.

    ``x``, ``v``, ``u`` have shape (n_episodes, n_steps): m, m/s, N (``u`` is the actuator force in
    force mode, the damper force ``-c v`` in damping mode); ``c`` is the damping applied (N s/m,
    damping mode; the passive ``c`` in force mode); ``cost`` the episode costs (s).
    """

    t: np.ndarray  # step start times, s
    x: np.ndarray  # displacement, m
    v: np.ndarray  # velocity, m/s
    u: np.ndarray  # control force, N
    cost: np.ndarray  # episode cost, s

    @property
    def peak_x(self) -> float:
        """Largest |x| over every episode and step, m."""
        return float(np.max(np.abs(self.x)))

    @property
    def rms_x(self) -> float:
        """Root mean square of x over every episode and step, m."""
        return float(np.sqrt(np.mean(self.x**2)))

    @property
    def rms_u(self) -> float:
        """Root mean square of the control force over every episode and step, N."""
        return float(np.sqrt(np.mean(self.u**2)))

    @property
    def peak_u(self) -> float:
        """Largest |u| over every episode and step, N."""
        return float(np.max(np.abs(self.u)))

    @property
    def mean_cost(self) -> float:
        """Mean episode cost, s."""
        return float(np.mean(self.cost))

    @property
    def cost_sem(self) -> float:
        """Standard error of the mean episode cost, s (0 with one episode)."""
        n = self.cost.size
        return float(np.std(self.cost, ddof=1) / math.sqrt(n)) if n > 1 else 0.0


def rollout(task: OscillatorTask | None, gains, x0) -> Rollouts:
    """Episodes of the linear law ``gains`` from the initial states ``x0``, with their trajectories.

    Parameters
    ----------
    task : OscillatorTask or None
        The task (default task if None).
    gains : array_like, shape (2,)
        ``[K_x, K_v]`` (N/m, N s/m) of ``u_des = -K [x, v]``.
    x0 : array_like, shape (2,) or (n, 2)
        Initial states, m and m/s.

    Examples
    --------
    >>> r = rollout(None, [0.0, 0.0], [1.0, 0.0])          # free decay from x = 1 m
    >>> r.x.shape, round(float(r.x[0, 0]), 3), round(r.mean_cost, 3)   # -, m, s
    ((1, 1000), 1.0, 20.868)
    """
    task = _check_task(task)
    g = _check_gains(gains)
    states = _check_states(x0)
    _check_work(task, 1, states.shape[0], MAX_RECORDED_STEPS, "recorded steps")
    costs, xs, vs, us = _run(task, g[None, :], states, record=True)
    if not (np.all(np.isfinite(costs)) and np.all(np.isfinite(xs)) and np.all(np.isfinite(vs))):
        raise ParameterError(
            f"gains = {g.tolist()!r} destabilise the plant: the state overflows (not finite) within "
            f"{task.n_steps} steps: allowed gains whose episodes stay finite"
        )
    return Rollouts(t=task.t, x=xs[0], v=vs[0], u=us[0], cost=costs[0])
