"""The digital twin: exact FOH discretisation, measurement files, identification, tracking, detection.

Every number is checked against an independent method: the closed form ``exact_response``,
``solve_ivp`` at tight tolerance, ``scipy.signal.cont2discrete(method="foh")`` + ``dlsim``,
``scipy.linalg.expm``, ``scipy.optimize.curve_fit`` on the full model, or a plain state recursion.
Data fed to :func:`identify` in the "independent" tests is made with ``solve_ivp`` from a force
written as a continuous function, not with the package's own simulator.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg
from scipy import signal
from scipy.integrate import solve_ivp
from scipy.optimize import curve_fit

import vibration
from vibration import Oscillator, ParameterError, SineForce, exact_response
from vibration.physics import twin
from vibration.physics.twin import (
    detect_change,
    detection_experiment,
    discretize,
    example_measurements,
    expm_batch,
    frequency_estimates,
    frf_estimate,
    identification_experiment,
    identify,
    load_measurements,
    measurements_csv,
    random_force,
    sampled_response,
    stiffness_profile,
    synthetic_measurements,
    track_stiffness,
)

DATA = Path(__file__).resolve().parents[3] / "data"

REGIMES = {
    "paper c=0.5": (1.0, 0.5, 20.0),
    "light": (0.3, 0.02, 50.0),
    "critical": (2.0, 2 * math.sqrt(2.0 * 8.0), 8.0),
    "overdamped": (1.0, 15.0, 20.0),
    "heavy mass": (80.0, 40.0, 3000.0),
}


def test_public_api_at_top_level():
    for name in ("load_measurements", "identify", "detect_change"):
        assert getattr(vibration, name) is getattr(twin, name)
    for name in ("track_stiffness", "sampled_response"):  # in the chapter's namespace
        assert getattr(vibration.twin, name) is getattr(twin, name)


# ----------------------------------------------------------------------------- matrix exponential, FOH


@pytest.mark.parametrize("scale", [1e-4, 1.0, 5.0])
def test_expm_batch_matches_scipy(scale):
    rng = np.random.default_rng(1)
    a = rng.standard_normal((8, 4, 4)) * scale
    ours = expm_batch(a)
    ref = np.array([scipy.linalg.expm(x) for x in a])
    np.testing.assert_allclose(ours, ref, rtol=1e-12, atol=1e-13 * np.abs(ref).max())


@pytest.mark.parametrize("params", REGIMES.values(), ids=REGIMES.keys())
def test_foh_matches_scipy_cont2discrete(params):
    """scipy's own FOH discretisation (a different state realisation) gives the same sampled output."""
    m, c, k = params
    osc = Oscillator(m=m, c=c, k=k)
    h = 0.3 / osc.natural_frequency
    t = np.arange(400) * h
    f = random_force(t, band=(0.01, 0.2 / h), seed=2)
    ours = sampled_response(osc, t, f)
    a = np.array([[0.0, 1.0], [-k / m, -c / m]])
    b = np.array([[0.0], [1.0 / m]])
    ad, bd, cd, dd, _ = signal.cont2discrete((a, b, np.eye(2), np.zeros((2, 1))), h, method="foh")
    # scipy's FOH state is z - D F, so z(0) = 0 is its state -D F[0]
    _, yd, _ = signal.dlsim((ad, bd, cd, dd, h), f, x0=-dd[:, 0] * f[0])
    scale = np.abs(yd).max(axis=0)
    np.testing.assert_allclose(ours.x, yd[:, 0], rtol=0, atol=1e-11 * scale[0])
    np.testing.assert_allclose(ours.v, yd[:, 1], rtol=0, atol=1e-11 * scale[1])


@pytest.mark.parametrize("params", REGIMES.values(), ids=REGIMES.keys())
def test_sampled_response_is_exact_for_piecewise_linear_force(params):
    """Against solve_ivp (DOP853, rtol 1e-12) integrated sample by sample with the linear force."""
    m, c, k = params
    osc = Oscillator(m=m, c=c, k=k)
    h = 0.4 / osc.natural_frequency
    t = np.arange(120) * h
    f = np.random.default_rng(3).standard_normal(t.size)
    x0, v0 = 0.2, -0.1
    ours = sampled_response(osc, t, f, x0=x0, v0=v0)
    z = np.array([x0, v0])
    ref = [z]
    for i in range(t.size - 1):
        slope = (f[i + 1] - f[i]) / h

        def rhs(s, y, i=i, slope=slope):
            return [y[1], (f[i] + slope * s - c * y[1] - k * y[0]) / m]

        sol = solve_ivp(rhs, (0.0, h), z, method="DOP853", rtol=1e-13, atol=1e-15)
        z = sol.y[:, -1]
        ref.append(z)
    ref = np.array(ref)
    np.testing.assert_allclose(ours.x, ref[:, 0], rtol=0, atol=1e-10 * np.abs(ref[:, 0]).max())
    np.testing.assert_allclose(ours.v, ref[:, 1], rtol=0, atol=1e-10 * np.abs(ref[:, 1]).max())
    np.testing.assert_allclose(ours.a, (f - c * ours.v - k * ours.x) / m)


@pytest.mark.parametrize("params", [(1.0, 0.5, 20.0), (1.0, 0.1, 20.0), (1.0, 15.0, 20.0)])
def test_sampled_response_converges_to_exact_response_for_a_sine(params):
    """The only error for a sine is the linear interpolation of the force: second order in h."""
    osc, force = Oscillator(**dict(zip(("m", "c", "k"), params, strict=True))), SineForce(F0=5.0, omega=4.47)
    errs = []
    for n in (2001, 4001, 8001):
        t = np.linspace(0.0, 50.0, n)
        ours = sampled_response(osc, t, force(t))
        errs.append(np.max(np.abs(ours.x - exact_response(osc, force, t).x)))
    h = 50.0 / 8000
    # |F - FOH(F)| <= h^2 omega^2 F0 / 8, response error <= that times the integral of |impulse response|
    bound = h**2 * 4.47**2 * 5.0 / 8.0 * (2.0 / (osc.c * osc.damped_natural_frequency) if osc.c < 2 else 1.0)
    assert errs[-1] < bound
    assert 3.6 < errs[0] / errs[1] < 4.4 and 3.6 < errs[1] / errs[2] < 4.4, errs


def test_lfilter_recursion_agrees_with_the_state_loop_on_a_long_fast_record():
    osc = Oscillator(m=1.0, c=0.05, k=4.0)
    h = 1e-3
    t = np.arange(60000) * h
    f = random_force(t, band=(0.05, 3.0), seed=4)
    d = discretize(osc, h)
    z = np.zeros(2)
    xs = np.empty(t.size)
    for i in range(t.size):
        xs[i] = z[0]
        if i + 1 < t.size:
            z = d.phi @ z + d.gamma0 * f[i] + d.gamma1 * f[i + 1]
    ours = sampled_response(osc, t, f)
    np.testing.assert_allclose(ours.x, xs, rtol=0, atol=1e-9 * np.abs(xs).max())


def test_synthetic_stiffness_history_matches_piecewise_solve():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    t = np.arange(0.0, 20.0, 0.02)
    f = random_force(t, seed=5)
    ks = stiffness_profile(t, 20.0, 1e9, decline_rate=0.0, drop_time=10.0, drop=0.3)
    ours = synthetic_measurements(osc, t, f, stiffness=ks)
    before = sampled_response(osc, t[t < 10.0 + 1e-9], f[t < 10.0 + 1e-9])
    i = int(np.searchsorted(t, 10.0 - 1e-9))
    after = sampled_response(Oscillator(m=1.0, c=0.5, k=14.0), t[i:], f[i:], x0=before.x[i], v0=before.v[i])
    np.testing.assert_allclose(ours.x[: i + 1], before.x[: i + 1], rtol=0, atol=1e-13)
    np.testing.assert_allclose(ours.x[i:], after.x, rtol=0, atol=1e-10)


# ----------------------------------------------------------------------------- measurement files


def test_committed_example_is_the_package_output():
    text = (DATA / "twin_example.csv").read_text(encoding="utf-8")
    assert text == measurements_csv(example_measurements())


def test_example_round_trip():
    meas = load_measurements(DATA / "twin_example.csv")
    ref = example_measurements()
    np.testing.assert_array_equal(meas.t, ref.t)
    np.testing.assert_array_equal(meas.x, ref.x)
    assert meas.a is None and meas.sensor == "x" and meas.dt == pytest.approx(0.02)


def _write(tmp_path, text, name="m.csv"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def _good_rows(n=40, h=0.01, col="x_m"):
    lines = [f"t_s,force_N,{col}"]
    lines += [f"{i * h:.6f},{math.sin(i * 0.3):.6f},{0.01 * math.cos(i * 0.2):.6f}" for i in range(n)]
    return lines


def test_acceleration_file_and_column_order(tmp_path):
    lines = ["a_m_s2, t_s ,force_N"] + [f"{0.1 * i},{i * 0.5},{i % 3}" for i in range(40)]
    meas = load_measurements(_write(tmp_path, "\n".join(lines) + "\n\n"))
    assert meas.sensor == "a" and meas.x is None and meas.dt == 0.5
    assert meas.a[3] == pytest.approx(0.3) and meas.force[4] == 1.0


def _bad(lines, row, value):
    lines = list(lines)
    parts = lines[row].split(",")
    parts[2] = value
    lines[row] = ",".join(parts)
    return lines


@pytest.mark.parametrize(
    ("mutate", "fragments"),
    [
        (lambda L: _bad(L, 7, "nan"), ["x_m", "row 7", "line 8", "nan"]),
        (lambda L: _bad(L, 7, "inf"), ["x_m", "row 7", "inf"]),
        (lambda L: _bad(L, 9, ""), ["x_m", "row 9", "empty"]),
        (lambda L: _bad(L, 9, "1,2e"), ["row 9", "cells"]),
        (lambda L: _bad(L, 12, "abc"), ["x_m", "row 12", "'abc'"]),
        (lambda L: _bad(L, 12, "1e20"), ["x_m", "row 12", "absurdly large"]),
        (lambda L: L[:5] + [L[5].rsplit(",", 1)[0]] + L[6:], ["x_m", "row 5", "2 cells"]),
        (lambda L: L[:5] + [L[6]] + L[6:], ["t_s", "row 6", "does not increase"]),
        (lambda L: L[:5] + [L[6], L[5]] + L[7:], ["t_s", "row 6", "does not increase"]),
        (lambda L: L[:10] + L[12:], ["t_s", "row 10", "gap"]),
        (lambda L: [L[0]] + [r.replace("0.140000,", "0.143000,") for r in L[1:]], ["t_s", "row 15", "non-uniform"]),
        (lambda L: ["t_s,force_N"] + [r.rsplit(",", 1)[0] for r in L[1:]], ["x_m", "missing"]),
        (lambda L: ["t_s,x_m"] + [r.split(",", 1)[1] for r in L[1:]], ["force_N", "missing"]),
        (lambda L: ["t_s,force_N,y_m"] + L[1:], ["y_m", "unknown", "header"]),
        (lambda L: ["t_s,t_s,x_m"] + L[1:], ["t_s", "twice"]),
        (lambda L: ["t_s,force_N,x_m,a_m_s2"] + [r + ",0" for r in L[1:]], ["x_m", "a_m_s2", "both"]),
        (lambda L: L[:10], ["9 data rows"]),
        (lambda L: [], ["empty"]),
        (lambda L: [""], ["empty"]),
    ],
    ids=[
        "nan", "inf", "empty-cell", "extra-cell", "text", "absurd-value", "missing-cell", "repeated-time",
        "decreasing-time", "gap", "jitter", "no-response", "no-force", "unknown", "duplicate", "both-sensors",
        "too-few", "empty-file", "blank-file",
    ],
)  # fmt: skip
def test_malformed_files_are_refused_with_column_and_row(tmp_path, mutate, fragments):
    path = _write(tmp_path, "\n".join(mutate(_good_rows())) + "\n")
    with pytest.raises(ParameterError) as info:
        load_measurements(path)
    msg = str(info.value)
    assert "allowed" in msg
    for frag in fragments:
        assert frag in msg, (frag, msg)


def test_rate_change_is_named_where_it_happens(tmp_path):
    lines = ["t_s,force_N,x_m"] + [f"{(i * 0.01 if i < 30 else 0.3 + (i - 30) * 0.0105):.6f},1,{i}" for i in range(60)]
    with pytest.raises(ParameterError, match=r"t_s, row (2[6-9]|3[0-4])\b.*non-uniform"):
        load_measurements(_write(tmp_path, "\n".join(lines)))


def test_absurd_file_size_and_missing_file(tmp_path, monkeypatch):
    path = _write(tmp_path, "\n".join(_good_rows()))
    monkeypatch.setattr(twin.measurements, "MAX_BYTES", 100)
    with pytest.raises(ParameterError, match="bytes: allowed at most 100"):
        load_measurements(path)
    with pytest.raises(ParameterError, match="cannot be read"):
        load_measurements(tmp_path / "absent.csv")
    monkeypatch.setattr(twin.measurements, "N_POINTS_MAX", 30)
    monkeypatch.setattr(twin.measurements, "MAX_BYTES", 10**9)
    with pytest.raises(ParameterError, match="40 data rows: allowed 32 to 30"):
        load_measurements(path)


def test_bom_comments_and_crlf_are_accepted(tmp_path):
    text = "\ufeff# synthetic\r\n" + "\r\n".join(_good_rows()) + "\r\n"
    p = tmp_path / "bom.csv"
    p.write_bytes(text.encode("utf-8"))
    assert len(load_measurements(p)) == 40


# ----------------------------------------------------------------------------- identification


def _ivp_record(m, c, k, fs, duration, sensor, noise, seed, band=(0.05, 0.4)):
    """A record made without the package: multisine force as a continuous function, solve_ivp, noise."""
    wn = math.sqrt(k / m)
    rng = np.random.default_rng(seed)
    freqs = np.linspace(band[0], band[1], 40) * wn * 2.5 / (2 * math.pi)
    ph = rng.uniform(0, 2 * np.pi, freqs.size)

    def force(t):
        return np.cos(2 * np.pi * np.multiply.outer(t, freqs) + ph).sum(axis=-1) * 0.3

    t = np.arange(int(duration * fs) + 1) / fs
    sol = solve_ivp(
        lambda s, y: [y[1], (force(s) - c * y[1] - k * y[0]) / m],
        (0.0, t[-1]),
        [0.0, 0.0],
        t_eval=t,
        method="DOP853",
        rtol=1e-11,
        atol=1e-14,
    )
    x, v = sol.y
    y = x if sensor == "x" else (force(t) - c * v - k * x) / m
    y = y + noise * np.std(y) * rng.standard_normal(t.size)
    return t, force(t), y


CASES = [  # m kg, zeta, k N/m, samples per natural period, periods in the record, sensor
    (1.0, 0.0559, 20.0, 25, 60, "x"),
    (0.1, 0.005, 400.0, 40, 200, "a"),
    (100.0, 0.3, 1e5, 12, 40, "x"),
    (5.0, 0.5, 80.0, 20, 30, "a"),
    (0.5, 0.02, 2.0, 30, 80, "x"),
]


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
@pytest.mark.parametrize("case", CASES, ids=[f"m{c[0]}-z{c[1]}-{c[5]}" for c in CASES])
def test_identify_recovers_independent_data(case):
    m, zeta, k, per_period, periods, sensor = case
    c = 2 * zeta * math.sqrt(k * m)
    wn = math.sqrt(k / m)
    fs = per_period * wn / (2 * math.pi)
    duration = periods * 2 * math.pi / wn
    t, f, y = _ivp_record(m, c, k, fs, duration, sensor, noise=0.02, seed=7)
    fit = identify(t, f, **{sensor: y})
    truth = np.array([m, c, k])
    est = np.array([fit.m, fit.c, fit.k])
    # within 4.5 standard errors, plus the FOH interpolation bias of a smooth force (estimated per record)
    slack = 4.5 * fit.stderr + 20 * fit.force_hold_error * np.abs(truth)
    assert np.all(np.abs(est - truth) <= slack), (est, truth, fit.stderr, fit.force_hold_error)
    assert fit.stderr.shape == (3,) and fit.ci95.shape == (3, 2)
    assert np.all(fit.ci95[:, 0] < est) and np.all(est < fit.ci95[:, 1])


def test_identify_equals_curve_fit_on_the_full_model():
    """Same optimum and covariance as scipy's curve_fit on (m, c, k, x0, v0), a different code path."""
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    t = np.arange(0.0, 40.0, 0.02)
    f = random_force(t, seed=8)
    meas = synthetic_measurements(osc, t, f, noise=0.01, seed=9, x0=0.05, v0=0.1)
    fit = identify(**meas)

    def model(_, m, c, k, x0, v0):
        return sampled_response(Oscillator(m=m, c=c, k=k), t, f, x0=x0, v0=v0).x

    p, pcov = curve_fit(model, t, meas.x, p0=[1.1, 0.4, 21.0, 0.0, 0.0], xtol=1e-13, ftol=1e-13)
    np.testing.assert_allclose([fit.m, fit.c, fit.k, fit.x0, fit.v0], p, rtol=1e-6, atol=1e-8)
    np.testing.assert_allclose(fit.cov, pcov[:3, :3], rtol=1e-3)
    assert fit.sigma == pytest.approx(np.sqrt(np.sum(fit.residual**2) / (t.size - 5)))


def test_identify_global_and_local_search_agree():
    t = np.arange(0.0, 60.0, 0.02)
    meas = synthetic_measurements(Oscillator(m=2.0, c=0.3, k=30.0), t, random_force(t, seed=10), sensor="a", noise=0.1)
    g, loc = identify(**meas), identify(**meas, search="local")
    np.testing.assert_allclose([g.m, g.c, g.k], [loc.m, loc.c, loc.k], rtol=1e-7)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_monte_carlo_coverage_is_near_95_percent():
    ex = identification_experiment(Oscillator(m=1.0, c=0.5, k=20.0), duration=30.0, runs=120, noise=0.05, seed=3)
    # binomial: P(coverage < 0.87 | 0.95, 120 runs) < 1e-3
    assert np.all(ex.coverage >= 0.87), ex.coverage
    # the reported standard errors match the scatter of the estimates (sampling error of 120 runs ~ 7 %)
    np.testing.assert_allclose(ex.rel_rmse / ex.rel_stderr, 1.0, atol=0.25)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"x": None, "a": None}, "x and a"),
        ({"a": "same"}, "x and a"),
        ({"force": "const"}, "force"),
        ({"x": "short"}, "x"),
        ({"x": "nan"}, "x[3]"),
        ({"t": "jitter"}, "t[5]"),
        ({"t": "2d"}, "t"),
        ({"search": "everywhere"}, "search"),
    ],
)
def test_identify_bad_input(kwargs, name):
    t = np.arange(0.0, 10.0, 0.02)
    f = random_force(t, seed=1)
    x = sampled_response(Oscillator(m=1.0, c=0.5, k=20.0), t, f).x
    args = {"t": t, "force": f, "x": x}
    for key, val in kwargs.items():
        if val == "same":
            args[key] = x
        elif val == "const":
            args[key] = np.ones_like(t)
        elif val == "short":
            args[key] = x[:-1]
        elif val == "nan":
            args[key] = np.where(np.arange(t.size) == 3, np.nan, x)
        elif val == "jitter":
            args[key] = np.where(np.arange(t.size) == 5, t + 0.008, t)
        elif val == "2d":
            args[key] = np.stack([t, t])
        else:
            args[key] = val
    with pytest.raises(ParameterError, match="allowed") as info:
        identify(**args)
    assert name in str(info.value)


def test_identify_refuses_undersampled_and_too_short_records():
    t = np.arange(0.0, 30.0, 0.2)  # Nyquist 15.7 rad/s
    for k, match in ((400.0, "does not fit"), (196.0, "does not resolve")):  # 20 and 14 rad/s
        f = random_force(t, band=(0.1, 2.4), seed=2)
        with pytest.raises(ParameterError, match=match):
            identify(t, f, x=sampled_response(Oscillator(m=1.0, c=0.1, k=k), t, f).x)
    osc = Oscillator(m=1.0, c=0.05, k=0.04)  # period 31 s
    t = np.arange(0.0, 5.0, 0.01)
    f = random_force(t, band=(0.2, 5.0), seed=3)
    meas = synthetic_measurements(osc, t, f, noise=1e-4)
    with pytest.raises(ParameterError, match="less than one period"):
        identify(**meas)


# ----------------------------------------------------------------------------- frequency domain


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_frequency_estimates_on_a_long_clean_record():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    t = np.arange(0.0, 800.0, 0.02)
    meas = synthetic_measurements(osc, t, random_force(t, seed=11), noise=1e-4)
    frf = frf_estimate(**meas, nperseg=2**14)
    exact = 1.0 / (20.0 - frf.omega**2 + 0.5j * frf.omega)
    err = np.abs(frf.H / exact - 1)
    near = np.abs(frf.omega - 4.47) < 1.0  # Hann leakage over the sharp peak: +-2 bins of 0.02 rad/s
    assert np.max(err[(frf.omega > 1.0) & (frf.omega < 10.0) & ~near]) < 0.04
    assert np.max(err[near]) < 0.15
    hp, cf = frequency_estimates(frf)
    for est, tol in ((hp, 0.08), (cf, 0.05)):
        np.testing.assert_allclose([est.m, est.c, est.k], [1.0, 0.5, 20.0], rtol=tol, err_msg=est.method)


def test_frequency_estimates_say_why_not_when_overdamped():
    osc = Oscillator(m=1.0, c=15.0, k=20.0)
    t = np.arange(0.0, 200.0, 0.02)
    hp, cf = frequency_estimates(frf_estimate(**synthetic_measurements(osc, t, random_force(t), noise=1e-5)))
    assert math.isnan(hp.k) and hp.reason and math.isnan(cf.k) and cf.reason


# ----------------------------------------------------------------------------- tracking and detection


def _fault_record(noise=2e-3, seed=12, sensor="x"):
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    t = np.arange(0.0, 240.0, 0.02)
    f = random_force(t, seed=13)
    ks = stiffness_profile(t, 20.0, 100.0, decline_rate=0.0005, drop_time=170.0, drop=0.1)
    return osc, t, ks, synthetic_measurements(osc, t, f, noise=noise, seed=seed, stiffness=ks, sensor=sensor)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
@pytest.mark.parametrize("sensor", ["x", "a"])
def test_kalman_tracks_decline_and_drop(sensor):
    osc, t, ks, meas = _fault_record(noise=2e-3 if sensor == "x" else 0.05, sensor=sensor)
    tr = track_stiffness(**meas, reference=osc, walk=0.02)
    late = (t > 120.0) & (np.abs(t - 170.0) > 15.0)
    err = np.abs(tr.k[late] - ks[late])
    assert np.sqrt(np.mean(err**2)) < 0.15, np.sqrt(np.mean(err**2))  # N/m, of 20 N/m
    z = (tr.k[late] - ks[late]) / tr.k_std[late]
    assert 0.3 < np.std(z) < 3.0  # the reported uncertainty is the right order


@pytest.mark.parametrize("reference", ["none", "identification", "oscillator", "tuple"])
def test_detect_change_alarm_and_no_alarm(reference):
    osc, t, ks, meas = _fault_record()
    healthy = synthetic_measurements(osc, t, meas.force, noise=2e-3, seed=14)
    ref = {
        "none": None,
        "identification": identify(t[:3000], meas.force[:3000], x=healthy.x[:3000]),
        "oscillator": osc,
        "tuple": (1.0, 0.5, 20.0),
    }[reference]
    quiet = detect_change(**healthy, reference=ref)
    assert quiet.alarm_time is None and quiet.change_time is None
    det = detect_change(**meas, reference=ref)
    assert 100.0 < det.alarm_time < 140.0
    assert det.change_time <= det.alarm_time
    assert det.statistic.shape == t.shape and np.all(det.statistic >= 0)


def test_cusum_matches_its_recursion():
    z = np.random.default_rng(0).standard_normal(500) - 0.2
    g, ref = twin._cusum(z), []
    acc = 0.0
    for v in z:
        acc = max(0.0, acc + v)
        ref.append(acc)
    np.testing.assert_allclose(g, ref, atol=1e-12)


def test_detection_experiment_tradeoff_is_monotone():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    t = np.arange(0.0, 120.0, 0.02)
    f = random_force(t, seed=15)
    ks = stiffness_profile(t, 20.0, 1e9, decline_rate=0.0, drop_time=70.0, drop=0.03)
    thr = np.geomspace(3.0, 300.0, 9)
    ex = detection_experiment(
        osc, t, f, stiffness=ks, change_time=70.0, noise=3e-3, runs=30, reference=osc, thresholds=thr
    )
    fa, pd, delay = ex.false_alarm_probability, ex.detection_probability, ex.mean_delay
    assert np.all(np.diff(fa) <= 0) and fa[0] > 0.5 and fa[-1] == 0.0
    ok = np.isfinite(delay)
    assert np.all(np.diff(delay[ok]) >= 0)
    assert pd[4] == 1.0


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [({"threshold": 0.0}, "threshold"), ({"drift": -1.0}, "drift"), ({"calibration": 0.95}, "calibration"),
     ({"calibration": 0.001}, "calibration"), ({"reference": "abc"}, "reference")],
)  # fmt: skip
def test_detect_change_bad_input(kwargs, name):
    t = np.arange(0.0, 20.0, 0.02)
    meas = synthetic_measurements(Oscillator(m=1.0, c=0.5, k=20.0), t, random_force(t), noise=1e-3)
    with pytest.raises(ParameterError, match=name):
        detect_change(**meas, **kwargs)


def test_random_force_refuses_a_band_beyond_the_nyquist_frequency():
    from vibration.physics.model import ParameterError

    t = np.arange(0.0, 10.0, 0.02)  # Nyquist 25 Hz
    with pytest.raises(ParameterError, match=r"band = \(0.1, 30.0\) Hz reaches the Nyquist frequency 25 Hz"):
        vibration.random_force(t, band=(0.1, 30.0))
    assert np.all(np.isfinite(vibration.random_force(t, band=(0.1, 24.0))))
