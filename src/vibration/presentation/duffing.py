"""Chapter 9 (the Duffing oscillator): studies, figures, tables, sentences and sliders.

The notebook calls one function per result: :func:`duffing_study` computes everything once
(harmonic balance, Floquet checks, sweeps, the paper's scenario, chaos) into a
:class:`DuffingStudy`; every figure, table and sentence below is a function of that record, so a
papermill run with other parameters never contradicts its own tables. :func:`hb_explorer` is the
JupyterLab slider (k3 and F0 moving the harmonic-balance curves) whose ``text/html`` bundle is the
kernel-free panel of :func:`hb_panel_html` (``assets/duffing.js``).
"""

from __future__ import annotations

import hashlib
import html
import io
import itertools
import json
import math
from dataclasses import dataclass, field

import numpy as np

from ..physics.duffing import (
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
from ..physics.exact import exact_response
from ..physics.model import Oscillator, ParameterError, SineForce, check_int, check_real
from .static_page import _asset
from .style import figure, place_legend
from .tables import Approx, Column, Missing, Table, bound

STABLE_LS, UNSTABLE_LS = "-", "--"
C_HARD, C_SOFT, C_LIN = "#1f77b4", "#d62728", "#7f7f7f"

#: The published largest Lyapunov exponent of Ueda's oscillator ``x'' + 0.05 x' + x^3 = 7.5 cos t``, 1/s (natural
#: logarithm, per unit time): J. C. Sprott, *Chaos and Time-Series Analysis* (Oxford University Press, 2003), the
#: table of Lyapunov exponents of common chaotic flows (0.0999, 0, -0.1499 for the flow with time as a third
#: variable). The averaging length is not stated there; a reproduction of the table states RK4 with step 0.001 s.
PUBLISHED_UEDA = {"exponent": 0.0999, "c": 0.05, "F0": 7.5, "step": 0.001}

#: Initial states (m, m/s) and RK4 steps per period of the chaotic runs; the first is the main run.
LYAPUNOV_RUNS = (((3.0, 0.0), 400), ((0.0, 0.0), 400), ((1.0, 1.0), 400), ((-2.0, 3.0), 400), ((3.0, 0.0), 200),
                 ((3.0, 0.0), 800))  # fmt: skip


# ----------------------------------------------------------------------------------- the study


@dataclass
class Case:
    """One oscillator of the chapter with its harmonic-balance and time-integration results."""

    label: str  # "hardening" / "softening"
    duffing: Duffing
    F0: float  # N
    folds: Folds
    curve: tuple  # (omega rad/s, A m, stable) along the response curve
    up: SweepResult
    down: SweepResult
    jump_up: tuple | None  # refined (omega_before, omega_after) of the sweep up, rad/s
    jump_down: tuple | None
    checks: list = field(default_factory=list)  # (omega, A_hb, stable_hb, A_orbit, max|mu|, stable_floquet)
    branch: OrbitBranch | None = None  # periodic orbits continued through the band (None without HB folds)


@dataclass
class DuffingStudy:
    """Everything the chapter shows, computed once (SI units)."""

    m: float
    k: float
    c: float
    F0: float
    omega_res: float
    t_end: float
    cases: list[Case]
    # the paper's scenario (hardening spring)
    trust_amplitude: float  # m
    linear_amplitude: float  # steady linear amplitude at omega_res, m
    paper_t: np.ndarray
    paper_x_linear: np.ndarray
    paper_x_duffing: np.ndarray
    history: list[dict]  # rows: omega, where-from amplitudes
    # chaos
    ueda: Duffing
    F0_ueda: float
    F0_periodic: float
    section_chaos: np.ndarray
    section_periodic: np.ndarray
    lyapunov: list[tuple[str, str, LyapunovResult]]  # periodic case: (case, start, result)
    lyap_runs: list[LyapunovEstimate]  # chaotic case, QR: the main run first, then other starts and step sizes
    lyap_benettin: LyapunovEstimate  # chaotic case, two trajectories on the main run's trajectory
    pooled: tuple[float, float, float, int]  # pooled exponent over lyap_runs: mean, SE (1/s), chi2, dof
    floquet_periodic: float  # log max|mu| / T of the periodic Ueda orbit, 1/s (nan if not found)
    amp_residual: float  # largest relative residual of the amplitude equation over the curves
    liouville: float  # largest relative error of prod(mu) = exp(-cT/m)


def _sweep_to(d: Duffing, F0: float, w_from: float, w_to: float, direction: str) -> float:
    """Amplitude at ``w_to`` after a sweep from ``w_from`` (60 steps), m."""
    res = frequency_sweep(d, F0, np.linspace(w_from, w_to, 60), direction)
    return float(res.amplitude[-1])


def duffing_study(
    m: float = 1.0,
    k: float = 20.0,
    F0: float = 5.0,
    c: float = 0.5,
    omega_res: float = 4.47,
    t_end: float = 50.0,
    k3_hard: float = 2.0,
    k3_soft: float = -1.0,
    omega_sweep_min: float = 3.0,
    omega_sweep_max: float = 6.5,
    n_sweep: int = 200,
    c_ueda: float = 0.05,
    F0_ueda: float = 7.5,
    F0_ueda_periodic: float = 2.0,
    n_lyapunov: int = 20_000,
) -> DuffingStudy:
    """Compute the whole chapter.

    Parameters
    ----------
    m, k, F0, c : float
        The paper's mass (kg), stiffness (N/m), force amplitude (N) and damping (N s/m).
    omega_res : float
        The paper's "resonant" forcing frequency, rad/s.
    t_end : float
        The paper's window, s.
    k3_hard, k3_soft : float
        Cubic stiffnesses of the hardening (> 0) and softening (< 0) cases, N/m^3.
    omega_sweep_min, omega_sweep_max : float
        Range of the stepped sweeps, rad/s.
    n_sweep : int
        Frequencies per sweep (10 to 2000).
    c_ueda : float
        Damping of Ueda's oscillator ``x'' + c x' + x^3 = F cos t`` (m = 1 kg, k3 = 1 N/m^3), N s/m.
    F0_ueda, F0_ueda_periodic : float
        Its chaotic and periodic forcing amplitudes, N.
    n_lyapunov : int
        Forcing periods of the main run on the chaotic attractor and of its two-trajectory twin (100 to
        100000); the runs from other starts and with other steps use at most 20000, the periodic case 5000.

    Returns
    -------
    DuffingStudy

    Examples
    --------
    >>> s = duffing_study(n_sweep=40, n_lyapunov=200)
    >>> [c.label for c in s.cases], s.cases[0].folds.bistable
    (['hardening', 'softening'], True)
    """
    k3_hard = check_real("k3_hard", k3_hard, low=0.0, low_open=True, unit="N/m^3")
    k3_soft = check_real("k3_soft", k3_soft, high=0.0, unit="N/m^3")
    if k3_soft == 0.0:
        raise ParameterError("k3_soft = 0.0 N/m^3 is out of range: allowed k3_soft < 0 N/m^3")
    omega_sweep_min = check_real("omega_sweep_min", omega_sweep_min, low=0.0, low_open=True, unit="rad/s")
    omega_sweep_max = check_real("omega_sweep_max", omega_sweep_max, low=omega_sweep_min, low_open=True, unit="rad/s")
    n_sweep = check_int("n_sweep", n_sweep, low=10, high=400)  # the runner's range, as in chapter 7
    n_lyapunov = check_int("n_lyapunov", n_lyapunov, low=100, high=100_000)
    c = check_real("c", c, low=0.0, low_open=True, unit="N s/m")
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    omega_res = check_real("omega_res", omega_res, low=0.0, low_open=True, unit="rad/s")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    ws = np.linspace(omega_sweep_min, omega_sweep_max, n_sweep)
    cases = []
    amp_res, liou = 0.0, 0.0
    for label, k3 in (("hardening", k3_hard), ("softening", k3_soft)):
        d = Duffing(m, c, k, k3)
        f = folds(d, F0)
        curve = response_curve(d, F0, omega_sweep_max, n=1201)
        for wi, ai in zip(curve[0], curve[1], strict=True):
            s_ = d.k - d.m * wi * wi + d.kappa * ai * ai
            amp_res = max(amp_res, abs(ai * ai * (s_ * s_ + (d.c * wi) ** 2) - F0 * F0) / (F0 * F0))
        up, down = frequency_sweep(d, F0, ws, "up"), frequency_sweep(d, F0, ws, "down")
        jump_up = locate_jump(d, F0, up) if up.jumps() else None
        jump_down = locate_jump(d, F0, down) if down.jumps() else None
        checks = []
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
                        checks.append((w, a, st, math.nan, math.nan, None))
                        continue
                    mu = max(abs(x) for x in orb.multipliers)
                    T = 2 * math.pi / w
                    liou = max(liou, abs(abs(np.prod(orb.multipliers)) / math.exp(-d.c * T / d.m) - 1))
                    checks.append((w, a, st, orb.amplitude, mu, orb.stable))
        branch = None
        if f.bistable:  # continue the periodic orbit from below the band to above it
            width = f.omega_high - f.omega_low
            branch = continue_orbits(d, F0, f.omega_low - 0.5 * width, f.omega_high + 0.5 * width)
        cases.append(Case(label, d, F0, f, curve, up, down, jump_up, jump_down, checks, branch))

    hard = cases[0].duffing
    lin = Duffing(m, c, k, 0.0)
    t = np.linspace(0.0, t_end, 2001)
    x_lin = exact_response(Oscillator(m, c, k), SineForce(F0, omega_res), t).x  # Part I's closed form
    x_duf, _ = duffing_response(hard, F0, omega_res, t, sine=True)
    history = []
    targets = [("the paper's ω", omega_res)]
    fh = cases[0].folds
    if fh.bistable:
        targets.append(("middle of the band", 0.5 * (fh.omega_low + fh.omega_high)))
    for name, w in targets:
        stable = [a for a, s in hb_amplitudes(hard, F0, w) if s]
        from_rest = float(frequency_sweep(hard, F0, [w], "up").amplitude[0])
        history.append(
            {
                "where": name,
                "omega": w,
                "linear": hb_amplitudes(lin, F0, w)[0][0],
                "hb_low": min(stable),
                "hb_high": max(stable) if len(stable) > 1 else Missing("one stable amplitude at this frequency"),
                "rest": from_rest,
                "up": _sweep_to(hard, F0, min(omega_sweep_min, 0.8 * w), w, "up"),
                "down": _sweep_to(hard, F0, max(omega_sweep_max, 1.2 * w), w, "down"),
            }
        )

    ueda = Duffing(1.0, c_ueda, 0.0, 1.0)
    section_chaos = poincare_section(ueda, F0_ueda, 1.0, 3.0, 0.0, n_periods=3000, n_transient=300)
    section_periodic = poincare_section(ueda, F0_ueda_periodic, 1.0, 3.0, 0.0, n_periods=200, n_transient=1000)
    n_blocks = min(20, n_lyapunov // 10)
    # the main run has n_lyapunov periods; the others at most 20,000 (bounded work at the parameter's extreme)
    lengths = [n_lyapunov] + [min(n_lyapunov, 20_000, MAX_RK4_STEPS // spp - 300) for _, spp in LYAPUNOV_RUNS[1:]]
    runs = [
        lyapunov_estimate(ueda, F0_ueda, 1.0, *start, n_periods=n, n_blocks=n_blocks, steps_per_period=spp)
        for (start, spp), n in zip(LYAPUNOV_RUNS, lengths, strict=True)
    ]
    partner = lyapunov_estimate(ueda, F0_ueda, 1.0, *LYAPUNOV_RUNS[0][0], n_periods=n_lyapunov, n_blocks=n_blocks,
                                method="benettin")  # fmt: skip
    lyap = []
    kw = {"n_periods": min(n_lyapunov, 5000), "n_transient": 300}
    lyap.append(("periodic", "x0 = 3 m, v0 = 0 m/s", lyapunov_qr(ueda, F0_ueda_periodic, 1.0, 3.0, 0.0, **kw)))
    lyap.append(("periodic", "x0 = 3 m, v0 = 0 m/s", lyapunov_benettin(ueda, F0_ueda_periodic, 1.0, 3.0, 0.0, **kw)))
    floq = math.nan
    if np.ptp(section_periodic, axis=0).max() < 1e-6:  # period 1: its Floquet multipliers give the exponent
        orb = periodic_orbit(
            ueda, F0_ueda_periodic, 1.0, x0=float(section_periodic[-1, 0]), v0=float(section_periodic[-1, 1])
        )
        floq = math.log(max(abs(x) for x in orb.multipliers)) / (2 * math.pi)
    return DuffingStudy(
        m=m,
        k=k,
        c=c,
        F0=F0,
        omega_res=omega_res,
        t_end=t_end,
        cases=cases,
        trust_amplitude=linear_trust_amplitude(hard),
        linear_amplitude=hb_amplitudes(lin, F0, omega_res)[0][0],
        paper_t=t,
        paper_x_linear=x_lin,
        paper_x_duffing=x_duf,
        history=history,
        ueda=ueda,
        F0_ueda=F0_ueda,
        F0_periodic=F0_ueda_periodic,
        section_chaos=section_chaos,
        section_periodic=section_periodic,
        lyapunov=lyap,
        lyap_runs=runs,
        lyap_benettin=partner,
        pooled=pooled_exponent(runs),
        floquet_periodic=floq,
        amp_residual=amp_res,
        liouville=liou,
    )


# ----------------------------------------------------------------------------------- figures


def _plot_curve(ax, curve, color, label):
    """Response curve with stable parts solid and unstable parts dashed (split where stability changes)."""
    w, a, st = curve
    breaks = np.flatnonzero(np.diff(st.astype(int))) + 1
    first = {True: True, False: True}
    for seg in np.split(np.arange(w.size), breaks):
        if seg.size == 0:
            continue
        s = bool(st[seg[0]])
        idx = np.concatenate([[seg[0] - 1] if seg[0] > 0 else [], seg]).astype(int)  # join the pieces
        lab = None
        if first[s]:
            lab = f"{label}, {'stable' if s else 'unstable'}"
            first[s] = False
        ax.plot(w[idx], a[idx], color=color, ls=STABLE_LS if s else UNSTABLE_LS, lw=1.5 if s else 1.1, label=lab)


def frequency_response_figure(study: DuffingStudy):
    """Harmonic-balance response curves (hardening and softening), backbones, folds and the linear curve."""
    fig, axes = figure(1, 2, height=3.7, sharey=True)
    lin = Duffing(study.m, study.c, study.k, 0.0)
    for ax, case, col in zip(axes, study.cases, (C_HARD, C_SOFT), strict=True):
        w = case.curve[0]
        wl = np.linspace(w.min(), w.max(), 800)
        ax.plot(wl, [hb_amplitudes(lin, case.F0, x)[0][0] for x in wl], color=C_LIN, lw=0.9, label="linear spring")
        _plot_curve(ax, case.curve, col, f"$k_3$ = {case.duffing.k3:g} N/m$^3$")
        a_bb = np.linspace(0.0, 1.1 * np.nanmax(case.curve[1]), 200)
        ax.plot(backbone(case.duffing, a_bb), a_bb, color="k", lw=0.8, ls=":", label="backbone")
        f = case.folds
        fw = [x for x in (f.omega_low, f.omega_high) if math.isfinite(x)]
        fa = [a for a, x in ((f.amplitude_low, f.omega_low), (f.amplitude_high, f.omega_high)) if math.isfinite(x)]
        if fw:
            ax.plot(fw, fa, "o", ms=4.5, mfc="white", color="k", label="folds")
        ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
        ax.set_title(f"{case.label}, $F_0$ = {case.F0:g} N, $c$ = {case.duffing.c:g} N s/m")
        ax.set_xlim(w.min(), w.max())
    axes[0].set_ylabel(r"amplitude $A$ (m)")
    axes[0].set_ylim(0.0, 1.12 * max(np.nanmax(c.curve[1]) for c in study.cases))
    for ax in axes:
        place_legend(ax)
    return fig


def sweep_figure(study: DuffingStudy):
    """Stepped sweeps up and down over the harmonic-balance curve: jumps and hysteresis."""
    fig, axes = figure(1, 2, height=3.7, sharey=True)
    for ax, case, col in zip(axes, study.cases, (C_HARD, C_SOFT), strict=True):
        _plot_curve(ax, case.curve, "#bbbbbb", "harmonic balance")
        if case.branch is not None:
            b = case.branch
            ax.plot(b.omega, b.amplitude, color="k", lw=0.7, label="periodic orbit (continuation)")
            ax.plot([f.omega for f in b.folds], [f.amplitude for f in b.folds], "s", ms=4.5, mfc="white", color="k",
                    label="folds of the orbit")  # fmt: skip
        ax.plot(case.up.omega, case.up.amplitude, "^", ms=3.2, color=col, label="sweep up")
        ax.plot(case.down.omega, case.down.amplitude, "v", ms=3.2, mfc="none", color="k", mew=0.7, label="sweep down")
        for j, direction in ((case.jump_up, "up"), (case.jump_down, "down")):
            if j is None:
                continue
            res = case.up if direction == "up" else case.down
            (wb, wa, ab, aa) = res.jumps()[0]
            wj = 0.5 * (j[0] + j[1])
            ax.annotate("", xy=(wj, aa), xytext=(wj, ab), arrowprops={"arrowstyle": "->", "color": col, "lw": 1.0})
        ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
        ax.set_title(f"{case.label}, $k_3$ = {case.duffing.k3:g} N/m$^3$")
        ax.set_xlim(case.up.omega.min(), case.up.omega.max())
    axes[0].set_ylabel(r"steady amplitude $A$ (m)")
    axes[0].set_ylim(0.0, 1.75 * max(np.nanmax(c.curve[1]) for c in study.cases))
    for ax in axes:
        place_legend(ax)
    return fig


def paper_figure(study: DuffingStudy):
    """The paper's resonance scenario from rest, linear and with the hardening spring."""
    fig, ax = figure(1, 1, height=3.2)
    k3 = study.cases[0].duffing.k3
    ax.plot(study.paper_t, study.paper_x_linear, color=C_LIN, lw=0.9, label="linear spring (the paper)")
    ax.plot(study.paper_t, study.paper_x_duffing, color=C_HARD, lw=1.0, label=f"$k_3$ = {k3:g} N/m$^3$")
    ax.axhline(study.trust_amplitude, color="k", ls=":", lw=0.8, label="amplitude where the linear answer fails")
    ax.axhline(-study.trust_amplitude, color="k", ls=":", lw=0.8)
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"displacement $x$ (m)")
    top = 1.1 * max(np.abs(study.paper_x_linear).max(), study.trust_amplitude)
    ax.set_ylim(-top, top)
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02, 1.0, 0.1), ncol=3, borderaxespad=0.0, frameon=False)
    return fig


def chaos_figure(study: DuffingStudy):
    """Poincaré sections of Ueda's oscillator and the running largest Lyapunov exponent."""
    fig, (ax1, ax2) = figure(1, 2, height=3.6)
    ax1.plot(
        study.section_chaos[:, 0],
        study.section_chaos[:, 1],
        ".",
        ms=1.2,
        color=C_HARD,
        label=f"F = {study.F0_ueda:g} N",
    )
    ax1.plot(
        study.section_periodic[:, 0],
        study.section_periodic[:, 1],
        "o",
        ms=6,
        color=C_SOFT,
        label=f"F = {study.F0_periodic:g} N",
    )
    ax1.set_xlabel(r"$x$ at $t = 2\pi n$ (m)")
    ax1.set_ylabel(r"$\dot x$ at $t = 2\pi n$ (m/s)")
    ax1.set_title("stroboscopic Poincaré section")
    place_legend(ax1)
    styles = {"qr": "-", "benettin": "--"}
    T = 2 * math.pi
    for e in (study.lyap_runs[0], study.lyap_benettin):
        n = np.arange(1, e.n_periods + 1)
        name = "QR, variational" if e.method == "qr" else "two trajectories"
        ax2.plot(n * T, np.cumsum(e.increments) / (n * T), color=C_HARD, ls=styles[e.method], lw=1.0,
                 label=f"chaotic: {name}")  # fmt: skip
    for _, _, r in study.lyapunov:
        t = (np.arange(r.running.size) + 1) * T
        name = "QR, variational" if r.method == "qr" else "two trajectories"
        ax2.plot(t, r.running, color=C_SOFT, ls=styles[r.method], lw=1.0, label=f"periodic: {name}")
    ax2.axhline(0.0, color="k", lw=0.6)
    ax2.set_xscale("log")
    ax2.set_xlabel(r"averaging time (s)")
    ax2.set_ylabel(r"largest exponent $\lambda_1$ (1/s)")
    ax2.set_title("Lyapunov exponent, running estimate")
    place_legend(ax2)
    return fig


# ------------------------------------------------------------------------------------ tables


def _m(v, reason):
    return v if (v is not None and math.isfinite(v)) else Missing(reason)


def hb_table(study: DuffingStudy) -> Table:
    """Folds, peak and its textbook estimate for each spring."""
    rows = []
    for case in study.cases:
        f, d = case.folds, case.duffing
        no = "single-valued response: no fold"
        rows.append(
            {
                "case": case.label,
                "k3": d.k3,
                "wl": _m(f.omega_low, no),
                "wh": _m(f.omega_high, no),
                "wp": _m(f.peak_omega, "the curve does not close"),
                "ap": _m(f.peak_amplitude, "the curve does not close"),
                "abb": _m(
                    case.F0 / (d.c * backbone(d, f.peak_amplitude)) if math.isfinite(f.peak_amplitude) else None,
                    "the curve does not close",
                ),
                "lin": case.F0 / (d.c * math.sqrt(d.k / d.m - (d.c / (2 * d.m)) ** 2)),
            }
        )
    return Table(
        rows,
        [
            Column("case", "spring"),
            Column("k3", "k_3 (N/m³)", 3),
            Column("wl", "ω_low (rad/s)", 5),
            Column("wh", "ω_high (rad/s)", 5),
            Column("wp", "ω_peak (rad/s)", 5),
            Column("ap", "A_peak (m)", 4),
            Column("abb", "F₀/(c ω_bb) (m)", 4),
            Column("lin", "linear peak (m)", 4),
        ],  # fmt: skip
        caption="One-harmonic frequency response: fold frequencies, peak, the textbook peak estimate on the backbone, "
        "and the linear oscillator's peak.",
        name="tab-duffing-folds",
    )


def stability_table(study: DuffingStudy) -> Table:
    """Slow-flow stability of every branch against the Floquet multipliers of the shooting orbit."""
    rows = []
    for case in study.cases:
        for w, a, st, a_orb, mu, st_f in case.checks:
            rows.append(
                {
                    "case": case.label,
                    "w": w,
                    "a": a,
                    "st": "stable" if st else "unstable",
                    "ao": _m(a_orb, "shooting did not converge"),
                    "mu": _m(mu, "shooting did not converge"),
                    "stf": Missing("shooting did not converge") if st_f is None else ("stable" if st_f else "unstable"),
                    "agree": Missing("shooting did not converge") if st_f is None else (st_f == st),
                }
            )
    if not rows:
        rows = [{"case": "—", "w": Missing("no bistable band"), "a": None, "st": None, "ao": None, "mu": None,
                 "stf": None, "agree": None}]  # fmt: skip
    return Table(
        rows,
        [
            Column("case", "spring"),
            Column("w", "ω (rad/s)", 5),
            Column("a", "A, one harmonic (m)", 4),
            Column("st", "slow flow"),
            Column("ao", "A, shooting (m)", 4),
            Column("mu", "max |μ|", 4),
            Column("stf", "Floquet"),
            Column("agree", "agree"),
        ],  # fmt: skip
        caption="Stability of each harmonic-balance branch: slow-flow Jacobian against the Floquet multipliers μ of "
        "the periodic orbit of the full equation (Newton shooting, DOP853).",
        name="tab-duffing-stability",
    )


def fold_comparison(study: DuffingStudy) -> list[dict]:
    """Fold frequencies by harmonic balance, by continuation of the periodic orbit and by the sweep jumps (rad/s).

    The sweep up leaves its branch at the upper fold, the sweep down at the lower one; ``inside`` says
    whether the true (continued) fold lies in the jump's refined bracket.
    """
    rows = []
    for case in study.cases:
        f = case.folds
        orbit_folds = [x.omega for x in case.branch.folds] if case.branch else []
        true_high = max(orbit_folds) if len(orbit_folds) >= 2 else math.nan
        true_low = min(orbit_folds) if len(orbit_folds) >= 2 else math.nan
        for direction, jump, hb, true in (
            ("up", case.jump_up, f.omega_high, true_high),
            ("down", case.jump_down, f.omega_low, true_low),
        ):
            w_t = 0.5 * (jump[0] + jump[1]) if jump else math.nan
            inside = bool(jump and min(jump) <= true <= max(jump)) if math.isfinite(true) and jump else None
            rows.append(
                {
                    "case": case.label,
                    "direction": direction,
                    "hb": hb,
                    "orbit": true,
                    "time": w_t,
                    "bracket": abs(jump[1] - jump[0]) if jump else math.nan,
                    "diff": w_t - hb if jump and math.isfinite(hb) else math.nan,
                    "hb_err": hb - true,
                    "jump_err": w_t - true,
                    "inside": inside,
                }
            )
    return rows


def fold_table(study: DuffingStudy) -> Table:
    """Jump frequencies of the sweeps against the true folds (continuation) and the harmonic-balance folds."""
    rows = []
    for r in fold_comparison(study):
        no_orbit = "no fold of the periodic orbit (single-valued response)"
        rows.append(
            {
                "case": r["case"],
                "dir": r["direction"],
                "orbit": _m(r["orbit"], no_orbit),
                "hb": _m(r["hb"], "no fold"),
                "time": _m(r["time"], "no jump in the sweep"),
                "bracket": _m(r["bracket"], "no jump in the sweep"),
                "hb_err": _m(r["hb_err"], "no fold"),
                "jump_err": _m(r["jump_err"], "no jump or no fold"),
            }
        )
    return Table(
        rows,
        [
            Column("case", "spring"),
            Column("dir", "sweep"),
            Column("orbit", "fold, periodic orbit (rad/s)", 6),
            Column("hb", "fold, one harmonic (rad/s)", 6),
            Column("time", "jump, time integration (rad/s)", 6),
            Column("bracket", "jump bracket (rad/s)", 2),
            Column("hb_err", "one harmonic − orbit (rad/s)", 2),
            Column("jump_err", "jump − orbit (rad/s)", 2),
        ],  # fmt: skip
        caption="Folds of the full equation (pseudo-arclength continuation of the periodic orbit by shooting: the "
        "branch turns where a Floquet multiplier passes +1), the one-harmonic folds, and where the sweeps jump "
        "(bracket refined by re-sweeping at 1/100 of the step).",
        name="tab-duffing-jumps",
    )


def history_table(study: DuffingStudy) -> Table:
    """Steady amplitude at the paper's frequency (and mid-band) depending on where the motion comes from."""
    return Table(
        study.history,
        [
            Column("where", "frequency"),
            Column("omega", "ω (rad/s)", 5),
            Column("linear", "linear (m)", 4),
            Column("hb_low", "lower stable A (m)", 4),
            Column("hb_high", "upper stable A (m)", 4),
            Column("rest", "from rest (m)", 4),
            Column("up", "sweep up (m)", 4),
            Column("down", "sweep down (m)", 4),
        ],  # fmt: skip
        caption=f"Hardening spring, k₃ = {study.cases[0].duffing.k3:g} N/m³: the steady amplitude depends on "
        "where the motion comes from only inside the bistable band.",
        name="tab-duffing-history",
    )


def _start(e) -> str:
    return f"x₀ = {e.x0:g} m, v₀ = {e.v0:g} m/s"


def lyapunov_table(study: DuffingStudy) -> Table:
    """Lyapunov exponents of the main chaotic run (both methods) and of the periodic case, with the sum check."""
    rows = []
    main, partner = study.lyap_runs[0], study.lyap_benettin
    for e in (main, partner):
        rows.append(
            {
                "case": f"chaotic, F = {study.F0_ueda:g} N",
                "start": _start(e),
                "method": "variational + QR" if e.method == "qr" else "two trajectories",
                "n": e.n_periods,
                "l1": Approx(e.exponent),
                "se": Approx(e.standard_error),
                "l2": Approx(e.second) if e.method == "qr" else Missing("the two-trajectory method gives λ₁ only"),
            }
        )
    for _, start, r in study.lyapunov:
        rows.append(
            {
                "case": f"periodic, F = {study.F0_periodic:g} N",
                "start": start.replace("x0", "x₀").replace("v0", "v₀"),
                "method": "variational + QR" if r.method == "qr" else "two trajectories",
                "n": r.running.size,
                "l1": r.exponents[0],
                "se": Missing("a periodic orbit: the exponent converges; the Floquet multipliers give it exactly"),
                "l2": r.exponents[1] if len(r.exponents) > 1 else Missing("the two-trajectory method gives λ₁ only"),
            }
        )
    return Table(
        rows,
        [
            Column("case", "Ueda's oscillator"),
            Column("start", "initial state"),
            Column("method", "method"),
            Column("n", "periods"),
            Column("l1", "λ_1 (1/s)", 4),
            Column("se", "standard error (1/s)", 1),
            Column("l2", "λ_2 (1/s)", 4),
        ],  # fmt: skip
        caption=f"Lyapunov exponents of x'' + {study.ueda.c:g} x' + x³ = F cos t (per unit time, natural logarithm); "
        "standard errors by batch means over 20 blocks. The two methods follow the same trajectory, so their "
        "agreement checks the code, not the estimate; λ₁ + λ₂ = −c/m holds by construction.",
        name="tab-duffing-lyapunov",
    )


def lyapunov_runs_table(study: DuffingStudy) -> Table:
    """Independent chaotic runs: other initial states and step sizes, each with its standard error."""
    pooled, se, chi2, dof = study.pooled
    rows = []
    for e in study.lyap_runs:
        rows.append(
            {
                "start": _start(e),
                "spp": e.steps_per_period,
                "h": e.period / e.steps_per_period,
                "n": e.n_periods,
                "l1": Approx(e.exponent),
                "se": Approx(e.standard_error),
                "z": Approx((e.exponent - pooled) / e.standard_error),
            }
        )
    total = sum(e.n_periods for e in study.lyap_runs)
    rows.append({"start": "pooled (inverse-variance weights)", "spp": None, "h": None, "n": total, "l1": Approx(pooled),
                 "se": Approx(se), "z": None})  # fmt: skip
    return Table(
        rows,
        [
            Column("start", "initial state"),
            Column("spp", "RK4 steps per period"),
            Column("h", "step h (s)", 3),
            Column("n", "periods"),
            Column("l1", "λ_1 (1/s)", 4),
            Column("se", "standard error (1/s)", 1),
            Column("z", "(λ_1 − pooled) / error", 2),
        ],  # fmt: skip
        caption=f"Largest exponent of Ueda's oscillator at F = {study.F0_ueda:g} N from runs that share no trajectory "
        "(other initial states, other RK4 steps), variational equations with QR.",
        name="tab-duffing-lyapunov-runs",
    )


def lyapunov_convergence(study: DuffingStudy) -> list[dict]:
    """The main run's estimate and batch-means error after 1000, 2000, 5000, ... periods (1/s)."""
    e = study.lyap_runs[0]
    n_blocks = min(20, e.n_periods // 10)
    lengths = [n for n in (1000, 2000, 5000, 10_000, 20_000, 50_000, 100_000) if 10 * n_blocks <= n < e.n_periods]
    rows = []
    for n in [*lengths, e.n_periods]:
        lam, se = e.at(n, n_blocks)
        rows.append({"n": n, "time": n * e.period, "l1": lam, "se": se})
    return rows


def lyapunov_convergence_table(study: DuffingStudy) -> Table:
    """Convergence of the main run: the estimate and its standard error against the averaging length."""
    rows = [{"n": r["n"], "time": r["time"], "l1": Approx(r["l1"]), "se": Approx(r["se"])}
            for r in lyapunov_convergence(study)]  # fmt: skip
    return Table(
        rows,
        [
            Column("n", "periods"),
            Column("time", "averaging time (s)", 3),
            Column("l1", "λ_1 (1/s)", 4),
            Column("se", "standard error (1/s)", 1),
        ],  # fmt: skip
        caption="The main run's largest exponent from its first N periods; the standard error falls as 1/√N.",
        name="tab-duffing-lyapunov-convergence",
    )


def checks_table(study: DuffingStudy) -> Table:
    """Rounding-level self-checks, printed as bounds."""
    cm = study.ueda.c / study.ueda.m
    qr_sums = [abs(e.exponent + e.second + cm) for e in study.lyap_runs]
    qr_sums += [abs(sum(r.exponents) + cm) for _, _, r in study.lyapunov if r.method == "qr"]
    fold_mu = [abs(f.multiplier - 1.0) for c in study.cases if c.branch for f in c.branch.folds]
    rows = [
        {
            "check": "amplitude equation on the drawn curves, relative residual",
            "bound": bound(study.amp_residual, 1e-12),
        },
        {"check": "Floquet: |μ₁ μ₂| against exp(−cT/m), relative error", "bound": bound(study.liouville, 1e-9)},
        {"check": "QR exponents: |λ₁ + λ₂ + c/m| (RK4 step error), 1/s", "bound": bound(max(qr_sums), 1e-6)},
        {
            "check": "continued folds: |μ − 1| of the multiplier closest to +1",
            "bound": bound(max(fold_mu), 1e-8) if fold_mu else Missing("no fold in either case"),
        },
    ]
    return Table(
        rows, [Column("check", "check"), Column("bound", "bound")], caption="Self-checks.", name="tab-duffing-checks"
    )


# --------------------------------------------------------------------------------- sentences


def trust_sentence(study: DuffingStudy) -> str:
    """The amplitude where the paper's linear answer stops being trustworthy, against its own amplitude."""
    d = study.cases[0].duffing
    a = study.trust_amplitude
    verdict = (
        "so the paper's resonant amplitude is already beyond it"
        if study.linear_amplitude > a
        else "so the paper's resonant amplitude stays below it"
    )
    return (
        f"With k₃ = {d.k3:g} N/m³ the backbone moves one half-power bandwidth (c/m = {d.c / d.m:g} rad/s) away from "
        f"ω_n = {d.natural_frequency:.4g} rad/s at an amplitude of {a:.3g} m. The linear steady amplitude at "
        f"ω = {study.omega_res:g} rad/s is {study.linear_amplitude:.4g} m, {verdict}."
    )


def paper_sentence(study: DuffingStudy) -> str:
    """What the paper's resonance scenario becomes with the hardening spring."""
    lin, duf = np.abs(study.paper_x_linear).max(), np.abs(study.paper_x_duffing).max()
    h = study.history[0]
    case = study.cases[0]
    f = case.folds
    same = abs(h["up"] - h["down"]) <= 1e-3 * max(h["up"], h["down"])
    where = (
        f"The steady amplitude there is {h['hb_low']:.4g} m whichever way the frequency is approached "
        f"(sweep up {h['up']:.4g} m, sweep down {h['down']:.4g} m): the resonance has moved"
        if same
        else f"There the sweep up ends at {h['up']:.4g} m and the sweep down at {h['down']:.4g} m"
    )
    band = (
        f" to the band {f.omega_low:.4g} to {f.omega_high:.4g} rad/s, where two stable amplitudes coexist and the "
        f"largest, {f.peak_amplitude:.3g} m, is reached only by sweeping up."
        if f.bistable and same
        else "."
    )
    return (
        f"From rest, the largest |x| in the paper's {study.t_end:g} s window at ω = {study.omega_res:g} rad/s is "
        f"{lin:.4g} m with the linear spring and {duf:.4g} m with k₃ = {case.duffing.k3:g} N/m³. {where}{band}"
    )


def fold_sentence(study: DuffingStudy) -> str:
    """The fold comparison: true folds, one harmonic, sweep jumps, and whether each jump brackets its fold."""
    parts = []
    for r in fold_comparison(study):
        head = f"{r['case']} sweep {r['direction']}"
        if not math.isfinite(r["time"]):
            parts.append(f"{head}: no jump")
            continue
        if not math.isfinite(r["orbit"]):
            parts.append(
                f"{head}: jump at {r['time']:.5g} rad/s, harmonic balance {r['hb']:.5g} rad/s (no fold of the periodic "
                "orbit was found to compare with)"
            )
            continue
        where = (
            "inside the jump's bracket"
            if r["inside"]
            else f"outside the jump's bracket (the jump is {r['jump_err']:+.2g} rad/s from it)"
        )
        early = ""
        if r["direction"] == "down" and r["time"] > r["hb"]:
            early = ", so the sweep down jumps before it reaches the one-harmonic fold"
        elif r["direction"] == "up" and r["time"] > r["hb"]:
            early = ", so the sweep up runs past the one-harmonic fold before it jumps"
        parts.append(
            f"{head}: the periodic orbit folds at {r['orbit']:.6g} rad/s, {where}; harmonic balance puts the fold at "
            f"{r['hb']:.5g} rad/s ({r['hb_err']:+.2g} rad/s) and the sweep jumps at {r['time']:.5g} rad/s{early}"
        )
    return "Fold frequencies: " + "; ".join(parts) + "."


def _pm(value: float, se: float) -> str:
    """``value ± se`` with the digits the standard error supports (down to its leading digit)."""
    if not (math.isfinite(se) and se > 0):
        return f"{value:.3g}"
    digits = max(0, -math.floor(math.log10(se)))
    return f"{value:.{digits}f} ± {se:.{digits}f}"


def lyapunov_sentence(study: DuffingStudy) -> str:
    """The largest exponent with its uncertainty, what the two methods' agreement does and does not show."""
    main, partner = study.lyap_runs[0], study.lyap_benettin
    pooled, se, chi2, dof = study.pooled
    starts = {(e.x0, e.v0) for e in study.lyap_runs}
    steps = sorted({e.period / e.steps_per_period for e in study.lyap_runs})
    consistent = chi2 <= dof + 3.0 * math.sqrt(2.0 * dof)
    agree = (
        f"agree within their errors (χ² = {chi2:.2g} for {dof} degrees of freedom)"
        if consistent
        else f"scatter more than their errors allow (χ² = {chi2:.2g} for {dof} degrees of freedom)"
    )
    if pooled - 3.0 * se > 0:
        verdict = "positive: the motion is chaotic"
    elif pooled + 3.0 * se < 0:
        verdict = "negative: the motion is not chaotic (it settles on a stable orbit)"
    else:
        verdict = "not distinguishable from zero at three standard errors"
    per = [r.exponents[0] for _, _, r in study.lyapunov]
    floq = (
        f", as the Floquet multipliers of its orbit give ({study.floquet_periodic:.3g} 1/s)"
        if math.isfinite(study.floquet_periodic)
        else ""
    )
    return (
        f"Largest Lyapunov exponent of Ueda's oscillator at F = {study.F0_ueda:g} N: λ₁ = "
        f"{_pm(main.exponent, main.standard_error)} 1/s from the main run of {main.n_periods} periods (standard error "
        f"by batch means over {main.block_means.size} blocks of {main.block_periods} periods). The "
        f"{len(study.lyap_runs)} runs from {len(starts)} initial states and step sizes h = {steps[0]:.2g} to "
        f"{steps[-1]:.2g} s share no trajectory; they {agree} and pool to λ₁ = {_pm(pooled, se)} 1/s, {verdict}. "
        f"The two-trajectory method gives {_pm(partner.exponent, partner.standard_error)} 1/s on the main run's "
        "trajectory: the two methods follow one trajectory, so their agreement checks the code, not the estimate. "
        "Likewise λ₁ + λ₂ = −c/m holds by construction of the QR method (the trace of the Jacobian), so it checks "
        f"the integration, not λ₁. At F = {study.F0_periodic:g} N the largest exponent is {max(per):.3g} 1/s{floq}."
    )


def published_sentence(study: DuffingStudy) -> str:
    """The pooled exponent against the published one, with what can and cannot explain the difference."""
    pub = PUBLISHED_UEDA
    if not (study.ueda.c == pub["c"] and study.F0_ueda == pub["F0"]):
        return (
            f"The published exponent ({pub['exponent']:g} 1/s) is for c = {pub['c']:g} N s/m and F = {pub['F0']:g} N; "
            f"with c = {study.ueda.c:g} N s/m and F = {study.F0_ueda:g} N there is no published value to compare with."
        )
    pooled, se, _, _ = study.pooled
    main = study.lyap_runs[0]
    delta = pooled - pub["exponent"]
    z = delta / se
    sigma1 = main.standard_error * math.sqrt(main.n_periods)  # scatter of a one-period average, 1/s
    zs = {e.steps_per_period: (e.exponent - pooled) / e.standard_error for e in study.lyap_runs[1:]}
    by_step = [f"{spp} steps per period {zs[spp]:+.1f}" for spp in sorted(zs) if spp != main.steps_per_period]
    spp_pub = 2 * math.pi / pub["step"]
    head = (
        f"Sprott's table gives {pub['exponent']:g} 1/s for this oscillator (per unit time, natural logarithm, as "
        f"here; per forcing period it would be 2π times larger, {2 * math.pi * pub['exponent']:.2f}). "
    )
    if abs(z) <= 2.0:
        return head + f"The pooled {_pm(pooled, se)} 1/s agrees with it within two standard errors ({z:+.1f})."
    n_star = (2.0 * sigma1 / delta) ** 2
    n_text, t_text = f"{float(f'{n_star:.2g}'):,.0f}", f"{float(f'{n_star * main.period:.2g}'):,.0f}"
    step_ok = all(abs(zs[spp]) <= 2.0 for spp in zs if spp != main.steps_per_period)
    step_verdict = "The step size does not explain this" if step_ok else "The step size may contribute"
    return head + (
        f"The pooled {_pm(pooled, se)} 1/s is {abs(z):.2g} standard errors {'above' if z > 0 else 'below'} it "
        f"({delta:+.2g} 1/s, {100 * delta / pub['exponent']:+.2g} %). {step_verdict}: runs with "
        f"other steps differ from the pooled value by {', '.join(by_step) or 'no run'} standard errors "
        f"(the published run used h = {pub['step']:g} s, {spp_pub:.0f} steps per period), and the definitions are "
        "the same (the published third exponent, 0, is that of time taken as a variable). The averaging length "
        "can: a single run of N periods scatters about the long-run value with standard deviation "
        f"{sigma1:.2g}/√N 1/s (from the main run's batch means), so a run shorter than about {n_text} periods "
        f"({t_text} s) misses it by {abs(delta):.2g} 1/s or more with a probability above 5 %. "
        "The published value states no averaging length; a finite-time average is the likeliest explanation."
    )


# --------------------------------------------------------------------------- sliders: JupyterLab


_counter = itertools.count(1)


def _panel_params(m, c, k, k3, F0, omega_max, k3_range, F0_max) -> dict:
    """The slider panel's values; a range left as None covers the chapter's case (twice its value, at least the
    paper's range), so that a run with other parameters still shows its resonance and its force."""
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    c = check_real("c", c, low=0.0, low_open=True, unit="N s/m")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    if omega_max is None:
        omega_max = max(8.0, 2.0 * math.sqrt(k / m))
    if k3_range is None:
        k3_range = max(5.0, 2.0 * abs(check_real("k3", k3, unit="N/m^3")))
    if F0_max is None:
        F0_max = max(20.0, 2.0 * check_real("F0", F0, low=0.0, low_open=True, unit="N"))
    k3_range = check_real("k3_range", k3_range, low=0.0, low_open=True, unit="N/m^3")
    k3 = check_real("k3", k3, low=-k3_range, high=k3_range, unit="N/m^3")
    F0_max = check_real("F0_max", F0_max, low=0.0, low_open=True, unit="N")
    F0 = check_real("F0", F0, low=0.0, low_open=True, high=F0_max, unit="N")
    omega_max = check_real("omega_max", omega_max, low=0.0, low_open=True, unit="rad/s")
    return {"m": m, "c": c, "k": k, "k3": k3, "F0": F0, "omega_max": omega_max, "k3_range": k3_range, "F0_max": F0_max}


def hb_panel_html(
    m: float = 1.0,
    c: float = 0.5,
    k: float = 20.0,
    k3: float = 2.0,
    F0: float = 5.0,
    omega_max: float | None = None,
    k3_range: float | None = None,
    F0_max: float | None = None,
) -> str:
    """Kernel-free slider panel: k3 and F0 move the harmonic-balance curve (all branches).

    Self-contained HTML (inline ``assets/duffing.css`` and ``assets/duffing.js``, no URL): the
    browser computes the curve by the amplitude parametrisation of
    :func:`vibration.physics.duffing.response_curve`, its stability, the folds and the
    amplitudes at a probe frequency by the closed-form cubic of
    :func:`vibration.physics.duffing.hb_amplitudes`; ``window.vibrationDuffing`` exposes the
    functions so tests compare them with Python.

    Parameters
    ----------
    m, c, k : float
        Mass (kg), damping (N s/m, > 0), linear stiffness (N/m, > 0).
    k3 : float
        Starting cubic stiffness, N/m^3, within ``±k3_range``.
    F0 : float
        Starting force amplitude, N, in ``(0, F0_max]``.
    omega_max : float, optional
        Right end of the frequency axis, rad/s (default: 8 or twice the natural frequency, the larger).
    k3_range : float, optional
        The k3 slider spans ``-k3_range`` to ``k3_range`` N/m^3 (default: 5 or twice |k3|, the larger).
    F0_max : float, optional
        The F0 slider spans ``F0_max / 200`` to ``F0_max`` N (default: 20 or twice F0, the larger).

    Returns
    -------
    str
        ``<div class="vib-duffing" ...>`` with its style, controls, an SVG and scripts.

    Examples
    --------
    >>> frag = hb_panel_html()
    >>> frag.startswith('<div class="vib-duffing"'), "<script src" in frag or "<link" in frag
    (True, False)
    """
    params = _panel_params(m, c, k, k3, F0, omega_max, k3_range, F0_max)
    k3_range, F0_max = params["k3_range"], params["F0_max"]
    digest = hashlib.sha1(json.dumps(params, sort_keys=True).encode()).hexdigest()[:8]
    pid = f"vib-duffing-{digest}-{next(_counter)}"
    e = html.escape
    return f"""<div class="vib-duffing" id="{e(pid)}" data-params="{e(json.dumps(params))}">
<style>
{_asset("duffing.css")}</style>
<p class="vd-sub">One-harmonic frequency response of \
<i>m x'' + c x' + k x + k<sub>3</sub> x<sup>3</sup> = F<sub>0</sub> cos(ωt)</i> \
with m = {m:g} kg, c = {c:g} N s/m, k = {k:g} N/m, computed in your browser: solid stable, dashed unstable, \
dotted the backbone, circles the folds.</p>
<noscript>This panel needs JavaScript to draw its plot.</noscript>
<div class="vd-controls">
<label for="{e(pid)}-k3">cubic stiffness k<sub>3</sub></label>
<input type="range" class="vd-k3" id="{e(pid)}-k3" min="{-k3_range:g}" max="{k3_range:g}" \
step="{k3_range / 500:g}" value="{k3!r}">
<output class="vd-k3-out" for="{e(pid)}-k3"></output>
<label for="{e(pid)}-F0">force amplitude F<sub>0</sub></label>
<input type="range" class="vd-F0" id="{e(pid)}-F0" min="{F0_max / 200:g}" max="{F0_max:g}" \
step="{F0_max / 200:g}" value="{F0!r}">
<output class="vd-F0-out" for="{e(pid)}-F0"></output>
</div>
<svg class="vd-plot" viewBox="0 0 640 300" role="img" \
aria-label="amplitude in m against forcing frequency in rad/s"></svg>
<p class="vd-readout"></p>
<script>
{_asset("duffing.js")}</script>
<script>window.vibrationDuffing.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


class HBExplorer:
    """JupyterLab sliders (ipywidgets) for k3 and F0 over the harmonic-balance curve.

    Displays as the live widget in JupyterLab; renderers without a kernel get the
    kernel-free panel of :func:`hb_panel_html` at the same parameters.
    """

    def __init__(self, m=1.0, c=0.5, k=20.0, k3=2.0, F0=5.0, omega_max=None, k3_range=None, F0_max=None):
        import ipywidgets as widgets
        import matplotlib.pyplot as plt

        self.params = _panel_params(m, c, k, k3, F0, omega_max, k3_range, F0_max)
        k3_range, F0_max = self.params["k3_range"], self.params["F0_max"]
        self.k3_slider = widgets.FloatSlider(value=k3, min=-k3_range, max=k3_range, step=k3_range / 500,
                                             description="k3 (N/m³)", continuous_update=False)  # fmt: skip
        self.F0_slider = widgets.FloatSlider(value=F0, min=F0_max / 200, max=F0_max, step=F0_max / 200,
                                             description="F0 (N)", continuous_update=False)  # fmt: skip
        self.image = widgets.Image(format="png", layout=widgets.Layout(max_width="100%", height="auto"))
        with plt.ioff():
            self.fig, self.ax = figure(1, 1, height=3.4)
        self.widget = widgets.VBox([widgets.HBox([self.k3_slider, self.F0_slider]), self.image])
        self.k3_slider.observe(lambda _: self.update(), names="value")
        self.F0_slider.observe(lambda _: self.update(), names="value")
        self.update()

    def update(self) -> None:
        """Redraw the curve for the sliders' values."""
        p = self.params
        d = Duffing(p["m"], p["c"], p["k"], float(self.k3_slider.value))
        F0 = float(self.F0_slider.value)
        ax = self.ax
        ax.clear()
        curve = response_curve(d, F0, p["omega_max"], n=801)
        _plot_curve(ax, curve, C_HARD if d.k3 >= 0 else C_SOFT, f"$k_3$ = {d.k3:.3g} N/m$^3$")
        a_bb = np.linspace(0.0, 1.1 * np.nanmax(curve[1]), 200)
        ax.plot(backbone(d, a_bb), a_bb, "k:", lw=0.8, label="backbone")
        f = folds(d, F0)
        if f.bistable:
            ax.plot(
                [f.omega_low, f.omega_high],
                [f.amplitude_low, f.amplitude_high],
                "o",
                mfc="white",
                color="k",
                label="folds",
            )
        ax.set_xlim(0.0, p["omega_max"])
        ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
        ax.set_ylabel(r"amplitude $A$ (m)")
        place_legend(ax)
        buf = io.BytesIO()
        self.fig.savefig(buf, format="png")
        self.image.value = buf.getvalue()

    def _repr_mimebundle_(self, include=None, exclude=None):
        data = self.widget._repr_mimebundle_()
        p = dict(self.params, k3=float(self.k3_slider.value), F0=float(self.F0_slider.value))
        data["text/html"] = hb_panel_html(**p)
        data["text/plain"] = f"HBExplorer(k3={p['k3']:g} N/m^3, F0={p['F0']:g} N)"
        return data


def hb_explorer(m=1.0, c=0.5, k=20.0, k3=2.0, F0=5.0, omega_max=None, k3_range=None, F0_max=None) -> HBExplorer:
    """JupyterLab explorer of the harmonic-balance curve (k3 in N/m^3 and F0 in N sliders).

    Parameters are those of :func:`hb_panel_html` (kg, N s/m, N/m, N/m^3, N, rad/s).

    Examples
    --------
    >>> ex = hb_explorer()
    >>> ex.k3_slider.value = -1.0
    >>> round(float(ex.ax.get_xlim()[1]), 4)      # rad/s: twice the natural frequency sqrt(20)
    8.9443
    """
    return HBExplorer(m, c, k, k3, F0, omega_max, k3_range, F0_max)


def closing_note(study: DuffingStudy) -> str:
    """The chapter's closing note: fold frequencies by the three methods, and the exponents with their errors."""
    return fold_sentence(study) + " " + lyapunov_sentence(study) + " " + published_sentence(study)
