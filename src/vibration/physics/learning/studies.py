"""Studies around the learners: many seeds, robustness to plant changes, identify-then-design."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..model import Oscillator, ParameterError, check_int, check_real
from .disturbance import best_fixed_gain, exosystem_optimum
from .references import lqr_reference
from .rollouts import episode_costs, sample_initial_states
from .task import OscillatorTask, _check_gains, _check_task
from .training import train

__all__ = [
    "IdentifyDesign",
    "Robustness",
    "SeedStudy",
    "identify_then_design",
    "robustness_study",
    "seed_study",
]


@dataclass(frozen=True, kw_only=True)
class SeedStudy:
    """One learner trained from several seeds on one task, scored against a reference cost ``J_ref``."""

    method: str  # "ars" or "cma"
    seeds: np.ndarray  # (S,) seeds
    final_ratio: np.ndarray  # (S,) J / J_ref of the learned law, 1
    episodes_to_target: np.ndarray  # (S,) training episodes to come within target of J_ref (nan: never), 1
    episodes: int  # training episodes per seed, 1
    iterations: int  # iterations (ARS) or generations (CMA-ES) per seed, 1
    target: float  # relative target, 1 (0.05: within 5 %)
    reference_cost: float  # J_ref, s

    @property
    def median_ratio(self) -> float:
        return float(np.median(self.final_ratio))

    @property
    def worst_ratio(self) -> float:
        return float(np.max(self.final_ratio))

    @property
    def reached(self) -> int:
        """Seeds that came within the target, 1."""
        return int(np.sum(np.isfinite(self.episodes_to_target)))

    @property
    def median_episodes(self) -> float:
        """Median episodes to the target over the seeds (nan when half or more never reach it), 1."""
        e = np.where(np.isfinite(self.episodes_to_target), self.episodes_to_target, np.inf)
        m = float(np.median(e))
        return m if math.isfinite(m) else math.nan

    @property
    def worst_episodes(self) -> float:
        """Largest episodes to the target over the seeds (nan when a seed never reaches it), 1."""
        e = self.episodes_to_target
        return float(np.max(e)) if np.all(np.isfinite(e)) else math.nan


def seed_study(
    task: OscillatorTask | None,
    method: str,
    seeds=tuple(range(10)),
    *,
    reference_cost: float | None = None,
    target: float = 0.05,
    iterations: int | None = None,
) -> SeedStudy:
    """Train ``method`` from every seed and score each final law (exact cost where linear) against ``J_ref``.

    ``reference_cost`` defaults to the LQR cost of the task (its optimum without a disturbance).

    Examples
    --------
    >>> st = seed_study(None, "cma", seeds=(0, 1), iterations=20)
    >>> st.final_ratio.shape, bool(st.worst_ratio < 1.05)
    ((2,), True)
    """
    task = _check_task(task)
    seeds = np.asarray([check_int("seed", s, low=0, high=2**32 - 2) for s in seeds], dtype=int)
    if seeds.size < 1 or seeds.size > 1000:
        raise ParameterError(f"seeds has {seeds.size} entries: allowed 1 to 1000")
    target = check_real("target", target, low=0.0, low_open=True, high=10.0)
    j_ref = lqr_reference(task).expected_cost if reference_cost is None else reference_cost
    j_ref = check_real("reference_cost", j_ref, low=0.0, low_open=True, unit="s")
    ratios, reach = [], []
    episodes = iters = 0
    for s in seeds:
        res = train(task, seed=int(s), method=method, iterations=iterations)
        ratio = res.curve_cost / j_ref
        ratios.append(float(ratio[-1]))
        hit = np.nonzero(ratio <= 1.0 + target)[0]
        reach.append(float(res.curve_episodes[hit[0]]) if hit.size else math.nan)
        episodes, iters = res.episodes, res.curve_episodes.size - 1
    return SeedStudy(
        method=method,
        seeds=seeds,
        final_ratio=np.array(ratios),
        episodes_to_target=np.array(reach),
        episodes=episodes,
        iterations=iters,
        target=target,
        reference_cost=float(j_ref),
    )


@dataclass(frozen=True, kw_only=True)
class Robustness:
    """Laws designed on the nominal plant, run on changed plants (sampled episodes, force bound applied)."""

    variations: tuple[str, ...]  # plant changes, e.g. "k −20 %"
    tasks: tuple[OscillatorTask, ...]  # the changed tasks
    laws: tuple[str, ...]  # law names
    gains: np.ndarray  # (L, 2) [K_x, K_v], N/m and N s/m
    cost: np.ndarray  # (V, L) mean episode cost, s
    stderr: np.ndarray  # (V, L) its standard error, s
    optimum: np.ndarray  # (V,) exact optimum of each changed task (forcing phase known), s
    n_episodes: int  # episodes per law and plant, 1
    seed: int


#: Plant changes of the robustness study: label, field, factor.
VARIATIONS = (
    ("nominal", None, 1.0),
    ("k −20 %", "k", 0.8),
    ("k +20 %", "k", 1.2),
    ("m +30 %", "m", 1.3),
    ("c × 4", "c", 4.0),
    ("ω −10 %", "omega", 0.9),
    ("ω +10 %", "omega", 1.1),
)


def robustness_study(task: OscillatorTask, laws: dict, n_episodes: int = 400, *, seed: int = 0) -> Robustness:
    """Run each law (name -> gains) on the task with each plant change of ``VARIATIONS`` (same episodes).

    Examples
    --------
    >>> from vibration.physics.learning import resonance_task
    >>> rb = robustness_study(resonance_task(), {"LQR": lqr_reference().gains}, n_episodes=8)
    >>> rb.cost.shape, bool(np.all(rb.cost[:, 0] >= rb.optimum))
    ((7, 1), True)
    """
    task = _check_task(task)
    if task.mode != "force":
        raise ParameterError(f"mode = {task.mode!r}: allowed mode = 'force' (the optimum is the exosystem LQ)")
    if not isinstance(laws, dict) or not laws:
        raise ParameterError(f"laws = {laws!r:.60}: allowed a non-empty {{name: gains}}")
    n_episodes = check_int("n_episodes", n_episodes, low=2, high=100_000)
    seed = check_int("seed", seed, low=0, high=2**32 - 2)
    names = tuple(str(n) for n in laws)
    gains = np.array([_check_gains(g) for g in laws.values()])
    states = sample_initial_states(task, n_episodes, np.random.default_rng(np.random.SeedSequence([seed, 14, 2])))
    tasks, cost, se, opt = [], [], [], []
    for _, fld, factor in VARIATIONS:
        t = task if fld is None else replace(task, **{fld: getattr(task, fld) * factor})
        c = episode_costs(t, gains, states)
        tasks.append(t)
        cost.append(c.mean(axis=1))
        se.append(c.std(axis=1, ddof=1) / math.sqrt(n_episodes))
        opt.append(exosystem_optimum(t).expected_cost)
    return Robustness(
        variations=tuple(v[0] for v in VARIATIONS),
        tasks=tuple(tasks),
        laws=names,
        gains=gains,
        cost=np.array(cost),
        stderr=np.array(se),
        optimum=np.array(opt),
        n_episodes=n_episodes,
        seed=seed,
    )


@dataclass(frozen=True, kw_only=True)
class IdentifyDesign:
    """Identify the plant from one short test record, then design on the fitted model."""

    duration: float  # record length, s
    samples: int  # samples of the record, 1
    noise: float  # sensor noise / rms response, 1
    fitted: np.ndarray  # (3,) m (kg), c (N s/m), k (N/m)
    stderr: np.ndarray  # (3,) their standard errors
    lqr_gains: np.ndarray  # LQR of the fitted model, [K_x, K_v]
    fixed_gains: np.ndarray  # best fixed gain of the fitted model (disturbance known), [K_x, K_v]


def identify_then_design(
    task: OscillatorTask, duration: float = 10.0, noise: float = 0.01, *, seed: int = 0
) -> IdentifyDesign:
    """Chapter 10's identification on a ``duration``-long broadband record of the plant, then LQR and the best
    fixed gain designed on the fitted model (the task's weights, horizon and disturbance).

    The record: the task's plant from rest, band-limited random force (0.1 to 2 Hz, 2 N rms), sampled
    every ``dt``, displacement with white noise of ``noise`` times its rms (seeds ``seed``, ``seed + 1``).

    Examples
    --------
    >>> from vibration.physics.learning import resonance_task
    >>> d = identify_then_design(resonance_task(), duration=10.0)
    >>> d.samples, bool(abs(d.fitted[2] - 20.0) < 1.0)
    (1001, True)
    """
    from ..twin import identify, simulated_test

    task = _check_task(task)
    duration = check_real("duration", duration, low=1.0, high=1e4, unit="s")
    noise = check_real("noise", noise, low=0.0, high=1.0)
    rec = simulated_test(Oscillator(m=task.m, c=task.c, k=task.k), duration, task.dt, noise=noise, seed=seed)
    fit = identify(rec.t, rec.force, x=rec.x)
    model = replace(task, m=fit.m, c=max(fit.c, 0.0), k=fit.k)
    return IdentifyDesign(
        duration=float(rec.t[-1]),
        samples=len(rec),
        noise=noise,
        fitted=np.array([fit.m, fit.c, fit.k]),
        stderr=np.asarray(fit.stderr, dtype=float),
        lqr_gains=lqr_reference(replace(model, F0=0.0)).gains,
        fixed_gains=best_fixed_gain(model).gains,
    )
