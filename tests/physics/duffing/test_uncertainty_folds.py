"""Chapter 9, issue 21: the Lyapunov exponent's uncertainty and the true folds of the periodic orbit.

The batch-means standard error is checked against the scatter of independent runs (other initial
states), the per-period increments against a separate shorter run, and a periodic orbit's exponent
against its Floquet multipliers. The folds found by continuing the shooting orbit are checked against
time integration (the refined jumps of stepped sweeps, a different integrator and method), against
shooting on either side of each fold, and against the limit of weak nonlinearity, where one harmonic
becomes exact.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibration import ParameterError
from vibration.physics.duffing import (
    Duffing,
    LyapunovEstimate,
    continue_orbits,
    folds,
    frequency_sweep,
    locate_jump,
    lyapunov_estimate,
    lyapunov_qr,
    periodic_orbit,
    pooled_exponent,
)

UEDA = Duffing(m=1.0, c=0.05, k=0.0, k3=1.0)  # x'' + 0.05 x' + x^3 = F cos t
HARD = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
SOFT = Duffing(m=1.0, c=0.5, k=20.0, k3=-1.0)
STARTS = [(3.0, 0.0), (0.0, 0.0), (1.0, 1.0), (-2.0, 3.0), (2.0, -1.0), (-1.0, -2.0), (0.5, 2.5), (-3.0, 0.5),
          (1.5, -3.0), (-0.5, 1.0), (2.5, 2.0), (-2.5, -1.5)]  # fmt: skip


# ------------------------------------------------------------------------------------ uncertainty


@pytest.fixture(scope="module")
def short_runs():
    """Twelve independent runs of 2000 periods on Ueda's attractor (20 blocks of 100 periods each)."""
    return [lyapunov_estimate(UEDA, 7.5, 1.0, x0=x, v0=v, n_periods=2000, n_blocks=20) for x, v in STARTS]


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_batch_means_error_matches_the_scatter_of_independent_runs(short_runs):
    lam = np.array([e.exponent for e in short_runs])
    se = np.array([e.standard_error for e in short_runs])
    ratio = lam.std(ddof=1) / np.sqrt(np.mean(se**2))
    # s^2 / sigma^2 ~ chi2(11)/11: its 0.1 % and 99.9 % quantiles are 0.29 and 2.87 (ratio 0.54 to 1.69)
    assert 0.5 < ratio < 1.75, ratio
    assert np.all(se > 0) and np.all(se < 0.02)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_pooled_runs_are_consistent_and_positive(short_runs):
    mean, se, chi2, dof = pooled_exponent(short_runs)
    assert dof == len(STARTS) - 1
    assert chi2 < dof + 4 * math.sqrt(2 * dof)  # 4 sigma of a chi-square with dof degrees of freedom
    assert mean - 5 * se > 0.09 and abs(mean - 0.1034) < 5 * se + 0.002


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_pooled_exponent_is_the_inverse_variance_mean(short_runs):
    a, b = short_runs[:2]
    w = np.array([1 / a.standard_error**2, 1 / b.standard_error**2])
    m = (w[0] * a.exponent + w[1] * b.exponent) / w.sum()
    mean, se, chi2, dof = pooled_exponent([a, b])
    assert mean == pytest.approx(m, rel=1e-14) and se == pytest.approx(1 / math.sqrt(w.sum()), rel=1e-14)
    assert chi2 == pytest.approx(w[0] * (a.exponent - m) ** 2 + w[1] * (b.exponent - m) ** 2, rel=1e-12)
    assert dof == 1
    with pytest.raises(ParameterError, match="estimates"):
        pooled_exponent([a])


def test_increments_reproduce_a_separate_shorter_run():
    e = lyapunov_estimate(UEDA, 7.5, 1.0, x0=3.0, v0=0.0, n_periods=3000, n_blocks=10)
    assert e.increments.sum() / (e.n_periods * e.period) == pytest.approx(e.exponent, rel=1e-12)
    short = lyapunov_qr(UEDA, 7.5, 1.0, x0=3.0, v0=0.0, n_periods=1000, n_transient=300)
    assert e.at(1000, 10)[0] == pytest.approx(short.exponents[0], rel=1e-10)
    assert e.block_means.size == 10 and e.block_periods == 300
    assert e.second == pytest.approx(-0.05 - e.exponent, abs=1e-6)  # the trace, by construction


def test_periodic_orbit_exponent_is_the_floquet_exponent_with_a_small_error():
    orbit = periodic_orbit(HARD, 5.0, 4.47)
    T = 2 * math.pi / 4.47
    floquet = math.log(max(abs(mu) for mu in orbit.multipliers)) / T
    for method in ("qr", "benettin"):
        e = lyapunov_estimate(HARD, 5.0, 4.47, x0=orbit.x0, v0=orbit.v0, n_periods=2000, n_transient=0, method=method)
        assert e.exponent == pytest.approx(floquet, abs=2e-3)
        assert e.standard_error < 0.01


def test_estimate_refuses_bad_arguments():
    with pytest.raises(ParameterError, match="method"):
        lyapunov_estimate(UEDA, 7.5, 1.0, n_periods=1000, method="svd")
    with pytest.raises(ParameterError, match="n_periods"):
        lyapunov_estimate(UEDA, 7.5, 1.0, n_periods=50, n_blocks=20)
    with pytest.raises(ParameterError, match="n_blocks"):
        lyapunov_estimate(UEDA, 7.5, 1.0, n_periods=1000, n_blocks=2)
    e = lyapunov_estimate(UEDA, 7.5, 1.0, n_periods=400, n_blocks=20)
    assert isinstance(e, LyapunovEstimate)
    with pytest.raises(ParameterError, match="n_periods"):
        e.at(401)


@pytest.mark.slow
def test_long_runs_give_the_long_run_exponent():
    """Four runs of 25,000 periods: the pooled exponent within a few standard errors of 0.1034 1/s
    (the value of 4 x 100,000 periods at 100 to 800 steps per period, standard error 0.0002)."""
    runs = [lyapunov_estimate(UEDA, 7.5, 1.0, x0=x, v0=v, n_periods=25_000) for x, v in STARTS[:4]]
    mean, se, chi2, dof = pooled_exponent(runs)
    assert abs(mean - 0.1034) < 4 * math.hypot(se, 0.0002)
    assert 0.0003 < se < 0.0008


# ------------------------------------------------------------------------------------------ folds


@pytest.fixture(scope="module")
def branches():
    out = {}
    for name, d in (("hard", HARD), ("soft", SOFT)):
        f = folds(d, 5.0)
        width = f.omega_high - f.omega_low
        out[name] = (d, f, continue_orbits(d, 5.0, f.omega_low - 0.5 * width, omega_end=f.omega_high + 0.5 * width))
    return out


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_branch_turns_twice_where_a_multiplier_is_one(branches):
    for _, _, b in branches.values():
        assert len(b.folds) == 2
        for fold in b.folds:
            assert abs(fold.multiplier - 1.0) < 1e-8 and abs(fold.det) < 1e-8
        # stable, unstable, stable along the branch, switching at the folds
        st = b.stable.astype(int)
        assert list(st[np.r_[True, np.diff(st) != 0]]) == [1, 0, 1]
        assert b.omega.min() < min(x.omega for x in b.folds) and b.omega.max() > max(x.omega for x in b.folds)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_branch_points_are_periodic_orbits(branches):
    d, _, b = branches["hard"]
    for i in (3, len(b.omega) // 2, len(b.omega) - 3):
        orb = periodic_orbit(d, 5.0, float(b.omega[i]), x0=float(b.x0[i]), v0=float(b.v0[i]))
        assert orb.x0 == pytest.approx(b.x0[i], abs=1e-7) and orb.v0 == pytest.approx(b.v0[i], abs=1e-6)
        assert orb.amplitude == pytest.approx(b.amplitude[i], rel=1e-7)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_sweep_jumps_bracket_the_continued_folds(branches):
    """Time integration (compiled Dormand-Prince, a different integrator and no shooting) jumps at the folds."""
    for d, _, b in branches.values():
        lo, hi = sorted(x.omega for x in b.folds)
        w = np.linspace(lo - 0.05, hi + 0.05, 41)
        up, down = frequency_sweep(d, 5.0, w, direction="up"), frequency_sweep(d, 5.0, w, direction="down")
        j_up, j_down = locate_jump(d, 5.0, up), locate_jump(d, 5.0, down)
        assert min(j_up) - 1e-6 <= hi <= max(j_up) + 1e-6, (j_up, hi)
        assert min(j_down) - 1e-6 <= lo <= max(j_down) + 1e-6, (j_down, lo)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_no_orbit_near_the_fold_beyond_it(branches):
    """Just inside the band shooting from the fold's state finds orbits near it; just beyond, it leaves."""
    d, _, b = branches["hard"]
    upper = max(b.folds, key=lambda x: x.omega)
    i = int(np.argmin(np.abs(b.amplitude - upper.amplitude)))
    x0, v0 = float(b.x0[i]), float(b.v0[i])
    inside = periodic_orbit(d, 5.0, upper.omega - 2e-3, x0=x0, v0=v0)
    assert abs(inside.amplitude - upper.amplitude) < 0.15
    try:  # only the lower branch is left: Newton fails, or it finds that far-away orbit
        beyond = periodic_orbit(d, 5.0, upper.omega + 2e-3, x0=x0, v0=v0)
    except ParameterError as exc:
        assert "did not converge" in str(exc)
    else:
        assert beyond.amplitude < 0.8 * upper.amplitude


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_one_harmonic_folds_converge_to_the_true_ones_as_the_amplitude_falls(branches):
    """The one-harmonic error is of second order in the nonlinearity k3 A^2 / k: with c = 0.1 N s/m and
    F0 = 0.5 N the peak amplitude is 1.07 m instead of 1.97 m, and the fold error falls by more than 3."""
    _, f5, b5 = branches["hard"]
    err5 = abs(f5.omega_high - max(x.omega for x in b5.folds))
    d = Duffing(m=1.0, c=0.1, k=20.0, k3=2.0)
    f = folds(d, 0.5)
    assert f.bistable and f.peak_amplitude < 0.6 * f5.peak_amplitude
    width = f.omega_high - f.omega_low
    b = continue_orbits(d, 0.5, f.omega_low - 0.5 * width, omega_end=f.omega_high + 0.5 * width)
    err = abs(f.omega_high - max(x.omega for x in b.folds))
    assert err < err5 / 3, (err, err5)


def test_continuation_refuses_bad_arguments():
    with pytest.raises(ParameterError, match="omega_end"):
        continue_orbits(HARD, 5.0, 5.0, omega_end=5.0)
    with pytest.raises(ParameterError, match="c = 0"):
        continue_orbits(Duffing(m=1.0, c=0.0, k=20.0, k3=2.0), 5.0, 4.9, omega_end=5.2)
    with pytest.raises(ParameterError, match="step"):
        continue_orbits(HARD, 5.0, 4.9, omega_end=5.2, step=2.0)
    with pytest.raises(ParameterError, match="F0"):
        continue_orbits(HARD, -1.0, 4.9, omega_end=5.2)
