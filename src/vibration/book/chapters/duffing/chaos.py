"""Chapter 9's chaotic case: Ueda's oscillator ``x'' + c_U x' + x^3 = F_U cos(omega t)``.

Poincaré sections of the chaotic and the periodic forcing, the largest Lyapunov exponent from runs that
share no trajectory (variational equations with QR, a standard error from batch means), pooled and set
against the published value, the two methods (QR and Benettin) side by side, the periodic case's exponents
against its Floquet multipliers, and the chaos map over forcing frequency and amplitude.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from vibration.book.chapters.duffing.params import Params
from vibration.physics.duffing import (
    MAX_RK4_STEPS,
    Duffing,
    LyapunovEstimate,
    lyapunov_benettin,
    lyapunov_estimate,
    lyapunov_qr,
    periodic_orbit,
    poincare_section,
    pooled_exponent,
)
from vibration.physics.model import ParameterError

#: The published largest Lyapunov exponent of Ueda's oscillator ``x'' + 0.05 x' + x^3 = 7.5 cos t``, 1/s (natural
#: logarithm, per unit time): J. C. Sprott, *Chaos and Time-Series Analysis* (Oxford University Press, 2003), the
#: table of Lyapunov exponents of common chaotic flows (0.0999, 0, -0.1499 for the flow with time as a third
#: variable). The averaging length is not stated there; a reproduction of the table states RK4 with step 0.001 s.
PUBLISHED_UEDA = {"exponent": 0.0999, "c": 0.05, "F0": 7.5, "step": 0.001}

#: Initial states (m, m/s) and RK4 steps per period of the chaotic runs; the first is the main run.
LYAPUNOV_RUNS = (((3.0, 0.0), 400), ((0.0, 0.0), 400), ((1.0, 1.0), 400), ((-2.0, 3.0), 400), ((3.0, 0.0), 200),
                 ((3.0, 0.0), 800))  # fmt: skip
#: Start of the Poincaré sections and of the periodic case's exponents (m, m/s).
UEDA_START = (3.0, 0.0)
#: Lengths (forcing periods) at which the convergence of the main run is shown, below its full length.
CONVERGENCE_LENGTHS = (1000, 2000, 5000, 10_000, 20_000, 50_000, 100_000)
#: Ueda's chaos map in the chapter: forcing frequencies (rad/s) and amplitudes (N) of its grid, and the periods of
#: each of its runs (the chapter's time budget; ``python -m vibration.report sweep 09 -g omega_ueda ... -g F0_ueda ...
#: -p n_lyapunov N`` computes the same map at any resolution).
MAP_OMEGAS, MAP_FORCES, MAP_PERIODS = np.linspace(0.5, 1.5, 9), np.linspace(1.0, 13.0, 7), 100
#: Periods of the periodic case's exponents (at most), of the other chaotic runs (at most), of the sections.
N_PERIODIC, N_OTHER_RUNS, N_SECTION = 5000, 20_000, 3000


@dataclass(frozen=True, kw_only=True)
class Pooled:
    """Inverse-variance pooled exponent of runs that share no trajectory (1/s) and their chi-square."""

    mean: float
    standard_error: float
    chi2: float
    dof: int

    @property
    def consistent(self) -> bool:
        """Whether the runs agree within their errors: chi2 at most dof + 3 standard deviations of chi2(dof)."""
        return self.chi2 <= self.dof + 3.0 * math.sqrt(2.0 * self.dof)

    @property
    def sign(self) -> int:
        """+1 (positive beyond three standard errors), -1 (negative beyond them) or 0 (not distinguishable)."""
        if self.mean - 3.0 * self.standard_error > 0:
            return 1
        if self.mean + 3.0 * self.standard_error < 0:
            return -1
        return 0


@dataclass(frozen=True, kw_only=True)
class Published:
    """The pooled exponent against the published one (only meaningful when ``applies``)."""

    exponent: float  # published, 1/s
    c: float  # its damping, N s/m
    F0: float  # its forcing, N
    step: float  # its RK4 step, s
    applies: bool  # whether the run's Ueda oscillator is the published one
    delta: float  # pooled less published, 1/s
    z: float  # delta in pooled standard errors
    sigma1: float  # scatter of a one-period average, 1/s (from the main run's batch means)
    n_needed: float  # periods below which a run misses the long-run value by |delta| with probability above 5 %
    step_z: tuple[tuple[int, float], ...]  # (steps per period, (run - pooled) / its error) of the other step sizes


@dataclass(frozen=True, kw_only=True)
class ConvergenceRow:
    """The main chaotic run's estimate from its first ``n`` periods."""

    n: int
    time: float  # averaging time, s
    exponent: float  # 1/s
    standard_error: float  # 1/s


@dataclass(frozen=True, kw_only=True, eq=False)
class ChaosMap:
    """Ueda's chaos map: the pooled largest Lyapunov exponent over forcing frequency and amplitude (1/s)."""

    omegas: np.ndarray = field(repr=False)  # forcing frequencies, rad/s
    forces: np.ndarray = field(repr=False)  # force amplitudes, N
    exponent: np.ndarray = field(repr=False)  # [force, omega], 1/s
    standard_error: np.ndarray = field(repr=False)  # [force, omega], 1/s
    n_periods: int  # periods of each run (the main run's n_lyapunov at every point)

    @property
    def chaotic(self) -> np.ndarray:
        """Points whose exponent is positive beyond three standard errors."""
        return self.exponent - 3.0 * self.standard_error > 0.0

    @property
    def share_chaotic(self) -> float:
        """Share of the grid's points that are chaotic, 1."""
        return float(np.mean(self.chaotic))


def _published(p: Params, pooled: Pooled, runs: tuple[LyapunovEstimate, ...]) -> Published:
    pub = PUBLISHED_UEDA
    main = runs[0]
    delta = pooled.mean - pub["exponent"]
    sigma1 = main.standard_error * math.sqrt(main.n_periods)
    z_steps = tuple(
        (e.steps_per_period, (e.exponent - pooled.mean) / e.standard_error)
        for e in runs[1:]
        if e.steps_per_period != main.steps_per_period
    )
    return Published(
        exponent=pub["exponent"],
        c=pub["c"],
        F0=pub["F0"],
        step=pub["step"],
        applies=p.c_ueda == pub["c"] and p.F0_ueda == pub["F0"] and p.omega_ueda == 1.0,
        delta=delta,
        z=delta / pooled.standard_error,
        sigma1=sigma1,
        n_needed=(2.0 * sigma1 / delta) ** 2 if delta != 0 else math.inf,
        step_z=tuple(sorted(z_steps)),
    )


def _convergence(main: LyapunovEstimate) -> tuple[ConvergenceRow, ...]:
    n_blocks = min(20, main.n_periods // 10)
    lengths = [n for n in CONVERGENCE_LENGTHS if 10 * n_blocks <= n < main.n_periods] + [main.n_periods]
    rows = []
    for n in lengths:
        lam, se = main.at(n, n_blocks)
        rows.append(ConvergenceRow(n=n, time=n * main.period, exponent=lam, standard_error=se))
    return tuple(rows)


def _lyapunov_runs(p: Params, ueda: Duffing) -> tuple[tuple[LyapunovEstimate, ...], Pooled]:
    """The independent QR runs on Ueda's oscillator at ``F0_ueda`` and their pooled largest exponent (1/s)."""
    n_blocks = min(20, p.n_lyapunov // 10)
    # the main run has n_lyapunov periods; the others at most N_OTHER_RUNS (bounded work at the parameter's extreme)
    lengths = [p.n_lyapunov] + [
        min(p.n_lyapunov, N_OTHER_RUNS, MAX_RK4_STEPS // spp - 300) for _, spp in LYAPUNOV_RUNS[1:]
    ]
    runs = tuple(
        lyapunov_estimate(
            ueda, p.F0_ueda, p.omega_ueda, x0=x0, v0=v0, n_periods=n, n_blocks=n_blocks, steps_per_period=spp
        )
        for ((x0, v0), spp), n in zip(LYAPUNOV_RUNS, lengths, strict=True)
    )
    return runs, Pooled(**dict(zip(("mean", "standard_error", "chi2", "dof"), pooled_exponent(runs), strict=True)))


@dataclass(frozen=True, kw_only=True, eq=False)
class ChaosStudy:
    """The chapter's largest Lyapunov exponent alone (what a sweep over Ueda's forcing needs), SI units."""

    params: Params
    lyap_runs: tuple[LyapunovEstimate, ...] = field(repr=False)  # main run first, QR
    pooled: Pooled  # 1/s


def chaos_study(params: Params | None = None, **values) -> ChaosStudy:
    """The pooled largest Lyapunov exponent of Ueda's oscillator at the run's ``c_ueda`` and ``F0_ueda``.

    The same runs as :func:`duffing_study`'s (so its key results equal the chapter's), without the rest of
    the chapter: the study a sweep runs at every point.

    Examples
    --------
    >>> st = chaos_study(n_lyapunov=200)
    >>> st.pooled.mean > 0, len(st.lyap_runs)   # 1/s
    (True, 6)
    """
    p = params if params is not None else Params.from_values(values)
    if not isinstance(p, Params):
        raise ParameterError(f"params = {p!r:.60} is not valid: allowed a duffing Params record or None")
    runs, pooled = _lyapunov_runs(p, Duffing(m=1.0, c=p.c_ueda, k=0.0, k3=1.0))
    return ChaosStudy(params=p, lyap_runs=runs, pooled=pooled)


def chaos_map(p: Params, omegas=MAP_OMEGAS, forces=MAP_FORCES, *, n_periods: int = MAP_PERIODS) -> ChaosMap:
    """Ueda's chaos map: :func:`chaos_study` (the sweep's study) at every forcing frequency and amplitude.

    ``p`` gives the damping ``c_ueda``; every point runs ``n_periods`` periods (at most 40 000 points).
    """
    omegas, forces = np.asarray(omegas, dtype=float), np.asarray(forces, dtype=float)
    if omegas.size * forces.size > 40_000:
        raise ParameterError(
            f"chaos map of {forces.size} x {omegas.size} points: allowed at most 40000 (the sweep command runs more)"
        )
    lam = np.empty((forces.size, omegas.size))
    se = np.empty_like(lam)
    for i, F in enumerate(forces):
        for j, w in enumerate(omegas):
            point = dataclasses.replace(p, omega_ueda=float(w), F0_ueda=float(F), n_lyapunov=int(n_periods))
            pooled = chaos_study(point).pooled
            lam[i, j], se[i, j] = pooled.mean, pooled.standard_error
    return ChaosMap(omegas=omegas, forces=forces, exponent=lam, standard_error=se, n_periods=int(n_periods))


def ueda_chaos(p: Params) -> dict:
    """The chaotic part of :func:`~vibration.book.chapters.duffing.study.duffing_study`: its fields of the study record.

    Sections, the independent QR runs and their pooled exponent, the Benettin partner of the main run, the
    periodic case's exponents by both methods and by its Floquet multipliers, the convergence of the main run,
    the comparison with the published exponent, the chaos map and the largest error of the QR exponents' sum
    against ``-c/m`` (1/s).
    """
    ueda = Duffing(m=1.0, c=p.c_ueda, k=0.0, k3=1.0)
    w_u = p.omega_ueda
    (x_u, v_u), (x_main, v_main) = UEDA_START, LYAPUNOV_RUNS[0][0]
    section_chaos = poincare_section(ueda, p.F0_ueda, w_u, x0=x_u, v0=v_u, n_periods=N_SECTION, n_transient=300)
    section_periodic = poincare_section(ueda, p.F0_ueda_periodic, w_u, x0=x_u, v0=v_u, n_periods=200, n_transient=1000)
    n_blocks = min(20, p.n_lyapunov // 10)
    runs, pooled = _lyapunov_runs(p, ueda)
    partner = lyapunov_estimate(ueda, p.F0_ueda, w_u, x0=x_main, v0=v_main, n_periods=p.n_lyapunov,
                                n_blocks=n_blocks, method="benettin")  # fmt: skip
    kw = {"n_periods": min(p.n_lyapunov, N_PERIODIC), "n_transient": 300}
    per_qr = lyapunov_qr(ueda, p.F0_ueda_periodic, p.omega_ueda, x0=x_u, v0=v_u, **kw)
    per_ben = lyapunov_benettin(ueda, p.F0_ueda_periodic, p.omega_ueda, x0=x_u, v0=v_u, **kw)
    floq = math.nan
    if np.ptp(section_periodic, axis=0).max() < 1e-6:  # period 1: its Floquet multipliers give the exponent
        orb = periodic_orbit(
            ueda, p.F0_ueda_periodic, p.omega_ueda, x0=float(section_periodic[-1, 0]), v0=float(section_periodic[-1, 1])
        )
        floq = math.log(max(abs(x) for x in orb.multipliers)) / (2 * math.pi / p.omega_ueda)
    cm = ueda.c / ueda.m
    qr_sums = [abs(e.exponent + e.second + cm) for e in runs] + [abs(sum(per_qr.exponents) + cm)]
    return {
        "ueda": ueda,
        "section_chaos": section_chaos,
        "section_periodic": section_periodic,
        "periodic_qr": per_qr,
        "periodic_benettin": per_ben,
        "lyap_runs": runs,
        "lyap_benettin": partner,
        "pooled": pooled,
        "convergence": _convergence(runs[0]),
        "floquet_periodic": floq,
        "published": _published(p, pooled, runs),
        "chaos_map": chaos_map(p),
        "qr_sum_error": max(qr_sums),
    }
