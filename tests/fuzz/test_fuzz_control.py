"""Fuzz tests of the control API (issue 20): invalid and extreme inputs give a ParameterError or a
finite result, and every call returns within a wall-clock budget.

Each call runs under :func:`guarded`: a ``SIGALRM`` watchdog of :data:`LIMIT` seconds, then the
result must be finite everywhere (numbers, arrays, dataclass fields, tuples); a ParameterError is
accepted (its message must say what is allowed). Any other exception fails the test.
"""

from __future__ import annotations

import dataclasses
import math
import signal
import time

import numpy as np
import pytest
from fuzzing import WALL
from hypothesis import given, settings
from hypothesis import strategies as st

from vibration.physics import control as ctl
from vibration.physics.checks import check_array
from vibration.physics.model import Oscillator, ParameterError, SineForce

#: Wall-clock budget of one call, s.
LIMIT = WALL  # the shared budget of tests/fuzzing.py (a loaded 2-core machine took 10 s on a 5 s call)

OSC = Oscillator(m=1.0, c=0.5, k=20.0)
RES = SineForce(F0=5.0, omega=4.47)


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout


def _finite(value, where: str = "result") -> None:
    if value is None or isinstance(value, str | bool):
        return
    if isinstance(value, Oscillator | SineForce):
        return
    if dataclasses.is_dataclass(value):
        for f in dataclasses.fields(value):
            if f.name != "u_max":  # inf documents "no limit"
                _finite(getattr(value, f.name), f"{where}.{f.name}")
        return
    if isinstance(value, tuple | list):
        for i, v in enumerate(value):
            _finite(v, f"{where}[{i}]")
        return
    if callable(value):
        return
    arr = np.asarray(value)
    if arr.dtype.kind in "fc":
        assert np.all(np.isfinite(arr)), f"{where} is not finite: {value!r}"


def guarded(fn, *args, finite: bool = True, **kwargs):
    """Call ``fn`` under a watchdog; return the result (checked finite) or the ParameterError."""
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, LIMIT)
    t0 = time.perf_counter()
    try:
        out = fn(*args, **kwargs)
    except ParameterError as err:
        assert "allowed" in str(err).lower(), str(err)
        return err
    except _Timeout:
        pytest.fail(f"{fn.__name__}{args!r} {kwargs!r} ran longer than {LIMIT} s")
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, old)
    assert time.perf_counter() - t0 < LIMIT
    if finite:
        _finite(out)
    return out


def refused(fn, *args, **kwargs) -> ParameterError:
    out = guarded(fn, *args, **kwargs)
    assert isinstance(out, ParameterError), f"{fn.__name__} accepted {args!r} {kwargs!r}"
    return out


BAD_SCALARS = [math.nan, math.inf, -math.inf, "1.0", True, 1j, None, [1.0], np.array([1.0, 2.0])]
BAD_ARRAYS = [
    [],
    np.array([]),
    ["a", "b"],
    "0.5",
    [True, False],
    np.array([1.0 + 1j, 2.0]),
    [0.0, math.nan],
    [0.0, math.inf],
    [[0.0, 1.0], [2.0, 3.0]],
    np.zeros((2, 2, 2)),
    object(),
    None,
]

extreme = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-300, 1e-6, 1e6, 1e8, 1e150, 1e300, -1.0, -1e8]),
)
positive = st.sampled_from([1e-6, 1e-3, 0.02, 0.5, 1.0, 15.0, 1e3, 1e6, 1e8])
scalar_osc = st.builds(
    Oscillator,
    m=st.sampled_from([1e-3, 1.0, 1e3]),
    c=st.sampled_from([-0.5, 0.0, 0.02, 0.5, 15.0, 1e6]),
    k=st.sampled_from([1e-6, 1.0, 20.0, 1e8]),
)


# ----------------------------------------------------------------------------- the chattering loops


def test_pi_with_a_limit_returns_fast_and_sticks_on_the_limit():
    """The PI case of the report (kd = 0, 10 s window) that used to run for minutes."""
    t0 = time.perf_counter()
    r = guarded(
        ctl.pid_response, OSC, RES, 133.6, ki=512.0, kd=0.0, u_max=12.0, anti_windup="clamping", x_ref=0.5, t_end=10.0
    )
    assert time.perf_counter() - t0 < 5.0
    assert isinstance(r, ctl.PIDResponse)
    assert np.max(np.abs(r.u)) <= 12.0 * (1 + 1e-12)


@pytest.mark.parametrize("omega", [2.2, 2.5, 3.0])
def test_clamping_sliding_mode_of_chapter_7(omega):
    """Chapter 7's move at omega_res 2.2 to 3: a sliding mode on u_d = u_max; fast, on the limit, finite."""
    t0 = time.perf_counter()
    f = SineForce(F0=5.0, omega=omega)
    r = guarded(ctl.pid_response, OSC, f, 133.6, ki=512.0, kd=18.7, u_max=12.0, anti_windup="clamping", x_ref=0.5)
    assert time.perf_counter() - t0 < 5.0
    assert r.nfev < 100_000
    assert np.max(np.abs(r.u)) <= 12.0 * (1 + 1e-12)
    # no chattering between the limits from one 10 ms sample to the next
    assert np.max(np.abs(np.diff(r.u))) < 0.5 * 12.0


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_clamping_agrees_with_a_fine_fixed_step_solution():
    """The piecewise solution against RK4 of the discontinuous loop at h = 1e-4 s (first order: about 1e-5 m)."""
    kp, ki, kd, umax, xr = 133.6, 512.0, 18.7, 12.0, 0.5
    w, h, t_end = 2.5, 1e-4, 4.0
    r = ctl.pid_response(
        OSC,
        SineForce(F0=5.0, omega=w),
        kp,
        ki=ki,
        kd=kd,
        u_max=umax,
        anti_windup="clamping",
        x_ref=xr,
        t_end=t_end,
        n_points=41,
    )
    m, c, k = OSC.m, OSC.c, OSC.k

    def f(t, y):
        x, v, i = y
        e = xr - x
        ud = kp * e + ki * i - kd * v
        u = min(max(ud, -umax), umax)
        di = 0.0 if (u != ud and e * ud > 0.0) else e
        return np.array([v, (5.0 * math.sin(w * t) - c * v - k * x + u) / m, di])

    y, out = np.zeros(3), [np.zeros(3)]
    n = round(t_end / h)
    for j in range(n):
        t = j * h
        k1 = f(t, y)
        k2 = f(t + h / 2, y + h / 2 * k1)
        k3 = f(t + h / 2, y + h / 2 * k2)
        k4 = f(t + h, y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        if (j + 1) % 1000 == 0:
            out.append(y)
    ref = np.array(out)
    assert np.max(np.abs(ref[:, 0] - r.x)) < 5e-5
    assert np.max(np.abs(ref[:, 2] - r.integral)) < 5e-5


def test_none_and_back_calculation_agree_with_the_unlimited_loop_when_never_saturated():
    for aw in ctl.ANTI_WINDUP:
        r = ctl.pid_response(OSC, RES, 80.0, ki=100.0, kd=10.0, u_max=1e6, anti_windup=aw, t_end=10.0, n_points=101)
        x, _, _ = ctl.pid_linear_response(OSC, RES, 80.0, ki=100.0, kd=10.0, t=r.t)
        assert np.max(np.abs(r.x - x)) < 1e-8


@pytest.mark.parametrize("k", [1e8, 1e12])
def test_stiff_plants_are_refused_in_seconds(k):
    osc = Oscillator(m=1.0, c=0.5, k=k)
    err = refused(ctl.pid_response, osc, RES, 80.0, ki=100.0, kd=10.0, u_max=12.0, anti_windup="clamping")
    assert "t_end" in str(err)
    err = refused(ctl.simulate_controlled, osc, lambda t, x, v: -x, RES)
    assert "t_end" in str(err)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_discontinuous_controller_hits_the_budget_in_seconds():
    """An on-off law handed to the generic simulator chatters; it must stop with a ParameterError, fast."""
    law = ctl.semi_active_controller("on-off", 8.0, 0.5, c_max=15.0, Y=0.25, omega=4.47)
    out = guarded(ctl.simulate_controlled, OSC, law, base=(0.25, 4.47), t_end=50.0, rtol=1e-12, atol=1e-14)
    assert isinstance(out, ParameterError | ctl.ControlledResponse)


# ----------------------------------------------------------------------------- argument checks


@pytest.mark.parametrize("bad", BAD_SCALARS)
def test_scalar_arguments_refused(bad):
    refused(ctl.pd_oscillator, OSC, bad, 1.0)
    refused(ctl.lqr, OSC, bad, 1.0, r=1.0)
    refused(ctl.lqr_closed_form, OSC, 1.0, 1.0, r=bad)
    refused(ctl.pid_response, OSC, None, 1.0, ki=bad, kd=1.0, t_end=1.0, n_points=11)
    refused(ctl.pid_linear_response, OSC, None, bad, ki=1.0, kd=1.0, t=[0.0, 1.0])
    refused(ctl.pid_linear_response, OSC, None, 1.0, ki=1.0, kd=bad, t=[0.0, 1.0])
    refused(ctl.simulate_controlled, OSC, lambda t, x, v: 0.0, t_end=bad)
    refused(ctl.semi_active_response, OSC, "on-off", bad, Y=0.25, c_min=0.5, c_max=15.0)
    refused(ctl.shaped_move, OSC, None, bad)
    refused(
        ctl.response_metrics, [0.0, 1.0, 2.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0], v_rel=[0.0, 0.0, 0.0], t_steady=bad
    )


@pytest.mark.parametrize(
    "bad", BAD_ARRAYS, ids=lambda b: type(b).__name__ + str(np.shape(b)) if b is not None else "None"
)
def test_array_arguments_refused(bad):
    refused(ctl.pid_linear_response, OSC, None, 80.0, ki=100.0, kd=10.0, t=bad)
    refused(ctl.passive_transmissibility, OSC, bad)
    refused(ctl.skyhook_transmissibility, OSC, 8.0, bad)
    refused(ctl.semi_active_sweep, OSC, "on-off", bad, Y=0.25, c_min=0.5, c_max=15.0, periods=1)
    good = np.linspace(0.0, 1.0, 5)
    refused(ctl.response_metrics, bad, good, good, v_rel=good, t_steady=0.5)
    refused(ctl.response_metrics, good, bad, good, v_rel=good, t_steady=0.5)
    refused(ctl.residual_amplitude, OSC, good, good, v=bad, target=0.0)


def test_pid_linear_response_findings():
    """The findings of issue 20: nan gains, t=None, negative times, negative ki."""
    refused(ctl.pid_linear_response, OSC, None, math.nan, ki=100.0, kd=10.0, t=[0.0, 1.0])
    refused(ctl.pid_linear_response, OSC, None, 80.0, ki=100.0, kd=10.0, t=None)
    refused(ctl.pid_linear_response, OSC, None, 80.0, ki=100.0, kd=10.0, t=[-1.0, 1.0])
    refused(ctl.pid_linear_response, OSC, None, 80.0, ki=-100.0, kd=10.0, t=[0.0, 1.0])
    refused(ctl.pid_linear_response, OSC, "force", 80.0, ki=100.0, kd=10.0, t=[0.0, 1.0])
    # an unstable loop overflows at large times: an error, not nan
    refused(ctl.pid_linear_response, OSC, None, 80.0, ki=100.0, kd=-50.0, t=[0.0, 1e6], x_ref=0.1)


def test_response_metrics_refuses_nan_and_unordered_times():
    t = np.linspace(0.0, 1.0, 11)
    x = np.sin(t)
    refused(ctl.response_metrics, t, np.where(t > 0.5, np.nan, x), x, v_rel=x, t_steady=0.5)
    refused(ctl.response_metrics, t[::-1], x, x, v_rel=x, t_steady=0.5)
    refused(ctl.response_metrics, t, x * 1e200, x, v_rel=x, t_steady=0.5)
    refused(ctl.response_metrics, t, x[:-1], x, v_rel=x, t_steady=0.5)


def test_check_array_messages():
    with pytest.raises(ParameterError, match="t contains nan"):
        check_array("t", [0.0, math.nan])
    with pytest.raises(ParameterError, match="booleans"):
        check_array("t", np.array([True]))
    with pytest.raises(ParameterError, match="complex"):
        check_array("t", [1j])
    with pytest.raises(ParameterError, match="string"):
        check_array("t", "abc")
    with pytest.raises(ParameterError, match="0 elements"):
        check_array("t", [])
    with pytest.raises(ParameterError, match="strictly increasing"):
        check_array("t", [0.0, 0.0], increasing=True)
    with pytest.raises(ParameterError, match="elements"):
        check_array("t", np.zeros(11), max_size=10)


def test_huge_sizes_refused_quickly():
    refused(ctl.simulate_controlled, OSC, lambda t, x, v: 0.0, n_points=10**9)
    refused(ctl.semi_active_response, OSC, "mr", 4.47, Y=0.25, t_end=1e6)
    refused(ctl.semi_active_sweep, OSC, "mr", np.linspace(1.0, 10.0, 1000), Y=0.25, periods=1000)
    refused(ctl.semi_active_sweep, OSC, "on-off", [1e-6], Y=0.25, c_max=15.0)
    refused(
        ctl.pid_linear_response,
        Oscillator(m=1.0, c=0.0, k=1.0),
        None,
        0.0,
        ki=1e-300,
        kd=0.0,
        t=np.linspace(0, 1, 10**7),
    )
    refused(ctl.simulate_controlled, OSC, lambda t, x, v: 0.0, t_end=1e300)
    refused(ctl.simulate_controlled, OSC, lambda t, x, v: 0.0, max_step=1e-9)


# ----------------------------------------------------------------------------- property tests


@settings(max_examples=12, deadline=None)
@given(osc=scalar_osc, kp=extreme, ki=extreme, kd=extreme, u_max=st.one_of(st.none(), extreme), x_ref=extreme)
def test_pid_response_fuzz(osc, kp, ki, kd, u_max, x_ref):
    guarded(
        ctl.pid_response,
        osc,
        RES,
        kp,
        ki=ki,
        kd=kd,
        u_max=u_max,
        anti_windup="clamping",
        x_ref=x_ref,
        t_end=2.0,
        n_points=21,
    )


@settings(max_examples=30, deadline=None)
@given(osc=scalar_osc, kp=extreme, ki=extreme, kd=extreme, x_ref=extreme, tmax=extreme)
def test_pid_linear_response_fuzz(osc, kp, ki, kd, x_ref, tmax):
    guarded(ctl.pid_linear_response, osc, RES, kp, ki=ki, kd=kd, t=[0.0, tmax], x_ref=x_ref)


@settings(max_examples=20, deadline=None)
@given(osc=scalar_osc, gain=extreme, u_max=st.one_of(st.none(), extreme), t_end=extreme)
def test_simulate_controlled_fuzz(osc, gain, u_max, t_end):
    guarded(ctl.simulate_controlled, osc, lambda t, x, v: -gain * v, RES, u_max=u_max, t_end=t_end, n_points=21)


@settings(max_examples=30, deadline=None)
@given(osc=scalar_osc, q_x=extreme, q_v=extreme, r=extreme)
def test_lqr_fuzz(osc, q_x, q_v, r):
    guarded(ctl.lqr, osc, q_x, q_v, r=r)
    guarded(ctl.lqr_closed_form, osc, q_x, q_v, r=r)


@settings(max_examples=20, deadline=None)
@given(
    osc=scalar_osc,
    law=st.sampled_from([*ctl.SEMI_ACTIVE_LAWS, "bogus", 3]),
    omega=extreme,
    Y=extreme,
    c_max=positive,
)
def test_semi_active_response_fuzz(osc, law, omega, Y, c_max):
    guarded(ctl.semi_active_response, osc, law, omega, Y=Y, c_sky=8.0, c_min=0.5, c_max=c_max, t_end=2.0, n_points=21)


@settings(max_examples=15, deadline=None)
@given(osc=scalar_osc, law=st.sampled_from(ctl.SEMI_ACTIVE_LAWS), omega=extreme, Y=extreme, c_max=positive)
def test_semi_active_sweep_fuzz(osc, law, omega, Y, c_max):
    guarded(ctl.semi_active_sweep, osc, law, [omega], Y=Y, c_sky=8.0, c_min=0.5, c_max=c_max, periods=2)


@settings(max_examples=30, deadline=None)
@given(osc=scalar_osc, w=st.one_of(extreme, st.lists(extreme, max_size=4)), c_sky=extreme)
def test_transmissibility_fuzz(osc, w, c_sky):
    guarded(ctl.passive_transmissibility, osc, w)
    guarded(ctl.skyhook_transmissibility, osc, c_sky, w)


@settings(max_examples=30, deadline=None)
@given(osc=scalar_osc, distance=extreme, t_end=extreme, n=st.sampled_from([-1, 0, 2, 11, True, 2.5]))
def test_shaping_fuzz(osc, distance, t_end, n):
    shaper = guarded(ctl.zv_shaper, osc)
    sh = shaper if isinstance(shaper, ctl.Shaper) else None
    guarded(ctl.zvd_shaper, osc)
    guarded(ctl.shaper_residual, sh, osc)
    guarded(ctl.shaped_move, osc, sh, distance, t_end=t_end, n_points=n)


@settings(max_examples=30, deadline=None)
@given(
    x=st.lists(extreme, min_size=0, max_size=6),
    scale=st.sampled_from([1.0, 1e-300, 1e200]),
    ts=extreme,
)
def test_response_metrics_fuzz(x, scale, ts):
    n = len(x)
    t = np.linspace(0.0, 1.0, n) if n else np.array([])
    with np.errstate(over="ignore", invalid="ignore"):
        xa = np.asarray(x, dtype=float) * scale
    guarded(ctl.response_metrics, t, xa, xa, v_rel=xa, t_steady=ts)
    guarded(ctl.residual_amplitude, OSC, t, xa, v=xa, target=ts)


@settings(max_examples=30, deadline=None)
@given(osc=scalar_osc, kp=extreme, kd=extreme)
def test_pd_fuzz(osc, kp, kd):
    guarded(ctl.pd_oscillator, osc, kp, kd)
    guarded(ctl.stabilising_velocity_gain, osc)


@settings(max_examples=20, deadline=None)
@given(law=st.sampled_from([*ctl.SEMI_ACTIVE_LAWS, "x"]), c=extreme, Y=extreme, w=extreme)
def test_semi_active_controller_fuzz(law, c, Y, w):
    f = guarded(ctl.semi_active_controller, law, 8.0, 0.5, c_max=c, Y=Y, omega=w, finite=False)
    if callable(f):
        _finite(guarded(f, 0.1, 0.01, 0.2))


def test_sweep_starts_in_the_linear_steady_state():
    """The ideal skyhook is linear: started in its steady state, one decay time constant of settling is enough."""
    w = np.array([0.7, 1.0, 1.5]) * OSC.natural_frequency
    s = ctl.semi_active_sweep(OSC, "skyhook", w, Y=0.25, c_sky=8.0, c_min=0.5, c_max=15.0, settle=1.0, periods=2)
    assert np.max(np.abs(s.fundamental - ctl.skyhook_transmissibility(OSC, 8.0, w))) < 1e-6
