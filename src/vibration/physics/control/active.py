"""Active control: PD and LQR gains (closed loops that are again oscillators), any memoryless
controller integrated with DOP853 (:func:`simulate_controlled`), and the metrics of a run."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..checks import OverBudget, check_array, check_derived, check_oscillator, optional
from ..model import Oscillator, ParameterError, SineForce, check_real
from ._common import MAX_NFEV, RTOL_MAX, RTOL_MIN, _base, _call, _counted, _grid, _limit, _over_budget, _work_check

# ----------------------------------------------------------------------------- active: PD, LQR


def pd_oscillator(osc: Oscillator, kp: float, kd: float) -> Oscillator:
    """The closed loop of ``u = -kp x - kd v``: the oscillator ``(m, c + kd, k + kp)``.

    Parameters
    ----------
    osc : Oscillator
        Plant: m (kg), c (N s/m), k (N/m).
    kp : float
        Position gain, N/m; ``k + kp > 0`` (a spring must remain).
    kd : float
        Velocity gain, N s/m; any finite value (``c + kd < 0`` is an unstable loop).

    Returns
    -------
    Oscillator
        ``m x'' + (c + kd) x' + (k + kp) x = F(t)``.

    Examples
    --------
    >>> cl = pd_oscillator(Oscillator(m=1.0, c=0.5, k=20.0), kp=16.0, kd=5.5)
    >>> cl.c, cl.k, round(cl.damping_ratio, 3)      # N s/m, N/m, 1
    (6.0, 36.0, 0.5)
    """
    check_oscillator(osc)
    kp = check_real("kp", kp, low=-osc.k, low_open=True, unit="N/m")
    kd = check_real("kd", kd, unit="N s/m")
    try:
        return Oscillator(m=osc.m, c=osc.c + kd, k=osc.k + kp)
    except ParameterError as exc:
        raise ParameterError(
            f"kp = {kp!r} N/m and kd = {kd!r} N s/m make the closed loop (m, c + kd, k + kp) invalid ({exc}); allowed "
            "kp and kd whose closed loop is an Oscillator"
        ) from None


def stabilising_velocity_gain(osc: Oscillator) -> float:
    """Boundary velocity gain of ``u = -kd v``: the loop is stable exactly when ``kd > -c``, N s/m.

    With negative damping (flutter's linear model, ``c < 0``) the smallest stabilising gain
    is the infimum ``-c = |c|``: at ``kd = -c`` the poles sit on the imaginary axis
    (``+- i omega_n``), any larger gain makes both real parts ``-(c + kd)/(2 m) < 0``.
    A position gain ``kp > -k`` changes neither the boundary nor its exactness.

    Examples
    --------
    >>> stabilising_velocity_gain(Oscillator(m=1.0, c=-0.5, k=20.0))     # N s/m
    0.5
    """
    check_oscillator(osc)
    return -osc.c + 0.0


@dataclass(frozen=True, kw_only=True)
class LQRResult:
    """Linear-quadratic regulator ``u = -K [x, v]`` for ``J = int (q_x x^2 + q_v v^2 + r u^2) dt``."""

    K: np.ndarray  # gains [N/m, N s/m]
    P: np.ndarray  # 2 x 2 Riccati solution (J of the unforced loop from state y0 is y0' P y0)
    poles: np.ndarray  # closed-loop eigenvalues, 1/s (complex)
    plant: Oscillator  # the open-loop oscillator
    q_x: float  # weight of x^2, 1/m^2
    q_v: float  # weight of v^2, s^2/m^2
    r: float  # weight of u^2, 1/N^2

    @property
    def closed_loop(self) -> Oscillator:
        """The loop as an oscillator: ``(m, c + K[1], k + K[0])``."""
        return pd_oscillator(self.plant, float(self.K[0]), float(self.K[1]))


def _lqr_args(osc, q_x, q_v, r):
    check_oscillator(osc)
    q_x = check_real("q_x", q_x, low=0.0, unit="1/m^2")
    q_v = check_real("q_v", q_v, low=0.0, unit="s^2/m^2")
    r = check_real("r", r, low=0.0, low_open=True, unit="1/N^2")
    return q_x, q_v, r


def lqr(osc: Oscillator, q_x: float, q_v: float, *, r: float) -> LQRResult:
    """LQR gains for the oscillator driven by a force ``u`` (python-control's ``lqr``).

    Minimises ``J = int_0^inf (q_x x^2 + q_v v^2 + r u^2) dt`` over ``u = -K [x, v]``
    for ``m x'' + c x' + k x = u``. With the cost in units of 1 (per second of
    integration), the weights are in 1/m^2, s^2/m^2 and 1/N^2; only their ratios
    to ``r`` matter for ``K``.

    Parameters
    ----------
    osc : Oscillator
        Plant: m (kg), c (N s/m, any sign), k (N/m).
    q_x : float
        Weight of the displacement, 1/m^2 (>= 0).
    q_v : float
        Weight of the velocity, s^2/m^2 (>= 0).
    r : float
        Weight of the control force, 1/N^2 (> 0).

    Returns
    -------
    LQRResult
        ``K`` = [N/m, N s/m], ``P`` (2 x 2), ``poles`` (1/s), ``closed_loop`` oscillator.

    Examples
    --------
    >>> res = lqr(Oscillator(m=1.0, c=0.5, k=20.0), q_x=96.0, q_v=1.0, r=0.01)
    >>> np.round(res.K, 4)                                # N/m, N s/m
    array([80.    , 15.6323])
    >>> round(res.closed_loop.k, 10)                      # sqrt(k^2 + q_x/r), N/m
    100.0
    """
    q_x, q_v, r = _lqr_args(osc, q_x, q_v, r)
    control = optional("control", extra="control", what="vibration.control.lqr")

    a = np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]])
    b = np.array([[0.0], [1.0 / osc.m]])
    if not (math.isfinite(q_x / r) and math.isfinite(q_v / r)):
        raise ParameterError(f"r = {r!r} 1/N^2 with q_x = {q_x!r}, q_v = {q_v!r}: q/r overflows; allowed finite q/r")
    try:
        with np.errstate(all="ignore"):
            K, P, E = control.lqr(a, b, np.diag([q_x, q_v]), np.array([[r]]))
    except (ValueError, np.linalg.LinAlgError) as err:
        raise ParameterError(
            f"r = {r!r} 1/N^2, q_x = {q_x!r}, q_v = {q_v!r}: the Riccati solver failed ({err}); "
            "allowed weights whose ratios q/r the solver can resolve"
        ) from None
    if not (np.all(np.isfinite(K)) and np.all(np.isfinite(P))):
        raise ParameterError(
            f"r = {r!r} 1/N^2, q_x = {q_x!r}, q_v = {q_v!r}: the Riccati solution is not finite; "
            "allowed weights with a finite solution"
        )
    return LQRResult(
        K=np.asarray(K, dtype=float).reshape(2),
        P=np.asarray(P, dtype=float),
        poles=np.asarray(E, dtype=complex),
        plant=osc,
        q_x=q_x,
        q_v=q_v,
        r=r,
    )


def lqr_closed_form(osc: Oscillator, q_x: float, q_v: float, *, r: float) -> np.ndarray:
    """LQR gains ``[K_0 (N/m), K_1 (N s/m)]`` from the closed-form 2 x 2 Riccati solution.

    ``K_0 = sqrt(k^2 + q_x/r) - k`` and ``K_1 = sqrt(c^2 + q_v/r + 2 m K_0) - c``: the
    (1,1) and (2,2) entries of the Riccati equation are quadratics in ``P_12`` and
    ``P_22`` whose stabilising roots give these. Written with ``hypot``-style forms
    that do not cancel when ``q/r`` is small.

    Examples
    --------
    >>> np.round(lqr_closed_form(Oscillator(m=1.0, c=0.5, k=20.0), 96.0, 1.0, r=0.01), 4)
    array([80.    , 15.6323])
    """
    q_x, q_v, r = _lqr_args(osc, q_x, q_v, r)
    m, c, k = osc.m, osc.c, osc.k
    a = q_x / r
    k0 = a / (math.hypot(k, math.sqrt(a)) + k)  # sqrt(k^2 + a) - k without cancellation
    b = q_v / r + 2.0 * m * k0
    root = math.sqrt(c * c + b)
    k1 = b / (root + c) if c > 0.0 else root - c
    if not (math.isfinite(k0) and math.isfinite(k1)):
        raise ParameterError(
            f"r = {r!r} 1/N^2 with q_x = {q_x!r}, q_v = {q_v!r}: the gains overflow; allowed finite q/r"
        )
    return np.array([k0, k1])


# ----------------------------------------------------------------------------- simulation with a callable


@dataclass(frozen=True, kw_only=True)
class ControlledResponse:
    """Response of the controlled oscillator on a uniform grid."""

    t: np.ndarray  # time, s
    x: np.ndarray  # displacement of the mass (absolute), m
    v: np.ndarray  # velocity of the mass (absolute), m/s
    u: np.ndarray  # applied (limited) control force on the mass, N
    u_demand: np.ndarray  # force the controller asked for, N
    x_base: np.ndarray  # base displacement, m (zeros without base motion)
    v_base: np.ndarray  # base velocity, m/s
    nfev: int  # right-hand-side evaluations


def simulate_controlled(
    osc: Oscillator,
    controller: Callable[[float, float, float], float],
    force: SineForce | None = None,
    *,
    base: tuple[float, float] | None = None,
    u_max: float | None = None,
    t_end: float = 50.0,
    n_points: int = 5001,
    x0: float = 0.0,
    v0: float = 0.0,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    max_step: float | None = None,
) -> ControlledResponse:
    """Integrate ``m x'' + c (v - v_b) + k (x - x_b) = F(t) + sat(controller(t, x, v))``.

    The controller is any plain callable of time (s), displacement (m) and velocity (m/s)
    of the mass (absolute, also under base motion) returning the force it asks for (N);
    it must be memoryless (it is called at the solver's trial points). The actuator limit
    clips it to ``[-u_max, u_max]``. Integration: ``solve_ivp`` DOP853 at tight tolerance.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m); c and k connect the mass to the base.
    controller : callable
        ``controller(t, x, v) -> u``; s, m, m/s -> N; must return a finite real.
    force : SineForce, optional
        External force ``F0 sin(omega t)`` on the mass (N, rad/s); none by default.
    base : (float, float), optional
        Base motion ``x_b = Y sin(omega t)``: ``(Y in m, omega in rad/s)``; fixed base by default.
    u_max : float, optional
        Actuator force limit, N (> 0); unlimited by default.
    t_end : float
        End of the window, s (> 0); the run starts at t = 0.
    n_points : int
        Output samples on ``linspace(0, t_end, n_points)``.
    x0, v0 : float
        Initial displacement (m) and velocity (m/s).
    rtol, atol : float
        Solver tolerances (relative; absolute in m and m/s).
    max_step : float, optional
        Largest solver step, s (helps a discontinuous controller).

    Returns
    -------
    ControlledResponse
        ``t`` (s), ``x`` (m), ``v`` (m/s), ``u`` and ``u_demand`` (N), base motion.

    Examples
    --------
    PD control ``u = -16 x - 5.5 v`` of the paper's oscillator is the oscillator
    ``(1, 6, 36)`` (see :func:`pd_oscillator`):

    >>> from vibration import exact_response
    >>> osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)
    >>> r = simulate_controlled(osc, lambda t, x, v: -16.0 * x - 5.5 * v, force, t_end=10.0, n_points=101)
    >>> ex = exact_response(pd_oscillator(osc, 16.0, 5.5), force, r.t)
    >>> bool(np.max(np.abs(r.x - ex.x)) < 1e-9)
    True
    """
    _check_loop_parts(osc, controller, force)
    Y, wb = _base(base)
    umax = _limit(u_max)
    grid = _grid(t_end, n_points)
    x0, v0 = _initial_state(osc, x0, v0)
    rtol = check_real("rtol", rtol, low=RTOL_MIN, high=RTOL_MAX)
    atol = check_real("atol", atol, low=0.0, low_open=True)
    step = math.inf if max_step is None else check_real("max_step", max_step, low=0.0, low_open=True, unit="s")
    F0, wf = (force.F0, force.omega) if force is not None else (0.0, 0.0)
    t_end = float(grid[-1])
    _check_loop_work(osc, t_end, max(osc.natural_frequency + abs(osc.c) / osc.m, wf, wb), rtol, step)
    rhs = _controlled_rhs(osc, controller, (F0, wf), (Y, wb), umax)
    x, v, nfev = _integrate_loop(rhs, (x0, v0), grid, rtol, atol, step)
    demand = np.array([_call(controller, ti, xi, vi) for ti, xi, vi in zip(grid, x, v, strict=True)])
    return ControlledResponse(
        t=grid,
        x=x,
        v=v,
        u=np.clip(demand, -umax, umax),
        u_demand=demand,
        x_base=Y * np.sin(wb * grid),
        v_base=Y * wb * np.cos(wb * grid),
        nfev=nfev,
    )


def _check_loop_parts(osc, controller, force) -> None:
    """Refuse a plant that is not an :class:`Oscillator`, a controller that is not callable or a wrong force."""
    check_oscillator(osc)
    if not callable(controller):
        raise ParameterError(f"controller = {controller!r} is not callable: allowed a function (t, x, v) -> force in N")
    if force is not None and not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed None or SineForce(F0, omega)")


def _initial_state(osc, x0, v0) -> tuple[float, float]:
    """The checked initial displacement (m) and velocity (m/s), whose energy must be a finite float."""
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    check_derived(
        "the initial energy (m v0^2 + |k| x0^2) / 2 (J)",
        0.5 * (osc.m * v0 * v0 + abs(osc.k) * x0 * x0),
        inputs={"x0": x0, "v0": v0},
        allowed="x0 and v0 whose energy is a finite float",
    )
    return x0, v0


def _check_loop_work(osc, t_end: float, rate: float, rtol: float, step: float) -> None:
    """Refuse a run whose plant (fastest ``rate``, 1/s) or ``max_step`` (s) needs more than :data:`MAX_NFEV`."""
    _work_check(t_end, rate, rtol, "plant")
    if t_end / step > MAX_NFEV / 12:
        raise ParameterError(
            f"max_step = {step!r} s: t_end / max_step = {t_end / step:.3g} steps of 12 evaluations, "
            f"allowed at most {MAX_NFEV // 12} steps (budget {MAX_NFEV} evaluations)"
        )


def _controlled_rhs(osc, controller, force, base, umax):
    """The loop's right-hand side ``(t, [x, v]) -> (v, a)`` with ``force = (F0, omega)`` and ``base = (Y, omega)``."""
    m, c, k = osc.m, osc.c, osc.k
    F0, wf = force
    Y, wb = base
    sin, cos = math.sin, math.cos

    def rhs(t, y):
        x, v = y
        u = min(max(_call(controller, t, x, v), -umax), umax)
        xb, vb = Y * sin(wb * t), Y * wb * cos(wb * t)
        return (v, (F0 * sin(wf * t) - c * (v - vb) - k * (x - xb) + u) / m)

    return rhs


def _integrate_loop(rhs, y0, grid, rtol: float, atol: float, step: float):
    """DOP853 on ``grid`` within :data:`MAX_NFEV` evaluations: ``(x, v, nfev)``, refused unless finite."""
    from scipy.integrate import solve_ivp

    t_end = float(grid[-1])
    budget = [MAX_NFEV]
    try:
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused below
            sol = solve_ivp(
                _counted(rhs, budget), (0.0, t_end), y0, method="DOP853", t_eval=grid, rtol=rtol, atol=atol,
                max_step=step,
            )  # fmt: skip
    except OverBudget:
        raise _over_budget(math.nan, t_end, "controlled loop") from None
    if sol.status != 0:
        raise ParameterError(
            f"t_end = {t_end!r} s: the solver (DOP853) stopped at t = {sol.t[-1] if sol.t.size else 0.0:g} s "
            f"({sol.message}); "
            "allowed inputs for which the loop can be integrated"
        )
    x, v = sol.y
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        raise ParameterError(
            f"t_end = {t_end!r} s: the controlled response overflowed (an unstable loop); allowed a finite response"
        )
    return x, v, int(sol.nfev)


# ----------------------------------------------------------------------------- metrics


@dataclass(frozen=True, kw_only=True)
class Metrics:
    """Performance and cost of one controller over a window."""

    peak_x: float  # max |x| over the window, m
    rms_x: float  # RMS x over the window, m
    peak_x_ss: float  # max |x| in steady state (the measured tail), m
    rms_x_ss: float  # RMS x in steady state, m
    peak_u: float  # max |u| over the window, N
    rms_u: float  # RMS u over the window, N
    energy: float  # int |u v_rel| dt over the window, J


def _trapz(y, t) -> float:
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(t)))


def response_metrics(t, x, u, *, v_rel, t_steady: float) -> Metrics:
    """Peak and RMS displacement (window and ``t >= t_steady``), peak and RMS force, actuator energy.

    RMS values are time averages by the trapezoidal rule; the energy is ``int |u v_rel| dt``
    (J), the mechanical energy the device exchanges with the structure (an actuator that
    cannot regenerate pays all of it; a semi-active damper only dissipates it).

    Parameters
    ----------
    t : array_like
        Uniform or not, increasing times, s.
    x : array_like
        Displacement, m.
    u : array_like
        Device force on the mass, N.
    v_rel : array_like
        Velocity across the device, m/s.
    t_steady : float
        Start of the steady-state tail, s (inside the window).

    Examples
    --------
    >>> t = np.linspace(0.0, 2 * np.pi, 20001)
    >>> m = response_metrics(t, np.sin(t), 2 * np.cos(t), v_rel=np.cos(t), t_steady=np.pi)
    >>> round(m.rms_x, 6), round(m.peak_u, 6), round(m.energy, 6)
    (0.707107, 2.0, 6.283185)
    """
    t = check_array("t", t, ndim=(1,), min_size=2, increasing=True, unit="s")
    x, u, vr = (check_array(n, a, ndim=(1,), min_size=2) for n, a in (("x", x), ("u", u), ("v_rel", v_rel)))
    for name, a in (("x", x), ("u", u), ("v_rel", vr)):
        if a.shape != t.shape:
            raise ParameterError(f"{name} has shape {a.shape}: allowed the shape of t, {t.shape}")
    ts = check_real("t_steady", t_steady, low=float(t[0]), high=float(t[-2]), unit="s")
    span = t[-1] - t[0]
    tail = t >= ts
    tt = t[tail]
    with np.errstate(over="ignore", invalid="ignore"):
        out = Metrics(
            peak_x=float(np.max(np.abs(x))),
            rms_x=math.sqrt(_trapz(x * x, t) / span),
            peak_x_ss=float(np.max(np.abs(x[tail]))),
            rms_x_ss=math.sqrt(_trapz(x[tail] ** 2, tt) / (tt[-1] - tt[0])),
            peak_u=float(np.max(np.abs(u))),
            rms_u=math.sqrt(_trapz(u * u, t) / span),
            energy=_trapz(np.abs(u * vr), t),
        )
    for name in Metrics.__dataclass_fields__:
        if not math.isfinite(getattr(out, name)):
            raise ParameterError(
                f"x, u, v_rel and t give {name} = {getattr(out, name)!r}: the squares or products overflow; "
                "allowed samples whose squares and time integrals are finite"
            )
    return out
