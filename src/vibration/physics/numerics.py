"""Numerical integration with :func:`scipy.integrate.solve_ivp`, as in the paper."""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from .checks import OverBudget, check_oscillator
from .exact import Response
from .forcing import Sampled, check_load, fastest_rate, load_function
from .model import N_POINTS_MAX, Oscillator, ParameterError, SineForce, check_int, check_real, check_records

#: Integrators of solve_ivp accepted by :func:`simulate`.
METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")

#: The paper's sampling: 5001 points on [0, 50] s, i.e. every 0.01 s (our choice;
#: the paper does not state its t_eval).
DEFAULT_N_POINTS = 5001

#: Smallest relative tolerance solve_ivp honours (100 eps); it silently raises a smaller one.
RTOL_MIN = 100 * float(np.finfo(float).eps)

#: Most right-hand-side evaluations one :func:`simulate` call may spend (about ten
#: seconds of work); a window that needs more is refused with :class:`ParameterError`.
MAX_NFEV = 2_000_000

#: Most periods of the fastest oscillation (forcing or natural) one window may hold.
MAX_PERIODS = 100_000

#: Largest ``|s_fast| t_end`` (the fast real root times the window) for the explicit
#: methods, whose step is bounded by stability to about ``3 / |s_fast|``.
MAX_STIFFNESS = 1_000_000

#: The explicit integrators among :data:`METHODS`.
EXPLICIT = ("RK45", "RK23", "DOP853")

#: Largest growth exponent ``Re(s) t_end`` of an unstable free mode: beyond about
#: 709 the response overflows the float range.
MAX_GROWTH = 700.0


def simulate(
    osc: Oscillator,
    force: SineForce,
    t_end: float,
    *,
    n_points: int = DEFAULT_N_POINTS,
    x0: float = 0.0,
    v0: float = 0.0,
    method: str = "RK45",
    rtol: float = 1e-3,
    atol: float = 1e-6,
    t_eval: bool = True,
) -> Response:
    """Integrate ``m x'' + c x' + k x = F(t)`` with ``solve_ivp``; the paper's ``F = F0 sin(omega t)``.

    The state-space form is ``y = [x, v]``, ``y' = [v, (F0 sin(omega t) - c v - k x)/m]``.
    The defaults (RK45, ``rtol=1e-3``, ``atol=1e-6``) are SciPy's, i.e. the paper's method.

    Parameters
    ----------
    osc, force
        The oscillator, m (kg), c (N s/m), k (N/m), and the force, F0 (N), omega (rad/s), or any load record
        of :mod:`vibration.forcing` (a sampled input up to its last sample time).
    t_end : float
        End of the window, s; > 0. The window starts at t = 0.
    n_points : int
        Number of output samples on ``numpy.linspace(0, t_end, n_points)``;
        2 <= n_points <= ``N_POINTS_MAX``.
    x0, v0 : float
        Initial displacement (m) and velocity (m/s).
    method : str
        One of ``METHODS``.
    rtol, atol : float
        Solver tolerances (relative, >= ``RTOL_MIN`` = 100 eps; absolute in m and
        m/s, > 0).
    t_eval : bool
        If False, return the solver's own steps instead of the uniform grid;
        ``n_points`` then caps their number (a run that needs more steps is
        refused).

    Returns
    -------
    Response
        Arrays ``t`` (s), ``x`` (m), ``v`` (m/s) and the solver's ``nfev``,
        ``njev``, ``nlu``, ``status`` and ``message``.

    Raises
    ------
    ParameterError
        On any out-of-range argument, before anything is allocated; on a window
        longer than ``MAX_PERIODS`` periods of the fastest oscillation or in
        which an unstable mode grows beyond ``exp(MAX_GROWTH)`` (the response
        would overflow); and, during the run, when the solver needs more than
        ``MAX_NFEV`` right-hand-side evaluations or (``t_eval=False``) more
        than ``n_points`` steps.
    RuntimeError
        When the solver fails.

    Examples
    --------
    >>> from vibration import Oscillator, SineForce
    >>> r = simulate(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), 50.0)
    >>> r.t.shape, r.method, r.status
    ((5001,), 'RK45', 0)
    """
    t_end, n_points, x0, v0, rtol, atol = _simulate_args(
        osc, force, t_end, n_points, x0, v0, method, rtol, atol, t_eval
    )
    _check_window(osc, force, t_end, method)
    sol = _integrate(osc, force, t_end, n_points, x0, v0, method, rtol, atol, t_eval)
    _check_solution(sol, t_end, n_points, method, t_eval)
    return _response(sol, method, rtol, atol)


def _simulate_args(osc, force, t_end, n_points, x0, v0, method, rtol, atol, t_eval):
    """The checked arguments of :func:`simulate`: ``(t_end, n_points, x0, v0, rtol, atol)``."""
    if isinstance(force, SineForce):
        check_records(osc, force)
    else:
        check_oscillator(osc)
        check_load(force)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    if isinstance(force, Sampled) and t_end > force.t_end:
        raise ParameterError(
            f"t_end = {t_end!r} s is beyond the sampled input: allowed t_end <= {force.t_end!r} s, its last sample"
        )
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    if method not in METHODS:
        raise ParameterError(f"method = {method!r} is not supported: allowed one of {', '.join(METHODS)}")
    rtol = check_real("rtol", rtol, low=RTOL_MIN)  # solve_ivp would raise a smaller one silently
    atol = check_real("atol", atol, low=0.0, low_open=True)
    if not isinstance(t_eval, bool | np.bool_):
        raise ParameterError(
            f"t_eval = {t_eval!r:.60} is not a bool: allowed True (n_points samples) or False (the solver's steps)"
        )
    return t_end, n_points, x0, v0, rtol, atol


def _integrate(osc, force, t_end, n_points, x0, v0, method, rtol, atol, t_eval):
    """``solve_ivp`` on the state space of :func:`simulate`, its right-hand side counted against ``MAX_NFEV``."""
    m, c, k = osc.m, osc.c, osc.k
    load = load_function(osc, force)
    nfev = 0

    def rhs(t, y):
        nonlocal nfev
        nfev += 1
        if nfev > MAX_NFEV:
            raise OverBudget
        return np.array((y[1], (load(t) - c * y[1] - k * y[0]) / m))

    def jac(t, y):
        return np.array(((0.0, 1.0), (-k / m, -c / m)))

    grid = np.linspace(0.0, t_end, n_points) if t_eval else None
    extra = {"jac": jac} if method in ("Radau", "BDF", "LSODA") else {}
    if isinstance(force, Sampled):  # no step may jump over a sample: the input bends there
        extra["max_step"] = float(np.min(np.diff(force.t)))
    try:
        with np.errstate(all="ignore"):  # an overflow is reported below, by name
            return solve_ivp(rhs, (0.0, t_end), (x0, v0), method=method, t_eval=grid, rtol=rtol, atol=atol, **extra)
    except OverBudget:
        raise ParameterError(
            f"t_end = {t_end!r} s needs more than {MAX_NFEV} right-hand-side evaluations with {method} at "
            f"rtol = {rtol!r}, atol = {atol!r}: allowed a shorter window or looser tolerances"
        ) from None


def _check_solution(sol, t_end: float, n_points: int, method: str, t_eval) -> None:
    """Refuse a run of :func:`simulate` with too many steps or an overflow; raise ``RuntimeError`` on a failure."""
    if sol.status == 0 and not t_eval and sol.t.size > n_points:
        raise ParameterError(
            f"n_points = {n_points} is out of range: the solver took {sol.t.size - 1} steps and t_eval=False "
            f"returns every one: allowed n_points >= {sol.t.size} (<= {N_POINTS_MAX}), or t_eval=True"
        )
    if sol.status == 0 and not (np.all(np.isfinite(sol.y))):
        raise ParameterError(f"t_end = {t_end!r} s: the response overflows the float range: allowed a shorter window")
    if sol.status != 0:
        raise RuntimeError(f"solve_ivp ({method}) failed at t = {sol.t[-1]:g} s: {sol.message}")


def _response(sol, method: str, rtol: float, atol: float) -> Response:
    """The :class:`Response` record of a finished ``solve_ivp`` run of :func:`simulate`."""
    return Response(
        t=sol.t,
        x=sol.y[0],
        v=sol.y[1],
        method=method,
        nfev=int(sol.nfev),
        njev=int(sol.njev),
        nlu=int(sol.nlu),
        status=int(sol.status),
        message=str(sol.message),
        rtol=rtol,
        atol=atol,
    )


def _check_window(osc: Oscillator, force: SineForce, t_end: float, method: str) -> None:
    """Refuse windows whose work or growth is unbounded, before integrating."""
    fastest = max(fastest_rate(force), osc.natural_frequency)  # rad/s
    periods = t_end * fastest / (2.0 * math.pi)
    if periods > MAX_PERIODS:
        raise ParameterError(
            f"t_end = {t_end!r} s is out of range: it holds {periods:.3g} periods of the fastest oscillation "
            f"({fastest:.6g} rad/s): allowed t_end <= {MAX_PERIODS * 2.0 * math.pi / fastest:.6g} s "
            f"({MAX_PERIODS} periods)"
        )
    sigma, wn2 = osc.decay_rate, osc.k / osc.m
    q = sigma * sigma - wn2
    mu = math.sqrt(q) if q > 0.0 else 0.0
    growth = -sigma + mu  # largest real part of the roots, 1/s
    fast = abs(sigma) + mu  # modulus of the fastest real part, 1/s
    if method in EXPLICIT and fast * t_end > MAX_STIFFNESS:
        raise ParameterError(
            f"t_end = {t_end!r} s is out of range for the explicit {method}: the fast mode decays at {fast:.6g} 1/s, "
            f"so stability alone needs about {fast * t_end / 3:.3g} steps: allowed t_end <= "
            f"{MAX_STIFFNESS / fast:.6g} s, or an implicit method (Radau, BDF, LSODA)"
        )
    if growth * t_end > MAX_GROWTH:
        raise ParameterError(
            f"t_end = {t_end!r} s is out of range: the unstable free mode grows like exp({growth:.6g} t) and would "
            f"overflow: allowed t_end <= {MAX_GROWTH / growth:.6g} s"
        )
