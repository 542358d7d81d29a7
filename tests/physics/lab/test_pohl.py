"""Another laboratory's wheel (tests/pohl_generator.py): the loaders read its CASSY files and manifest, and the
fits recover the law it was simulated with."""

from __future__ import annotations

import math

import numpy as np
import pohl_generator as gen
import pytest

from vibration.physics.lab import (
    check_lab_data,
    compare_damping,
    fit_free_decays,
    load_lab_data,
    steadiness,
)


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    folder = tmp_path_factory.mktemp("pohl")
    truth = gen.write_lab(folder)
    return folder, truth


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_loader_reads_every_run(lab):
    folder, _ = lab
    data = load_lab_data(folder)
    assert len(data.select(kind="free")) == 3 * len(gen.CURRENTS)
    assert len(data.select(kind="driven")) == len(gen.DRIVEN_CURRENTS) * len(gen.DRIVE_OMEGAS)
    assert set(data.formats.values()) == {"CASSY Lab 2"}
    r = data.select(kind="driven")[0]
    assert r.data.drive_unit == "V" and r.data.drive_angle is not None
    assert r.data.t[1] - r.data.t[0] == pytest.approx(0.1)
    assert data.rig.encoder_step_rad == 0.001 and data.rig.max_angle_rad == 30.0
    assert data.current("700 mA") == pytest.approx(0.7)
    check = check_lab_data(folder)
    assert check.n_free == 12 and check.n_driven == 10
    assert not any("not testable" in w for w in check.warnings)  # driven runs at two brake settings


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_fits_recover_the_simulated_law(lab):
    """Viscous ratio per current within 10 % + 0.001, Coulomb angle within 10 %, omega_n within 0.2 %."""
    folder, truth = lab
    data = load_lab_data(folder)
    zetas = []
    for current in gen.CURRENTS:
        label = f"{round(current * 1000)} mA"
        pooled = fit_free_decays(data.select(kind="free", brake=label), "coulomb+viscous")
        z_true = gen.zeta_of(current)
        assert pooled.mean["zeta"] == pytest.approx(z_true, rel=0.10, abs=1e-3), label
        assert pooled.mean["friction"] == pytest.approx(truth["friction"], rel=0.10), label
        assert pooled.mean["omega_n"] == pytest.approx(truth["omega_n"], rel=2e-3), label
        zetas.append(pooled.mean["zeta"])
    # the eddy-current law zeta = zeta0 + k I^2, fitted by numpy's own least squares
    i2 = np.array(gen.CURRENTS) ** 2
    k, z0 = np.polyfit(i2, zetas, 1)
    assert k == pytest.approx(truth["k_brake"], rel=0.10)
    assert z0 == pytest.approx(truth["zeta0"], abs=1.5e-3)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_brake_difference_at_matched_amplitude(lab):
    """0 mA against 700 mA: zeta_eq differs by about the viscous part, resolved (Coulomb adds to both sides)."""
    folder, _ = lab
    data = load_lab_data(folder)
    d = compare_damping(data.select(kind="free", brake="0 mA"), data.select(kind="free", brake="700 mA"), (0.5, 2.0))
    assert d.resolved and d.method == "bootstrap over runs"
    assert d.delta_zeta == pytest.approx(gen.K_BRAKE * 0.49, rel=0.25)


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_steadiness_follows_the_transient(lab):
    """The transient decays as exp(-zeta omega_n t): tau = 5.4 s at 700 mA (60 s records), 37 s at 200 mA (130 s).
    Every resonant run is steady at the end and reaches 90 % within a few tau; cut during its build-up (at 1.5 tau)
    the 200 mA resonant run is still growing."""
    folder, _ = lab
    data = load_lab_data(folder)
    for r in data.select(kind="driven"):
        omega = gen.DRIVE_OMEGAS[int(r.file.rsplit("_", 1)[1].split(".")[0]) - 1]
        tau = 1.0 / (gen.zeta_of(r.brake_current_A) * gen.OMEGA_N)
        s = steadiness(r.t, r.angle, omega)
        if omega == 4.4:
            assert s.steady, (r.file, s)
            assert s.t90 < 3.0 * tau + 2.0 * math.pi / omega, (r.file, s.t90, tau)
            if r.brake == "200 mA":
                cut = r.t < 1.5 * tau
                early = steadiness(r.t[cut], r.angle[cut], omega)
                assert not early.steady and early.drift > 0.02


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
def test_check_lab_command(lab, tmp_path, capsys):
    from vibration.book.publishing.report import main

    folder, _ = lab
    assert main(["--check-lab", str(folder)]) == 0
    out = capsys.readouterr().out
    assert "12 free decays, 10 driven" in out and "CASSY Lab 2" in out
    (tmp_path / "runs.csv").write_text("file,kind,brake,brake_current_A,session,run\nmissing.csv,free,off,,A,\n")
    assert main(["--check-lab", str(tmp_path)]) == 2
    assert "row 1, column 'file'" in capsys.readouterr().err
