"""Model records: textbook values, regimes, derived quantities and validation."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import vibration
from vibration import REGIMES, Oscillator, ParameterError, SineForce, exact_response

SQRT20 = math.sqrt(20.0)


# --- textbook values (m = 1 kg, c = 0.5 N s/m, k = 20 N/m: the paper's nominal system) ---


def test_textbook_values_of_the_nominal_oscillator():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    assert osc.natural_frequency == pytest.approx(4.4721, abs=5e-5)  # rad/s, as printed in textbooks
    assert osc.natural_frequency == pytest.approx(SQRT20, rel=1e-15)
    assert osc.critical_damping == pytest.approx(2.0 * SQRT20, rel=1e-15)  # N s/m
    assert osc.damping_ratio == pytest.approx(0.5 / (2.0 * SQRT20), rel=1e-15)
    assert osc.damping_ratio == pytest.approx(0.0559, abs=5e-5)
    assert osc.decay_rate == pytest.approx(0.25, rel=1e-15)  # 1/s
    zeta = 0.5 / (2.0 * SQRT20)
    assert osc.damped_natural_frequency == pytest.approx(SQRT20 * math.sqrt(1.0 - zeta**2), rel=1e-14)
    assert osc.quality_factor == pytest.approx(1.0 / (2.0 * zeta), rel=1e-14)
    assert osc.half_power_bandwidth == pytest.approx(0.5, rel=1e-15)  # c / m, rad/s
    assert osc.time_constant == pytest.approx(2.0 * 1.0 / 0.5, rel=1e-15)  # 2 m / c = 4 s
    assert osc.regime == "underdamped"


def test_textbook_values_with_non_unit_mass():
    m, c, k = 3.0, 0.4, 7.0
    osc = Oscillator(m=m, c=c, k=k)
    wn = math.sqrt(k / m)
    zeta = c / (2.0 * math.sqrt(k * m))
    assert osc.natural_frequency == pytest.approx(wn, rel=1e-15)
    assert osc.critical_damping == pytest.approx(2.0 * math.sqrt(k * m), rel=1e-15)
    assert osc.damping_ratio == pytest.approx(zeta, rel=1e-15)
    assert osc.quality_factor == pytest.approx(1.0 / (2.0 * zeta), rel=1e-14)
    assert osc.half_power_bandwidth == pytest.approx(c / m, rel=1e-15)
    assert osc.half_power_bandwidth == pytest.approx(2.0 * zeta * wn, rel=1e-14)
    assert osc.time_constant == pytest.approx(2.0 * m / c, rel=1e-15)
    assert osc.damped_natural_frequency == pytest.approx(wn * math.sqrt(1.0 - zeta**2), rel=1e-14)


def test_time_constant_critically_damped_is_one_over_natural_frequency():
    for m, k in [(1.0, 20.0), (3.0, 7.0)]:
        osc = Oscillator(m=m, c=2.0 * math.sqrt(k * m), k=k)
        assert osc.regime == "critically damped"
        assert osc.time_constant == pytest.approx(1.0 / math.sqrt(k / m), rel=1e-12)
        # |zeta - 1| <= 1e-12 counts as critical; c = 2 sqrt(k m) rounded leaves
        # wd = wn sqrt(1 - zeta^2) <= wn sqrt(2e-12) (2e-8 rad/s measured for m = 3, k = 7)
        assert osc.damped_natural_frequency <= math.sqrt(2e-12) * math.sqrt(k / m)


@pytest.mark.parametrize(("m", "c", "k"), [(1.0, 15.0, 20.0), (1.0, 200.0, 20.0), (3.0, 40.0, 7.0)])
def test_time_constant_overdamped(m, c, k):
    osc = Oscillator(m=m, c=c, k=k)
    assert osc.regime == "overdamped"
    sigma, wn2 = c / (2.0 * m), k / m
    assert osc.time_constant == pytest.approx(1.0 / (sigma - math.sqrt(sigma**2 - wn2)), rel=1e-9)
    assert osc.damped_natural_frequency == 0.0


@pytest.mark.parametrize(("m", "c", "k"), [(1.0, 15.0, 20.0), (3.0, 40.0, 7.0)])
def test_time_constant_overdamped_is_the_decay_of_the_free_response(m, c, k):
    """Second formulation: late in a free decay, x(t + 1) / x(t) = exp(-1 / tau)."""
    osc = Oscillator(m=m, c=c, k=k)
    tau = osc.time_constant
    t = np.array([8.0 * tau, 8.0 * tau + 1.0])
    x = exact_response(osc, SineForce(F0=0.0, omega=0.0), t, x0=1.0, v0=0.0).x
    assert math.log(x[1] / x[0]) == pytest.approx(-1.0 / tau, rel=1e-9)


# --- regimes ---


@pytest.mark.parametrize(
    ("c", "regime"),
    [
        (-1.0, "unstable"),
        (-2.0 * SQRT20, "unstable"),
        (0.0, "undamped"),
        (0.5, "underdamped"),
        (2.0 * SQRT20, "critically damped"),
        (2.0 * SQRT20 * (1.0 - 1e-9), "underdamped"),
        (2.0 * SQRT20 * (1.0 + 1e-9), "overdamped"),
        (15.0, "overdamped"),
    ],
)
def test_regime(c, regime):
    osc = Oscillator(m=1.0, c=c, k=20.0)
    assert osc.regime == regime
    assert osc.regime in REGIMES


def test_regimes_are_the_five_documented_ones():
    assert set(REGIMES) == {"undamped", "underdamped", "critically damped", "overdamped", "unstable"}


def test_critically_damped_with_non_unit_mass():
    m, k = 3.0, 7.0
    assert Oscillator(m=m, c=2.0 * math.sqrt(k * m), k=k).regime == "critically damped"


def test_derived_values_undamped():
    osc = Oscillator(m=1.0, c=0.0, k=20.0)
    assert osc.damping_ratio == 0.0
    assert osc.quality_factor == math.inf
    assert osc.time_constant == math.inf
    assert osc.half_power_bandwidth == 0.0
    assert osc.damped_natural_frequency == pytest.approx(SQRT20, rel=1e-15)


@pytest.mark.parametrize("c", [-0.2, -1.0, -15.0])
def test_derived_values_negative_damping_are_undefined(c):
    osc = Oscillator(m=1.0, c=c, k=20.0)
    assert osc.regime == "unstable"
    assert osc.damping_ratio == pytest.approx(c / (2.0 * SQRT20), rel=1e-15)
    assert osc.decay_rate == pytest.approx(c / 2.0, rel=1e-15)
    assert math.isnan(osc.quality_factor)
    assert math.isnan(osc.time_constant)
    assert math.isnan(osc.half_power_bandwidth)


def test_sine_force():
    f = SineForce(F0=5.0, omega=3.0)
    assert f.frequency_hz == pytest.approx(3.0 / (2.0 * math.pi), rel=1e-15)
    t = np.linspace(0.0, 10.0, 101)
    np.testing.assert_allclose(f(t), 5.0 * np.sin(3.0 * t), rtol=0, atol=1e-15)
    assert float(f(0.0)) == 0.0


def test_numpy_and_integer_inputs_become_floats():
    osc = Oscillator(m=np.float32(2.0), c=np.int64(0), k=20)
    f = SineForce(F0=np.int32(5), omega=np.float64(3.0))
    for value in (osc.m, osc.c, osc.k, f.F0, f.omega):
        assert type(value) is float
    assert (osc.m, osc.c, osc.k, f.F0, f.omega) == (2.0, 0.0, 20.0, 5.0, 3.0)


def test_zero_force_and_zero_frequency_are_allowed():
    f = SineForce(F0=0.0, omega=0.0)
    assert (f.F0, f.omega) == (0.0, 0.0)


# --- frozen records ---


def test_records_are_frozen():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    force = SineForce(F0=5.0, omega=3.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        osc.m = 2.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        osc.c = 0.1
    with pytest.raises(dataclasses.FrozenInstanceError):
        force.F0 = 1.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        force.omega = 1.0
    assert (osc.m, osc.c, force.F0, force.omega) == (1.0, 0.5, 5.0, 3.0)


# --- validation ---


def test_parameter_error_is_a_value_error():
    assert issubclass(ParameterError, ValueError)


GOOD_OSC = {"m": 1.0, "c": 0.5, "k": 20.0}
GOOD_FORCE = {"F0": 5.0, "omega": 3.0}

NOT_FINITE = [math.nan, math.inf, -math.inf]
NOT_REAL = ["1.0", True, False, None, 1 + 0j, [1.0]]

OSC_BAD = (
    [("m", v, "m > 0") for v in [0, 0.0, -1, -1.0, -1e-300]]
    + [("k", v, "k > 0") for v in [0, 0.0, -20.0]]
    + [(name, v, "finite") for name in GOOD_OSC for v in NOT_FINITE]
    + [(name, v, "finite") for name in GOOD_OSC for v in NOT_REAL]
)
FORCE_BAD = (
    [("F0", v, "F0 >= 0") for v in [-1.0, -1e-12, -5]]
    + [("omega", v, "omega >= 0") for v in [-3.0, -1e-300]]
    + [(name, v, "finite") for name in GOOD_FORCE for v in NOT_FINITE]
    + [(name, v, "finite") for name in GOOD_FORCE for v in NOT_REAL]
)


@pytest.mark.parametrize(("name", "bad", "allowed"), OSC_BAD, ids=lambda v: repr(v))
def test_oscillator_refuses_bad_values(raises_parameter_error, name, bad, allowed):
    with raises_parameter_error(name, bad, allowed):
        Oscillator(**{**GOOD_OSC, name: bad})


@pytest.mark.parametrize(("name", "bad", "allowed"), FORCE_BAD, ids=lambda v: repr(v))
def test_sine_force_refuses_bad_values(raises_parameter_error, name, bad, allowed):
    with raises_parameter_error(name, bad, allowed):
        SineForce(**{**GOOD_FORCE, name: bad})


def test_message_gives_the_unit():
    with pytest.raises(ParameterError, match=r"m = 0\.0 kg .*allowed m > 0 kg"):
        Oscillator(m=0.0, c=0.5, k=20.0)
    with pytest.raises(ParameterError, match=r"omega = -3\.0 rad/s .*allowed omega >= 0 rad/s"):
        SineForce(F0=5.0, omega=-3.0)


def test_wrong_record_types_are_named():
    from vibration import exact_response, simulate, steady_state

    osc, force = vibration.Oscillator(m=1.0, c=0.5, k=20.0), vibration.SineForce(F0=5.0, omega=3.0)
    with pytest.raises(vibration.ParameterError, match="osc = .* is not an Oscillator"):
        exact_response((1, 2, 3), force, [0.0, 1.0])
    with pytest.raises(vibration.ParameterError, match="force = .* is not a load record: allowed one of SineForce"):
        simulate(osc, 5.0, 1.0)
    with pytest.raises(vibration.ParameterError, match="osc = .* is not an Oscillator"):
        steady_state(None, force)
    with pytest.raises(vibration.ParameterError, match="t = .* is not an array of numbers"):
        exact_response(osc, force, ["a"])


@pytest.mark.parametrize("scale", [1e-200, 1e200])
def test_derived_quantities_survive_extreme_scales(scale):
    osc = vibration.Oscillator(m=scale, c=3.0 * scale, k=scale)
    assert osc.damping_ratio == pytest.approx(1.5, rel=1e-14)
    assert osc.regime == "overdamped"
