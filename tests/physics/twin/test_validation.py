"""Residual tests, broken-assumption records and the first-order coverage of the digital twin.

Independent references: scipy's Wilson interval, the chi-square level of the tests measured on
series that satisfy their null hypothesis, a dense-matrix sandwich covariance, ``solve_ivp`` for the
cubic oscillator, and the Monte Carlo coverage against the analytic (sandwich) prediction.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import signal
from scipy.integrate import solve_ivp
from scipy.stats import binomtest, norm
from scipy.stats import t as student_t

from vibration import Oscillator, ParameterError
from vibration.physics import twin
from vibration.physics.twin import validation

OSC = Oscillator(m=1.0, c=0.5, k=20.0)


def _band(n_lo: float, alpha: float, runs: int) -> float:
    """Acceptance band for a rejection share: three binomial standard deviations."""
    return 3.0 * math.sqrt(alpha * (1 - alpha) / runs)


@pytest.mark.parametrize("successes, runs", [(0, 40), (7, 40), (190, 200), (200, 200), (13, 31)])
def test_wilson_halfwidth_matches_scipy(successes, runs):
    ci = binomtest(successes, runs).proportion_ci(method="wilson")
    assert float(twin.binomial_halfwidth(successes, runs)) == pytest.approx((ci.high - ci.low) / 2, rel=1e-9)


def test_ljung_box_has_its_level_on_white_noise_and_power_on_ar1():
    rng = np.random.default_rng(3)
    runs = 400
    p = np.array([twin.ljung_box(rng.standard_normal(3000))[1] for _ in range(runs)])
    assert abs(np.mean(p < 0.05) - 0.05) < _band(0, 0.05, runs)
    # its p-values are uniform under the null: the share below 0.5 too
    assert abs(np.mean(p < 0.5) - 0.5) < _band(0, 0.5, runs)
    ar = signal.lfilter([1.0], [1.0, -0.2], rng.standard_normal(3000))
    assert twin.ljung_box(ar)[1] < 1e-6


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_input_correlation_has_its_level_with_the_band_limited_force():
    """White residual, independent of the chapter's (nearly singular) band-limited force: rejections at alpha."""
    t = np.arange(3001) * 0.02
    force = twin.random_force(t, seed=1)
    rng = np.random.default_rng(4)
    runs = 300
    out = [twin.input_correlation(rng.standard_normal(t.size), force) for _ in range(runs)]
    p = np.array([o[1] for o in out])
    assert 1 <= out[0][2] <= twin.WHITENESS_LAGS
    assert abs(np.mean(p < 0.05) - 0.05) < _band(0, 0.05, runs)
    leaked = rng.standard_normal(t.size) + 0.1 * np.roll(force, 3)
    assert twin.input_correlation(leaked, force)[1] < 1e-6


def test_residual_tests_refuse_bad_input():
    with pytest.raises(ParameterError, match="lags"):
        twin.ljung_box(np.ones(100) + np.arange(100), lags=0)
    with pytest.raises(ParameterError, match="residual"):
        twin.ljung_box(np.ones(100))
    with pytest.raises(ParameterError, match="force"):
        twin.input_correlation(np.arange(100.0), np.ones(100))


def test_cubic_response_matches_solve_ivp():
    t = np.arange(0.0, 20.0, 0.02)
    force = twin.random_force(t, seed=2)
    k3 = 40.0
    x = twin.cubic_response(OSC, k3, t, force=force)

    def rhs(tt, z):
        f = np.interp(tt, t, force)
        return [z[1], (f - OSC.c * z[1] - OSC.k * z[0] - k3 * z[0] ** 3) / OSC.m]

    # integrate interval by interval so the solver never straddles a kink of the force
    z = np.zeros(2)
    ref = [0.0]
    for i in range(t.size - 1):
        sol = solve_ivp(rhs, (t[i], t[i + 1]), z, method="DOP853", rtol=1e-12, atol=1e-14)
        z = sol.y[:, -1]
        ref.append(z[0])
    ref = np.array(ref)
    assert np.max(np.abs(x - ref)) < 1e-7 * np.max(np.abs(ref))
    # and the cubic term matters at this size: the linear response is far from it
    lin = twin.sampled_response(OSC, t, force).x
    assert np.max(np.abs(lin - ref)) > 1e-2 * np.max(np.abs(ref))


def test_predicted_coverage_is_the_dense_sandwich():
    t = np.arange(0.0, 8.0, 0.02)
    force = twin.random_force(t, seed=5)
    colour = 0.8
    jac = validation._response_jacobian(OSC, t, force)
    sigma = colour ** np.abs(np.subtract.outer(np.arange(t.size), np.arange(t.size)))
    inv = np.linalg.inv(jac.T @ jac)
    true = np.diag(inv @ jac.T @ sigma @ jac @ inv)[:3]
    q = student_t.ppf(0.975, t.size - 5)
    expected = 2 * norm.cdf(q * np.sqrt(np.diag(inv)[:3] / true)) - 1
    np.testing.assert_allclose(twin.predicted_coverage(OSC, t, force, colour=colour), expected, rtol=1e-8)
    np.testing.assert_allclose(twin.predicted_coverage(OSC, t, force, colour=0.0), 2 * norm.cdf(q) - 1, rtol=1e-10)


def test_response_jacobian_matches_identify_covariance():
    """sigma^2 (J^T J)^-1 at the truth is identify's reported covariance to first order (a different code path)."""
    t = np.arange(0.0, 60.0, 0.02)
    force = twin.random_force(t, seed=6)
    meas = twin.synthetic_measurements(OSC, t, force, noise=1e-4, seed=7)
    fit = twin.identify(**meas)
    jac = validation._response_jacobian(OSC, t, force)
    cov = fit.sigma**2 * np.linalg.inv(jac.T @ jac)[:3, :3]
    np.testing.assert_allclose(np.sqrt(np.diag(cov)), fit.stderr, rtol=0.02)


@pytest.fixture(scope="module")
def study():
    ref = twin.identification_experiment(OSC, duration=40.0, runs=40, seed=8)
    return twin.assumption_study(OSC, ref, runs=24, seed=8)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_assumption_study_reveals_each_broken_assumption(study):
    assert list(study.experiments) == ["as assumed", *twin.ASSUMPTION_CASES]
    ref = study.experiments["as assumed"]
    assert np.all(ref.coverage >= 0.8)
    for label, ex in study.experiments.items():
        if label == "as assumed":
            continue
        # the test that does not know the truth flags most runs ...
        assert ex.flagged("whiteness") >= 0.8, label
        # ... and the intervals have lost their 95 %
        assert np.min(ex.coverage) < 0.8, label
    assert study.experiments["unmodelled cubic spring"].coverage[2] <= 0.1
    # equivalent linearisation: the fitted k/m rises by about 3 k3 E[x^2] / k for a Gaussian response
    cub = study.experiments["unmodelled cubic spring"]
    wn2 = np.mean(cub.estimates[:, 2] / cub.estimates[:, 0]) / (OSC.k / OSC.m)
    assert 1 + 1.5 * study.cubic < wn2 < 1 + 4.5 * study.cubic


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_assumption_cases_draw_independent_noise(study):
    e = [ex.estimates[:, 2] - ex.truth[2] for ex in study.experiments.values()]
    assert abs(np.corrcoef(e[0][:24], e[4])[0, 1]) < 0.9


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_sweep_points_draw_independent_noise():
    by_noise, _ = twin.identification_sweep(OSC, noises=(0.02, 0.04), durations=(20.0,), runs=12, duration=20.0)
    a = (by_noise[0].estimates[:, 2] - OSC.k) / by_noise[0].noise
    b = (by_noise[1].estimates[:, 2] - OSC.k) / by_noise[1].noise
    # rescaling one draw would make these equal to first order (correlation ~1); independent draws do not
    assert abs(np.corrcoef(a, b)[0, 1]) < 0.9


def test_assumption_study_bad_input():
    ref = twin.identification_experiment(OSC, duration=20.0, runs=3)
    for kwargs, name in (({"colour": 1.0}, "colour"), ({"cubic": 0.0}, "cubic"), ({"force_noise": -1}, "force_noise")):
        with pytest.raises(ParameterError, match=name):
            twin.assumption_study(OSC, ref, runs=2, **kwargs)
    with pytest.raises(ParameterError, match="reference"):
        twin.assumption_study(OSC, "not an experiment", runs=2)


@pytest.mark.slow
def test_coloured_noise_coverage_matches_the_sandwich_prediction():
    ref = twin.identification_experiment(OSC, duration=40.0, runs=10, seed=9)
    st = twin.assumption_study(OSC, ref, runs=150, seed=9, colour=0.9)
    ex, pred = st.experiments["coloured sensor noise"], st.predicted["coloured sensor noise"]
    # binomial 3 sigma, plus 0.05 for the first-order approximation (s^2 and the delta method)
    tol = 3 * np.sqrt(pred * (1 - pred) / ex.runs) + 0.05
    assert np.all(np.abs(ex.coverage - pred) < tol), (ex.coverage, pred)


# ----------------------------------------------------------------------------- CUSUM tuning and false alarms


@pytest.mark.parametrize("drift", [0.386, 1.0, 3.0])
def test_cusum_ratio_is_the_gaussian_likelihood_ratio(drift):
    """The increment u - 1 - drift is proportional to the one-sample log-likelihood ratio of variance rho."""
    rho = twin.cusum_variance_ratio(drift)
    u = np.linspace(0.0, 20.0, 41)
    llr = 0.5 * (-np.log(rho) + (1 - 1 / rho) * u)  # log N(0, rho) / N(0, 1) at r^2 = u
    np.testing.assert_allclose(llr, 0.5 * (1 - 1 / rho) * (u - 1 - drift), rtol=1e-10, atol=1e-12)


def test_cusum_nu_one_is_not_a_doubling():
    assert twin.cusum_variance_ratio(1.0) == pytest.approx(4.9215536, rel=1e-6)
    assert twin.cusum_variance_ratio(2 * math.log(2) - 1) == pytest.approx(2.0, rel=1e-10)


def test_false_alarm_upper_bound_is_the_exact_poisson_bound():
    from scipy.stats import poisson

    t = np.arange(0.0, 120.0, 0.02)
    force = twin.random_force(t, seed=3)
    ks = twin.stiffness_profile(t, 20.0, 1e9, decline_rate=0.0, drop_time=60.0, drop=0.1)
    ex = twin.detection_experiment(
        OSC, t, force, stiffness=ks, change_time=60.0, noise=2e-3, runs=4, reference=OSC, thresholds=[1.0, 40]
    )
    hours = ex.monitored_hours
    alarms = np.round(ex.false_alarm_rate * hours).astype(int)
    for k, upper in zip(alarms, ex.false_alarm_rate_upper, strict=True):
        # the bound is the rate at which k or fewer alarms have probability 5 %
        assert poisson.cdf(k, upper * hours) == pytest.approx(0.05, rel=1e-8)
    assert ex.healthy_max >= 0.0
