r"""Chapter 9, the Duffing oscillator: the whole computation, once, into frozen records (SI units, no prose).

The paper's oscillator with a cubic spring,

.. math::

    m\ddot x + c\dot x + kx + k_3x^3 = F_0\cos\omega t,

is studied two independent ways: harmonic balance (one harmonic, closed form, stability from the
slow flow) against the full equation (periodic orbits by shooting with their Floquet multipliers,
continued through the bistable band; stepped frequency sweeps by time integration). The paper's
resonance scenario is re-run with the hardening spring, and Ueda's oscillator
:math:`\ddot x + c_U\dot x + x^3 = F_U\cos t` gives the chaotic case with its largest Lyapunov
exponent, a standard error from batch means and runs that share no trajectory.

:func:`duffing_study` takes the chapter's validated :class:`~vibration.chapters.duffing.params.Params`
and returns a :class:`DuffingStudy`; figures, tables and sentences are functions of that record.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from vibration.chapters.duffing.params import Params
from vibration.physics.duffing import (
    MAX_RK4_STEPS,
    Duffing,
    Folds,
    LyapunovEstimate,
    LyapunovResult,
    OrbitBranch,
    SweepResult,
    backbone,
    continue_orbits,
    duffing_response,
    folds,
    frequency_sweep,
    hb_amplitudes,
    linear_trust_amplitude,
    locate_jump,
    lyapunov_benettin,
    lyapunov_estimate,
    lyapunov_qr,
    periodic_orbit,
    poincare_section,
    pooled_exponent,
    response_curve,
)
from vibration.physics.exact import exact_response
from vibration.physics.model import Oscillator, ParameterError, SineForce

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
#: Largest arclength step of the continuation through the band (scaled unknowns): the folds are located by
#: the secant method on det(M - I) whatever the step, so a coarser step costs only resolution of the drawn branch.
CONTINUATION_STEP = 0.1
#: Ueda's chaos map in the chapter: forcing frequencies (rad/s) and amplitudes (N) of its grid, and the periods of
#: each of its runs (the chapter's time budget; ``python -m vibration.report sweep 09 -g omega_ueda ... -g F0_ueda ...
#: -p n_lyapunov N`` computes the same map at any resolution).
MAP_OMEGAS, MAP_FORCES, MAP_PERIODS = np.linspace(0.5, 1.5, 9), np.linspace(1.0, 13.0, 7), 100
#: Periods of the periodic case's exponents (at most), of the other chaotic runs (at most), of the sections.
N_PERIODIC, N_OTHER_RUNS, N_SECTION = 5000, 20_000, 3000


# ----------------------------------------------------------------------------------- records


@dataclass(frozen=True, kw_only=True)
class StabilityCheck:
    """One harmonic-balance root inside the band against the periodic orbit of the full equation there."""

    omega: float  # forcing frequency, rad/s
    amplitude: float  # one-harmonic amplitude, m
    stable: bool  # the slow flow's verdict
    orbit_amplitude: float  # amplitude of the shooting orbit started from that root, m (nan: no convergence)
    max_multiplier: float  # largest |Floquet multiplier| of that orbit (nan: no convergence)
    floquet_stable: bool | None  # both multipliers inside the unit circle (None: no convergence)

    @property
    def agree(self) -> bool | None:
        """Whether the slow flow and the Floquet multipliers give the same verdict (None: no orbit)."""
        return None if self.floquet_stable is None else self.floquet_stable == self.stable


@dataclass(frozen=True, eq=False, kw_only=True)
class SpringCase:
    """One cubic spring (hardening or softening) at the paper's mass, damping, stiffness and force."""

    label: str  # "hardening" or "softening"
    duffing: Duffing
    F0: float  # N
    folds: Folds  # one-harmonic folds and peak
    curve_omega: np.ndarray = field(repr=False)  # one-harmonic response curve: frequency, rad/s
    curve_amplitude: np.ndarray = field(repr=False)  # amplitude, m
    curve_stable: np.ndarray = field(repr=False)  # slow-flow stability of each point
    up: SweepResult = field(repr=False)
    down: SweepResult = field(repr=False)
    jump_up: tuple[float, float] | None  # refined bracket (before, after) of the sweep up's jump, rad/s
    jump_down: tuple[float, float] | None
    checks: tuple[StabilityCheck, ...]
    branch: OrbitBranch | None  # periodic orbits continued through the band (None without one-harmonic folds)

    @property
    def linear_peak(self) -> float:
        """Resonance peak of the same oscillator with a linear spring, ``F0 / (c omega_d)``, m (nan if overdamped)."""
        d = self.duffing
        wd2 = d.k / d.m - (d.c / (2 * d.m)) ** 2
        return self.F0 / (d.c * math.sqrt(wd2)) if wd2 > 0 else math.nan

    @property
    def linear_peak_omega(self) -> float:
        """Frequency of that peak, ``sqrt(k/m - c^2/(2 m^2))``, rad/s (nan if there is none)."""
        d = self.duffing
        w2 = d.k / d.m - d.c**2 / (2 * d.m**2)
        return math.sqrt(w2) if w2 > 0 else math.nan

    @property
    def backbone_peak(self) -> float:
        """The textbook estimate of the peak, ``F0 / (c omega)`` on the backbone at the peak amplitude, m."""
        a = self.folds.peak_amplitude
        return self.F0 / (self.duffing.c * float(backbone(self.duffing, a))) if math.isfinite(a) else math.nan

    def jump_amplitudes(self, res: SweepResult) -> tuple[float, float]:
        """Amplitudes (m) of the sweep ``res`` (``self.up`` or ``self.down``) on either side of its fold jump."""
        jump = self.jump_up if res.direction == "up" else self.jump_down
        mid = 0.5 * (jump[0] + jump[1])
        for w_before, w_after, a_before, a_after in res.jumps():
            if min(w_before, w_after) <= mid <= max(w_before, w_after):
                return a_before, a_after
        return math.nan, math.nan

    def sweep_orbit_gap(self) -> float:
        """Largest relative difference between a sweep's amplitude and the continued periodic orbit at the same
        frequency (the nearer branch point), over the sweep points inside the branch's range (nan: none)."""
        if self.branch is None or len(self.branch.folds) < 2:  # compare only with a branch through the band
            return math.nan
        wb, ab = self.branch.omega, self.branch.amplitude
        worst = math.nan
        for res in (self.up, self.down):
            for w, a in zip(res.omega, res.amplitude, strict=True):
                crossing = (wb[:-1] - w) * (wb[1:] - w) <= 0
                if not (math.isfinite(a) and crossing.any()):
                    continue
                i = np.flatnonzero(crossing)
                span = wb[i + 1] - wb[i]
                frac = np.divide(w - wb[i], span, out=np.zeros_like(span), where=span != 0)
                on_branch = ab[i] + frac * (ab[i + 1] - ab[i])
                gap = float(np.min(np.abs(on_branch - a)) / a)
                worst = gap if math.isnan(worst) else max(worst, gap)
        return worst

    @property
    def orbit_folds(self) -> tuple[float, float]:
        """Lower and upper fold frequencies of the periodic orbit (nan without two folds), rad/s."""
        ws = [f.omega for f in self.branch.folds] if self.branch else []
        return (min(ws), max(ws)) if len(ws) >= 2 else (math.nan, math.nan)


@dataclass(frozen=True, kw_only=True)
class FoldRow:
    """Where one sweep leaves its branch: one-harmonic fold, fold of the periodic orbit and the refined jump."""

    case: str  # "hardening" / "softening"
    direction: str  # "up" (leaves at the upper fold) / "down" (at the lower fold)
    hb: float  # one-harmonic fold, rad/s (nan: none)
    orbit: float  # fold of the periodic orbit of the full equation, rad/s (nan: none)
    jump: float  # middle of the refined jump bracket, rad/s (nan: the sweep does not jump)
    bracket: float  # width of that bracket, rad/s (nan: no jump)

    @property
    def hb_error(self) -> float:
        """One-harmonic fold less the orbit's, rad/s."""
        return self.hb - self.orbit

    @property
    def jump_error(self) -> float:
        """Jump less the orbit's fold, rad/s."""
        return self.jump - self.orbit

    @property
    def inside(self) -> bool | None:
        """Whether the orbit's fold lies inside the jump's refined bracket (None: no jump or no fold)."""
        if not (math.isfinite(self.jump) and math.isfinite(self.orbit)):
            return None
        return abs(self.jump - self.orbit) <= 0.5 * self.bracket


@dataclass(frozen=True, kw_only=True)
class HistoryRow:
    """Steady amplitudes of the hardening spring at one frequency, by where the motion comes from (m)."""

    where: str  # "the paper's ω" / "the middle of the band"
    omega: float  # rad/s
    linear: float  # steady amplitude with the linear spring, m
    hb_low: float  # smallest stable one-harmonic amplitude, m
    hb_high: float  # largest stable one-harmonic amplitude, m (nan: only one stable amplitude)
    rest: float  # time integration from rest, m
    up: float  # after a sweep up to omega, m
    down: float  # after a sweep down to omega, m

    @property
    def depends_on_history(self) -> bool:
        """Whether the sweeps up and down end on different amplitudes (by more than 10 %)."""
        return abs(self.up - self.down) > 0.1 * max(self.up, self.down)


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


@dataclass(frozen=True, eq=False, kw_only=True)
class DuffingStudy:
    """Everything chapter 9 shows, computed once (SI units)."""

    params: Params
    cases: tuple[SpringCase, SpringCase]  # hardening, softening
    linear_omega: np.ndarray = field(repr=False)  # linear spring over the hardening curve's range, rad/s
    linear_amplitude_curve: np.ndarray = field(repr=False)  # m
    folds_compared: tuple[FoldRow, ...]
    # the paper's scenario (hardening spring)
    trust_amplitude: float  # amplitude where the backbone leaves the half-power band, m
    linear_amplitude: float  # steady linear amplitude at omega_res, m
    paper_t: np.ndarray = field(repr=False)  # s
    paper_x_linear: np.ndarray = field(repr=False)  # m
    paper_x_duffing: np.ndarray = field(repr=False)  # m
    history: tuple[HistoryRow, ...]
    # chaos
    ueda: Duffing
    section_chaos: np.ndarray = field(repr=False)  # (x, v) once per forcing period, m and m/s
    section_periodic: np.ndarray = field(repr=False)
    periodic_qr: LyapunovResult = field(repr=False)
    periodic_benettin: LyapunovResult = field(repr=False)
    lyap_runs: tuple[LyapunovEstimate, ...] = field(repr=False)  # main run first, QR
    lyap_benettin: LyapunovEstimate = field(repr=False)  # two trajectories, main run's start
    pooled: Pooled
    convergence: tuple[ConvergenceRow, ...]
    floquet_periodic: float  # log max|mu| / T of the periodic Ueda orbit, 1/s (nan: not period 1)
    published: Published
    chaos_map: ChaosMap
    # self-checks
    amp_residual: float  # largest relative residual of the amplitude equation on the drawn curves
    liouville: float  # largest relative error of |mu1 mu2| against exp(-cT/m)
    qr_sum_error: float  # largest |lambda1 + lambda2 + c/m| of the QR runs, 1/s
    fold_multiplier_error: float  # largest |mu - 1| at the continued folds (nan: no fold)

    @property
    def hardening(self) -> SpringCase:
        return self.cases[0]

    @property
    def softening(self) -> SpringCase:
        return self.cases[1]

    @property
    def main_run(self) -> LyapunovEstimate:
        """The main chaotic run (variational equations with QR)."""
        return self.lyap_runs[0]

    @property
    def periodic_exponent(self) -> float:
        """Largest exponent of the periodic Ueda case (QR), 1/s."""
        return self.periodic_qr.exponents[0]

    def running(self, which: str, method: str) -> tuple[np.ndarray, np.ndarray]:
        """Running estimate of the largest exponent: (averaging time s, estimate 1/s) of ``which`` in
        ("chaotic", "periodic") by ``method`` in ("qr", "benettin")."""
        T = 2 * math.pi / self.params.omega_ueda  # forcing period, s
        if which == "chaotic":
            e = self.main_run if method == "qr" else self.lyap_benettin
            n = np.arange(1, e.n_periods + 1)
            return n * T, np.cumsum(e.increments) / (n * T)
        r = self.periodic_qr if method == "qr" else self.periodic_benettin
        return (np.arange(r.running.size) + 1) * T, r.running

    def method_gap(self, which: str, skip: int = 10) -> float:
        """Largest difference of the two methods' running estimates after the first ``skip`` periods,
        relative to the final estimate's magnitude."""
        _, a = self.running(which, "qr")
        _, b = self.running(which, "benettin")
        n = min(a.size, b.size)
        return float(np.max(np.abs(a[skip:n] - b[skip:n])) / abs(a[n - 1]))

    def section_points(self, which: str) -> int:
        """Distinct points (to 10⁻⁶ m and m/s) of the Poincaré section of the ``"chaotic"`` or ``"periodic"`` case
        (1: a period-1 orbit)."""
        sec = self.section_chaos if which == "chaotic" else self.section_periodic
        return int(np.unique(np.round(sec / 1e-6), axis=0).shape[0])


# ----------------------------------------------------------------------------------- computation


def _check_values(p: Params) -> None:
    """The chapter's needs beyond the schema's ranges: damping (the slow flow and the folds need c > 0), a
    softening spring that softens."""
    if not p.c_nominal > 0.0:
        raise ParameterError(
            f"c_nominal = {p.c_nominal!r} N s/m is out of range for the Duffing chapter: allowed c_nominal > 0 N s/m"
        )
    if not p.k3_soft < 0.0:
        raise ParameterError(f"k3_soft = {p.k3_soft!r} N/m³ is out of range: allowed k3_soft < 0 N/m³")


def _fold_jump(d: Duffing, F0: float, f: Folds, res: SweepResult) -> tuple[float, float] | None:
    """Refined bracket of the sweep's jump off its branch at a fold, or None (no one-harmonic fold, no such jump).

    On a steep resonance flank the amplitude can change between two coarse steps by more than the jump
    threshold as well, so a jump counts only near the band of the one-harmonic folds (within the band's
    width and one step), in the direction the fold dictates (a hardening spring drops sweeping up and rises
    sweeping down, a softening one the reverse); of those, the largest."""
    if not f.bistable:
        return None
    step = float(np.max(np.abs(np.diff(res.omega)))) if res.omega.size > 1 else 0.0
    margin = (f.omega_high - f.omega_low) + step
    rising = (d.k3 > 0) == (res.direction == "down")
    fits = [
        (abs(aa - ab) / max(aa, ab), i)
        for i, (wb, wa, ab, aa) in enumerate(res.jumps())
        if (aa > ab) == rising and max(wb, wa) >= f.omega_low - margin and min(wb, wa) <= f.omega_high + margin
    ]
    if not fits:
        return None
    return locate_jump(d, F0, res, which=max(fits)[1])


#: The one-harmonic curve reaches at least this multiple of the natural frequency (the paper's band: 6.5 rad/s,
#: 1.45 of its 4.47 rad/s).
CURVE_REACH = 1.45


def _spring(label: str, d: Duffing, F0: float, ws: np.ndarray, omega_max: float) -> tuple[SpringCase, float, float]:
    """One spring: curve, sweeps, jumps, Floquet checks inside the band, the continued branch.

    Returns the case, the largest relative residual of the amplitude equation on its curve and the largest
    Liouville error of its shooting orbits."""
    f = folds(d, F0)
    # the whole resonance, also when the sweep band stops below it (a stiffer spring than the paper's)
    curve_max = max(omega_max, CURVE_REACH * d.natural_frequency, 1.1 * f.omega_high if f.bistable else 0.0)
    w_c, a_c, s_c = response_curve(d, F0, curve_max, n=1201)
    s_ = d.k - d.m * w_c * w_c + d.kappa * a_c * a_c
    with np.errstate(invalid="ignore"):
        res = np.abs(a_c * a_c * (s_ * s_ + (d.c * w_c) ** 2) - F0 * F0) / (F0 * F0)
    amp_res = float(np.nanmax(res)) if res.size else 0.0
    up, down = frequency_sweep(d, F0, ws, "up"), frequency_sweep(d, F0, ws, "down")
    jump_up, jump_down = _fold_jump(d, F0, f, up), _fold_jump(d, F0, f, down)
    checks, liou, branch = [], 0.0, None
    if f.bistable:
        # inside the band of the full equation: between the refined jumps when they exist
        lo = max(f.omega_low, min(jump_down) if jump_down else f.omega_low)
        hi = min(f.omega_high, max(jump_up) if jump_up else f.omega_high)
        for frac in (0.3, 0.7):
            w = lo + frac * (hi - lo)
            for a, st in hb_amplitudes(d, F0, w):
                if a > f.peak_amplitude * (1 + 1e-9):
                    continue
                try:
                    orb = periodic_orbit(d, F0, w, a)
                except ParameterError:
                    checks.append(
                        StabilityCheck(
                            omega=w,
                            amplitude=a,
                            stable=st,
                            orbit_amplitude=math.nan,
                            max_multiplier=math.nan,
                            floquet_stable=None,
                        )
                    )
                    continue
                T = 2 * math.pi / w
                liou = max(liou, abs(abs(np.prod(orb.multipliers)) / math.exp(-d.c * T / d.m) - 1))
                checks.append(
                    StabilityCheck(
                        omega=w,
                        amplitude=a,
                        stable=st,
                        orbit_amplitude=orb.amplitude,
                        max_multiplier=max(abs(x) for x in orb.multipliers),
                        floquet_stable=orb.stable,
                    )
                )
        width = f.omega_high - f.omega_low  # continue the periodic orbit from below the band to above it
        branch = continue_orbits(d, F0, f.omega_low - 0.5 * width, f.omega_high + 0.5 * width, step=CONTINUATION_STEP)
    case = SpringCase(
        label=label,
        duffing=d,
        F0=F0,
        folds=f,
        curve_omega=w_c,
        curve_amplitude=a_c,
        curve_stable=s_c,
        up=up,
        down=down,
        jump_up=jump_up,
        jump_down=jump_down,
        checks=tuple(checks),
        branch=branch,
    )
    return case, amp_res, liou


def _fold_rows(cases) -> tuple[FoldRow, ...]:
    rows = []
    for case in cases:
        low, high = case.orbit_folds
        for direction, jump, hb, orbit in (
            ("up", case.jump_up, case.folds.omega_high, high),
            ("down", case.jump_down, case.folds.omega_low, low),
        ):
            w_j = 0.5 * (jump[0] + jump[1]) if jump else math.nan
            width = abs(jump[1] - jump[0]) if jump else math.nan
            rows.append(FoldRow(case=case.label, direction=direction, hb=hb, orbit=orbit, jump=w_j, bracket=width))
    return tuple(rows)


def _sweep_to(d: Duffing, F0: float, w_from: float, w_to: float, direction: str) -> float:
    """Amplitude at ``w_to`` after a sweep from ``w_from`` (60 steps), m."""
    return float(frequency_sweep(d, F0, np.linspace(w_from, w_to, 60), direction).amplitude[-1])


def _history(p: Params, hard: SpringCase) -> tuple[HistoryRow, ...]:
    d, F0 = hard.duffing, p.F0
    lin = Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=0.0)
    targets = [("the paper's ω", p.omega_res)]
    if hard.folds.bistable:
        targets.append(("the middle of the band", 0.5 * (hard.folds.omega_low + hard.folds.omega_high)))
    rows = []
    for name, w in targets:
        stable = [a for a, s in hb_amplitudes(d, F0, w) if s]
        rows.append(
            HistoryRow(
                where=name,
                omega=w,
                linear=hb_amplitudes(lin, F0, w)[0][0],
                hb_low=min(stable),
                hb_high=max(stable) if len(stable) > 1 else math.nan,
                rest=float(frequency_sweep(d, F0, [w], "up").amplitude[0]),
                up=_sweep_to(d, F0, min(p.omega_sweep_min, 0.8 * w), w, "up"),
                down=_sweep_to(d, F0, max(p.omega_sweep_max, 1.2 * w), w, "down"),
            )
        )
    return tuple(rows)


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
        lyapunov_estimate(ueda, p.F0_ueda, p.omega_ueda, *start, n_periods=n, n_blocks=n_blocks, steps_per_period=spp)
        for (start, spp), n in zip(LYAPUNOV_RUNS, lengths, strict=True)
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


def chaos_map(p: Params, omegas=MAP_OMEGAS, forces=MAP_FORCES, n_periods: int = MAP_PERIODS) -> ChaosMap:
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


def duffing_study(params: Params | None = None, **values) -> DuffingStudy:
    """Compute chapter 9: harmonic balance, Floquet checks, sweeps, continued folds, the paper's scenario, chaos.

    Parameters
    ----------
    params : Params, optional
        The chapter's validated parameters (see :data:`~vibration.chapters.duffing.params.SCHEMA`); or give
        them as keyword arguments, checked by the schema (the others keep their defaults).

    Returns
    -------
    DuffingStudy
        Frozen record of every result the chapter shows.

    Raises
    ------
    ParameterError
        A value outside the schema's range, a damping ``c_nominal <= 0`` or ``k3_soft = 0``.

    Examples
    --------
    >>> s = duffing_study(n_sweep=40, n_lyapunov=200)
    >>> [c.label for c in s.cases], s.hardening.folds.bistable, s.hardening.orbit_folds[0] > 5.0   # rad/s
    (['hardening', 'softening'], True, True)
    """
    p = params if params is not None else Params.from_values(values)
    if not isinstance(p, Params):
        raise ParameterError(f"params = {p!r:.60} is not valid: allowed a duffing Params record or None")
    _check_values(p)
    ws = np.linspace(p.omega_sweep_min, p.omega_sweep_max, p.n_sweep)
    hard, r1, l1 = _spring("hardening", Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=p.k3_hard), p.F0, ws, p.omega_sweep_max)
    soft, r2, l2 = _spring("softening", Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=p.k3_soft), p.F0, ws, p.omega_sweep_max)
    cases = (hard, soft)
    lin = Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=0.0)
    w_lin = np.linspace(hard.curve_omega.min(), hard.curve_omega.max(), 800)
    a_lin = np.array([hb_amplitudes(lin, p.F0, w)[0][0] for w in w_lin])

    t = np.linspace(0.0, p.t_end, 2001)
    x_lin = exact_response(
        Oscillator(m=p.m, c=p.c_nominal, k=p.k), SineForce(F0=p.F0, omega=p.omega_res), t
    ).x  # Part I's form
    x_duf, _ = duffing_response(hard.duffing, p.F0, p.omega_res, t, sine=True)

    ueda = Duffing(m=1.0, c=p.c_ueda, k=0.0, k3=1.0)
    w_u = p.omega_ueda
    section_chaos = poincare_section(ueda, p.F0_ueda, w_u, *UEDA_START, n_periods=N_SECTION, n_transient=300)
    section_periodic = poincare_section(ueda, p.F0_ueda_periodic, w_u, *UEDA_START, n_periods=200, n_transient=1000)
    n_blocks = min(20, p.n_lyapunov // 10)
    runs, pooled = _lyapunov_runs(p, ueda)
    partner = lyapunov_estimate(ueda, p.F0_ueda, w_u, *LYAPUNOV_RUNS[0][0], n_periods=p.n_lyapunov, n_blocks=n_blocks,
                                method="benettin")  # fmt: skip
    kw = {"n_periods": min(p.n_lyapunov, N_PERIODIC), "n_transient": 300}
    per_qr = lyapunov_qr(ueda, p.F0_ueda_periodic, p.omega_ueda, *UEDA_START, **kw)
    per_ben = lyapunov_benettin(ueda, p.F0_ueda_periodic, p.omega_ueda, *UEDA_START, **kw)
    floq = math.nan
    if np.ptp(section_periodic, axis=0).max() < 1e-6:  # period 1: its Floquet multipliers give the exponent
        orb = periodic_orbit(
            ueda, p.F0_ueda_periodic, p.omega_ueda, x0=float(section_periodic[-1, 0]), v0=float(section_periodic[-1, 1])
        )
        floq = math.log(max(abs(x) for x in orb.multipliers)) / (2 * math.pi / p.omega_ueda)
    cm = ueda.c / ueda.m
    qr_sums = [abs(e.exponent + e.second + cm) for e in runs] + [abs(sum(per_qr.exponents) + cm)]
    fold_mu = [abs(f.multiplier - 1.0) for c in cases if c.branch for f in c.branch.folds]
    return DuffingStudy(
        params=p,
        cases=cases,
        linear_omega=w_lin,
        linear_amplitude_curve=a_lin,
        folds_compared=_fold_rows(cases),
        trust_amplitude=linear_trust_amplitude(hard.duffing),
        linear_amplitude=hb_amplitudes(lin, p.F0, p.omega_res)[0][0],
        paper_t=t,
        paper_x_linear=x_lin,
        paper_x_duffing=x_duf,
        history=_history(p, hard),
        ueda=ueda,
        section_chaos=section_chaos,
        section_periodic=section_periodic,
        periodic_qr=per_qr,
        periodic_benettin=per_ben,
        lyap_runs=runs,
        lyap_benettin=partner,
        pooled=pooled,
        convergence=_convergence(runs[0]),
        floquet_periodic=floq,
        published=_published(p, pooled, runs),
        chaos_map=chaos_map(p),
        amp_residual=max(r1, r2),
        liouville=max(l1, l2),
        qr_sum_error=max(qr_sums),
        fold_multiplier_error=max(fold_mu) if fold_mu else math.nan,
    )
