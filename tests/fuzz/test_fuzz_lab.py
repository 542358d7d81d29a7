"""Fuzz-style inputs for the lab analyses added for any Pohl wheel: every bad input is a ParameterError naming it."""

from __future__ import annotations

import numpy as np
import pytest
from fuzzing import refused

from vibration.physics.lab import (
    check_lab_data,
    compare_damping,
    damping_vs_amplitude,
    fit_free_decay,
    fit_free_decays,
    free_decay_response,
    load_cassy_runs,
    load_lab_data,
    steadiness,
)

T = np.arange(0.0, 10.0, 0.05)
Y = free_decay_response(T, 4.5, 0.01, friction=0.02, theta0=1.0)
BAD_ARRAYS = [
    ("nan", np.where(np.arange(T.size) == 7, np.nan, Y)),
    ("inf", np.where(np.arange(T.size) == 7, np.inf, Y)),
    ("2-D", np.vstack([Y, Y])),
    ("empty", np.array([])),
    ("text", np.array(["a"] * T.size)),
    ("bool", np.ones(T.size, bool)),
    ("complex", Y + 1j),
    ("short", Y[:5]),
]


@pytest.mark.parametrize(("label", "bad"), BAD_ARRAYS, ids=[b[0] for b in BAD_ARRAYS])
def test_bad_theta(label, bad):
    refused(damping_vs_amplitude, T, bad, name="theta")
    refused(fit_free_decay, T, bad, name="theta")
    refused(steadiness, T, bad, 4.5, name="theta")
    refused(fit_free_decays, [(T, bad)], name="theta")
    refused(compare_damping, [(T, Y)], [(T, bad)], (0.1, 1.0), name="runs_b[0] theta")


def test_bad_time():
    unsorted = T.copy()
    unsorted[[3, 4]] = unsorted[[4, 3]]
    for fn in (damping_vs_amplitude, fit_free_decay):
        refused(fn, unsorted, Y, name="t")
        refused(fn, np.where(np.arange(T.size) == 2, np.nan, T), Y, name="t")
        refused(fn, T[:-1], Y, name="t")
    refused(steadiness, unsorted, Y, 4.5, name="t")


@pytest.mark.parametrize("omega", [np.nan, np.inf, -1.0, 0.0, "4", None, True])
def test_steadiness_omega(omega):
    refused(steadiness, T, np.sin(4.5 * T), omega, name="omega")


@pytest.mark.parametrize(
    ("kw", "name"),
    [
        ({"periods": 1}, "periods"),
        ({"periods": 2.5}, "periods"),
        ({"periods": True}, "periods"),
        ({"periods": 40}, "t"),
        ({"tolerance": 0.0}, "tolerance"),
        ({"tolerance": np.nan}, "tolerance"),
        ({"tolerance": 2.0}, "tolerance"),
    ],
)
def test_steadiness_options(kw, name):
    refused(steadiness, T, np.sin(4.5 * T), 4.5, name=name, **kw)


@pytest.mark.parametrize("law", ["", "quadratic+power", "viscous+viscous", 3, None, "cubic"])
def test_bad_law(law):
    refused(fit_free_decay, T, Y, law, name="law")
    refused(fit_free_decays, [(T, Y)], law, name="law")


@pytest.mark.parametrize(
    ("runs", "name"),
    [
        ([], "runs"),
        ("abc", "runs"),
        (5, "runs"),
        ([(T,)], "runs[0]"),
        ([(T, Y[:-3])], "runs[0]"),
        ([(T, np.full(T.size, np.nan))], "runs[0]"),
    ],
)
def test_bad_runs(runs, name):
    refused(fit_free_decays, runs, name=name)
    refused(compare_damping, runs, [(T, Y)], (0.1, 1.0), name=name.replace("runs", "runs_a"))


@pytest.mark.parametrize("band", [(1.0, 0.5), (np.nan, 1.0), (0.1, np.inf), (-1.0, 1.0), "ab", (1.0,), None])
def test_bad_band(band):
    refused(compare_damping, [(T, Y)], [(T, Y)], band, name="band")


@pytest.mark.parametrize(
    "text",
    [
        b"",
        b"\xff\xfe\x00garbage",
        b"Zeit t / s;Weg &b_A1 / rad\r\n0;1\r\n",  # too short
        b"Zeit t / s;Temperatur T / K\r\n",
        b"Weg &b_A1 / rad\r\n1,0\r\n",
        ("Zeit t / s;Weg &b_A1 / rad\r\n" + "".join(f"{i % 5};1,0\r\n" for i in range(30))).encode(),  # not sorted
        ("Zeit t / s;Weg &b_A1 / rad\r\n" + "".join(f"{i},0;\r\n" for i in range(30))).encode(),  # empty angles
    ],
)
def test_malformed_cassy(tmp_path, text):
    p = tmp_path / "x.csv"
    p.write_bytes(text)
    msg = refused(load_cassy_runs, p)
    assert "x.csv" in msg


@pytest.mark.parametrize("path", [None, 3, b"x.csv", "/nonexistent/x.csv"])
def test_bad_paths(path):
    refused(load_cassy_runs, path, name="path")
    refused(load_lab_data, path, name="folder")
    refused(check_lab_data, path, name="folder")


def test_folder_without_manifest(tmp_path):
    refused(load_lab_data, tmp_path, name="runs.csv")


@pytest.mark.parametrize(
    ("kw", "name"),
    [
        ({"omega_n": np.nan}, "omega_n"),
        ({"omega_n": -1.0}, "omega_n"),
        ({"force": np.inf}, "force"),
        ({"zeta": -0.1}, "zeta"),
        ({"friction": "a"}, "friction"),
        ({"quadratic": np.nan}, "quadratic"),
        ({"power": -1.0}, "power"),
        ({"power_exponent": 50.0}, "power_exponent"),
    ],
)
def test_law_forced_amplitude_and_equivalent_zeta(kw, name):
    from vibration.physics.lab import damping_ode, equivalent_zeta, law_forced_amplitude

    base = {"omega_n": 4.5, "force": 0.1}
    refused(law_forced_amplitude, 4.0, **{**base, **kw}, name=name)
    if name not in ("force", "friction"):
        eq = {k: v for k, v in {**base, **kw}.items() if k != "force"}
        refused(equivalent_zeta, 1.0, eq.pop("omega_n"), **eq, name=name)
        refused(damping_ode, T, **eq, omega_n=base["omega_n"] if name != "omega_n" else kw["omega_n"], name=name)


@pytest.mark.parametrize("omega", [np.nan, -1.0, 0.0, [[1.0]], "x"])
def test_law_forced_amplitude_omega(omega):
    from vibration.physics.lab import law_forced_amplitude

    refused(law_forced_amplitude, omega, omega_n=4.5, force=0.1, name="omega")


@pytest.mark.parametrize("amplitude", [np.nan, -1.0, "x", [[1.0]], True])
def test_equivalent_zeta_amplitude(amplitude):
    from vibration.physics.lab import equivalent_zeta

    refused(equivalent_zeta, amplitude, 4.5, name="amplitude")


def test_joint_brake_fit_inputs():
    from vibration.physics.lab import joint_brake_fit

    refused(joint_brake_fit, [], [(T, Y)], name="runs_a")
    refused(joint_brake_fit, [(T, Y)], "ab", name="runs_b")
    refused(joint_brake_fit, [(T, Y)], [(T, np.full(T.size, np.inf))], name="runs_b[0] theta")
    flat = np.where(T < 9.0, 0.0, 1e-3) + 1e-4 * np.sin(T)  # no free decay: too few half periods
    refused(joint_brake_fit, [(T, flat)], [(T, Y)], name="runs_a")
