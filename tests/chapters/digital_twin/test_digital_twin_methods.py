"""Chapter 10's own methods against independent ones: the batch identification against identify(), the
Markov-chain run lengths against simulation, the Kalman filter's stated sigma against its error."""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibration import Oscillator
from vibration.book.chapters.digital_twin import cusum, montecarlo
from vibration.book.chapters.digital_twin.study import digital_twin_study
from vibration.physics.twin import cubic_response, identify

# every test here builds on a study or a book that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

OSC = Oscillator(m=1.0, c=0.5, k=20.0)
SMALL = dict(t_record=30.0, runs=20, sweep_runs=5, assumption_runs=20, t_monitor=120.0, detect_runs=5)


def test_batch_fit_reproduces_identify_run_by_run():
    t, force, clean = montecarlo.design(OSC, 30.0, 0.02, seed=3, band=(0.1, 2.0), rms=2.0)
    sd = 0.05 * float(np.sqrt(np.mean(clean**2)))
    # white noise as assumed: estimates and standard errors to 1e-6 relative
    assert montecarlo.agreement(OSC, t, force, clean=clean, noise_sd=sd, seed=3, stream=0, runs=4) < 1e-6


def test_batch_fit_reproduces_identify_under_model_error():
    """A cubic spring biases k by tens of per cent: the batch must still land on identify()'s optimum."""
    t, force, linear = montecarlo.design(OSC, 30.0, 0.02, seed=5, band=(0.1, 2.0), rms=2.0)
    k3 = 0.05 * OSC.k / float(np.mean(linear**2))
    clean = cubic_response(OSC, k3, t, force=force)
    sd = 0.05 * float(np.sqrt(np.mean(clean**2)))
    ex = montecarlo.experiment(OSC, t, force, clean=clean, noise_sd=sd, runs=3, seed=5, stream=9, noise=0.05)
    for i in range(3):
        y = clean + sd * montecarlo.ar1(1, t.size, 0.0, rngs=[np.random.default_rng([5, 9, i])])[0]
        ref = identify(t, force, x=y, search="local")
        np.testing.assert_allclose(ex.estimates[i], [ref.m, ref.c, ref.k], rtol=1e-6)
        np.testing.assert_allclose(ex.stderr[i], ref.stderr, rtol=1e-4)
    assert abs(ex.rel_bias[2]) > 0.05  # the case really is biased


@pytest.mark.parametrize(("h", "drift"), [(3.0, 1.0), (6.0, 1.0), (5.0, 0.386)])
def test_markov_chain_arl_against_simulation(h, drift):
    """Brook-Evans ARL of the chi-square CUSUM against a restarted CUSUM on 2 million simulated increments."""
    rng = np.random.default_rng(11)
    z = rng.standard_normal(2_000_000) ** 2 - 1.0 - drift
    alarms = int(cusum.restart_alarms(z, [h])[0])
    measured = z.size / alarms
    se = measured / math.sqrt(alarms)
    theory, err = cusum.arl_theory(h, drift)
    assert err < 1e-3 * theory
    assert abs(measured - theory) < 3.0 * se + 0.01 * theory


def test_alarm_distribution_against_simulation():
    """Time-varying mean shift: the propagated alarm-time law against 20000 simulated CUSUM paths."""
    mu = np.r_[np.zeros(100), np.linspace(0.0, 2.0, 200), np.full(300, 2.0)]
    prob = cusum.alarm_distribution(mu, 8.0, 1.0)
    rng = np.random.default_rng(2)
    runs = 20000
    g = np.zeros(runs)
    first = np.full(runs, -1)
    for n in range(mu.size):
        g = np.maximum(g + (rng.standard_normal(runs) + mu[n]) ** 2 - 2.0, 0.0)
        hit = (g > 8.0) & (first < 0)
        first[hit] = n
    early = float(np.mean((first >= 0) & (first < 100)))
    assert prob[:100].sum() == pytest.approx(early, abs=4 * math.sqrt(early * (1 - early) / runs) + 1e-3)
    late = first[first >= 100] - 100
    n = np.arange(mu.size)
    mean = float(np.sum(prob[100:] * (n[100:] - 100)) / prob[100:].sum())
    assert mean == pytest.approx(float(np.mean(late)), abs=4 * float(np.std(late)) / math.sqrt(late.size))


@pytest.fixture(scope="module")
def small():
    return digital_twin_study(**SMALL)


def test_kalman_stated_sigma_matches_its_error_on_its_own_model(small):
    """Over many samples the stated sigma of k is the rms error when k is the random walk the filter assumes
    (within 15 %), and overstated by more than 1.4 times when k is constant."""
    walk = next(c for c in small.kalman if c.truth == "random walk")
    const = next(c for c in small.kalman if c.truth == "constant")
    assert walk.samples > 5000
    assert abs(walk.ratio - 1.0) < 0.15
    assert const.ratio < 1.0 / 1.4
    assert 0.0 < walk.halfwidth < 0.2


def test_run_lengths_agree_with_the_markov_chain(small):
    rl = small.run_lengths
    rows = (rl.alarms >= 20) & np.isfinite(rl.theory)
    assert np.count_nonzero(rows) >= 3
    z = np.abs(rl.measured[rows] - rl.theory[rows]) / rl.stderr[rows]
    assert np.all(z < 3.5), z
    j = small.threshold_index
    for label, ex in small.detection.items():
        d = ex.first_crossing[:, j] - ex.change_time
        d = d[np.isfinite(d) & (d >= 0)]
        th = small.delay_theory[label]
        assert th.detection_probability == pytest.approx(ex.detection_probability[j], abs=0.2)
        se = max(float(np.std(d, ddof=1)) / math.sqrt(d.size), 0.02 * th.mean_delay)
        assert abs(float(np.mean(d)) - th.mean_delay) < 4 * se, label


def test_cusum_drift_is_tuned_to_a_fivefold_power_increase():
    from vibration.physics.twin import cusum_variance_ratio

    rho = cusum_variance_ratio(1.0)
    assert rho == pytest.approx(4.92, abs=0.01)
    assert math.log(rho) / (1 - 1 / rho) == pytest.approx(2.0, rel=1e-12)
