"""Control: active (PD, PID, LQR), semi-active (skyhook, MR damper) and input shaping (Part II).

The plant is the paper's oscillator ``m x'' + c x' + k x = F(t) + u`` (SI units: kg, N s/m,
N/m; x in m, v in m/s, forces in N, t in s).

Active control (the force ``u`` is applied to the mass by an actuator)

* :func:`pd_oscillator`: ``u = -kp x - kd v`` is the oscillator ``(m, c + kd, k + kp)``;
  :func:`stabilising_velocity_gain` is the exact boundary ``kd* = -c`` of the flutter model.
* :func:`lqr`: gains of ``u = -K [x, v]`` minimising ``J = int (q_x x^2 + q_v v^2 + r u^2) dt``
  (python-control's ``lqr``); the closed loop is again an oscillator. For this plant the
  Riccati equation has the closed form ``k + K_0 = sqrt(k^2 + q_x/r)``,
  ``c + K_1 = sqrt(c^2 + q_v/r + 2 m K_0)`` (:func:`lqr_closed_form`).
* :func:`pid_response`: PID with an actuator force limit and one of three integrator
  treatments ("none", "clamping", "back-calculation").
* :func:`simulate_controlled`: any memoryless controller given as a plain callable
  ``controller(t, x, v) -> u`` (s, m, m/s -> N), with optional force limit and optional
  harmonic base motion.

Semi-active control under base excitation ``x_b = Y sin(omega t)`` (the suspension case):
the mass hangs on the spring k and passive damper c from the base, and a controllable
device adds a force ``f`` on the mass.

* :func:`skyhook_transmissibility`: the ideal skyhook, ``f = -c_sky v`` (a damper to the
  inertial frame), exact.
* :func:`semi_active_response` and :func:`semi_active_sweep`: on-off and continuous
  clipped skyhook with the device damping bounded to ``[c_min, c_max]``, and an MR damper
  (modified Bouc-Wen model, :data:`SPENCER_1997`, scaled with :meth:`MRDamper.scaled`) switched
  by the on-off skyhook condition. Integrated with fixed-step RK4 compiled by numba.

Input shaping: :func:`zv_shaper`, :func:`zvd_shaper` (impulse times in s and amplitudes
summing to 1), :func:`shaper_residual` (residual vibration ratio, closed form) and
:func:`shaped_move` (exact response to a shaped step command).

Metrics: :func:`response_metrics` (peak and RMS displacement in the window and in steady
state, peak and RMS force, energy exchanged by the actuator).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from .checks import check_array
from .exact import exact_response
from .model import N_POINTS_MAX, Oscillator, ParameterError, SineForce, check_int, check_real
from .stability import _check_osc, transmissibility

__all__ = [
    "SPENCER_1997",
    "SPENCER_1997_STROKE",
    "ControlledResponse",
    "LQRResult",
    "MRDamper",
    "Metrics",
    "PIDResponse",
    "SemiActiveResponse",
    "SemiActiveSweep",
    "Shaper",
    "lqr",
    "lqr_closed_form",
    "passive_transmissibility",
    "pd_oscillator",
    "pid_linear_response",
    "pid_response",
    "residual_amplitude",
    "response_metrics",
    "semi_active_controller",
    "semi_active_response",
    "semi_active_sweep",
    "shaped_move",
    "shaper_residual",
    "simulate_controlled",
    "skyhook_transmissibility",
    "stabilising_velocity_gain",
    "zv_shaper",
    "zvd_shaper",
]

ANTI_WINDUP = ("none", "clamping", "back-calculation")
SEMI_ACTIVE_LAWS = ("passive", "skyhook", "on-off", "clipped", "mr")


def _omegas(omegas, name: str = "omegas") -> np.ndarray:
    return check_array(name, omegas, low=0.0, ndim=(0, 1), unit="rad/s")


def _finite(name: str, value, what: str):
    """Refuse a non-finite result: an overflow is an error, never a silent nan or inf."""
    arr = np.asarray(value)
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} = {value!r}: {what} is not finite (overflow); allowed inputs that keep it finite")
    return value


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
    >>> cl = pd_oscillator(Oscillator(1.0, 0.5, 20.0), kp=16.0, kd=5.5)
    >>> cl.c, cl.k, round(cl.damping_ratio, 3)      # N s/m, N/m, 1
    (6.0, 36.0, 0.5)
    """
    _check_osc(osc)
    kp = check_real("kp", kp, low=-osc.k, low_open=True, unit="N/m")
    kd = check_real("kd", kd, unit="N s/m")
    return Oscillator(osc.m, osc.c + kd, osc.k + kp)


def stabilising_velocity_gain(osc: Oscillator) -> float:
    """Boundary velocity gain of ``u = -kd v``: the loop is stable exactly when ``kd > -c``, N s/m.

    With negative damping (flutter's linear model, ``c < 0``) the smallest stabilising gain
    is the infimum ``-c = |c|``: at ``kd = -c`` the poles sit on the imaginary axis
    (``+- i omega_n``), any larger gain makes both real parts ``-(c + kd)/(2 m) < 0``.
    A position gain ``kp > -k`` changes neither the boundary nor its exactness.

    Examples
    --------
    >>> stabilising_velocity_gain(Oscillator(1.0, -0.5, 20.0))     # N s/m
    0.5
    """
    _check_osc(osc)
    return -osc.c + 0.0


@dataclass(frozen=True)
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
    _check_osc(osc)
    q_x = check_real("q_x", q_x, low=0.0, unit="1/m^2")
    q_v = check_real("q_v", q_v, low=0.0, unit="s^2/m^2")
    r = check_real("r", r, low=0.0, low_open=True, unit="1/N^2")
    return q_x, q_v, r


def lqr(osc: Oscillator, q_x: float, q_v: float, r: float) -> LQRResult:
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
    >>> res = lqr(Oscillator(1.0, 0.5, 20.0), q_x=96.0, q_v=1.0, r=0.01)
    >>> np.round(res.K, 4)                                # N/m, N s/m
    array([80.    , 15.6323])
    >>> round(res.closed_loop.k, 10)                      # sqrt(k^2 + q_x/r), N/m
    100.0
    """
    q_x, q_v, r = _lqr_args(osc, q_x, q_v, r)
    import control

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


def lqr_closed_form(osc: Oscillator, q_x: float, q_v: float, r: float) -> np.ndarray:
    """LQR gains ``[K_0 (N/m), K_1 (N s/m)]`` from the closed-form 2 x 2 Riccati solution.

    ``K_0 = sqrt(k^2 + q_x/r) - k`` and ``K_1 = sqrt(c^2 + q_v/r + 2 m K_0) - c``: the
    (1,1) and (2,2) entries of the Riccati equation are quadratics in ``P_12`` and
    ``P_22`` whose stabilising roots give these. Written with ``hypot``-style forms
    that do not cancel when ``q/r`` is small.

    Examples
    --------
    >>> np.round(lqr_closed_form(Oscillator(1.0, 0.5, 20.0), 96.0, 1.0, 0.01), 4)
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


@dataclass(frozen=True)
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


def _limit(u_max) -> float:
    if u_max is None:
        return math.inf
    if isinstance(u_max, float) and u_max == math.inf:
        return math.inf
    return check_real("u_max", u_max, low=0.0, low_open=True, unit="N")


def _base(base) -> tuple[float, float]:
    if base is None:
        return 0.0, 0.0
    try:
        Y, w = base
    except (TypeError, ValueError):
        raise ParameterError(f"base = {base!r}: allowed None or (Y in m, omega in rad/s)") from None
    return check_real("Y", Y, low=0.0, unit="m"), check_real("omega", w, low=0.0, unit="rad/s")


def _grid(t_end, n_points) -> np.ndarray:
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    return np.linspace(0.0, t_end, n_points)


def _call(controller, t: float, x: float, v: float) -> float:
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # a non-finite force is refused below
        u = controller(t, x, v)
    try:
        val = float(u)
    except (TypeError, ValueError):
        raise ParameterError(f"controller returned {u!r} at t = {t!r} s: allowed a finite real force in N") from None
    if not math.isfinite(val):
        raise ParameterError(f"controller returned {val!r} at t = {t!r} s: allowed a finite real force in N")
    return val


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
    >>> osc, force = Oscillator(1.0, 0.5, 20.0), SineForce(5.0, 4.47)
    >>> r = simulate_controlled(osc, lambda t, x, v: -16.0 * x - 5.5 * v, force, t_end=10.0, n_points=101)
    >>> ex = exact_response(pd_oscillator(osc, 16.0, 5.5), force, r.t)
    >>> bool(np.max(np.abs(r.x - ex.x)) < 1e-9)
    True
    """
    from scipy.integrate import solve_ivp

    _check_osc(osc)
    if not callable(controller):
        raise ParameterError(f"controller = {controller!r} is not callable: allowed a function (t, x, v) -> force in N")
    if force is not None and not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed None or SineForce(F0, omega)")
    Y, wb = _base(base)
    umax = _limit(u_max)
    grid = _grid(t_end, n_points)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    rtol = check_real("rtol", rtol, low=RTOL_MIN, high=RTOL_MAX)
    atol = check_real("atol", atol, low=0.0, low_open=True)
    step = math.inf if max_step is None else check_real("max_step", max_step, low=0.0, low_open=True, unit="s")
    m, c, k = osc.m, osc.c, osc.k
    F0, wf = (force.F0, force.omega) if force is not None else (0.0, 0.0)
    t_end = float(grid[-1])
    _work_check(t_end, max(osc.natural_frequency + abs(c) / m, wf, wb), rtol, "plant")
    if t_end / step > MAX_NFEV / 12:
        raise ParameterError(
            f"max_step = {step!r} s: t_end / max_step = {t_end / step:.3g} steps of 12 evaluations, "
            f"allowed at most {MAX_NFEV // 12} steps (budget {MAX_NFEV} evaluations)"
        )
    sin, cos = math.sin, math.cos

    def rhs(t, y):
        x, v = y
        u = min(max(_call(controller, t, x, v), -umax), umax)
        xb, vb = Y * sin(wb * t), Y * wb * cos(wb * t)
        return (v, (F0 * sin(wf * t) - c * (v - vb) - k * (x - xb) + u) / m)

    budget = [MAX_NFEV]
    try:
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused below
            sol = solve_ivp(
                _counted(rhs, budget), (0.0, t_end), (x0, v0), method="DOP853", t_eval=grid, rtol=rtol, atol=atol,
                max_step=step,
            )  # fmt: skip
    except _OverBudget:
        raise _over_budget(math.nan, t_end, "controlled loop") from None
    if sol.status != 0:
        raise ParameterError(
            f"t_end = {t_end!r} s: the solver (DOP853) stopped at t = {sol.t[-1]:g} s ({sol.message}); "
            "allowed inputs for which the loop can be integrated"
        )
    x, v = sol.y
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        raise ParameterError(
            f"t_end = {t_end!r} s: the controlled response overflowed (an unstable loop); allowed a finite response"
        )
    demand = np.array([_call(controller, ti, xi, vi) for ti, xi, vi in zip(grid, x, v, strict=True)])
    return ControlledResponse(
        t=grid,
        x=x,
        v=v,
        u=np.clip(demand, -umax, umax),
        u_demand=demand,
        x_base=Y * np.sin(wb * grid),
        v_base=Y * wb * np.cos(wb * grid),
        nfev=int(sol.nfev),
    )


# ----------------------------------------------------------------------------- PID with a force limit

#: Right-hand-side evaluations one adaptive (DOP853) run may use, about 5 s of Python work.
MAX_NFEV = 250_000

#: Smooth pieces (between switching events) one run of :func:`pid_response` may have.
MAX_SEGMENTS = 20_000

#: Allowed relative tolerances of the adaptive solver (below 100 eps it warns and fails).
RTOL_MIN, RTOL_MAX = 1e-13, 1e-2

#: Samples :func:`pid_linear_response` evaluates with one matrix exponential each (repeated poles).
EXPM_SAMPLES_MAX = 20_000


class _OverBudget(Exception):
    """Raised from a counting right-hand side when the run exceeds its evaluation budget."""


def _counted(f, budget: list):
    """Wrap ``f`` so that every call spends one unit of ``budget[0]``; :class:`_OverBudget` when spent."""

    def g(t, y):
        budget[0] -= 1
        if budget[0] < 0:
            raise _OverBudget
        return f(t, y)

    return g


def _work_check(t_end: float, rate: float, rtol: float, what: str) -> None:
    """Refuse up front a window that spans too many of the loop's fastest time scales for DOP853."""
    # DOP853 at rtol 1e-10 needs about 100 evaluations per unit of t * rate on these loops (measured)
    est = 100.0 * t_end * rate * (1e-10 / rtol) ** 0.125
    if not est <= MAX_NFEV:
        raise ParameterError(
            f"t_end = {t_end!r} s spans {t_end * rate:.3g} time scales of the {what} (fastest rate {rate:.3g} 1/s): "
            f"about {est:.3g} right-hand-side evaluations, allowed at most {MAX_NFEV} "
            f"(t_end * rate <= {MAX_NFEV / 100.0 / (1e-10 / rtol) ** 0.125:.3g}); shorten t_end or soften the loop"
        )


def _over_budget(t: float, t_end: float, what: str) -> ParameterError:
    at = f" after t = {t:.6g} s" if math.isfinite(t) else ""
    return ParameterError(
        f"t_end = {t_end!r} s: the {what} used up its budget of {MAX_NFEV} right-hand-side evaluations{at} "
        f"(a stiff loop, a discontinuous controller or a tolerance too tight); allowed at most {MAX_NFEV} "
        "evaluations: shorten t_end or loosen rtol"
    )


def _pid_run(p: dict, grid: np.ndarray, rtol: float, atol: float, t_end: float) -> tuple[np.ndarray, int]:
    """Integrate the limited PID loop piece by piece between its switching events (DOP853 on each piece).

    The pieces: ``L`` (linear, ``|u_d| < u_max``), ``S`` (saturated at ``s u_max``, ``s = +-1``;
    with clamping the integrator is frozen while ``s e > 0``) and, with clamping, the sliding
    mode ``Z`` on ``u_d = s u_max``: there the linear side pushes ``u_d`` into the limit and
    the frozen side pulls it back, so the state sticks on the surface; Filippov's solution keeps
    ``u_d = s u_max`` with the integrator rate ``I' = (kp v + kd a) / ki``. Each piece is smooth, so
    DOP853 keeps its order; the pieces end at located events. Returns the states ``(3, n)`` on the
    grid and the number of right-hand-side evaluations.
    """
    from scipy.integrate import solve_ivp

    m, c, k, F0, wf = p["m"], p["c"], p["k"], p["F0"], p["wf"]
    kp, ki, kd, umax, xr, mode, gbc = p["kp"], p["ki"], p["kd"], p["umax"], p["x_ref"], p["mode"], p["gain_bc"]
    sin = math.sin

    def acc(t, x, v, u):
        return (F0 * sin(wf * t) - c * v - k * x + u) / m

    def ud_of(x, v, i):
        return kp * (xr - x) + ki * i - kd * v

    def rhs_lin(t, y):
        x, v, i = y
        e = xr - x
        return (v, acc(t, x, v, kp * e + ki * i - kd * v), e)

    def make_sat(s, frozen):
        u = s * umax

        def rhs(t, y):
            x, v, i = y
            e = xr - x
            if frozen:
                di = 0.0
            elif mode == 2:
                di = e + (u - (kp * e + ki * i - kd * v)) * gbc
            else:
                di = e
            return (v, acc(t, x, v, u), di)

        return rhs

    def make_slide(s):
        u = s * umax

        def rhs(t, y):
            x, v, _ = y
            a = acc(t, x, v, u)
            return (v, a, (kp * v + kd * a) / ki)

        return rhs

    def ev(f, direction):
        f.terminal, f.direction = True, direction
        return f

    def events(kind, s, frozen):
        if kind == "L":
            return [
                ev(lambda t, y: ud_of(*y) - umax, 1.0),
                ev(lambda t, y: ud_of(*y) + umax, -1.0),
            ]
        if kind == "S":
            out = [ev(lambda t, y: s * ud_of(*y) - umax, -1.0)]
            if mode == 1:  # the integrator law switches where e changes sign
                out.append(ev(lambda t, y: xr - y[0], -s if frozen else s))
            return out

        def d_rate(t, y):  # rate of u_d with the integrator frozen, on the surface
            return -kp * y[1] - kd * acc(t, y[0], y[1], s * umax)

        return [
            ev(lambda t, y: s * d_rate(t, y), 1.0),  # the frozen side no longer pulls back: into S
            ev(lambda t, y: s * (d_rate(t, y) + ki * (xr - y[0])), -1.0),  # the linear side no longer pushes: into L
        ]

    def classify(t, y):
        x, v, i = y
        e = xr - x
        ud = ud_of(x, v, i)
        tol = 1e-9 * (umax + abs(kp * e) + abs(ki * i) + abs(kd * v))
        for s in (1.0, -1.0):
            gap = s * ud - umax
            se = s * e if abs(e) > 1e-12 * (abs(xr) + abs(x)) else -s * v
            if gap > tol:
                return "S", s, mode == 1 and se > 0.0
            if gap >= -tol:  # on the surface u_d = s u_max: the rates decide
                d = -kp * v - kd * acc(t, x, v, s * umax)
                r_lin = d + ki * e
                if mode == 1 and se > 0.0:
                    if s * r_lin <= 0.0:
                        return "L", s, False
                    return ("S", s, True) if s * d > 0.0 else ("Z", s, False)
                return ("S", s, False) if s * r_lin > 0.0 else ("L", s, False)
        return "L", 1.0, False

    n = grid.size
    out = np.empty((3, n))
    filled, t0, y0 = 0, 0.0, np.zeros(3)
    budget = [MAX_NFEV]
    segments = 0
    what = "PID loop"
    nxt = None
    while True:
        if not math.isfinite(umax):
            kind, s, frozen = "L", 1.0, False
        else:
            kind, s, frozen = nxt if nxt is not None else classify(t0, y0)
        if kind == "Z":  # put the state exactly on the surface
            y0 = y0.copy()
            y0[2] = (s * umax - kp * (xr - y0[0]) + kd * y0[1]) / ki
        f = rhs_lin if kind == "L" else make_sat(s, frozen) if kind == "S" else make_slide(s)
        evs = events(kind, s, frozen) if math.isfinite(umax) else None
        segments += 1
        if segments > MAX_SEGMENTS:
            raise ParameterError(
                f"u_max = {umax!r} N: the limited PID loop switched more than {MAX_SEGMENTS} times by t = {t0:.6g} s "
                "(chattering against the limit); allowed at most that many pieces: shorten t_end"
            )
        try:
            with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused below
                sol = solve_ivp(
                    _counted(f, budget), (t0, t_end), y0, method="DOP853", t_eval=grid[filled:], rtol=rtol,
                    atol=atol, events=evs,
                )  # fmt: skip
        except _OverBudget:
            raise _over_budget(t0, t_end, what) from None
        if sol.status < 0:  # an overflow makes DOP853 fail
            break
        m_new = len(sol.t)  # a list (empty) when the piece ends before the next sample
        if m_new:
            ys = sol.y
            if kind == "Z":
                ys = ys.copy()
                ys[2] = (s * umax - kp * (xr - ys[0]) + kd * ys[1]) / ki
            out[:, filled : filled + m_new] = ys
            filled += m_new
        if sol.status == 0 or filled >= n:
            break
        hit = next(j for j, te in enumerate(sol.t_events) if te.size)
        t0, y0 = float(sol.t_events[hit][0]), np.array(sol.y_events[hit][0], dtype=float)
        nxt = None
        if kind == "Z":  # leaving the sliding mode: to the frozen side or to the linear side
            nxt = ("S", s, True) if hit == 0 else ("L", s, False)
        elif kind == "S" and hit == 1:  # e changed sign: the integrator law switches
            nxt = ("S", s, not frozen)
    if not np.all(np.isfinite(out[:, :filled])) or filled < n:
        raise ParameterError(
            f"t_end = {t_end!r} s: the PID loop's response overflowed (an unstable loop grows beyond floating point); "
            "allowed inputs that keep it finite"
        )
    return out, MAX_NFEV - budget[0]


@dataclass(frozen=True)
class PIDResponse:
    """PID loop response: ``u = sat(kp e + ki I - kd v)``, ``e = x_ref - x``, ``I' = e`` (+ anti-windup)."""

    t: np.ndarray  # time, s
    x: np.ndarray  # displacement, m
    v: np.ndarray  # velocity, m/s
    integral: np.ndarray  # integrator state I = int e dt (with anti-windup), m s
    u: np.ndarray  # applied force, N
    u_demand: np.ndarray  # unlimited PID output, N
    anti_windup: str  # "none", "clamping" or "back-calculation"
    u_max: float  # force limit, N (inf: none)
    nfev: int  # right-hand-side evaluations

    @property
    def saturated_fraction(self) -> float:
        """Fraction of the samples at which the actuator is at its limit, 1."""
        return float(np.mean(np.abs(self.u_demand) > self.u_max))


def pid_response(
    osc: Oscillator,
    force: SineForce | None,
    kp: float,
    ki: float,
    kd: float,
    *,
    u_max: float | None = None,
    anti_windup: str = "none",
    t_track: float | None = None,
    x_ref: float = 0.0,
    t_end: float = 50.0,
    n_points: int = 5001,
    rtol: float = 1e-10,
    atol: float = 1e-12,
) -> PIDResponse:
    """PID position control with an actuator force limit, integrated with DOP853.

    ``u_d = kp e + ki I - kd v`` with ``e = x_ref - x`` (derivative on the measurement, so
    a set-point step gives no derivative kick), ``u = clip(u_d, -u_max, u_max)``, and the
    integrator ``I`` (m s) follows

    * ``"none"``: ``I' = e`` (winds up while the actuator is saturated);
    * ``"clamping"`` (conditional integration): ``I' = 0`` while saturated and ``e``
      pushes further into the limit, else ``e``;
    * ``"back-calculation"``: ``I' = e + (u - u_d) / (ki t_track)`` with tracking time
      ``t_track`` (default ``sqrt(kd / ki)``, the geometric mean of the integral and
      derivative times: Astrom and Hagglund, Advanced PID Control, 2006, sec. 3.5).

    Parameters
    ----------
    osc : Oscillator
        Plant: m (kg), c (N s/m), k (N/m).
    force : SineForce or None
        Disturbance force on the mass (N, rad/s).
    kp, ki, kd : float
        Gains: N/m, N/(m s) (> 0), N s/m.
    u_max : float, optional
        Actuator limit, N (> 0); none by default.
    anti_windup : str
        One of ``"none"``, ``"clamping"``, ``"back-calculation"``.
    t_track : float, optional
        Tracking time constant of back-calculation, s (> 0).
    x_ref : float
        Set point from t = 0 on, m (the mass starts at rest at x = 0).
    t_end, n_points : float, int
        Window (s) and uniform samples.
    rtol, atol : float
        Solver tolerances.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> r = pid_response(osc, None, 80.0, 100.0, 10.0, x_ref=0.1, t_end=20.0, n_points=201)
    >>> round(float(r.x[-1]), 6)                        # m: integral action removes the offset
    0.1
    """
    _check_osc(osc)
    if force is not None and not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed None or SineForce(F0, omega)")
    kp = check_real("kp", kp, low=-osc.k, low_open=True, unit="N/m")
    ki = check_real("ki", ki, low=0.0, low_open=True, unit="N/(m s)")
    kd = check_real("kd", kd, unit="N s/m")
    umax = _limit(u_max)
    if anti_windup not in ANTI_WINDUP:
        raise ParameterError(f"anti_windup = {anti_windup!r} is not supported: allowed one of {', '.join(ANTI_WINDUP)}")
    if t_track is None:
        tt = math.sqrt(abs(kd)) / math.sqrt(ki) if kd != 0.0 else 1.0 / math.sqrt(ki)
    else:
        tt = check_real("t_track", t_track, low=0.0, low_open=True, unit="s")
    if not (tt > 0.0 and math.isfinite(1.0 / (ki * tt))):
        raise ParameterError(
            f"t_track = {tt!r} s with ki = {ki!r} N/(m s): the back-calculation gain 1/(ki t_track) is not finite; "
            "allowed ki t_track > 0 and finite"
        )
    x_ref = check_real("x_ref", x_ref, unit="m")
    grid = _grid(t_end, n_points)
    rtol = check_real("rtol", rtol, low=RTOL_MIN, high=RTOL_MAX)
    atol = check_real("atol", atol, low=0.0, low_open=True)
    F0, wf = (force.F0, force.omega) if force is not None else (0.0, 0.0)
    mode = ANTI_WINDUP.index(anti_windup)
    p = dict(m=osc.m, c=osc.c, k=osc.k, F0=F0, wf=wf, kp=kp, ki=ki, kd=kd, umax=umax, x_ref=x_ref, mode=mode,
             gain_bc=1.0 / (ki * tt))  # fmt: skip
    with np.errstate(over="ignore", invalid="ignore"):
        A = np.array([[0.0, 1.0, 0.0], [-(osc.k + kp) / osc.m, -(osc.c + kd) / osc.m, ki / osc.m], [-1.0, 0.0, 0.0]])
    if not np.all(np.isfinite(A)):
        raise ParameterError(
            f"kp = {kp!r}, ki = {ki!r}, kd = {kd!r} over m = {osc.m!r} kg overflow: allowed finite gains/m"
        )
    rate = max(float(np.max(np.abs(np.linalg.eigvals(A)))), osc.natural_frequency + abs(osc.c) / osc.m, wf)
    _work_check(float(grid[-1]), rate, rtol, "PID loop")
    y, nfev = _pid_run(p, grid, rtol, atol, float(grid[-1]))
    x, v, integ = y
    with np.errstate(over="ignore", invalid="ignore"):
        ud = kp * (x_ref - x) + ki * integ - kd * v
    if not np.all(np.isfinite(ud)):
        raise ParameterError(
            f"x_ref = {x_ref!r} m, kp = {kp!r}, ki = {ki!r}, kd = {kd!r}: the PID demand overflows; "
            "allowed inputs that keep it finite"
        )
    return PIDResponse(
        t=grid,
        x=x,
        v=v,
        integral=integ,
        u=np.clip(ud, -umax, umax),
        u_demand=ud,
        anti_windup=anti_windup,
        u_max=umax,
        nfev=int(nfev),
    )


def pid_linear_response(osc: Oscillator, force: SineForce | None, kp: float, ki: float, kd: float, t, x_ref=0.0):
    """Exact response of the unlimited PID loop (matrix exponential plus particular solution).

    The loop ``y = [x, v, I]``, ``y' = A y + b_F F0 sin(omega t) + b_r x_ref`` is linear; its
    solution is ``y_p(t) + expm(A t) (y(0) - y_p(0))`` with the particular solution
    ``y_p = Im(H e^{i omega t}) - A^{-1} b_r x_ref``, ``H = (i omega I - A)^{-1} b_F F0``.
    Returns ``(x, v, I)`` at the times ``t`` (s): m, m/s, m s. Used to check
    :func:`pid_response`.

    Examples
    --------
    >>> x, v, i = pid_linear_response(Oscillator(1.0, 0.5, 20.0), None, 80.0, 100.0, 10.0, [0.0, 60.0], 0.1)
    >>> np.round(x, 9)
    array([0. , 0.1])
    """
    from scipy.linalg import expm

    _check_osc(osc)
    if force is not None and not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed None or SineForce(F0, omega)")
    kp = check_real("kp", kp, low=-osc.k, low_open=True, unit="N/m")
    ki = check_real("ki", ki, low=0.0, low_open=True, unit="N/(m s)")
    kd = check_real("kd", kd, unit="N s/m")
    x_ref = check_real("x_ref", x_ref, unit="m")
    t = np.atleast_1d(check_array("t", t, low=0.0, unit="s"))
    m, c, k = osc.m, osc.c, osc.k
    A = np.array([[0.0, 1.0, 0.0], [-(k + kp) / m, -(c + kd) / m, ki / m], [-1.0, 0.0, 0.0]])
    if not np.all(np.isfinite(A)):
        raise ParameterError(
            f"kp = {kp!r}, ki = {ki!r}, kd = {kd!r} over m = {m!r} kg overflow: allowed finite gains/m"
        )
    bF = np.array([0.0, 1.0 / m, 0.0])
    br = np.array([0.0, kp / m, 1.0])
    F0, w = (force.F0, force.omega) if force is not None else (0.0, 0.0)
    with np.errstate(all="ignore"):  # an overflow is refused below
        try:
            H = np.linalg.solve(1j * w * np.eye(3) - A, bF * F0)
            ystat = -np.linalg.solve(A, br * x_ref)
        except np.linalg.LinAlgError:
            raise ParameterError(
                f"force.omega = {w!r} rad/s is a pole of the loop (kp = {kp!r}, ki = {ki!r}, kd = {kd!r}): "
                "no steady state; allowed a forcing frequency off the loop's undamped poles"
            ) from None
        yp = np.imag(H[:, None] * np.exp(1j * w * t)[None, :]) + ystat[:, None]
        d0 = -(np.imag(H) + ystat)  # y(0) - y_p(0), y(0) = 0
        lam, V = np.linalg.eig(A)
        try:
            coef = np.linalg.solve(V, d0)
        except np.linalg.LinAlgError:  # exactly defective: the expm fallback below handles it
            coef = np.zeros(3)
        with np.errstate(over="ignore", invalid="ignore"):
            free = np.real(V @ (coef[:, None] * np.exp(lam[:, None] * t[None, :])))
        if np.linalg.cond(V) > 1e8:  # defective or nearly so: fall back on expm per sample
            if t.size > EXPM_SAMPLES_MAX:
                raise ParameterError(
                    f"t has {t.size} samples: this loop (kp = {kp!r}, ki = {ki!r}, kd = {kd!r}) has a (nearly) "
                    f"repeated pole, so each sample needs its own matrix exponential; "
                    f"allowed at most {EXPM_SAMPLES_MAX} samples"
                )
            with np.errstate(over="ignore", invalid="ignore"):
                free = np.stack([expm(A * ti) @ d0 for ti in t], axis=1)
        y = yp + free
    if not np.all(np.isfinite(y)):
        raise ParameterError(
            f"t reaches {float(t.max())!r} s: the loop's response overflows there (an unstable loop, poles "
            f"{[f'{z:.6g}' for z in lam]} 1/s); allowed times at which it stays finite"
        )
    return y[0], y[1], y[2]


# ----------------------------------------------------------------------------- semi-active


def passive_transmissibility(osc: Oscillator, omegas) -> np.ndarray:
    """Base-excitation transmissibility ``|X/Y| = |k + i c w| / |k - m w^2 + i c w|``, 1.

    The absolute displacement of the mass over the base amplitude, in steady state:
    :func:`vibration.physics.stability.transmissibility`, for a scalar or 1-D ``omegas``,
    always as an array.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> float(passive_transmissibility(osc, np.sqrt(40.0)).round(12))   # at sqrt(2) omega_n: 1
    1.0
    """
    _check_osc(osc)
    return np.asarray(transmissibility(osc, _omegas(omegas)))


def skyhook_transmissibility(osc: Oscillator, c_sky: float, omegas) -> np.ndarray:
    """Ideal-skyhook transmissibility ``|X/Y| = |k + i c w| / |k - m w^2 + i (c + c_sky) w|``, 1.

    The passive spring k and damper c connect the mass to the base ``Y sin(w t)``; the
    skyhook damper ``c_sky`` connects it to the inertial frame (force ``-c_sky v``).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, passive damper to the base), k (N/m).
    c_sky : float
        Skyhook damping, N s/m (>= 0).
    omegas : array_like
        Base frequencies, rad/s (>= 0).

    Returns
    -------
    numpy.ndarray
        Transmissibility, 1, same shape as ``omegas``.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> w = osc.natural_frequency
    >>> round(float(skyhook_transmissibility(osc, 8.0, w)), 4)          # at resonance
    0.5294
    >>> round(float(skyhook_transmissibility(osc, 0.0, w)), 4)          # passive: sqrt(1 + (k/(c w))^2)
    9.0
    """
    _check_osc(osc)
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    w = _omegas(omegas)
    # divided through by w^2 above 1 rad/s, so that no product overflows
    s = 1.0 / np.maximum(w, 1.0)
    m, c, k, cc = osc.m, osc.c, osc.k, osc.c + c_sky
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        num = np.hypot(k * s * s, c * w * s * s)
        den = np.hypot(k * s * s - m * (w * s) * (w * s), cc * w * s * s)
        out = num / den
    if not np.all(np.isfinite(out)):
        bad = float(np.asarray(w)[~np.isfinite(out)].ravel()[0])
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: the transmissibility is not finite there (undamped resonance or "
            "overflow); allowed frequencies with a finite steady state"
        )
    return out


@dataclass(frozen=True)
class MRDamper:
    """Modified Bouc-Wen model of an MR damper (Spencer, Dyke, Sain and Carlson 1997), SI units.

    ``F = c1 y' + k1 x``, ``y' = (alpha z + c0 x' + k0 (x - y)) / (c0 + c1)``,
    ``z' = -gamma |x' - y'| z |z|^(n-1) - beta (x' - y') |z|^n + A (x' - y')``, with
    ``alpha = alpha_a + alpha_b u``, ``c0 = c0a + c0b u``, ``c1 = c1a + c1b u`` and the
    coil filter ``u' = -eta (u - V)`` on the commanded voltage ``V`` in ``[0, v_max]``.
    ``x`` is the piston displacement (relative to the base), ``F`` the force it resists with.
    The accumulator preload ``k1 x0`` of the original is left out: a constant force only
    shifts the static equilibrium.
    """

    c0a: float  # viscous damping at large velocity, 0 V, N s/m
    c0b: float  # its voltage slope, N s/(m V)
    k0: float  # stiffness at large velocity, N/m
    c1a: float  # viscous damping at low velocity (roll-off), 0 V, N s/m
    c1b: float  # its voltage slope, N s/(m V)
    k1: float  # accumulator stiffness, N/m
    alpha_a: float  # evolutionary coefficient, 0 V, N/m
    alpha_b: float  # its voltage slope, N/(m V)
    gamma: float  # Bouc-Wen shape, 1/m^2 (for n = 2)
    beta: float  # Bouc-Wen shape, 1/m^2 (for n = 2)
    A: float  # Bouc-Wen scale, 1
    n: float  # Bouc-Wen exponent, 1
    eta: float  # coil (first-order filter) rate, 1/s
    v_max: float  # largest command voltage, V

    def __post_init__(self) -> None:
        for name in ("c0a", "c0b", "k0", "c1a", "c1b", "k1", "alpha_a", "alpha_b", "gamma", "beta", "A"):
            object.__setattr__(self, name, check_real(name, getattr(self, name), low=0.0))
        object.__setattr__(self, "c1a", check_real("c1a", self.c1a, low=0.0, low_open=True, unit="N s/m"))
        object.__setattr__(self, "n", check_real("n", self.n, low=1.0, high=4.0))
        object.__setattr__(self, "eta", check_real("eta", self.eta, low=0.0, low_open=True, unit="1/s"))
        object.__setattr__(self, "v_max", check_real("v_max", self.v_max, low=0.0, unit="V"))

    @property
    def z_max(self) -> float:
        """Largest evolutionary displacement ``(A / (gamma + beta))^(1/n)``, m."""
        return (self.A / (self.gamma + self.beta)) ** (1.0 / self.n)

    @property
    def yield_force(self) -> float:
        """Hysteretic force ``alpha z_max`` at full voltage, N."""
        return (self.alpha_a + self.alpha_b * self.v_max) * self.z_max

    def scaled(self, length: float, force: float) -> MRDamper:
        """Similitude copy: displacements times ``length``, forces times ``force``, time unchanged.

        Stiffnesses and damping coefficients scale by ``force / length``, ``gamma`` and
        ``beta`` (for n = 2) by ``1 / length^n``, ``A``, ``n``, ``eta`` and the voltage are unchanged, so
        the scaled device run at ``length`` times the stroke gives exactly ``force`` times
        the force history.

        Examples
        --------
        >>> d = SPENCER_1997.scaled(length=2.0, force=0.5)
        >>> round(d.yield_force / SPENCER_1997.yield_force, 12), round(d.z_max / SPENCER_1997.z_max, 12)
        (0.5, 2.0)
        """
        length = check_real("length", length, low=0.0, low_open=True)
        force = check_real("force", force, low=0.0, low_open=True)
        s, g = force / length, length ** (-self.n)
        return replace(
            self,
            c0a=self.c0a * s,
            c0b=self.c0b * s,
            k0=self.k0 * s,
            c1a=self.c1a * s,
            c1b=self.c1b * s,
            k1=self.k1 * s,
            alpha_a=self.alpha_a * s,
            alpha_b=self.alpha_b * s,
            gamma=self.gamma * g,
            beta=self.beta * g,
        )


#: Spencer, Dyke, Sain and Carlson (1997), "Phenomenological model for magnetorheological
#: dampers", J. Eng. Mech. 123(3):230-238, parameters of the modified Bouc-Wen model
#: identified for their prototype damper (about 3000 N capacity, tested at 1.5 cm and
#: 2.5 Hz, 0-2.25 V): c0a 21.0 N s/cm, c0b 3.50 N s/(cm V), k0 46.9 N/cm, c1a 283 N s/cm,
#: c1b 2.95 N s/(cm V), k1 5.00 N/cm, x0 14.3 cm (preload, not used), alpha_a 140 N/cm,
#: alpha_b 695 N/(cm V), gamma = beta = 363 cm^-2, A 301, n 2, eta 190 1/s; here in SI.
SPENCER_1997 = MRDamper(
    c0a=21.0e2,
    c0b=3.50e2,
    k0=46.9e2,
    c1a=283.0e2,
    c1b=2.95e2,
    k1=5.00e2,
    alpha_a=140.0e2,
    alpha_b=695.0e2,
    gamma=363.0e4,
    beta=363.0e4,
    A=301.0,
    n=2.0,
    eta=190.0,
    v_max=2.25,
)

#: Displacement amplitude of the tests the parameters were identified on, m (1.5 cm).
SPENCER_1997_STROKE = 0.015


def _sa_params(osc, law, c_sky, c_min, c_max, damper):
    if law not in SEMI_ACTIVE_LAWS:
        raise ParameterError(f"law = {law!r} is not supported: allowed one of {', '.join(SEMI_ACTIVE_LAWS)}")
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    c_min = check_real("c_min", c_min, low=0.0, unit="N s/m")
    c_max = check_real("c_max", c_max, low=c_min, unit="N s/m")
    d = damper if damper is not None else SPENCER_1997
    if not isinstance(d, MRDamper):
        raise ParameterError(f"damper = {damper!r} is not an MRDamper: allowed None or MRDamper(...)")
    p = np.array(
        [
            osc.m, osc.c, osc.k, c_sky, c_min, c_max,
            d.c0a, d.c0b, d.k0, d.c1a, d.c1b, d.k1, d.alpha_a, d.alpha_b, d.gamma, d.beta, d.A, d.n, d.eta, d.v_max,
        ]
    )  # fmt: skip
    return SEMI_ACTIVE_LAWS.index(law), p


# The kernels are plain module-level functions compiled on first use by _sa_kernel (numba is imported
# lazily). They refer to each other through the module globals below, not through closures: numba's
# on-disk cache keys a closure by its pickled free variables, which differ in every process, so nested
# kernels were recompiled (several seconds) by every new process.
#: Largest number of fixed RK4 steps of one semi-active run (about 8 s at 400 ns a step).
RK4_STEPS_MAX = 20_000_000

#: Largest total number of RK4 steps of one sweep (parallel over the frequencies: about 20 s on two cores).
SWEEP_STEPS_MAX = 100_000_000

_KERNEL = None
_nb_device = _nb_rhs = _nb_run = None
_prange = range


def _sa_device(law, p, xb, vb, s):  # pragma: no cover - compiled
    """Force of the device on the mass (N), state derivatives of the MR internals, command."""
    c_sky, c_min, c_max = p[3], p[4], p[5]
    x, v = s[0], s[1]
    vr = v - vb
    dz = dy = du = 0.0
    cmd = 0.0
    if law == 0:  # passive at c_min
        f = -c_min * vr
    elif law == 1:  # ideal skyhook
        f = -c_sky * v
    elif law == 2:  # on-off skyhook
        if v * vr > 0.0:
            f = -c_max * vr
            cmd = 1.0
        else:
            f = -c_min * vr
    elif law == 3:  # continuous clipped skyhook
        if v * vr > 0.0:
            a = min(max(c_sky * abs(v), c_min * abs(vr)), c_max * abs(vr))
            f = -a if vr > 0.0 else a
            cmd = 1.0
        else:
            f = -c_min * vr
    else:  # MR damper, modified Bouc-Wen, clipped-optimal voltage
        xr = x - xb
        z, y, u = s[2], s[3], s[4]
        c0 = p[6] + p[7] * u
        k0 = p[8]
        c1 = p[9] + p[10] * u
        k1 = p[11]
        alpha = p[12] + p[13] * u
        gam, bet, A, n, eta, vmax = p[14], p[15], p[16], p[17], p[18], p[19]
        dy = (alpha * z + c0 * vr + k0 * (xr - y)) / (c0 + c1)
        d = vr - dy
        az = abs(z)
        if n == 2.0:
            dz = -gam * abs(d) * z * az - bet * d * az * az + A * d
        else:
            dz = -gam * abs(d) * z * az ** (n - 1.0) - bet * d * az**n + A * d
        f = -(c1 * dy + k1 * xr)
        if v * vr > 0.0:
            cmd = 1.0
        du = -eta * (u - cmd * vmax)
    return f, dz, dy, du, cmd


def _sa_rhs(law, p, xb, vb, s, out):  # pragma: no cover - compiled
    m, c, k = p[0], p[1], p[2]
    f, dz, dy, du, cmd = _nb_device(law, p, xb, vb, s)
    out[0] = s[1]
    out[1] = (-k * (s[0] - xb) - c * (s[1] - vb) + f) / m
    out[2] = dz
    out[3] = dy
    out[4] = du
    return f, cmd


def _sa_run(law, p, Y, w, s0, dt, n_steps, stride, m_start):  # pragma: no cover - compiled
    """RK4 from state s0 for n_steps of dt; record every stride steps; measure from step m_start.

    Returns (record (n_rec, 5): t, x, v, f, cmd; stats: sum x cos, sum x sin, max|x|,
    sum f^2, max|f|, switches, samples, sum |f vr| dt).
    """
    s = s0.copy()
    k1 = np.empty(5)
    k2 = np.empty(5)
    k3 = np.empty(5)
    k4 = np.empty(5)
    tmp = np.empty(5)
    n_rec = n_steps // stride + 1
    rec = np.empty((n_rec, 5))
    stats = np.zeros(8)
    prev = -1.0
    yw = Y * w
    for i in range(n_steps + 1):
        t = i * dt
        sn, cs = math.sin(w * t), math.cos(w * t)
        f, cmd = _nb_rhs(law, p, Y * sn, yw * cs, s, k1)
        if i % stride == 0:
            j = i // stride
            rec[j, 0] = t
            rec[j, 1] = s[0]
            rec[j, 2] = s[1]
            rec[j, 3] = f
            rec[j, 4] = s[4] if law == 4 else cmd
        if i >= m_start and i < n_steps:  # left-point sums over whole periods (exact for trig polynomials)
            x = s[0]
            stats[0] += x * cs
            stats[1] += x * sn
            stats[2] = max(stats[2], abs(x))
            stats[3] += f * f
            stats[4] = max(stats[4], abs(f))
            if prev >= 0.0 and cmd != prev:
                stats[5] += 1.0
            prev = cmd
            stats[6] += 1.0
            stats[7] += abs(f * (s[1] - yw * cs)) * dt
        if i == n_steps:
            break
        for q in range(5):
            tmp[q] = s[q] + 0.5 * dt * k1[q]
        sh, ch = math.sin(w * (t + 0.5 * dt)), math.cos(w * (t + 0.5 * dt))
        _nb_rhs(law, p, Y * sh, yw * ch, tmp, k2)
        for q in range(5):
            tmp[q] = s[q] + 0.5 * dt * k2[q]
        _nb_rhs(law, p, Y * sh, yw * ch, tmp, k3)
        for q in range(5):
            tmp[q] = s[q] + dt * k3[q]
        t1 = (i + 1) * dt
        _nb_rhs(law, p, Y * math.sin(w * t1), yw * math.cos(w * t1), tmp, k4)
        for q in range(5):
            s[q] += dt / 6.0 * (k1[q] + 2.0 * k2[q] + 2.0 * k3[q] + k4[q])
    return rec, stats


def _sa_sweep(law, p, Y, ws, s0s, dts, n_steps, n_settle):  # pragma: no cover - compiled
    out = np.empty((ws.size, 8))
    for j in _prange(ws.size):
        _, st = _nb_run(law, p, Y, ws[j], s0s[j], dts[j], n_steps[j], n_steps[j], n_settle[j])
        out[j] = st
    return out


def _sa_kernel():
    """Compile (once per process, cached on disk) the fixed-step RK4 of the semi-active loop."""
    global _KERNEL, _nb_device, _nb_rhs, _nb_run, _prange
    if _KERNEL is not None:
        return _KERNEL
    import numba

    _prange = numba.prange
    _nb_device = numba.njit(cache=True)(_sa_device)
    _nb_rhs = numba.njit(cache=True)(_sa_rhs)
    _nb_run = numba.njit(cache=True)(_sa_run)
    _KERNEL = (_nb_run, numba.njit(cache=True, parallel=True)(_sa_sweep))
    return _KERNEL


@dataclass(frozen=True)
class SemiActiveResponse:
    """Time response of the base-excited oscillator with a controllable device."""

    t: np.ndarray  # time, s
    x: np.ndarray  # absolute displacement of the mass, m
    v: np.ndarray  # absolute velocity of the mass, m/s
    x_base: np.ndarray  # base displacement, m
    v_base: np.ndarray  # base velocity, m/s
    f: np.ndarray  # force of the device on the mass, N
    command: np.ndarray  # 1 when the law asks for more than c_min (MR: coil voltage, V)
    law: str  # the control law
    dt: float  # RK4 step, s


def _sa_rate_check(p: np.ndarray, dt: float, w: float, spp: int) -> None:
    """Refuse an RK4 step longer than the plant's fastest time scale (RK4 would be inaccurate or diverge)."""
    m, c, k, c_sky, c_max = p[0], p[1], p[2], p[3], p[5]
    rate = math.sqrt(k / m) + (abs(c) + max(c_sky, c_max)) / m
    if not dt * rate <= 1.0:
        raise ParameterError(
            f"omega = {w!r} rad/s with steps_per_period = {spp}: the RK4 step {dt:.3g} s is {dt * rate:.3g} times the "
            f"plant's fastest time scale 1/{rate:.3g} s; allowed at most 1 (raise the frequency or steps_per_period)"
        )


def _sa_step(law_i: int, w: float, steps_per_period: int, dt_max: float) -> tuple[float, int]:
    """RK4 step (s) and steps per forcing period: ``steps_per_period`` or more, below ``dt_max``."""
    period = 2.0 * math.pi / w
    if law_i == 4 and not period / dt_max <= RK4_STEPS_MAX:
        raise ParameterError(
            f"omega = {w!r} rad/s with dt_max = {dt_max!r} s: {period / dt_max:.3g} RK4 steps per period, "
            f"allowed at most {RK4_STEPS_MAX}"
        )
    n = max(steps_per_period, math.ceil(period / dt_max)) if law_i == 4 else steps_per_period
    return period / n, n


def semi_active_response(
    osc: Oscillator,
    law: str,
    omega: float,
    Y: float,
    *,
    c_sky: float = 0.0,
    c_min: float = 0.0,
    c_max: float = 0.0,
    damper: MRDamper | None = None,
    t_end: float = 50.0,
    n_points: int = 5001,
    steps_per_period: int = 2000,
    dt_max: float = 2e-4,
) -> SemiActiveResponse:
    """Base-excited response from rest with a controllable device, fixed-step RK4 (numba).

    ``m x'' + c (x' - x_b') + k (x - x_b) = f``, ``x_b = Y sin(omega t)``, with the device force
    ``f`` on the mass given by ``law``:

    * ``"passive"``: a damper at ``c_min``, ``f = -c_min (v - v_b)``;
    * ``"skyhook"``: ideal, ``f = -c_sky v`` (needs an active actuator);
    * ``"on-off"``: damper at ``c_max`` when ``v (v - v_b) > 0`` (the skyhook force is
      dissipative), else ``c_min``;
    * ``"clipped"``: damper coefficient ``c_sky v / (v - v_b)`` clipped to ``[c_min, c_max]``
      when ``v (v - v_b) > 0``, else ``c_min`` (continuous clipped skyhook);
    * ``"mr"``: the MR damper ``damper`` (modified Bouc-Wen) switched by the on-off
      skyhook condition: full voltage ``v_max`` when ``v (v - v_b) > 0``, else 0 V (the
      coil filter smooths the step). Dyke et al.'s clipped-optimal rule
      ``(f_sky - f) f > 0`` chatters at the integration step here, so it is not used.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (passive damper to the base, N s/m), k (N/m).
    law : str
        One of ``"passive"``, ``"skyhook"``, ``"on-off"``, ``"clipped"``, ``"mr"``.
    omega : float
        Base frequency, rad/s (> 0).
    Y : float
        Base amplitude, m (>= 0).
    c_sky : float
        Skyhook gain, N s/m (>= 0).
    c_min, c_max : float
        Bounds of the device damping, N s/m (0 <= c_min <= c_max).
    damper : MRDamper, optional
        For ``law="mr"``; :data:`SPENCER_1997` unscaled by default.
    t_end : float
        End of the window, s (> 0).
    n_points : int
        Output samples (nearest RK4 steps; the grid is uniform).
    steps_per_period : int
        RK4 steps per forcing period (100 to 100000).
    dt_max : float
        Largest RK4 step for the stiff MR model, s.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> r = semi_active_response(osc, "clipped", 4.47, 0.25, c_sky=8.0, c_min=0.5, c_max=15.0, t_end=10.0, n_points=11)
    >>> r.t.shape, r.law
    ((11,), 'clipped')
    """
    _check_osc(osc)
    law_i, p = _sa_params(osc, law, c_sky, c_min, c_max, damper)
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    Y = check_real("Y", Y, low=0.0, unit="m")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    spp = check_int("steps_per_period", steps_per_period, low=100, high=100_000)
    dt_max = check_real("dt_max", dt_max, low=0.0, low_open=True, unit="s")
    dt, _ = _sa_step(law_i, w, spp, dt_max)
    _sa_rate_check(p, dt, w, spp)
    if not t_end / dt <= RK4_STEPS_MAX:
        raise ParameterError(
            f"t_end = {t_end!r} s needs {t_end / dt:.3g} RK4 steps of {dt:.3g} s: allowed at most {RK4_STEPS_MAX} "
            "(shorten t_end or lower steps_per_period)"
        )
    n_steps = max(1, math.ceil(t_end / dt))
    stride = max(1, n_steps // (n_points - 1))
    n_steps = stride * (n_points - 1)
    dt = t_end / n_steps
    if n_steps > RK4_STEPS_MAX:
        raise ParameterError(
            f"t_end = {t_end!r} s needs {n_steps} RK4 steps of {dt:.3g} s: allowed at most {RK4_STEPS_MAX} "
            "(shorten t_end or lower steps_per_period)"
        )
    rec, _ = _sa_kernel()[0](law_i, p, Y, w, np.zeros(5), dt, n_steps, stride, n_steps + 1)
    if not np.all(np.isfinite(rec)):
        raise ParameterError(
            f"dt_max = {dt_max!r} s, steps_per_period = {spp}: the RK4 run overflowed (step {dt:.3g} s too long "
            "for the device or the plant); allowed a smaller step"
        )
    t = rec[:, 0]
    return SemiActiveResponse(
        t=t,
        x=rec[:, 1],
        v=rec[:, 2],
        x_base=Y * np.sin(w * t),
        v_base=Y * w * np.cos(w * t),
        f=rec[:, 3],
        command=rec[:, 4],
        law=law,
        dt=dt,
    )


@dataclass(frozen=True)
class SemiActiveSweep:
    """Steady-state measures of a semi-active law across base frequencies."""

    omegas: np.ndarray  # base frequencies, rad/s
    peak: np.ndarray  # max |x| / Y over the measured periods, 1
    fundamental: np.ndarray  # amplitude of the fundamental harmonic of x over Y, 1
    force_rms: np.ndarray  # RMS device force, N
    force_peak: np.ndarray  # peak device force, N
    switches: np.ndarray  # command changes per period, 1
    power: np.ndarray  # mean |f (v - v_b)|, W (mechanical power handled by the device)
    law: str  # the control law


def semi_active_sweep(
    osc: Oscillator,
    law: str,
    omegas,
    Y: float,
    *,
    c_sky: float = 0.0,
    c_min: float = 0.0,
    c_max: float = 0.0,
    damper: MRDamper | None = None,
    settle: float = 12.0,
    periods: int = 8,
    steps_per_period: int = 1000,
    dt_max: float = 2e-4,
) -> SemiActiveSweep:
    """Steady-state transmissibility of a semi-active law at each base frequency (numba RK4).

    Each frequency starts in the steady state of the ideal skyhook (or of the passive
    damper ``c + c_min`` for ``law="passive"``), runs ``settle / sigma`` seconds with
    ``sigma = (c + c_min) / (2 m)`` the slowest decay any law allows (so the start is
    forgotten by a factor ``exp(-settle)``), rounded up to whole periods, then measures
    over ``periods`` whole periods: peak ``|x| / Y``, the fundamental harmonic of ``x``
    over ``Y`` (left-point sums over whole periods, exact for trigonometric polynomials
    of low degree), RMS and peak device force, command switches per period and mean
    mechanical power.

    Parameters are those of :func:`semi_active_response`; ``omegas`` in rad/s (> 0),
    ``settle`` (1 to 50) in decay time constants, ``periods`` (1 to 1000).

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> s = semi_active_sweep(osc, "skyhook", [4.4721], 0.25, c_sky=8.0, periods=2)
    >>> bool(abs(s.fundamental[0] - skyhook_transmissibility(osc, 8.0, 4.4721)) < 1e-6)
    True
    """
    _check_osc(osc)
    law_i, p = _sa_params(osc, law, c_sky, c_min, c_max, damper)
    w_arr = _omegas(omegas)
    if np.any(w_arr <= 0):
        raise ParameterError(f"omegas contains {float(w_arr[w_arr <= 0][0])!r}: allowed frequencies > 0 rad/s")
    Y = check_real("Y", Y, low=0.0, low_open=True, unit="m")
    settle = check_real("settle", settle, low=1.0, high=50.0)
    periods = check_int("periods", periods, low=1, high=1000)
    spp = check_int("steps_per_period", steps_per_period, low=100, high=100_000)
    dt_max = check_real("dt_max", dt_max, low=0.0, low_open=True, unit="s")
    sigma = (osc.c + c_min) / (2.0 * osc.m)
    if sigma <= 0.0:
        raise ParameterError(
            f"c + c_min = {osc.c + c_min!r} N s/m: allowed > 0 (a steady state needs some damping in every state)"
        )
    ws = w_arr.ravel()
    c_start = osc.c + (c_min if law_i == 0 else 0.0)
    sky = c_sky if law_i != 0 else 0.0
    dts, n_steps, n_settle = np.empty(ws.size), np.empty(ws.size, np.int64), np.empty(ws.size, np.int64)
    s0s = np.zeros((ws.size, 5))
    for j, w in enumerate(ws.tolist()):  # Python floats: an overflow gives inf (checked below), not a warning
        if not math.isfinite(2.0 * math.pi / w):
            raise ParameterError(f"omegas contains {w!r} rad/s: its period overflows; allowed a finite period")
        dts[j], n_per = _sa_step(law_i, w, spp, dt_max)
        _sa_rate_check(p, dts[j], w, spp)
        settle_periods = settle / sigma / (2.0 * math.pi / w)
        if not (settle_periods + periods) * n_per <= RK4_STEPS_MAX:
            raise ParameterError(
                f"omegas contains {w!r} rad/s: settling {settle!r} time constants of {1.0 / sigma:.3g} s "
                f"(c + c_min = {osc.c + c_min!r} N s/m) takes {settle_periods:.3g} periods of {n_per} RK4 steps: "
                f"allowed at most {RK4_STEPS_MAX} steps"
            )
        n_settle[j] = math.ceil(settle_periods) * n_per
        n_steps[j] = n_settle[j] + periods * n_per
        if n_steps[j] > RK4_STEPS_MAX:
            raise ParameterError(
                f"omegas contains {w!r} rad/s: it needs {n_steps[j]} RK4 steps (settle = {settle!r} time constants "
                f"of {1.0 / sigma:.3g} s plus {periods} periods), allowed at most {RK4_STEPS_MAX}"
            )
        # start in the steady state of the linear loop (c_start to the base, sky to the frame)
        h = (osc.k + 1j * osc.c * w) / (osc.k - osc.m * w * w + 1j * (c_start + sky) * w) * Y
        s0s[j, :2] = h.imag, w * h.real
    if n_steps.sum() > SWEEP_STEPS_MAX:
        raise ParameterError(
            f"omegas has {ws.size} frequencies needing {int(n_steps.sum())} RK4 steps in all: "
            f"allowed at most {SWEEP_STEPS_MAX} (fewer frequencies, periods or steps_per_period)"
        )
    st = _sa_kernel()[1](law_i, p, Y, ws, s0s, dts, n_steps, n_settle)
    if not np.all(np.isfinite(st)):
        bad = ws[~np.all(np.isfinite(st), axis=1)][0]
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: the RK4 run overflowed (step {dts[ws == bad][0]:.3g} s too long for "
            f"the device; allowed a smaller dt_max = {dt_max!r} s or more steps_per_period = {spp})"
        )
    n, span = st[:, 6], periods * 2.0 * np.pi / ws
    out = np.stack(
        [
            st[:, 2] / Y,
            2.0 * np.hypot(st[:, 0], st[:, 1]) / n / Y,
            np.sqrt(st[:, 3] / n),
            st[:, 4],
            st[:, 5] / periods,
            st[:, 7] / span,
        ]
    )
    shape = w_arr.shape
    return SemiActiveSweep(
        omegas=w_arr,
        peak=out[0].reshape(shape),
        fundamental=out[1].reshape(shape),
        force_rms=out[2].reshape(shape),
        force_peak=out[3].reshape(shape),
        switches=out[4].reshape(shape),
        power=out[5].reshape(shape),
        law=law,
    )


def semi_active_controller(
    law: str, c_sky: float, c_min: float, c_max: float, Y: float, omega: float
) -> Callable[[float, float, float], float]:
    """The skyhook laws as a plain callable ``controller(t, x, v) -> f`` (s, m, m/s -> N).

    For :func:`simulate_controlled` with ``base=(Y, omega)``; ``law`` is one of
    ``"passive"``, ``"skyhook"``, ``"on-off"``, ``"clipped"`` (the MR damper has an
    internal state, so it is not memoryless). Same laws as :func:`semi_active_response`.

    Examples
    --------
    >>> f = semi_active_controller("on-off", 8.0, 0.5, 15.0, 0.25, 4.47)
    >>> round(f(0.0, 0.0, 1.0), 12)     # N: v (v - v_b) = 1 (1 - 1.1175) < 0, so c_min
    0.05875
    """
    if law not in SEMI_ACTIVE_LAWS[:4]:
        raise ParameterError(f"law = {law!r} is not supported: allowed one of {', '.join(SEMI_ACTIVE_LAWS[:4])}")
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    c_min = check_real("c_min", c_min, low=0.0, unit="N s/m")
    c_max = check_real("c_max", c_max, low=c_min, unit="N s/m")
    Y = check_real("Y", Y, low=0.0, unit="m")
    w = check_real("omega", omega, low=0.0, unit="rad/s")
    if not math.isfinite(max(c_max, c_sky, 1.0) * Y * max(w, 1.0)):
        raise ParameterError(
            f"Y = {Y!r} m, omega = {w!r} rad/s: the base velocity times the damping overflows; allowed a finite force"
        )

    def controller(t: float, x: float, v: float) -> float:
        vr = v - Y * w * math.cos(w * t)
        if law == "passive":
            return -c_min * vr
        if law == "skyhook":
            return -c_sky * v
        if v * vr > 0.0:
            if law == "on-off":
                return -c_max * vr
            a = min(max(c_sky * abs(v), c_min * abs(vr)), c_max * abs(vr))
            return -a if vr > 0.0 else a
        return -c_min * vr

    return controller


# ----------------------------------------------------------------------------- input shaping


@dataclass(frozen=True)
class Shaper:
    """Input shaper: impulses of ``amplitudes`` (summing to 1) at ``times`` (s)."""

    times: np.ndarray  # impulse times, s (first 0)
    amplitudes: np.ndarray  # impulse amplitudes, 1 (sum 1)
    omega_n: float  # design natural frequency, rad/s
    zeta: float  # design damping ratio, 1
    kind: str  # "ZV" or "ZVD"

    @property
    def duration(self) -> float:
        """Time of the last impulse (the delay the shaper adds to a move), s."""
        return float(self.times[-1])


def _underdamped(osc) -> tuple[float, float, float]:
    _check_osc(osc)
    zeta = osc.damping_ratio
    if not 0.0 <= zeta < 1.0:
        raise ParameterError(
            f"osc.c = {osc.c!r} N s/m gives zeta = {zeta!r}: allowed an underdamped oscillator, 0 <= zeta < 1"
        )
    return zeta, osc.natural_frequency, osc.damped_natural_frequency


def zv_shaper(osc: Oscillator) -> Shaper:
    """Zero-vibration shaper: ``[1, K] / (1 + K)`` at ``[0, T_d / 2]``, ``K = exp(-zeta pi / sqrt(1 - zeta^2))``.

    Singer and Seering (1990), J. Dyn. Syst. Meas. Control 112:76-82. ``T_d = 2 pi / omega_d`` (s).

    Examples
    --------
    >>> s = zv_shaper(Oscillator(1.0, 0.0, 4.0 * np.pi**2))       # 1 Hz, undamped
    >>> s.times, s.amplitudes
    (array([0. , 0.5]), array([0.5, 0.5]))
    """
    zeta, wn, wd = _underdamped(osc)
    K = math.exp(-zeta * math.pi / math.sqrt(1.0 - zeta * zeta))
    return Shaper(np.array([0.0, math.pi / wd]), np.array([1.0, K]) / (1.0 + K), wn, zeta, "ZV")


def zvd_shaper(osc: Oscillator) -> Shaper:
    """Zero-vibration-derivative shaper: ``[1, 2K, K^2] / (1 + K)^2`` at ``[0, T_d/2, T_d]``.

    Singer and Seering (1990). Zero residual vibration and zero slope against frequency
    error at the design point, at the cost of twice the ZV delay.

    Examples
    --------
    >>> s = zvd_shaper(Oscillator(1.0, 0.0, 4.0 * np.pi**2))
    >>> s.times, s.amplitudes
    (array([0. , 0.5, 1. ]), array([0.25, 0.5 , 0.25]))
    """
    zeta, wn, wd = _underdamped(osc)
    K = math.exp(-zeta * math.pi / math.sqrt(1.0 - zeta * zeta))
    amps = np.array([1.0, 2.0 * K, K * K]) / (1.0 + K) ** 2
    return Shaper(np.array([0.0, math.pi / wd, 2.0 * math.pi / wd]), amps, wn, zeta, "ZVD")


def _check_shaper(shaper) -> Shaper:
    if shaper is not None and not isinstance(shaper, Shaper):
        raise ParameterError(f"shaper = {shaper!r} is not a Shaper: allowed None, zv_shaper(osc) or zvd_shaper(osc)")
    if shaper is not None:
        times = check_array("shaper.times", shaper.times, low=0.0, ndim=(1,), max_size=100, unit="s")
        amps = check_array("shaper.amplitudes", shaper.amplitudes, ndim=(1,), max_size=100)
        if times.shape != amps.shape:
            raise ParameterError(f"shaper has {times.size} times and {amps.size} amplitudes: allowed as many of each")
    return shaper


def shaper_residual(shaper: Shaper | None, osc: Oscillator) -> float:
    """Residual vibration of a shaped step over that of the unshaped step, on the oscillator ``osc``, 1.

    ``V = exp(-sigma t_N) sqrt(C^2 + S^2)`` with ``C = sum A_i exp(sigma t_i) cos(omega_d t_i)``,
    ``S`` the same with ``sin`` (Singer and Seering 1990): the ringing just after the last
    impulse over the ringing of the plain step just after its impulse. 1 without shaper, 0 when the
    shaper was designed for ``osc``. ``osc`` may differ from the design oscillator
    (sensitivity to modelling error); it must be underdamped.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> shaper_residual(zv_shaper(osc), osc) < 1e-15
    True
    >>> round(shaper_residual(zv_shaper(osc), Oscillator(1.0, 0.5, 20.0 * 1.1**2)), 4)    # 10 % frequency error
    0.1431
    """
    _check_shaper(shaper)
    zeta, wn, wd = _underdamped(osc)
    if shaper is None:
        return 1.0
    sigma = zeta * wn
    tn = shaper.times[-1]
    e = shaper.amplitudes * np.exp(-sigma * (tn - shaper.times))
    return float(math.hypot(np.sum(e * np.cos(wd * shaper.times)), np.sum(e * np.sin(wd * shaper.times))))


def _step_response(osc: Oscillator, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Response (m, m/s) to a unit-displacement step command ``F = k H(t)`` from rest: ``1 + free(-1, 0)``."""
    free = exact_response(osc, SineForce(0.0, 0.0), t, x0=-1.0, v0=0.0)
    return 1.0 + free.x, free.v


def shaped_move(
    osc: Oscillator, shaper: Shaper | None, distance: float, t_end: float = 10.0, n_points: int = 2001
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Exact point-to-point move: force command ``k D sum A_i H(t - t_i)`` from rest.

    The command moves the static equilibrium from 0 to ``D``; unshaped it is one step. The
    response is the superposition of exact step responses (``exact_response`` free
    response), so it is exact to rounding for every regime.

    Parameters
    ----------
    osc : Oscillator
        The real oscillator, m (kg), c (N s/m), k (N/m).
    shaper : Shaper or None
        Shaper (designed on any model) or None for the plain step.
    distance : float
        Move distance D, m.
    t_end, n_points : float, int
        Window (s) and samples.

    Returns
    -------
    (t, x, v, command)
        s, m, m/s and the command force, N.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.5, 20.0)
    >>> t, x, v, u = shaped_move(osc, zv_shaper(osc), 0.1, t_end=20.0, n_points=3)
    >>> np.round(x, 6)                                     # m
    array([0. , 0.1, 0.1])
    """
    _check_osc(osc)
    _check_shaper(shaper)
    D = check_real("distance", distance, unit="m")
    t = _grid(t_end, n_points)
    times, amps = (np.array([0.0]), np.array([1.0])) if shaper is None else (shaper.times, shaper.amplitudes)
    x = np.zeros_like(t)
    v = np.zeros_like(t)
    u = np.zeros_like(t)
    for ti, ai in zip(times, amps, strict=True):
        on = t >= ti
        xs, vs = _step_response(osc, t[on] - ti)
        x[on] += ai * D * xs
        v[on] += ai * D * vs
        u[on] += ai * D * osc.k
    for name, a in (("x", x), ("v", v), ("command", u)):
        if not np.all(np.isfinite(a)):
            raise ParameterError(f"distance = {D!r} m: the move's {name} overflows; allowed a smaller distance")
    return t, x, v, u


def residual_amplitude(osc: Oscillator, t, x, v, target: float) -> np.ndarray:
    """Amplitude of the ringing about ``target`` (m) at each sample, m: ``|(x - D) + i (v + sigma (x - D)) / omega_d|``.

    For a free underdamped oscillation this is its envelope ``a exp(-sigma t)``.

    Examples
    --------
    >>> osc = Oscillator(1.0, 0.0, 4.0)
    >>> float(residual_amplitude(osc, 0.0, 1.0, 2.0, 0.0)[0])     # sqrt(1 + (2/2)^2)
    1.4142135623730951
    """
    zeta, wn, wd = _underdamped(osc)
    sigma = zeta * wn
    target = check_real("target", target, unit="m")
    tt = np.atleast_1d(check_array("t", t, unit="s"))
    xx = np.atleast_1d(check_array("x", x, unit="m"))
    vv = np.atleast_1d(check_array("v", v, unit="m/s"))
    if not tt.shape == xx.shape == vv.shape:
        raise ParameterError(f"t, x, v have shapes {tt.shape}, {xx.shape}, {vv.shape}: allowed one and the same shape")
    d = xx - target
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.hypot(d, (vv + sigma * d) / wd)
    return _finite("x, v", out, "the ringing amplitude")


# ----------------------------------------------------------------------------- metrics


@dataclass(frozen=True)
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


def response_metrics(t, x, u, v_rel, t_steady: float) -> Metrics:
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
    >>> m = response_metrics(t, np.sin(t), 2 * np.cos(t), np.cos(t), np.pi)
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
