"""Linear policies and the model-free learners (augmented random search, CMA-ES)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..checks import optional
from ..duffing import _real_array
from ..model import ParameterError, check_int, check_real
from .references import _moments
from .rollouts import episode_costs, sample_initial_states
from .task import MAX_EPISODE_STEPS, METHODS, OscillatorTask, _check_gains, _check_task

# ----------------------------------------------------------------------------- policies and learning


@dataclass(frozen=True, kw_only=True)
class LinearPolicy:
    """A linear desired-force law ``u_des = -K [x, v]`` realised by the task's device.

    ``gains = [K_x, K_v]``: K_x in N/m, K_v in N s/m; the sign convention is ``u = -K [x, v]``
    (positive gains act as a spring and a damper). Calling the policy on an observation
    ``[x, v]`` (m, m/s) returns the environment's action: the force ``clip(-K s, -u_max, u_max)``
    (N) in force mode, the damping ``clip(K_v + K_x x / v, c_min, c_max)`` (N s/m) in damping mode.

    Examples
    --------
    >>> from vibration.physics.learning import semi_active_task
    >>> pol = LinearPolicy(gains=[1.0, 2.0], task=OscillatorTask())
    >>> pol(np.array([0.5, -1.0]))                    # N
    array([1.5])
    >>> LinearPolicy(gains=[1.0, 2.0], task=semi_active_task())(np.array([0.5, -1.0]))   # N s/m
    array([1.5])
    """

    gains: np.ndarray  # [K_x (N/m), K_v (N s/m)]
    task: OscillatorTask

    def __post_init__(self) -> None:
        object.__setattr__(self, "gains", _check_gains(self.gains))
        object.__setattr__(self, "task", _check_task(self.task))

    def __call__(self, observation) -> np.ndarray:
        obs = _real_array("observation", observation, max_size=2)
        if obs.size != 2:
            raise ParameterError(f"observation = {observation!r:.60} is not [x, v]: allowed two finite numbers")
        x, v = (float(z) for z in obs.reshape(2))
        kx, kv = (float(z) for z in self.gains)
        t = self.task
        if t.mode == "force":
            return np.array([min(max(-(kx * x + kv * v), -t.u_max), t.u_max)])
        c = kv + kx * x / v if v != 0.0 else kv
        c = t.c_min if not c >= t.c_min else min(c, t.c_max)
        return np.array([c])


@dataclass(frozen=True, kw_only=True)
class TrainingResult:
    """What :func:`train` learned, and how it got there.

    ``policy.gains`` (= ``gains``) are ``[K_x (N/m), K_v (N s/m)]`` for ``u_des = -K [x, v]``.
    ``curve_cost[i]`` is the expected cost (s) of the learner's current gains ``curve_gains[i]``
    after ``curve_episodes[i]`` training episodes (index 0: the initial gains): exact
    (:func:`expected_cost`) where ``curve_exact[i]``, else the mean over ``n_eval`` fixed
    evaluation episodes drawn from a seed stream separate from training's.
    """

    policy: LinearPolicy
    method: str  # "ars" or "cma"
    seed: int
    curve_episodes: np.ndarray  # training episodes used so far, 1
    curve_gains: np.ndarray  # (n, 2): K_x (N/m), K_v (N s/m)
    curve_cost: np.ndarray  # expected cost, s
    curve_exact: np.ndarray  # bool: exact (True) or sampled (False)

    @property
    def gains(self) -> np.ndarray:
        """Learned ``[K_x, K_v]``, N/m and N s/m, for ``u_des = -K [x, v]``."""
        return self.policy.gains

    @property
    def episodes(self) -> int:
        """Training episodes used, 1."""
        return int(self.curve_episodes[-1])

    @property
    def expected_cost(self) -> float:
        """Expected cost of the learned gains as in the curve's last point, s."""
        return float(self.curve_cost[-1])


def _finite_costs(costs: np.ndarray, cand: np.ndarray) -> np.ndarray:
    """The candidates' mean costs, or :class:`ParameterError` when one of them overflowed (inf)."""
    bad = np.flatnonzero(~np.isfinite(costs))
    if bad.size:
        raise ParameterError(
            f"the learner's candidate gains {cand[bad[0]].tolist()!r} destabilise the plant (the episode cost "
            "overflows): allowed smaller initial_gains, noise, step or sigma0"
        )
    return costs


def _curve_point(task, g, eval_states):
    if task.mode == "force":
        cost, peak = _moments(task, g)
        if peak <= task.u_max:
            return cost, True
    return float(episode_costs(task, g, eval_states).mean()), False


#: Default hyper-parameters per method (tuned on the default task; see the chapter).
DEFAULTS = {
    "ars": {"iterations": 100, "n_episodes": 4, "n_directions": 4, "top": 2, "step": 0.5, "noise": 0.5},
    "cma": {"iterations": 40, "n_episodes": 4, "popsize": 6, "sigma0": 3.0},
}


def train(
    task: OscillatorTask | None = None,
    seed: int = 0,
    method: str = "ars",
    *,
    iterations: int | None = None,
    n_episodes: int | None = None,
    initial_gains=(0.0, 0.0),
    n_eval: int = 64,
    **options,
) -> TrainingResult:
    """Learn the two gains of a linear law from episodes of the task (model-free, seeded).

    Each iteration draws ``n_episodes`` fresh initial states and scores every candidate gain
    vector of the iteration on those same states (common random numbers), by running the
    environment's dynamics; the learner never sees the model. Methods:

    * ``"ars"``: augmented random search (ARS), Mania, Guy and Recht (2018), "Simple random search
      provides a competitive approach to reinforcement learning", algorithm V1-t: ``n_directions``
      antithetic Gaussian perturbations of size ``noise`` (gain units), the ``top`` best kept,
      step ``step / (top sigma_R) sum (R+ - R-) delta`` with ``sigma_R`` the standard deviation of
      the kept returns.
    * ``"cma"``: CMA-ES (Hansen, ``cma`` package) from ``initial_gains`` with step ``sigma0``
      and population ``popsize``; the learner's gains are the distribution mean.

    Parameters
    ----------
    task : OscillatorTask, optional
        Task to learn (default task if omitted).
    seed : int
        Seed of every random draw (initial states, directions, CMA-ES sampling), >= 0.
    method : {"ars", "cma"}
        The learner.
    iterations : int, optional
        Iterations (ARS) or generations (CMA-ES); default ``DEFAULTS[method]["iterations"]`` (100 ARS, 40 CMA-ES).
    n_episodes : int, optional
        Initial states per iteration, shared by its candidates; default 4.
    initial_gains : array_like, shape (2,)
        Starting ``[K_x, K_v]``, N/m and N s/m (default: no control).
    n_eval : int
        Fixed evaluation episodes for the learning curve where the cost is not exact.
    **options
        ``n_directions``, ``top``, ``step``, ``noise`` (ARS) or ``popsize``, ``sigma0`` (CMA-ES).

    Returns
    -------
    TrainingResult
        ``.policy.gains`` are ``[K_x, K_v]`` for ``u_des = -K [x, v]``.

    Examples
    --------
    >>> from vibration.physics.learning import lqr_reference, semi_active_task
    >>> res = train(seed=0)
    >>> ref = lqr_reference()
    >>> bool(res.expected_cost < 1.001 * ref.expected_cost), res.episodes          # -, 1
    (True, 3200)
    """
    task = _check_task(task)
    seed = check_int("seed", seed, low=0, high=2**32 - 2)
    opts = _learner_options(method, options)
    iters, n_ep, n_eval, theta = _checked_budget(task, method, opts, iterations, n_episodes, n_eval, initial_gains)
    train_seq, eval_seq, algo_seq = np.random.SeedSequence([seed, 14]).spawn(3)
    states_rng = np.random.default_rng(train_seq)
    eval_states = sample_initial_states(task, n_eval, np.random.default_rng(eval_seq))
    episodes, gains_hist, costs, exact = [0], [theta.copy()], [], []
    c0, e0 = _curve_point(task, theta, eval_states)
    costs.append(c0)
    exact.append(e0)
    learner = _ars_iterations if method == "ars" else _cma_iterations
    for used, gains in learner(task, theta, opts, iters, n_ep, states_rng, algo_seq):
        theta = gains
        episodes.append(episodes[-1] + used)
        gains_hist.append(theta.copy())
        c, e = _curve_point(task, theta, eval_states)
        costs.append(c)
        exact.append(e)
    return TrainingResult(
        policy=LinearPolicy(gains=theta, task=task),
        method=method,
        seed=seed,
        curve_episodes=np.array(episodes),
        curve_gains=np.array(gains_hist),
        curve_cost=np.array(costs),
        curve_exact=np.array(exact),
    )


def _learner_options(method, options) -> dict:
    """The learner's hyper-parameters: :data:`DEFAULTS` of ``method`` updated with ``options`` (checked names)."""
    if not isinstance(method, str) or method not in METHODS:
        raise ParameterError(f"method = {method!r:.60} is not a learner: allowed one of {METHODS}")
    opts = dict(DEFAULTS[method])
    unknown = set(options) - set(opts) - {"iterations", "n_episodes"}
    if unknown:
        raise ParameterError(f"options = {sorted(unknown)!r} are not options of {method}: allowed {sorted(opts)}")
    opts.update(options)
    return opts


def _checked_budget(task, method, opts, iterations, n_episodes, n_eval, initial_gains):
    """``(iterations, n_episodes, n_eval, initial gains)`` checked, and the simulated steps they make up."""
    iters = check_int("iterations", opts["iterations"] if iterations is None else iterations, low=1, high=100_000)
    n_ep = check_int("n_episodes", opts["n_episodes"] if n_episodes is None else n_episodes, low=1, high=100_000)
    n_eval = check_int("n_eval", n_eval, low=1, high=1_000_000)
    theta = _check_gains(initial_gains).copy()
    if method == "ars":
        per_iteration = 2 * check_int("n_directions", opts["n_directions"], low=1, high=10_000)
    else:
        per_iteration = check_int("popsize", opts["popsize"], low=2, high=10_000)
    # every iteration simulates its candidates, and a curve point that is not exact its n_eval episodes
    work = (iters * (per_iteration * n_ep + n_eval) + n_eval) * task.n_steps
    if work > MAX_EPISODE_STEPS:
        raise ParameterError(
            f"iterations = {iters}, n_episodes = {n_ep}, n_eval = {n_eval} with {per_iteration} candidates per "
            f"iteration and n_steps = {task.n_steps} make up to {work} simulated steps: allowed at most "
            f"{MAX_EPISODE_STEPS}"
        )
    return iters, n_ep, n_eval, theta


def _ars_iterations(task, theta, opts, iters, n_ep, states_rng, algo_seq):
    """Augmented random search (V1-t) from ``theta``: yields each iteration's training episodes and new gains."""
    n_dir = check_int("n_directions", opts["n_directions"], low=1, high=10_000)
    top = check_int("top", opts["top"], low=1, high=n_dir)
    step = check_real("step", opts["step"], low=0.0, low_open=True, unit="N/m")
    noise = check_real("noise", opts["noise"], low=0.0, low_open=True, unit="N/m")
    rng = np.random.default_rng(algo_seq)
    for _ in range(iters):
        delta = rng.standard_normal((n_dir, 2))
        cand = np.concatenate([theta + noise * delta, theta - noise * delta])
        states = sample_initial_states(task, n_ep, states_rng)
        ret = -_finite_costs(episode_costs(task, cand, states).mean(axis=1), cand)
        r_plus, r_minus = ret[:n_dir], ret[n_dir:]
        best = np.argsort(-np.maximum(r_plus, r_minus), kind="stable")[:top]
        sigma = float(np.std(np.concatenate([r_plus[best], r_minus[best]])))
        if sigma > 0.0:
            theta = theta + step / (top * sigma) * ((r_plus[best] - r_minus[best]) @ delta[best])
        yield 2 * n_dir * n_ep, theta


def _cma_iterations(task, theta, opts, iters, n_ep, states_rng, algo_seq):
    """CMA-ES from ``theta``: yields each generation's training episodes and the distribution mean."""
    cma = optional("cma", extra="learn", what="CMA-ES training")

    popsize = check_int("popsize", opts["popsize"], low=2, high=10_000)
    sigma0 = check_real("sigma0", opts["sigma0"], low=0.0, low_open=True, unit="N/m")
    es = cma.CMAEvolutionStrategy(
        theta,
        sigma0,
        {"seed": int(algo_seq.generate_state(1)[0]) % (2**31 - 1) + 1, "popsize": popsize, "verbose": -9,
         "tolfun": 0.0, "tolx": 0.0, "tolfunhist": 0.0, "tolflatfitness": 10**9, "tolstagnation": 10**9,
         "maxiter": 10**9, "CMA_diagonal": False},
    )  # fmt: skip
    for _ in range(iters):
        cand = np.asarray(es.ask(), dtype=float)
        states = sample_initial_states(task, n_ep, states_rng)
        es.tell(list(cand), list(_finite_costs(episode_costs(task, cand, states).mean(axis=1), cand)))
        yield popsize * n_ep, np.asarray(es.mean, dtype=float).copy()
