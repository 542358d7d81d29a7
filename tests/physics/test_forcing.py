"""Loads beyond F0 sin(omega t): each against a closed form, SciPy called directly, or python-control."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.signal import lsim

import vibration
from vibration import (
    BaseMotion,
    Harmonic,
    Oscillator,
    Sampled,
    SineForce,
    Step,
    Unbalance,
    exact_response,
    frequency_response,
    log_decrement,
    magnification,
    peak_response,
    phase_lag,
    settling_time,
    simulate,
    state_space,
    steady_state,
)

OSC = Oscillator(m=1.0, c=0.5, k=20.0)
T = np.linspace(0.0, 12.0, 1201)


def _reference(osc, force_of_t, t, x0=0.0, v0=0.0):
    """SciPy's DOP853 on m x'' + c x' + k x = F(t), at tolerances far below the comparisons'."""
    sol = solve_ivp(
        lambda s, y: (y[1], (force_of_t(s) - osc.c * y[1] - osc.k * y[0]) / osc.m),
        (0.0, t[-1]),
        (x0, v0),
        method="DOP853",
        t_eval=t,
        rtol=1e-12,
        atol=1e-14,
        max_step=0.01,
    )
    return sol.y


@pytest.mark.parametrize("osc", [OSC, Oscillator(m=2.0, c=14.0, k=20.0), Oscillator(m=1.0, c=0.0, k=20.0)])
@pytest.mark.parametrize("phase", [0.0, 0.9, -2.0])
def test_harmonic_with_a_phase_meets_an_independent_integration(osc, phase):
    load = Harmonic(F0=3.0, omega=2.5, phase=phase)
    ref = _reference(osc, lambda s: 3.0 * math.sin(2.5 * s + phase), T, x0=0.05, v0=-0.3)
    r = exact_response(osc, load, T, x0=0.05, v0=-0.3)
    np.testing.assert_allclose(r.x, ref[0], atol=1e-9)
    np.testing.assert_allclose(r.v, ref[1], atol=1e-8)


def test_base_motion_moves_the_mass_through_spring_and_damper():
    """m x'' + c (x' - y') + k (x - y) = 0, integrated as written, y = Y sin(omega t + phase)."""
    Y, w, ph = 0.02, 4.0, 0.4
    osc = OSC

    def rhs(s, q):
        y, yd = Y * math.sin(w * s + ph), Y * w * math.cos(w * s + ph)
        return (q[1], (-osc.c * (q[1] - yd) - osc.k * (q[0] - y)) / osc.m)

    ref = solve_ivp(rhs, (0.0, T[-1]), (0.0, 0.0), method="DOP853", t_eval=T, rtol=1e-12, atol=1e-14).y
    r = exact_response(osc, BaseMotion(Y=Y, omega=w, phase=ph), T)
    np.testing.assert_allclose(r.x, ref[0], atol=1e-10)
    n = simulate(osc, BaseMotion(Y=Y, omega=w, phase=ph), T[-1], n_points=T.size, rtol=1e-10, atol=1e-13)
    np.testing.assert_allclose(n.x, ref[0], atol=1e-8)


@pytest.mark.parametrize("zeta", [0.02, 0.1, 0.3, 0.6])
def test_base_motion_steady_state_is_the_textbook_transmissibility(zeta):
    osc = Oscillator.from_modal(m=3.0, omega_n=5.0, zeta=zeta)
    for r in (0.3, 1.0, 1.7, 4.0):
        w = 5.0 * r
        T_closed = math.sqrt(1 + (2 * zeta * r) ** 2) / math.sqrt((1 - r * r) ** 2 + (2 * zeta * r) ** 2)
        ss = steady_state(osc, BaseMotion.from_acceleration(A=2.0, omega=w))
        assert ss.magnification == pytest.approx(T_closed, rel=1e-13)
        assert ss.amplitude == pytest.approx(2.0 / w**2 * T_closed, rel=1e-13)
        fr = frequency_response(osc, BaseMotion(Y=1.0, omega=1.0), w)
        assert fr.transmitted[0] == pytest.approx(3.0 * w**2 * T_closed, rel=1e-13)  # m omega^2 X: the support's load


@pytest.mark.parametrize("zeta", [0.02, 0.1, 0.25, 0.5])
def test_unbalance_amplitude_and_peak_are_the_textbook_ones(zeta):
    """X = (m_e e / m) r^2 / |D|, peaking at omega_n / sqrt(1 - 2 zeta^2), (m_e e / m) / (2 zeta sqrt(1 - zeta^2))."""
    osc = Oscillator.from_modal(m=40.0, omega_n=37.7, zeta=zeta)
    me, e = 0.3, 0.25
    w = np.linspace(1.0, 150.0, 2001)
    r = w / 37.7
    closed = me * e / 40.0 * r * r / np.hypot(1 - r * r, 2 * zeta * r)
    fr = frequency_response(osc, Unbalance(m_e=me, e=e, omega=1.0), w)
    np.testing.assert_allclose(fr.amplitude, closed, rtol=1e-12)
    np.testing.assert_allclose(fr.transmitted, closed * np.hypot(osc.k, osc.c * w), rtol=1e-12)
    p = peak_response(osc, Unbalance(m_e=me, e=e, omega=1.0))
    assert p.omega == pytest.approx(37.7 / math.sqrt(1 - 2 * zeta**2), rel=1e-12)
    assert p.amplitude == pytest.approx(me * e / 40.0 / (2 * zeta * math.sqrt(1 - zeta**2)), rel=1e-12)
    # and a dense grid finds no larger amplitude
    dense = frequency_response(osc, Unbalance(m_e=me, e=e, omega=1.0), np.linspace(0.5 * p.omega, 2 * p.omega, 20001))
    assert dense.amplitude.max() <= p.amplitude * (1 + 1e-12)


def test_the_three_peaks_differ_as_the_loads_do():
    """A force peaks below omega_n, an unbalance above it, base motion below it (its closed form)."""
    osc = Oscillator.from_modal(m=1.0, omega_n=10.0, zeta=0.2)
    force, unb, base = (peak_response(osc, L) for L in (Harmonic(F0=1, omega=1), Unbalance(m_e=1, e=1, omega=1),
                                                       BaseMotion(Y=1, omega=1)))  # fmt: skip
    assert force.omega == pytest.approx(10.0 * math.sqrt(1 - 2 * 0.04), rel=1e-13)
    assert unb.omega == pytest.approx(10.0 / math.sqrt(1 - 2 * 0.04), rel=1e-13)
    assert base.omega == pytest.approx(10.0 * math.sqrt(math.sqrt(1 + 8 * 0.04) - 1) / (2 * 0.2), rel=1e-13)
    assert force.omega < 10.0 < unb.omega and base.omega < 10.0
    heavy = Oscillator.from_modal(m=1.0, omega_n=10.0, zeta=0.8)
    assert peak_response(heavy, Harmonic(F0=2.0, omega=1.0)).omega == 0.0
    assert peak_response(heavy, Unbalance(m_e=1.0, e=0.5, omega=1.0)).amplitude == pytest.approx(0.5)


@pytest.mark.parametrize(
    "osc", [OSC, Oscillator(m=1.0, c=2 * math.sqrt(20.0), k=20.0), Oscillator(m=1.0, c=30.0, k=20.0)]
)
def test_a_step_is_the_textbook_step_response(osc):
    t0 = 1.5
    r = exact_response(osc, Step(F0=4.0, t0=t0), T)
    ref = _reference(osc, lambda s: 4.0 if s >= t0 else 0.0, T)
    np.testing.assert_allclose(r.x, ref[0], atol=1e-8)
    assert np.all(r.x[T < t0] == 0.0)
    if osc.regime == "underdamped":  # x = F0/k (1 - exp(-sigma s) (cos wd s + sigma/wd sin wd s)), s = t - t0
        s = T[T >= t0] - t0
        sg, wd = osc.decay_rate, osc.damped_natural_frequency
        closed = 4.0 / 20.0 * (1 - np.exp(-sg * s) * (np.cos(wd * s) + sg / wd * np.sin(wd * s)))
        np.testing.assert_allclose(r.x[T >= t0], closed, atol=1e-14)


def test_a_sampled_input_meets_scipy_lsim_and_python_control():
    rng = np.random.default_rng(3)
    ts = np.linspace(0.0, 12.0, 241)
    F = rng.normal(size=ts.size)
    r = exact_response(OSC, Sampled(t=ts, F=F), ts, x0=0.1, v0=0.0)
    ss = state_space(OSC)
    _, _, xout = lsim((ss.A, ss.B, ss.C, ss.D), F, ts, X0=[0.1, 0.0], interp=True)
    np.testing.assert_allclose(r.x, xout[:, 0], atol=1e-12)
    np.testing.assert_allclose(r.v, xout[:, 1], atol=1e-12)
    control = pytest.importorskip("control")
    out = control.forced_response(ss.to_control(), ts, F, X0=[0.1, 0.0])
    np.testing.assert_allclose(r.x, np.asarray(out.outputs)[0], atol=1e-10)
    # between the samples the force is linear: the integrator sees the same input
    n = simulate(OSC, Sampled(t=ts, F=F), 12.0, n_points=241, x0=0.1, rtol=1e-10, atol=1e-13)
    np.testing.assert_allclose(n.x, r.x, atol=1e-8)


def test_a_sampled_input_refuses_what_it_cannot_say():
    with pytest.raises(vibration.ParameterError, match=r"t\[0\] = 1.0 s"):
        Sampled(t=[1.0, 2.0], F=[0.0, 1.0])
    with pytest.raises(vibration.ParameterError, match=r"t\[2\] = 1.0 s is not after"):
        Sampled(t=[0.0, 1.0, 1.0], F=[0.0, 1.0, 2.0])
    with pytest.raises(vibration.ParameterError, match="t has shape .* and F has shape"):
        Sampled(t=[0.0, 1.0], F=[0.0, 1.0, 2.0])
    with pytest.raises(vibration.ParameterError, match="allowed 0 <= t <= 1.0 s"):
        exact_response(OSC, Sampled(t=[0.0, 1.0], F=[0.0, 1.0]), [0.5, 2.0])
    with pytest.raises(vibration.ParameterError, match="beyond the sampled input"):
        simulate(OSC, Sampled(t=[0.0, 1.0], F=[0.0, 1.0]), 2.0)


def test_records_and_results_read_with_units():
    osc = Oscillator.from_modal(m=2.0, omega_n=3.0, zeta=0.25)
    assert (osc.k, osc.c) == pytest.approx((18.0, 3.0), rel=1e-15)
    assert repr(osc) == f"Oscillator(m=2.0 kg, c={osc.c!r} N s/m, k={osc.k!r} N/m)"
    assert "rad/s" in repr(Unbalance(m_e=0.1, e=0.02, omega=3.0)) and " m," in repr(BaseMotion(Y=0.1, omega=1.0))
    assert repr(steady_state(OSC, SineForce(F0=5.0, omega=3.0))).startswith(
        "SteadyState(amplitude=0.450"
    ) and " m/s" in repr(steady_state(OSC, SineForce(F0=5.0, omega=3.0)))
    text = repr(exact_response(OSC, SineForce(F0=5.0, omega=3.0), T))
    assert "1201 samples" in text and " m" in text and "array" not in text
    with pytest.raises(vibration.ParameterError, match="omega_n = 0.0 rad/s"):
        Oscillator.from_modal(m=1.0, omega_n=0.0, zeta=0.1)


def test_a_scalar_frequency_gives_a_float_and_an_array_an_array():
    m, p = magnification(OSC, 3.0), phase_lag(OSC, 3.0)
    assert type(m) is float and type(p) is float
    r = 3.0 / OSC.natural_frequency
    assert m == pytest.approx(1 / math.hypot(1 - r * r, 2 * OSC.damping_ratio * r), rel=1e-15)
    assert isinstance(magnification(OSC, [3.0]), np.ndarray) and magnification(OSC, [3.0]).shape == (1,)
    assert type(vibration.stability.transmissibility(OSC, 3.0)) is float


def test_the_state_space_is_the_oscillator_and_python_control_agrees():
    ss = state_space(OSC)
    eig = np.sort_complex(np.linalg.eigvals(ss.A))
    roots = np.sort_complex(np.roots([OSC.m, OSC.c, OSC.k]))
    np.testing.assert_allclose(eig, roots, rtol=1e-14)
    pytest.importorskip("control")
    sys = ss.to_control()
    np.testing.assert_allclose(np.sort_complex(sys.poles()), roots, rtol=1e-12)
    dc = np.asarray(sys.dcgain())
    assert dc[0] == pytest.approx(1.0 / OSC.k, rel=1e-12)  # x per newton at rest


def test_results_plot_themselves():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    top, bottom = exact_response(OSC, Harmonic(F0=5.0, omega=3.0), T).plot()
    assert len(top.lines) == 1 and "(m)" in top.get_ylabel() and "(s)" in bottom.get_xlabel()
    amp, phase = frequency_response(OSC, Unbalance(m_e=0.1, e=0.1, omega=1.0), np.geomspace(0.5, 50, 200)).plot()
    assert amp.get_yscale() == "log" and "rad/s" in phase.get_xlabel()
    plt.close("all")


def test_a_free_decays_settling_time_comes_from_its_initial_state():
    """Underdamped: the envelope R exp(-sigma t) reaches tol times the initial amplitude sqrt(x0^2 + (v0/wn)^2)."""
    x0, v0 = 0.1, 0.4
    ts = settling_time(OSC, SineForce(F0=0.0, omega=0.0), 0.02, x0=x0, v0=v0)
    sg, wd, wn = OSC.decay_rate, OSC.damped_natural_frequency, OSC.natural_frequency
    R = math.hypot(x0, (v0 + sg * x0) / wd)
    assert ts == pytest.approx(math.log(R / (0.02 * math.hypot(x0, v0 / wn))) / sg, rel=1e-12)


def test_a_decrement_of_noise_is_flagged_and_a_decay_is_not():
    rng = np.random.default_rng(7)
    t = np.linspace(0.0, 20.0, 4001)
    with pytest.warns(RuntimeWarning, match="not resolved from zero"):
        log_decrement(t, rng.normal(size=t.size))
    decay = exact_response(OSC, SineForce(F0=0.0, omega=0.0), t, x0=1.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, zeta = log_decrement(t, decay.x)
    assert zeta == pytest.approx(OSC.damping_ratio, rel=1e-3)


def test_a_pd_loop_keeps_its_static_offset():
    """ki = 0: x settles at kp x_ref / (k + kp); with a force limit the loop still settles there when it can."""
    from vibration.control import pid_response

    for u_max in (None, 5.0):
        r = pid_response(OSC, None, 60.0, ki=0.0, kd=8.0, x_ref=0.1, u_max=u_max, t_end=15.0, n_points=301)
        assert r.x[-1] == pytest.approx(60.0 * 0.1 / (20.0 + 60.0), rel=1e-8)
    assert np.max(np.abs(r.u)) <= 5.0 + 1e-12


def test_loads_are_refused_by_name():
    with pytest.raises(vibration.ParameterError, match="m_e = -1.0 kg"):
        Unbalance(m_e=-1.0, e=0.1, omega=3.0)
    with pytest.raises(vibration.ParameterError, match="force = .* is not a harmonic load"):
        frequency_response(OSC, Step(F0=1.0), [1.0])
    with pytest.raises(vibration.ParameterError, match="c = -0.5 N s/m"):
        peak_response(Oscillator(m=1.0, c=-0.5, k=20.0), Harmonic(F0=1.0, omega=1.0))
