"""Fuzzing of the Duffing module's public API (issue 20): invalid and extreme inputs.

Every call must either raise :class:`ParameterError` or return a finite result (``nan`` only
where the docstring documents it), and must do so within a time budget: the integrators
carry work budgets (steps, right-hand-side evaluations) and refuse up front what the
stiffness or a long forcing period clearly makes too large.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pytest
from fuzzing import finite, refused, refused_or
from hypothesis import given, settings
from hypothesis import strategies as st

from vibration import ParameterError
from vibration.physics import duffing as D
from vibration.physics.duffing import (
    Duffing,
    backbone,
    duffing_response,
    folds,
    frequency_sweep,
    hb_amplitudes,
    linear_trust_amplitude,
    locate_jump,
    lyapunov_benettin,
    lyapunov_qr,
    periodic_orbit,
    poincare_section,
    response_curve,
    sweep,
)

PAPER = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
SOFT = Duffing(m=1.0, c=0.1, k=20.0, k3=-1.0)

BAD_SCALARS = [math.nan, math.inf, -math.inf, "3", True, 1j, None, [1.0], np.array([1.0, 2.0])]
BAD_ARRAYS = [[], ["a", "b"], [True, False], np.array([1j, 2.0]), [[1.0, 2.0], [3.0]], [math.nan], "1.0", None]
EXTREME = [0.0, 1e-300, 1e-6, 1e6, 1e150, 1e300, -1.0, -1e300]


# ---------------------------------------------------------------------------------- records


@settings(max_examples=30, deadline=None)
@given(field=st.sampled_from(["m", "c", "k", "k3"]), bad=st.sampled_from(BAD_SCALARS))
def test_duffing_record_refuses_bad_fields(field, bad):
    args = {"m": 1.0, "c": 0.5, "k": 20.0, "k3": 2.0, field: bad}
    refused(Duffing, **args, name=field)


# ---------------------------------------------------------------------- closed forms


@settings(max_examples=40, deadline=None)
@given(
    c=st.sampled_from([0.0, 1e-6, 0.5, 1e6, 1e150]),
    k=st.sampled_from([0.0, 1e-6, 20.0, 1e6, 1e150]),
    k3=st.sampled_from([-1e150, -1.0, 0.0, 2.0, 1e150]),
    F0=st.sampled_from(EXTREME),
    omega=st.sampled_from(EXTREME),
)
def test_closed_forms_extreme(c, k, k3, F0, omega):
    try:
        d = Duffing(m=1.0, c=c, k=k, k3=k3)
    except ParameterError:
        return
    refused_or(hb_amplitudes, d, F0, omega)
    refused_or(folds, d, F0, check=lambda f: all(math.isfinite(v) or math.isnan(v) for v in vars(f).values()))
    refused_or(response_curve, d, F0, omega, n=50)
    refused_or(linear_trust_amplitude, d, check=lambda a: not math.isinf(a) or d.k3 == 0)
    refused_or(backbone, d, [0.0, abs(F0)], check=lambda w: bool(np.all(~np.isinf(w))))


@settings(max_examples=20, deadline=None)
@given(bad=st.sampled_from(BAD_ARRAYS + [[-1.0], [math.inf]]))
def test_backbone_refuses_bad_amplitudes(bad):
    refused(backbone, PAPER, bad, name="amplitude")


@settings(max_examples=25, deadline=None)
@given(which=st.sampled_from(["F0", "omega"]), bad=st.sampled_from(BAD_SCALARS + [-1.0]))
def test_hb_functions_refuse_bad_scalars(which, bad):
    args = {"F0": 5.0, "omega": 5.0, which: bad}
    refused(hb_amplitudes, PAPER, args["F0"], args["omega"], name=which)
    if which == "F0":
        refused(folds, PAPER, bad, name="F0")


def test_closed_forms_refuse_wrong_records():
    for fn in (linear_trust_amplitude,):
        refused(fn, "duffing", name="duffing")
    refused(hb_amplitudes, (1.0, 0.5, 20.0, 2.0), 5.0, 5.0, name="duffing")
    refused(response_curve, PAPER, 5.0, 8.0, n=10**9, name="n")
    refused(response_curve, PAPER, 5.0, 8.0, amplitude_max=-1.0, name="amplitude_max")


# ------------------------------------------------------------------------------- sweeps


@settings(max_examples=25, deadline=None)
@given(bad=st.sampled_from(BAD_ARRAYS + [[0.0], [-1.0], [math.inf]]))
def test_sweep_refuses_bad_omegas(bad):
    refused(sweep, PAPER, 5.0, bad, direction="up", name="omegas")


@settings(max_examples=30, deadline=None)
@given(
    which=st.sampled_from(["F0", "x0", "v0", "rtol", "atol", "steady_tol", "max_periods", "direction", "integrator"]),
    bad=st.sampled_from(BAD_SCALARS + [-1.0, 0, 1e9, (1, 2)]),
)
def test_frequency_sweep_refuses_bad_arguments(which, bad):
    kwargs = {which: bad}
    F0 = kwargs.pop("F0", 5.0)
    direction = kwargs.pop("direction", "up")
    if which in ("x0", "v0") and any(bad is v for v in (-1.0, 0, 1e9)):
        return  # valid states
    refused_or(frequency_sweep, PAPER, F0, [5.0], direction=direction, **kwargs)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_sweep_stiff_damping_stops_within_seconds():
    """c = 1e6 used to run for minutes inside the compiled kernel; its budget now stops it inside the loop."""
    msg = refused(frequency_sweep, Duffing(m=1.0, c=1e6, k=20.0, k3=2.0), 5.0, [4.0, 5.0], direction="up")
    assert "max_steps" in msg
    # a small budget: stopped inside the loop, and the frequency named
    msg = refused(frequency_sweep, PAPER, 5.0, np.linspace(3.0, 6.0, 20), direction="up", max_steps=1000)
    assert "omega =" in msg and "max_steps = 1000" in msg
    refused(frequency_sweep, PAPER, 5.0, [3.0], direction="up", integrator="scipy", max_steps=50)


@settings(max_examples=10, deadline=None)
@given(omega=st.sampled_from([1e-300, 1e-12, 1e-6]), c=st.sampled_from([0.5, 1e9, 1e12]))
def test_sweep_tiny_omega_or_huge_damping_refused_up_front(omega, c):
    t0 = time.perf_counter()
    msg = refused(sweep, Duffing(m=1.0, c=c, k=20.0, k3=2.0), 5.0, [omega], direction="up")
    assert "max_steps" in msg
    assert time.perf_counter() - t0 < 0.5


def test_sweep_escaping_softening_spring_is_flagged():
    res = refused_or(frequency_sweep, SOFT, 50.0, [3.0, 4.0], direction="up", check=lambda r: True)
    assert res.escaped.all() and np.isnan(res.amplitude).all()
    res = frequency_sweep(PAPER, 5.0, [4.6, 5.0], direction="up")
    assert not res.escaped.any() and finite(res.amplitude)


def test_locate_jump_bad_inputs_and_budget():
    up = frequency_sweep(PAPER, 5.0, np.linspace(4.6, 5.4, 9), direction="up")
    refused(locate_jump, PAPER, 5.0, "result", name="result")
    refused(locate_jump, PAPER, "5", up, name="F0")
    refused(locate_jump, PAPER, 5.0, up, which=3, name="which")
    refused(locate_jump, PAPER, 5.0, up, levels=9, name="levels")
    refused(locate_jump, PAPER, 5.0, up, n=True, name="n")
    refused(locate_jump, PAPER, 5.0, up, max_periods=2.5, name="max_periods")
    refused(locate_jump, Duffing(m=1.0, c=0.0, k=20.0, k3=2.0), 5.0, up, name="c")


# ----------------------------------------------------------------------------- time responses


@settings(max_examples=25, deadline=None)
@given(
    c=st.sampled_from([0.0, 0.5, 1e6, 1e12]),
    omega=st.sampled_from([0.0, 1e-6, 4.47, 1e6]),
    t_end=st.sampled_from([1.0, 50.0, 6.3e6, 1e300]),
    k3=st.sampled_from([-1.0, 0.0, 2.0]),
    F0=st.sampled_from([0.0, 5.0, 50.0]),
)
def test_duffing_response_extreme(c, omega, t_end, k3, F0):
    out = refused_or(duffing_response, Duffing(m=1.0, c=c, k=20.0, k3=k3), F0, omega, t=[0.0, t_end])
    if out is not None:
        assert out[0].shape == (2,)


def test_duffing_response_refusals():
    msg = refused(duffing_response, Duffing(m=1.0, c=1e6, k=20.0, k3=2.0), 5.0, 4.0, t=[0.0, 50.0])
    assert "right-hand-side evaluations" in msg
    refused(duffing_response, PAPER, 5.0, 1e-6, t=[0.0, 2 * np.pi / 1e-6], name="t")
    msg = refused(duffing_response, SOFT, 50.0, 1e-6, t=np.linspace(0.0, 50.0, 11))
    assert "escaped" in msg
    for bad in BAD_ARRAYS + [[1.0, 0.5], [-1.0, 1.0]]:
        refused(duffing_response, PAPER, 5.0, 4.0, t=bad, name="t")
    refused(duffing_response, PAPER, 5.0, 4.0, t=[0.0, 1.0], sine="yes", name="sine")
    refused(duffing_response, PAPER, 5.0, 4.0, t=[0.0, 1.0], rtol=1.0, name="rtol")


@settings(max_examples=15, deadline=None)
@given(
    c=st.sampled_from([0.5, 1e6]),
    omega=st.sampled_from([1e-6, 5.07, 1e6]),
    guess=st.sampled_from([None, 0.0, 1.0, 1e150]),
)
def test_periodic_orbit_extreme(c, omega, guess):
    refused_or(periodic_orbit, Duffing(m=1.0, c=c, k=20.0, k3=2.0), 5.0, omega, amplitude_guess=guess)


def test_periodic_orbit_refusals():
    msg = refused(periodic_orbit, Duffing(m=1.0, c=1e6, k=20.0, k3=2.0), 5.0, 4.0)
    assert "right-hand-side evaluations" in msg
    refused(periodic_orbit, PAPER, 5.0, 1e-6, name="omega")
    refused(periodic_orbit, PAPER, 5.0, 5.07, x0=1.0, name="v0")
    refused(periodic_orbit, PAPER, 5.0, 5.07, max_iterations=0, name="max_iterations")
    refused(periodic_orbit, Duffing(m=1.0, c=0.0, k=4.0, k3=0.0), 5.0, 2.0, name="omega")  # undamped resonance


# -------------------------------------------------------------------------------- chaos


CHAOS = [poincare_section, lyapunov_qr, lyapunov_benettin]


@settings(max_examples=30, deadline=None)
@given(
    fn=st.sampled_from(CHAOS),
    c=st.sampled_from([0.0, 0.05, 100.0, 1e6]),
    k3=st.sampled_from([-1.0, 1.0]),
    F0=st.sampled_from([0.0, 7.5, 50.0, 1e150]),
    omega=st.sampled_from([1e-6, 1.0, 1e6]),
    x0=st.sampled_from([0.0, 3.0, 1e10]),
)
def test_chaos_tools_extreme(fn, c, k3, F0, omega, x0):
    out = refused_or(fn, Duffing(m=1.0, c=c, k=20.0, k3=k3), F0, omega, x0=x0, v0=0.0, n_periods=50, n_transient=10)
    if out is not None and fn is not poincare_section:
        assert finite(out.exponents) and finite(out.running)


def test_chaos_tools_refusals():
    for fn in CHAOS:
        msg = refused(fn, SOFT, 50.0, 3.0)
        assert "escaped" in msg
        refused(fn, PAPER, 5.0, 1e-6, name="steps_per_period")
        refused(fn, PAPER, 5.0, 3.0, n_periods=10**7, name="n_periods")
        refused(fn, PAPER, 5.0, 3.0, n_periods=100_000, steps_per_period=1000, name="RK4 steps")
        refused(fn, PAPER, 5.0, 3.0, n_transient=-1, name="n_transient")
        refused(fn, PAPER, 5.0, 3.0, steps_per_period=4, name="steps_per_period")
        for bad in BAD_SCALARS:
            refused(fn, PAPER, bad, 3.0)
            refused(fn, PAPER, 5.0, 3.0, x0=bad, v0=0.0, name="x0")
            refused(fn, PAPER, 5.0, 3.0, x0=0.0, v0=bad, name="v0")
    refused(lyapunov_benettin, PAPER, 5.0, 3.0, d0=0.0, name="d0")


def test_lyapunov_strong_damping_isfinite():
    """c T / m = 200: the tangent vectors are renormalised within the period instead of underflowing to log 0."""
    r = lyapunov_qr(Duffing(m=1.0, c=100.0, k=20.0, k3=2.0), 5.0, 3.0, n_periods=100, n_transient=10)
    assert finite(r.exponents)
    assert sum(r.exponents) == pytest.approx(-100.0, rel=2e-3)
    b = lyapunov_benettin(Duffing(m=1.0, c=100.0, k=20.0, k3=2.0), 5.0, 3.0, n_periods=100, n_transient=10)
    assert b.exponents[0] == pytest.approx(r.exponents[0], rel=1e-6)


def test_budgets_are_public_constants():
    assert D.MAX_SWEEP_STEPS > 0 and D.MAX_RK4_STEPS > 0 and D.MAX_RHS_EVALUATIONS > 0
