"""The learning chapter's computation: the optimum, the learners, and the tasks without a closed form.

Pure computation on :mod:`vibration.physics.learning`; everything is returned in one frozen
:class:`LearningStudy`, and the sentences, tables and figures (modules ``text`` and ``figures``)
are functions of it. Choices, stated once:

* **The tasks.** The base task is the paper's oscillator with a force actuator and no disturbance
  (its optimum is the discrete LQR). The *resonance task* adds ``F0 sin(omega_res t)`` on the mass;
  the *semi-active task* replaces the force by a damper whose coefficient is the action, in
  ``[c_semi_min, c_semi_max]``, under the same force.
* **The learners.** ARS and CMA-ES train the two gains of ``u = -K [x, v]`` from ``K = [0, 0]``
  with their default budgets; the seed study repeats each from ``n_seeds`` seeds, starting at ``seed``.
* **The comparisons.** Every controller of a task is rolled out on the same ``n_eval`` seeded
  episodes (not the training episodes); two controllers differ when their paired mean difference
  exceeds :data:`RESOLVED_Z` standard errors. The robustness study uses :data:`ROBUST_EPISODES`
  episodes per changed plant.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from vibration.book.chapters.learning.params import Params
from vibration.physics.learning import (
    Comparison,
    LQRReference,
    OscillatorTask,
    PassiveOptimum,
    TrainingResult,
    _moments,
    best_passive_damping,
    compare_controllers,
    lqr_reference,
    train,
    verification,
)
from vibration.physics.learning.disturbance import (
    CostCurvature,
    ExosystemOptimum,
    FixedGainOptimum,
    best_fixed_gain,
    cost_hessian,
    exosystem_optimum,
)
from vibration.physics.learning.studies import (
    IdentifyDesign,
    Robustness,
    SeedStudy,
    identify_then_design,
    robustness_study,
    seed_study,
)
from vibration.physics.model import check_real

#: Learners, in the order the chapter shows them.
METHODS = ("ars", "cma")
#: Two mean costs on the same episodes differ when their paired difference exceeds this many standard errors.
RESOLVED_Z = 3.0
#: Relative targets of the learning curves: within 5 % and within 1 % of the optimum.
TARGETS = (0.05, 0.01)
#: Episodes per changed plant in the robustness study.
ROBUST_EPISODES = 400
#: Grid points per gain of the cost surface drawn under the learners' paths.
SURFACE_POINTS = 61

#: Controllers of the force-actuator task under the resonance force, in table order.
ACTIVE = ("no control", "best passive damper", "LQR", "learned (ARS)", "best fixed gain", "identified, then designed")
#: Controllers of the semi-active task, in table order.
SEMI = ("plant damping", "best constant damping", "clipped skyhook", "clipped LQR", "learned (ARS)")
#: Laws of the robustness study.
ROBUST = ("LQR", "learned (ARS)", "best fixed gain")


# ----------------------------------------------------------------------------- records


@dataclass(frozen=True, kw_only=True)
class Paired:
    """Law ``b`` against law ``a`` on the same episodes: ``diff = J_b - J_a`` (s) and its standard error."""

    diff: float  # s
    se: float  # s
    base: float  # mean cost of a, s

    @property
    def rel(self) -> float:
        """``J_b / J_a - 1``, 1."""
        return self.diff / self.base

    @property
    def rel_se(self) -> float:
        return self.se / self.base

    @property
    def resolved(self) -> bool:
        """The difference exceeds :data:`RESOLVED_Z` standard errors."""
        return abs(self.diff) > RESOLVED_Z * self.se


@dataclass(frozen=True, eq=False, kw_only=True)
class CostSurface:
    """Exact expected cost of the unclipped linear law on a grid of gains (no disturbance)."""

    kx: np.ndarray = field(repr=False)  # (nx,) N/m
    kv: np.ndarray = field(repr=False)  # (nv,) N s/m
    cost: np.ndarray = field(repr=False)  # (nv, nx) s; inf where the sampled loop is unstable


@dataclass(frozen=True, eq=False, kw_only=True)
class LearningStudy:
    """Every result the learning chapter shows, at one set of parameters."""

    params: Params
    task: OscillatorTask  # force actuator, no disturbance
    ref: LQRReference  # its optimum
    learners: tuple[TrainingResult, ...]  # one per METHODS, on `task`
    seeds: tuple[SeedStudy, ...]  # one per METHODS
    curvature: CostCurvature  # of J at the LQR gains
    surface: CostSurface
    res_task: OscillatorTask  # force actuator, resonance force
    semi_task: OscillatorTask  # semi-active damper, resonance force
    learned_res: TrainingResult  # ARS on res_task
    learned_semi: TrainingResult  # ARS on semi_task
    exo: ExosystemOptimum  # res_task's exact optimum, forcing phase known
    fixed: FixedGainOptimum  # best law of [x, v] on res_task
    id_design: IdentifyDesign  # identify from one record, then design
    passive_res: PassiveOptimum
    passive_semi: PassiveOptimum
    active: Comparison  # controllers ACTIVE on res_task
    semi: Comparison  # controllers SEMI on semi_task
    robust: Robustness  # laws ROBUST on changed plants
    checks: dict = field(repr=False)  # verification residuals, relative

    def learner(self, method: str) -> TrainingResult:
        return self.learners[METHODS.index(method)]

    def seed_result(self, method: str) -> SeedStudy:
        return self.seeds[METHODS.index(method)]

    def ratio(self, res: TrainingResult) -> float:
        """Learned expected cost over the optimum ``J / J*``, 1."""
        return res.expected_cost / self.ref.expected_cost

    def episodes_to(self, res: TrainingResult, target: float) -> float:
        """Training episodes until the curve first comes within ``target`` of ``J*`` (nan: never), 1."""
        ok = np.nonzero(res.curve_cost <= (1.0 + target) * self.ref.expected_cost)[0]
        return float(res.curve_episodes[ok[0]]) if ok.size else math.nan

    def a(self, name: str) -> int:
        """Index of a controller of the force-actuator comparison."""
        return ACTIVE.index(name)

    def s(self, name: str) -> int:
        """Index of a controller of the semi-active comparison."""
        return SEMI.index(name)

    def paired(self, cmp: Comparison, a: int, b: int) -> Paired:
        """Law ``b`` against law ``a`` on the comparison's common episodes."""
        d, se = cmp.paired_gain(a, b)
        return Paired(diff=d, se=se, base=cmp.runs[a].mean_cost)

    def learned_vs(self, name: str) -> Paired:
        """The learned law against a controller of the force-actuator comparison (``rel > 0``: learned costs more)."""
        return self.paired(self.active, self.a(name), self.a("learned (ARS)"))

    def semi_vs(self, name: str) -> Paired:
        """The learned clipped law against a controller of the semi-active comparison."""
        return self.paired(self.semi, self.s(name), self.s("learned (ARS)"))

    @property
    def excess_over_optimum(self) -> tuple[float, float]:
        """The learned law's mean cost over the exact optimum of the resonance task, ``- 1``, and its error."""
        run = self.active.runs[self.a("learned (ARS)")]
        return run.mean_cost / self.exo.expected_cost - 1.0, run.cost_sem / self.exo.expected_cost

    @property
    def identify_vs_learned(self) -> Paired:
        """Identify-then-design against the learned law (``rel > 0``: the designed law costs more)."""
        return self.paired(self.active, self.a("learned (ARS)"), self.a("identified, then designed"))

    @property
    def training_steps(self) -> int:
        """Simulated steps the resonance learner trained on, 1."""
        return self.learned_res.episodes * self.res_task.n_steps

    def bound_fraction(self, i: int) -> float:
        """Fraction of the steps (v != 0) at which the damping of semi-active controller ``i`` sits on a bound."""
        run, t = self.semi.runs[i], self.semi_task
        v = run.v.ravel()
        ok = v != 0.0
        c = -run.u.ravel()[ok] / v[ok]
        tol = 1e-9 * t.c_max
        return float(np.mean((np.abs(c - t.c_min) <= tol) | (np.abs(c - t.c_max) <= tol)))

    def robust_ratio(self) -> np.ndarray:
        """(plant change, law): cost over the changed plant's exact optimum, 1."""
        return self.robust.cost / self.robust.optimum[:, None]


# ----------------------------------------------------------------------------- the computation


def _surface(task: OscillatorTask, ref: LQRReference, learners) -> CostSurface:
    """The cost surface over a box that holds every learner's path and the optimum."""
    kx_all = np.concatenate([r.curve_gains[:, 0] for r in learners] + [[ref.gains[0]]])
    kv_all = np.concatenate([r.curve_gains[:, 1] for r in learners] + [[ref.gains[1]]])
    span_x = max(float(np.ptp(kx_all)), 1e-3 * task.k, 1.0)
    span_v = max(float(np.ptp(kv_all)), 1.0)
    kx = np.linspace(kx_all.min() - 0.15 * span_x, kx_all.max() + 0.15 * span_x, SURFACE_POINTS)
    kv = np.linspace(kv_all.min() - 0.15 * span_v, kv_all.max() + 0.15 * span_v, SURFACE_POINTS)
    cost = np.array([[_moments(task, np.array([a, b]))[0] for a in kx] for b in kv])
    return CostSurface(kx=kx, kv=kv, cost=cost)


def learning_study(params: Params | None = None, **values) -> LearningStudy:
    """The learning chapter on one parameter record: the optimum, the learners and the harder tasks.

    ``params`` is the chapter's validated record (the task's step, horizon, force weight and limit, the
    damper's range, the seeds and the evaluation episodes), or the values are given as keyword arguments
    and checked by the schema; the plant must be passive (``c_nominal >= 0``). Returns the frozen
    :class:`LearningStudy`.
    """
    p = params if params is not None else Params.from_values(values)
    check_real("c_nominal", p.c_nominal, low=0.0, unit="N s/m")  # a learner needs a passive plant
    task = OscillatorTask(m=p.m, c=p.c_nominal, k=p.k, dt=p.dt, n_steps=p.n_steps, r=p.r_weight, u_max=p.u_max)
    ref = lqr_reference(task)
    learners = tuple(train(task, seed=p.seed, method=m) for m in METHODS)
    seeds = tuple(seed_study(task, m, seeds=range(p.seed, p.seed + p.n_seeds)) for m in METHODS)
    res_task = replace(task, F0=p.F0, omega=p.omega_res)
    semi_task = replace(res_task, mode="damping", c_min=p.c_semi_min, c_max=p.c_semi_max)
    learned_res = train(res_task, seed=p.seed)
    learned_semi = train(semi_task, seed=p.seed)
    exo = exosystem_optimum(res_task)
    fixed = best_fixed_gain(res_task)
    id_design = identify_then_design(res_task, seed=p.seed)
    passive_res = best_passive_damping(res_task)
    passive_semi = best_passive_damping(semi_task)
    active_gains = (
        [0.0, 0.0],
        [0.0, passive_res.c],
        ref.gains,
        learned_res.gains,
        fixed.gains,
        id_design.fixed_gains,
    )
    semi_gains = ([0.0, p.c_nominal], [0.0, passive_semi.c], [0.0, ref.gains[1]], ref.gains, learned_semi.gains)
    active = compare_controllers(res_task, dict(zip(ACTIVE, active_gains, strict=True)), p.n_eval, seed=p.seed)
    semi = compare_controllers(semi_task, dict(zip(SEMI, semi_gains, strict=True)), p.n_eval, seed=p.seed)
    laws = dict(zip(ROBUST, (ref.gains, learned_res.gains, fixed.gains), strict=True))
    robust = robustness_study(res_task, laws, ROBUST_EPISODES, seed=p.seed)
    return LearningStudy(
        params=p,
        task=task,
        ref=ref,
        learners=learners,
        seeds=seeds,
        curvature=cost_hessian(task, ref.gains),
        surface=_surface(task, ref, learners),
        res_task=res_task,
        semi_task=semi_task,
        learned_res=learned_res,
        learned_semi=learned_semi,
        exo=exo,
        fixed=fixed,
        id_design=id_design,
        passive_res=passive_res,
        passive_semi=passive_semi,
        active=active,
        semi=semi,
        robust=robust,
        checks=verification(task, ref.gains),
    )
