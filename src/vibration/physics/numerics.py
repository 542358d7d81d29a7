"""Numerical integration with :func:`scipy.integrate.solve_ivp`, as in the paper."""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from .exact import Response
from .model import N_POINTS_MAX, Oscillator, ParameterError, SineForce, check_int, check_real, check_records

#: Integrators of solve_ivp accepted by :func:`simulate`.
METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")

#: The paper's sampling: 5001 points on [0, 50] s, i.e. every 0.01 s (our choice;
#: the paper does not state its t_eval).
DEFAULT_N_POINTS = 5001


def simulate(
    osc: Oscillator,
    force: SineForce,
    t_end: float,
    n_points: int = DEFAULT_N_POINTS,
    x0: float = 0.0,
    v0: float = 0.0,
    method: str = "RK45",
    rtol: float = 1e-3,
    atol: float = 1e-6,
    t_eval: bool = True,
) -> Response:
    """Integrate ``m x'' + c x' + k x = F0 sin(omega t)`` with ``solve_ivp``.

    The state-space form is ``y = [x, v]``, ``y' = [v, (F0 sin(omega t) - c v - k x)/m]``.
    The defaults (RK45, ``rtol=1e-3``, ``atol=1e-6``) are SciPy's, i.e. the paper's method.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    force : SineForce
        F0 (N), omega (rad/s).
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
        Solver tolerances (relative; absolute in m and m/s); > 0.
    t_eval : bool
        If False, return the solver's own steps instead of the uniform grid
        (``n_points`` is then ignored).

    Returns
    -------
    Response
        Arrays ``t`` (s), ``x`` (m), ``v`` (m/s) and the solver's ``nfev``,
        ``njev``, ``nlu``, ``status`` and ``message``.

    Raises
    ------
    ParameterError
        On any out-of-range argument, before anything is allocated.
    RuntimeError
        When the solver fails.

    Examples
    --------
    >>> from vibration import Oscillator, SineForce
    >>> r = simulate(Oscillator(1.0, 0.5, 20.0), SineForce(5.0, 3.0), 50.0)
    >>> r.t.shape, r.method, r.status
    ((5001,), 'RK45', 0)
    """
    check_records(osc, force)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    if method not in METHODS:
        raise ParameterError(f"method = {method!r} is not supported: allowed one of {', '.join(METHODS)}")
    rtol = check_real("rtol", rtol, low=0.0, low_open=True)
    atol = check_real("atol", atol, low=0.0, low_open=True)

    m, c, k = osc.m, osc.c, osc.k
    F0, w = force.F0, force.omega
    sin = math.sin

    def rhs(t, y):
        return np.array((y[1], (F0 * sin(w * t) - c * y[1] - k * y[0]) / m))

    def jac(t, y):
        return np.array(((0.0, 1.0), (-k / m, -c / m)))

    grid = np.linspace(0.0, t_end, n_points) if t_eval else None
    extra = {"jac": jac} if method in ("Radau", "BDF", "LSODA") else {}
    sol = solve_ivp(rhs, (0.0, t_end), (x0, v0), method=method, t_eval=grid, rtol=rtol, atol=atol, **extra)
    if sol.status != 0:
        raise RuntimeError(f"solve_ivp ({method}) failed at t = {sol.t[-1]:g} s: {sol.message}")
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
