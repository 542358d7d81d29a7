"""Chapter 7, control: every run of the chapter, once, as frozen records (no prose).

:func:`control_study` takes the chapter's validated :class:`~vibration.chapters.control.params.Params`
and runs the physics of :mod:`vibration.physics.control` three times over:

* :func:`active_study`: passive, PD, LQR and PID at the forcing ``F0 sin(omega_res t)``, the LQR
  trade-off along its force weight, the force-limited PID move under three integrator treatments,
  the loops' costs (delay margin, noise) and the negative-damping (flutter) plant;
* :func:`semi_active_study`: the base-excited suspension, swept in frequency and run in time with
  the ideal, on-off and clipped skyhook and a scaled MR damper;
* :func:`shaping_study`: a point-to-point move, unshaped and with ZV and ZVD shapers designed on a
  model whose natural frequency is off by ``freq_error``.

Figures, tables and sentences (modules ``figures``, ``tables``, ``text``) read only these records,
so a run with other parameters never contradicts itself.

Examples
--------
>>> s = shaping_study(Params(move=0.1, freq_error=0.1), n_ratio=21)
>>> s.shapers["ZV"].kind, round(float(s.residual["ZV"]), 3)
('ZV', 0.143)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_continuous_are

from vibration.chapters.control.params import Params
from vibration.physics.control import (
    SPENCER_1997,
    SPENCER_1997_STROKE,
    LoopCosts,
    LQRResult,
    Metrics,
    MRDamper,
    PIDPoles,
    PIDResponse,
    SemiActiveResponse,
    SemiActiveSweep,
    Shaper,
    SkyhookPower,
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
from vibration.physics.exact import exact_response, steady_state
from vibration.physics.model import Oscillator, SineForce, check_int

#: Forcing periods at the end of the window that count as steady state.
STEADY_PERIODS = 10
#: The active designs compared on equal footing: PD, LQR, a PD with the PID's K_p and K_d, the PID.
DESIGNS = ("PD", "LQR", "PD2", "PID")
#: Integrator treatments of the force-limited PID move ("unlimited": no force limit).
MOVE_SCHEMES = ("unlimited", "none", "clamping", "back-calculation")
#: RK4 steps per period of the on-off skyhook refinement at omega_n (the sweeps use 1000).
REFINE_STEPS = (1000, 4000, 16000, 64000)
#: Fraction of the largest holdable set point that the feasible PID move goes to.
FEASIBLE_FRACTION = 0.8
#: Largest residual vibration (fraction of the unshaped step's) that a shaper's band tolerates.
SHAPER_LEVEL = 0.05


def t_steady(t_end: float, omega: float) -> float:
    """Start of the steady-state tail (the last :data:`STEADY_PERIODS` forcing periods), s."""
    return max(0.0, t_end - STEADY_PERIODS * 2.0 * math.pi / omega) if omega > 0 else 0.5 * t_end


def _params(params: Params | None, values: dict) -> Params:
    return params if params is not None else Params.from_values(values)


# ----------------------------------------------------------------------------- active


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


def loop_amplitude(osc: Oscillator, force: SineForce, kp: float, ki: float, kd: float) -> float:
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
        "closed form": float(np.max(np.abs(design.K - lqr_closed_form(osc, q_x, q_v, r)))) / scale,
        "residual": float(np.max(np.abs(resid))) / float(np.max(np.abs(design.P)) * max(1.0, np.max(np.abs(A)))),
    }


def _tradeoff(osc: Oscillator, force: SineForce, p: Params, design: LQRResult, pd: ClosedLoop, n_r: int) -> Tradeoff:
    rs = np.geomspace(1e-7, 1e2, n_r) * p.r_lqr / 1e-3
    amp, frc = [], []
    for ri in rs:
        des = lqr(osc, p.q_x, p.q_v, float(ri))
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
    p = _params(params, values)
    n_r = check_int("n_r", n_r, low=2, high=2000)
    osc, force = Oscillator(m=p.m, c=p.c_nominal, k=p.k), SineForce(F0=p.F0, omega=p.omega_res)
    t = np.linspace(0.0, p.t_end, p.n_points)
    ts = t_steady(p.t_end, p.omega_res)
    xs, us, vs = {}, {}, {}

    ex = exact_response(osc, force, t)
    xs["passive"], us["passive"], vs["passive"] = ex.x, np.zeros_like(t), ex.v

    design = lqr(osc, p.q_x, p.q_v, p.r_lqr)
    loops = {
        "PD": _closed_loop("PD", osc, p.kp, p.kd, force),
        "LQR": _closed_loop("LQR", osc, float(design.K[0]), float(design.K[1]), force),
    }
    gains = {
        "PD": (p.kp, 0.0, p.kd),
        "PD2": (p.pid_kp, 0.0, p.pid_kd),
        "LQR": (float(design.K[0]), 0.0, float(design.K[1])),
        "PID": (p.pid_kp, p.pid_ki, p.pid_kd),
    }
    for name in ("PD", "PD2", "LQR"):
        kx, _, kv = gains[name]
        r = exact_response(pd_oscillator(osc, kx, kv), force, t)
        xs[name], us[name], vs[name] = r.x, -kx * r.x - kv * r.v, r.v
    sim_pd = simulate_controlled(osc, lambda _t, x, v: -p.kp * x - p.kd * v, force, t_end=p.t_end, n_points=p.n_points)
    pd_error = float(np.max(np.abs(sim_pd.x - xs["PD"])))

    reg = pid_response(
        osc, force, p.pid_kp, p.pid_ki, p.pid_kd, u_max=p.u_max, anti_windup="clamping", t_end=p.t_end,
        n_points=p.n_points,
    )  # fmt: skip
    xs["PID"], us["PID"], vs["PID"] = reg.x, reg.u, reg.v
    metrics = {name: response_metrics(t, xs[name], us[name], vs[name], ts) for name in xs}

    designs = {}
    for name in DESIGNS:
        kx, ki, kv = gains[name]
        X = loop_amplitude(osc, force, kx, ki, kv)
        designs[name] = Design(
            name=name,
            kx=kx,
            ki=ki,
            kv=kv,
            amplitude=X,
            u_rms=metrics[name].rms_u,
            floor=float(force_floor(osc, force, X)),
            costs=loop_costs(osc, kx, kv, ki, p.omega_res),
        )

    moves = {}
    for scheme in MOVE_SCHEMES:
        limit = {} if scheme == "unlimited" else {"u_max": p.u_max, "anti_windup": scheme}
        run = pid_response(
            osc, force, p.pid_kp, p.pid_ki, p.pid_kd, x_ref=p.x_ref, t_end=p.t_end, n_points=p.n_points, **limit
        )
        moves[scheme] = _move_run(scheme, run, p.x_ref, ts)

    needed = hold_force(osc, force, p.x_ref)
    x_max = largest_holdable_reference(osc, force, p.u_max)
    x_ok, ok_run = math.nan, None
    if math.isfinite(x_max) and x_max > 0.0:
        x_ok = FEASIBLE_FRACTION * x_max * (1.0 if p.x_ref >= 0.0 else -1.0)
        run = pid_response(
            osc, force, p.pid_kp, p.pid_ki, p.pid_kd, u_max=p.u_max, anti_windup="clamping", x_ref=x_ok,
            t_end=p.t_end, n_points=p.n_points,
        )  # fmt: skip
        ok_run = _move_run("clamping", run, x_ok, ts)
    hold = Hold(needed=needed, feasible=needed <= p.u_max, x_max=x_max, x_ok=x_ok, run=ok_run)

    flutter = Oscillator(m=p.m, c=p.c_flutter, k=p.k)
    kd_star = stabilising_velocity_gain(flutter)
    cases = []
    for label, kv in (("no feedback", 0.0), ("0.9", 0.9 * kd_star), ("1", kd_star), ("1.1", 1.1 * kd_star)):
        poles = np.roots([flutter.m, flutter.c + kv, flutter.k]).astype(complex)
        cases.append(
            FlutterCase(label=label, kv=kv, re=float(np.max(poles.real)), im=float(np.max(np.abs(poles.imag))))
        )

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
        pid_poles=pid_poles(osc, p.pid_kp, p.pid_ki, p.pid_kd),
        tradeoff=_tradeoff(osc, force, p, design, loops["PD"], n_r),
        u_max=p.u_max,
        x_ref=p.x_ref,
        moves=moves,
        hold=hold,
        flutter=flutter,
        kd_star=kd_star,
        flutter_cases=tuple(cases),
    )


# ----------------------------------------------------------------------------- semi-active


@dataclass(frozen=True, kw_only=True)
class SemiActiveFindings:
    """What the sweeps show: where clipped skyhook beats every passive damper, and what it costs."""

    band: tuple[float, float]  # frequency ratios where clipped skyhook beats the best passive damper (nan: none)
    all_near: bool  # it beats it over the whole band 1/sqrt(2) .. sqrt(2)
    any_near: bool  # it beats it somewhere in that band
    t_res: dict[str, float]  # transmissibility at omega_n: "soft", "firm", "skyhook", "clipped", "on-off", "mr"
    loss_soft: float  # largest clipped/soft ratio above sqrt(2) omega_n, 1
    gain_firm: float  # smallest firm/clipped ratio above sqrt(2) omega_n, 1
    mr_loss_soft: float  # largest MR/soft ratio above sqrt(2) omega_n, 1
    switches: float  # median command changes per period of the on-off law, 1
    force_res: float  # RMS force of the clipped damper at omega_n, N
    force_res_firm: float  # RMS force of the firm passive damper at omega_n, N


@dataclass(frozen=True, kw_only=True)
class SemiActiveStudy:
    """Semi-active suspension: sweeps across frequency and time runs at the forcing frequency."""

    osc: Oscillator  # m, passive c, k
    Y: float  # base amplitude, m
    omega: float  # base frequency of the time runs, rad/s
    c_sky: float  # skyhook gain, N s/m
    c_min: float  # device damping bounds, N s/m
    c_max: float
    damper: MRDamper  # scaled MR damper
    mr_scale: tuple[float, float]  # (length, force) scale factors
    ratios: np.ndarray  # frequency ratios of the sweep, 1
    closed: dict[str, np.ndarray]  # "soft"/"firm"/"skyhook"/"envelope" -> transmissibility (closed form)
    sweeps: dict[str, SemiActiveSweep]  # "on-off"/"clipped"/"mr"
    runs: dict[str, SemiActiveResponse]  # "soft"/"firm"/"skyhook"/"on-off"/"clipped"/"mr"
    metrics: dict[str, Metrics]
    t_steady: float  # s
    refine: dict[int, float]  # RK4 steps per period -> on-off skyhook peak transmissibility at omega_n, 1
    power: SkyhookPower  # closed form at omega
    power_run: dict[str, float]  # the same four mean powers measured on the skyhook run's steady tail, W
    closed_run_error: dict[str, float]  # "soft"/"skyhook": run's steady max|x|/Y against the closed form, relative
    worst_power: float  # largest instantaneous power f v_rel the on-off and clipped dampers deliver, W
    findings: SemiActiveFindings


def _passive_force_rms(osc: Oscillator, c_d: float, Y: float, w: float) -> float:
    """RMS force of a passive device damper c_d in steady state under base motion, N."""
    h = (osc.k + 1j * (osc.c + c_d) * w) / (osc.k - osc.m * w * w + 1j * (osc.c + c_d) * w)
    return c_d * w * Y * abs(h - 1.0) / math.sqrt(2.0)


def _findings(osc, ratios, closed, sweeps, c_max, Y) -> SemiActiveFindings:
    cl = sweeps["clipped"].peak
    beats = cl < closed["envelope"]
    near = np.abs(np.log(ratios)) <= np.log(np.sqrt(2.0))
    hi = ratios >= math.sqrt(2.0)
    i1 = int(np.argmin(np.abs(ratios - 1.0)))
    idx = np.nonzero(beats)[0]
    return SemiActiveFindings(
        band=(float(ratios[idx.min()]), float(ratios[idx.max()])) if idx.size else (math.nan, math.nan),
        all_near=bool(np.all(beats[near])),
        any_near=bool(np.any(beats[near])),
        t_res={
            "soft": float(closed["soft"][i1]),
            "firm": float(closed["firm"][i1]),
            "skyhook": float(closed["skyhook"][i1]),
            "clipped": float(cl[i1]),
            "on-off": float(sweeps["on-off"].peak[i1]),
            "mr": float(sweeps["mr"].peak[i1]),
        },
        loss_soft=float(np.max(cl[hi] / closed["soft"][hi])),
        gain_firm=float(np.min(closed["firm"][hi] / cl[hi])),
        mr_loss_soft=float(np.max(sweeps["mr"].peak[hi] / closed["soft"][hi])),
        switches=float(np.median(sweeps["on-off"].switches)),
        force_res=float(sweeps["clipped"].force_rms[i1]),
        force_res_firm=_passive_force_rms(osc, c_max, Y, ratios[i1] * osc.natural_frequency),
    )


def semi_active_study(params: Params | None = None, **values) -> SemiActiveStudy:
    """Base excitation ``Y = F0 / k`` (so that ``k Y = F0``): sweeps and runs of every law.

    The MR damper is :data:`~vibration.physics.control.SPENCER_1997` scaled so that its stroke at
    the test amplitude (1.5 cm) maps onto ``Y`` and its full-voltage yield force onto ``f_mr`` (N).

    Examples
    --------
    >>> s = semi_active_study(t_end=5.0, n_points=101, n_sweep=10)
    >>> round(s.Y, 3), sorted(s.sweeps)
    (0.25, ['clipped', 'mr', 'on-off'])
    """
    p = _params(params, values)
    osc = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    c_min, c_max, omega = p.c_sa_min, p.c_sa_max, p.omega_res
    Y = p.F0 / p.k
    wn = osc.natural_frequency
    ratios = np.unique(np.concatenate([np.geomspace(0.3, 4.0, p.n_sweep), [1.0, math.sqrt(2.0)]]))
    w = ratios * wn
    closed = {
        "soft": passive_transmissibility(Oscillator(m=p.m, c=p.c_nominal + c_min, k=p.k), w),
        "firm": passive_transmissibility(Oscillator(m=p.m, c=p.c_nominal + c_max, k=p.k), w),
        "skyhook": skyhook_transmissibility(osc, p.c_sky, w),
        "envelope": np.where(ratios < math.sqrt(2.0), 1.0, 1.0 / np.abs(ratios**2 - 1.0 + (ratios == 1.0))),
    }
    scale = (Y / SPENCER_1997_STROKE, p.f_mr / SPENCER_1997.yield_force)
    damper = SPENCER_1997.scaled(*scale)
    kw = {"c_sky": p.c_sky, "c_min": c_min, "c_max": c_max}
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
            osc, law, omega, Y, c_sky=p.c_sky, c_min=cmin, c_max=cmax, damper=damper, t_end=p.t_end,
            n_points=p.n_points,
        )  # fmt: skip
    ts = t_steady(p.t_end, omega)
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
        "removed": mean(p.c_sky * sky.v[tail] ** 2),
        "net": mean(p_rel),
        "supplied": mean(np.maximum(p_rel, 0.0)),
        "gross": mean(np.abs(p_rel)),
    }
    closed_run_error = {}
    for name, exact in (
        ("soft", float(passive_transmissibility(Oscillator(m=p.m, c=p.c_nominal + c_min, k=p.k), omega))),
        ("skyhook", float(skyhook_transmissibility(osc, p.c_sky, omega))),
    ):
        r = runs[name]
        closed_run_error[name] = abs(float(np.max(np.abs(r.x[r.t >= ts]))) / Y / exact - 1.0)
    worst = max(float(np.max(runs[n].f * (runs[n].v - runs[n].v_base))) for n in ("on-off", "clipped"))
    return SemiActiveStudy(
        osc=osc,
        Y=Y,
        omega=omega,
        c_sky=p.c_sky,
        c_min=c_min,
        c_max=c_max,
        damper=damper,
        mr_scale=scale,
        ratios=ratios,
        closed=closed,
        sweeps=sweeps,
        runs=runs,
        metrics=metrics,
        t_steady=ts,
        refine=refine,
        power=skyhook_power(osc, p.c_sky, Y, omega),
        power_run=power_run,
        closed_run_error=closed_run_error,
        worst_power=worst,
        findings=_findings(osc, ratios, closed, sweeps, c_max, Y),
    )


# ----------------------------------------------------------------------------- input shaping


@dataclass(frozen=True, kw_only=True)
class ShapingStudy:
    """Point-to-point moves with and without input shaping, and the sensitivity curves."""

    model: Oscillator  # the oscillator the shapers are designed on
    actual: Oscillator  # the real one (natural frequency off by freq_error)
    move: float  # distance, m
    freq_error: float  # relative natural-frequency error, 1
    shapers: dict[str, Shaper]  # "ZV"/"ZVD"
    t: np.ndarray  # times, s
    x: dict[str, np.ndarray]  # "none"/"ZV"/"ZVD" -> displacement, m
    residual: dict[str, float]  # residual vibration ratio (closed form), 1
    residual_sim: dict[str, float]  # ratio measured on the simulated move, 1
    amplitude: dict[str, float]  # ringing amplitude just after the move, m
    ratios: np.ndarray  # real / model natural frequency, 1
    sensitivity: dict[str, np.ndarray]  # "ZV"/"ZVD" -> residual vibration ratio along ratios, 1
    design_residual: float  # largest residual ratio at the design point, 1
    bands: dict[str, tuple[float, float]]  # "ZV"/"ZVD" -> ratios where V <= SHAPER_LEVEL (exact roots), 1


def shaping_study(
    params: Params | None = None, *, t_end: float = 10.0, n_points: int = 2001, n_ratio: int = 201, **values
) -> ShapingStudy:
    """ZV and ZVD on the model ``(m, c_nominal, k)``; moves of ``move`` m on the real oscillator whose
    natural frequency is ``(1 + freq_error)`` times the model's (k scaled by its square).

    ``t_end`` (s) and ``n_points`` set the window of the moves, ``n_ratio`` the sensitivity grid.
    """
    p = _params(params, values)
    n_ratio = check_int("n_ratio", n_ratio, low=2, high=100_000)
    model = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    actual = Oscillator(m=p.m, c=p.c_nominal, k=p.k * (1.0 + p.freq_error) ** 2)
    shapers = {"ZV": zv_shaper(model), "ZVD": zvd_shaper(model)}
    xs, res, sim, amp = {}, {}, {}, {}
    t0, x0, v0, _ = shaped_move(actual, None, p.move, t_end, n_points)
    a0 = residual_amplitude(actual, t0, x0, v0, p.move)
    for name, sh in (("none", None), *shapers.items()):
        t, x, v, _ = shaped_move(actual, sh, p.move, t_end, n_points)
        xs[name] = x
        res[name] = shaper_residual(sh, actual)
        tn = 0.0 if sh is None else sh.duration
        after = t > tn + 1e-12
        ring = residual_amplitude(actual, t, x, v, p.move)
        ratio = np.median(ring[after] / a0[after]) * math.exp(-actual.decay_rate * tn)  # Singer-Seering V
        sim[name] = float(ratio) if p.move != 0 else 0.0
        amp[name] = float(ring[after][0] * math.exp(actual.decay_rate * (t[after][0] - tn)))
    ratios = np.linspace(0.5, 1.5, n_ratio)
    sens = {
        name: np.array([shaper_residual(sh, Oscillator(m=p.m, c=p.c_nominal, k=p.k * q * q)) for q in ratios])
        for name, sh in shapers.items()
    }
    return ShapingStudy(
        model=model,
        actual=actual,
        move=p.move,
        freq_error=p.freq_error,
        shapers=shapers,
        t=t0,
        x=xs,
        residual=res,
        residual_sim=sim,
        amplitude=amp,
        ratios=ratios,
        sensitivity=sens,
        design_residual=max(shaper_residual(sh, model) for sh in shapers.values()),
        bands={name: insensitivity_band(sh, model, SHAPER_LEVEL) for name, sh in shapers.items()},
    )


# ----------------------------------------------------------------------------- the chapter


@dataclass(frozen=True, kw_only=True)
class ControlStudy:
    """The whole chapter: its parameters and the three studies."""

    params: Params
    active: ActiveStudy
    semi: SemiActiveStudy
    shaping: ShapingStudy


def control_study(params: Params | None = None, **values) -> ControlStudy:
    """Run the whole chapter's computation.

    Parameters
    ----------
    params : Params, optional
        The validated parameters; or give them as keyword arguments (checked by the schema).

    Returns
    -------
    ControlStudy
        Frozen record of every result the chapter shows.
    """
    p = _params(params, values)
    return ControlStudy(params=p, active=active_study(p), semi=semi_active_study(p), shaping=shaping_study(p))
