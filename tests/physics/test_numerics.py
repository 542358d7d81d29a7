"""The paper's numerical path (solve_ivp) against the exact solution.

Global error of an adaptive integrator is a modest multiple of the local
tolerance it was asked for. Measured on these 20 s windows (x0 = 0.3 m,
v0 = -0.2 m/s), as max|x_num - x_exact| / (rtol * max|x| + atol):

* RK45   rtol 1e-10, atol 1e-12: <= 10  (worst: negative damping c = -0.2)
* DOP853 rtol 1e-10, atol 1e-12: <= 92  (worst: the reference case; dense output)
* Radau  rtol 1e-9,  atol 1e-12: <= 0.3
* LSODA  rtol 1e-9,  atol 1e-12: <= 30  (worst: negative damping c = -0.2)
* RK45 at SciPy's defaults (rtol 1e-3, atol 1e-6) on the paper's 50 s: <= 34.

The bound asserted is ``ERR_FACTOR * (rtol * max|x| + atol)`` with one factor for
all methods, about three times the worst measured ratio.
"""

from __future__ import annotations

import inspect
import math
import tracemalloc

import numpy as np
import pytest
import scipy.integrate
from scipy.integrate import solve_ivp

import vibration.physics.numerics
from vibration import N_POINTS_MAX, Oscillator, ParameterError, SineForce, exact_response, simulate

ERR_FACTOR = 300.0

CASES = {
    "reference": (1.0, 0.5, 20.0, 5.0, 3.0),
    "low-damping-resonance": (1.0, 0.1, 20.0, 5.0, 4.47),
    "overdamped": (1.0, 15.0, 20.0, 5.0, 4.47),
    "undamped-resonance": (1.0, 0.0, 20.0, 5.0, math.sqrt(20.0)),
    "critical": (1.0, 2.0 * math.sqrt(20.0), 20.0, 5.0, 3.0),
    "negative-damping": (1.0, -0.2, 20.0, 5.0, 3.0),
    "mass-3-k-7": (3.0, 0.4, 7.0, 2.0, 1.1),
}
TIGHT = {"RK45": (1e-10, 1e-12), "DOP853": (1e-10, 1e-12), "Radau": (1e-9, 1e-12), "LSODA": (1e-9, 1e-12)}
SLOW = {("Radau", name) for name in CASES} - {("Radau", "reference"), ("Radau", "mass-3-k-7")}  # ~1.4 s each


def _tight_cases():
    for method, (rtol, atol) in TIGHT.items():
        for name, case in CASES.items():
            marks = [pytest.mark.slow] if (method, name) in SLOW else []
            yield pytest.param(method, rtol, atol, *case, id=f"{method}-{name}", marks=marks)


def _errors(osc, force, r, x0, v0):
    e = exact_response(osc, force, r.t, x0=x0, v0=v0)
    return (
        float(np.max(np.abs(r.x - e.x))),
        float(np.max(np.abs(r.v - e.v))),
        float(np.max(np.abs(e.x))),
        float(np.max(np.abs(e.v))),
    )


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
@pytest.mark.parametrize(("method", "rtol", "atol", "m", "c", "k", "F0", "w"), list(_tight_cases()))
def test_tight_tolerance_meets_proportional_bound(method, rtol, atol, m, c, k, F0, w):
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w)
    x0, v0 = 0.3, -0.2
    r = simulate(osc, force, 20.0, n_points=2001, x0=x0, v0=v0, method=method, rtol=rtol, atol=atol)
    assert r.method == method and r.status == 0 and r.success and r.nfev > 0
    assert (r.rtol, r.atol) == (rtol, atol)
    err_x, err_v, max_x, max_v = _errors(osc, force, r, x0, v0)
    assert err_x <= ERR_FACTOR * (rtol * max_x + atol)
    assert err_v <= ERR_FACTOR * (rtol * max_v + atol)


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_error_scales_with_the_tolerance_asked():
    """RK45 over six decades of rtol: the bound holds at each, and the error falls with rtol."""
    osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)
    errors = []
    for rtol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]:
        atol = rtol * 1e-2
        r = simulate(osc, force, 20.0, n_points=2001, method="RK45", rtol=rtol, atol=atol)
        err_x, _, max_x, _ = _errors(osc, force, r, 0.0, 0.0)
        assert err_x <= ERR_FACTOR * (rtol * max_x + atol)
        errors.append(err_x)
    assert errors[-1] < 1e-4 * errors[0]  # 1e6 in tolerance buys at least 1e4 in error


def test_paper_method_at_default_tolerances():
    """The paper's run (RK45, SciPy defaults, 50 s): error within the same bound."""
    osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)
    r = simulate(osc, force, 50.0)
    err_x, err_v, max_x, max_v = _errors(osc, force, r, 0.0, 0.0)
    assert err_x <= ERR_FACTOR * (1e-3 * max_x + 1e-6)
    assert err_v <= ERR_FACTOR * (1e-3 * max_v + 1e-6)


def test_defaults_are_scipys():
    params = inspect.signature(simulate).parameters
    rk45 = inspect.signature(scipy.integrate.RK45).parameters
    assert params["method"].default == inspect.signature(solve_ivp).parameters["method"].default == "RK45"
    assert params["rtol"].default == rk45["rtol"].default == 1e-3
    assert params["atol"].default == rk45["atol"].default == 1e-6
    assert params["x0"].default == 0.0 and params["v0"].default == 0.0


def test_defaults_reproduce_a_plain_solve_ivp_call():
    """simulate(osc, force, t_end) is solve_ivp on the textbook state space with nothing changed."""
    m, c, k, F0, w = 1.0, 0.5, 20.0, 5.0, 3.0

    def rhs(t, y):
        return np.array((y[1], (F0 * math.sin(w * t) - c * y[1] - k * y[0]) / m))

    grid = np.linspace(0.0, 50.0, 5001)
    ref = solve_ivp(rhs, (0.0, 50.0), (0.0, 0.0), t_eval=grid)
    r = simulate(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w), 50.0)
    assert r.nfev == ref.nfev
    np.testing.assert_array_equal(r.t, grid)
    np.testing.assert_allclose(r.x, ref.y[0], rtol=0, atol=1e-12 * np.max(np.abs(ref.y[0])))
    np.testing.assert_allclose(r.v, ref.y[1], rtol=0, atol=1e-12 * np.max(np.abs(ref.y[1])))


@pytest.mark.parametrize(("t_end", "n_points"), [(50.0, 5001), (1.0, 2), (7.3, 1234)])
def test_output_grid_is_linspace(t_end, n_points):
    r = simulate(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), t_end, n_points=n_points)
    np.testing.assert_array_equal(r.t, np.linspace(0.0, t_end, n_points))
    assert r.x.shape == r.v.shape == (n_points,)
    assert r.nfev > 0 and r.status == 0 and r.method == "RK45"
    assert r.x[0] == 0.0 and r.v[0] == 0.0


def test_default_number_of_points_is_the_papers_sampling():
    r = simulate(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), 50.0)
    np.testing.assert_array_equal(r.t, np.linspace(0.0, 50.0, 5001))  # every 0.01 s


@pytest.mark.parametrize("method", ["RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA"])
def test_every_method_runs_and_reports(method):
    r = simulate(
        Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), 5.0, n_points=101, x0=0.1, v0=0.0, method=method
    )
    assert r.method == method and r.status == 0 and r.nfev > 0
    if method in ("Radau", "BDF"):
        assert r.njev > 0 and r.nlu > 0
    err_x, _, max_x, _ = _errors(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), r, 0.1, 0.0)
    assert err_x <= ERR_FACTOR * (1e-3 * max_x + 1e-6)


def test_without_t_eval_returns_the_solver_steps():
    osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    r = simulate(
        osc, force, 20.0, n_points=2001, x0=0.3, v0=-0.2, method="DOP853", rtol=1e-10, atol=1e-12, t_eval=False
    )
    assert r.t[0] == 0.0 and r.t[-1] == 20.0
    assert np.all(np.diff(r.t) > 0)
    assert r.t.size != 2001
    steps = np.diff(r.t)
    assert steps.max() / steps.min() > 1.01  # adaptive, not a uniform grid
    err_x, err_v, max_x, max_v = _errors(osc, force, r, 0.3, -0.2)
    assert err_x <= ERR_FACTOR * (1e-10 * max_x + 1e-12)
    assert err_v <= ERR_FACTOR * (1e-10 * max_v + 1e-12)


def test_overflowing_window_is_refused_before_integrating():
    """c = -1e4 N s/m overflows within 0.1 s: refused up front (it used to fail inside RK45)."""
    with pytest.raises(ParameterError, match=r"t_end = 1.0 s is out of range: the unstable free mode grows"):
        simulate(
            Oscillator(m=1.0, c=-1e4, k=1.0), SineForce(F0=1.0, omega=1.0), 1.0, n_points=11, x0=1.0, method="RK45"
        )


def test_failed_solver_result_raises_runtime_error(monkeypatch):
    """Any status other than 0 from solve_ivp becomes a RuntimeError naming method and message."""

    def failing_solve_ivp(*args, **kwargs):
        sol = solve_ivp(*args, **kwargs)
        sol.status = -1
        sol.message = "Required step size is less than spacing between numbers."
        sol.success = False
        return sol

    monkeypatch.setattr(vibration.physics.numerics, "solve_ivp", failing_solve_ivp)
    with pytest.raises(RuntimeError, match=r"LSODA.*Required step size"):
        simulate(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), 1.0, n_points=11, method="LSODA")


# --- validation ---

OSC, FORCE = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)

BAD_ARGS = (
    [("t_end", v, "t_end > 0") for v in [0.0, 0, -1.0, -1e-300]]
    + [("t_end", v, "finite") for v in [math.inf, math.nan, -math.inf, "50", True, None]]
    + [("n_points", v, f"n_points <= {N_POINTS_MAX}") for v in [1, 0, -5, N_POINTS_MAX + 1, 10**12]]
    + [("n_points", v, "integer") for v in [2.5, 5001.0, "5001", True, None, math.nan]]
    + [("x0", v, "finite") for v in [math.nan, math.inf, "0"]]
    + [("v0", v, "finite") for v in [math.nan, -math.inf, False]]
    + [("method", v, "RK45") for v in ["Euler", "rk45", "", None]]
    + [("rtol", v, "rtol >= 2.22045e-14") for v in [0.0, -1e-3, 1e-15, 1e-148]]
    + [("rtol", v, "finite") for v in [math.nan, math.inf, "1e-3"]]
    + [("atol", v, "atol > 0") for v in [0.0, -1e-6]]
    + [("atol", v, "finite") for v in [math.nan, math.inf]]
)


@pytest.mark.parametrize(("name", "bad", "allowed"), BAD_ARGS, ids=lambda v: repr(v))
def test_simulate_refuses_bad_arguments(raises_parameter_error, name, bad, allowed):
    kwargs = {"t_end": 1.0, "n_points": 11, **{name: bad}}
    with raises_parameter_error(name, bad, allowed):
        simulate(OSC, FORCE, **kwargs)


@pytest.mark.parametrize("n_points", [N_POINTS_MAX + 1, 10**12, 10**18])
def test_huge_n_points_is_refused_before_allocating(n_points):
    tracemalloc.start()
    try:
        with pytest.raises(ParameterError, match="n_points"):
            simulate(OSC, FORCE, 50.0, n_points=n_points)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 1_000_000  # bytes; N_POINTS_MAX + 1 samples alone would be 16 MB


def test_largest_allowed_n_points_is_accepted():
    r = simulate(OSC, FORCE, 1.0, n_points=N_POINTS_MAX)
    assert r.t.size == N_POINTS_MAX
