"""Steady forced response with Coulomb + viscous friction; the stick-slip simulator."""

from __future__ import annotations

import numpy as np
import pytest

from vibration.physics.lab import (
    free_decay_response,
    friction_forced_amplitude,
    friction_forced_amplitude_hb,
    simulate_friction_oscillator,
)
from vibration.physics.model import ParameterError


def test_no_friction_is_the_linear_magnification():
    r = np.linspace(0.05, 4.0, 400)
    for zeta in (0.0, 0.05, 0.3):
        lin = 1.0 / np.sqrt((1 - r**2) ** 2 + (2 * zeta * r) ** 2)
        assert np.allclose(friction_forced_amplitude(r, zeta, 0.0), lin, rtol=1e-12, atol=0)
        assert np.allclose(friction_forced_amplitude_hb(r, zeta, 0.0), lin, rtol=1e-12, atol=0)


def test_den_hartog_pure_coulomb_special_case():
    # Den Hartog (1930): X/X_st = sqrt(V0^2 - delta^2 U^2), V0 = 1/(1 - r^2), U = sin(pi/r) / (r (1 + cos(pi/r)))
    r = np.array([0.6, 0.8, 0.9, 1.1, 1.3, 1.5, 2.0, 3.0])
    delta = 0.2
    v0 = 1 / (1 - r**2)
    u = np.sin(np.pi / r) / (r * (1 + np.cos(np.pi / r)))
    assert np.allclose(friction_forced_amplitude(r, 0.0, delta), np.sqrt(v0**2 - (delta * u) ** 2), rtol=1e-10)


def test_exact_agrees_with_the_linear_solver_with_small_friction():
    # tiny friction: the exact solution tends to the linear one, the harmonic balance too
    r = np.array([0.7, 1.0, 1.4])
    lin = 1 / np.sqrt((1 - r**2) ** 2 + (2 * 0.1 * r) ** 2)
    assert np.allclose(friction_forced_amplitude(r, 0.1, 1e-6), lin, rtol=1e-4)


def _simulated_amplitude(r, zeta, delta, periods=150, per_period=256):
    t = np.linspace(0.0, periods * 2 * np.pi / r, periods * per_period + 1)
    th, _ = simulate_friction_oscillator(t, np.cos(r * t), 1.0, zeta=zeta, friction=delta, gain=1.0, substeps=2)
    last = t > t[-1] - 10 * 2 * np.pi / r
    return 0.5 * (th[last].max() - th[last].min())


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
@pytest.mark.parametrize(
    ("r", "zeta", "delta"), [(0.8, 0.05, 0.2), (1.2, 0.1, 0.3), (1.5, 0.0, 0.2), (2.0, 0.02, 0.5), (0.9, 0.05, 0.1)]
)
def test_exact_against_long_simulation(r, zeta, delta):
    # sampled extremes of a 256-point period miss the peak by at most (pi/256)^2/2 = 8e-5 relative;
    # 150 periods are enough for the transient to die (friction removes it in a finite time)
    exact = friction_forced_amplitude(r, zeta, delta)
    assert _simulated_amplitude(r, zeta, delta) == pytest.approx(exact, rel=1e-3)


def test_sticking_region_is_nan_and_scalar_in_float_out():
    assert np.isnan(friction_forced_amplitude(1.5, 0.05, 0.9))  # 4 delta / pi > 1 region: stops
    assert np.isnan(friction_forced_amplitude_hb(1.5, 0.05, 0.9))
    assert np.isnan(friction_forced_amplitude(0.2, 0.05, 0.5))  # slow drive with strong friction: stops
    x = friction_forced_amplitude(1.5, 0.05, 0.1)
    assert isinstance(x, float) and x > 0
    out = friction_forced_amplitude(np.array([0.2, 1.5]), 0.05, 0.5)
    assert out.shape == (2,) and np.isnan(out[0]) and out[1] > 0


def test_simulator_linear_exact_solution():
    # Delta = 0, from rest: x(t) = steady + transient, the closed form of the linear oscillator
    w, z, r = 4.5, 0.05, 0.8
    om = r * w
    # the simulator integrates the linearly interpolated drive: on a 0.5 ms grid that differs from
    # the sine by (om dt)^2 / 8 = 4e-7 of its amplitude, so the comparison is good to about 1e-6
    t = np.linspace(0.0, 5.0, 10_001)
    th, _ = simulate_friction_oscillator(t, np.sin(om * t), w, zeta=z, friction=0.0, gain=1.0, substeps=1)
    H = 1 / (1 - r**2 + 2j * z * r)
    wd = w * np.sqrt(1 - z**2)
    # particular: Im(H e^{i om t}); homogeneous fixes x(0) = 0, v(0) = 0
    xp0, vp0 = np.imag(H), np.real(H) * om
    a = -xp0
    b = (-vp0 + z * w * a) / wd
    exact = np.imag(H * np.exp(1j * om * t)) + np.exp(-z * w * t) * (a * np.cos(wd * t) + b * np.sin(wd * t))
    assert np.max(np.abs(th - exact)) < 2e-6


def test_simulator_free_decay_closed_form():
    t = np.linspace(0.0, 12.0, 241)
    th, v = simulate_friction_oscillator(
        t, np.zeros_like(t), 4.5, zeta=0.02, friction=0.05, gain=1.0, theta0=1.1, offset=0.1
    )
    exact = free_decay_response(t, 4.5, 0.02, friction=0.05, offset=0.1, theta0=1.1)
    assert np.max(np.abs(th - exact)) < 1e-6
    assert v[-1] == 0.0  # stuck in the dead band


def test_simulator_validation():
    t = np.linspace(0.0, 1.0, 11)
    with pytest.raises(ParameterError, match="drive has 5 samples"):
        simulate_friction_oscillator(t, np.zeros(5), 4.5, zeta=0.0, friction=0.0, gain=1.0)
    with pytest.raises(ParameterError, match="zeta"):
        simulate_friction_oscillator(t, np.zeros(11), 4.5, zeta=-0.1, friction=0.0, gain=1.0)
    with pytest.raises(ParameterError, match="steps"):
        simulate_friction_oscillator(
            np.linspace(0, 1, 300_000), np.zeros(300_000), 4.5, zeta=0.0, friction=0.0, gain=1.0, substeps=20
        )
    with pytest.raises(ParameterError, match="friction_ratio"):
        friction_forced_amplitude(1.0, 0.1, -0.1)
    with pytest.raises(ParameterError, match=r"r\[1\]"):
        friction_forced_amplitude(np.array([1.0, -1.0]), 0.1, 0.1)
    with pytest.raises(ParameterError, match="r = "):
        friction_forced_amplitude(True, 0.1, 0.1)
