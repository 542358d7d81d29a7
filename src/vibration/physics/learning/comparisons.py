"""Comparisons of controllers on common episodes, and the self-checks of the chapter."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..checks import optional
from ..model import ParameterError, check_int
from .references import _moments, _passive_cost, lqr_reference
from .rollouts import Rollouts, _check_work, episode_costs, rollout, sample_initial_states
from .task import MAX_RECORDED_STEPS, MAX_STATES, OscillatorTask, _check_gains, _check_task, _increments, zoh

# ----------------------------------------------------------------------------- comparisons and checks


@dataclass(frozen=True, kw_only=True)
class Comparison:
    """Controllers of one task rolled out on the same seeded episodes.

    ``names[i]`` has gains ``gains[i]`` (``[K_x, K_v]``, N/m and N s/m) and episodes ``runs[i]``;
    ``exact[i]`` is its exact expected cost (s) when the law is linear on the task (force mode,
    bound never reached, or a constant damping), else ``nan``.
    """

    task: OscillatorTask
    names: tuple[str, ...]
    gains: tuple[np.ndarray, ...]
    runs: tuple[Rollouts, ...]
    exact: tuple[float, ...]
    seed: int

    def paired_gain(self, i: int, j: int) -> tuple[float, float]:
        """Mean cost of controller j minus controller i on the same episodes, and its standard error, s."""
        diff = self.runs[j].cost - self.runs[i].cost
        return float(diff.mean()), float(diff.std(ddof=1) / math.sqrt(diff.size)) if diff.size > 1 else 0.0


def compare_controllers(
    task: OscillatorTask, controllers: dict, n_episodes: int = 1000, *, seed: int = 0
) -> Comparison:
    """Roll every controller (name -> gains) out on the same ``n_episodes`` seeded initial states.

    Examples
    --------
    >>> cmp = compare_controllers(OscillatorTask(), {"LQR": lqr_reference().gains}, n_episodes=8)
    >>> cmp.names, round(cmp.exact[0], 4)                                    # -, s
    (('LQR',), 0.7663)
    """
    task = _check_task(task)
    n_episodes = check_int("n_episodes", n_episodes, low=2, high=MAX_STATES)
    seed = check_int("seed", seed, low=0, high=2**32 - 2)
    if not isinstance(controllers, dict) or not controllers:
        raise ParameterError(f"controllers = {controllers!r:.60} is not a dict: allowed a non-empty {{name: gains}}")
    _check_work(task, len(controllers), n_episodes, MAX_RECORDED_STEPS, "recorded steps")
    states = sample_initial_states(task, n_episodes, np.random.default_rng(np.random.SeedSequence([seed, 14, 1])))
    names, gains, runs, exact = [], [], [], []
    for name, g in controllers.items():
        g = _check_gains(g)
        names.append(str(name))
        gains.append(g)
        runs.append(rollout(task, g, states))
        ex = math.nan
        if task.mode == "force":
            cost, peak = _moments(task, g)
            ex = cost if peak <= task.u_max else math.nan
        elif g[0] == 0.0 and task.c_min <= g[1] <= task.c_max:
            ex = _passive_cost(task, float(g[1]))
        exact.append(ex)
    return Comparison(
        task=task, names=tuple(names), gains=tuple(gains), runs=tuple(runs), exact=tuple(exact), seed=seed
    )


def verification(task: OscillatorTask, gains) -> dict[str, float]:
    """Residuals of the chapter's numbers against independent methods (all relative, 1).

    * ``lqr_vs_control``: LQR gains against python-control's ``dlqr``;
    * ``riccati``: residual of the discrete Riccati equation, relative to ``|P|``;
    * ``cost_vs_cubature``: exact expected cost of ``gains`` against the 2 x 2 Gauss-Legendre
      cubature of the environment's episode costs (exact for a cost quadratic in ``s_0``);
    * ``env_vs_loop``: one episode of the gymnasium-side step (scipy ``expm``) against the compiled
      loop (closed-form exponential), largest displacement difference relative to ``x0_max``.

    Examples
    --------
    >>> chk = verification(OscillatorTask(), lqr_reference().gains)
    >>> all(v < 1e-9 for v in chk.values())
    True
    """
    control = optional("control", extra="control", what="vibration.learning.verification")

    task = replace(_check_task(task), mode="force")
    g = _check_gains(gains)
    ref = lqr_reference(task)
    a_d, b_d = zoh(task)
    k_ctrl = np.ravel(control.dlqr(a_d, b_d[:, None], task.state_weight, task.dt * task.r)[0])
    b = b_d[:, None]
    pa = ref.P @ a_d
    resid = a_d.T @ pa - ref.P - pa.T @ b @ b.T @ pa / (task.dt * task.r + b.T @ ref.P @ b) + task.state_weight
    nodes = np.array([-1.0, 1.0]) / math.sqrt(3.0)
    xs, vs = np.meshgrid(nodes * task.x0_max, nodes * task.v0_max, indexing="ij")
    cub = float(episode_costs(task, g, np.column_stack([xs.ravel(), vs.ravel()])).mean())
    cost, peak = _moments(task, g)
    # one episode with the step map of the environment: expm-based ZOH, force held
    s = np.array([task.x0_max, -task.v0_max])
    d = _increments(task)
    xs_env = np.empty(task.n_steps)
    for i in range(task.n_steps):
        xs_env[i] = s[0]
        u = min(max(-(g[0] * s[0] + g[1] * s[1]), -task.u_max), task.u_max)
        s = a_d @ s + b_d * u + d[i]
    loop = rollout(task, g, [task.x0_max, -task.v0_max]).x[0]
    return {
        "lqr_vs_control": float(np.max(np.abs(ref.gains - k_ctrl)) / np.max(np.abs(k_ctrl))),
        "riccati": float(np.max(np.abs(resid)) / np.max(np.abs(ref.P))),
        "cost_vs_cubature": abs(cost - cub) / cub if peak <= task.u_max else math.nan,
        "env_vs_loop": float(np.max(np.abs(xs_env - loop)) / max(task.x0_max, 1e-300)),
    }
