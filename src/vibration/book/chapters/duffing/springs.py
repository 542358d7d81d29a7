"""Chapter 9's two cubic springs: harmonic balance against the full equation.

For a hardening and a softening spring at the paper's mass, damping, stiffness and force: the one-harmonic
response curve with its folds and slow-flow stability, stepped frequency sweeps up and down with their
refined jumps, Floquet checks of the one-harmonic roots inside the bistable band, the periodic orbits
continued through it, and the steady amplitudes of the hardening spring by where the motion comes from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from vibration.book.chapters.duffing.params import Params
from vibration.physics.duffing import (
    Duffing,
    Folds,
    OrbitBranch,
    SweepResult,
    backbone,
    continue_orbits,
    folds,
    frequency_sweep,
    hb_amplitudes,
    locate_jump,
    periodic_orbit,
    response_curve,
)
from vibration.physics.model import ParameterError

#: Largest arclength step of the continuation through the band (scaled unknowns): the folds are located by
#: the secant method on det(M - I) whatever the step, so a coarser step costs only resolution of the drawn branch.
CONTINUATION_STEP = 0.1
#: The one-harmonic curve reaches at least this multiple of the natural frequency (the paper's band: 6.5 rad/s,
#: 1.45 of its 4.47 rad/s).
CURVE_REACH = 1.45


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


def _stability_check(omega: float, amplitude: float, stable: bool, orbit) -> StabilityCheck:
    """The balance's verdict at ``omega`` (rad/s), ``amplitude`` (m) beside the orbit's (none: nan, None)."""
    found = orbit is not None
    return StabilityCheck(
        omega=omega,
        amplitude=amplitude,
        stable=stable,
        orbit_amplitude=orbit.amplitude if found else math.nan,
        max_multiplier=max(abs(x) for x in orbit.multipliers) if found else math.nan,
        floquet_stable=orbit.stable if found else None,
    )


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
    up, down = frequency_sweep(d, F0, ws, direction="up"), frequency_sweep(d, F0, ws, direction="down")
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
                    orb = periodic_orbit(d, F0, w, amplitude_guess=a)
                except ParameterError:
                    checks.append(_stability_check(w, a, st, None))
                    continue
                T = 2 * math.pi / w
                liou = max(liou, abs(abs(np.prod(orb.multipliers)) / math.exp(-d.c * T / d.m) - 1))
                checks.append(_stability_check(w, a, st, orb))
        width = f.omega_high - f.omega_low  # continue the periodic orbit from below the band to above it
        branch = continue_orbits(
            d, F0, f.omega_low - 0.5 * width, omega_end=f.omega_high + 0.5 * width, step=CONTINUATION_STEP
        )
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
    return float(frequency_sweep(d, F0, np.linspace(w_from, w_to, 60), direction=direction).amplitude[-1])


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
                rest=float(frequency_sweep(d, F0, [w], direction="up").amplitude[0]),
                up=_sweep_to(d, F0, min(p.omega_sweep_min, 0.8 * w), w, "up"),
                down=_sweep_to(d, F0, max(p.omega_sweep_max, 1.2 * w), w, "down"),
            )
        )
    return tuple(rows)
