"""Chapter 3's computation, run once: every integrator against the exact solution, RK45 on its own steps.

:func:`solver_accuracy_study` runs each method of a tolerance ladder on the resonance case from
rest and measures it against the closed form, runs RK45 on its own steps (no output grid) at the
paper's tolerance and a tight one, and identifies SciPy's Runge–Kutta pair from its nodes. The
figures, tables and sentences only read the one :class:`SolverStudy` it returns, so a run with other
parameters never contradicts itself.

Examples
--------
>>> st = solver_accuracy_study(t_end=10.0, n_points=1001)
>>> st.pair
'Dormand-Prince 5(4)'
>>> [(r.method, r.rtol, r.atol) for r in st.runs][:2]        # tolerances: 1, m and m/s
[('RK45', 0.001, 1e-06), ('RK45', 1e-05, 1e-08)]
>>> st.paper.err_x < 0.05 * st.peak                          # the paper's RK45, m
True
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from vibration.book.chapters.solver_accuracy.params import Params
from vibration.physics.audit import RK_PAIRS, rk45_pair, scipy_rk45_nodes
from vibration.physics.exact import Response, exact_response
from vibration.physics.model import N_POINTS_MAX, Oscillator, SineForce
from vibration.physics.numerics import simulate

#: Relative tolerances of each method's ladder (the absolute tolerance is one thousandth of it,
#: except at rtol = 1e-3 where it is SciPy's default 1e-6).
LADDER = {
    "RK45": (1e-3, 1e-5, 1e-7, 1e-9),
    "DOP853": (1e-3, 1e-5, 1e-7, 1e-9),
    "LSODA": (1e-3, 1e-5, 1e-7, 1e-9),
    "Radau": (1e-3, 1e-4),
}

#: Methods whose step sequence changes with the last bit of the input: LSODA switches between Adams and
#: BDF formulas and picks its order adaptively, so a change of F0 by one unit in the last place moves its
#: evaluations by up to about 10 % and its errors by up to a factor of 4 (measured at every rtol of the
#: ladder); a different CPU or maths library does the same. Their counts and errors print as ≈ cells.
MACHINE_DEPENDENT = frozenset({"LSODA"})

#: Relative tolerances of the own-steps comparison: the paper's, and a tight one.
STEP_RTOLS = (1e-3, 1e-6)

#: The last part of the window in which the own-steps peaks are compared (fraction of t_end).
LATE = 0.2

#: Forcing periods drawn by the own-steps figure (the last ones of the window).
STEP_PERIODS = 5


def atol_for(rtol: float) -> float:
    """Absolute tolerance (m and m/s) paired with ``rtol``: SciPy's default 1e-6 at 1e-3, else rtol/1000."""
    return 1e-6 if rtol == 1e-3 else rtol * 1e-3


@dataclass(frozen=True, kw_only=True)
class LadderRun:
    """One method at one tolerance, against the exact solution on the output grid."""

    method: str  # solve_ivp method name
    rtol: float  # relative tolerance, 1
    atol: float  # absolute tolerance, m (displacement) and m/s (velocity)
    nfev: int  # right-hand-side evaluations
    err_x: float  # worst |x - x_exact| over the output samples, m
    err_v: float  # worst |v - v_exact|, m/s
    rel_err_x: float  # err_x over the exact peak |x|, 1
    time_s: float  # wall time of the run on this machine, s (varies between runs and machines)

    @property
    def machine_dependent(self) -> bool:
        """True when the run's digits depend on last-bit rounding (see :data:`MACHINE_DEPENDENT`)."""
        return self.method in MACHINE_DEPENDENT


@dataclass(frozen=True, kw_only=True)
class OwnSteps:
    """RK45 returning only its own steps (no output grid), and the peaks a line through them reaches."""

    rtol: float  # relative tolerance, 1
    atol: float  # absolute tolerance, m and m/s
    steps: int  # accepted steps in the window
    max_step: float  # largest step, s
    per_period: float  # mean steps per forcing period
    late_mean_peak: float  # mean over the late half periods of the largest |x| among the steps, m
    late_low_peak: float  # the smallest of those, m
    late_exact_peak: float  # exact peak |x| in the same late part of the window, m

    @property
    def shortfall(self) -> float:
        """How far the mean peak of the steps falls below the exact peak, as a fraction of it."""
        return 1.0 - self.late_mean_peak / self.late_exact_peak if self.late_exact_peak > 0 else 0.0


@dataclass(frozen=True, kw_only=True)
class Reach:
    """The error every method reaches (m), and the fewest evaluations with which each method reaches it.

    The common error is the largest of the methods' best errors, taken over the methods whose digits do not
    depend on the machine (:data:`MACHINE_DEPENDENT`), so that their last bits cannot move it.
    """

    target: float  # m
    cost: tuple[tuple[str, int], ...]  # (method, evaluations), ladder order; a machine-dependent one may miss it

    @property
    def cheapest(self) -> str:
        """The method that reaches the common error with the fewest evaluations."""
        return min(self.cost, key=lambda mc: mc[1])[0]

    def evaluations(self, method: str) -> int | None:
        """Evaluations ``method`` needs to reach the common error (None if it does not reach it)."""
        return dict(self.cost).get(method)


@dataclass(frozen=True, kw_only=True)
class SolverStudy:
    """Every run of chapter 3, done once (SI units)."""

    params: Params
    osc: Oscillator  # the resonance case's oscillator (kg, N s/m, N/m)
    force: SineForce  # its forcing (N, rad/s)
    exact: Response  # closed form on the output grid (s, m, m/s)
    runs: tuple[LadderRun, ...]  # the ladder, method by method, loosest tolerance first
    steps: tuple[OwnSteps, ...]  # one per STEP_RTOLS
    own: Response  # RK45 at SciPy's defaults on its own steps (s, m, m/s)
    pair: str  # name of SciPy's RK45 pair
    nodes: tuple[Fraction, ...]  # its nodes c_i
    pairs: tuple[tuple[str, tuple[Fraction, ...]], ...]  # the candidate pairs and their nodes

    @property
    def t_end(self) -> float:
        """End of the window, s."""
        return self.params.t_end

    @property
    def period(self) -> float:
        """Forcing period 2π/ω, s."""
        return 2.0 * math.pi / self.force.omega

    @property
    def peak(self) -> float:
        """Exact peak |x| in the window, m."""
        return float(np.max(np.abs(self.exact.x)))

    @property
    def paper(self) -> LadderRun:
        """The paper's method: RK45 at SciPy's default tolerances."""
        return self.runs[0]

    @property
    def methods(self) -> tuple[str, ...]:
        """The ladder's methods, in order."""
        return tuple(dict.fromkeys(r.method for r in self.runs))

    def ladder(self, method: str) -> tuple[LadderRun, ...]:
        """The runs of one method, loosest tolerance first."""
        return tuple(r for r in self.runs if r.method == method)

    @property
    def reach(self) -> Reach:
        """The common error and each method's cost to reach it."""
        stable = [m for m in self.methods if m not in MACHINE_DEPENDENT] or list(self.methods)
        target = max(min(r.err_x for r in self.ladder(m)) for m in stable)
        cost = []
        for m in self.methods:
            reached = [r.nfev for r in self.ladder(m) if r.err_x <= target]
            if reached:
                cost.append((m, min(reached)))
        return Reach(target=target, cost=tuple(cost))

    @property
    def step_window(self) -> tuple[float, float]:
        """Time span of the own-steps figure: the last :data:`STEP_PERIODS` forcing periods, s."""
        return max(0.0, self.t_end - STEP_PERIODS * self.period), self.t_end


def _ladder_run(osc: Oscillator, force: SineForce, t_end: float, n: int, exact: Response, method: str, rtol: float):
    peak = float(np.max(np.abs(exact.x)))
    start = time.perf_counter()
    r = simulate(osc, force, t_end, n_points=n, method=method, rtol=rtol, atol=atol_for(rtol))
    elapsed = time.perf_counter() - start
    err_x = float(np.max(np.abs(r.x - exact.x)))
    return LadderRun(
        method=method,
        rtol=rtol,
        atol=atol_for(rtol),
        nfev=int(r.nfev),
        err_x=err_x,
        err_v=float(np.max(np.abs(r.v - exact.v))),
        rel_err_x=err_x / peak if peak > 0 else math.inf,
        time_s=elapsed,
    )


def _own_steps(r: Response, rtol: float, t_end: float, period: float, late_exact: float) -> OwnSteps:
    dt = np.diff(r.t)
    late = r.t >= (1 - LATE) * t_end
    half = np.floor(r.t[late] / (0.5 * period))  # index of the half period of each late step
    per_half = [float(np.max(np.abs(r.x[late][half == h]))) for h in np.unique(half)[1:-1]]
    return OwnSteps(
        rtol=rtol,
        atol=atol_for(rtol),
        steps=int(dt.size),
        max_step=float(np.max(dt)),
        per_period=float(period / np.mean(dt)),
        late_mean_peak=float(np.mean(per_half)) if per_half else math.nan,
        late_low_peak=float(np.min(per_half)) if per_half else math.nan,
        late_exact_peak=late_exact,
    )


def solver_accuracy_study(params: Params | None = None, **values) -> SolverStudy:
    """Run the ladder, the own-steps comparison and the pair identification once.

    Parameters
    ----------
    params : Params, optional
        The chapter's validated parameters (m kg, k N/m, F0 N, t_end s, omega_res rad/s, c_nominal N s/m,
        n_points); or give some of them as keyword arguments (the rest keep their defaults).

    Returns
    -------
    SolverStudy
        Frozen record of every run.

    Examples
    --------
    >>> solver_accuracy_study(n_points=1)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: n_points = 1 is out of range: allowed ...
    """
    p = params if params is not None else Params.from_values(values)
    osc, force = Oscillator(m=p.m, c=p.c_nominal, k=p.k), SineForce(F0=p.F0, omega=p.omega_res)
    t = np.linspace(0.0, p.t_end, p.n_points)
    exact = exact_response(osc, force, t)
    runs = tuple(
        _ladder_run(osc, force, p.t_end, p.n_points, exact, method, rtol)
        for method, rtols in LADDER.items()
        for rtol in rtols
    )
    late_exact = float(np.max(np.abs(exact.x[t >= (1 - LATE) * p.t_end])))
    period = 2.0 * math.pi / p.omega_res
    own = [
        simulate(osc, force, p.t_end, n_points=N_POINTS_MAX, rtol=rtol, atol=atol_for(rtol), t_eval=False)
        for rtol in STEP_RTOLS
    ]
    steps = tuple(_own_steps(r, rtol, p.t_end, period, late_exact) for r, rtol in zip(own, STEP_RTOLS, strict=True))
    return SolverStudy(
        params=p,
        osc=osc,
        force=force,
        exact=exact,
        runs=runs,
        steps=steps,
        own=own[0],
        pair=rk45_pair(),
        nodes=tuple(scipy_rk45_nodes()),
        pairs=tuple((name, tuple(nodes)) for name, nodes in RK_PAIRS.items()),
    )
