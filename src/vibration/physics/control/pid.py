"""PID position control with an actuator limit and three integrator treatments, integrated piecewise
between switching events (with the sliding mode of clamping), and the exact unlimited loop."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import OverBudget, check_array, check_oscillator
from ..model import Oscillator, ParameterError, SineForce, check_real
from ._common import (
    EXPM_SAMPLES_MAX,
    MAX_NFEV,
    MAX_SEGMENTS,
    RTOL_MAX,
    RTOL_MIN,
    _counted,
    _grid,
    _limit,
    _over_budget,
    _work_check,
)

ANTI_WINDUP = ("none", "clamping", "back-calculation")


def _event(f, direction: float):
    """Make ``f`` a terminal event of ``solve_ivp`` that fires on a zero crossing in ``direction``."""
    f.terminal, f.direction = True, direction
    return f


@dataclass(frozen=True, slots=True, kw_only=True)
class _PIDLoop:
    """The limited PID loop of :func:`_pid_run` (the parameters of :func:`_pid_parameters`) and its pieces.

    The pieces: ``L`` (linear, ``|u_d| < u_max``), ``S`` (saturated at ``s u_max``, ``s = +-1``;
    with clamping the integrator is frozen while ``s e > 0``) and, with clamping, the sliding
    mode ``Z`` on ``u_d = s u_max``: there the linear side pushes ``u_d`` into the limit and
    the frozen side pulls it back, so the state sticks on the surface; Filippov's solution keeps
    ``u_d = s u_max`` with the integrator rate ``I' = (kp v + kd a) / ki``. A piece is named by
    ``(kind, s, frozen)``; each is smooth, and ends at one of its located events.
    """

    m: float  # plant: kg, N s/m, N/m
    c: float
    k: float
    F0: float  # disturbance F0 sin(wf t): N, rad/s
    wf: float
    kp: float  # gains: N/m, N/(m s), N s/m
    ki: float
    kd: float
    umax: float  # force limit, N (inf: none)
    x_ref: float  # set point, m
    mode: int  # index of the integrator treatment in ANTI_WINDUP
    gain_bc: float  # back-calculation gain 1 / (ki t_track), 1/(N s)

    def _acc(self, t, x, v, u):
        """The mass's acceleration under the force ``u`` (N), m/s^2."""
        return (self.F0 * math.sin(self.wf * t) - self.c * v - self.k * x + u) / self.m

    def ud(self, x, v, i):
        """The unlimited PID output ``u_d``, N."""
        return self.kp * (self.x_ref - x) + self.ki * i - self.kd * v

    def d_rate(self, t, y, s):
        """The rate of ``u_d`` with the integrator frozen, on the surface ``u_d = s u_max``, N/s."""
        return -self.kp * y[1] - self.kd * self._acc(t, y[0], y[1], s * self.umax)

    def on_surface(self, s, x, v):
        """The integrator state that puts ``(x, v)`` exactly on the surface ``u_d = s u_max``, m s."""
        return (s * self.umax - self.kp * (self.x_ref - x) + self.kd * v) / self.ki

    def rhs_lin(self, t, y):
        """Right-hand side of the linear piece ``L``."""
        x, v, i = y
        e = self.x_ref - x
        return (v, self._acc(t, x, v, self.kp * e + self.ki * i - self.kd * v), e)

    def rhs(self, kind, s, frozen):
        """The right-hand side of the piece ``(kind, s, frozen)``."""
        if kind == "L":
            return self.rhs_lin
        u = s * self.umax
        acc = self._acc
        if kind == "Z":

            def slide(t, y):
                x, v, _ = y
                a = acc(t, x, v, u)
                return (v, a, (self.kp * v + self.kd * a) / self.ki)

            return slide
        xr, kp, ki, kd, mode, gbc = self.x_ref, self.kp, self.ki, self.kd, self.mode, self.gain_bc

        def sat(t, y):
            x, v, i = y
            e = xr - x
            if frozen:
                di = 0.0
            elif mode == 2:
                di = e + (u - (kp * e + ki * i - kd * v)) * gbc
            else:
                di = e
            return (v, acc(t, x, v, u), di)

        return sat

    def events(self, kind, s, frozen):
        """The terminal events that end the piece ``(kind, s, frozen)``."""
        umax, ud, xr = self.umax, self.ud, self.x_ref
        if kind == "L":
            return [
                _event(lambda t, y: ud(*y) - umax, 1.0),
                _event(lambda t, y: ud(*y) + umax, -1.0),
            ]
        if kind == "S":
            out = [_event(lambda t, y: s * ud(*y) - umax, -1.0)]
            if self.mode == 1:  # the integrator law switches where e changes sign
                out.append(_event(lambda t, y: xr - y[0], -s if frozen else s))
            return out
        d_rate, ki = self.d_rate, self.ki
        return [  # Z ends where the frozen side no longer pulls back (into S) or the linear side no longer pushes (L)
            _event(lambda t, y: s * d_rate(t, y, s), 1.0),
            _event(lambda t, y: s * (d_rate(t, y, s) + ki * (xr - y[0])), -1.0),
        ]

    def classify(self, t, y):
        """The piece ``(kind, s, frozen)`` the state ``y`` at ``t`` starts in."""
        xr, kp, ki, kd, umax, mode = self.x_ref, self.kp, self.ki, self.kd, self.umax, self.mode
        x, v, i = y
        e = xr - x
        ud = self.ud(x, v, i)
        tol = 1e-9 * (umax + abs(kp * e) + abs(ki * i) + abs(kd * v))
        for s in (1.0, -1.0):
            gap = s * ud - umax
            se = s * e if abs(e) > 1e-12 * (abs(xr) + abs(x)) else -s * v
            if gap > tol:
                return "S", s, mode == 1 and se > 0.0
            if gap >= -tol:  # on the surface u_d = s u_max: the rates decide
                d = -kp * v - kd * self._acc(t, x, v, s * umax)
                r_lin = d + ki * e
                if mode == 1 and se > 0.0:
                    if s * r_lin <= 0.0:
                        return "L", s, False
                    return ("S", s, True) if s * d > 0.0 else ("Z", s, False)
                return ("S", s, False) if s * r_lin > 0.0 else ("L", s, False)
        return "L", 1.0, False


def _pid_piece(loop: _PIDLoop, piece: tuple, t0: float, y0: np.ndarray, t_end: float, t_eval: np.ndarray,
               tols: tuple[float, float], budget: list):  # fmt: skip
    """DOP853 on one piece from ``(t0, y0)``, up to its first event, its evaluations spent from ``budget``."""
    from scipy.integrate import solve_ivp

    f = loop.rhs(*piece)
    evs = loop.events(*piece) if math.isfinite(loop.umax) else None
    try:
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused by the caller
            return solve_ivp(
                _counted(f, budget), (t0, t_end), y0, method="DOP853", t_eval=t_eval, rtol=tols[0], atol=tols[1],
                events=evs,
            )  # fmt: skip
    except OverBudget:
        raise _over_budget(t0, t_end, "PID loop") from None


def _after_event(sol, piece: tuple) -> tuple[float, np.ndarray, tuple | None]:
    """Time and state of the event that ended ``piece``, and the next piece when the event decides it."""
    kind, s, frozen = piece
    hit = next(j for j, te in enumerate(sol.t_events) if te.size)
    t0, y0 = float(sol.t_events[hit][0]), np.array(sol.y_events[hit][0], dtype=float)
    nxt = None
    if kind == "Z":  # leaving the sliding mode: to the frozen side or to the linear side
        nxt = ("S", s, True) if hit == 0 else ("L", s, False)
    elif kind == "S" and hit == 1:  # e changed sign: the integrator law switches
        nxt = ("S", s, not frozen)
    return t0, y0, nxt  # nxt None: classify the state


def _pid_run(p: dict, grid: np.ndarray, rtol: float, atol: float, t_end: float) -> tuple[np.ndarray, int]:
    """Integrate the limited PID loop piece by piece between its switching events (DOP853 on each piece).

    The pieces are those of :class:`_PIDLoop`; each is smooth, so DOP853 keeps its order. Returns the
    states ``(3, n)`` on the grid and the number of right-hand-side evaluations.
    """
    loop = _PIDLoop(**p)
    umax = loop.umax
    n = grid.size
    out = np.empty((3, n))
    filled, t0, y0 = 0, 0.0, np.zeros(3)
    budget = [MAX_NFEV]
    segments = 0
    nxt = None
    while True:
        if not math.isfinite(umax):
            piece = ("L", 1.0, False)
        else:
            piece = nxt if nxt is not None else loop.classify(t0, y0)
        kind, s, _ = piece
        if kind == "Z":  # put the state exactly on the surface
            y0 = y0.copy()
            y0[2] = loop.on_surface(s, y0[0], y0[1])
        segments += 1
        if segments > MAX_SEGMENTS:
            raise ParameterError(
                f"u_max = {umax!r} N: the limited PID loop switched more than {MAX_SEGMENTS} times by t = {t0:.6g} s "
                "(chattering against the limit); allowed at most that many pieces: shorten t_end"
            )
        sol = _pid_piece(loop, piece, t0, y0, t_end, grid[filled:], (rtol, atol), budget)
        if sol.status < 0:  # an overflow makes DOP853 fail
            break
        m_new = len(sol.t)  # a list (empty) when the piece ends before the next sample
        if m_new:
            ys = sol.y
            if kind == "Z":
                ys = ys.copy()
                ys[2] = loop.on_surface(s, ys[0], ys[1])
            out[:, filled : filled + m_new] = ys
            filled += m_new
        if sol.status == 0 or filled >= n:
            break
        t0, y0, nxt = _after_event(sol, piece)
    if not np.all(np.isfinite(out[:, :filled])) or filled < n:
        raise ParameterError(
            f"t_end = {t_end!r} s: the PID loop's response overflowed (an unstable loop grows beyond floating point); "
            "allowed inputs that keep it finite"
        )
    return out, MAX_NFEV - budget[0]


@dataclass(frozen=True, kw_only=True)
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


def pid_work_check(osc: Oscillator, kp: float, ki: float, *, kd: float, t_end: float, omega: float = 0.0,
                   rtol: float = 1e-10) -> None:  # fmt: skip
    """Refuse, before any integration, a PID loop whose window spans too many of its fastest time scales.

    The rate is the largest of the closed loop's eigenvalue moduli, the plant's ``omega_n + |c|/m`` and the
    forcing frequency ``omega`` (rad/s); the report runner calls this on a chapter's parameters before any
    kernel starts, so that a run it accepts finishes within the budget.

    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> pid_work_check(osc, 133.6, 512.0, kd=18.7, t_end=50.0, omega=4.47)  # the chapter's loop: fine
    >>> pid_work_check(Oscillator(m=1.0, c=0.5, k=20.0), 133.6, 1e5, kd=18.7, t_end=1000.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: t_end = 1000.0 s spans ... time scales of the PID loop ...
    """
    with np.errstate(over="ignore", invalid="ignore"):
        A = np.array([[0.0, 1.0, 0.0], [-(osc.k + kp) / osc.m, -(osc.c + kd) / osc.m, ki / osc.m], [-1.0, 0.0, 0.0]])
    if not np.all(np.isfinite(A)):
        raise ParameterError(
            f"kp = {kp!r}, ki = {ki!r}, kd = {kd!r} over m = {osc.m!r} kg overflow: allowed finite gains/m"
        )
    rate = max(float(np.max(np.abs(np.linalg.eigvals(A)))), osc.natural_frequency + abs(osc.c) / osc.m, omega)
    _work_check(t_end, rate, rtol, "PID loop")


def _check_loop(osc, force, kp, ki, kd, *, pd: bool = False) -> tuple[float, float, float]:
    """Check the oscillator, the optional force and the three gains of a PID loop (``ki = 0``, a PD loop, where
    ``pd``); the gains as floats."""
    check_oscillator(osc)
    if force is not None and not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed None or SineForce(F0, omega)")
    kp = check_real("kp", kp, low=-osc.k, low_open=True, unit="N/m")
    ki = check_real("ki", ki, low=0.0, low_open=not pd, unit="N/(m s)")
    kd = check_real("kd", kd, unit="N s/m")
    return kp, ki, kd


def pid_response(
    osc: Oscillator,
    force: SineForce | None,
    kp: float,
    *,
    ki: float,
    kd: float,
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
        Gains: N/m, N/(m s) (>= 0; 0 is a PD loop), N s/m.
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
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> r = pid_response(osc, None, 80.0, ki=100.0, kd=10.0, x_ref=0.1, t_end=20.0, n_points=201)
    >>> round(float(r.x[-1]), 6)                        # m: integral action removes the offset
    0.1
    >>> pd = pid_response(osc, None, 80.0, ki=0.0, kd=10.0, x_ref=0.1, t_end=20.0, n_points=201)
    >>> round(float(pd.x[-1]), 6), round(80.0 * 0.1 / (20.0 + 80.0), 6)   # m: a PD loop keeps kp x_ref / (k + kp)
    (0.08, 0.08)
    """
    p = _pid_parameters(osc, force, kp, ki, kd, u_max, anti_windup, t_track, x_ref)
    grid = _grid(t_end, n_points)
    rtol = check_real("rtol", rtol, low=RTOL_MIN, high=RTOL_MAX)
    atol = check_real("atol", atol, low=0.0, low_open=True)
    pid_work_check(osc, p["kp"], p["ki"], kd=p["kd"], t_end=float(grid[-1]), omega=p["wf"], rtol=rtol)
    y, nfev = _pid_run(p, grid, rtol, atol, float(grid[-1]))
    return _pid_record(p, grid, y, nfev, anti_windup)


def _pid_parameters(osc, force, kp, ki, kd, u_max, anti_windup, t_track, x_ref) -> dict:
    """Check the loop's arguments (in :func:`pid_response`'s order); the parameters :func:`_pid_run` takes."""
    kp, ki, kd = _check_loop(osc, force, kp, ki, kd, pd=True)
    umax = _limit(u_max)
    if anti_windup not in ANTI_WINDUP:
        raise ParameterError(f"anti_windup = {anti_windup!r} is not supported: allowed one of {', '.join(ANTI_WINDUP)}")
    if ki == 0.0:  # a PD loop: the integrator never reaches the force, so there is nothing to wind up
        if t_track is not None:
            check_real("t_track", t_track, low=0.0, low_open=True, unit="s")
        x_ref = check_real("x_ref", x_ref, unit="m")
        F0, wf = (force.F0, force.omega) if force is not None else (0.0, 0.0)
        return dict(m=osc.m, c=osc.c, k=osc.k, F0=F0, wf=wf, kp=kp, ki=0.0, kd=kd, umax=umax, x_ref=x_ref, mode=0,
                    gain_bc=0.0)  # fmt: skip
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
    F0, wf = (force.F0, force.omega) if force is not None else (0.0, 0.0)
    mode = ANTI_WINDUP.index(anti_windup)
    return dict(m=osc.m, c=osc.c, k=osc.k, F0=F0, wf=wf, kp=kp, ki=ki, kd=kd, umax=umax, x_ref=x_ref, mode=mode,
                gain_bc=1.0 / (ki * tt))  # fmt: skip


def _pid_record(p: dict, grid: np.ndarray, y: np.ndarray, nfev: int, anti_windup: str) -> PIDResponse:
    """The response record of the states ``y`` on ``grid``: the demand (refused when it overflows) and the force."""
    kp, ki, kd, x_ref, umax = p["kp"], p["ki"], p["kd"], p["x_ref"], p["umax"]
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


def pid_linear_response(osc: Oscillator, force: SineForce | None, kp: float, *, ki: float, kd: float, t, x_ref=0.0):
    """Exact response of the unlimited PID loop (matrix exponential plus particular solution).

    The loop ``y = [x, v, I]``, ``y' = A y + b_F F0 sin(omega t) + b_r x_ref`` is linear; its
    solution is ``y_p(t) + expm(A t) (y(0) - y_p(0))`` with the particular solution
    ``y_p = Im(H e^{i omega t}) - A^{-1} b_r x_ref``, ``H = (i omega I - A)^{-1} b_F F0``.
    Returns ``(x, v, I)`` at the times ``t`` (s): m, m/s, m s. Used to check
    :func:`pid_response`.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> x, v, i = pid_linear_response(osc, None, 80.0, ki=100.0, kd=10.0, t=[0.0, 60.0], x_ref=0.1)
    >>> np.round(x, 9)
    array([0. , 0.1])
    """
    from scipy.linalg import expm

    kp, ki, kd = _check_loop(osc, force, kp, ki, kd)
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
