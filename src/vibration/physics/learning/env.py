"""The learning chapter's public API: a gymnasium environment, the LQR optimum, and a learner.

Needs the ``learn`` extra (``pip install vibration[learn]``: gymnasium, cma). Importing this module
registers ``vibration/Oscillator-v0`` with gymnasium; the package also declares :func:`register` as
its ``gymnasium.envs`` entry point, and ``vibration.learn`` is this module under its short name
(``gymnasium.make("vibration/Oscillator-v0", **fields)`` builds :class:`OscillatorEnv`; the
keyword arguments are fields of :class:`~vibration.physics.learning.OscillatorTask`).

Conventions (the acceptance checks rely on them)
-----------------------------------------------
* Observation ``[x, v]``: displacement (m) and velocity (m/s) at the start of the step.
* Action: the force ``u`` on the mass (N, in ``[-u_max, u_max]``, default ``mode="force"``) or the
  damping coefficient ``c`` (N s/m, in ``[c_min, c_max]``, ``mode="damping"``), held over the step
  of ``dt`` = 0.01 s (exact zero-order hold).
* Reward of a step: ``-(x**2 + v**2 + 0.01 u**2) dt`` on the state the action was chosen on and
  the force applied (the damper force ``-c v`` in damping mode); 1000 steps, then ``truncated``.
* Initial state uniform in ``[-1, 1] m x [-1, 1] m/s``.
* Linear policies: ``u = -K [x, v]`` with ``K = .gains = [K_x (N/m), K_v (N s/m)]``.
* Expected cost: the mean over the initial-state distribution of the episode's summed cost
  (minus the return), in s; :func:`lqr_reference` gives the optimum's, exactly.

Examples
--------
>>> import gymnasium as gym
>>> import vibration.learn as learn
>>> env = gym.make(learn.ENV_ID)
>>> obs, info = env.reset(seed=0)
>>> obs.shape, env.action_space.high.tolist()                 # m, m/s; N
((2,), [50.0])
>>> ref = learn.lqr_reference()
>>> np.round(ref.gains, 3), round(ref.expected_cost, 4)        # N/m, N s/m; s
(array([1.298, 9.268]), 0.7663)
"""

from __future__ import annotations

import math
from dataclasses import replace

import gymnasium
import numpy as np
from gymnasium import spaces

from ..duffing import _real_array
from ..model import ParameterError
from . import (
    LinearPolicy,
    LQRReference,
    OscillatorTask,
    PassiveOptimum,
    Rollouts,
    TrainingResult,
    _check_task,
    _particular,
    _zoh,
    best_passive_damping,
    episode_costs,
    expected_cost,
    lqr_reference,
    peak_force,
    resonance_task,
    rollout,
    sample_initial_states,
    semi_active_task,
    train,
    zoh,
)
from .disturbance import best_fixed_gain, cost_hessian, exosystem_optimum
from .studies import identify_then_design, robustness_study, seed_study

__all__ = [
    "ENV_ID",
    "LQRReference",
    "LinearPolicy",
    "OscillatorEnv",
    "OscillatorTask",
    "PassiveOptimum",
    "Rollouts",
    "TrainingResult",
    "best_fixed_gain",
    "best_passive_damping",
    "cost_hessian",
    "episode_costs",
    "exosystem_optimum",
    "identify_then_design",
    "expected_cost",
    "lqr_reference",
    "peak_force",
    "resonance_task",
    "robustness_study",
    "rollout",
    "sample_initial_states",
    "seed_study",
    "semi_active_task",
    "train",
    "zoh",
]

#: The gymnasium id registered on import.
ENV_ID = "vibration/Oscillator-v0"

#: Bound of the observation box, m and m/s (gymnasium's checker warns about infinite bounds).
OBS_LIMIT = 1e9


class OscillatorEnv(gymnasium.Env):
    """The paper's oscillator as a gymnasium environment (exact ZOH, dt = 0.01 s, 1000 steps).

    Parameters
    ----------
    task : OscillatorTask, optional
        The task; the default task (force action, no disturbance) if omitted.
    render_mode : None
        No rendering.
    **fields
        Fields of :class:`~vibration.physics.learning.OscillatorTask` to change, e.g.
        ``F0=5.0`` (the resonance disturbance ``F0 sin(4.47 t)``, N) or ``mode="damping"``
        (semi-active: the action is the damping in ``[c_min, c_max]``, N s/m).

    Notes
    -----
    ``reset(options={"state": [x, v]})`` starts from a given state (m, m/s) instead of a
    random one. ``info`` carries the time ``t`` (s) of the next step and, after a step, the
    ``force`` (N) and ``damping`` (N s/m) applied and the step's ``cost`` (s).

    Examples
    --------
    >>> env = OscillatorEnv()
    >>> obs, _ = env.reset(options={"state": [1.0, 0.0]})
    >>> obs, reward, terminated, truncated, info = env.step(np.array([0.0]))
    >>> round(float(obs[0]), 6), reward, terminated, truncated            # m, s
    (0.999002, -0.01, False, False)
    """

    metadata = {"render_modes": []}

    def __init__(self, task: OscillatorTask | None = None, render_mode: str | None = None, **fields) -> None:
        super().__init__()
        task = _check_task(task)
        if fields:
            try:
                task = replace(task, **fields)
            except TypeError as exc:  # an unknown field (ParameterError, also a TypeError, passes through)
                if isinstance(exc, ParameterError):
                    raise
                raise ParameterError(
                    f"fields {sorted(fields)!r} are not all fields of OscillatorTask ({exc}): allowed "
                    f"{sorted(OscillatorTask.__dataclass_fields__)}"
                ) from None
        if render_mode is not None:
            raise ParameterError(f"render_mode = {render_mode!r} is not supported: allowed None")
        self.task = task
        self.render_mode = None
        # finite only for gymnasium's checker: no state of any task comes near OBS_LIMIT
        self.observation_space = spaces.Box(-OBS_LIMIT, OBS_LIMIT, shape=(2,), dtype=np.float64)
        if task.mode == "force":
            self.action_space = spaces.Box(-task.u_max, task.u_max, shape=(1,), dtype=np.float64)
        else:
            self.action_space = spaces.Box(task.c_min, task.c_max, shape=(1,), dtype=np.float64)
        self._state = np.zeros(2)
        self._k = 0

    # the exact one-step maps (scipy's expm; the batched learner uses a separate closed form)
    def _advance(self, state: np.ndarray, k: int, action: float) -> tuple[np.ndarray, float, float]:
        t = self.task
        if t.mode == "force":
            u, c = float(np.clip(action, -t.u_max, t.u_max)), t.c
            a_d, b_d = _zoh(t.m, t.c, t.k, t.dt)
            nxt = a_d @ state + b_d * u
        else:
            c = float(np.clip(action, t.c_min, t.c_max))
            u = -c * float(state[1])
            a_d, b_d = _zoh(t.m, c, t.k, t.dt)
            nxt = a_d @ state
        if t.F0 != 0.0:
            p = _particular(t, c, np.array([k * t.dt, (k + 1) * t.dt]))
            nxt = nxt + p[1] - a_d @ p[0]
        return nxt, u, c

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        if seed is not None and (
            isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)) or seed < 0
        ):
            raise ParameterError(f"seed = {seed!r:.60} is not a non-negative integer: allowed None or an int >= 0")
        if options is not None and not isinstance(options, dict):
            raise ParameterError(f"options = {options!r:.60} is not a dict: allowed None or {{'state': [x, v]}}")
        super().reset(seed=None if seed is None else int(seed))
        t = self.task
        if options and "state" in options:
            try:
                s = _real_array("state", options["state"], max_size=2).reshape(-1)
            except ParameterError:
                s = None
            if s is None or s.shape != (2,):
                raise ParameterError(
                    f"state = {options['state']!r:.60} is not [x, v]: allowed two finite numbers (m, m/s)"
                )
            self._state = s.copy()
        else:
            self._state = self.np_random.uniform(-1.0, 1.0, size=2) * np.array([t.x0_max, t.v0_max])
        self._k = 0
        return self._state.copy(), {"t": 0.0}

    def step(self, action):
        t = self.task
        try:
            arr = _real_array("action", action, max_size=1)
        except ParameterError:
            arr = None
        if arr is None:
            raise ParameterError(
                f"action = {action!r:.60} is not one finite number: allowed a finite force (N) or damping (N s/m), "
                "shape (1,)"
            )
        a = float(arr.reshape(-1)[0])
        x, v = (float(z) for z in self._state)
        with np.errstate(over="ignore", invalid="ignore"):
            nxt, u, c = self._advance(self._state, self._k, a)
            cost = (t.q_x * x * x + t.q_v * v * v + t.r * u * u) * t.dt
        if not (math.isfinite(cost) and np.all(np.isfinite(nxt))):
            raise ParameterError(
                f"the state [{x!r}, {v!r}] overflows (not finite) after this step: allowed states and actions whose "
                "step stays a finite float"
            )
        self._state = nxt
        self._k += 1
        truncated = self._k >= t.n_steps
        info = {"t": self._k * t.dt, "force": u, "damping": c, "cost": cost}
        return self._state.copy(), -cost, False, truncated, info


def register() -> None:
    """Register :data:`ENV_ID` with gymnasium (the package's ``gymnasium.envs`` entry point; idempotent)."""
    if ENV_ID not in gymnasium.registry:
        gymnasium.register(id=ENV_ID, entry_point="vibration.physics.learning.env:OscillatorEnv")


register()
