"""Control chapter physics against independent references.

References: exact closed forms (PD is an oscillator; LQR's 2 x 2 Riccati in closed form;
the unlimited PID loop by matrix exponential), third-party solvers (python-control's
``lqr`` against scipy's ``solve_continuous_are``; python-control frequency and forced
responses; solve_ivp with another method and an independently written right-hand side),
and the input-shaping literature (Singer and Seering 1990: ZV/ZVD amplitudes, zero
residual vibration at the design frequency).
"""

from __future__ import annotations

import math

import control
import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp
from scipy.linalg import solve_continuous_are

import vibration
from vibration import Oscillator, SineForce, exact_response
from vibration.physics.control import (
    SPENCER_1997,
    lqr_closed_form,
    passive_transmissibility,
    pd_oscillator,
    pid_linear_response,
    pid_response,
    residual_amplitude,
    response_metrics,
    semi_active_controller,
    semi_active_response,
    semi_active_sweep,
    shaped_move,
    shaper_residual,
    simulate_controlled,
    stabilising_velocity_gain,
)

OSC = Oscillator(m=1.0, c=0.5, k=20.0)
RES = SineForce(F0=5.0, omega=4.47)
WN = OSC.natural_frequency


# ----------------------------------------------------------------------------- public API


def test_public_api_at_top_level():
    for name in ("lqr", "zv_shaper", "zvd_shaper", "skyhook_transmissibility", "simulate_controlled"):
        assert callable(getattr(vibration, name))
    res = vibration.lqr(OSC, 1.0, 0.0, r=1e-3)
    assert res.K.shape == (2,) and res.P.shape == (2, 2) and res.poles.shape == (2,)
    s = vibration.zv_shaper(OSC)
    assert math.isclose(float(np.sum(s.amplitudes)), 1.0, rel_tol=0, abs_tol=1e-15)


# ----------------------------------------------------------------------------- PD, flutter


@pytest.mark.parametrize("seed", range(4))
def test_pd_loop_is_the_oscillator_k_plus_kp_c_plus_kd(seed):
    rng = np.random.default_rng(seed)
    kp, kd = rng.uniform(-15.0, 80.0), rng.uniform(-0.4, 12.0)
    force = SineForce(F0=5.0, omega=rng.uniform(1.0, 8.0))
    sim = simulate_controlled(OSC, lambda t, x, v: -kp * x - kd * v, force, t_end=20.0, n_points=401)
    ex = exact_response(pd_oscillator(OSC, kp, kd), force, sim.t)
    scale = np.max(np.abs(ex.x))
    assert np.max(np.abs(sim.x - ex.x)) < 1e-9 * scale
    assert np.max(np.abs(sim.v - ex.v)) < 1e-8 * np.max(np.abs(ex.v))
    assert_allclose(sim.u, -kp * sim.x - kd * sim.v, rtol=0, atol=1e-12 * (1 + np.max(np.abs(sim.u))))


def test_pd_rejects_a_loop_without_spring(raises_parameter_error):
    with raises_parameter_error("kp", -20.0, "> -20"):
        pd_oscillator(OSC, -20.0, 1.0)


@pytest.mark.parametrize("c", [-0.5, -2.0, -12.0])
def test_smallest_stabilising_velocity_gain_is_exactly_minus_c(c):
    osc = Oscillator(m=1.0, c=c, k=20.0)
    kd = stabilising_velocity_gain(osc)
    assert kd == -c
    for kp in (0.0, 30.0):
        marginal = np.roots([osc.m, osc.c + kd, osc.k + kp])
        assert np.max(np.abs(marginal.real)) == 0.0  # on the imaginary axis (or a double zero root)
        eps = 1e-9 * max(1.0, abs(c))
        assert np.all(np.roots([1.0, c + kd + eps, 20.0 + kp]).real < 0)
        assert np.any(np.roots([1.0, c + kd - eps, 20.0 + kp]).real > 0)


# ----------------------------------------------------------------------------- LQR


def _ab(osc):
    return np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]]), np.array([[0.0], [1.0 / osc.m]])


@pytest.mark.parametrize("seed", range(8))
def test_lqr_matches_scipy_riccati_and_the_closed_form(seed):
    rng = np.random.default_rng(100 + seed)
    osc = Oscillator(m=rng.uniform(0.2, 5.0), c=rng.uniform(-3.0, 20.0), k=rng.uniform(1.0, 200.0))
    q_x, q_v, r = 10 ** rng.uniform(-2, 4), 10 ** rng.uniform(-3, 2), 10 ** rng.uniform(-6, 1)
    res = vibration.lqr(osc, q_x, q_v, r=r)
    A, B = _ab(osc)
    Q = np.diag([q_x, q_v])
    P = solve_continuous_are(A, B, Q, np.array([[r]]))
    K = (B.T @ P / r).ravel()
    assert_allclose(res.P, P, rtol=1e-8, atol=1e-12 * np.max(np.abs(P)))
    assert_allclose(res.K, K, rtol=1e-8)
    assert_allclose(lqr_closed_form(osc, q_x, q_v, r=r), K, rtol=1e-8)
    resid = A.T @ res.P + res.P @ A - res.P @ B @ B.T @ res.P / r + Q
    assert np.max(np.abs(resid)) < 1e-8 * (np.max(np.abs(Q)) + np.max(np.abs(A.T @ res.P)))
    cl = res.closed_loop
    assert_allclose(np.sort_complex(res.poles), np.sort_complex(np.linalg.eigvals(A - B @ K[None, :])), rtol=1e-8)
    assert_allclose(
        np.sort_complex(res.poles), np.sort_complex(np.roots([cl.m, cl.c, cl.k]).astype(complex)), rtol=1e-7
    )
    assert np.all(res.poles.real < 0)


def test_lqr_closed_form_without_cancellation_at_tiny_weights():
    k0, k1 = lqr_closed_form(OSC, 1e-12, 1e-14, r=1.0)
    assert_allclose(k0, 1e-12 / (2 * 20.0), rtol=1e-12)  # sqrt(k^2 + a) - k ~ a / (2k)
    assert_allclose(k1, (1e-14 + 2 * k0) / (2 * 0.5), rtol=1e-9)


def test_lqr_gain_falls_as_control_gets_expensive():
    gains = [vibration.lqr(OSC, 1.0, 0.0, r=r).K for r in (1e-6, 1e-4, 1e-2, 1.0)]
    assert all(a[0] > b[0] and a[1] > b[1] for a, b in zip(gains, gains[1:], strict=False))


@pytest.mark.parametrize(("kwargs", "name"), [({"r": 0.0}, "r"), ({"q_x": -1.0}, "q_x"), ({"q_v": math.nan}, "q_v")])
def test_lqr_bad_weights(kwargs, name, raises_parameter_error):
    args = {"q_x": 1.0, "q_v": 0.0, "r": 1.0} | kwargs
    with raises_parameter_error(name):
        vibration.lqr(OSC, **args)


# ----------------------------------------------------------------------------- PID


@pytest.mark.parametrize("seed", range(3))
def test_unlimited_pid_matches_the_matrix_exponential(seed):
    rng = np.random.default_rng(200 + seed)
    kp, ki, kd = rng.uniform(10, 150), rng.uniform(10, 500), rng.uniform(2, 20)
    x_ref = rng.uniform(-1, 1)
    r = pid_response(OSC, RES, kp, ki=ki, kd=kd, x_ref=x_ref, t_end=20.0, n_points=801)
    x, v, i = pid_linear_response(OSC, RES, kp, ki=ki, kd=kd, t=r.t, x_ref=x_ref)
    assert np.max(np.abs(r.x - x)) < 1e-8 * np.max(np.abs(x))
    assert np.max(np.abs(r.v - v)) < 1e-8 * np.max(np.abs(v))
    assert np.max(np.abs(r.integral - i)) < 1e-8 * np.max(np.abs(i))


def _independent_pid(kp, ki, kd, u_max, mode, x_ref, t):
    """The limited PID loop written again, integrated with Radau (implicit, another method)."""
    tt = math.sqrt(kd / ki)

    def f(time, y):
        e = x_ref - y[0]
        ud = kp * e + ki * y[2] - kd * y[1]
        u = float(np.clip(ud, -u_max, u_max))
        if mode == "none":
            di = e
        elif mode == "clamping":
            di = 0.0 if (abs(ud) > u_max and np.sign(e) == np.sign(ud)) else e
        else:
            di = e + (u - ud) / (ki * tt)
        return [y[1], 5.0 * math.sin(4.47 * time) - 0.5 * y[1] - 20.0 * y[0] + u, di]

    sol = solve_ivp(f, (0, t[-1]), [0, 0, 0], method="Radau", t_eval=t, rtol=1e-11, atol=1e-13, max_step=0.01)
    return sol.y


# one mode in make test, the other two (each a long stiff reference integration) with the slow tests
@pytest.mark.slow  # over 1.5 s: make test-slow runs it
@pytest.mark.parametrize(
    "mode",
    [
        pytest.param("none", marks=pytest.mark.slow),
        "clamping",
        pytest.param("back-calculation", marks=pytest.mark.slow),
    ],
)
def test_limited_pid_agrees_with_an_independent_integration(mode):
    t_end = 8.0
    r = pid_response(
        OSC, RES, 133.6, ki=512.0, kd=18.7, u_max=12.0, anti_windup=mode, x_ref=0.5, t_end=t_end, n_points=161
    )
    ref = _independent_pid(133.6, 512.0, 18.7, 12.0, mode, 0.5, r.t)
    assert np.max(np.abs(r.x - ref[0])) < 1e-6
    assert np.max(np.abs(r.integral - ref[2])) < 1e-6
    assert np.all(np.abs(r.u) <= 12.0) and r.saturated_fraction > 0.0


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_anti_windup_cuts_the_overshoot_and_the_integrator():
    runs = {
        m: pid_response(
            OSC, RES, 133.6, ki=512.0, kd=18.7, u_max=12.0, anti_windup=m, x_ref=0.5, t_end=30.0, n_points=601
        )
        for m in ("none", "clamping", "back-calculation")
    }
    over = {m: np.max(r.x) - 0.5 for m, r in runs.items()}
    assert over["clamping"] < 0.5 * over["none"] and over["back-calculation"] < 0.5 * over["none"]
    wound = {m: np.max(np.abs(r.integral)) for m, r in runs.items()}
    assert wound["clamping"] < wound["none"] / 5


def test_pid_bad_input(raises_parameter_error):
    with raises_parameter_error("anti_windup", "conditional", "clamping"):
        pid_response(OSC, RES, 1.0, ki=1.0, kd=1.0, anti_windup="conditional")
    with raises_parameter_error("ki", -1.0, ">= 0"):
        pid_response(OSC, RES, 1.0, ki=-1.0, kd=1.0)
    with raises_parameter_error("u_max", -1.0, "> 0"):
        pid_response(OSC, RES, 1.0, ki=1.0, kd=1.0, u_max=-1.0)


# ----------------------------------------------------------------------------- simulation API


def test_force_limit_clips_the_demand():
    r = simulate_controlled(OSC, lambda t, x, v: -200.0 * v, RES, u_max=2.0, t_end=5.0, n_points=501)
    assert np.max(np.abs(r.u)) == 2.0 and np.max(np.abs(r.u_demand)) > 2.0


def test_controller_output_is_validated(raises_parameter_error):
    with raises_parameter_error("controller", math.nan, "finite"):
        simulate_controlled(OSC, lambda t, x, v: math.nan, RES, t_end=1.0, n_points=3)
    with raises_parameter_error("controller", "push", "finite"):
        simulate_controlled(OSC, lambda t, x, v: "push", RES, t_end=1.0, n_points=3)
    with raises_parameter_error("controller", 3.0, "callable"):
        simulate_controlled(OSC, 3.0, RES)
    with raises_parameter_error("base", 0.25):
        simulate_controlled(OSC, lambda t, x, v: 0.0, base=0.25)


# ----------------------------------------------------------------------------- skyhook


def _ss_base(osc, c_sky):
    """State space from base displacement y to x: x'' = (-k (x - y) - c (x' - y') - c_sky x') / m."""
    m, c, k = osc.m, osc.c, osc.k
    # with q = x - (c/m) y as second state variable form: use the transfer function directly
    return control.tf([c, k], [m, c + c_sky, k])


@pytest.mark.parametrize("c_sky", [0.0, 2.0, 8.0, 40.0])
def test_skyhook_transmissibility_matches_python_control(c_sky):
    w = np.geomspace(0.05, 50.0, 301) * WN
    mag = np.abs(_ss_base(OSC, c_sky)(1j * w))
    assert_allclose(vibration.skyhook_transmissibility(OSC, c_sky, w), mag, rtol=1e-12)
    if c_sky == 0.0:
        assert_allclose(passive_transmissibility(OSC, w), mag, rtol=1e-12)


def test_skyhook_cross_checks_the_stability_chapter():
    w = np.linspace(0.1, 20.0, 97)
    assert_allclose(vibration.skyhook_transmissibility(OSC, 0.0, w), vibration.transmissibility(OSC, w), rtol=1e-12)


@pytest.mark.parametrize("c_sky", [4.5, 8.0, 20.0])
def test_skyhook_is_below_every_passive_curve_at_resonance(c_sky):
    t_sky = float(vibration.skyhook_transmissibility(OSC, c_sky, WN))
    # passive: T(wn; c) = sqrt(1 + (k / (c wn))^2) > 1 for every c; sample c densely up to 1e6 N s/m
    cs = np.geomspace(1e-3, 1e6, 2001)
    t_pass = np.array([passive_transmissibility(Oscillator(m=1.0, c=c, k=20.0), WN) for c in cs])
    assert np.all(t_pass > 1.0) and t_sky < 1.0 and t_sky < t_pass.min()


def test_skyhook_bad_input(raises_parameter_error):
    with raises_parameter_error("c_sky", -1.0, ">= 0"):
        vibration.skyhook_transmissibility(OSC, -1.0, [1.0])
    with raises_parameter_error("omegas", -2.0):
        vibration.skyhook_transmissibility(OSC, 1.0, [1.0, -2.0])


# ----------------------------------------------------------------------------- semi-active kernel


@pytest.mark.parametrize("law", ["passive", "skyhook"])
def test_semi_active_kernel_reproduces_the_linear_closed_forms(law):
    w = np.array([0.5, 1.0, 1.7, 3.0]) * WN
    s = semi_active_sweep(OSC, law, w, Y=0.25, c_sky=8.0, c_min=1.5, c_max=15.0, periods=4)
    exact = (
        passive_transmissibility(Oscillator(m=1.0, c=2.0, k=20.0), w)
        if law == "passive"
        else vibration.skyhook_transmissibility(OSC, 8.0, w)
    )
    assert_allclose(s.fundamental, exact, rtol=1e-6)  # RK4 at 1000 steps per period
    assert_allclose(s.peak, exact, rtol=2e-5)  # max of samples of a sine: 1000 samples per period


def test_on_off_kernel_converges_with_the_step():
    """The on-off law switches the force discontinuously, which solve_ivp grinds through; check RK4 by refinement."""
    Y, w = 0.25, 1.1 * WN
    runs = [
        semi_active_response(OSC, "on-off", w, Y=Y, c_sky=8.0, c_min=0.5, c_max=15.0, t_end=6.0, n_points=61,
                             steps_per_period=n)
        for n in (2000, 16000)
    ]  # fmt: skip
    assert np.max(np.abs(runs[0].x - runs[1].x)) < 5e-3 * Y  # first order at the switches


@pytest.mark.parametrize(("law", "tol", "rtol"), [("clipped", 1e-6, 1e-10)])
def test_semi_active_kernel_agrees_with_solve_ivp_on_the_callable(law, tol, rtol):
    Y, w = 0.25, 1.1 * WN
    rk4 = semi_active_response(OSC, law, w, Y=Y, c_sky=8.0, c_min=0.5, c_max=15.0, t_end=6.0, n_points=61)
    ctl = semi_active_controller(law, 8.0, 0.5, c_max=15.0, Y=Y, omega=w)
    ref = simulate_controlled(OSC, ctl, base=(Y, w), t_end=6.0, n_points=61, rtol=rtol, atol=1e-12)
    assert np.max(np.abs(rk4.x - ref.x)) < tol * Y
    assert np.max(np.abs(rk4.f - ref.u)) < 50 * tol * np.max(np.abs(ref.u))


def _mr_reference(d, law_on, Y, w, t):
    """Base-excited mass with the modified Bouc-Wen damper, written again, integrated with LSODA."""

    def f(time, s):
        x, v, z, y, u = s
        xb, vb = Y * math.sin(w * time), Y * w * math.cos(w * time)
        xr, vr = x - xb, v - vb
        c0, c1, alpha = d.c0a + d.c0b * u, d.c1a + d.c1b * u, d.alpha_a + d.alpha_b * u
        dy = (alpha * z + c0 * vr + d.k0 * (xr - y)) / (c0 + c1)
        dd = vr - dy
        dz = -d.gamma * abs(dd) * z * abs(z) - d.beta * dd * z * z + d.A * dd
        force = c1 * dy + d.k1 * xr
        cmd = d.v_max if (law_on and v * vr > 0) else 0.0
        return [v, -20.0 * xr - 0.5 * vr - force, dz, dy, -d.eta * (u - cmd)]

    sol = solve_ivp(f, (0, t[-1]), [0.0] * 5, method="LSODA", t_eval=t, rtol=1e-9, atol=1e-12, max_step=1e-3)
    assert sol.status == 0
    return sol.y


def test_mr_damper_kernel_agrees_with_an_independent_integration():
    Y, w = 0.25, WN
    d = SPENCER_1997.scaled(Y / 0.015, 10.0 / SPENCER_1997.yield_force)
    rk4 = semi_active_response(OSC, "mr", w, Y=Y, c_sky=8.0, damper=d, t_end=4.0, n_points=41, dt_max=5e-5)
    ref = _mr_reference(d, True, Y, w, rk4.t)
    assert np.max(np.abs(rk4.x - ref[0])) < 2e-4 * Y
    assert np.max(np.abs(rk4.command - ref[4])) < 2e-2 * d.v_max


def test_mr_scaling_is_a_similitude():
    d = SPENCER_1997.scaled(length=3.0, force=0.01)
    assert math.isclose(d.yield_force, 0.01 * SPENCER_1997.yield_force, rel_tol=1e-12)
    assert math.isclose(d.z_max, 3.0 * SPENCER_1997.z_max, rel_tol=1e-12)
    assert math.isclose(d.c1a, SPENCER_1997.c1a * 0.01 / 3.0, rel_tol=1e-12)
    assert SPENCER_1997.c0a == 2100.0 and SPENCER_1997.gamma == 3.63e6 and SPENCER_1997.A == 301.0  # Spencer 1997 in SI


def test_clipped_skyhook_beats_every_passive_damper_at_resonance_and_keeps_isolation():
    w = np.array([1.0, 1.5, 2.0, 3.0]) * WN
    s = semi_active_sweep(OSC, "clipped", w, Y=0.25, c_sky=8.0, c_min=0.5, c_max=15.0)
    assert s.peak[0] < 1.0  # every passive c gives T(wn) > 1 (see the skyhook test)
    soft = passive_transmissibility(Oscillator(m=1.0, c=1.0, k=20.0), w[1:])
    assert np.all(s.peak[1:] <= soft * 1.001)


def test_semi_active_bad_input(raises_parameter_error):
    with raises_parameter_error("law", "bang-bang", "on-off"):
        semi_active_sweep(OSC, "bang-bang", [1.0], Y=0.25)
    with raises_parameter_error("c_max", 0.1, ">= 0.5"):
        semi_active_sweep(OSC, "clipped", [1.0], Y=0.25, c_min=0.5, c_max=0.1)
    with raises_parameter_error("c + c_min"):
        semi_active_sweep(Oscillator(m=1.0, c=0.0, k=20.0), "clipped", [1.0], Y=0.25, c_min=0.0, c_max=1.0)


# ----------------------------------------------------------------------------- input shaping


@pytest.mark.parametrize("make", [vibration.zv_shaper, vibration.zvd_shaper])
def test_shaper_amplitudes_and_zero_residual_at_the_design_frequency(make):
    for c in (0.0, 0.5, 3.0):
        osc = Oscillator(m=1.0, c=c, k=20.0)
        s = make(osc)
        assert math.isclose(float(np.sum(s.amplitudes)), 1.0, abs_tol=1e-15)
        assert np.all(s.amplitudes > 0) and s.times[0] == 0.0
        t, x, v, _ = shaped_move(osc, s, 0.1, t_end=12.0, n_points=1201)
        after = t > s.duration + 1e-9
        assert np.max(residual_amplitude(osc, t[after], x[after], v=v[after], target=0.1)) < 1e-12


@pytest.mark.parametrize("ratio", [0.7, 0.9, 1.05, 1.2, 1.5])
def test_residual_formula_matches_the_simulated_move(ratio):
    actual = Oscillator(m=1.0, c=0.5, k=20.0 * ratio**2)
    for s in (vibration.zv_shaper(OSC), vibration.zvd_shaper(OSC)):
        t, x, v, _ = shaped_move(actual, s, 0.1, t_end=8.0, n_points=801)
        t0, x0, v0, _ = shaped_move(actual, None, 0.1, t_end=8.0, n_points=801)
        after = t > s.duration + 1e-9
        ratio_sim = (
            residual_amplitude(actual, t, x, v=v, target=0.1)[after]
            / residual_amplitude(actual, t0, x0, v=v0, target=0.1)[after]
        )
        # Singer and Seering compare with the unshaped ringing t_N earlier (each just after its last impulse)
        ratio_sim *= math.exp(-actual.decay_rate * s.duration)
        assert_allclose(ratio_sim, shaper_residual(s, actual), rtol=1e-9)


def test_shaped_move_matches_python_control_forced_response():
    s = vibration.zvd_shaper(OSC)
    t, x, _, u = shaped_move(OSC, s, 0.2, t_end=6.0, n_points=60001)
    sys = control.tf([1.0], [OSC.m, OSC.c, OSC.k])
    ref = control.forced_response(sys, T=t, U=u).outputs
    assert np.max(np.abs(x - ref)) < 5e-4 * 0.2  # lsim interpolates the staircase over one 1e-4 s sample


def test_zvd_is_flat_at_the_design_frequency_and_zv_is_not():
    def v_at(shaper, ratio):
        return shaper_residual(shaper, Oscillator(m=1.0, c=0.5, k=20.0 * ratio**2))

    h = 1e-3
    zv, zvd = vibration.zv_shaper(OSC), vibration.zvd_shaper(OSC)
    assert v_at(zvd, 1 + h) < 1e-5 and v_at(zvd, 1 - h) < 1e-5  # quadratic: V ~ h^2
    assert v_at(zv, 1 + h) > 1e-3  # linear: V ~ (pi/2) h


def test_shaper_needs_an_underdamped_oscillator(raises_parameter_error):
    with raises_parameter_error("osc.c", 15.0, "underdamped"):
        vibration.zv_shaper(Oscillator(m=1.0, c=15.0, k=20.0))


# ----------------------------------------------------------------------------- metrics


def test_metrics_of_a_known_signal():
    t = np.linspace(0.0, 4 * np.pi, 40001)
    m = response_metrics(t, 0.3 * np.sin(t), 2.0 * np.cos(t), v_rel=np.cos(t), t_steady=2 * np.pi)
    assert_allclose([m.peak_x, m.rms_x, m.peak_x_ss, m.rms_x_ss], [0.3, 0.3 / 2**0.5, 0.3, 0.3 / 2**0.5], rtol=1e-6)
    assert_allclose([m.peak_u, m.rms_u, m.energy], [2.0, 2**0.5, 4 * np.pi], rtol=1e-6)


def test_metrics_bad_input(raises_parameter_error):
    with raises_parameter_error("t_steady", 9.0):
        response_metrics([0.0, 1.0, 2.0], [0, 0, 0], [0, 0, 0], v_rel=[0, 0, 0], t_steady=9.0)


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_a_stiff_mr_damper_run_is_refined_instead_of_overflowing():
    """A heavy, stiff plant drives the MR damper's Bouc-Wen state faster than dt_max resolves: the sweep and
    the single run shorten their step (a quarter, twice at most) and agree with a run given the short step."""
    from vibration import SPENCER_1997, SPENCER_1997_STROKE, semi_active_response, semi_active_sweep

    osc, w, Y = vibration.Oscillator(m=4.0, c=4.0, k=400.0), 9.020284133645712, 0.1
    damper = SPENCER_1997.scaled(Y / SPENCER_1997_STROKE, 10.0 / SPENCER_1997.yield_force)
    auto = semi_active_sweep(osc, "mr", [w], Y=Y, damper=damper, periods=4)
    short = semi_active_sweep(osc, "mr", [w], Y=Y, damper=damper, periods=4, dt_max=2e-4 / 16)
    assert np.isfinite(auto.peak[0]) and auto.peak[0] == pytest.approx(short.peak[0], rel=1e-6)
    run = semi_active_response(osc, "mr", w, Y=Y, damper=damper, t_end=5.0)
    assert np.all(np.isfinite(run.x))
