"""Chapter 7 (control): studies run once, and the figures, tables and sentences built from them.

:func:`active_study`, :func:`semi_active_study` and :func:`shaping_study` run the physics of
:mod:`vibration.physics.control` once for the chapter's parameters; every figure, table and
sentence below reads those results, so a run with other parameters never contradicts itself.

Examples
--------
>>> s = shaping_study(1.0, 0.5, 20.0, move=0.1, freq_error=0.1, n_points=401, n_ratio=21)
>>> s.shapers["ZV"].kind, round(float(s.residual["ZV"]), 3)
('ZV', 0.143)
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from ..physics.control import (
    SPENCER_1997,
    SPENCER_1997_STROKE,
    LoopCosts,
    LQRResult,
    Metrics,
    PIDResponse,
    force_floor,
    hold_force,
    insensitivity_band,
    largest_holdable_reference,
    loop_costs,
    lqr,
    lqr_closed_form,
    passive_transmissibility,
    pd_oscillator,
    pid_poles,
    pid_response,
    residual_amplitude,
    response_metrics,
    semi_active_response,
    semi_active_sweep,
    shaped_move,
    shaper_residual,
    simulate_controlled,
    skyhook_power,
    skyhook_transmissibility,
    stabilising_velocity_gain,
    zv_shaper,
    zvd_shaper,
)
from ..physics.exact import exact_response, steady_state
from ..physics.model import N_POINTS_MAX, Oscillator, SineForce, check_int, check_real
from .static_page import _asset
from .style import figure, place_legend
from .tables import Column, Missing, Table, bound

#: Forcing periods at the end of the window that count as steady state.
STEADY_PERIODS = 10


def _t_steady(t_end: float, omega: float) -> float:
    return max(0.0, t_end - STEADY_PERIODS * 2.0 * math.pi / omega) if omega > 0 else 0.5 * t_end


# ----------------------------------------------------------------------------- active


@dataclass(frozen=True)
class ActiveStudy:
    """Every active-control run of the chapter, at the paper's resonance."""

    osc: Oscillator  # plant (m, c_nominal, k)
    force: SineForce  # disturbance at the resonant frequency
    t: np.ndarray  # output times, s
    x: dict  # name -> displacement, m
    u: dict  # name -> control force, N
    v: dict  # name -> velocity, m/s
    metrics: dict  # name -> Metrics
    pd: Oscillator  # closed loop of the PD gains
    pd_error: float  # max |simulated - exact| of the PD loop, m
    lqr: LQRResult  # LQR design
    lqr_check: dict  # discrepancies: scipy Riccati, closed form, Riccati residual
    tradeoff: dict  # r grid and steady amplitude / force along it
    move: dict  # anti-windup name -> PIDResponse of the set-point move
    move_ref: float  # set point of the move, m
    u_max: float  # actuator force limit, N
    pid_gains: tuple  # (kp, ki, kd)
    flutter: Oscillator  # negative-damping plant
    kd_star: float  # smallest stabilising velocity gain, N s/m
    t_steady: float  # start of the steady-state tail, s
    pd_pid: Oscillator  # closed loop of a PD with the PID's kp and kd (no integrator)
    costs: dict  # name -> LoopCosts (delay margin, crossover, loop gain, noise bandwidth)
    amplitude: dict  # name -> steady amplitude of the unlimited linear loop, m
    pid_poles: object  # PIDPoles of the PID gains
    hold: dict  # force needed to hold x_ref, the largest holdable set point, and the feasible move
    gains: dict  # name -> (K_x N/m, K_i N/(m s), K_v N s/m)


def active_study(
    m: float,
    c: float,
    k: float,
    F0: float,
    omega: float,
    t_end: float,
    n_points: int,
    *,
    kp: float,
    kd: float,
    pid_kp: float,
    pid_ki: float,
    pid_kd: float,
    u_max: float,
    x_ref: float,
    q_x: float,
    q_v: float,
    r: float,
    c_flutter: float,
    n_r: int = 61,
) -> ActiveStudy:
    """Passive, PD, LQR and PID at the forcing ``F0 sin(omega t)``, the PID move, the LQR trade-off.

    Units: kg, N s/m, N/m, N, rad/s, s; gains N/m, N/(m s), N s/m; limit N; set point m;
    LQR weights 1/m^2, s^2/m^2, 1/N^2; ``c_flutter`` the negative damping, N s/m.

    Examples
    --------
    >>> a = active_study(1.0, 0.5, 20.0, 5.0, 4.47, 10.0, 201, kp=16.0, kd=5.5, pid_kp=133.6,
    ...                  pid_ki=512.0, pid_kd=18.7, u_max=12.0, x_ref=0.5, q_x=1.0, q_v=0.0, r=1e-3,
    ...                  c_flutter=-0.5, n_r=5)
    >>> sorted(a.metrics), a.kd_star
    (['LQR', 'PD', 'PD2', 'PID', 'passive'], 0.5)
    """
    osc, force = Oscillator(m, c, k), SineForce(F0, omega)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=11, high=N_POINTS_MAX)
    u_max = check_real("u_max", u_max, low=0.0, low_open=True, unit="N")
    n_r = check_int("n_r", n_r, low=2, high=2000)
    t = np.linspace(0.0, t_end, n_points)
    ts = _t_steady(t_end, omega)
    xs, us, vs = {}, {}, {}

    ex = exact_response(osc, force, t)
    xs["passive"], us["passive"], vs["passive"] = ex.x, np.zeros_like(t), ex.v

    pd = pd_oscillator(osc, kp, kd)
    exp_pd = exact_response(pd, force, t)
    sim_pd = simulate_controlled(osc, lambda _t, x, v: -kp * x - kd * v, force, t_end=t_end, n_points=n_points)
    xs["PD"], us["PD"], vs["PD"] = exp_pd.x, -kp * exp_pd.x - kd * exp_pd.v, exp_pd.v
    pd_error = float(np.max(np.abs(sim_pd.x - exp_pd.x)))

    pd_pid = pd_oscillator(osc, pid_kp, pid_kd)
    exp_pp = exact_response(pd_pid, force, t)
    xs["PD2"], us["PD2"], vs["PD2"] = exp_pp.x, -pid_kp * exp_pp.x - pid_kd * exp_pp.v, exp_pp.v

    design = lqr(osc, q_x, q_v, r)
    from scipy.linalg import solve_continuous_are

    A = np.array([[0.0, 1.0], [-k / m, -c / m]])
    B = np.array([[0.0], [1.0 / m]])
    Q = np.diag([q_x, q_v])
    P = solve_continuous_are(A, B, Q, np.array([[r]]))
    K_sp = (B.T @ P / r).ravel()
    resid = A.T @ design.P + design.P @ A - design.P @ B @ B.T @ design.P / r + Q
    scale_k = float(np.max(np.abs(K_sp)))
    lqr_check = {
        "scipy": float(np.max(np.abs(design.K - K_sp))) / scale_k,
        "closed form": float(np.max(np.abs(design.K - lqr_closed_form(osc, q_x, q_v, r)))) / scale_k,
        "residual": float(np.max(np.abs(resid))) / float(np.max(np.abs(design.P)) * max(1.0, np.max(np.abs(A)))),
    }
    cl = design.closed_loop
    exp_lqr = exact_response(cl, force, t)
    xs["LQR"], us["LQR"], vs["LQR"] = exp_lqr.x, -design.K[0] * exp_lqr.x - design.K[1] * exp_lqr.v, exp_lqr.v

    reg = pid_response(
        osc, force, pid_kp, pid_ki, pid_kd, u_max=u_max, anti_windup="clamping", t_end=t_end, n_points=n_points
    )
    xs["PID"], us["PID"], vs["PID"] = reg.x, reg.u, reg.v

    metrics = {name: response_metrics(t, xs[name], us[name], vs[name], ts) for name in xs}

    rs = np.geomspace(1e-7, 1e2, n_r) * r / 1e-3 if r > 0 else np.geomspace(1e-7, 1e2, n_r)
    amp, frc = [], []
    for ri in rs:
        des = lqr(osc, q_x, q_v, float(ri))
        ss = steady_state(des.closed_loop, force)
        amp.append(ss.amplitude)
        frc.append(ss.amplitude * abs(des.K[0] + 1j * omega * des.K[1]) / math.sqrt(2.0))
    tradeoff = {"r": rs, "amplitude": np.array(amp), "force_rms": np.array(frc)}

    move = {}
    for aw in ("none", "clamping", "back-calculation"):
        move[aw] = pid_response(
            osc, force, pid_kp, pid_ki, pid_kd, u_max=u_max, anti_windup=aw, x_ref=x_ref, t_end=t_end,
            n_points=n_points,
        )  # fmt: skip
    move["unlimited"] = pid_response(osc, force, pid_kp, pid_ki, pid_kd, x_ref=x_ref, t_end=t_end, n_points=n_points)
    flutter = Oscillator(m, c_flutter, k)
    gains = {
        "PD": (kp, 0.0, kd),
        "PD2": (pid_kp, 0.0, pid_kd),
        "LQR": (float(design.K[0]), 0.0, float(design.K[1])),
        "PID": (pid_kp, pid_ki, pid_kd),
    }
    costs = {name: loop_costs(osc, g[0], g[2], g[1], omega) for name, g in gains.items()}
    amplitude = {name: loop_amplitude(osc, force, *g) for name, g in gains.items()}
    amplitude["passive"] = steady_state(osc, force).amplitude
    x_ok = largest_holdable_reference(osc, force, u_max)
    hold = {"needed": hold_force(osc, force, x_ref), "x_max": x_ok, "x_ok": math.nan, "run": None}
    if math.isfinite(x_ok) and x_ok > 0.0:
        hold["x_ok"] = 0.8 * x_ok * (1.0 if x_ref >= 0.0 else -1.0)
        hold["run"] = pid_response(
            osc, force, pid_kp, pid_ki, pid_kd, u_max=u_max, anti_windup="clamping", x_ref=hold["x_ok"],
            t_end=t_end, n_points=n_points,
        )  # fmt: skip
    return ActiveStudy(
        osc=osc,
        force=force,
        t=t,
        x=xs,
        u=us,
        v=vs,
        metrics=metrics,
        pd=pd,
        pd_error=pd_error,
        lqr=design,
        lqr_check=lqr_check,
        tradeoff=tradeoff,
        move=move,
        move_ref=x_ref,
        u_max=u_max,
        pid_gains=(pid_kp, pid_ki, pid_kd),
        flutter=flutter,
        kd_star=stabilising_velocity_gain(flutter),
        t_steady=ts,
        pd_pid=pd_pid,
        costs=costs,
        amplitude=amplitude,
        pid_poles=pid_poles(osc, pid_kp, pid_ki, pid_kd),
        hold=hold,
        gains=gains,
    )


def loop_amplitude(osc: Oscillator, force: SineForce, kp: float, ki: float, kd: float) -> float:
    """Steady amplitude (m) of the unlimited loop ``kp + ki/s + kd s`` at the forcing: ``F0 |P / (1 + P C)|``."""
    w = force.omega
    C = kp + 1j * kd * w + (ki / (1j * w) if ki > 0.0 else 0.0)
    return force.F0 / abs(osc.k - osc.m * w * w + 1j * osc.c * w + C)


_LABELS = {
    "passive": "passive",
    "PD": "PD",
    "PD2": "PD with the PID's K_p, K_d",
    "LQR": "LQR",
    "PID": "PID (limited, clamping)",
}


def active_figure(a: ActiveStudy):
    """Displacement and control force of every active controller at resonance (two panels)."""
    fig, (ax1, ax2) = figure(2, 1, height=5.0, sharex=True)
    for name, col in (("passive", "C0"), ("PD", "C1"), ("LQR", "C2"), ("PID", "C3")):
        lw = 1.0 if name == "passive" else 1.3
        ax1.plot(a.t, a.x[name], label=_LABELS[name], lw=lw, color=col)
        ax2.plot(a.t, a.u[name], label=_LABELS[name], lw=lw, color=col)
    ax1.set_ylabel(r"$x$ (m)")
    ax2.set_ylabel(r"$u$ (N)")
    ax2.set_xlabel(r"$t$ (s)")
    ax1.set_title(
        rf"forced at $\omega$ = {a.force.omega:g} rad/s, $F_0$ = {a.force.F0:g} N, passive $c$ = {a.osc.c:g} N s/m"
    )
    place_legend(ax1, outside=True)
    return fig


def active_zoom_figure(a: ActiveStudy):
    """The controlled responses on their own scale (the passive one is 10 to 100 times larger)."""
    fig, ax = figure(height=3.2)
    for name in ("PD", "LQR", "PD2", "PID"):
        ax.plot(
            a.t, a.x[name] * 1e3, label=_LABELS[name], color={"PD": "C1", "LQR": "C2", "PD2": "C4", "PID": "C3"}[name]
        )
    ax.set_xlabel(r"$t$ (s)")
    ax.set_ylabel(r"$x$ (mm)")
    place_legend(ax, outside=True)
    return fig


_METRIC_COLUMNS = [
    Column("controller", "controller"),
    Column("peak_x", "max|x| (m)", 3),
    Column("rms_x", "x_rms (m)", 3),
    Column("peak_x_ss", "max|x|_ss (m)", 3),
    Column("rms_x_ss", "x_rms,ss (m)", 3),
    Column("reduction", "reduction_ss", 3),
    Column("peak_u", "max|u| (N)", 3),
    Column("rms_u", "u_rms (N)", 3),
    Column("energy", "E (J)", 3),
]


def _metric_rows(metrics: dict, labels: dict, reference: str) -> list[dict]:
    ref = metrics[reference].rms_x_ss
    rows = []
    for name, mt in metrics.items():
        rows.append(
            {
                "controller": labels.get(name, name),
                **{f: getattr(mt, f) for f in Metrics.__dataclass_fields__},
                "reduction": ref / mt.rms_x_ss if mt.rms_x_ss > 0 else math.inf,
            }
        )
    return rows


def active_metrics_table(a: ActiveStudy) -> Table:
    """Peak and RMS displacement (window and steady state), force and energy per active controller."""
    return Table(
        _metric_rows(a.metrics, _LABELS, "passive"),
        _METRIC_COLUMNS,
        caption=(
            f"Active control at ω = {a.force.omega:g} rad/s from rest over {a.t[-1]:g} s: displacement over the "
            f"window and in steady state (the last {STEADY_PERIODS} forcing periods, from t = {a.t_steady:.4g} s), "
            "the steady RMS reduction against the passive oscillator, control force and the energy ∫|u v| dt "
            "the actuator exchanges with the mass."
        ),
        name="tab-control-active",
    )


def gains_table(a: ActiveStudy, kp: float, kd: float) -> Table:
    """Gains, closed-loop natural frequency, damping ratio and poles of PD and LQR."""
    rows = []
    for name, (g0, g1), cl in (
        ("PD", (kp, kd), a.pd),
        ("LQR", tuple(a.lqr.K), a.lqr.closed_loop),
    ):
        poles = np.roots([cl.m, cl.c, cl.k])
        p = poles[np.argmax(poles.imag)] if np.iscomplexobj(poles) else poles.max()
        rows.append(
            {
                "law": name,
                "k0": float(g0),
                "k1": float(g1),
                "wn": cl.natural_frequency,
                "zeta": cl.damping_ratio,
                "re": float(np.real(p)),
                "im": abs(float(np.imag(p))),
                "X": steady_state(cl, a.force).amplitude,
            }
        )
    return Table(
        rows,
        [
            Column("law", "law"),
            Column("k0", "K_x (N/m)", 4),
            Column("k1", "K_v (N s/m)", 4),
            Column("wn", "ω_n,cl (rad/s)", 4),
            Column("zeta", "ζ_cl", 3),
            Column("re", "Re s (1/s)", 4),
            Column("im", "|Im s| (rad/s)", 4),
            Column("X", "X_ss (m)", 4),
        ],
        caption=(
            "The closed loop of u = −K_x x − K_v v is the oscillator (m, c + K_v, k + K_x): its natural frequency, "
            "damping ratio, pole pair s and steady amplitude at the resonant forcing."
        ),
        name="tab-control-gains",
    )


def checks_table(a: ActiveStudy) -> Table:
    """Rounding-level checks of the active designs, printed as bounds."""
    rows = [
        {"check": "PD simulated (DOP853) against the exact oscillator (m, c + K_v, k + K_x), max |Δx| (m)",
         "value": bound(a.pd_error, 1e-9)},
        {"check": "LQR gains: python-control against scipy's Riccati solver, relative",
         "value": bound(a.lqr_check["scipy"], 1e-12)},
        {"check": "LQR gains: python-control against the closed form, relative",
         "value": bound(a.lqr_check["closed form"], 1e-12)},
        {"check": "Riccati residual of the returned P, relative", "value": bound(a.lqr_check["residual"], 1e-12)},
    ]  # fmt: skip
    return Table(
        rows,
        [Column("check", "check"), Column("value", "bound")],
        caption="Self-checks of the active designs (rounding level, printed as bounds).",
        name="tab-control-checks",
    )


def tradeoff_figure(a: ActiveStudy):
    """LQR trade-off: steady RMS force against steady amplitude as r varies, design point marked."""
    fig, ax = figure(height=3.4)
    tr = a.tradeoff
    ax.loglog(tr["force_rms"], tr["amplitude"], color="C2", label=r"LQR, $r$ varied")
    ss = steady_state(a.lqr.closed_loop, a.force)
    f_op = ss.amplitude * abs(a.lqr.K[0] + 1j * a.force.omega * a.lqr.K[1]) / math.sqrt(2.0)
    ax.loglog([f_op], [ss.amplitude], "o", color="C2", label=rf"design, $r$ = {a.lqr.r:g} 1/N$^2$")
    ss_p = steady_state(a.osc, a.force)
    ax.axhline(ss_p.amplitude, color="0.4", ls="--", lw=1.0, label=rf"passive, $X$ = {ss_p.amplitude:.3g} m")
    ss_pd = steady_state(a.pd, a.force)
    f_pd = ss_pd.amplitude * abs((a.pd.k - a.osc.k) + 1j * a.force.omega * (a.pd.c - a.osc.c)) / math.sqrt(2.0)
    ax.loglog([f_pd], [ss_pd.amplitude], "s", color="C1", label="PD")
    xs = np.geomspace(float(np.min(tr["amplitude"])), ss_p.amplitude, 200)
    ax.loglog(force_floor(a.osc, a.force, xs), xs, color="k", ls=":", lw=1.0,
              label=r"least force for $X$: $(F_0 - |Z|X)/\sqrt{2}$")  # fmt: skip
    ax.axvline(a.force.F0 / math.sqrt(2.0), color="0.6", lw=0.8)
    ax.set_xlabel(r"steady RMS control force $u_{rms}$ (N)")
    ax.set_ylabel(r"steady amplitude $X$ (m)")
    place_legend(ax)
    return fig


def move_figure(a: ActiveStudy):
    """PID set-point move under the resonant disturbance: displacement and force per anti-windup scheme."""
    fig, (ax1, ax2) = figure(2, 1, height=5.0, sharex=True)
    colors = {"unlimited": "0.5", "none": "C1", "clamping": "C2", "back-calculation": "C3"}
    for name in ("unlimited", "none", "clamping", "back-calculation"):
        r = a.move[name]
        lab = "no limit" if name == "unlimited" else f"limited, {'no anti-windup' if name == 'none' else name}"
        ax1.plot(r.t, r.x, color=colors[name], label=lab, lw=1.0 if name == "unlimited" else 1.3)
        ax2.plot(r.t, r.u, color=colors[name], label=lab, lw=1.0 if name == "unlimited" else 1.3)
    ax1.axhline(a.move_ref, color="k", lw=0.8, ls=":")
    for s in (1, -1):
        ax2.axhline(s * a.u_max, color="k", lw=0.8, ls=":")
    ax1.set_ylabel(r"$x$ (m)")
    ax2.set_ylabel(r"$u$ (N)")
    ax2.set_xlabel(r"$t$ (s)")
    ax2.set_ylim(-2.2 * a.u_max, 2.2 * a.u_max)
    ax1.set_xlim(0, min(a.t[-1], 20.0))
    place_legend(ax1, outside=True)
    return fig


def _settle(t, x, ref, band) -> float:
    out = np.abs(x - ref) > band
    if not out.any():
        return 0.0
    last = np.nonzero(out)[0][-1]
    return float(t[last + 1]) if last + 1 < t.size else math.inf


def move_rows(a: ActiveStudy) -> list[dict]:
    ts = a.t_steady
    rows = []
    for name in ("unlimited", "none", "clamping", "back-calculation"):
        r: PIDResponse = a.move[name]
        tail = r.t >= ts
        rows.append(
            {
                "scheme": "no limit" if name == "unlimited" else name,
                "over": float(np.max(r.x) - a.move_ref),
                "amp": float(np.ptp(r.x[tail]) / 2.0),
                "mean": float(np.mean(r.x[tail]) - a.move_ref),
                "sat": r.saturated_fraction,
                "imax": float(np.max(np.abs(r.integral))),
                "peak_u": float(np.max(np.abs(r.u))),
            }
        )
    return rows


def move_table(a: ActiveStudy) -> Table:
    """Overshoot, steady oscillation and saturation of the PID move per anti-windup scheme."""
    return Table(
        move_rows(a),
        [
            Column("scheme", "integrator"),
            Column("over", "overshoot (m)", 3),
            Column("amp", "X_ss (m)", 3),
            Column("mean", "mean error_ss (m)", 2),
            Column("sat", "time saturated", 3),
            Column("imax", "max|I| (m s)", 3),
            Column("peak_u", "max|u| (N)", 3),
        ],
        caption=(
            f"PID move to x_ref = {a.move_ref:g} m under the resonant disturbance, force limited to "
            f"±{a.u_max:g} N: overshoot, steady half peak-to-peak oscillation and mean error (last "
            f"{STEADY_PERIODS} periods), fraction of the window at the limit and the largest integrator state."
        ),
        name="tab-control-windup",
    )


def flutter_table(a: ActiveStudy) -> Table:
    """Poles of the negative-damping plant under velocity feedback at, below and above kd*."""
    rows = []
    for label, kd in (
        ("no feedback", 0.0),
        ("K_v = 0.9 K_v*", 0.9 * a.kd_star),
        ("K_v = K_v*", a.kd_star),
        ("K_v = 1.1 K_v*", 1.1 * a.kd_star),
    ):
        poles = np.roots([a.flutter.m, a.flutter.c + kd, a.flutter.k]).astype(complex)
        rows.append(
            {
                "case": label,
                "kd": kd,
                "re": float(np.max(poles.real)),
                "im": float(np.max(np.abs(poles.imag))),
                "verdict": "stable"
                if np.max(poles.real) < 0
                else ("marginal" if np.max(poles.real) == 0 else "unstable"),
            }
        )
    return Table(
        rows,
        [
            Column("case", "velocity gain"),
            Column("kd", "K_v (N s/m)", 4),
            Column("re", "max Re s (1/s)", 4),
            Column("im", "|Im s| (rad/s)", 4),
            Column("verdict", "loop"),
        ],
        caption=(
            f"Negative damping c = {a.flutter.c:g} N s/m (the linear galloping or stall-flutter model) under "
            "u = −K_v v: the poles have real part −(c + K_v)/(2m); the loop is stable exactly when "
            f"K_v > K_v* = −c = {a.kd_star:g} N s/m."
        ),
        name="tab-control-flutter",
    )


def active_sentences(a: ActiveStudy) -> str:
    """What the active runs found, in numbers."""
    mp = a.metrics["passive"]
    parts = []
    for name in ("PD", "LQR", "PID"):
        mt = a.metrics[name]
        parts.append(
            f"{_LABELS[name]} brings the steady RMS displacement from {mp.rms_x_ss:.3g} m to {mt.rms_x_ss:.3g} m "
            f"(÷{mp.rms_x_ss / mt.rms_x_ss:.3g}) with an RMS force of {mt.rms_u:.3g} N"
        )
    lim = a.metrics["PID"].peak_u
    sat = "never reaches" if lim < a.u_max else "reaches"
    return (
        "; ".join(parts) + f". The limited PID {sat} its ±{a.u_max:g} N limit while regulating "
        f"(largest force {lim:.3g} N); the passive oscillator needs none."
    )


def move_sentence(a: ActiveStudy) -> str:
    rows = {r["scheme"]: r for r in move_rows(a)}
    none, cl, bc = rows["none"], rows["clamping"], rows["back-calculation"]
    return (
        f"With the force limited to ±{a.u_max:g} N and no anti-windup the integrator winds up to "
        f"{none['imax']:.3g} m s, the move overshoots by {none['over']:.3g} m and the mass keeps oscillating "
        f"with {none['amp']:.3g} m in steady state (saturated {100 * none['sat']:.0f} % of the time). Clamping "
        f"cuts the overshoot to {cl['over']:.3g} m and the steady oscillation to {cl['amp']:.3g} m; "
        f"back-calculation gives {bc['over']:.3g} m and {bc['amp']:.3g} m. Without a limit the overshoot is "
        f"{rows['no limit']['over']:.3g} m."
    )


def flutter_sentence(a: ActiveStudy) -> str:
    return (
        f"With c = {a.flutter.c:g} N s/m the oscillator is self-excited, the single-mode model of galloping or stall "
        "flutter (classical flutter couples two modes, bending and torsion, and needs two degrees of freedom); "
        "velocity feedback adds K_v to the "
        f"damping, so the smallest stabilising gain is exactly K_v* = {a.kd_star:g} N s/m (an open bound: at "
        f"K_v* the poles sit on the imaginary axis at ±{a.flutter.natural_frequency:.4g} rad/s)."
    )


# ----------------------------------------------------------------------------- active: equal footing and costs

_COST_NAMES = ("PD", "LQR", "PD2", "PID")


def cost_rows(a: ActiveStudy) -> list[dict]:
    """Per design: gains, steady amplitude, RMS force against the least force, loop margins and noise."""
    rows = []
    for name in _COST_NAMES:
        lc: LoopCosts = a.costs[name]
        X = a.amplitude[name]
        floor = force_floor(a.osc, a.force, X)
        u_rms = a.metrics[name].rms_u if name in a.metrics else math.nan
        kx, ki, kv = a.gains[name]
        rows.append(
            {
                "law": _LABELS[name].replace(" (limited, clamping)", ""),
                "kx": kx,
                "ki": ki,
                "kv": kv,
                "X": X,
                "u_rms": u_rms,
                "floor": floor,
                "L": lc.loop_gain,
                "wc": lc.crossover,
                "pm": math.degrees(lc.phase_margin),
                "dm": lc.delay_margin,
                "bn": lc.noise_bandwidth,
            }
        )
    return rows


def costs_table(a: ActiveStudy) -> Table:
    """The active designs on equal footing: amplitude, force against its floor, margins and noise."""
    return Table(
        cost_rows(a),
        [
            Column("law", "law"),
            Column("kx", "K_p (N/m)", 4),
            Column("ki", "K_i (N/(m s))", 4),
            Column("kv", "K_d (N s/m)", 4),
            Column("X", "X_ss (m)", 3),
            Column("u_rms", "u_rms (N)", 3),
            Column("floor", "least u_rms for X_ss (N)", 3),
            Column("L", "|L(iω)|", 3),
            Column("wc", "ω_c (rad/s)", 3),
            Column("pm", "phase margin (°)", 3),
            Column("dm", "delay margin (s)", 3),
            Column("bn", "B_n (rad/s)", 3),
        ],
        caption=(
            f"The active laws at ω = {a.force.omega:g} rad/s on equal footing. X_ss: steady amplitude of the unlimited "
            "loop; u_rms: steady RMS force of the run; the least RMS force any controller needs to hold X_ss, "
            "(F0 − |k − mω² + icω| X_ss)/√2; |L(iω)|: loop gain at the forcing; ω_c: the gain crossover that sets "
            "the delay margin (the loop's bandwidth); delay margin: the smallest time delay in the loop that "
            "destabilises it; B_n = ∫|T(iω)|² dω over ω > 0: white position-sensor noise of two-sided density S_n "
            "moves the mass with variance 2 S_n B_n, and the force it causes grows as K_d ω above crossover."
        ),
        name="tab-control-costs",
    )


def _delay_text(x: float) -> str:
    """A delay margin in words; none when the loop gain never reaches 1 (no crossover: no delay destabilises)."""
    return f"{x:.3g} s" if math.isfinite(x) else "any delay (its loop gain never reaches 1)"


def _crossing_text(x: float) -> str:
    return f"{x:.3g} rad/s" if math.isfinite(x) else "absent (loop gain below 1 at every frequency)"


def comparison_sentence(a: ActiveStudy) -> str:
    """The PID against the PD with its own K_p and K_d, how its gains were chosen, and what stiffness costs."""
    X = a.amplitude
    kp, ki, kd = a.pid_gains
    pp = a.pid_poles
    if math.isfinite(pp.pair_omega):
        radii_equal = abs(abs(pp.real_pole) / pp.pair_omega - 1.0) < 1e-3
        poles = (
            f"The PID's gains place its three closed-loop poles at s = {pp.real_pole:.4g} 1/s and a pair with natural "
            f"frequency {pp.pair_omega:.4g} rad/s and damping ratio {pp.pair_zeta:.3g}"
            + (
                f": a pole placement with every pole at {pp.pair_omega:.4g} rad/s from the origin"
                if radii_equal
                else ""
            )
            + " (m s³ + (c + K_d) s² + (k + K_p) s + K_i = 0). "
        )
    else:
        poles = "The PID's gains give three real closed-loop poles. "
    if X["PD2"] < X["PID"]:
        integ = (
            f"A PD with the PID's K_p = {kp:.4g} N/m and K_d = {kd:.4g} N s/m and no integrator holds "
            f"X = {X['PD2']:.3g} m against the PID's {X['PID']:.3g} m: at this frequency the integral term costs "
            "amplitude, it does not buy it"
        )
    else:
        integ = (
            f"A PD with the PID's K_p = {kp:.4g} N/m and K_d = {kd:.4g} N s/m and no integrator holds "
            f"X = {X['PD2']:.3g} m against the PID's {X['PID']:.3g} m: here the integral term helps"
        )
    if X["PD2"] < X["PD"]:
        stiff = f"k + K_p = {a.osc.k + kp:.4g} N/m against {a.pd.k:.4g} N/m"
        integ += (
            f". The PID's advantage over the PD (X = {X['PD']:.3g} m) is its stiffness, {stiff}, "
            "not its integral action"
            if X["PD2"] < X["PID"]
            else f". Most of the PID's advantage over the PD (X = {X['PD']:.3g} m) is its stiffness, {stiff}; "
            "the integrator adds the rest"
        )
    c = a.costs
    delay, crossing = _delay_text, _crossing_text
    cost = (
        ". Stiffness is paid for in robustness and noise: the PID tolerates a loop delay of "
        f"{delay(c['PID'].delay_margin)} before it goes unstable, the PD {delay(c['PD'].delay_margin)} and the LQR "
        f"{delay(c['LQR'].delay_margin)}; "
        f"its crossover is {crossing(c['PID'].crossover)} against {crossing(c['PD'].crossover)}, and sensor noise "
        f"reaches the mass through a noise bandwidth of {c['PID'].noise_bandwidth:.3g} rad/s against "
        f"{c['PD'].noise_bandwidth:.3g} rad/s, with {c['PID'].hf_noise_gain / max(c['PD'].hf_noise_gain, 1e-300):.3g} "
        "times the PD's high-frequency noise gain K_d."
    )
    rows = {r["law"]: r for r in cost_rows(a)}
    ratio = max(r["u_rms"] / r["floor"] for r in rows.values() if math.isfinite(r["u_rms"]) and r["floor"] > 0)
    force = (
        f" Each design uses at most {ratio:.3g} times the least RMS force that can hold its "
        "amplitude ({numref}`tab-control-costs`)."
    )
    return poles + integ + cost + force


def lqr_sentence(a: ActiveStudy) -> str:
    """The LQR weights read by Bryson's rule, and why the force tends to F0/sqrt(2)."""
    d = a.lqr
    xm = 1.0 / math.sqrt(d.q_x) if d.q_x > 0 else math.inf
    um = 1.0 / math.sqrt(d.r)
    vpart = (
        "q_v = 0 leaves the velocity unweighted"
        if d.q_v == 0
        else f"q_v = {d.q_v:g} s²/m² a velocity of {1.0 / math.sqrt(d.q_v):.3g} m/s"
    )
    xpart = f"a displacement of {xm:.3g} m" if math.isfinite(xm) else "no displacement weight"
    tr = a.tradeoff
    floor = force_floor(a.osc, a.force, tr["amplitude"])
    excess = float(np.max(tr["force_rms"] / np.maximum(floor, 1e-300)))
    F_inf = a.force.F0 / math.sqrt(2.0)
    pd_gains = (a.pd.k - a.osc.k, a.pd.c - a.osc.c)
    gap = max(abs(d.K[i] - pd_gains[i]) / max(abs(pd_gains[i]), 1e-300) for i in (0, 1))
    return (
        f"Read by Bryson's rule (each weight is one over the square of the largest acceptable value) the weights "
        f"q_x = {d.q_x:g} 1/m² and r = {d.r:g} 1/N² accept {xpart} and a force of {um:.3g} N; {vpart}. "
        f"With these weights the LQR gains (K_x = {d.K[0]:.4g} N/m, K_v = {d.K[1]:.4g} N s/m) differ from the "
        f"PD's ({a.pd.k - a.osc.k:.4g} N/m, {a.pd.c - a.osc.c:.4g} N s/m) by at most {100 * gap:.2g} %. "
        f"As r falls the RMS force tends to F0/√2 = {F_inf:.3g} N. That is not a trade-off the weights could "
        "improve: to hold the mass still the force must cancel the disturbance, and any controller holding an "
        "amplitude X needs at least (F0 − |k − mω² + icω| X)/√2 (dotted in the figure). "
        f"Along the whole curve the LQR designs use at most {excess:.3g} times that least force."
    )


def hold_sentence(a: ActiveStudy) -> str:
    """Whether the force limit can hold the PID's set point, and the feasible case."""
    h = a.hold
    k, F0 = a.osc.k, a.force.F0
    fr = []
    for name in ("none", "clamping", "back-calculation"):
        r = a.move[name]
        tl = r.t >= a.t_steady
        fr.append(100.0 * float(np.mean(np.abs(r.u_demand[tl]) >= r.u_max)))
    lo, hi = min(fr), max(fr)
    if h["needed"] > a.u_max:
        head = (
            f"The move to x_ref = {a.move_ref:g} m cannot succeed with ±{a.u_max:g} N: holding the mass there against "
            f"the disturbance needs k x_ref + F0 = {k * abs(a.move_ref):.3g} + {F0:.3g} = {h['needed']:.3g} N of peak "
            f"force, more than the limit, so no integrator treatment can make the limited runs above settle: they "
            f"spend {lo:.3g} to {hi:.3g} % of the steady state at the limit."
        )
    else:
        head = (
            f"Holding x_ref = {a.move_ref:g} m against the disturbance needs k x_ref + F0 = {h['needed']:.3g} N, "
            f"within the ±{a.u_max:g} N limit."
        )
    r = h["run"]
    if r is None:
        return head + f" No set point can be held with ±{a.u_max:g} N: the disturbance alone needs F0 = {F0:.3g} N."
    tail = r.t >= a.t_steady
    sat = float(np.mean(np.abs(r.u_demand[tail]) > r.u_max))
    mean_err = float(np.mean(r.x[tail]) - h["x_ok"])
    amp = float(np.ptp(r.x[tail]) / 2.0)
    return head + (
        f" The largest set point the limit can hold is (u_max − F0)/k = {h['x_max']:.3g} m. A move to "
        f"{h['x_ok']:.3g} m (80 % of it) with clamping is saturated {100 * sat:.3g} % of the steady state, "
        f"settles with a mean error of {bound(mean_err, 1e-4)} m and oscillates with {amp:.3g} m, the unlimited "
        f"loop's {a.amplitude['PID']:.3g} m."
    )


# ----------------------------------------------------------------------------- semi-active


@dataclass(frozen=True)
class SemiActiveStudy:
    """Semi-active suspension: sweeps across frequency and time runs at resonance."""

    osc: Oscillator  # m, passive c, k
    Y: float  # base amplitude, m
    omega: float  # base frequency of the time runs, rad/s
    c_sky: float  # skyhook gain, N s/m
    c_min: float  # device damping bounds, N s/m
    c_max: float
    damper: object  # scaled MR damper
    mr_scale: tuple  # (length, force) scale factors
    ratios: np.ndarray  # frequency ratios of the sweep, 1
    closed: dict  # name -> transmissibility (closed form)
    sweeps: dict  # law -> SemiActiveSweep
    t: np.ndarray  # times of the runs, s
    runs: dict  # name -> SemiActiveResponse
    metrics: dict  # name -> Metrics
    t_steady: float  # s
    refine: dict  # RK4 steps per period -> on-off skyhook peak transmissibility at omega_n, 1
    power: object  # SkyhookPower at omega (closed form)
    power_run: dict  # the same four mean powers measured on the skyhook run's steady tail, W


_SA_LABELS = {
    "soft": "passive, c + c_min",
    "firm": "passive, c + c_max",
    "skyhook": "ideal skyhook (active)",
    "on-off": "on-off skyhook",
    "clipped": "clipped skyhook",
    "mr": "MR damper, on-off",
}


def semi_active_study(
    m: float,
    c: float,
    k: float,
    F0: float,
    omega: float,
    t_end: float,
    n_points: int,
    *,
    c_sky: float,
    c_min: float,
    c_max: float,
    f_mr: float,
    n_sweep: int,
) -> SemiActiveStudy:
    """Base excitation ``Y = F0 / k`` (so that ``k Y = F0``): sweeps and runs of every law.

    The MR damper is :data:`SPENCER_1997` scaled so that its stroke at the test amplitude
    (1.5 cm) maps onto ``Y`` and its full-voltage yield force onto ``f_mr`` (N).

    Examples
    --------
    >>> s = semi_active_study(1.0, 0.5, 20.0, 5.0, 4.47, 5.0, 101, c_sky=8.0, c_min=0.5, c_max=15.0,
    ...                       f_mr=10.0, n_sweep=10)
    >>> round(s.Y, 3), sorted(s.sweeps)
    (0.25, ['clipped', 'mr', 'on-off'])
    """
    osc = Oscillator(m, c, k)
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    c_min = check_real("c_sa_min", c_min, low=0.0, unit="N s/m")
    c_max = check_real("c_sa_max", c_max, low=c_min, unit="N s/m")
    f_mr = check_real("f_mr", f_mr, low=0.0, low_open=True, unit="N")
    n_sweep = check_int("n_sweep", n_sweep, low=10, high=400)  # the runner's range, as in chapter 9
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    Y = F0 / k
    wn = osc.natural_frequency
    ratios = np.unique(np.concatenate([np.geomspace(0.3, 4.0, n_sweep), [1.0, math.sqrt(2.0)]]))
    w = ratios * wn
    closed = {
        "soft": passive_transmissibility(Oscillator(m, c + c_min, k), w),
        "firm": passive_transmissibility(Oscillator(m, c + c_max, k), w),
        "skyhook": skyhook_transmissibility(osc, c_sky, w),
        "envelope": np.where(ratios < math.sqrt(2.0), 1.0, 1.0 / np.abs(ratios**2 - 1.0 + (ratios == 1.0))),
    }
    scale = (Y / SPENCER_1997_STROKE, f_mr / SPENCER_1997.yield_force)
    damper = SPENCER_1997.scaled(*scale)
    kw = {"c_sky": c_sky, "c_min": c_min, "c_max": c_max}
    sweeps = {law: semi_active_sweep(osc, law, w, Y, damper=damper, **kw) for law in ("on-off", "clipped", "mr")}
    runs = {}
    for name, law, cmin, cmax in (
        ("soft", "passive", c_min, c_min),
        ("firm", "passive", c_max, c_max),
        ("skyhook", "skyhook", c_min, c_max),
        ("on-off", "on-off", c_min, c_max),
        ("clipped", "clipped", c_min, c_max),
        ("mr", "mr", c_min, c_max),
    ):
        runs[name] = semi_active_response(
            osc, law, omega, Y, c_sky=c_sky, c_min=cmin, c_max=cmax, damper=damper, t_end=t_end, n_points=n_points
        )
    t = runs["soft"].t
    ts = _t_steady(t_end, omega)
    metrics = {name: response_metrics(r.t, r.x, r.f, r.v - r.v_base, ts) for name, r in runs.items()}
    refine = {
        spp: float(semi_active_sweep(osc, "on-off", np.array([wn]), Y, steps_per_period=spp, **kw).peak[0])
        for spp in REFINE_STEPS
    }
    sky = runs["skyhook"]
    tail = sky.t >= ts
    tt = sky.t[tail]
    p_rel = (sky.f * (sky.v - sky.v_base))[tail]
    span = tt[-1] - tt[0]

    def mean(y):
        return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(tt))) / span

    power_run = {
        "removed": mean(c_sky * sky.v[tail] ** 2),
        "net": mean(p_rel),
        "supplied": mean(np.maximum(p_rel, 0.0)),
        "gross": mean(np.abs(p_rel)),
    }
    return SemiActiveStudy(
        osc=osc,
        Y=Y,
        omega=omega,
        c_sky=c_sky,
        c_min=c_min,
        c_max=c_max,
        damper=damper,
        mr_scale=scale,
        ratios=ratios,
        closed=closed,
        sweeps=sweeps,
        t=t,
        runs=runs,
        metrics=metrics,
        t_steady=ts,
        refine=refine,
        power=skyhook_power(osc, c_sky, Y, omega),
        power_run=power_run,
    )


#: RK4 steps per period of the on-off skyhook refinement at omega_n (the sweeps use 1000).
REFINE_STEPS = (1000, 4000, 16000, 64000)


def transmissibility_figure(s: SemiActiveStudy):
    """Transmissibility |X/Y| against frequency ratio: passive bounds, ideal and clipped skyhook, MR."""
    fig, ax = figure(height=3.8)
    r = s.ratios
    ax.loglog(r, s.closed["soft"], color="0.55", ls="--", lw=1.0, label=_SA_LABELS["soft"])
    ax.loglog(r, s.closed["firm"], color="0.3", ls="-.", lw=1.0, label=_SA_LABELS["firm"])
    ax.loglog(r, s.closed["envelope"], color="k", ls=":", lw=1.0, label="best passive c (bound)")
    ax.loglog(r, s.closed["skyhook"], color="C0", label=_SA_LABELS["skyhook"])
    ax.loglog(r, s.sweeps["on-off"].peak, color="C4", label=_SA_LABELS["on-off"])
    ax.loglog(r, s.sweeps["clipped"].peak, color="C1", lw=1.8, label=_SA_LABELS["clipped"])
    ax.loglog(r, s.sweeps["mr"].peak, color="C2", label=_SA_LABELS["mr"])
    ax.axvline(math.sqrt(2.0), color="0.6", lw=0.8)
    from matplotlib.ticker import FixedLocator, NullLocator, ScalarFormatter

    ax.xaxis.set_major_locator(FixedLocator([0.3, 0.5, 0.7, 1.0, 1.414, 2.0, 3.0, 4.0]))
    ax.xaxis.set_minor_locator(NullLocator())
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.set_xlabel(r"frequency ratio $\omega/\omega_n$")
    ax.set_ylabel(r"transmissibility max$|x|/Y$")
    place_legend(ax, outside=True)
    return fig


def semi_active_findings(s: SemiActiveStudy) -> dict:
    """Band where clipped skyhook beats every passive damper, and its isolation loss above sqrt(2)."""
    r = s.ratios
    cl = s.sweeps["clipped"].peak
    beats = cl < s.closed["envelope"]
    near = np.abs(np.log(r)) <= np.log(np.sqrt(2.0))  # the band sqrt(1/2) .. sqrt(2)
    hi = r >= math.sqrt(2.0)
    i1 = int(np.argmin(np.abs(r - 1.0)))
    idx = np.nonzero(beats)[0]
    band = (float(r[idx.min()]), float(r[idx.max()])) if idx.size else (math.nan, math.nan)
    loss_soft = float(np.max(cl[hi] / s.closed["soft"][hi]))
    gain_firm = float(np.min(s.closed["firm"][hi] / cl[hi]))
    return {
        "band": band,
        "all_near": bool(np.all(beats[near])),
        "t_res": float(cl[i1]),
        "t_res_soft": float(s.closed["soft"][i1]),
        "t_res_firm": float(s.closed["firm"][i1]),
        "t_res_sky": float(s.closed["skyhook"][i1]),
        "t_res_mr": float(s.sweeps["mr"].peak[i1]),
        "t_res_onoff": float(s.sweeps["on-off"].peak[i1]),
        "loss_soft": loss_soft,
        "gain_firm": gain_firm,
        "mr_loss_soft": float(np.max(s.sweeps["mr"].peak[hi] / s.closed["soft"][hi])),
        "switches": float(np.median(s.sweeps["on-off"].switches)),
        "force_res": float(s.sweeps["clipped"].force_rms[i1]),
        "force_res_firm": float(
            s.closed["firm"][i1] * 0 + _passive_force_rms(s.osc, s.c_max, s.Y, s.ratios[i1] * s.osc.natural_frequency)
        ),
    }


def _passive_force_rms(osc: Oscillator, c_d: float, Y: float, w: float) -> float:
    """RMS force of a passive device damper c_d in steady state under base motion, N."""
    h = (osc.k + 1j * (osc.c + c_d) * w) / (osc.k - osc.m * w * w + 1j * (osc.c + c_d) * w)
    return c_d * w * Y * abs(h - 1.0) / math.sqrt(2.0)


def semi_active_sentence(s: SemiActiveStudy) -> str:
    f = semi_active_findings(s)
    lo, hi = f["band"]
    near = "over the whole band" if f["all_near"] else "over part of the band"
    keeps = " (it loses no isolation)" if f["loss_soft"] <= 1.0 else ""
    return (
        f"At resonance the clipped skyhook transmits {f['t_res']:.3g} of the base motion, where every passive "
        f"damper transmits more than 1 (c + c_min: {f['t_res_soft']:.3g}, c + c_max: {f['t_res_firm']:.3g}) and the "
        f"ideal skyhook {f['t_res_sky']:.3g}. It beats every passive damper from ω/ω_n = {lo:.3g} to {hi:.3g} on "
        f"the sweep grid ({near} 1/√2 to √2). Above √2 ω_n it transmits at most {f['loss_soft']:.3g} times what "
        f"the soft passive damper transmits{keeps}, and {f['gain_firm']:.3g} times less than the firm one or better. "
        f"The cost: the damper switches {f['switches']:.0f} times per period and carries an RMS force of "
        f"{f['force_res']:.3g} N at resonance (the firm passive damper: {f['force_res_firm']:.3g} N); it supplies "
        f"no energy. The on-off law reaches {f['t_res_onoff']:.3g} at resonance, the MR damper {f['t_res_mr']:.3g}, "
        f"but the MR damper's zero-field yield force costs isolation above √2 ω_n (up to {f['mr_loss_soft']:.3g} "
        f"times the soft passive damper)."
    )


def mr_sentence(s: SemiActiveStudy) -> str:
    L, F = s.mr_scale
    d = s.damper
    return (
        f"The MR damper is the modified Bouc-Wen model with the parameters Spencer, Dyke, Sain and Carlson (1997) "
        f"identified for their prototype (about 3000 N capacity, tested at ±1.5 cm). Scaled here with lengths "
        f"×{L:.4g} (so the test stroke maps onto Y = {s.Y:.3g} m) and forces ×{F:.4g} (so the full-voltage yield "
        f"force α z_max = {SPENCER_1997.yield_force:.4g} N maps onto {d.yield_force:.3g} N); damping and stiffness "
        f"coefficients scale by the force factor over the length factor, γ and β by one over the length factor "
        f"squared, A, n, η and the voltage are unchanged; time is not scaled. At 0 V it still yields at "
        f"{d.alpha_a * d.z_max:.3g} N."
    )


def semi_active_metrics_table(s: SemiActiveStudy) -> Table:
    rows = _metric_rows(s.metrics, _SA_LABELS, "soft")
    return Table(
        rows,
        [c if c.key != "energy" else Column("energy", "E (J)", 3) for c in _METRIC_COLUMNS],
        caption=(
            f"Semi-active suspension at ω = {s.omega:g} rad/s, base amplitude Y = F0/k = {s.Y:.3g} m, from rest over "
            f"{s.t[-1]:g} s: absolute displacement of the mass, device force on the mass and the energy "
            "∫|f v_rel| dt it exchanges with the mass and the base, v_rel = v − v_b (all of it dissipated by the "
            "passive and semi-active dampers; for the ideal skyhook's actuator the gross exchange, split into what it "
            "supplies and absorbs in {numref}`tab-control-skyhook-energy`); steady state is the last "
            f"{STEADY_PERIODS} periods; reduction against the soft passive damper."
        ),
        name="tab-control-semiactive",
    )


def skyhook_energy_table(s: SemiActiveStudy) -> Table:
    """What the ideal skyhook removes and what an actuator between body and base must exchange, W."""
    p, r = s.power, s.power_run
    rows = [
        {"what": "removed from the mass by the skyhook force, c_sky v²", "closed": p.removed, "run": r["removed"]},
        {"what": "net power of the actuator, f v_rel", "closed": p.net, "run": r["net"]},
        {"what": "power the actuator supplies (positive part of f v_rel)", "closed": p.supplied, "run": r["supplied"]},
        {"what": "gross power exchanged, |f v_rel|", "closed": p.gross, "run": r["gross"]},
    ]
    return Table(
        rows,
        [
            Column("what", "mean power"),
            Column("closed", "closed form (W)", 4),
            Column("run", "run, steady tail (W)", 4),
        ],
        caption=(
            f"The ideal skyhook (c_sky = {s.c_sky:g} N s/m) at ω = {s.omega:g} rad/s, base amplitude Y = {s.Y:.3g} m, "
            "realised by an actuator between the mass and the base (v_rel = v − v_b): mean powers in steady state, "
            f"in closed form and measured on the RK4 run over its last {STEADY_PERIODS} periods. A negative net power "
            "means the actuator absorbs more than it supplies."
        ),
        name="tab-control-skyhook-energy",
    )


def skyhook_energy_sentence(s: SemiActiveStudy) -> str:
    p = s.power
    net = (
        f"absorbs {-p.net:.3g} W more than it supplies" if p.net < 0 else f"supplies {p.net:.3g} W more than it absorbs"
    )
    return (
        f"The skyhook force removes c_sky⟨v²⟩ = {p.removed:.3g} W from the mass. An actuator that produces it between "
        f"the body and the base does the work ∫f v_rel dt: on average it {net}, but it must supply {p.supplied:.3g} W "
        f"during the phases where f v_rel > 0 and exchanges {p.gross:.3g} W in all. A semi-active damper cannot "
        "supply those phases; that is what the clipped and on-off laws give up."
    )


def refinement_rows(s: SemiActiveStudy) -> list[dict]:
    rows, prev = [], None
    for spp, val in s.refine.items():
        rows.append({"spp": spp, "dt": 2.0 * math.pi / s.osc.natural_frequency / spp, "T": val,
                     "d": Missing("first row") if prev is None else val - prev})  # fmt: skip
        prev = val
    return rows


def refinement_table(s: SemiActiveStudy) -> Table:
    """On-off skyhook at omega_n under step refinement: the switching is what limits RK4's order."""
    return Table(
        refinement_rows(s),
        [
            Column("spp", "RK4 steps per period"),
            Column("dt", "Δt (s)", 3),
            Column("T", "max|x|/Y at ω_n", 5),
            Column("d", "change from the row above", 2),
        ],
        caption=(
            "On-off skyhook transmissibility at ω = ω_n under step refinement. The law switches the damping "
            "discontinuously, so fixed-step RK4 loses its fourth order at each switch; the table shows how far "
            "the sweeps' value (1000 steps per period) is from the converged one."
        ),
        name="tab-control-onoff-refinement",
    )


def semi_active_checks_table(s: SemiActiveStudy) -> Table:
    """The semi-active runs against closed forms and against themselves under refinement."""
    ts = s.t_steady
    rows = []
    for name, exact in (
        ("soft", float(passive_transmissibility(Oscillator(s.osc.m, s.osc.c + s.c_min, s.osc.k), s.omega))),
        ("skyhook", float(skyhook_transmissibility(s.osc, s.c_sky, s.omega))),
    ):
        r = s.runs[name]
        tail = r.t >= ts
        val = float(np.max(np.abs(r.x[tail]))) / s.Y
        rows.append({"check": f"{_SA_LABELS[name]}: RK4 run's steady max|x|/Y against the closed form, relative",
                     "value": bound(abs(val / exact - 1.0), 1e-4)})  # fmt: skip
    p, pr = s.power, s.power_run
    rows.append({"check": "ideal skyhook: mean powers of the run against the closed form, largest relative difference",
                 "value": bound(max(abs(pr[f] - getattr(p, f)) / max(abs(p.gross), 1e-300)
                                    for f in ("removed", "net", "supplied", "gross")), 1e-3)})  # fmt: skip
    vals = list(s.refine.values())
    rows.append({"check": "on-off skyhook at ω_n: last refinement step (16000 to 64000 steps per period), absolute",
                 "value": bound(abs(vals[-1] - vals[-2]), 1e-4)})  # fmt: skip
    worst = max(float(np.max(s.runs[n].f * (s.runs[n].v - s.runs[n].v_base))) for n in ("on-off", "clipped"))
    rows.append({"check": "on-off and clipped dampers: largest instantaneous power f v_rel they deliver (W)",
                 "value": "≤ 0" if worst <= 0.0 else bound(worst, 1e-12)})  # fmt: skip
    return Table(
        rows,
        [Column("check", "check"), Column("value", "bound")],
        caption="Self-checks of the semi-active runs (printed as bounds against stated tolerances).",
        name="tab-control-semiactive-checks",
    )


def passivity_sentence(s: SemiActiveStudy) -> str:
    worst = max(float(np.max(s.runs[n].f * (s.runs[n].v - s.runs[n].v_base))) for n in ("on-off", "clipped"))
    mr = s.metrics["mr"]
    if worst <= 0.0:
        head = (
            "The on-off and clipped dampers never deliver power: their force opposes the relative velocity at every "
            "instant of the runs (f v_rel ≤ 0), as a damper's must."
        )
    else:
        head = f"The on-off and clipped runs deliver at most {worst:.3g} W at some instant."
    return head + (
        " A device that can only dissipate cannot add energy to the suspension, so no semi-active law, however badly "
        "tuned or fed by a faulty sensor, can destabilise it: the worst it can do is damp badly. The MR damper has no "
        f"power source either (its coil only changes how hard it resists; {mr.energy:.3g} J exchanged over the "
        "window). The ideal skyhook needs an actuator, which supplies energy, so its loop can be destabilised like "
        "any active loop."
    )


def mr_figure(s: SemiActiveStudy):
    """MR damper force against relative velocity at resonance (steady state): the hysteresis loop."""
    fig, ax = figure(height=3.2)
    r = s.runs["mr"]
    tail = r.t >= s.t_steady
    vr = (r.v - r.v_base)[tail]
    ax.plot(vr, -r.f[tail], color="C2", lw=1.0, label="MR damper, on-off voltage")
    rc = s.runs["clipped"]
    ax.plot((rc.v - rc.v_base)[tail], -rc.f[tail], color="C1", lw=1.0, label="clipped skyhook")
    ax.set_xlabel(r"relative velocity $v - v_b$ (m/s)")
    ax.set_ylabel(r"damper force $-f$ (N)")
    place_legend(ax, outside=True)
    return fig


# ----------------------------------------------------------------------------- input shaping


@dataclass(frozen=True)
class ShapingStudy:
    """Point-to-point moves with and without input shaping, and the sensitivity curves."""

    model: Oscillator  # the oscillator the shapers are designed on
    actual: Oscillator  # the real one (natural frequency off by freq_error)
    move: float  # distance, m
    freq_error: float  # relative natural-frequency error, 1
    shapers: dict  # "ZV"/"ZVD" -> Shaper
    t: np.ndarray  # times, s
    x: dict  # "none"/"ZV"/"ZVD" -> displacement, m
    residual: dict  # name -> residual vibration ratio (closed form), 1
    residual_sim: dict  # name -> ratio measured on the simulated move, 1
    amplitude: dict  # name -> ringing amplitude just after the move, m
    ratios: np.ndarray  # actual / model natural frequency, 1
    sensitivity: dict  # "ZV"/"ZVD" -> residual vibration ratio along ratios, 1
    design_residual: float  # max residual ratio at the design point, 1
    bands: dict  # "ZV"/"ZVD" -> (low, high) ratio where V <= 5 %, exact roots, 1


def shaping_study(
    m: float,
    c: float,
    k: float,
    *,
    move: float,
    freq_error: float,
    t_end: float = 10.0,
    n_points: int = 2001,
    n_ratio: int = 201,
) -> ShapingStudy:
    """ZV and ZVD on the model ``(m, c, k)``; moves of ``move`` m on the real oscillator whose
    natural frequency is ``(1 + freq_error)`` times the model's (k scaled by its square)."""
    model = Oscillator(m, c, k)
    freq_error = check_real("freq_error", freq_error, low=-0.9, high=2.0)
    actual = Oscillator(m, c, k * (1.0 + freq_error) ** 2)
    shapers = {"ZV": zv_shaper(model), "ZVD": zvd_shaper(model)}
    xs, res, sim, amp = {}, {}, {}, {}
    t0, x0, v0, _ = shaped_move(actual, None, move, t_end, n_points)
    a0 = residual_amplitude(actual, t0, x0, v0, move)
    for name, sh in (("none", None), *shapers.items()):
        t, x, v, _ = shaped_move(actual, sh, move, t_end, n_points)
        xs[name] = x
        res[name] = shaper_residual(sh, actual)
        tn = 0.0 if sh is None else sh.duration
        after = t > tn + 1e-12
        ring = residual_amplitude(actual, t, x, v, move)
        ratio = np.median(ring[after] / a0[after]) * math.exp(-actual.decay_rate * tn)  # Singer-Seering V
        sim[name] = float(ratio) if move != 0 else 0.0
        amp[name] = float(ring[after][0] * math.exp(actual.decay_rate * (t[after][0] - tn)))
    ratios = np.linspace(0.5, 1.5, n_ratio)
    sens = {
        name: np.array([shaper_residual(sh, Oscillator(m, c, k * q * q)) for q in ratios])
        for name, sh in shapers.items()
    }
    design = max(shaper_residual(sh, model) for sh in shapers.values())
    bands = {name: insensitivity_band(sh, model, 0.05) for name, sh in shapers.items()}
    return ShapingStudy(
        model=model,
        actual=actual,
        move=move,
        freq_error=freq_error,
        shapers=shapers,
        t=t0,
        x=xs,
        residual=res,
        residual_sim=sim,
        amplitude=amp,
        ratios=ratios,
        sensitivity=sens,
        design_residual=design,
        bands=bands,
    )


def shaping_figure(s: ShapingStudy):
    """The move on the real oscillator (left) and the sensitivity curves (right)."""
    fig, (ax1, ax2) = figure(1, 2, height=3.4)
    colors = {"none": "0.45", "ZV": "C0", "ZVD": "C1"}
    for name, x in s.x.items():
        ax1.plot(s.t, x * 1e3, color=colors[name], label="unshaped step" if name == "none" else name)
    ax1.axhline(s.move * 1e3, color="k", lw=0.8, ls=":")
    ax1.set_xlabel(r"$t$ (s)")
    ax1.set_ylabel(r"$x$ (mm)")
    ax1.set_title(rf"model error {100 * s.freq_error:+.0f} % in $\omega_n$")
    place_legend(ax1)
    for name, v in s.sensitivity.items():
        ax2.plot(s.ratios, 100 * v, color=colors[name], label=name)
    q = 1.0 + s.freq_error
    for name in s.sensitivity:
        ax2.plot([q], [100 * s.residual[name]], "o", color=colors[name], ms=4)
    ax2.axhline(5.0, color="0.5", lw=0.8, ls="--", label="5 %")
    ax2.set_xlabel(r"real $\omega_n$ / model $\omega_n$")
    ax2.set_ylabel("residual vibration (%)")
    place_legend(ax2)
    return fig


def shaping_table(s: ShapingStudy) -> Table:
    rows = []
    for name in ("none", "ZV", "ZVD"):
        sh = s.shapers.get(name)
        lo, hi = _tolerable(s, name) if sh is not None else (math.nan, math.nan)
        rows.append(
            {
                "shaper": "unshaped step" if name == "none" else name,
                "delay": 0.0 if sh is None else sh.duration,
                "V": s.residual[name],
                "Vsim": s.residual_sim[name],
                "amp": s.amplitude[name],
                "lo": lo,
                "hi": hi,
            }
        )
    return Table(
        rows,
        [
            Column("shaper", "command"),
            Column("delay", "added delay (s)", 4),
            Column("V", "V (closed form)", 3),
            Column("Vsim", "V (simulated)", 3),
            Column("amp", "ringing after the move (m)", 3),
            Column("lo", "V ≤ 5 % from ω/ω_model", 4),
            Column("hi", "to", 4),
        ],
        caption=(
            f"Move of {s.move:g} m on an oscillator whose natural frequency is {100 * s.freq_error:+.0f} % off the "
            "model the shapers were designed on: delay added to the move, residual vibration V as a fraction of the "
            "unshaped step's (closed form and measured on the exact response), ringing amplitude just after the "
            "last impulse, and the frequency band where V stays below 5 % (edges are roots of V = 5 %, solved to "
            "1e-12 in the frequency ratio)."
        ),
        name="tab-control-shaping",
    )


def _tolerable(s: ShapingStudy, name: str) -> tuple[float, float]:
    """Edges of the band where V <= 5 %: roots of V(q) = 0.05 (Brent), not grid points."""
    return s.bands[name]


def shaping_sentence(s: ShapingStudy) -> str:
    zv, zvd = _tolerable(s, "ZV"), _tolerable(s, "ZVD")
    return (
        f"On the model itself both shapers leave no residual vibration (below {max(s.design_residual, 1e-16):.0e} "
        f"of the unshaped ringing). With the natural frequency {100 * s.freq_error:+.0f} % off, the unshaped move "
        f"rings with {s.amplitude['none']:.3g} m, ZV leaves {100 * s.residual['ZV']:.3g} % of that and ZVD "
        f"{100 * s.residual['ZVD']:.3g} %. ZV keeps the residual below 5 % for a real natural frequency from "
        f"{zv[0]:.4f} to {zv[1]:.4f} times the model's, ZVD from {zvd[0]:.4f} to {zvd[1]:.4f} (roots of V = 5 %), "
        "at the price of "
        f"{s.shapers['ZVD'].duration:.3g} s of added delay instead of {s.shapers['ZV'].duration:.3g} s."
    )


# ----------------------------------------------------------------------------- summary


def summary(a: ActiveStudy, s: SemiActiveStudy, sh: ShapingStudy) -> str:
    """The closing note: each design against the best of its class and the optimum where one exists."""
    X, c = a.amplitude, a.costs
    rows = {r["law"]: r for r in cost_rows(a)}
    excess = max(r["u_rms"] / r["floor"] for r in rows.values() if math.isfinite(r["u_rms"]) and r["floor"] > 0)
    lines = [f"Measured at the paper's resonance (steady state = last {STEADY_PERIODS} forcing periods):", ""]
    lines.append(
        f"- **Active laws** cut the steady amplitude from {X['passive']:.3g} m (passive) to {X['PD']:.3g} m (PD), "
        f"{X['LQR']:.3g} m (LQR) and {X['PID']:.3g} m (PID). On equal footing, a PD with the PID's own K_p and K_d "
        f"holds {X['PD2']:.3g} m: "
        + ("the integrator costs amplitude here" if X["PD2"] < X["PID"] else "the integrator helps here")
        + ("; the PID's advantage over the PD is its stiffness." if X["PD2"] < X["PD"] else ".")
        + f" Every design uses at most {excess:.3g} times the least RMS force that can hold its amplitude "
        f"(F0/√2 = {a.force.F0 / math.sqrt(2.0):.3g} N as the amplitude goes to zero)."
    )  # fmt: skip
    lines.append(
        f"- **What stiffness costs**: delay margin {_delay_text(c['PID'].delay_margin)} (PID) against "
        f"{_delay_text(c['PD'].delay_margin)} (PD) and {_delay_text(c['LQR'].delay_margin)} (LQR); noise bandwidth "
        f"{c['PID'].noise_bandwidth:.3g} rad/s against "
        f"{c['PD'].noise_bandwidth:.3g} rad/s."
    )
    h = a.hold
    rows_m = {r["scheme"]: r for r in move_rows(a)}
    feas = (
        f"it needs k x_ref + F0 = {h['needed']:.3g} N > {a.u_max:g} N, so no integrator treatment can settle it"
        if h["needed"] > a.u_max
        else f"it needs k x_ref + F0 = {h['needed']:.3g} N, within the limit"
    )
    lines.append(
        f"- **PID move to {a.move_ref:g} m with a ±{a.u_max:g} N limit**: {feas}; clamping still cuts the overshoot "
        f"from {rows_m['none']['over']:.3g} m to {rows_m['clamping']['over']:.3g} m. "
        + (
            f"The largest set point the limit can hold is {h['x_max']:.3g} m."
            if math.isfinite(h["x_max"]) and h["x_max"] > 0.0
            else f"No set point can be held: the disturbance alone needs F0 = {a.force.F0:.3g} N."
        )
    )
    lines.append(
        f"- **Galloping / stall-flutter model** (c = {a.flutter.c:g} N s/m): any velocity gain above "
        f"{a.kd_star:g} N s/m stabilises it."
    )
    ref = s.metrics["soft"]
    f = semi_active_findings(s)
    sky = s.metrics["skyhook"]
    lines.append(
        f"- **Ideal skyhook** (the active law the semi-active ones imitate): steady RMS displacement "
        f"÷{ref.rms_x_ss / sky.rms_x_ss:.3g} against the soft passive damper; it removes {s.power.removed:.3g} W from "
        f"the mass, while its actuator between body and base must supply {s.power.supplied:.3g} W and exchanges "
        f"{s.power.gross:.3g} W (net {s.power.net:.3g} W)."
    )
    for name in ("on-off", "clipped", "mr"):
        mt = s.metrics[name]
        lines.append(
            f"- **{_SA_LABELS[name]}**: steady RMS displacement ÷{ref.rms_x_ss / mt.rms_x_ss:.3g} against the soft "
            f"passive damper, at {mt.rms_u:.3g} N RMS device force and {mt.energy:.3g} J exchanged, "
            "with no power source."
        )
    conv = list(s.refine.values())
    lines.append(
        f"- At ω_n the clipped skyhook transmits {f['t_res']:.3g}, the on-off law {conv[-1]:.4g} (converged under "
        f"step refinement), the ideal skyhook {f['t_res_sky']:.3g} and the best passive damper no less than 1. "
        f"Clipped skyhook beats every passive damper from ω/ω_n = {f['band'][0]:.3g} to {f['band'][1]:.3g} and above "
        f"√2 ω_n transmits at most {f['loss_soft']:.3g} times what the soft passive damper transmits."
    )
    zv, zvd = sh.bands["ZV"], sh.bands["ZVD"]
    lines.append(
        f"- **Input shaping**: with a {100 * sh.freq_error:+.0f} % frequency error ZV leaves "
        f"{100 * sh.residual['ZV']:.3g} % and ZVD {100 * sh.residual['ZVD']:.3g} % of the unshaped ringing, "
        f"for {sh.shapers['ZV'].duration:.3g} s and {sh.shapers['ZVD'].duration:.3g} s of delay; residual below 5 % "
        f"for frequency ratios {zv[0]:.4f} to {zv[1]:.4f} (ZV) and {zvd[0]:.4f} to {zvd[1]:.4f} (ZVD)."
    )
    return "\n".join(lines)


# ----------------------------------------------------------------------------- sliders


_PANEL_COUNTER = itertools.count(1)


def control_panel_html(
    m: float = 1.0,
    c: float = 0.5,
    k: float = 20.0,
    F0: float = 5.0,
    omega: float = 4.47,
    *,
    q_x: float = 1.0,
    q_v: float = 0.0,
    r: float = 1e-3,
    c_sky: float = 8.0,
    move: float = 0.1,
    freq_error: float = 0.1,
    t_end: float = 20.0,
) -> str:
    """Self-contained HTML + inline JavaScript: LQR weight, skyhook gain, shaper and frequency error.

    Computed in the browser from the closed forms (``assets/control.js``, exposed as
    ``window.vibrationControl``); loads nothing. Units: kg, N s/m, N/m, N, rad/s; LQR weights
    1/m^2, s^2/m^2, 1/N^2 (r on a log slider, 1e-7 to 1e2); c_sky N s/m (0 to 60); move m;
    freq_error 1 (slider -50 % to +50 %); t_end s.

    Examples
    --------
    >>> html_ = control_panel_html()
    >>> html_.startswith('<div class="vc-panel"'), "http" in html_
    (True, False)
    """
    import html
    import json

    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    c = check_real("c", c, low=0.0, unit="N s/m")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    r = check_real("r", r, low=0.0, low_open=True, unit="1/N^2")
    q_x = check_real("q_x", q_x, low=0.0, unit="1/m^2")
    q_v = check_real("q_v", q_v, low=0.0, unit="s^2/m^2")
    c_sky = check_real("c_sky", c_sky, low=0.0, high=60.0, unit="N s/m")
    freq_error = check_real("freq_error", freq_error, low=-0.5, high=0.5)
    params = {"m": m, "c": c, "k": k, "F0": F0, "omega": omega, "q_x": q_x, "q_v": q_v, "t_end": t_end, "move": move}
    pid = f"vc-{next(_PANEL_COUNTER)}"
    e = html.escape
    lr = min(max(math.log10(r), -7.0), 2.0)
    return f"""<div class="vc-panel" id="{pid}" data-params="{e(json.dumps(params))}">
<style>
{_asset("control.css")}</style>
<h3 class="vc-title">Explore without a kernel: m = {m:g} kg, c = {c:g} N s/m, k = {k:g} N/m</h3>
<noscript>This panel needs JavaScript to draw its plots.</noscript>
<div class="vc-grid">
<figure><figcaption>LQR at F<sub>0</sub> = {F0:g} N, ω = {omega:g} rad/s \
(grey: passive, colour: LQR, no force limit)</figcaption>
<label>weight r of the force (log scale) \
<input type="range" class="vc-logr" min="-7" max="2" step="0.05" value="{lr:g}"></label>
<output class="vc-r-out"></output>
<svg class="vc-active" viewBox="0 0 420 240" role="img" aria-label="displacement x in m against time t in s"></svg>
<p class="vc-active-read"></p></figure>
<figure><figcaption>Ideal skyhook under base motion (grey: passive c, colour: skyhook)</figcaption>
<label>skyhook damping <input type="range" class="vc-csky" min="0" max="60" step="0.5" value="{c_sky:g}"></label>
<output class="vc-csky-out"></output>
<svg class="vc-sky" viewBox="0 0 420 240" role="img" aria-label="transmissibility against frequency ratio"></svg>
<p class="vc-sky-read"></p></figure>
<figure><figcaption>Move of {move:g} m (grey: unshaped step, colour: shaped command)</figcaption>
<label>shaper <select class="vc-kind"><option value="none">none</option><option value="ZV">ZV</option>\
<option value="ZVD" selected>ZVD</option></select></label>
<label>natural-frequency error <input type="range" class="vc-err" min="-50" max="50" step="1" \
value="{round(100 * freq_error)}"></label>
<output class="vc-err-out"></output>
<svg class="vc-shape" viewBox="0 0 420 240" role="img" aria-label="displacement x in m against time t in s"></svg>
<p class="vc-shape-read"></p></figure>
</div>
<script>
{_asset("control.js")}</script>
<script>window.vibrationControl.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


class ControlPanel:
    """The kernel-free panel: in JupyterLab and in the book its ``text/html`` is the panel itself."""

    def __init__(self, **kwargs) -> None:
        self.kwargs = kwargs
        self.html = control_panel_html(**kwargs)

    def _repr_mimebundle_(self, include=None, exclude=None):
        args = ", ".join(f"{k}={v!r}" for k, v in self.kwargs.items())
        return {"text/html": self.html, "text/plain": f"ControlPanel({args})"}


def control_panel(m, c, k, F0, omega, **kwargs) -> ControlPanel:
    """:class:`ControlPanel` at the chapter's parameters (see :func:`control_panel_html`)."""
    return ControlPanel(m=m, c=c, k=k, F0=F0, omega=omega, **kwargs)


def control_explorer(
    m, c, k, F0, omega, *, q_x, q_v, r, u_max, c_sky, c_min, c_max, move, freq_error, t_end: float = 20.0
):
    """JupyterLab sliders (ipywidgets): LQR weight and force limit; skyhook gain; shaper and frequency error.

    The LQR loop with the force limit is simulated with :func:`vibration.simulate_controlled`;
    the clipped skyhook curve comes from :func:`vibration.physics.control.semi_active_sweep`.
    Returns an ``ipywidgets.Tab`` whose mime bundle also carries the kernel-free panel as
    ``text/html`` for renderers without a kernel.
    """
    import ipywidgets as widgets
    import matplotlib.pyplot as plt

    osc, force = Oscillator(m, c, k), SineForce(F0, omega)
    Y = F0 / k
    wn = osc.natural_frequency

    logr = widgets.FloatSlider(value=math.log10(r), min=-7, max=2, step=0.05, description="log10 r (1/N²)")
    lim = widgets.FloatSlider(value=u_max, min=0.5, max=50.0, step=0.5, description="u_max (N)")
    out_a = widgets.Output()

    def draw_active(*_):
        with out_a:
            out_a.clear_output(wait=True)
            des = lqr(osc, q_x, q_v, 10**logr.value)
            run = simulate_controlled(
                osc, lambda t, x, v: -des.K @ (x, v), force, u_max=lim.value, t_end=t_end, n_points=2001, rtol=1e-8
            )
            fig, ax = figure(height=3.0)
            ex = exact_response(osc, force, run.t)
            ax.plot(run.t, ex.x, color="0.5", lw=1.0, label="passive")
            ax.plot(run.t, run.x, color="C2", label=f"LQR, |u| ≤ {lim.value:g} N")
            ax.set_xlabel(r"$t$ (s)")
            ax.set_ylabel(r"$x$ (m)")
            place_legend(ax, outside=True)
            plt.show()
            print(
                f"K = [{des.K[0]:.4g} N/m, {des.K[1]:.4g} N s/m]; max|u| demanded {np.max(np.abs(run.u_demand)):.3g} N"
            )

    csky = widgets.FloatSlider(value=c_sky, min=0.0, max=40.0, step=0.5, description="c_sky (N s/m)")
    out_s = widgets.Output()

    def draw_sky(*_):
        with out_s:
            out_s.clear_output(wait=True)
            rr = np.geomspace(0.3, 4.0, 25)
            sw = semi_active_sweep(osc, "clipped", rr * wn, Y, c_sky=csky.value, c_min=c_min, c_max=c_max, periods=4)
            fine = np.geomspace(0.3, 4.0, 400)
            fig, ax = figure(height=3.0)
            ax.loglog(fine, passive_transmissibility(Oscillator(m, c + c_min, k), fine * wn), color="0.5", ls="--",
                      label="passive, c + c_min")  # fmt: skip
            ax.loglog(fine, skyhook_transmissibility(osc, csky.value, fine * wn), color="C0", label="ideal skyhook")
            ax.loglog(rr, sw.peak, "o-", ms=3, color="C1", label="clipped skyhook")
            ax.set_xlabel(r"$\omega/\omega_n$")
            ax.set_ylabel(r"max$|x|/Y$")
            place_legend(ax, outside=True)
            plt.show()

    kind = widgets.Dropdown(options=["none", "ZV", "ZVD"], value="ZVD", description="shaper")
    err = widgets.FloatSlider(value=100 * freq_error, min=-50, max=50, step=1, description="ω_n error (%)")
    out_h = widgets.Output()

    def draw_shape(*_):
        with out_h:
            out_h.clear_output(wait=True)
            actual = Oscillator(m, c, k * (1 + err.value / 100) ** 2)
            sh = {"none": None, "ZV": zv_shaper(osc), "ZVD": zvd_shaper(osc)}[kind.value]
            t, x, _, _ = shaped_move(actual, sh, move, 10.0, 1001)
            t0, x0, _, _ = shaped_move(actual, None, move, 10.0, 1001)
            fig, ax = figure(height=3.0)
            ax.plot(t0, x0, color="0.5", lw=1.0, label="unshaped")
            ax.plot(t, x, color="C1", label=kind.value)
            ax.set_xlabel(r"$t$ (s)")
            ax.set_ylabel(r"$x$ (m)")
            place_legend(ax, outside=True)
            plt.show()
            print(f"residual vibration {100 * shaper_residual(sh, actual):.3g} % of the unshaped step")

    for wdg, fn in ((logr, draw_active), (lim, draw_active), (csky, draw_sky), (kind, draw_shape), (err, draw_shape)):
        wdg.observe(fn, names="value")
    draw_active()
    draw_sky()
    draw_shape()
    panel = control_panel_html(m, c, k, F0, omega, q_x=q_x, q_v=q_v, r=r, c_sky=min(c_sky, 60.0), move=move,
                               freq_error=max(-0.5, min(0.5, freq_error)))  # fmt: skip

    class _Tab(widgets.Tab):
        def _repr_mimebundle_(self, **kwargs):
            data = super()._repr_mimebundle_(**kwargs)
            if data is not None:
                data["text/html"] = panel
            return data

    tab = _Tab(
        children=[
            widgets.VBox([logr, lim, out_a]),
            widgets.VBox([csky, out_s]),
            widgets.VBox([widgets.HBox([kind, err]), out_h]),
        ]
    )
    for i, title in enumerate(("active (LQR, force limit)", "skyhook", "input shaping")):
        tab.set_title(i, title)
    return tab
