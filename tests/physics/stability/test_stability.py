"""Stability chapter physics: every closed form against an independent method.

References used: numpy.roots and python-control (poles, frequency response, step_info),
the library's exact closed form (exact_response) on fine grids, scipy.signal.lsim
(base excitation in the time domain), scipy.integrate.quad of |H|^2 and the Lyapunov
equation (white-noise variance), and a seeded Monte Carlo simulation.
"""

from __future__ import annotations

import math

import control
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy import signal
from scipy.integrate import quad
from scipy.linalg import solve_continuous_lyapunov

import vibration
from vibration import Oscillator, SineForce, exact_response
from vibration.physics import stability as stab

PAPER = {"low": 0.1, "nominal": 0.5, "high": 15.0}  # N s/m, m = 1 kg, k = 20 N/m


def osc_of(zeta: float, m: float = 1.0, k: float = 20.0) -> Oscillator:
    return Oscillator(m=m, c=2.0 * zeta * math.sqrt(k * m), k=k)


masses = st.floats(1e-2, 1e2)
stiffnesses = st.floats(1e-1, 1e4)
ratios = st.floats(1e-3, 20.0)


# ----------------------------------------------------------------------------- public API at the top level


def test_public_api_is_at_the_top_level():
    for name in ("poles", "transmissibility", "step_metrics", "white_noise_variance", "stability_class"):
        assert getattr(vibration, name) is getattr(stab, name)
    assert vibration.stability is stab  # the rest of the chapter's names are in its namespace


# ----------------------------------------------------------------------------- poles and stability


@given(m=masses, k=stiffnesses, zeta=st.floats(-5.0, 5.0))
def test_poles_match_numpy_roots_and_vieta(m, k, zeta):
    osc = osc_of(zeta, m, k)
    p = stab.poles(osc)
    ref = np.roots([osc.m, osc.c, osc.k])
    scale = math.sqrt(k / m) * max(1.0, abs(zeta))
    assert np.max(np.abs(np.sort_complex(p) - np.sort_complex(ref))) <= 1e-7 * scale
    # Vieta, relative to each quantity: product k/m, sum -c/m
    assert (p[0] * p[1]).real == pytest.approx(k / m, rel=1e-12)
    assert (p[0] + p[1]).real == pytest.approx(-osc.c / m, rel=1e-12, abs=1e-14 * scale)
    assert p[0].real >= p[1].real


def test_poles_match_python_control():
    for c in (0.1, 0.5, 15.0, 0.0, -0.3, 2.0 * math.sqrt(20.0)):
        osc = Oscillator(m=1.0, c=c, k=20.0)
        ref = control.poles(control.tf([1.0], [osc.m, osc.c, osc.k]))
        np.testing.assert_allclose(np.sort_complex(stab.poles(osc)), np.sort_complex(ref), rtol=0, atol=1e-7)


def test_overdamped_small_pole_has_no_cancellation():
    osc = Oscillator(m=1.0, c=1e8, k=1.0)  # slow pole -k/c = -1e-8 1/s, lost by the textbook formula
    assert stab.poles(osc)[0].real == pytest.approx(-1e-8, rel=1e-12)


def test_stability_classes():
    s = stab.stability_class(Oscillator(m=1.0, c=0.1, k=20.0))
    assert (s.asymptotic, s.lyapunov, s.bibo, s.verdict) == (True, True, True, "asymptotically stable")
    assert s.spectral_abscissa == pytest.approx(-0.05, rel=1e-15)
    s = stab.stability_class(Oscillator(m=1.0, c=0.0, k=20.0))
    assert (s.asymptotic, s.lyapunov, s.bibo, s.verdict) == (False, True, False, "marginally stable")
    assert s.spectral_abscissa == 0.0 and math.copysign(1.0, s.spectral_abscissa) == 1.0
    s = stab.stability_class(Oscillator(m=1.0, c=-0.2, k=20.0))
    assert (s.asymptotic, s.lyapunov, s.bibo, s.verdict) == (False, False, False, "unstable")
    assert s.spectral_abscissa == pytest.approx(0.1, rel=1e-15)
    s = stab.stability_class(Oscillator(m=1.0, c=-20.0, k=20.0))  # real positive roots
    assert s.spectral_abscissa == pytest.approx(10.0 + math.sqrt(80.0), rel=1e-14)


# ----------------------------------------------------------------------------- growth


@pytest.mark.parametrize(
    ("c", "omega"),
    [(0.1, 4.47), (0.5, 3.0), (0.0, math.sqrt(20.0)), (0.0, 3.0), (-0.1, 4.47), (-0.5, 3.0)],
)
def test_growth_envelope_bounds_and_touches_the_exact_response(c, omega):
    osc, force = Oscillator(m=1.0, c=c, k=20.0), SineForce(F0=5.0, omega=omega)
    t = np.linspace(0.0, 60.0, 120001)
    x = exact_response(osc, force, t).x
    env = stab.growth_envelope(osc, force, t)
    assert np.all(np.abs(x) <= env * (1.0 + 1e-12) + 1e-12)
    # touches: in the last 10 s the response comes within 1 % of its envelope
    tail = t > 50.0
    assert np.max(np.abs(x[tail]) / env[tail]) > 0.99


def test_linear_growth_rate_at_undamped_resonance():
    osc = Oscillator(m=1.0, c=0.0, k=20.0)
    force = SineForce(F0=5.0, omega=osc.natural_frequency)
    t = np.array([1e4, 2e4])
    env = stab.growth_envelope(osc, force, t)
    slope = (env[1] - env[0]) / 1e4
    assert slope == pytest.approx(5.0 / (2.0 * osc.natural_frequency), rel=1e-9)  # F0 / (2 m omega_n), m/s


def test_exponential_growth_rate_with_negative_damping():
    osc = Oscillator(m=1.0, c=-0.2, k=20.0)
    env = stab.growth_envelope(osc, SineForce(F0=5.0, omega=3.0), np.array([400.0, 410.0]))
    rate = math.log(env[1] / env[0]) / 10.0  # the steady part is exp(-40) of the transient by then
    assert rate == pytest.approx(0.1, rel=1e-12)


@pytest.mark.parametrize("c", [15.0, 2.0 * math.sqrt(20.0), -2.0 * math.sqrt(20.0), -12.0, -100.0])
def test_growth_envelope_with_real_roots_bounds_the_exact_response(c):
    """|zeta| >= 1, either sign: |H| + |free part| bounds |x|, and grows like exp(s1 t) when c <= -c_crit."""
    osc, force = Oscillator(m=1.0, c=c, k=20.0), SineForce(F0=5.0, omega=4.47)
    s1 = float(stab.poles(osc)[0].real)
    t_end = 5.0 if s1 <= 0.0 else min(5.0, 30.0 / s1)
    t = np.linspace(0.0, t_end, 20001)
    x = exact_response(osc, force, t).x
    env = stab.growth_envelope(osc, force, t)
    assert np.all(np.abs(x) <= env * (1.0 + 1e-9) + 1e-12)
    if s1 > 0.0:  # the free part dominates: the bound is tight at the end and grows at s1
        assert abs(x[-1]) / env[-1] > 0.99
        rate = math.log(env[-1] / env[-2]) / (t[-1] - t[-2])
        if abs(stab.poles(osc)[1] - s1) < 1e-6 * s1:  # double root: x ~ (a + b t) exp(s1 t)
            assert s1 < rate < s1 + 2.0 / t[-1]
        else:
            assert rate == pytest.approx(s1, rel=1e-3)


def test_growth_envelope_bad_input(raises_parameter_error):
    with raises_parameter_error("t", -1.0):
        stab.growth_envelope(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), [0.0, -1.0])
    with raises_parameter_error("force"):
        stab.growth_envelope(Oscillator(m=1.0, c=0.5, k=20.0), 3.0, [0.0])


# ----------------------------------------------------------------------------- transmissibility


def _t_direct(osc, w):
    """|(k + i c w) / (k - m w^2 + i c w)|, the complex ratio written directly."""
    w = np.asarray(w, dtype=float)
    return np.abs((osc.k + 1j * osc.c * w) / (osc.k - osc.m * w * w + 1j * osc.c * w))


@given(m=masses, k=stiffnesses, zeta=ratios, r=st.floats(0.0, 50.0))
def test_transmissibility_matches_the_complex_ratio(m, k, zeta, r):
    osc = osc_of(zeta, m, k)
    w = r * osc.natural_frequency
    assert stab.transmissibility(osc, w) == pytest.approx(float(_t_direct(osc, w)), rel=1e-12)


def test_transmissibility_matches_python_control():
    w = np.geomspace(0.05, 200.0, 400)
    for c in (0.1, 0.5, 15.0, 3.0):
        osc = Oscillator(m=1.0, c=c, k=20.0)
        resp = control.frequency_response(control.tf([osc.c, osc.k], [osc.m, osc.c, osc.k]), w)
        np.testing.assert_allclose(stab.transmissibility(osc, w), np.abs(resp.complex), rtol=1e-11)


def test_transmissibility_in_the_time_domain():
    """Base motion y = sin(w t) through m x'' + c x' + k x = c y' + k y (scipy.signal.lsim): the steady amplitude."""
    for c, w in ((0.5, 3.0), (15.0, 13.4), (2.0, 4.47), (0.5, 9.0)):
        osc = Oscillator(m=1.0, c=c, k=20.0)
        t = np.linspace(0.0, 60.0, 12001)
        _, x, _ = signal.lsim(signal.lti([osc.c, osc.k], [osc.m, osc.c, osc.k]), np.sin(w * t), t)
        tail = t > 40.0  # transient below exp(-10) of its start
        fit = np.linalg.lstsq(np.column_stack([np.sin(w * t[tail]), np.cos(w * t[tail])]), x[tail], rcond=None)[0]
        # lsim holds the input linearly between samples: amplitude error about (w dt)^2 / 12
        dt = t[1] - t[0]
        assert math.hypot(*fit) == pytest.approx(stab.transmissibility(osc, w), rel=(w * dt) ** 2 / 6)


@pytest.mark.parametrize("zeta", [0.0, 1e-6, 0.011, 0.0559, 0.3, 1.0, 1.677, 50.0])
def test_all_curves_cross_one_at_sqrt2_omega_n(zeta):
    osc = osc_of(zeta)
    w_iso = stab.isolation_frequency(osc)
    assert w_iso == pytest.approx(math.sqrt(2.0 * 20.0), rel=1e-15)
    assert stab.transmissibility(osc, w_iso) == pytest.approx(1.0, abs=4e-15)


def test_damping_helps_below_and_hurts_above_the_crossing():
    zetas = np.geomspace(1e-3, 10.0, 60)
    r = np.array([0.5, 1.0, 1.3, 1.5, 2.0, 3.0, 10.0])
    table = np.array([stab.transmissibility(osc_of(z), r * math.sqrt(20.0)) for z in zetas])
    assert np.all(np.diff(table[:, r < math.sqrt(2)], axis=0) < 0)  # more damping transmits less
    assert np.all(np.diff(table[:, r > math.sqrt(2)], axis=0) > 0)  # more damping transmits more


def test_transmissibility_shapes_and_limits():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    assert isinstance(stab.transmissibility(osc, 3.0), float)
    with pytest.raises(vibration.ParameterError, match="omegas has shape"):  # 1-D grids only (issue 32)
        stab.transmissibility(osc, np.ones((2, 3)))
    assert stab.transmissibility(osc, 0.0) == 1.0
    far = stab.transmissibility(osc, 1e200)  # no overflow: T -> 2 zeta omega_n / omega
    assert far == pytest.approx(2.0 * osc.damping_ratio * osc.natural_frequency / 1e200, rel=1e-12)
    assert stab.transmissibility(Oscillator(m=1.0, c=0.0, k=4.0), 2.0) == math.inf
    heavy = Oscillator(m=1.0, c=1e150, k=1.0)  # zeta = 5e149: T = 1 until r ~ 2 zeta, then 2 zeta / r
    assert stab.transmissibility(heavy, 1e10) == 1.0
    assert stab.transmissibility(heavy, 1e200) == pytest.approx(1e-50, rel=1e-12)


def test_peak_transmissibility_and_magnification_against_a_fine_grid():
    for c in (0.1, 0.5, 3.0, 6.0, 15.0):
        osc = Oscillator(m=1.0, c=c, k=20.0)
        w = np.linspace(0.0, 3.0 * osc.natural_frequency, 600001)
        wp, tp = stab.peak_transmissibility(osc)
        t = stab.transmissibility(osc, w)
        assert tp == pytest.approx(np.max(t), rel=1e-9) and tp >= np.max(t) * (1 - 1e-15)
        assert wp == pytest.approx(w[np.argmax(t)], abs=2 * (w[1] - w[0]) + 1e-3 * osc.damping_ratio)
        wg, g = stab.peak_magnification(osc)
        mag = vibration.magnification(osc, w)
        assert g == pytest.approx(np.max(mag), rel=1e-9)
        assert float(vibration.magnification(osc, [wg])[0]) == pytest.approx(g, rel=1e-13)


def test_transmissibility_bad_input(raises_parameter_error):
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    with raises_parameter_error("omegas", -1.0, ">= 0"):
        stab.transmissibility(osc, [1.0, -1.0])
    with raises_parameter_error("omegas", math.nan):
        stab.transmissibility(osc, math.nan)
    with raises_parameter_error("omegas"):
        stab.transmissibility(osc, "fast")
    with raises_parameter_error("osc"):
        stab.transmissibility((1.0, 0.5, 20.0), [1.0])


# ----------------------------------------------------------------------------- step response


def _exact_step(osc, t):
    """1 - free response from x0 = 1 (exact_response), the library's own closed form."""
    return 1.0 - exact_response(osc, SineForce(F0=0.0, omega=0.0), t, x0=1.0).x


@pytest.mark.parametrize("zeta", [0.0, 0.011, 0.0559, 0.5, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.677, 40.0])
def test_step_response_matches_the_exact_free_response(zeta):
    osc = osc_of(zeta)
    t = np.linspace(0.0, 30.0, 3001)
    np.testing.assert_allclose(stab.step_response(osc, t), _exact_step(osc, t), rtol=0, atol=1e-12)


@given(zeta=st.floats(0.005, 0.9))
def test_overshoot_formula(zeta):
    osc = osc_of(zeta)
    s = stab.step_metrics(osc)
    assert s.overshoot == pytest.approx(math.exp(-math.pi * zeta / math.sqrt(1 - zeta * zeta)), rel=1e-13)
    assert s.peak_time == pytest.approx(math.pi / osc.damped_natural_frequency, rel=1e-14)
    # the exact response on a fine grid around the peak reaches 1 + overshoot at the peak time
    t = s.peak_time * np.linspace(0.9, 1.1, 20001)
    y = _exact_step(osc, t)
    assert np.max(y) == pytest.approx(s.peak, rel=1e-12)
    assert t[np.argmax(y)] == pytest.approx(s.peak_time, abs=2 * (t[1] - t[0]))


@pytest.mark.parametrize("zeta", [0.011, 0.0559, 0.2, 0.5, 0.7, 0.78, 0.9, 1.0, 1.3, 1.677, 5.0])
def test_step_metrics_against_a_fine_exact_grid(zeta):
    """Rise time and the true last exit from the 2 % band, located on a fine grid of the exact response."""
    osc = osc_of(zeta)
    s = stab.step_metrics(osc)
    t_end = s.settling_time * 1.5 + 1.0
    t = np.linspace(0.0, t_end, 400001)
    dt = t[1] - t[0]
    y = _exact_step(osc, t)
    outside = np.nonzero(np.abs(y - 1.0) > 0.02)[0]
    assert abs(t[outside[-1]] - s.settling_time) <= dt
    assert abs(float(stab.step_response(osc, s.settling_time)) - 1.0) == pytest.approx(0.02, abs=1e-12)
    t10, t90 = t[np.argmax(y >= 0.1)], t[np.argmax(y >= 0.9)]
    assert abs((t90 - t10) - s.rise_time) <= 2 * dt
    if zeta >= 1.0:
        assert s.overshoot == 0.0 and s.peak_time == math.inf and np.all(np.diff(y) >= -1e-15)
    else:
        assert np.max(y) - 1.0 == pytest.approx(s.overshoot, abs=1e-6)


@pytest.mark.parametrize("zeta", [0.0559, 0.3, 0.6, 1.0, 1.677])
def test_step_metrics_match_python_control_step_info(zeta):
    osc = osc_of(zeta)
    s = stab.step_metrics(osc)
    t = np.linspace(0.0, 1.5 * s.settling_time + 1.0, 20001)
    info = control.step_info(control.tf([osc.k], [osc.m, osc.c, osc.k]), T=t, SettlingTimeThreshold=0.02)
    dt = t[1] - t[0]
    curvature = osc.natural_frequency**2 * (1.0 + s.overshoot)  # |y''| near the peak, 1/s^2
    assert info["Overshoot"] / 100.0 == pytest.approx(s.overshoot, abs=curvature * dt * dt / 8 + 1e-12)
    assert info["RiseTime"] == pytest.approx(s.rise_time, abs=2 * dt)
    assert info["SettlingTime"] == pytest.approx(s.settling_time, abs=2 * dt)
    if zeta < 1.0:
        assert info["PeakTime"] == pytest.approx(s.peak_time, abs=2 * dt)


def test_true_settling_is_not_the_envelope():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    s = stab.step_metrics(osc)
    zeta = osc.damping_ratio
    envelope = -math.log(0.02 * math.sqrt(1 - zeta * zeta)) / osc.decay_rate
    assert envelope - math.pi / osc.damped_natural_frequency <= s.settling_time < envelope


@pytest.mark.parametrize("zeta", [1e-9, 1e-6, 1e-4, 1e3])
def test_step_metrics_extreme_damping(zeta):
    osc = osc_of(zeta)
    s = stab.step_metrics(osc)
    assert math.isfinite(s.settling_time) and s.settling_time > 0.0
    assert abs(float(stab.step_response(osc, s.settling_time)) - 1.0) == pytest.approx(0.02, rel=1e-6)
    if zeta < 1.0:
        envelope = -math.log(0.02 * math.sqrt(1 - zeta * zeta)) / osc.decay_rate
        assert envelope - math.pi / osc.damped_natural_frequency <= s.settling_time * (1 + 1e-12) <= envelope


def test_step_metrics_continuous_through_critical_damping():
    ref = stab.step_metrics(osc_of(1.0))
    for zeta in (1.0 - 1e-8, 1.0 + 1e-8):
        s = stab.step_metrics(osc_of(zeta))
        assert s.settling_time == pytest.approx(ref.settling_time, rel=1e-6)
        assert s.rise_time == pytest.approx(ref.rise_time, rel=1e-6)
        assert s.overshoot < 1e-100


@given(m=masses, k=stiffnesses, zeta=st.floats(0.01, 5.0))
def test_step_times_scale_with_the_natural_period(m, k, zeta):
    a, b = stab.step_metrics(osc_of(zeta)), stab.step_metrics(osc_of(zeta, m, k))
    scale = math.sqrt(20.0) / math.sqrt(k / m)
    assert b.settling_time == pytest.approx(a.settling_time * scale, rel=1e-9)
    assert b.rise_time == pytest.approx(a.rise_time * scale, rel=1e-9)
    assert b.overshoot == pytest.approx(a.overshoot, rel=1e-9, abs=1e-300)
    assert b.final_value == pytest.approx(1.0 / k, rel=1e-15)  # a step of 1 N by default, m
    assert stab.step_metrics(osc_of(zeta, m, k), F0=7.0).final_value == pytest.approx(7.0 / k, rel=1e-15)


def test_settling_optimal_zeta_minimises_settling_on_a_dense_sweep():
    zstar = stab.settling_optimal_zeta(0.02)
    assert zstar == pytest.approx(0.7797, abs=1e-4)
    assert math.exp(-math.pi * zstar / math.sqrt(1 - zstar**2)) == pytest.approx(0.02, rel=1e-13)
    zetas = np.linspace(0.3, 1.5, 2401)
    ts = np.array([stab.step_metrics(osc_of(z)).settling_time for z in zetas])
    best = zetas[np.argmin(ts)]
    assert zstar <= best <= zstar + (zetas[1] - zetas[0])  # the infimum is approached from above
    assert ts.min() <= stab.step_metrics(osc_of(zstar + 1e-9)).settling_time * (1 + 1e-3)
    # and for the 5 % band
    assert stab.settling_optimal_zeta(0.05) == pytest.approx(0.6901, abs=1e-4)


def test_step_metrics_bad_input(raises_parameter_error):
    with raises_parameter_error("c", 0.0, "c > 0"):
        stab.step_metrics(Oscillator(m=1.0, c=0.0, k=20.0))
    with raises_parameter_error("c", -0.5, "c > 0"):
        stab.step_metrics(Oscillator(m=1.0, c=-0.5, k=20.0))
    for band in (0.0, 1.0, 1.5, math.nan):
        with raises_parameter_error("band"):
            stab.step_metrics(Oscillator(m=1.0, c=0.5, k=20.0), band)
    with raises_parameter_error("osc"):
        stab.step_metrics("spring")
    with raises_parameter_error("band"):
        stab.settling_optimal_zeta(0.0)


# ----------------------------------------------------------------------------- white noise


@pytest.mark.parametrize(("m", "c", "k"), [(1.0, 0.1, 20.0), (1.0, 0.5, 20.0), (1.0, 15.0, 20.0), (3.0, 2.0, 0.7)])
def test_white_noise_variance_against_quadrature_and_lyapunov(m, c, k):
    osc, S0 = Oscillator(m=m, c=c, k=k), 0.37
    var = stab.white_noise_variance(osc, S0)
    assert var == pytest.approx(math.pi * S0 / (k * c), rel=1e-15)
    wn = osc.natural_frequency

    def h2(w):
        return S0 / ((k - m * w * w) ** 2 + (c * w) ** 2)

    pts = [wn * math.sqrt(max(0.0, 1 - 2 * osc.damping_ratio**2))]
    half = (
        quad(h2, 0.0, 10 * wn, points=pts, limit=500, epsabs=0, epsrel=1e-12)[0]
        + quad(h2, 10 * wn, np.inf, epsabs=0, epsrel=1e-12)[0]
    )
    assert 2.0 * half == pytest.approx(var, rel=1e-9)
    # Lyapunov: A P + P A^T + B q B^T = 0, q = 2 pi S0
    a = np.array([[0.0, 1.0], [-k / m, -c / m]])
    p = solve_continuous_lyapunov(a, -np.array([[0.0, 0.0], [0.0, 2 * math.pi * S0 / m**2]]))
    assert p[0, 0] == pytest.approx(var, rel=1e-10)
    assert p[1, 1] == pytest.approx(stab.white_noise_velocity_variance(osc, S0), rel=1e-10)
    assert abs(p[0, 1]) <= 1e-12 * math.sqrt(p[0, 0] * p[1, 1])


def test_exact_transition_reproduces_the_stationary_covariance():
    """Q(dt) = P - Phi P Phi^T: the simulation's one-step noise is exact, for any dt."""
    for c, dt in ((0.1, 0.05), (0.5, 0.7), (15.0, 0.01)):
        osc = Oscillator(m=1.0, c=c, k=20.0)
        phi, qd = stab._transition(osc, 1.0, dt)
        p = np.diag([stab.white_noise_variance(osc, 1.0), stab.white_noise_velocity_variance(osc, 1.0)])
        np.testing.assert_allclose(qd, p - phi @ p @ phi.T, rtol=1e-9, atol=1e-12 * p[1, 1])


@pytest.mark.parametrize(("c", "dt"), [(1e-4, 1e3), (1e-3, 37.0), (1e4, 25.0), (1e4, 2e-3), (0.1, 1e5)])
def test_exact_transition_over_long_steps(c, dt):
    """Doubling reaches steps far beyond the stiff or lightly damped time scales without overflow."""
    osc = Oscillator(m=1.0, c=c, k=20.0)
    phi, qd = stab._transition(osc, 1.0, dt)
    p = np.diag([stab.white_noise_variance(osc, 1.0), stab.white_noise_velocity_variance(osc, 1.0)])
    assert np.all(np.isfinite(qd)) and np.all(np.isfinite(phi))
    np.testing.assert_allclose(qd, p - phi @ p @ phi.T, rtol=1e-8, atol=1e-10 * p[1, 1])
    # Phi against the exact free response from (1, 0) and (0, 1)
    free = exact_response(osc, SineForce(F0=0.0, omega=1.0), np.array([0.0, dt]), x0=1.0, v0=0.0)
    assert phi[0, 0] == pytest.approx(free.x[-1], rel=1e-7, abs=1e-9)


@pytest.mark.parametrize("c", [1e-4, 1e-3, 0.1, 0.5, 15.0, 1e4])
def test_monte_carlo_agrees_with_the_closed_form(c):
    osc, S0 = Oscillator(m=1.0, c=c, k=20.0), 0.1
    mc = stab.white_noise_monte_carlo(osc, S0, n_paths=200, seed=7)
    exact = stab.white_noise_variance(osc, S0)
    assert mc.standard_error < 0.03 * exact  # the check has teeth
    assert abs(mc.variance - exact) < 4.0 * mc.standard_error
    exact_v = stab.white_noise_velocity_variance(osc, S0)
    assert abs(mc.velocity_variance - exact_v) < 4.0 * mc.velocity_standard_error
    again = stab.white_noise_monte_carlo(osc, S0, n_paths=200, seed=7)
    assert again == mc  # seeded


def test_simulated_paths_start_at_rest_and_scale_with_sqrt_S0():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    t, x1, v1 = stab.simulate_white_noise(osc, 1.0, 5.0, dt=0.01, n_paths=3, seed=1)
    _, x4, _ = stab.simulate_white_noise(osc, 4.0, 5.0, dt=0.01, n_paths=3, seed=1)
    assert t.shape == (501,) and x1.shape == (3, 501)
    assert np.all(x1[:, 0] == 0.0) and np.all(v1[:, 0] == 0.0)
    np.testing.assert_allclose(x4, 2.0 * x1, rtol=1e-12, atol=1e-15)
    _, x0, _ = stab.simulate_white_noise(osc, 0.0, 5.0, dt=0.01)
    assert np.all(x0 == 0.0)


def test_white_noise_bad_input(raises_parameter_error):
    for c in (0.0, -1.0):
        with raises_parameter_error("c", c, "c > 0"):
            stab.white_noise_variance(Oscillator(m=1.0, c=c, k=20.0), 1.0)
    with raises_parameter_error("S0", -1.0, ">= 0"):
        stab.white_noise_variance(Oscillator(m=1.0, c=0.5, k=20.0), -1.0)
    with raises_parameter_error("S0"):
        stab.white_noise_variance(Oscillator(m=1.0, c=0.5, k=20.0), math.inf)
    with raises_parameter_error("n_paths", 1):
        stab.white_noise_monte_carlo(Oscillator(m=1.0, c=0.5, k=20.0), 1.0, n_paths=1)
    with raises_parameter_error("dt", 100.0):
        stab.simulate_white_noise(Oscillator(m=1.0, c=0.5, k=20.0), 1.0, 10.0, dt=100.0)
    with raises_parameter_error("n_paths"):
        stab.simulate_white_noise(Oscillator(m=1.0, c=0.5, k=20.0), 1.0, 1e6, dt=1e-3, n_paths=1000)


# ----------------------------------------------------------------------------- cost of damping


@pytest.mark.parametrize("c", [0.1, 0.5, 15.0, 2.0])
def test_damper_load_at_resonance_and_energy_balance(c):
    osc, F0 = Oscillator(m=1.0, c=c, k=20.0), 5.0
    wn = osc.natural_frequency
    d = stab.damper_load(osc, F0, [wn])
    assert d.force_amplitude[0] == pytest.approx(F0, rel=1e-14)
    assert d.mean_power[0] == pytest.approx(F0**2 / (2.0 * c), rel=1e-14)
    # mean power delivered by the force over the steady state, from the steady-state phase
    for w in (1.0, 3.0, wn, 9.0):
        ss = vibration.steady_state(osc, SineForce(F0=F0, omega=w))
        p_in = 0.5 * F0 * w * ss.amplitude * math.sin(ss.phase)
        assert float(stab.damper_load(osc, F0, w).mean_power) == pytest.approx(p_in, rel=1e-12)


def test_damper_load_time_average_of_c_v_squared():
    osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    period = 2.0 * math.pi / force.omega
    t = np.linspace(200.0, 200.0 + period, 20001)
    v = exact_response(osc, force, t).v
    mean = np.trapezoid(osc.c * v * v, t) / period
    assert mean == pytest.approx(float(stab.damper_load(osc, 5.0, 3.0).mean_power), rel=1e-8)


def test_damper_load_bad_input(raises_parameter_error):
    with raises_parameter_error("c", -0.1, ">= 0"):
        stab.damper_load(Oscillator(m=1.0, c=-0.1, k=20.0), 5.0, [1.0])
    with raises_parameter_error("F0", -5.0):
        stab.damper_load(Oscillator(m=1.0, c=0.1, k=20.0), -5.0, [1.0])


def test_design_metrics_of_the_paper_dampings():
    rows = {name: stab.design_metrics(Oscillator(m=1.0, c=c, k=20.0)) for name, c in PAPER.items()}
    assert all(r.stability == "asymptotically stable" for r in rows.values())
    # more damping: lower resonant peak, worse isolation at 3 omega_n
    assert rows["low"].peak_magnification > rows["nominal"].peak_magnification > rows["high"].peak_magnification
    assert rows["low"].transmissibility < rows["nominal"].transmissibility < rows["high"].transmissibility
    assert rows["high"].settling_time < rows["nominal"].settling_time < rows["low"].settling_time
    for r in rows.values():
        osc = Oscillator(m=1.0, c=r.c, k=20.0)
        assert r.transmissibility == pytest.approx(float(_t_direct(osc, 3 * osc.natural_frequency)), rel=1e-13)
        assert r.rms_per_sqrt_S0 == pytest.approx(math.sqrt(math.pi / (20.0 * r.c)), rel=1e-15)
    with pytest.raises(vibration.ParameterError, match="isolation_ratio"):
        stab.design_metrics(Oscillator(m=1.0, c=0.5, k=20.0), isolation_ratio=0.0)


def test_design_metrics_without_positive_damping():
    """c = 0: steady T = 1/(r^2 - 1) and overshoot 1 exist, nothing else; c < 0: nothing exists."""
    d = stab.design_metrics(Oscillator(m=1.0, c=0.0, k=20.0), isolation_ratio=3.0)
    assert d.transmissibility == pytest.approx(1.0 / 8.0, rel=1e-15)
    y = stab.step_response(Oscillator(m=1.0, c=0.0, k=20.0), np.linspace(0.0, 2.0, 200001))
    assert d.overshoot == 1.0 and np.max(y) - 1.0 == pytest.approx(1.0, abs=1e-9)
    assert (d.peak_magnification, d.settling_time, d.rms_per_sqrt_S0) == (None, None, None)
    assert d.stability == "marginally stable"
    for c in (-0.1, -100.0):
        d = stab.design_metrics(Oscillator(m=1.0, c=c, k=20.0))
        assert d.stability == "unstable"
        assert (d.peak_magnification, d.transmissibility, d.overshoot, d.settling_time, d.rms_per_sqrt_S0) == (
            None,
        ) * 5
