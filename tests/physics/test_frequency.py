"""Frequency-domain and window quantities against textbook formulas and brute force."""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibration import (
    N_POINTS_MAX,
    Oscillator,
    ParameterError,
    SineForce,
    energy_balance,
    exact_response,
    half_power_points,
    log_decrement,
    magnification,
    peak_displacement_map,
    phase_lag,
    settling_time,
    simulate,
    steady_state,
)

SQRT20 = math.sqrt(20.0)
C_CRIT = 2.0 * SQRT20


def _textbook_steady(m, c, k, F0, w):
    """Amplitude (m) and phase lag (rad) of x_p = P sin wt + Q cos wt, from the ODE directly."""
    a, b = k - m * w * w, c * w
    return F0 / math.hypot(a, b), math.atan2(b, a)


# --- magnification and phase lag ---


@pytest.mark.parametrize("c", [0.1, 0.5, C_CRIT, 15.0, 0.0, -0.2])
def test_magnification_and_phase_lag_match_steady_state(c):
    osc = Oscillator(m=1.0, c=c, k=20.0)
    omegas = np.linspace(0.0, 3.0 * SQRT20, 301)
    omegas = omegas[np.abs(omegas - SQRT20) > 1e-3] if c == 0.0 else omegas
    mag, lag = magnification(osc, omegas), phase_lag(osc, omegas)
    assert mag.shape == lag.shape == omegas.shape
    for w, g, p in zip(omegas, mag, lag, strict=True):
        ss = steady_state(osc, SineForce(F0=5.0, omega=float(w)))
        amp, phase = _textbook_steady(1.0, c, 20.0, 5.0, float(w))
        assert g == pytest.approx(ss.magnification, rel=1e-13)
        assert g == pytest.approx(amp / (5.0 / 20.0), rel=1e-12)
        assert p == pytest.approx(ss.phase, rel=1e-13, abs=1e-15)
        assert p == pytest.approx(phase, rel=1e-12, abs=1e-15)
    if c >= 0.0:
        assert np.all((lag >= 0.0) & (lag <= math.pi))


def test_magnification_doc_values():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    mag = magnification(osc, [0.0, SQRT20])
    assert mag[0] == 1.0
    assert mag[1] == pytest.approx(1.0 / (2.0 * osc.damping_ratio), rel=1e-14)  # Q at resonance
    lag = phase_lag(osc, [0.0, SQRT20, 1e6])
    np.testing.assert_allclose(lag, [0.0, math.pi / 2, math.pi], rtol=0, atol=1e-5)


def test_undamped_resonance_magnification_is_infinite_without_warning():
    osc = Oscillator(m=1.0, c=0.0, k=20.0)
    wn = osc.natural_frequency
    mag = magnification(osc, [0.5 * wn, wn, 2.0 * wn])
    assert mag[1] == math.inf
    assert mag[0] == pytest.approx(1.0 / 0.75, rel=1e-14)
    assert mag[2] == pytest.approx(1.0 / 3.0, rel=1e-14)


def test_undamped_resonance_phase_lag_matches_steady_state():
    """At undamped resonance the response is -(F0 t / 2 m wn) cos(wn t): a lag of pi/2,
    which is what steady_state reports. phase_lag must agree."""
    osc = Oscillator(m=1.0, c=0.0, k=20.0)
    wn = osc.natural_frequency
    omegas = np.array([0.5 * wn, wn, 2.0 * wn])
    expected = [steady_state(osc, SineForce(F0=1.0, omega=float(w))).phase for w in omegas]
    assert expected == pytest.approx([0.0, math.pi / 2, math.pi], abs=1e-15)
    np.testing.assert_allclose(phase_lag(osc, omegas), expected, rtol=0, atol=1e-15)


@pytest.mark.parametrize("bad", [[-1.0], [math.nan], [0.0, math.inf]])
def test_magnification_refuses_bad_omegas(raises_parameter_error, bad):
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    bad_value = next(v for v in bad if not (math.isfinite(v) and v >= 0))
    with raises_parameter_error("omegas", bad_value, ">= 0"):
        magnification(osc, bad)
    with raises_parameter_error("omegas", bad_value, ">= 0"):
        phase_lag(osc, bad)


# --- half-power points ---


@pytest.mark.parametrize("zeta", [0.01, 0.056, 0.2])
def test_half_power_points_recover_damping_ratio(zeta):
    osc = Oscillator(m=1.0, c=2.0 * zeta * SQRT20, k=20.0)
    wn = osc.natural_frequency
    omegas = np.linspace(0.2 * wn, 1.8 * wn, 20001)  # measured: zeta within 6e-6 (zeta = 0.01)
    hp = half_power_points(omegas, magnification(osc, omegas))
    assert hp.damping_ratio == pytest.approx(osc.damping_ratio, rel=1e-4)
    # the exact half-power points r^2 = 1 - 2 z^2 -/+ 2 z sqrt(1 - z^2)
    lo = wn * math.sqrt(1 - 2 * zeta**2 - 2 * zeta * math.sqrt(1 - zeta**2))
    hi = wn * math.sqrt(1 - 2 * zeta**2 + 2 * zeta * math.sqrt(1 - zeta**2))
    step = omegas[1] - omegas[0]
    assert hp.omega_low == pytest.approx(lo, abs=step)
    assert hp.omega_high == pytest.approx(hi, abs=step)
    assert hp.bandwidth == pytest.approx(hi - lo, abs=2 * step)
    assert hp.peak_omega == pytest.approx(wn * math.sqrt(1 - 2 * zeta**2), abs=step)
    # the sampled peak is below the true one by ~ (step / (2 zeta wn))^2 / 2, 8e-6 for zeta = 0.01
    assert hp.peak_magnification == pytest.approx(1 / (2 * zeta * math.sqrt(1 - zeta**2)), rel=1e-4)


def test_half_power_light_damping_bandwidth_is_c_over_m():
    osc = Oscillator(m=1.0, c=0.05, k=20.0)  # zeta = 0.0056
    w = np.linspace(3.0, 6.0, 300001)
    hp = half_power_points(w, magnification(osc, w))
    assert hp.bandwidth == pytest.approx(osc.half_power_bandwidth, rel=1e-3)


def test_half_power_points_need_both_sides():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    w = np.linspace(4.4, 6.0, 1001)  # the lower half-power point (4.24 rad/s) is outside
    with pytest.raises(ParameterError, match="omegas") as info:
        half_power_points(w, magnification(osc, w))
    assert isinstance(info.value, ValueError)


# --- logarithmic decrement ---


@pytest.mark.parametrize("zeta", [0.01, 0.056, 0.2])
def test_log_decrement_of_exact_free_decay(zeta):
    osc = Oscillator(m=1.0, c=2.0 * zeta * SQRT20, k=20.0)
    t = np.linspace(0.0, 20.0, 20001)
    r = exact_response(osc, SineForce(F0=0.0, omega=0.0), t, x0=1.0, v0=0.0)
    delta, z = log_decrement(r.t, r.x)
    assert z == pytest.approx(osc.damping_ratio, rel=1e-4)  # measured <= 2e-10
    assert delta == pytest.approx(2 * math.pi * zeta / math.sqrt(1 - zeta**2), rel=1e-4)


@pytest.mark.parametrize("zeta", [0.01, 0.056, 0.2])
def test_log_decrement_of_simulated_free_decay(zeta):
    osc = Oscillator(m=1.0, c=2.0 * zeta * SQRT20, k=20.0)
    r = simulate(
        osc, SineForce(F0=0.0, omega=0.0), 20.0, n_points=20001, x0=0.0, v0=1.0, method="DOP853", rtol=1e-10, atol=1e-12
    )
    _, z = log_decrement(r.t, r.x)
    assert z == pytest.approx(osc.damping_ratio, rel=1e-4)  # measured <= 4e-8


def test_log_decrement_needs_two_peaks():
    t = np.linspace(0.0, 10.0, 1001)
    x = exact_response(Oscillator(m=1.0, c=15.0, k=20.0), SineForce(F0=0.0, omega=0.0), t, x0=1.0).x  # overdamped
    with pytest.raises(ParameterError, match=r"\bx\b.*allowed") as info:
        log_decrement(t, x)
    assert isinstance(info.value, ValueError)


# --- settling time ---


def _transient(osc, force, t):
    """Exact response from rest minus the textbook steady state (independent amplitude, phase)."""
    amp, phase = _textbook_steady(osc.m, osc.c, osc.k, force.F0, force.omega)
    return exact_response(osc, force, t).x - amp * np.sin(force.omega * t - phase), amp


@pytest.mark.parametrize(
    ("m", "c", "k", "F0", "w", "tol"),
    [
        (1.0, 0.5, 20.0, 5.0, 3.0, 0.02),
        (1.0, 0.5, 20.0, 5.0, 4.47, 0.02),
        (1.0, 0.1, 20.0, 5.0, 4.47, 0.05),
        (3.0, 0.4, 7.0, 2.0, 1.1, 0.02),
        (1.0, 4.0, 20.0, 5.0, 9.0, 0.01),
    ],
)
def test_settling_time_underdamped_is_the_envelope_crossing(m, c, k, F0, w, tol):
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w)
    amp, phase = _textbook_steady(m, c, k, F0, w)
    sigma = c / (2 * m)
    wd = math.sqrt(k / m - sigma**2)
    # transient's initial state: minus the steady state's at t = 0
    y0, yd0 = amp * math.sin(phase), -w * amp * math.cos(phase)
    envelope0 = math.hypot(y0, (yd0 + sigma * y0) / wd)
    expected = math.log(envelope0 / (tol * amp)) / sigma
    ts = settling_time(osc, force, tol)
    assert ts == pytest.approx(expected, rel=1e-12)
    # and the envelope is the transient's: it bounds it and is touched once per period
    t = np.linspace(0.0, ts + 4 * math.pi / wd, 200001)
    tr, _ = _transient(osc, force, t)
    env = envelope0 * np.exp(-sigma * t)
    assert np.all(np.abs(tr) <= env * (1 + 1e-9) + 1e-12 * amp)
    near = (t > ts - 2 * math.pi / wd) & (t < ts)
    assert np.max(np.abs(tr[near])) >= tol * amp * 0.99  # still above tol within the last period
    assert np.max(np.abs(tr[t > ts])) <= tol * amp * (1 + 1e-9)


@pytest.mark.parametrize(
    ("m", "c", "k", "F0", "w", "tol"),
    [
        (1.0, 15.0, 20.0, 5.0, 4.47, 0.02),
        (1.0, 15.0, 20.0, 5.0, 0.3, 0.02),
        (1.0, 15.0, 20.0, 5.0, 30.0, 0.02),
        (1.0, 200.0, 20.0, 5.0, 4.47, 0.02),
        (1.0, C_CRIT, 20.0, 5.0, 3.0, 0.02),
        (1.0, C_CRIT * (1 + 1e-6), 20.0, 5.0, 3.0, 0.05),
        (3.0, 40.0, 7.0, 2.0, 1.1, 0.02),
        (3.0, 2.0 * math.sqrt(21.0), 7.0, 2.0, 1.1, 0.1),
    ],
)
def test_settling_time_overdamped_and_critical_by_brute_force(m, c, k, F0, w, tol):
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w)
    ts = settling_time(osc, force, tol)
    t = np.linspace(0.0, max(4 * ts, 1.0), 1_000_001)
    tr, amp = _transient(osc, force, t)
    level = tol * amp
    j = np.nonzero(np.abs(tr) > level)[0][-1]  # last sample above the band
    lo, hi = t[j], t[j + 1]
    for _ in range(60):  # bisect the last crossing
        mid = 0.5 * (lo + hi)
        tr_mid, _ = _transient(osc, force, np.array([mid]))
        lo, hi = (mid, hi) if abs(tr_mid[0]) > level else (lo, mid)
    assert ts == pytest.approx(lo, abs=1e-6)  # s; measured agreement 1e-13 s


def test_settling_time_special_cases(raises_parameter_error):
    f = SineForce(F0=5.0, omega=3.0)
    assert settling_time(Oscillator(m=1.0, c=0.0, k=20.0), f) == math.inf
    assert settling_time(Oscillator(m=1.0, c=-0.2, k=20.0), f) == math.inf
    with raises_parameter_error("F0", 0.0, "free decay from x0"):  # nothing moves: not a settling time of 0
        settling_time(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=0.0, omega=3.0))
    for bad in [0.0, -0.02, math.nan]:
        with raises_parameter_error("tol", bad, "tol >= 1e-12"):
            settling_time(Oscillator(m=1.0, c=0.5, k=20.0), f, bad)


@pytest.mark.parametrize("c", [0.5, 15.0, C_CRIT])
def test_settling_time_without_forcing_frequency_is_zero(c):
    """omega = 0: F0 sin(0) = 0, the response from rest is x = 0, there is no transient."""
    osc, force = Oscillator(m=1.0, c=c, k=20.0), SineForce(F0=5.0, omega=0.0)
    assert np.all(exact_response(osc, force, np.linspace(0.0, 10.0, 11)).x == 0.0)
    assert settling_time(osc, force) == 0.0


# --- energy balance (deterministic cases; random ones in test_properties) ---


@pytest.mark.parametrize(
    ("m", "c", "k", "F0", "w", "x0", "v0"),
    [
        (1.0, 0.5, 20.0, 5.0, 3.0, 0.0, 0.0),
        (1.0, 0.5, 20.0, 5.0, 4.47, 0.3, -0.7),
        (1.0, 0.0, 20.0, 5.0, SQRT20, 0.0, 0.0),
        (1.0, 15.0, 20.0, 5.0, 4.47, 0.3, -0.7),
        (1.0, -0.2, 20.0, 5.0, 3.0, 0.1, 0.0),
        (3.0, 0.4, 7.0, 2.0, 1.1, 0.0, 1.0),
    ],
)
def test_energy_balance(m, c, k, F0, w, x0, v0):
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w)
    t = np.linspace(0.0, 20.0, 40001)
    r = exact_response(osc, force, t, x0=x0, v0=v0)
    eb = energy_balance(osc, force, r)
    scale = max(np.max(np.abs(eb.work)), np.max(np.abs(eb.dissipated)), np.max(np.abs(eb.stored)))
    assert np.max(np.abs(eb.residual)) <= 1e-9 * scale  # Simpson, h = 5e-4 s: measured <= 1e-11
    assert eb.work[0] == eb.dissipated[0] == eb.stored[0] == 0.0
    assert eb.stored[-1] == pytest.approx(
        0.5 * m * (r.v[-1] ** 2 - v0**2) + 0.5 * k * (r.x[-1] ** 2 - x0**2), rel=1e-12, abs=1e-15
    )
    if c > 0:  # non-decreasing, up to Simpson's non-monotone weights (-6e-16 J seen near t = 0)
        assert np.all(np.diff(eb.dissipated) >= -1e-12 * scale)
    if c == 0:
        assert np.all(eb.dissipated == 0.0)


def test_energy_balance_detects_a_wrong_response():
    """The check has teeth: a response 1e-6 off in x breaks the balance by far more than 1e-9."""
    osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    t = np.linspace(0.0, 20.0, 40001)
    r = exact_response(osc, force, t)
    bad = type(r)(t=r.t, x=r.x * (1 + 1e-6), v=r.v, method="perturbed")
    eb = energy_balance(osc, force, bad)
    scale = max(np.max(np.abs(eb.work)), np.max(np.abs(eb.stored)), np.max(np.abs(eb.dissipated)))
    assert np.max(np.abs(eb.residual)) > 1e-7 * scale


# --- design map ---

M, K, F0 = 1.0, 20.0, 5.0
WN = math.sqrt(K / M)
MAP_OMEGAS = [0.0, 1.0, 3.0, WN, 4.47, 9.0]
MAP_DAMPINGS = [-15.0, -0.2, 0.0, 1e-9, 0.1, 0.5, 2.0 * math.sqrt(K * M), 15.0]


def _brute_force_map(m, k, F0, omegas, dampings, t_end, n_points):
    t = np.linspace(0.0, t_end, n_points)
    out = np.empty((len(dampings), len(omegas)))
    for i, c in enumerate(dampings):
        for j, w in enumerate(omegas):
            out[i, j] = np.max(np.abs(exact_response(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w), t).x))
    return out


@pytest.mark.parametrize(("t_end", "n_points"), [(20.0, 2001), (50.0, 5001)])
def test_peak_map_equals_max_of_exact_response(t_end, n_points):
    pk = peak_displacement_map(M, K, F0, omegas=MAP_OMEGAS, dampings=MAP_DAMPINGS, t_end=t_end, n_points=n_points)
    assert pk.shape == (len(MAP_DAMPINGS), len(MAP_OMEGAS))
    expected = _brute_force_map(M, K, F0, MAP_OMEGAS, MAP_DAMPINGS, t_end, n_points)
    np.testing.assert_allclose(pk, expected, rtol=1e-12, atol=0)
    assert np.all(pk[:, 0] == 0.0)  # omega = 0: no force at all


def test_peak_map_shape_is_dampings_by_omegas():
    omegas, dampings = [2.0, 3.0, 4.0], [0.5, 15.0]
    pk = peak_displacement_map(3.0, 7.0, 2.0, omegas=omegas, dampings=dampings, t_end=10.0, n_points=501)
    assert pk.shape == (2, 3)
    expected = _brute_force_map(3.0, 7.0, 2.0, omegas, dampings, 10.0, 501)
    np.testing.assert_allclose(pk, expected, rtol=1e-12, atol=0)


def test_peak_map_doc_example_against_steady_amplitude():
    """Paper's map corners: at 50 s the lightly damped resonance has reached its steady amplitude."""
    pk = peak_displacement_map(1.0, 20.0, 5.0, omegas=[3.0, 4.47], dampings=[0.5, 15.0])
    amp = steady_state(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)).amplitude
    assert pk[0, 1] == pytest.approx(amp, rel=1e-3)


def test_peak_map_near_undamped_resonance():
    """Cells close to, but not at, undamped resonance must be as accurate as the rest.

    exact_response is itself checked there against an 80-digit closed form
    (tests/physics/test_exact.py, detunings 1e-6 and 1e-9: agreement 1e-14).
    """
    detunings = np.array([1e-4, -1e-5, 1e-6, -1e-6, 1e-7, 1e-8, -1e-8, 3e-9])
    omegas = WN * (1.0 + detunings)
    dampings = [0.0, 1e-9]
    pk = peak_displacement_map(M, K, F0, omegas=omegas, dampings=dampings, t_end=20.0, n_points=2001)
    expected = _brute_force_map(M, K, F0, omegas, dampings, 20.0, 2001)
    np.testing.assert_allclose(pk, expected, rtol=1e-12, atol=0)


BAD_MAP = [
    ("m", {"m": 0.0}, 0.0, "m > 0"),
    ("m", {"m": math.nan}, math.nan, "finite"),
    ("k", {"k": -20.0}, -20.0, "k > 0"),
    ("k", {"k": math.inf}, math.inf, "finite"),
    ("F0", {"F0": -5.0}, -5.0, "F0 >= 0"),
    ("F0", {"F0": "5"}, "5", "finite"),
    ("t_end", {"t_end": 0.0}, 0.0, "t_end > 0"),
    ("t_end", {"t_end": math.inf}, math.inf, "finite"),
    ("n_points", {"n_points": 1}, 1, "2 <= n_points"),
    ("n_points", {"n_points": 10**12}, 10**12, f"n_points <= {N_POINTS_MAX}"),
    ("n_points", {"n_points": 2.5}, 2.5, "integer"),
    ("omegas", {"omegas": [3.0, -1.0]}, -1.0, ">= 0"),
    ("omegas", {"omegas": [3.0, math.nan]}, math.nan, "finite"),
    ("omegas", {"omegas": []}, (0,), "non-empty"),
    ("omegas", {"omegas": [[3.0, 4.0]]}, (1, 2), "1-D"),
    ("dampings", {"dampings": [0.5, math.nan]}, math.nan, "finite"),
    ("dampings", {"dampings": [0.5, -math.inf]}, -math.inf, "finite"),
    ("dampings", {"dampings": []}, [], "non-empty"),
]


@pytest.mark.parametrize(("name", "override", "bad", "allowed"), BAD_MAP, ids=[b[0] for b in BAD_MAP])
def test_peak_map_refuses_bad_inputs(raises_parameter_error, name, override, bad, allowed):
    args = {"m": 1.0, "k": 20.0, "F0": 5.0, "omegas": [3.0], "dampings": [0.5], "t_end": 5.0, "n_points": 11}
    args.update(override)
    with raises_parameter_error(name, bad, allowed):
        peak_displacement_map(**args)


def test_local_maxima_are_scipys_peaks_on_random_signals():
    """The one local-maximum rule (log decrement, the audit's cycle peaks, the chapter 1 envelope) finds what
    scipy.signal.find_peaks finds on signals without plateaus."""
    from scipy.signal import find_peaks

    from vibration.physics.frequency import local_maxima

    rng = np.random.default_rng(3)
    for n in (3, 10, 1000):
        y = rng.standard_normal(n)
        np.testing.assert_array_equal(local_maxima(y), find_peaks(y)[0])
    assert local_maxima(np.array([1.0, 2.0, 2.0, 1.0])).tolist() == [1]  # a plateau once, at its first sample
