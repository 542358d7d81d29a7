"""Tuned mass damper and MDOF physics, each number against an independent method.

References: Den Hartog (Mechanical Vibrations, 1956) for the fixed points and Brock's averaged damping;
Nishihara and Asami (2002, J. Vib. Acoust. 124:576-582) for the exact H∞ optimum of an undamped primary;
Warburton (1982, Earthquake Eng. Struct. Dyn. 10:381-401) for the H2 optimum; the building is after the
uniform five-storey shear frame of Chopra, Dynamics of Structures (100 kips/g floors, 31.54 kips/in storeys,
T1 = 2 s), with the SI values converted; its higher periods are checked against the closed form of the
uniform shear building, not against printed values.
"""

from __future__ import annotations

import math

import control
import numpy as np
import pytest
import scipy.linalg as sla
from hypothesis import given
from hypothesis import strategies as st
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, minimize_scalar

import vibration
from vibration import (
    MDOF,
    ParameterError,
    add_absorber,
    den_hartog,
    h2_tuning,
    hinf_tuning,
    mistuned_peak,
    shear_building,
    tmd_fixed_points,
    tmd_magnification,
    tmd_peak,
    tmd_system,
)
from vibration.physics.tmd import DampingNotClassical, h2_norm, modal_damping_matrix


def brute_peak(mu, f, za, zp=0.0, r_max=4.0, r_min=0.0):
    """Largest |H| by a dense grid and a bounded Brent refinement around the best sample."""
    r = np.linspace(r_min, r_max, 40001)
    h = tmd_magnification(mu, f, za, r=r, zeta_p=zp)
    i = int(np.argmax(h))
    r = np.linspace(r[max(i - 2, 0)], r[min(i + 2, r.size - 1)], 20001)  # a finer grid around the best sample
    h = tmd_magnification(mu, f, za, r=r, zeta_p=zp)
    i = int(np.argmax(h))
    lo, hi = r[max(i - 1, 0)], r[min(i + 1, r.size - 1)]
    res = minimize_scalar(
        lambda x: -float(tmd_magnification(mu, f, za, r=x, zeta_p=zp)), bounds=(lo, hi), method="bounded",
        options={"xatol": 1e-12},
    )  # fmt: skip
    return max(-res.fun, float(h[i]))


# ----------------------------------------------------------------------------- magnification and peak


def test_magnification_matches_the_two_dof_model_and_scipy_signal():
    mu, f, za, zp = 0.05, 0.95, 0.12, 0.0559
    k, m = 20.0, 1.0
    wp = math.sqrt(k / m)
    model = tmd_system(
        m,
        2 * zp * math.sqrt(k * m),
        k,
        tuning=vibration.TMDTuning(rule="x", mu=mu, f=f, zeta_a=za, zeta_p=zp, peak=0.0, r_peak=0.0),
    )
    r = np.linspace(0.0, 3.0, 301)
    x = np.abs(model.frf(r * wp, [1.0, 0.0])[:, 0]) * k
    np.testing.assert_allclose(tmd_magnification(mu, f, za, r=r, zeta_p=zp), x, rtol=1e-12)
    A = model.state_matrix
    B = np.concatenate([np.zeros(2), np.linalg.solve(model.M, [1.0, 0.0])])[:, None]
    sys = control.ss(A, B, np.eye(1, 4), np.zeros((1, 1)))
    h = np.array([complex(sys(1j * w)) for w in r[1:] * wp])
    np.testing.assert_allclose(tmd_magnification(mu, f, za, r=r[1:], zeta_p=zp), np.abs(h) * k, rtol=1e-10)


@given(
    mu=st.floats(0.005, 2.0),
    f=st.floats(0.5, 1.5),
    za=st.floats(0.01, 1.0),
    zp=st.sampled_from([0.0, 0.02, 0.0559, 0.2]),
)
def test_exact_peak_matches_a_dense_grid(mu, f, za, zp):
    exact = tmd_peak(mu, f, za, zeta_p=zp)
    brute = brute_peak(mu, f, za, zp)
    # |H| near a peak of height H is computed with a relative rounding error of about eps H² (small denominator)
    rel = 1e-9 + 1e-14 * exact**2
    assert exact >= brute * (1 - rel)  # a value of |H| at a real r: never above the true peak but by rounding
    assert exact == pytest.approx(brute, rel=rel)


def test_undamped_peak_is_infinite_and_static_value_is_one():
    assert tmd_peak(0.05, 1.0, 0.0) == math.inf
    assert float(tmd_magnification(0.05, 1.0, 0.2, r=0.0, zeta_p=0.1)) == 1.0


# ----------------------------------------------------------------------------- Den Hartog


@pytest.mark.parametrize("mu", [0.01, 0.05, 0.2, 1.0])
def test_fixed_points_are_common_to_every_damping_and_equal_at_den_hartog_tuning(mu):
    f = 1.0 / (1.0 + mu)
    r, h = tmd_fixed_points(mu, f)
    np.testing.assert_allclose(h, math.sqrt(1.0 + 2.0 / mu), rtol=1e-12)
    for za in (0.01, 0.1, 0.5, 3.0):
        np.testing.assert_allclose(tmd_magnification(mu, f, za, r=r), h, rtol=1e-10)
    r2, h2 = tmd_fixed_points(mu, 0.9)  # other tuning: still common to every damping
    for za in (0.02, 0.3):
        np.testing.assert_allclose(tmd_magnification(mu, 0.9, za, r=r2), h2, rtol=1e-10)


@pytest.mark.parametrize("mu", [0.01, 0.05, 0.1, 0.5])
def test_den_hartog_damping_is_brocks_average_in_the_absorbers_own_frequency(mu):
    """The ζ_a² of the rule is the mean of the two ζ_a² that make each fixed point a horizontal tangent."""
    t = den_hartog(mu)
    f = t.f
    r, _ = tmd_fixed_points(mu, f)

    def slope(za, rr):
        h = 1e-6
        return float(tmd_magnification(mu, f, za, r=rr + h) - tmd_magnification(mu, f, za, r=rr - h)) / (2 * h)

    z2 = [brentq(slope, 1e-3, 2.0, args=(rr,), xtol=1e-14) ** 2 for rr in r]
    assert t.zeta_a == pytest.approx(math.sqrt(np.mean(z2)), rel=1e-5)
    assert t.zeta_a_primary == pytest.approx(math.sqrt(3 * mu / (8 * (1 + mu) ** 3)), rel=1e-12)  # Den Hartog's form
    assert t.peak >= math.sqrt(1 + 2 / mu)


# ----------------------------------------------------------------------------- H∞


@pytest.mark.parametrize("mu", [0.01, 0.05, 0.2, 1.0])
def test_hinf_closed_form_equals_a_numerical_min_max(mu):
    closed = hinf_tuning(mu)
    numerical = hinf_tuning(mu, method="numerical")
    assert closed.rule == "H∞ closed form" and numerical.rule == "H∞ numerical"
    assert numerical.f == pytest.approx(closed.f, rel=1e-7)
    assert numerical.zeta_a == pytest.approx(closed.zeta_a, rel=2e-6)
    assert numerical.peak == pytest.approx(closed.peak, rel=1e-10)


@pytest.mark.parametrize("mu", [0.01, 0.05, 0.1, 0.7])
def test_hinf_closed_form_peak_formula_and_local_optimality(mu):
    t = hinf_tuning(mu)
    assert t.peak == pytest.approx(brute_peak(mu, t.f, t.zeta_a), rel=1e-10)
    # equal peaks on both sides of the tuning frequency
    lo = brute_peak(mu, t.f, t.zeta_a, r_max=t.f)
    hi = brute_peak(mu, t.f, t.zeta_a, r_min=t.f, r_max=3.0)
    assert lo == pytest.approx(hi, rel=1e-10)
    # no small step in (f, ζ_a) lowers the peak
    for df, dz in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)):
        assert tmd_peak(mu, t.f * (1 + 1e-4 * df), t.zeta_a * (1 + 1e-3 * dz)) > t.peak


def test_hinf_beats_den_hartog_and_h2_and_the_damped_primary_optimum_is_local():
    for mu in (0.01, 0.02, 0.05, 0.1):
        hinf, dh, h2 = hinf_tuning(mu), den_hartog(mu), h2_tuning(mu)
        assert hinf.peak < dh.peak < h2.peak
    t = hinf_tuning(0.05, zeta_p=0.0559)
    assert t.zeta_p == 0.0559 and t.rule == "H∞ numerical"
    assert t.peak == pytest.approx(brute_peak(0.05, t.f, t.zeta_a, 0.0559), rel=1e-10)
    for df, dz in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1)):
        assert tmd_peak(0.05, t.f * (1 + 1e-4 * df), t.zeta_a * (1 + 1e-3 * dz), zeta_p=0.0559) > t.peak
    assert den_hartog(0.05, zeta_p=0.0559).peak > t.peak


# ----------------------------------------------------------------------------- H2


def squared_integral(mu, f, za, zp):
    """∫_0^∞ |H|² dr by adaptive quadrature, split at the peaks (independent of the Lyapunov route)."""
    _, r_fixed = None, tmd_fixed_points(mu, f)[0]
    edges = [0.0, *sorted({*r_fixed.tolist(), f}), 3.0]
    total = 0.0
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        total += quad(
            lambda r: float(tmd_magnification(mu, f, za, r=r, zeta_p=zp)) ** 2, a, b, limit=200, epsrel=1e-13
        )[0]
    return (
        total + quad(lambda r: float(tmd_magnification(mu, f, za, r=r, zeta_p=zp)) ** 2, 3.0, np.inf, epsrel=1e-13)[0]
    )


@pytest.mark.parametrize(
    ("mu", "f", "za", "zp"), [(0.02, 0.98, 0.07, 0.0), (0.1, 0.9, 0.2, 0.0559), (0.5, 1.1, 0.05, 0.01)]
)
def test_h2_norm_equals_the_integral_of_the_squared_magnification(mu, f, za, zp):
    assert h2_norm(mu, f, za, zeta_p=zp) == pytest.approx(squared_integral(mu, f, za, zp), rel=1e-9)


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.parametrize("mu", [0.02, 0.1])
def test_warburton_is_the_minimum_of_the_integral(mu):
    t = h2_tuning(mu)

    def integral(f, za):
        return squared_integral(mu, f, za, 0.0)

    base = integral(t.f, t.zeta_a)
    assert base == pytest.approx(t.h2, rel=1e-9)
    for df, dz in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        assert integral(t.f * (1 + 1e-3 * df), t.zeta_a * (1 + 1e-2 * dz)) > base
    num = h2_tuning(mu, method="numerical")
    assert num.f == pytest.approx(t.f, rel=1e-6) and num.zeta_a == pytest.approx(t.zeta_a, rel=1e-5)


def test_h2_numerical_for_a_damped_primary_is_a_minimum():
    t = h2_tuning(0.05, zeta_p=0.0559)
    for df, dz in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        assert h2_norm(0.05, t.f * (1 + 1e-4 * df), t.zeta_a * (1 + 1e-3 * dz), zeta_p=0.0559) > t.h2


# ----------------------------------------------------------------------------- conventions and mistuning


def test_absorber_in_si_uses_the_absorbers_own_frequency():
    t = hinf_tuning(0.05)
    m_a, k_a, c_a = t.absorber(1.0, 20.0)
    w_a = math.sqrt(k_a / m_a)
    assert m_a == pytest.approx(0.05) and w_a == pytest.approx(t.f * math.sqrt(20.0), rel=1e-14)
    assert c_a / (2 * m_a * w_a) == pytest.approx(t.zeta_a, rel=1e-14)
    assert c_a / (2 * m_a * math.sqrt(20.0)) == pytest.approx(t.zeta_a_primary, rel=1e-14)


def test_mistuned_peak_matches_the_two_dof_model():
    t = hinf_tuning(0.05, zeta_p=0.0559)
    m, k = 1.0, 20.0
    m_a, k_a, c_a = t.absorber(m, k)
    for eps in (-0.1, 0.0, 0.1):
        model = add_absorber(
            MDOF(M=[[m]], C=[[2 * 0.0559 * math.sqrt(k * m)]], K=[[k * (1 + eps)]]), 0, m_a, k_a=k_a, c_a=c_a
        )
        w = np.linspace(3.0, 6.0, 3001)
        i = int(np.argmax(np.abs(model.frf(w, [1.0, 0.0])[:, 0])))
        res = minimize_scalar(
            lambda om, mdl=model: -abs(mdl.frf([om], [1.0, 0.0])[0, 0]),
            bounds=(w[i - 1], w[i + 1]),
            method="bounded",
            options={"xatol": 1e-12},
        )
        brute = -res.fun * k
        assert float(mistuned_peak(t, eps)) == pytest.approx(brute, rel=1e-9)


# ----------------------------------------------------------------------------- MDOF


def chopra_frame(n=5, zeta=0.05):
    """After Chopra's uniform shear frame: 100 kips/g floors, 31.54 kips/in storeys, converted to SI."""
    m = 100 * 4448.2216152605 / 9.80665  # 100 kips/g = 45 359.237 kg
    k = 31.54 * 4448.2216152605 / 0.0254  # 31.54 kips/in = 5.5235e6 N/m
    return shear_building([m] * n, [k] * n, zeta), m, k


def test_chopra_frame_periods_closed_form_and_eigh():
    b, m, k = chopra_frame()
    T = 2 * np.pi / b.natural_frequencies
    assert T[0] == pytest.approx(2.0, rel=1e-3)  # Chopra's T1 = 2 s (the values are rounded in kips)
    j = np.arange(1, 6)
    exact = 2 * math.sqrt(k / m) * np.sin((2 * j - 1) * np.pi / 22)  # uniform shear beam of 5 storeys
    np.testing.assert_allclose(b.natural_frequencies, exact, rtol=1e-12)
    w2 = sla.eigh(b.K, b.M, eigvals_only=True)
    np.testing.assert_allclose(b.natural_frequencies, np.sqrt(w2), rtol=1e-13)
    phi = b.modes
    np.testing.assert_allclose(phi.T @ b.M @ phi, np.eye(5), atol=1e-12)
    np.testing.assert_allclose(phi.T @ b.K @ phi, np.diag(b.natural_frequencies**2), atol=1e-6 * k / m)
    assert b.is_classically_damped
    np.testing.assert_allclose(b.modal_damping_ratios, 0.05, rtol=1e-10)


def test_rayleigh_damping_ratios_and_repeated_frequencies():
    M = np.diag([2.0, 1.0, 3.0])
    K = np.array([[6.0, -2.0, 0.0], [-2.0, 4.0, -1.0], [0.0, -1.0, 5.0]])
    a0, a1 = 0.3, 0.02
    s = MDOF(M=M, C=a0 * M + a1 * K, K=K)
    w = s.natural_frequencies
    np.testing.assert_allclose(s.modal_damping_ratios, a0 / (2 * w) + a1 * w / 2, rtol=1e-12)
    rep = MDOF(M=np.eye(3), C=np.diag([0.1, 0.4, 0.2]), K=4.0 * np.eye(3))  # one triple frequency, C not scalar
    assert rep.is_classically_damped
    np.testing.assert_allclose(sorted(rep.modal_damping_ratios), [0.025, 0.05, 0.1], rtol=1e-12)


def test_non_classical_damping_is_said_and_poles_exist():
    s = tmd_system(1.0, 0.5, 20.0, tuning=den_hartog(0.05))
    assert not s.is_classically_damped
    assert "not classical" in s.damping_note
    with pytest.raises(DampingNotClassical, match="not classical"):
        _ = s.modal_damping_ratios
    lam = s.poles
    assert lam.size == 4 and np.all(lam.real < 0)
    np.testing.assert_allclose(sorted(np.abs(lam)), sorted(np.abs(np.linalg.eigvals(s.state_matrix))), rtol=1e-12)


def test_frf_against_modal_superposition_and_direct_solve():
    b, m, k = chopra_frame()
    load = np.zeros(5)
    load[-1] = 1.0
    w = np.linspace(0.0, 25.0, 201)
    X = b.frf(w, load)
    phi, wn, z = b.modes, b.natural_frequencies, b.modal_damping_ratios
    modal = np.array([(phi * ((phi.T @ load) / (wn**2 - om**2 + 2j * z * wn * om))) @ np.ones(5) for om in w])
    np.testing.assert_allclose(X, modal, rtol=1e-9, atol=1e-12 * np.max(np.abs(modal)))
    s = tmd_system(1.0, 0.5, 20.0, tuning=hinf_tuning(0.05))
    direct = [np.linalg.solve(s.K - om**2 * s.M + 1j * om * s.C, [5.0, 0.0]) for om in (3.0, 4.47)]
    np.testing.assert_allclose(s.frf([3.0, 4.47], [5.0, 0.0]), direct, rtol=1e-13)


def augmented_expm(model, t, load, omega, x0, v0):
    """Independent reference: exp of the first-order system with two extra states for sin and cos."""
    n = model.n
    A = np.zeros((2 * n + 2, 2 * n + 2))
    A[:n, n : 2 * n] = np.eye(n)
    Minv = np.linalg.inv(model.M)
    A[n : 2 * n, :n] = -Minv @ model.K
    A[n : 2 * n, n : 2 * n] = -Minv @ model.C
    A[n : 2 * n, 2 * n] = Minv @ load
    A[2 * n, 2 * n + 1], A[2 * n + 1, 2 * n] = omega, -omega
    z0 = np.concatenate([x0, v0, [0.0, 1.0]])
    return np.array([sla.expm(A * ti) @ z0 for ti in t])


@pytest.mark.parametrize("case", ["tmd", "building", "undamped resonance"])
def test_response_against_augmented_expm(case):
    if case == "tmd":
        model, load, omega = tmd_system(1.0, 0.5, 20.0, tuning=hinf_tuning(0.05, 0.0559)), np.array([5.0, 0.0]), 4.47
    elif case == "building":
        model = add_absorber(chopra_frame()[0], -1, 0.02 * 5 * 45359.237, k_a=1e5, c_a=2e3)
        load, omega = np.r_[np.zeros(4), 1e4, 0.0], 3.1
    else:
        model, omega = MDOF(M=np.eye(2), C=np.zeros((2, 2)), K=[[2.0, -1.0], [-1.0, 2.0]]), 1.0
        load = np.array([1.0, 0.0])
    rng = np.random.default_rng(11)
    x0, v0 = rng.normal(size=model.n) * 0.1, rng.normal(size=model.n) * 0.1
    t = np.array([0.0, 0.37, 3.0, 11.2, 50.0])
    ref = augmented_expm(model, t, load, omega, x0, v0)
    got = model.response(t, load, omega, x0=x0, v0=v0)
    scale = np.max(np.abs(ref[:, : model.n]))
    np.testing.assert_allclose(got.x, ref[:, : model.n], atol=1e-9 * scale)
    np.testing.assert_allclose(got.v, ref[:, model.n : 2 * model.n], atol=1e-9 * np.max(np.abs(ref[:, model.n :])))
    if case != "undamped resonance":
        other = model.response(t, load, omega, x0=x0, v0=v0, method="expm")
        np.testing.assert_allclose(got.x, other.x, atol=1e-10 * scale)


def test_response_of_one_dof_is_the_papers_closed_form_and_tmd_matches_dop853():
    t = np.linspace(0.0, 50.0, 2001)
    one = MDOF(M=[[1.0]], C=[[0.5]], K=[[20.0]]).response(t, [5.0], 4.47)
    exact = vibration.exact_response(
        vibration.Oscillator(m=1.0, c=0.5, k=20.0), vibration.SineForce(F0=5.0, omega=4.47), t
    )
    np.testing.assert_allclose(one.x[:, 0], exact.x, atol=1e-11)
    np.testing.assert_allclose(one.v[:, 0], exact.v, atol=1e-10)
    s = tmd_system(1.0, 0.5, 20.0, tuning=den_hartog(0.05))
    got = s.response(t, [5.0, 0.0], 4.47, x0=[0.01, -0.02], v0=[0.0, 0.3])
    A = s.state_matrix
    b = np.concatenate([np.zeros(2), np.linalg.solve(s.M, [5.0, 0.0])])
    sol = solve_ivp(lambda tt, z: A @ z + b * np.sin(4.47 * tt), (0, 50), [0.01, -0.02, 0.0, 0.3], method="DOP853",
                    t_eval=t, rtol=1e-12, atol=1e-13)  # fmt: skip
    np.testing.assert_allclose(got.x, sol.y[:2].T, atol=1e-8)


# ----------------------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    ("call", "name", "bad"),
    [
        (lambda: den_hartog(0.0), "mu", 0.0),
        (lambda: den_hartog(-0.1), "mu", -0.1),
        (lambda: hinf_tuning(11.0), "mu", 11.0),
        (lambda: hinf_tuning(0.05, zeta_p=0.6), "zeta_p", 0.6),
        (lambda: h2_tuning(0.05, zeta_p=-0.01), "zeta_p", -0.01),
        (lambda: h2_tuning(True), "mu", True),
        (lambda: tmd_magnification(0.05, 0.0, 0.1, r=1.0), "f", 0.0),
        (lambda: tmd_magnification(0.05, 1.0, -0.1, r=1.0), "zeta_a", -0.1),
        (lambda: tmd_magnification(0.05, 1.0, 0.1, r=[1.0, -2.0]), "r", -2.0),
        (lambda: tmd_peak(0.05, 1.0, float("nan")), "zeta_a", float("nan")),
        (lambda: mistuned_peak(den_hartog(0.05), -0.95), "stiffness_error", -0.95),
    ],
)
def test_bad_tmd_input_names_the_parameter(raises_parameter_error, call, name, bad):
    with raises_parameter_error(name, bad):
        call()


def test_bad_method_and_closed_form_with_damped_primary():
    with pytest.raises(ParameterError, match="method"):
        hinf_tuning(0.05, method="guess")
    with pytest.raises(ParameterError, match="zeta_p"):
        h2_tuning(0.05, zeta_p=0.05, method="closed form")


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (([[1.0, 0.1], [0.0, 1.0]], np.zeros((2, 2)), np.eye(2)), "M"),
        ((np.eye(2), np.zeros((2, 2)), [[1.0, 2.0], [2.0, 1.0]]), "K"),
        ((np.eye(2), -np.eye(2), np.eye(2)), "C"),
        ((np.eye(2), np.zeros((3, 3)), np.eye(2)), "C"),
        ((np.eye(2), np.zeros((2, 2)), [[1.0, np.inf], [np.inf, 1.0]]), "K"),
        (([1.0, 2.0], np.zeros((2, 2)), np.eye(2)), "M"),
    ],
)
def test_bad_matrices_are_named(args, name):
    with pytest.raises(ParameterError, match=rf"^{name}\b"):
        MDOF(**dict(zip(("M", "C", "K"), args, strict=True)))


def test_bad_mdof_calls_are_named():
    s = MDOF(M=np.eye(2), C=np.zeros((2, 2)), K=2 * np.eye(2))
    with pytest.raises(ParameterError, match="load"):
        s.frf([1.0], [1.0, 2.0, 3.0])
    with pytest.raises(ParameterError, match="omegas"):
        s.frf([-1.0], [1.0, 0.0])
    with pytest.raises(ParameterError, match="omega"):
        s.response([0.0, 1.0], [1.0, 0.0], -2.0)
    with pytest.raises(ParameterError, match="t"):
        s.response([-1.0, 1.0], [1.0, 0.0], 2.0)
    with pytest.raises(ParameterError, match="x0"):
        s.response([0.0], [1.0, 0.0], 2.0, x0=[1.0])
    with pytest.raises(ParameterError, match="dof"):
        add_absorber(s, 2, 1.0, k_a=1.0, c_a=0.0)
    with pytest.raises(ParameterError, match="masses"):
        shear_building([1.0, 1.0], [1.0], 0.05)
    with pytest.raises(ParameterError, match="zeta"):
        modal_damping_matrix(np.eye(2), np.eye(2), -0.1)
