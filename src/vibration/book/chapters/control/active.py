"""Chapter 7's active control: passive, PD, LQR and PID at the forcing ``F0 sin(omega_res t)``, the LQR
trade-off along its force weight, the force-limited PID move under three integrator treatments, the loops'
costs (delay margin, noise) and the negative-damping (flutter) plant under velocity feedback.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_continuous_are

from vibration.book.chapters.control.params import Params
from vibration.book.chapters.control.steady import t_steady
from vibration.physics.control import (
    LoopCosts,
    LQRResult,
    Metrics,
    PIDPoles,
    PIDResponse,
    force_floor,
    hold_force,
    largest_holdable_reference,
    loop_costs,
    lqr,
    lqr_closed_form,
    pd_oscillator,
    pid_poles,
    pid_response,
    response_metrics,
    simulate_controlled,
    stabilising_velocity_gain,
)
from vibration.physics.exact import Response, exact_response, steady_state
from vibration.physics.model import Oscillator, SineForce, check_int

#: The active designs compared on equal footing: PD, LQR, a PD with the PID's K_p and K_d, the PID.
DESIGNS = ("PD", "LQR", "PD2", "PID")
#: Integrator treatments of the force-limited PID move ("unlimited": no force limit).
MOVE_SCHEMES = ("unlimited", "none", "clamping", "back-calculation")
#: Fraction of the largest holdable set point that the feasible PID move goes to.
FEASIBLE_FRACTION = 0.8


@dataclass(frozen=True, kw_only=True)
class Design:
    """One active law on equal footing: gains, steady amplitude, force against its floor, loop costs."""

    name: str  # "PD", "LQR", "PD2" (a PD with the PID's K_p and K_d) or "PID"
    kx: float  # position (proportional) gain, N/m
    ki: float  # integral gain, N/(m s)
    kv: float  # velocity (derivative) gain, N s/m
    amplitude: float  # steady amplitude of the unlimited loop at the forcing, m
    u_rms: float  # steady-window RMS force of the run, N
    floor: float  # least RMS force any controller needs to hold that amplitude, N
    costs: LoopCosts  # delay margin, crossover, loop gain, noise bandwidth


@dataclass(frozen=True, kw_only=True)
class ClosedLoop:
    """A PD-type loop ``u = -K_x x - K_v v`` seen as the oscillator ``(m, c + K_v, k + K_x)``."""

    name: str  # "PD" or "LQR"
    kx: float  # N/m
    kv: float  # N s/m
    osc: Oscillator  # the closed loop
    pole: complex  # the pole of largest imaginary part (the larger real pole if both are real), 1/s
    amplitude: float  # steady amplitude at the forcing, m


@dataclass(frozen=True, kw_only=True)
class Tradeoff:
    """The LQR designs along the force weight r: steady amplitude and RMS force."""

    r: np.ndarray  # force weights, 1/N^2
    amplitude: np.ndarray  # steady amplitude, m
    force_rms: np.ndarray  # steady RMS control force, N
    excess: float  # largest ratio of the RMS force to the least force for the same amplitude, 1
    design_force: float  # steady RMS force of the chapter's LQR design, N
    pd_force: float  # steady RMS force of the PD loop, N


@dataclass(frozen=True, kw_only=True)
class MoveRun:
    """One PID set-point move (force limit and integrator treatment) summarised over its steady tail."""

    scheme: str  # one of MOVE_SCHEMES
    run: PIDResponse
    overshoot: float  # max x - x_ref, m
    amplitude: float  # steady half peak-to-peak oscillation, m
    mean_error: float  # steady mean of x - x_ref, m
    saturated: float  # fraction of the window at the limit, 1
    saturated_ss: float  # fraction of the steady tail the demand exceeds the limit, 1
    integral_max: float  # largest |integrator state|, m s
    peak_u: float  # largest |u|, N


@dataclass(frozen=True, kw_only=True)
class Hold:
    """Can the force limit hold the set point against the disturbance? And a move that it can hold."""

    needed: float  # peak force to hold x_ref against the disturbance, k |x_ref| + F0, N
    feasible: bool  # needed <= u_max
    x_max: float  # largest holdable set point (u_max - F0)/k, m (nan: none)
    x_ok: float  # set point of the feasible move (FEASIBLE_FRACTION of x_max), m (nan: none)
    run: MoveRun | None  # the feasible move with clamping (None: no set point can be held)


@dataclass(frozen=True, kw_only=True)
class FlutterCase:
    """The negative-damping plant under velocity feedback ``u = -K_v v``."""

    label: str  # "no feedback", "0.9", "1", "1.1" (multiples of the stabilising gain)
    kv: float  # N s/m
    re: float  # largest real part of the poles, 1/s
    im: float  # largest |imaginary part|, rad/s


@dataclass(frozen=True, kw_only=True)
class ActiveStudy:
    """Every active-control run of the chapter at the forcing ``F0 sin(omega_res t)``."""

    osc: Oscillator  # plant (m, c_nominal, k)
    force: SineForce  # the disturbance
    t: np.ndarray  # output times, s
    t_steady: float  # start of the steady-state tail, s
    x: dict[str, np.ndarray]  # "passive"/"PD"/"PD2"/"LQR"/"PID" -> displacement, m
    u: dict[str, np.ndarray]  # -> control force, N
    metrics: dict[str, Metrics]  # -> peak/RMS displacement and force, energy
    pd_error: float  # max |simulated - exact| of the PD loop, m
    lqr: LQRResult  # the chapter's LQR design
    lqr_check: dict[str, float]  # relative discrepancies: "scipy", "closed form", "residual"
    loops: dict[str, ClosedLoop]  # "PD", "LQR"
    passive_amplitude: float  # steady amplitude of the plant without control, m
    designs: dict[str, Design]  # DESIGNS on equal footing
    pid_poles: PIDPoles  # the PID's closed-loop poles
    tradeoff: Tradeoff
    u_max: float  # the PID's force limit, N
    x_ref: float  # set point of the move, m
    moves: dict[str, MoveRun]  # MOVE_SCHEMES
    hold: Hold
    flutter: Oscillator  # negative-damping plant
    kd_star: float  # smallest stabilising velocity gain, N s/m
    flutter_cases: tuple[FlutterCase, ...]

    @property
    def forcing_ratio(self) -> float:
        """Forcing frequency over the plant's natural frequency, 1."""
        return self.force.omega / self.osc.natural_frequency


def loop_amplitude(osc: Oscillator, force: SineForce, kp: float, *, ki: float, kd: float) -> float:
    """Steady amplitude (m) of the unlimited loop ``kp + ki/s + kd s`` at the forcing: ``F0 |P / (1 + P C)|``."""
    w = force.omega
    C = kp + 1j * kd * w + (ki / (1j * w) if ki > 0.0 else 0.0)
    return force.F0 / abs(osc.k - osc.m * w * w + 1j * osc.c * w + C)


def _closed_loop(name: str, osc: Oscillator, kx: float, kv: float, force: SineForce) -> ClosedLoop:
    cl = pd_oscillator(osc, kx, kv)
    poles = np.roots([cl.m, cl.c, cl.k]).astype(complex)
    pole = poles[np.argmax(poles.imag)] if np.any(poles.imag != 0) else poles[np.argmax(poles.real)]
    return ClosedLoop(name=name, kx=kx, kv=kv, osc=cl, pole=complex(pole), amplitude=steady_state(cl, force).amplitude)


def _lqr_check(osc: Oscillator, design: LQRResult, q_x: float, q_v: float, r: float) -> dict[str, float]:
    """python-control's gains against scipy's Riccati solver and the closed form; the Riccati residual."""
    A = np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]])
    B = np.array([[0.0], [1.0 / osc.m]])
    Q = np.diag([q_x, q_v])
    P = solve_continuous_are(A, B, Q, np.array([[r]]))
    K_sp = (B.T @ P / r).ravel()
    resid = A.T @ design.P + design.P @ A - design.P @ B @ B.T @ design.P / r + Q
    scale = float(np.max(np.abs(K_sp)))
    return {
        "scipy": float(np.max(np.abs(design.K - K_sp))) / scale,
        "closed form": float(np.max(np.abs(design.K - lqr_closed_form(osc, q_x, q_v, r=r)))) / scale,
        "residual": float(np.max(np.abs(resid))) / float(np.max(np.abs(design.P)) * max(1.0, np.max(np.abs(A)))),
    }


def _tradeoff(osc: Oscillator, force: SineForce, p: Params, design: LQRResult, pd: ClosedLoop, n_r: int) -> Tradeoff:
    rs = np.geomspace(1e-7, 1e2, n_r) * p.r_lqr / 1e-3
    amp, frc = [], []
    for ri in rs:
        des = lqr(osc, p.q_x, p.q_v, r=float(ri))
        X = steady_state(des.closed_loop, force).amplitude
        amp.append(X)
        frc.append(X * abs(des.K[0] + 1j * force.omega * des.K[1]) / math.sqrt(2.0))
    amp, frc = np.array(amp), np.array(frc)
    floor = force_floor(osc, force, amp)
    X_d = steady_state(design.closed_loop, force).amplitude
    return Tradeoff(
        r=rs,
        amplitude=amp,
        force_rms=frc,
        excess=float(np.max(frc / np.maximum(floor, 1e-300))),
        design_force=X_d * abs(design.K[0] + 1j * force.omega * design.K[1]) / math.sqrt(2.0),
        pd_force=pd.amplitude * abs(pd.kx + 1j * force.omega * pd.kv) / math.sqrt(2.0),
    )


def _move_run(scheme: str, run: PIDResponse, x_ref: float, ts: float) -> MoveRun:
    tail = run.t >= ts
    return MoveRun(
        scheme=scheme,
        run=run,
        overshoot=float(np.max(run.x) - x_ref),
        amplitude=float(np.ptp(run.x[tail]) / 2.0),
        mean_error=float(np.mean(run.x[tail]) - x_ref),
        saturated=run.saturated_fraction,
        saturated_ss=float(np.mean(np.abs(run.u_demand[tail]) >= run.u_max)) if math.isfinite(run.u_max) else 0.0,
        integral_max=float(np.max(np.abs(run.integral))),
        peak_u=float(np.max(np.abs(run.u))),
    )


def _gains(p: Params, design: LQRResult) -> dict[str, tuple[float, float, float]]:
    """``(K_x, K_i, K_v)`` of each design in :data:`DESIGNS`."""
    return {
        "PD": (p.kp, 0.0, p.kd),
        "PD2": (p.pid_kp, 0.0, p.pid_kd),
        "LQR": (float(design.K[0]), 0.0, float(design.K[1])),
        "PID": (p.pid_kp, p.pid_ki, p.pid_kd),
    }


def _responses(osc: Oscillator, force: SineForce, p: Params, t: np.ndarray, passive: Response, gains: dict):
    """Displacement, force and velocity of every run (passive first), and the PD loop's simulation error."""
    xs, us, vs = {}, {}, {}
    xs["passive"], us["passive"], vs["passive"] = passive.x, np.zeros_like(t), passive.v
    for name in ("PD", "PD2", "LQR"):
        kx, _, kv = gains[name]
        r = exact_response(pd_oscillator(osc, kx, kv), force, t)
        xs[name], us[name], vs[name] = r.x, -kx * r.x - kv * r.v, r.v
    sim_pd = simulate_controlled(osc, lambda _t, x, v: -p.kp * x - p.kd * v, force, t_end=p.t_end, n_points=p.n_points)
    pd_error = float(np.max(np.abs(sim_pd.x - xs["PD"])))

    reg = pid_response(
        osc, force, p.pid_kp, ki=p.pid_ki, kd=p.pid_kd, u_max=p.u_max, anti_windup="clamping", t_end=p.t_end,
        n_points=p.n_points,
    )  # fmt: skip
    xs["PID"], us["PID"], vs["PID"] = reg.x, reg.u, reg.v
    return xs, us, vs, pd_error


def _designs(osc: Oscillator, force: SineForce, p: Params, gains: dict, metrics: dict) -> dict[str, Design]:
    """The designs of :data:`DESIGNS` on equal footing: amplitude, force against its floor, loop costs."""
    designs = {}
    for name in DESIGNS:
        kx, ki, kv = gains[name]
        X = loop_amplitude(osc, force, kx, ki=ki, kd=kv)
        designs[name] = Design(
            name=name,
            kx=kx,
            ki=ki,
            kv=kv,
            amplitude=X,
            u_rms=metrics[name].rms_u,
            floor=float(force_floor(osc, force, X)),
            costs=loop_costs(osc, kx, kv, ki=ki, omega=p.omega_res),
        )
    return designs


def _moves(osc: Oscillator, force: SineForce, p: Params, ts: float) -> dict[str, MoveRun]:
    """The PID set-point move under each integrator treatment of :data:`MOVE_SCHEMES`."""
    moves = {}
    for scheme in MOVE_SCHEMES:
        limit = {} if scheme == "unlimited" else {"u_max": p.u_max, "anti_windup": scheme}
        run = pid_response(
            osc, force, p.pid_kp, ki=p.pid_ki, kd=p.pid_kd, x_ref=p.x_ref, t_end=p.t_end, n_points=p.n_points, **limit
        )
        moves[scheme] = _move_run(scheme, run, p.x_ref, ts)
    return moves


def _hold(osc: Oscillator, force: SineForce, p: Params, ts: float) -> Hold:
    """Whether the force limit holds the set point, and the clamped move to a set point it can hold."""
    needed = hold_force(osc, force, p.x_ref)
    x_max = largest_holdable_reference(osc, force, p.u_max)
    x_ok, ok_run = math.nan, None
    if math.isfinite(x_max) and x_max > 0.0:
        x_ok = FEASIBLE_FRACTION * x_max * (1.0 if p.x_ref >= 0.0 else -1.0)
        run = pid_response(
            osc, force, p.pid_kp, ki=p.pid_ki, kd=p.pid_kd, u_max=p.u_max, anti_windup="clamping", x_ref=x_ok,
            t_end=p.t_end, n_points=p.n_points,
        )  # fmt: skip
        ok_run = _move_run("clamping", run, x_ok, ts)
    return Hold(needed=needed, feasible=needed <= p.u_max, x_max=x_max, x_ok=x_ok, run=ok_run)


def _flutter_cases(flutter: Oscillator, kd_star: float) -> tuple[FlutterCase, ...]:
    """The flutter plant's poles without feedback and at 0.9, 1 and 1.1 times the stabilising gain."""
    cases = []
    for label, kv in (("no feedback", 0.0), ("0.9", 0.9 * kd_star), ("1", kd_star), ("1.1", 1.1 * kd_star)):
        poles = np.roots([flutter.m, flutter.c + kv, flutter.k]).astype(complex)
        cases.append(
            FlutterCase(label=label, kv=kv, re=float(np.max(poles.real)), im=float(np.max(np.abs(poles.imag))))
        )
    return tuple(cases)


def active_study(params: Params | None = None, *, n_r: int = 61, **values) -> ActiveStudy:
    """Passive, PD, LQR and PID at the forcing, the PID move under a force limit, the LQR trade-off.

    Parameters
    ----------
    params : Params, optional
        The chapter's parameters (or give them as keyword arguments, checked by the schema).
    n_r : int
        Force weights on the LQR trade-off curve (2 to 2000).

    Examples
    --------
    >>> a = active_study(t_end=10.0, n_points=201, n_r=5)
    >>> sorted(a.metrics), a.kd_star
    (['LQR', 'PD', 'PD2', 'PID', 'passive'], 0.5)
    """
    p = params if params is not None else Params.from_values(values)
    n_r = check_int("n_r", n_r, low=2, high=2000)
    osc, force = Oscillator(m=p.m, c=p.c_nominal, k=p.k), SineForce(F0=p.F0, omega=p.omega_res)
    t = np.linspace(0.0, p.t_end, p.n_points)
    ts = t_steady(p.t_end, p.omega_res)
    passive = exact_response(osc, force, t)
    design = lqr(osc, p.q_x, p.q_v, r=p.r_lqr)
    loops = {
        "PD": _closed_loop("PD", osc, p.kp, p.kd, force),
        "LQR": _closed_loop("LQR", osc, float(design.K[0]), float(design.K[1]), force),
    }
    gains = _gains(p, design)
    xs, us, vs, pd_error = _responses(osc, force, p, t, passive, gains)
    metrics = {name: response_metrics(t, xs[name], us[name], v_rel=vs[name], t_steady=ts) for name in xs}
    designs = _designs(osc, force, p, gains, metrics)
    moves = _moves(osc, force, p, ts)
    hold = _hold(osc, force, p, ts)
    flutter = Oscillator(m=p.m, c=p.c_flutter, k=p.k)
    kd_star = stabilising_velocity_gain(flutter)
    cases = _flutter_cases(flutter, kd_star)

    return ActiveStudy(
        osc=osc,
        force=force,
        t=t,
        t_steady=ts,
        x=xs,
        u=us,
        metrics=metrics,
        pd_error=pd_error,
        lqr=design,
        lqr_check=_lqr_check(osc, design, p.q_x, p.q_v, p.r_lqr),
        loops=loops,
        passive_amplitude=steady_state(osc, force).amplitude,
        designs=designs,
        pid_poles=pid_poles(osc, p.pid_kp, p.pid_ki, kd=p.pid_kd),
        tradeoff=_tradeoff(osc, force, p, design, loops["PD"], n_r),
        u_max=p.u_max,
        x_ref=p.x_ref,
        moves=moves,
        hold=hold,
        flutter=flutter,
        kd_star=kd_star,
        flutter_cases=cases,
    )
