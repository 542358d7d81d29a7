"""Chapter 1's computation: the paper's runs, once by its method and once exactly.

:func:`reproduction_study` builds the reference run (``omega_ref``), the resonance run (``omega_res``), both
at ``c_nominal``, and one run at ``omega_res`` for each damping of the list ``dampings`` (the paper's
0.1, 0.5 and 15 N s/m by default); it runs each distinct one by the paper's method (RK45 at SciPy's default
tolerances) and by the exact closed form on the same output times, and returns one frozen
:class:`ReproductionStudy`. The figures and tables are functions of that record.

Examples
--------
>>> st = reproduction_study(n_points=1001)
>>> [st.cases[s].regime for s in st.dampings]
['underdamped', 'underdamped', 'overdamped']
>>> [st.name(s) for s in st.dampings]
['c = 0.1 N s/m', 'c = 0.5 N s/m', 'c = 15 N s/m']
>>> [list(run) for run in st.runs]
[['reference'], ['resonance', 'damping_1'], ['damping_0'], ['damping_2']]
>>> reproduction_study(n_points=1001, dampings=[0.1, 2.0]).dampings
('damping_0', 'damping_1')
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.reproduction.params import Params
from vibration.book.presentation.findings import same_run
from vibration.book.presentation.narrative import g
from vibration.physics.exact import Response, exact_response, steady_state
from vibration.physics.frequency import settling_time
from vibration.physics.model import N_POINTS_MAX, Oscillator, SineForce, check_int
from vibration.physics.numerics import simulate
from vibration.physics.paper import Scenario


@dataclass(frozen=True, kw_only=True)
class CaseRun:
    """One scenario's findings: exact quantities and the paper's method side by side (SI units)."""

    scenario_id: str
    omega: float  # forcing frequency, rad/s
    c: float  # damping, N s/m
    omega_n: float  # natural frequency, rad/s
    zeta: float  # damping ratio, 1
    regime: str  # "underdamped", "overdamped", "critically damped", "undamped" or "unstable"
    x_ss: float  # steady amplitude, m (inf undamped at exact resonance; meaningless when c < 0)
    v_ss: float  # steady velocity amplitude, m/s
    peak_x: float  # largest |x| in the window, exact, m
    peak_v: float  # largest |v| in the window, exact, m/s
    peak_x_rk45: float  # largest |x| by the paper's method, m
    peak_v_rk45: float  # largest |v| by the paper's method, m/s
    max_err_x: float  # largest |x_RK45 - x| in the window, m
    tau: float  # time constant of the slowest free mode, s (inf when c = 0)
    t_settle: float  # 2 % settling time, s (inf when c <= 0)
    settles: bool  # whether the 2 % settling time is inside the window

    @property
    def has_steady(self) -> bool:
        """Whether a finite steady amplitude exists and is reached (c > 0, or c = 0 off resonance)."""
        return self.c >= 0 and math.isfinite(self.x_ss)

    @property
    def rel_err(self) -> float:
        """RK45's worst displacement error over the window's exact peak |x|, 1."""
        return self.max_err_x / self.peak_x if self.peak_x > 0 else 0.0

    @property
    def detuning(self) -> float:
        """omega / omega_n, 1."""
        return self.omega / self.omega_n


@dataclass(frozen=True, kw_only=True)
class ReproductionStudy:
    """Every scenario of the paper run once by its method and exactly, with its findings."""

    params: Params
    scenarios: dict  # scenario id -> Scenario, in the paper's order
    paper: dict  # scenario id -> Response of RK45 at SciPy's defaults (s; m; m/s)
    exact: dict  # scenario id -> Response of the closed form on the same times
    cases: dict  # scenario id -> CaseRun
    runs: tuple  # the distinct runs: tuples of scenario ids that are one computation

    dampings: tuple  # the ids of the damping runs at the resonant frequency, in the list's order

    def name(self, sid: str) -> str:
        """A run's name: "reference", "resonance", or its damping ("c = 0.1 N s/m")."""
        return f"c = {g(self.cases[sid].c)} N s/m" if sid in self.dampings else sid

    def run_name(self, sid: str) -> str:
        """The name of ``sid``'s run: "resonance (c = 0.5 N s/m)" when a damping's run is the resonance run."""
        run = self.run_of(sid)
        if len(run) == 1:
            return self.name(sid)
        return f"{self.name(run[0])} ({', '.join(self.name(s) for s in run[1:])})"

    @property
    def t_end(self) -> float:
        """End of the window, s."""
        return self.params.t_end

    def run_of(self, sid: str) -> tuple:
        """The ids that share ``sid``'s run (``("resonance", "damping_nominal")`` for the paper's)."""
        return next(run for run in self.runs if sid in run)

    @property
    def worst(self) -> CaseRun:
        """The case where RK45's error is largest relative to the window's peak."""
        return max(self.cases.values(), key=lambda f: f.rel_err)

    @property
    def largest(self) -> CaseRun:
        """The damping case with the largest peak |x| in the window."""
        return max((self.cases[s] for s in self.dampings), key=lambda f: f.peak_x)

    @property
    def lightest(self) -> CaseRun:
        """The damping case with the smallest damping coefficient."""
        return min((self.cases[s] for s in self.dampings), key=lambda f: f.c)

    @property
    def ratio(self) -> float:
        """Steady amplitude at resonance over the reference one (nan when either does not exist)."""
        res, ref = self.cases["resonance"], self.cases["reference"]
        if not (res.has_steady and ref.has_steady and ref.x_ss > 0):
            return math.nan
        return res.x_ss / ref.x_ss


def _case(sc: Scenario, paper: Response, exact: Response) -> CaseRun:
    osc, force = sc.oscillator, sc.force
    ss = steady_state(osc, force)
    ts = settling_time(osc, force)
    return CaseRun(
        scenario_id=sc.scenario_id,
        omega=force.omega,
        c=osc.c,
        omega_n=osc.natural_frequency,
        zeta=osc.damping_ratio,
        regime=osc.regime,
        x_ss=ss.amplitude,
        v_ss=ss.velocity_amplitude,
        peak_x=float(np.max(np.abs(exact.x))),
        peak_v=float(np.max(np.abs(exact.v))),
        peak_x_rk45=float(np.max(np.abs(paper.x))),
        peak_v_rk45=float(np.max(np.abs(paper.v))),
        max_err_x=float(np.max(np.abs(paper.x - exact.x))),
        tau=osc.time_constant,
        t_settle=ts,
        settles=bool(ts <= sc.t_end),
    )


def reproduce(scenarios: dict[str, Scenario], n_points: int, params: Params) -> ReproductionStudy:
    """Run the paper's method and the closed form once per distinct scenario (``n_points`` samples each)."""
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    paper, exact, runs = {}, {}, []
    for sid, sc in scenarios.items():
        twin = next((run for run in runs if same_run(scenarios[run[0]], sc)), None)
        if twin is None:
            p = simulate(sc.oscillator, sc.force, sc.t_end, n_points=n_points, x0=sc.x0, v0=sc.v0)
            paper[sid], exact[sid] = p, exact_response(sc.oscillator, sc.force, p.t, x0=sc.x0, v0=sc.v0)
            runs.append((sid,))
        else:
            paper[sid], exact[sid] = paper[twin[0]], exact[twin[0]]
            runs[runs.index(twin)] = (*twin, sid)
    cases = {sid: _case(sc, paper[sid], exact[sid]) for sid, sc in scenarios.items()}
    return ReproductionStudy(
        params=params, scenarios=dict(scenarios), paper=paper, exact=exact, cases=cases, runs=tuple(runs),
        dampings=tuple(s for s in scenarios if s.startswith("damping_")),
    )  # fmt: skip


def scenarios(p: Params) -> dict[str, Scenario]:
    """The reference and resonance runs at ``c_nominal``, then one run per damping of ``p.dampings`` at resonance."""
    rows = [("reference", "Reference case (far from resonance)", "", p.c_nominal, p.omega_ref),
            ("resonance", "Resonance case", "Figure 1", p.c_nominal, p.omega_res)]  # fmt: skip
    rows += [(f"damping_{i}", f"Damping c = {c!r} N s/m at resonance", "Figure 2", c, p.omega_res)
             for i, c in enumerate(p.dampings)]  # fmt: skip
    return {
        sid: Scenario(
            scenario_id=sid,
            label=label,
            figure=fig,
            oscillator=Oscillator(m=p.m, c=c, k=p.k),
            force=SineForce(F0=p.F0, omega=w),
            t_end=p.t_end,
            x0=0.0,
            v0=0.0,
        )  # fmt: skip
        for sid, label, fig, c, w in rows
    }


def reproduction_study(params: Params | None = None, **values) -> ReproductionStudy:
    """The paper's five runs, repeated with its RK45 settings and computed exactly, and what each shows.

    ``params`` are the validated parameters; without it, keyword arguments are checked by the schema.

    Returns
    -------
    ReproductionStudy
        Frozen record of every run and finding the chapter shows.
    """
    p = params if params is not None else Params.from_values(values)
    return reproduce(scenarios(p), p.n_points, p)
