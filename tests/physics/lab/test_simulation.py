"""The driven-wheel simulator checked against closed forms (the linear steady state, the Coulomb free
decay's 2 Delta per half period) and SciPy's solve_ivp on the same law with driven forcing."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from vibration.physics.lab import simulate_driven
from vibration.physics.model import ParameterError

W = 4.5


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_linear_steady_state_matches_the_closed_form():
    omegas = np.array([3.5, 4.3, 4.5, 5.2])
    zeta, force = 0.04, 0.2
    t, th = simulate_driven(80.0, sample_interval=0.05, omega_n=W, force=force, omega=omegas, zeta=zeta, substeps=8)
    late = t > 60.0
    r = omegas / W
    exact = force / np.sqrt((1 - r * r) ** 2 + (2 * zeta * r) ** 2)
    got = 0.5 * (th[:, late].max(axis=1) - th[:, late].min(axis=1))
    np.testing.assert_allclose(got, exact, rtol=2e-3)


def test_coulomb_free_decay_loses_two_friction_angles_per_half_period():
    delta, x0 = 0.1, 3.0
    t, th = simulate_driven(
        12.0, sample_interval=0.01, omega_n=W, force=0.0, omega=W, friction=delta, theta0=x0, substeps=4
    )
    for k in range(1, 8):
        i = np.argmin(np.abs(t - k * math.pi / W))
        window = th[0, max(i - 5, 0) : i + 6]
        extreme = np.max(np.abs(window))
        assert extreme == pytest.approx(x0 - 2 * k * delta, abs=2e-3)
    # stops inside the dead band and stays
    assert abs(th[0, -1]) <= delta + 1e-9
    assert np.ptp(th[0, t > 11.5]) < 1e-9


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_driven_quadratic_and_power_laws_against_solve_ivp():
    zeta, delta, b, a, p, force, om = 0.01, 0.05, 0.02, 0.001, 3.0, 0.3, 4.3

    def rhs(tt, x):
        v = x[1]
        s = math.tanh(v / 1e-5)
        return [
            v,
            W * W * (force * math.sin(om * tt + 0.4) - x[0])
            - 2 * zeta * W * v
            - W * W * delta * s
            - b * v * abs(v)
            - a * abs(v) ** p * s,
        ]

    t, th = simulate_driven(
        30.0,
        sample_interval=0.05,
        omega_n=W,
        force=force,
        omega=om,
        phase=0.4,
        zeta=zeta,
        friction=delta,
        quadratic=b,
        power=a,
        power_exponent=p,
        theta0=0.5,
        velocity0=-1.0,
        substeps=10,
    )
    ref = integrate.solve_ivp(rhs, (0, t[-1]), [0.5, -1.0], method="LSODA", rtol=1e-9, atol=1e-11, t_eval=t).y[0]
    assert np.max(np.abs(th[0] - ref)) < 5e-3 * np.max(np.abs(ref))


def test_budget_and_step_are_refused_with_a_clear_error():
    with pytest.raises(ParameterError, match="max_evaluations"):
        simulate_driven(100.0, sample_interval=0.05, omega_n=W, force=0.1, omega=W, max_evaluations=1000)
    with pytest.raises(ParameterError, match="substeps"):
        simulate_driven(10.0, sample_interval=0.5, omega_n=W, force=0.1, omega=W, substeps=1)
    with pytest.raises(ParameterError, match="zeta"):
        simulate_driven(10.0, sample_interval=0.05, omega_n=W, force=0.1, omega=W, zeta=-1.0)
    with pytest.raises(ParameterError, match="omega has 2 values"):
        simulate_driven(10.0, sample_interval=0.05, omega_n=[W, W, W], force=0.1, omega=[W, W])
