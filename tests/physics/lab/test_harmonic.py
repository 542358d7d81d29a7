"""One-harmonic least squares: exact recovery, calibrated errors, non-uniform time, omega estimated."""

from __future__ import annotations

import numpy as np
import pytest

from vibration.physics.lab import harmonic_fit
from vibration.physics.model import ParameterError


@pytest.mark.parametrize("omega", [None, 3.7])
def test_exact_recovery_noiseless_non_uniform(omega):
    rng = np.random.default_rng(1)
    t = np.sort(rng.uniform(0.0, 20.0, 300))
    y = -0.3 + 1.7 * np.sin(3.7 * t + 2.5)
    f = harmonic_fit(t, y, omega)
    assert f.omega == pytest.approx(3.7, abs=1e-9)
    assert f.amplitude == pytest.approx(1.7, abs=1e-9)
    assert f.phase == pytest.approx(2.5, abs=1e-9)
    assert f.offset == pytest.approx(-0.3, abs=1e-9)
    assert f.residual_rms < 1e-9 and f.n == 300
    assert (f.stderr["omega"] == 0.0) == (omega is not None)


def test_phase_wraps_and_amplitude_is_positive():
    t = np.linspace(0.0, 10.0, 200)
    f = harmonic_fit(t, -2.0 * np.sin(2.0 * t + 0.5), 2.0)  # = 2 sin(2t + 0.5 - pi)
    assert f.amplitude == pytest.approx(2.0, abs=1e-12)
    assert f.phase == pytest.approx(0.5 - np.pi, abs=1e-12)
    assert -np.pi < f.phase <= np.pi


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
@pytest.mark.parametrize("omega", [None, 4.5])
def test_stderr_calibrated_on_noisy_data(omega):
    seeds, sigma = 300, 0.05
    z = {k: [] for k in ("amplitude", "phase", "offset", "omega")}
    for seed in range(seeds):
        rng = np.random.default_rng(seed)
        t = np.arange(200) * 0.05 + rng.uniform(-0.01, 0.01, 200)
        y = 0.2 + 1.0 * np.sin(4.5 * t + 1.0) + rng.normal(0.0, sigma, t.size)
        f = harmonic_fit(t, y, omega)
        truth = {"amplitude": 1.0, "phase": 1.0, "offset": 0.2, "omega": 4.5}
        for k in z:
            if f.stderr[k] > 0:
                z[k].append((getattr(f, k) - truth[k]) / f.stderr[k])
    for k, v in z.items():
        if omega is not None and k == "omega":
            assert v == []
            continue
        v = np.asarray(v)
        # standardised errors: sd 1 within sampling error (sd of sd ~ 1/sqrt(2*300) = 0.04), mean 0
        assert abs(np.std(v) - 1.0) < 0.15, (k, np.std(v))
        assert abs(np.mean(v)) < 0.2, (k, np.mean(v))


def test_predict():
    t = np.linspace(0.0, 5.0, 100)
    f = harmonic_fit(t, 1.0 + np.sin(6.0 * t))
    assert np.allclose(f.predict(t), 1.0 + np.sin(6.0 * t), atol=1e-9)


@pytest.mark.parametrize(
    ("t", "y", "omega", "fragment"),
    [
        (np.arange(30.0), np.r_[np.sin(np.arange(29.0)), np.nan], None, "y[29]"),
        (np.r_[np.arange(29.0), 0.5], np.sin(np.arange(30.0)), None, "t[29]"),
        (np.arange(30.0), np.sin(np.arange(25.0)), None, "same number"),
        (np.arange(30.0), np.full(30, 2.0), None, "constant"),
        (np.arange(5.0), np.sin(np.arange(5.0)), None, "at least 20"),
        (np.arange(30.0), np.sin(np.arange(30.0)) * 1j, None, "complex"),
        (np.arange(30.0) > 3, np.sin(np.arange(30.0)), None, "bool"),
        (np.arange(30.0), np.sin(np.arange(30.0)), -1.0, "omega"),
        (np.arange(30.0), np.sin(np.arange(30.0)), True, "omega"),
    ],
)
def test_validation(t, y, omega, fragment):
    with pytest.raises(ParameterError) as info:
        harmonic_fit(t, y, omega)
    assert fragment in str(info.value)
