"""Damping laws, damping against amplitude, steadiness, CASSY files and manifests, checked against independent
computations (SciPy's solve_ivp on the same law, the Coulomb energy balance, numpy directly)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy import integrate

from vibration.physics.lab import (
    compare_damping,
    damping_laws,
    damping_vs_amplitude,
    fit_free_decay,
    fit_free_decays,
    free_decay_response,
    load_cassy_runs,
    load_lab_data,
    steadiness,
)
from vibration.physics.model import ParameterError

W = 4.5


def _ode(t, *, zeta=0.0, delta=0.0, b=0.0, a=0.0, p=2.0, theta0=5.0):
    """Free decay from rest, integrated directly (smooth friction, 1e-4 rad/s regularisation)."""

    def rhs(_t, x):
        v = x[1]
        s = math.tanh(v / 1e-4)
        return [v, -W * W * x[0] - 2 * zeta * W * v - W * W * delta * s - b * v * abs(v) - a * abs(v) ** p * s]

    sol = integrate.solve_ivp(rhs, (0, t[-1]), [theta0, 0.0], method="LSODA", rtol=1e-9, atol=1e-11, t_eval=t)
    return sol.y[0]


T = np.arange(0.0, 30.0, 0.05)


@pytest.mark.parametrize(
    ("law", "kw", "expect"),
    [
        ("coulomb+quadratic", {"delta": 0.1, "b": 0.02}, {"coulomb": 0.1, "quadratic": 0.02}),
        ("coulomb+viscous", {"delta": 0.1, "zeta": 0.01}, {"coulomb": 0.1, "viscous": 0.01}),
        ("coulomb+power", {"delta": 0.1, "a": 2e-4, "p": 4.0}, {"coulomb": 0.1, "power_exponent": 4.0}),
    ],
)
def test_fits_recover_a_law_integrated_by_scipy(law, kw, expect):
    y = np.round(_ode(T, **kw) / 0.01745) * 0.01745  # the PASCO encoder's step
    f = fit_free_decay(T, y, law)
    for key, value in expect.items():
        assert f.coefficients[key] == pytest.approx(value, rel=0.08), (key, f.coefficients)
    assert set(f.coefficients) == set(expect) | ({"power"} if "power" in law else set())
    assert f.omega_n == pytest.approx(W, rel=2e-3)


def test_law_strings():
    t = np.arange(0.0, 10.0, 0.05)
    y = free_decay_response(t, W, 0.01, friction=0.02, theta0=1.0)
    assert fit_free_decay(t, y, "combined").law == fit_free_decay(t, y, "viscous+coulomb").law == "coulomb+viscous"
    with pytest.raises(ParameterError, match="quadratic\\+power"):
        fit_free_decay(t, y, "coulomb+quadratic+power")
    with pytest.raises(ParameterError, match="law"):
        fit_free_decay(t, y, "coulomb+cubic")


def test_coulomb_energy_balance_and_viscous_ratio():
    """Coulomb: the half-period amplitude drops by 2 Delta per half period; viscous: zeta_eq is zeta."""
    t = np.arange(0.0, 12.0, 0.005)
    c = damping_vs_amplitude(t, free_decay_response(t, W, 0.0, friction=0.07, theta0=3.0))
    assert c.n > 10
    np.testing.assert_allclose(c.loss, 2 * 0.07, atol=2e-3)
    v = damping_vs_amplitude(t, free_decay_response(t, W, 0.03, friction=0.0, theta0=3.0))
    np.testing.assert_allclose(v.zeta_eq, 0.03, atol=5e-4)
    assert v.amplitude.size == v.zeta_eq.size == v.loss.size == v.t.size
    # quadratic law: loss per half period (4/3) b X^2 to first order (energy balance), from the direct integration
    q = damping_vs_amplitude(T, _ode(T, b=0.02, theta0=4.0))
    big = q.amplitude > 1.0
    ratio = q.loss[big] / (4.0 / 3.0 * 0.02 * (q.amplitude[big] - q.loss[big] / 2) ** 2)
    np.testing.assert_allclose(ratio, 1.0, atol=0.05)


def test_pooled_errors_are_the_run_to_run_scatter():
    runs = [(T, free_decay_response(T, W, z, friction=0.05, theta0=2.0)) for z in (0.004, 0.006, 0.008, 0.01)]
    p = fit_free_decays(runs, "coulomb+viscous")
    zs = np.array([f.zeta for f in p.fits])
    assert p.stderr["zeta"] == pytest.approx(zs.std(ddof=1) / 2.0, rel=1e-9)
    assert p.mean["zeta"] == pytest.approx(0.007, rel=1e-3)
    assert p.bic == pytest.approx(sum(f.bic for f in p.fits))
    assert p.n_runs == 4


def test_compare_damping_methods():
    a = [(T, free_decay_response(T, W, 0.01, friction=0.0, theta0=x)) for x in (3.0, 3.3, 3.6)]
    b = [(T, free_decay_response(T, W, 0.015, friction=0.0, theta0=x)) for x in (3.0, 3.3, 3.6)]
    d = compare_damping(a, b, (0.5, 2.5))
    assert d.delta_zeta == pytest.approx(0.005, abs=2e-4) and d.method == "bootstrap over runs"
    assert d.n_a == d.n_b == 3
    d2 = compare_damping(a[:2], b, (0.5, 2.5))
    assert d2.method == "bootstrap over half periods"
    assert compare_damping(a, b, (0.5, 2.5)).stderr == d.stderr  # fixed seed
    with pytest.raises(ParameterError, match="band"):
        compare_damping(a, b, (10.0, 20.0))


def test_steadiness_against_an_exact_build_up():
    t = np.arange(0.0, 40.0, 0.05)
    w, tau = 4.0, 3.0
    s = steadiness(t, (1 - np.exp(-t / tau)) * np.sin(w * t), w)
    assert s.steady and s.t90 == pytest.approx(tau * math.log(10), abs=0.3)
    cut = t < 8.0  # cut during the build-up: still growing
    g = steadiness(t[cut], (1 - np.exp(-t[cut] / tau)) * np.sin(w * t[cut]), w)
    assert not g.steady and g.drift > 0.02
    beat = np.sin(w * t) + 0.3 * np.sin(1.15 * w * t)
    assert not steadiness(t, beat, w).steady


def _cassy(path, header, rows, sep=";"):
    path.write_bytes(("\ufeff" + sep.join(header) + "\r\n" + "\r\n".join(sep.join(r) for r in rows)).encode())


def test_cassy_german_and_english(tmp_path):
    n = 40
    de = [[f"{0.1 * i:.1f}".replace(".", ","), f"{math.sin(i):.3f}".replace(".", ","), "0,01", "1,2"] for i in range(n)]
    _cassy(tmp_path / "de.csv", ["Zeit t / s", "Weg &b_A1 / rad", "Spannung U_B1 / V", "Frequenz f / Hz"], de)
    en = [[f"{0.1 * i:.1f}", f"{math.sin(i):.3f}"] for i in range(n)]
    _cassy(tmp_path / "en.csv", ["Time t / s", "Angle &b_A1 / rad"], en)
    r_de, r_en = load_cassy_runs(tmp_path / "de.csv")[0], load_cassy_runs(tmp_path / "en.csv")[0]
    np.testing.assert_allclose(r_de.angle, r_en.angle)
    np.testing.assert_allclose(r_de.t, 0.1 * np.arange(n), atol=1e-12)
    assert r_de.drive_unit == "V" and r_en.drive_angle is None
    bad = [list(r) for r in de]
    bad[5][1] = "x"
    _cassy(tmp_path / "bad.csv", ["Zeit t / s", "Weg &b_A1 / rad", "Spannung U_B1 / V", "Frequenz f / Hz"], bad)
    with pytest.raises(ParameterError, match=r"data row 6 .*column 'Weg &b_A1 / rad'"):
        load_cassy_runs(tmp_path / "bad.csv")


def test_todays_folder_and_manifest_errors(tmp_path):
    data = load_lab_data(Path(__file__).resolve().parents[3] / "data" / "lab_oscillator")
    assert len(data.select(kind="free", brake="off")) == len(data.select(kind="free", brake="on")) == 10
    assert len(data.select(kind="driven")) == 54 and data.sessions == ["decays", "1", "2"]
    assert data.rig.encoder_step_rad == pytest.approx(math.pi / 180)
    src = tmp_path / "src.csv"
    _cassy(src, ["Zeit t / s", "Weg &b_A1 / rad"], [[f"{0.1 * i:.1f}", f"{i % 3}"] for i in range(30)], sep=";")
    head = "file,kind,brake,brake_current_A,session,run\n"
    cases = {
        "src.csv,freee,off,,A,\n": "row 1, column 'kind'",
        "src.csv,free,off,-1,A,\n": "row 1, column 'brake_current_A'",
        "src.csv,free,off,,A,2\n": "row 1, column 'run'",
        "nope.csv,free,off,,A,\n": "row 1, column 'file'",
        "src.csv,free,,,A,\n": "row 1, column 'brake'",
        "src.csv,free,off,,A,\nsrc.csv,free,off,,A,\n": "row 2, column 'run'",
        "../x.csv,free,off,,A,\n": "row 1, column 'file'",
    }
    for body, where in cases.items():
        (tmp_path / "runs.csv").write_text(head + body)
        with pytest.raises(ParameterError, match=where):
            load_lab_data(tmp_path)
    (tmp_path / "runs.csv").write_text("file,kind,brake\nsrc.csv,free,off\n")
    with pytest.raises(ParameterError, match="header"):
        load_lab_data(tmp_path)


def _half_cycles_python(theta0, offset, omega_n, zeta, friction, quad, power, p, t_span):
    """The half-cycle recurrence of the energy-balance model in plain Python, the compiled kernel's reference."""
    cap = 0.9
    n_max = damping_laws.MAX_HALF_CYCLES
    T = [0.0]
    e = [theta0]
    centre: list[float] = []
    zk: list[float] = []
    stop = None
    kp = damping_laws._sine_power_integral(p + 1.0) * omega_n ** (p - 2.0) / math.pi if power else 0.0

    def z_of(a):
        z = zeta + 4.0 * quad * a / (3.0 * math.pi)
        if power:
            z += power * kp * a ** (p - 1.0)
        return min(z, cap)

    while T[-1] <= t_span:
        if len(centre) >= n_max:
            raise ParameterError(
                f"t spans more than {n_max} half periods which is out of range: allowed at most {n_max} (omega_n * "
                "duration too large)"
            )
        d = e[-1] - offset
        if abs(d) <= friction:
            stop = len(centre)
            break
        c = offset + math.copysign(friction, d)
        a = abs(e[-1] - c)
        z = z_of(a)
        q = math.exp(-math.pi * z / math.sqrt(1.0 - z * z))
        z = z_of(0.5 * (a + q * a))  # corrector: the ratio at the half period's mean amplitude
        q = math.exp(-math.pi * z / math.sqrt(1.0 - z * z))
        centre.append(c)
        zk.append(z)
        e.append(c - q * (e[-1] - c))
        T.append(T[-1] + math.pi / (omega_n * math.sqrt(1.0 - z * z)))
    n = len(centre)
    return np.asarray(T), np.asarray(e), np.asarray(centre), np.asarray(zk), (n if stop is None else stop)


@pytest.mark.parametrize(
    "friction, zeta, quad, power, p",
    [
        (0.0, 0.01, 0.02, 0.0, 2.0),  # quadratic
        (0.004, 0.005, 0.0, 0.01, 3.0),  # power with friction: stops within the window
        (0.0, 0.0, 0.0, 0.03, 0.7),  # a power below one
        (0.02, 0.0, 0.05, 0.02, 1.5),  # every term
    ],
)
def test_compiled_half_cycles_equal_the_python_recurrence_to_the_bit(friction, zeta, quad, power, p):
    args = (0.8, 0.01, 3.7, zeta, friction, quad, power, p, 120.0)
    got, want = damping_laws._half_cycles(*args), _half_cycles_python(*args)
    for g, w in zip(got[:4], want[:4], strict=True):
        assert g.shape == w.shape and np.array_equal(g, w)
    assert got[4] == want[4]
    assert friction > 0 or got[0].size > 65  # without friction the kernel's arrays grew past their first size


def test_too_many_half_cycles_is_an_error_naming_the_window():
    from vibration.physics.lab.damping_laws import _half_cycles

    with pytest.raises(ParameterError, match="half periods which is out of range"):
        _half_cycles(1.0, 0.0, 1e4, 1e-9, 0.0, 1e-9, 0.0, 2.0, 1e3)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_the_pooled_power_term_recovers_one_law_and_its_jackknife_error_sees_runs_that_disagree():
    """Runs of one power law (a = 0.004, p = 3) from four start angles: the pooled term is that law and its
    jackknife errors are small. Runs of two laws (p = 2 and p = 4): the error of the exponent grows to cover both."""
    t = np.arange(0.0, 25.0, 0.01)
    same = [(t, _ode(t, delta=0.02, a=0.004, p=3.0, theta0=x)) for x in (2.0, 2.5, 3.0, 3.5)]
    p = fit_free_decays(same, "coulomb+power")
    assert p.mean["power_exponent"] == pytest.approx(3.0, abs=0.05)
    assert p.mean["power"] == pytest.approx(0.004, rel=0.05)
    assert p.stderr["power_exponent"] < 0.05
    mixed = [(t, _ode(t, delta=0.02, a=a, p=q, theta0=x)) for a, q, x in ((0.02, 2.0, 2.5), (0.0008, 4.0, 2.5))] * 2
    m = fit_free_decays(mixed, "coulomb+power")
    assert 2.0 < m.mean["power_exponent"] < 4.0
    assert m.stderr["power_exponent"] > 10 * p.stderr["power_exponent"]
