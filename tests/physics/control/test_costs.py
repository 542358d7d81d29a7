"""Chapter 7 (issue 21): loop costs, force floor, set-point feasibility, exact shaper bands, skyhook power.

Each quantity is checked against an independent method: python-control's margins and Pade-approximated
delays, numerical quadrature, closed forms of special cases, and time-domain simulation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from vibration import Oscillator, ParameterError, SineForce, pd_oscillator, steady_state
from vibration.book.chapters.control.study import loop_amplitude
from vibration.physics.control import (
    force_floor,
    hold_force,
    insensitivity_band,
    largest_holdable_reference,
    loop_costs,
    pid_linear_response,
    pid_poles,
    skyhook_power,
    skyhook_transmissibility,
    zv_shaper,
    zvd_shaper,
)

OSC = Oscillator(m=1.0, c=0.5, k=20.0)
FORCE = SineForce(F0=5.0, omega=4.47)
LAWS = [(16.0, 5.5, 0.0), (133.6, 18.7, 0.0), (133.6, 18.7, 512.0), (17.4166, 5.4231, 0.0), (40.0, 2.0, 30.0)]


def _tf(kp, kd, ki):
    import control

    if ki > 0:
        return control.tf([kd, kp, ki], [OSC.m, OSC.c, OSC.k, 0.0])
    return control.tf([kd, kp], [OSC.m, OSC.c, OSC.k])


@pytest.mark.parametrize("kp, kd, ki", LAWS)
def test_crossover_and_phase_margin_match_python_control(kp, kd, ki):
    import control

    lc = loop_costs(OSC, kp, kd, ki=ki, omega=4.47)
    gm, pm, sm, wpc, wgc, wms = control.stability_margins(_tf(kp, kd, ki))
    # python-control reports the crossover of least phase margin; ours is the one of least delay margin
    assert any(abs(w - wgc) < 1e-6 * wgc for w in lc.crossovers)
    i = int(np.argmin(np.abs(lc.crossovers - wgc)))
    L = _tf(kp, kd, ki)(1j * lc.crossovers[i])
    assert abs(abs(L) - 1.0) < 1e-10
    assert math.degrees(np.mod(math.pi + np.angle(L), 2 * math.pi)) == pytest.approx(pm, abs=1e-6)


@pytest.mark.parametrize("kp, kd, ki", LAWS)
def test_delay_margin_separates_stable_from_unstable_delays(kp, kd, ki):
    """Independent: the loop with a 12th-order Pade delay is stable just below the margin, unstable above."""
    import control

    lc = loop_costs(OSC, kp, kd, ki=ki, omega=4.47)
    assert lc.stable
    L = _tf(kp, kd, ki)
    for factor, stable in ((0.97, True), (1.03, False)):
        num, den = control.pade(factor * lc.delay_margin, 12)
        cl = control.feedback(L * control.tf(num, den), 1)
        assert bool(np.all(np.real(cl.poles()) < 0)) is stable, (factor, lc.delay_margin)


@pytest.mark.parametrize("kp, kd, ki", LAWS)
def test_noise_bandwidth_against_quadrature(kp, kd, ki):
    lc = loop_costs(OSC, kp, kd, ki=ki, omega=4.47)
    L = _tf(kp, kd, ki)

    def t2(w):
        lw = L(1j * w)
        return abs(lw / (1 + lw)) ** 2

    val = sum(quad(t2, a, b, limit=400)[0] for a, b in ((0, 1), (1, 10), (10, 100), (100, 1e3)))
    val += quad(t2, 1e3, np.inf, limit=400)[0]
    assert lc.noise_bandwidth == pytest.approx(val, rel=1e-6)


def test_noise_bandwidth_pd_closed_form():
    """T = (b1 s + b0)/(s^2 + a1 s + a0): int_0^inf |T|^2 dw = pi (b1^2 a0 + b0^2) / (2 a0 a1)."""
    kp, kd = 16.0, 5.5
    b1, b0, a1, a0 = kd, kp, OSC.c + kd, OSC.k + kp
    assert loop_costs(OSC, kp, kd, ki=0.0, omega=4.47).noise_bandwidth == pytest.approx(
        math.pi * (b1 * b1 * a0 + b0 * b0) / (2 * a0 * a1), rel=1e-12
    )


def test_loop_amplitude_matches_pd_oscillator_and_pid_simulation():
    assert loop_amplitude(OSC, FORCE, 133.6, ki=0.0, kd=18.7) == pytest.approx(
        steady_state(pd_oscillator(OSC, 133.6, 18.7), FORCE).amplitude, rel=1e-12
    )
    t = np.linspace(40.0, 40.0 + 2 * math.pi / FORCE.omega, 4001)
    x, _, _ = pid_linear_response(OSC, FORCE, 133.6, ki=512.0, kd=18.7, t=t)
    assert float(np.max(np.abs(x))) == pytest.approx(loop_amplitude(OSC, FORCE, 133.6, ki=512.0, kd=18.7), rel=1e-6)


def test_force_floor_is_met_by_direct_minimisation():
    """Independent: the least force amplitude over the phase, by brute-force minimisation of |Z X e^{i phi} - F0|."""
    w = FORCE.omega
    Z = complex(OSC.k - OSC.m * w * w, OSC.c * w)
    phi = np.linspace(0.0, 2 * math.pi, 200001)
    for X in (0.0, 0.03, 0.16, 1.0, 2.5):
        brute = float(np.min(np.abs(Z * X * np.exp(1j * phi) - FORCE.F0))) / math.sqrt(2.0)
        assert force_floor(OSC, FORCE, X) == pytest.approx(brute, rel=1e-8, abs=1e-12)
    with pytest.raises(ParameterError, match="X"):
        force_floor(OSC, FORCE, -1.0)


def test_hold_force_and_feasibility():
    assert hold_force(OSC, FORCE, 0.5) == pytest.approx(15.0)
    assert largest_holdable_reference(OSC, FORCE, 12.0) == pytest.approx(0.35)
    assert math.isnan(largest_holdable_reference(OSC, FORCE, 4.0))


def test_pid_poles_are_the_roots_of_the_characteristic_polynomial():
    p = pid_poles(OSC, 133.6, 512.0, kd=18.7)
    poly = np.poly([p.real_pole, p.pair_omega * complex(-p.pair_zeta, math.sqrt(1 - p.pair_zeta**2)),
                    p.pair_omega * complex(-p.pair_zeta, -math.sqrt(1 - p.pair_zeta**2))])  # fmt: skip
    np.testing.assert_allclose(np.real(poly), [1.0, OSC.c + 18.7, OSC.k + 133.6, 512.0], rtol=1e-10)


@pytest.mark.parametrize("make, exact", [
    (zv_shaper, lambda lv: 2 * np.arccos(lv) / np.pi),
    (zvd_shaper, lambda lv: 2 * np.arccos(np.sqrt(lv)) / np.pi),
])  # fmt: skip
def test_undamped_bands_against_closed_form(make, exact):
    """Undamped: V(q) = |cos(pi q / 2)| (ZV) and cos^2(pi q / 2) (ZVD)."""
    osc = Oscillator(m=1.0, c=0.0, k=20.0)
    for level in (0.01, 0.05, 0.2):
        lo, hi = insensitivity_band(make(osc), osc, level)
        assert lo == pytest.approx(float(exact(level)), abs=1e-10)
        assert hi == pytest.approx(2.0 - float(exact(level)), abs=1e-10)


def test_damped_bands_are_roots_and_beat_the_grid():
    for make in (zv_shaper, zvd_shaper):
        sh = make(OSC)
        lo, hi = insensitivity_band(sh, OSC, 0.05)
        from vibration.physics.control import shaper_residual

        for q in (lo, hi):
            assert shaper_residual(sh, Oscillator(m=1.0, c=0.5, k=20.0 * q * q)) == pytest.approx(0.05, abs=1e-11)
        for q in (lo + 1e-4, hi - 1e-4):
            assert shaper_residual(sh, Oscillator(m=1.0, c=0.5, k=20.0 * q * q)) < 0.05


@pytest.mark.parametrize("c_sky, w", [(8.0, math.sqrt(20.0)), (8.0, 2.0), (3.0, 9.0), (0.0, 4.0)])
def test_skyhook_power_against_quadrature(c_sky, w):
    Y = 0.25
    p = skyhook_power(OSC, c_sky, Y, omega=w)
    H = (OSC.k + 1j * OSC.c * w) / (OSC.k - OSC.m * w * w + 1j * (OSC.c + c_sky) * w)
    assert abs(H) == pytest.approx(float(skyhook_transmissibility(OSC, c_sky, w)), rel=1e-12)
    T = 2 * math.pi / w
    v = lambda t: float(np.imag(1j * w * H * Y * np.exp(1j * w * t)))  # noqa: E731
    pr = lambda t: -c_sky * v(t) * (v(t) - Y * w * math.cos(w * t))  # noqa: E731
    pts = np.linspace(0, T, 9)
    q = lambda f: sum(quad(f, a, b, limit=200)[0] for a, b in zip(pts[:-1], pts[1:], strict=True)) / T  # noqa: E731
    assert p.removed == pytest.approx(q(lambda t: c_sky * v(t) ** 2), rel=1e-9, abs=1e-14)
    assert p.net == pytest.approx(q(pr), rel=1e-9, abs=1e-14)
    assert p.supplied == pytest.approx(q(lambda t: max(pr(t), 0.0)), rel=1e-6, abs=1e-12)
    assert p.gross == pytest.approx(q(lambda t: abs(pr(t))), rel=1e-6, abs=1e-12)
