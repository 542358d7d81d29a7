"""The Duffing chapter's physics: harmonic balance against independent methods.

Every number is checked against something computed another way: the amplitude cubic against
mpmath's polynomial roots at 40 digits, the folds against a dense root count and the double-root
conditions, the slow-flow stability against Floquet multipliers of shooting (DOP853), the
compiled sweep against SciPy's RK45 and against the shooting orbits, the linear limit against
Part I's closed form, the Lyapunov exponents against each other, against the trace of the
Jacobian, against Floquet multipliers (periodic case) and against a published value (Ueda's
oscillator).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from vibration import (
    Duffing,
    Oscillator,
    ParameterError,
    SineForce,
    duffing_response,
    exact_response,
    folds,
    frequency_sweep,
    hb_amplitudes,
    lyapunov_benettin,
    lyapunov_qr,
    poincare_section,
    response_curve,
    steady_state,
)
from vibration.physics.duffing import backbone, linear_trust_amplitude, locate_jump, periodic_orbit, sweep

HARD = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)  # the paper's oscillator with a modest hardening spring
SOFT = Duffing(m=1.0, c=0.5, k=20.0, k3=-1.0)  # ... and a softening one
UEDA = Duffing(m=1.0, c=0.05, k=0.0, k3=1.0)  # x'' + 0.05 x' + x^3 = 7.5 cos t


def amplitude_residual(d: Duffing, F0: float, w: float, a: float) -> float:
    """Relative residual of the one-harmonic amplitude equation."""
    s = d.k - d.m * w * w + d.kappa * a * a
    return abs(a * a * (s * s + (d.c * w) ** 2) - F0 * F0) / (F0 * F0)


def mp_roots(d: Duffing, F0: float, w: float) -> list[float]:
    """Positive amplitudes of the cubic in A^2 from numpy's companion-matrix roots, each polished by
    Newton's method in 40-digit arithmetic (mpmath): independent of the closed form."""
    mpmath.mp.dps = 40
    m, c, k, kap = (mpmath.mpf(v) for v in (d.m, d.c, d.k, d.kappa))
    F0m, wm = mpmath.mpf(F0), mpmath.mpf(w)
    s = k - m * wm * wm
    coeffs = [kap * kap, 2 * s * kap, s * s + (c * wm) ** 2, -(F0m**2)]
    out = set()
    for r in np.roots([float(x) for x in coeffs]):
        if abs(r.imag) > 1e-6 * abs(r):
            continue
        z = mpmath.mpf(float(r.real))
        for _ in range(60):
            f = ((coeffs[0] * z + coeffs[1]) * z + coeffs[2]) * z + coeffs[3]
            fp = (3 * coeffs[0] * z + 2 * coeffs[1]) * z + coeffs[2]
            if fp == 0:
                break
            z -= f / fp
        if z > 0:
            out.add(round(float(mpmath.sqrt(z)), 15))
    return sorted(out)


# ----------------------------------------------------------------------------- model and input


def test_duffing_record_is_frozen_and_derived():
    assert HARD.natural_frequency == pytest.approx(math.sqrt(20.0), rel=1e-15)
    assert HARD.character == "hardening" and SOFT.character == "softening"
    assert Duffing(m=1.0, c=0.5, k=20.0, k3=0.0).character == "linear"
    assert SOFT.barrier == pytest.approx(math.sqrt(20.0), rel=1e-15)
    assert HARD.half_power_bandwidth == 0.5
    with pytest.raises(AttributeError):
        HARD.k3 = 1.0  # type: ignore[misc]


@pytest.mark.parametrize(
    ("args", "name", "bad"),
    [((0.0, 0.5, 20.0, 1.0), "m", 0.0), ((1.0, -0.1, 20.0, 1.0), "c", -0.1), ((1.0, 0.5, -1.0, 1.0), "k", -1.0),
     ((1.0, 0.5, 0.0, -1.0), "k3", -1.0), ((1.0, 0.5, 20.0, math.inf), "k3", math.inf),
     ((1.0, 0.5, 20.0, "2"), "k3", "2")],
)  # fmt: skip
def test_bad_records_are_named(raises_parameter_error, args, name, bad):
    with raises_parameter_error(name, bad):
        Duffing(**dict(zip(("m", "c", "k", "k3"), args, strict=True)))


@pytest.mark.parametrize(
    ("call", "name"),
    [(lambda: hb_amplitudes(HARD, -1.0, 5.0), "F0"), (lambda: hb_amplitudes(HARD, 5.0, 0.0), "omega"),
     (lambda: hb_amplitudes("HARD", 5.0, 5.0), "duffing"), (lambda: folds(Duffing(m=1, c=0, k=20, k3=1), 5.0), "c"),
     (lambda: folds(HARD, 0.0), "F0"), (lambda: sweep(HARD, 5.0, [5.0], direction="sideways"), "direction"),
     (lambda: sweep(HARD, 5.0, [5.0, -1.0], direction="up"), "omegas"),
     (lambda: sweep(HARD, 5.0, [], direction="up"), "omegas"),
     (lambda: sweep(Duffing(m=1, c=0, k=20, k3=1), 5.0, [5.0], direction="up"), "c"),
     (lambda: frequency_sweep(HARD, 5.0, [5.0], direction="up", rtol=1.0), "rtol"),
     (lambda: frequency_sweep(HARD, 5.0, [5.0], direction="up", integrator="euler"), "integrator"),
     (lambda: backbone(HARD, -1.0), "amplitude"), (lambda: lyapunov_qr(UEDA, 7.5, 1.0, n_periods=0), "n_periods"),
     (lambda: lyapunov_benettin(UEDA, 7.5, 1.0, d0=1.0), "d0"),
     (lambda: poincare_section(UEDA, 7.5, 1.0, steps_per_period=2), "steps_per_period"),
     (lambda: linear_trust_amplitude(UEDA), "k"), (lambda: response_curve(HARD, 5.0, 8.0, n=3), "n"),
     (lambda: duffing_response(HARD, 5.0, 4.0, t=[1.0, 0.5]), "t")],
)  # fmt: skip
def test_bad_inputs_raise_parameter_error_naming_the_parameter(call, name):
    with pytest.raises(ParameterError, match=rf"\b{name}\b") as info:
        call()
    assert "allowed" in str(info.value)


# ----------------------------------------------------------------------------- harmonic balance


def test_three_roots_in_the_band_stable_unstable_stable():
    roots = hb_amplitudes(HARD, 5.0, 5.07)
    assert [s for _, s in roots] == [True, False, True]
    assert [a for a, _ in roots] == sorted(a for a, _ in roots)
    assert all(amplitude_residual(HARD, 5.0, 5.07, a) < 1e-13 for a, _ in roots)
    np.testing.assert_allclose([a for a, _ in roots], mp_roots(HARD, 5.0, 5.07), rtol=1e-13)


@given(
    m=st.floats(0.1, 10.0),
    k=st.floats(0.1, 100.0),
    zeta=st.floats(0.005, 0.5),
    k3_rel=st.one_of(st.just(0.0), st.floats(1e-6, 10.0), st.floats(-0.3, -1e-6)),
    F0_rel=st.floats(0.01, 3.0),
    r=st.floats(0.05, 4.0),
)
def test_amplitudes_match_mpmath_polynomial_roots(m, k, zeta, k3_rel, F0_rel, r):
    c = 2 * zeta * math.sqrt(k * m)
    d = Duffing(m=m, c=c, k=k, k3=k3_rel * k)
    F0 = F0_rel * k
    w = r * d.natural_frequency
    ours = [a for a, _ in hb_amplitudes(d, F0, w)]
    ref = mp_roots(d, F0, w)
    if len(ours) != len(ref):  # only possible within rounding of a fold (a double root)
        assert min(np.diff(ref), default=1.0) < 1e-6 * max(ref), (ours, ref)
        return
    np.testing.assert_allclose(ours, ref, rtol=1e-9)
    assert all(amplitude_residual(d, F0, w, a) < 1e-9 for a in ours)


@given(zeta=st.floats(0.005, 2.0), r=st.floats(0.05, 5.0), F0=st.floats(0.0, 50.0))
def test_linear_limit_is_part_one_closed_form(zeta, r, F0):
    osc = Oscillator(m=1.0, c=2 * zeta * math.sqrt(20.0), k=20.0)
    w = r * osc.natural_frequency
    [(a, stable)] = hb_amplitudes(Duffing(m=1.0, c=osc.c, k=20.0, k3=0.0), F0, w)
    assert stable
    assert a == pytest.approx(steady_state(osc, SineForce(F0=F0, omega=w)).amplitude, rel=1e-13, abs=1e-300)


def test_backbone_and_peak_textbook_light_damping():
    """Nayfeh & Mook (1979) section 4.1; Kovacic & Brennan (2011): as damping vanishes the peak of the
    frequency response lies on the backbone omega^2 = k/m + (3/4)(k3/m) A^2 with A = F0/(c omega)."""
    for k3 in (2.0, 0.5, -0.2):
        for c in (0.05, 0.01, 0.002):
            d = Duffing(m=1.0, c=c, k=20.0, k3=k3)
            F0 = c * math.sqrt(20.0)  # a peak near 1 m whatever the damping
            f = folds(d, F0)
            a, w = f.peak_amplitude, f.peak_omega
            zeta = c / (2 * math.sqrt(20.0))
            assert w == pytest.approx(backbone(d, a), rel=zeta**2 * 2)
            assert a == pytest.approx(F0 / (c * backbone(d, a)), rel=zeta**2 * 2)
            # and it is the largest amplitude of the curve
            wc, ac, _ = response_curve(d, F0, 2 * w, n=20001)
            assert a == pytest.approx(ac.max(), rel=1e-6)
    assert backbone(HARD, 2.0) == pytest.approx(math.sqrt(20.0 + 0.75 * 2.0 * 4.0), rel=1e-15)


def test_peak_of_linear_oscillator_is_damped_resonance():
    d = Duffing(m=1.0, c=0.5, k=20.0, k3=0.0)
    f = folds(d, 5.0)
    assert not f.bistable and math.isnan(f.omega_low)
    assert f.peak_omega == pytest.approx(math.sqrt(20.0 - 0.5**2 / 2), rel=1e-14)
    assert f.peak_amplitude == pytest.approx(5.0 / (0.5 * math.sqrt(20.0 - 0.25**2)), rel=1e-14)


@pytest.mark.parametrize(
    ("d", "F0"),
    [
        (HARD, 5.0),
        (SOFT, 5.0),
        (Duffing(m=2.0, c=0.3, k=7.0, k3=0.4), 3.0),
        (Duffing(m=0.5, c=0.02, k=1.0, k3=-0.1), 0.05),
    ],
)
def test_folds_are_double_roots_and_bound_the_three_root_band(d, F0):
    f = folds(d, F0)
    assert f.bistable
    for w, a in ((f.omega_low, f.amplitude_low), (f.omega_high, f.amplitude_high)):
        s, y = d.k - d.m * w * w, d.kappa * a * a
        assert amplitude_residual(d, F0, w, a) < 1e-10  # p = 0
        assert abs((s + y) * (s + 3 * y) + (d.c * w) ** 2) < 1e-8 * (d.k**2 + (d.c * w) ** 2)  # dp/dA^2 = 0
    a_cap = f.peak_amplitude * (1 + 1e-9)

    def n_roots(w):
        return len([a for a, _ in hb_amplitudes(d, F0, w) if a <= a_cap])

    eps = 1e-6 * f.omega_high
    assert n_roots(f.omega_low - eps) == 1 and n_roots(f.omega_low + eps) == 3
    assert n_roots(f.omega_high - eps) == 3 and n_roots(f.omega_high + eps) == 1
    # dense scan: three roots nowhere else
    ws = np.linspace(0.5 * f.omega_low, 1.5 * f.omega_high, 3001)
    inside = np.array([n_roots(w) == 3 for w in ws])
    assert np.all(inside == ((ws > f.omega_low) & (ws < f.omega_high)))


def test_weak_forcing_is_not_bistable():
    f = folds(HARD, 0.5)
    assert not f.bistable and math.isnan(f.omega_high)
    assert f.peak_amplitude == pytest.approx(max(a for a, _ in hb_amplitudes(HARD, 0.5, f.peak_omega)), rel=1e-12)


def test_response_curve_points_solve_the_amplitude_equation_and_carry_its_stability():
    w, a, stable = response_curve(HARD, 5.0, 8.0, n=401)
    res = [amplitude_residual(HARD, 5.0, wi, ai) for wi, ai in zip(w, a, strict=True)]
    assert max(res) < 1e-10
    f = folds(HARD, 5.0)
    assert np.all(stable[(w < f.omega_low) | (w > f.omega_high)])
    assert np.any(~stable)
    for wi, ai, si in list(zip(w, a, stable, strict=True))[::25]:
        match = min(hb_amplitudes(HARD, 5.0, wi), key=lambda p: abs(p[0] - ai))
        if abs(match[0] - ai) < 1e-9 * ai:
            assert match[1] == si


def test_linear_trust_amplitude_moves_the_backbone_one_bandwidth():
    a = linear_trust_amplitude(HARD)
    assert backbone(HARD, a) - HARD.natural_frequency == pytest.approx(HARD.half_power_bandwidth, rel=1e-12)
    a = linear_trust_amplitude(SOFT)
    assert HARD.natural_frequency - backbone(SOFT, a) == pytest.approx(SOFT.half_power_bandwidth, rel=1e-12)
    assert linear_trust_amplitude(Duffing(m=1.0, c=0.5, k=20.0, k3=0.0)) == math.inf


# -------------------------------------------------------------------- stability: slow flow vs Floquet


# inside the band of the full equation (the sweeps jump at 5.0447/5.1079 and 3.8505/3.9592 rad/s)
@pytest.mark.parametrize(("d", "w"), [(HARD, 5.06), (HARD, 5.09), (SOFT, 3.90), (SOFT, 3.94)])
def test_slow_flow_stability_agrees_with_floquet_multipliers(d, w):
    roots = hb_amplitudes(d, 5.0, w)
    assert len(roots) >= 3
    T = 2 * math.pi / w
    for a, stable in roots:
        if d is SOFT and a > 0.8 * d.barrier:
            continue
        orbit = periodic_orbit(d, 5.0, w, amplitude_guess=a)
        assert orbit.stable == stable, (w, a, orbit.multipliers)
        assert orbit.amplitude == pytest.approx(a, rel=0.03)  # one harmonic is a few per cent off here
        # Liouville: the product of the multipliers is exp(-c T / m)
        assert abs(np.prod(orbit.multipliers)) == pytest.approx(math.exp(-d.c * T / d.m), rel=1e-8)
        if not stable:
            assert max(abs(mu) for mu in orbit.multipliers) > 1.0
            assert all(abs(mu.imag) < 1e-9 for mu in orbit.multipliers)  # a saddle: real multipliers


# ----------------------------------------------------------------------------- time integration


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_compiled_sweep_matches_scipy_rk45_step_for_step():
    w = np.array([4.9, 5.0, 5.08])
    ours = frequency_sweep(HARD, 5.0, w, direction="up", steady_tol=1e-4)
    ref = frequency_sweep(HARD, 5.0, w, direction="up", steady_tol=1e-4, integrator="scipy")
    np.testing.assert_allclose(ours.amplitude, ref.amplitude, rtol=1e-7)
    np.testing.assert_array_equal(ours.periods, ref.periods)


def test_sweep_amplitudes_are_the_shooting_orbits():
    w = np.linspace(4.8, 5.3, 11)
    for direction in ("up", "down"):
        res = frequency_sweep(HARD, 5.0, w, direction=direction)
        assert res.steady.all()
        for wi, a, x, v in zip(w, res.amplitude, res.x_end, res.v_end, strict=True):
            orbit = periodic_orbit(HARD, 5.0, wi, x0=x, v0=v)
            assert orbit.stable
            assert a == pytest.approx(orbit.amplitude, rel=1e-5)
            assert math.hypot(x - orbit.x0, (v - orbit.v0) / wi) < 1e-4 * a


def test_sweep_output_is_aligned_with_the_input_order():
    w = np.array([5.3, 4.8, 5.08, 5.0])
    up, up_sorted = sweep(HARD, 5.0, w, direction="up"), sweep(HARD, 5.0, np.sort(w), direction="up")
    np.testing.assert_allclose(up, up_sorted[np.argsort(np.argsort(w))], rtol=1e-12)


@pytest.mark.parametrize("d", [HARD, SOFT])
def test_hysteresis_jumps_sit_at_the_harmonic_balance_folds(d):
    f = folds(d, 5.0)
    w = np.linspace(3.5, 6.5, 200)
    step = w[1] - w[0]
    up, down = frequency_sweep(d, 5.0, w, direction="up"), frequency_sweep(d, 5.0, w, direction="down")
    assert up.steady.all() and down.steady.all()
    [(a_up, b_up, *_)] = up.jumps()
    [(a_dn, b_dn, *_)] = down.jumps()
    # the coarse jumps bracket the folds up to the one-harmonic error (< 0.5 % here)
    assert a_up - 0.005 * f.omega_high <= f.omega_high <= b_up + 0.005 * f.omega_high
    assert b_dn - 0.005 * f.omega_low <= f.omega_low <= a_dn + 0.005 * f.omega_low
    assert b_up - a_up == pytest.approx(step) and a_dn - b_dn == pytest.approx(step)
    # hysteresis: inside the band the two sweeps sit on different branches
    band = (w > f.omega_low + step) & (w < f.omega_high - step) & (w > b_dn) & (w < a_up)
    assert band.any()
    hi, lo = (up, down) if d.k3 > 0 else (down, up)
    assert np.all(hi.amplitude[band] > 1.3 * lo.amplitude[band])
    # refined jump: within 0.5 % of the harmonic-balance fold, bracket 1e-4 of the step
    lo_w, hi_w = locate_jump(d, 5.0, up)
    assert abs(hi_w - lo_w) <= 1.01 * step / 100
    assert abs(0.5 * (lo_w + hi_w) - f.omega_high) < 0.005 * f.omega_high


def test_linear_sweep_is_part_one_steady_state():
    d = Duffing(m=1.0, c=0.5, k=20.0, k3=0.0)
    w = np.linspace(3.0, 6.0, 13)
    amps = sweep(d, 5.0, w, direction="down")
    ref = [steady_state(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=wi)).amplitude for wi in w]
    np.testing.assert_allclose(amps, ref, rtol=1e-5)


def test_softening_spring_escapes_and_the_sweep_goes_on():
    d = Duffing(m=1.0, c=0.1, k=1.0, k3=-1.0)  # barrier at 1 m
    res = frequency_sweep(d, 0.5, [0.5, 0.6], direction="up")
    assert np.isnan(res.amplitude).any() and not res.steady[np.isnan(res.amplitude)].any()


def test_paper_forcing_linear_limit_matches_the_closed_form():
    t = np.linspace(0.0, 50.0, 2001)
    x, _ = duffing_response(Duffing(m=1.0, c=0.5, k=20.0, k3=0.0), 5.0, 4.47, t=t, sine=True)
    ref = exact_response(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47), t).x
    assert np.max(np.abs(x - ref)) < 1e-7 * np.max(np.abs(ref))


# ----------------------------------------------------------------------------- chaos


@pytest.fixture(scope="module")
def ueda():
    """Two methods and two initial conditions on Ueda's attractor."""
    kw = {"n_periods": 2500, "n_transient": 300}
    return {
        "qr_a": lyapunov_qr(UEDA, 7.5, 1.0, x0=3.0, v0=0.0, **kw),
        "ben_a": lyapunov_benettin(UEDA, 7.5, 1.0, x0=3.0, v0=0.0, **kw),
        "qr_b": lyapunov_qr(UEDA, 7.5, 1.0, x0=0.0, v0=0.0, **kw),
        "ben_b": lyapunov_benettin(UEDA, 7.5, 1.0, x0=0.0, v0=0.0, **kw),
    }


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_ueda_exponents_agree_between_methods_and_initial_conditions(ueda):
    lam = [r.exponents[0] for r in ueda.values()]
    assert min(lam) > 0.05  # chaos
    assert ueda["qr_a"].exponents[0] == pytest.approx(ueda["ben_a"].exponents[0], rel=1e-3)
    assert ueda["qr_b"].exponents[0] == pytest.approx(ueda["ben_b"].exponents[0], rel=1e-3)
    assert max(lam) - min(lam) < 0.01  # finite-time averages from two starts


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_ueda_exponent_matches_published_value(ueda):
    """J. C. Sprott, Chaos and Time-Series Analysis (Oxford, 2003), Ueda oscillator: largest exponent
    about 0.10 per unit time (an independent RK4 run with step 0.001 gives 0.0999, 0, -0.1499)."""
    for r in ueda.values():
        assert abs(r.exponents[0] - 0.10) < 0.01


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_qr_exponents_sum_to_the_trace(ueda):
    for key in ("qr_a", "qr_b"):
        assert sum(ueda[key].exponents) == pytest.approx(-UEDA.c / UEDA.m, abs=1e-5)


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_periodic_case_exponent_is_negative_and_floquet():
    orbit = periodic_orbit(HARD, 5.0, 4.47)
    T = 2 * math.pi / 4.47
    floquet = math.log(max(abs(mu) for mu in orbit.multipliers)) / T
    qr = lyapunov_qr(HARD, 5.0, 4.47, x0=orbit.x0, v0=orbit.v0, n_periods=600, n_transient=0)
    ben = lyapunov_benettin(HARD, 5.0, 4.47, x0=orbit.x0, v0=orbit.v0, n_periods=600, n_transient=0)
    assert qr.exponents[0] <= 0 and ben.exponents[0] <= 0
    assert qr.exponents[0] == pytest.approx(floquet, abs=0.005)
    assert ben.exponents[0] == pytest.approx(floquet, abs=0.005)
    # Poincare section of a period-1 orbit: one point, the shooting orbit's
    pts = poincare_section(HARD, 5.0, 4.47, x0=orbit.x0, v0=orbit.v0, n_periods=5, n_transient=0)
    assert np.max(np.abs(pts[:, 0] - orbit.x0)) < 1e-7 and np.max(np.abs(pts[:, 1] - orbit.v0)) < 1e-6


def test_ueda_section_is_not_periodic():
    pts = poincare_section(UEDA, 7.5, 1.0, x0=3.0, v0=0.0, n_periods=300, n_transient=100)
    assert len({(round(x, 6), round(v, 6)) for x, v in pts}) == 300
    assert np.all(np.abs(pts[:, 0]) < 5.0) and np.all(np.abs(pts[:, 1]) < 10.0)  # bounded attractor
