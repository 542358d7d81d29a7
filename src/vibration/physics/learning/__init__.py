"""A learning controller measured against the optimum it should find (Part II).

Modules, by concept: :mod:`.task` (the task and its exact step), :mod:`.rollouts` (compiled
episodes), :mod:`.references` (exact costs, LQR, the best passive damper), :mod:`.training`
(policies and learners) and :mod:`.comparisons` (controllers side by side, self-checks).

The task
--------
:class:`OscillatorTask` is the paper's oscillator ``m x'' + c x' + k x = u + F0 sin(omega t)``
sampled every ``dt`` with an exact zero-order hold: the action is held constant over each
step and the state is propagated by the matrix exponential, not by an integrator. The
observation is the state ``s = [x, v]`` (m, m/s). Two modes:

* ``mode="force"``: the action is a force ``u`` (N) on the mass, bounded by ``|u| <= u_max``;
* ``mode="damping"`` (semi-active): the action is the damping coefficient ``c`` (N s/m) of the
  oscillator's damper, in ``[c_min, c_max]``; it replaces the passive ``c`` and is held over the
  step, so the damper force ``-c v(t)`` follows the velocity within the step. Its "control force"
  is that damper force, ``u = -c v``.

Cost
----
Step ``k`` starts at ``t_k = k dt`` in state ``s_k`` (the observation the action is chosen on)
and costs ``(q_x x_k**2 + q_v v_k**2 + r u_k**2) dt``; the gymnasium reward is its negative.
An episode is ``n_steps`` steps from ``s_0`` uniform in ``[-x0_max, x0_max] x [-v0_max, v0_max]``,
and the disturbance starts at phase 0 at ``t = 0``. The **episode cost** is the sum of the
step costs (``= -`` the episode's return); the **expected cost** is its mean over the
initial-state distribution. With the default weights (``q_x`` in 1/m², ``q_v`` in s²/m², ``r``
in 1/N²) every term is dimensionless and costs are in seconds.

Policies
--------
Every controller of the chapter is a *linear desired-force law* ``u_des = -K s`` with
``K = [K_x, K_v]`` (N/m, N s/m), realised by the mode's device:

* force mode: ``u = clip(-K s, -u_max, u_max)`` (``u = -K [x, v]``: positive ``K_x`` acts as a
  spring, positive ``K_v`` as a damper);
* damping mode: the damper can only produce ``-c v`` with ``c`` in ``[c_min, c_max]``, so the
  law is *clipped*: ``c = clip(K_v + K_x x / v, c_min, c_max)`` (``c = clip(K_v)`` at ``v = 0``).
  ``K = [0, c]`` is passive damping, ``K = [0, c_sky]`` clipped skyhook (on a damper anchored to
  the ground the skyhook force ``-c_sky v`` is a damper, so clipped skyhook is passive damping at
  ``clip(c_sky)``), and ``K = K_LQR`` the clipped-optimal law of Dyke et al. (1996).

The optimum and the learners
----------------------------
:func:`lqr_reference` solves the discrete algebraic Riccati equation for the sampled plant with
weights ``Q = dt diag(q_x, q_v)``, ``R = dt r`` (the same stage cost as the environment);
:func:`expected_cost` evaluates any linear force-mode law exactly (covariance recursion from the
uniform initial distribution plus the deterministic forced response), and certifies with
:func:`peak_force` that the bound ``u_max`` never binds. :func:`train` learns the two gains from
episodes only (model-free): augmented random search with antithetic directions, top-``b``
selection and steps scaled by the spread of the returns (ARS V1-t, Mania et al. 2018) or CMA-ES
(Hansen's ``cma`` package), every candidate of an iteration scored on the same freshly drawn
initial states (common random numbers).
"""

from __future__ import annotations

from . import disturbance, studies  # noqa: F401 - the disturbed task's references, studies
from .comparisons import (  # noqa: F401 - reachable as vibration.physics.learning.NAME
    Comparison,
    compare_controllers,
    verification,
)
from .references import (  # noqa: F401 - reachable as vibration.physics.learning.NAME
    LQRReference,
    PassiveOptimum,
    _largest_damper,
    _moments,
    best_passive_damping,
    expected_cost,
    lqr_reference,
    peak_force,
)
from .rollouts import (  # noqa: F401 - reachable as vibration.physics.learning.NAME
    Rollouts,
    episode_costs,
    rollout,
    sample_initial_states,
)
from .task import (  # noqa: F401 - reachable as vibration.physics.learning.NAME
    MAX_EPISODE_STEPS,
    MAX_RECORDED_STEPS,
    MAX_STATES,
    METHODS,
    MODES,
    OscillatorTask,
    _check_task,
    _particular,
    _zoh,
    disturbance_increments,
    resonance_task,
    semi_active_task,
    zoh,
)
from .training import (  # noqa: F401 - reachable as vibration.physics.learning.NAME
    DEFAULTS,
    LinearPolicy,
    TrainingResult,
    train,
)

# Exported at the top level (``vibration.<name>``); the rest is in ``vibration.learn``.
__all__ = [
    "LQRReference",
    "LinearPolicy",
    "OscillatorTask",
    "PassiveOptimum",
    "Rollouts",
    "TrainingResult",
    "best_passive_damping",
    "lqr_reference",
    "resonance_task",
    "semi_active_task",
]
