"""Sweeps: grids refused before any task, key results equal to the chapters' boxes, the dataset and its files."""

from __future__ import annotations

import csv
import json
import math
import re
from pathlib import Path

import nbformat
import numpy as np
import pytest

from vibration.book.publishing import engine
from vibration.book.publishing import sweep as sw
from vibration.physics.model import ParameterError

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def no_task(monkeypatch):
    """Any point run or cluster started fails the test: the grid must be refused first."""

    def boom(*args, **kwargs):
        raise AssertionError("a task or a cluster was started")

    monkeypatch.setattr(sw, "run_point", boom)
    monkeypatch.setattr(engine, "cluster", boom)


@pytest.mark.parametrize(
    ("grid", "params", "pattern"),
    [
        ({"omega_typo": "1:2:3"}, None, r"parameter 'omega_typo' is not one of 09_duffing's"),
        ({"F0_ueda": "1:200:3"}, None, r"F0_ueda = 100.5 N is out of range"),
        ({"F0_ueda": "-1:2:3"}, None, r"F0_ueda = -1.0 N is out of range"),
        ({"F0_ueda": ""}, None, r"F0_ueda grid '' is empty"),
        ({"F0_ueda": "1:2:0"}, None, r"F0_ueda grid '1:2:0' is empty"),
        ({"F0_ueda": []}, None, r"F0_ueda grid is empty"),
        ({}, None, r"the grid is empty"),
        ({"n_lyapunov": "100:201:3"}, None, r"n_lyapunov grid 100:201:3 gives 150.5, not an integer"),
        ({"c_ueda": "0:1:3log"}, None, r"c_ueda grid '0:1:3log' is logarithmic"),
        ({"F0_ueda": "1,1"}, None, r"F0_ueda grid '1,1' repeats a value"),
        # a combination the schema's rules refuse: the sweep band's lower end above its upper end
        ({"omega_sweep_min": "3:8:3"}, None, r"omega_sweep_max = 6.5 rad/s must exceed omega_sweep_min = 8.0 rad/s"),
        ({"F0_ueda": "1:2:3"}, {"F0_ueda": "3"}, r"'F0_ueda' is both swept and fixed"),
        ({"F0_ueda": "1:2:3"}, {"c_typo": "3"}, r"parameter 'c_typo' \(value '3'\) is not one of 09_duffing's"),
        ({"F0_ueda": "1:2:3"}, {"c_ueda": "20"}, r"c_ueda = 20.0 N s/m is out of range"),
    ],
)
def test_bad_grids_are_refused_before_any_task_naming_the_parameter(no_task, grid, params, pattern):
    with pytest.raises(ParameterError, match=pattern):
        sw.sweep("09", grid, params=params)


def test_the_command_refuses_a_bad_grid_before_any_task(no_task, tmp_path, capsys):
    from vibration.book.publishing import report

    rc = report.main(["sweep", "04", "-g", "c_nominal", "1:1e6:3", "--out", str(tmp_path / "s")])
    assert rc == 2
    assert "c_nominal = " in capsys.readouterr().err
    assert not (tmp_path / "s" / "points.jsonl").exists()


def test_a_chapter_without_key_results_is_refused(no_task):
    with pytest.raises(ParameterError, match=r"declares no key results.*allowed .*04_frequency_response"):
        sw.sweep("01", {"F0": "1:2:2"})


def test_grids_parse_linear_log_and_lists():
    g = sw.make_grid("09", {"F0_ueda": "2:10:5", "c_ueda": "0.01:1:3log"}, {"n_lyapunov": "100"})
    assert g.shape == (5, 3) and g.size == 15
    assert g.axes[0].values == (2.0, 4.0, 6.0, 8.0, 10.0)
    np.testing.assert_allclose(g.axes[1].values, [0.01, 0.1, 1.0], rtol=1e-14)
    assert g.axes[1].log and g.fixed["n_lyapunov"] == 100 and "F0_ueda" not in g.fixed
    assert sw.make_grid("09", {"n_lyapunov": "100:300:3"}).axes[0].values == (100, 200, 300)


def _box(notebook: str) -> str:
    """The key-results box of a committed notebook (its stored output, written by the notebook's own code)."""
    nb = nbformat.read(ROOT / "notebooks" / notebook, as_version=4)
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            text = out.get("data", {}).get("text/markdown", "")
            if "**Key results**" in text:
                return text
    raise AssertionError(f"{notebook} has no key-results box")


def _glued(notebook: str, name: str) -> str:
    """A number a committed notebook glues into its prose (its stored output, written by the notebook's own code)."""
    nb = nbformat.read(ROOT / "notebooks" / notebook, as_version=4)
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            if out.get("metadata", {}).get("scrapbook", {}).get("name") == name:
                return out["data"]["application/papermill.record/text/plain"].strip("'")
    raise AssertionError(f"{notebook} glues no {name!r}")


def _printed(pattern: str, text: str) -> tuple[float, float]:
    """The number the pattern's group prints and half a unit of its last printed digit."""
    m = re.search(pattern, text)
    assert m, (pattern, text[:300])
    digits = m.group(1)
    decimals = len(digits.split(".")[1]) if "." in digits else 0
    return float(digits), 0.5 * 10.0**-decimals


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_chapter_4_sweep_point_at_defaults_equals_its_key_results_box():
    ds = sw.sweep("04", {"c_nominal": [0.5]}, serial=True)
    value, half = _printed(r"([\d.]+)", _glued("04_frequency_response.ipynb", "M_res_nom_value"))
    assert abs(float(ds["M_res"].values[0]) - value) <= half
    assert ds["X_res"].attrs["units"] == "m" and ds["M_res"].attrs["units"] == "1"
    assert ds["c_nominal"].attrs == {"units": "N s/m", "long_name": ds["c_nominal"].attrs["long_name"],
                                     "spacing": "as given"}  # fmt: skip


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_chapter_8_sweep_point_at_defaults_equals_its_key_results_box():
    ds = sw.sweep("08", {"mu": [0.05]}, serial=True)
    value, half = _printed(r"robust min-max design's worst peak is ([\d.]+)", _box("08_tmd.ipynb"))
    assert abs(float(ds["worst_peak_robust"].values[0]) - value) <= half
    assert {n for n in ds.data_vars if n.startswith("worst_peak_")} == {
        "worst_peak_den_hartog", "worst_peak_hinf_closed", "worst_peak_h2_closed", "worst_peak_hinf",
        "worst_peak_h2", "worst_peak_robust"}  # fmt: skip
    # the H∞ optimum's worst peak is the robust one's over (1 - the printed share lower)
    share, _ = _printed(r"robust min-max design's worst peak is [\d.]+, ([\d.]+) % lower", _box("08_tmd.ipynb"))
    ratio = float(ds["worst_peak_robust"].values[0] / ds["worst_peak_hinf"].values[0])
    assert abs((1 - ratio) * 100 - share) < 0.01


@pytest.mark.slow
def test_chapter_9_sweep_point_at_defaults_equals_its_key_results_box():
    ds = sw.sweep("09", {"F0_ueda": [7.5]}, serial=True)
    box = re.sub(r'<span class="vib-approx"[^>]*>([^<]*)</span>', r"\1", _box("09_duffing.ipynb"))
    mean, half = _printed(r"λ₁ ([\d.]+) ± ", box)
    se, half_se = _printed(r"λ₁ [\d.]+ ± ([\d.]+) 1/s", box)
    assert abs(float(ds["lyapunov"].values[0]) - mean) <= half
    assert abs(float(ds["lyapunov_se"].values[0]) - se) <= half_se
    assert ds["lyapunov"].attrs["units"] == "1/s"


def _magnification(m: float, c: float, k: float, w: float) -> float:
    """|X| / (F0/k) of m x'' + c x' + k x = F0 sin(w t), written out here (not the package's)."""
    return k / math.hypot(k - m * w * w, c * w)


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_chapter_4_points_equal_the_closed_form_and_a_failed_point_is_nan_with_its_message(tmp_path):
    cs = [0.2, 0.5, 1.5]
    out = tmp_path / "s4"
    ds = sw.sweep("04", {"c_nominal": cs, "omega_res": [3.0, 4.47]},
                  params={"n_omega": 4, "n_damping": 3, "n_points": 501}, serial=True, out=out)  # fmt: skip
    assert ds["M_res"].dims == ("c_nominal", "omega_res") and ds["M_res"].shape == (3, 2)
    for i, c in enumerate(cs):
        for j, w in enumerate([3.0, 4.47]):
            expected = _magnification(1.0, c, 20.0, w)
            assert float(ds["M_res"].values[i, j]) == pytest.approx(expected, rel=1e-12)
            assert float(ds["X_res"].values[i, j]) == pytest.approx(expected * 5.0 / 20.0, rel=1e-12)
    assert (ds["error"].values == "").all()
    assert ds.attrs["param_n_omega"] == 4 and ds.attrs["package_version"] and ds.attrs["commit"]
    import xarray as xr

    back = xr.open_dataset(out / "sweep.nc", engine="h5netcdf")
    np.testing.assert_array_equal(back["M_res"].values, ds["M_res"].values)
    assert back["omega_res"].attrs["units"] == "rad/s" and back["M_res"].attrs["long_name"]
    rows = list(csv.DictReader((out / "sweep.csv").open()))
    assert len(rows) == 3 * 2 * 2 and set(rows[0]) == {"c_nominal", "omega_res", "result", "value", "unit", "error"}
    row = next(r for r in rows if r["result"] == "M_res" and float(r["c_nominal"]) == 0.2 and r["omega_res"] == "3.0")
    assert float(row["value"]) == pytest.approx(_magnification(1.0, 0.2, 20.0, 3.0), rel=1e-12)
    assert {p.name for p in out.glob("*.png")} == {"X_res.png", "M_res.png"}
    assert "# Sweep of chapter 04_frequency_response" in (out / "summary.md").read_text()
    assert len((out / "points.jsonl").read_text().splitlines()) == 6


def test_a_point_whose_study_fails_is_nan_with_its_error(monkeypatch):
    from vibration.book.chapters.frequency_response import keyresults

    real = keyresults.KEY_RESULTS.study

    def flaky(p):
        if p.c_nominal > 1.0:
            raise FloatingPointError("the study diverged")
        return real(p)

    monkeypatch.setattr(keyresults, "KEY_RESULTS", keyresults.KEY_RESULTS.__class__(
        study=flaky, results=keyresults.KEY_RESULTS.results))  # fmt: skip
    ds = sw.sweep("04", {"c_nominal": [0.5, 2.0]}, params={"n_omega": 4, "n_damping": 3}, serial=True)
    assert math.isfinite(float(ds["M_res"].values[0])) and math.isnan(float(ds["M_res"].values[1]))
    assert list(ds["error"].values) == ["", "FloatingPointError: the study diverged"]


def test_resume_refuses_another_grid(tmp_path):
    out = tmp_path / "s"
    sw.sweep("04", {"c_nominal": [0.5]}, params={"n_omega": 4, "n_damping": 3}, serial=True, out=out)
    with pytest.raises(ParameterError, match=r"--resume: the grid differs .* \(in axes\)"):
        sw.sweep("04", {"c_nominal": [0.5, 0.6]}, params={"n_omega": 4, "n_damping": 3}, serial=True, out=out,
                 resume=True)  # fmt: skip
    with pytest.raises(ParameterError, match=r"--resume: the grid differs .* \(in fixed\)"):
        sw.sweep("04", {"c_nominal": [0.5]}, params={"n_omega": 5, "n_damping": 3}, serial=True, out=out,
                 resume=True)  # fmt: skip


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_resume_computes_only_the_missing_points(tmp_path, monkeypatch):
    out = tmp_path / "s"
    grid, params = {"c_nominal": [0.3, 0.5, 0.7]}, {"n_omega": 4, "n_damping": 3}
    sw.sweep("04", grid, params=params, serial=True, out=out)
    lines = (out / "points.jsonl").read_text().splitlines()
    (out / "points.jsonl").write_text(lines[0] + "\n" + lines[2][:20])  # one kept, one cut short by a kill
    ran = []
    real = sw.run_point
    monkeypatch.setattr(sw, "run_point", lambda task: ran.append(task.index) or real(task))
    ds = sw.sweep("04", grid, params=params, serial=True, out=out, resume=True)
    kept = tuple(json.loads(lines[0])["index"])
    assert sorted(ran) == sorted({(0,), (1,), (2,)} - {kept})
    np.testing.assert_allclose(ds["M_res"].values, [_magnification(1.0, c, 20.0, 4.47) for c in grid["c_nominal"]],
                               rtol=1e-12)  # fmt: skip


@pytest.mark.slow
def test_a_local_cluster_sweep_equals_the_same_points_computed_serially():
    grid = {"F0_ueda": "4:10:4", "c_ueda": "0.05,0.1"}
    serial = sw.sweep("09", grid, params={"n_lyapunov": 100}, serial=True)
    cluster = sw.sweep("09", grid, params={"n_lyapunov": 100}, jobs=2)
    np.testing.assert_array_equal(cluster["lyapunov"].values, serial["lyapunov"].values)
    np.testing.assert_array_equal(cluster["lyapunov_se"].values, serial["lyapunov_se"].values)
    from vibration.book.chapters.duffing.study import chaos_study

    direct = chaos_study(F0_ueda=10.0, c_ueda=0.1, n_lyapunov=100).pooled.mean  # the study called directly
    assert float(cluster["lyapunov"].sel(F0_ueda=10.0, c_ueda=0.1)) == direct


@pytest.mark.slow
def test_sigterm_stops_a_sweep_within_seconds_and_resume_completes_only_the_missing_points(tmp_path):
    import signal
    import subprocess
    import sys
    import time

    out = tmp_path / "s"
    cmd = [sys.executable, "-m", "vibration.report", "sweep", "09", "-g", "F0_ueda", "3:11:24", "-p", "n_lyapunov",
           "400", "--out", str(out), "--no-progress"]  # fmt: skip
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        time.sleep(0.3)
        points = out / "points.jsonl"
        if points.is_file() and len(points.read_text().splitlines()) >= 3:
            break
    proc.send_signal(signal.SIGTERM)
    start = time.perf_counter()
    _, err = proc.communicate(timeout=60)
    assert time.perf_counter() - start < 10.0
    assert proc.returncode == 130, err
    assert "finished points kept" in err
    kept = {tuple(json.loads(x)["index"]) for x in (out / "points.jsonl").read_text().splitlines() if x.strip()}
    assert 3 <= len(kept) < 24
    assert not (out / "sweep.nc").exists()
    done = subprocess.run([*cmd, "--resume"], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    lines = [json.loads(x) for x in (out / "points.jsonl").read_text().splitlines()]
    assert len(lines) == 24 and len({tuple(x["index"]) for x in lines}) == 24  # each missing point computed once
    import xarray as xr

    ds = xr.open_dataset(out / "sweep.nc", engine="h5netcdf")
    assert (ds["error"].values == "").all() and np.isfinite(ds["lyapunov"].values).all()


def test_no_chapter_takes_a_subcommands_name(tmp_path):
    from vibration.book.publishing import report
    from vibration.book.publishing.template import new_chapter

    for ch in report.discover():
        assert not any(ch.matches(name) for name in report.SUBCOMMANDS), ch.name
    with pytest.raises(ParameterError, match="topic = 'sweep' is the runner's subcommand"):
        new_chapter("13_sweep", tmp_path)


@pytest.mark.slow
def test_the_same_grid_twice_on_one_client_is_not_reported_as_a_rerun(capsys):
    """Starts are counted per submission: a second sweep of the same points is not a worker lost."""
    from vibration.book.publishing.engine import cluster

    grid = {"F0_ueda": "4,10", "c_ueda": "0.05"}
    with cluster(2) as client:
        first = sw.sweep("09", grid, params={"n_lyapunov": 100}, client=client)
        second = sw.sweep("09", grid, params={"n_lyapunov": 100}, client=client)
        assert client.restarts.drain() == []
        assert client.restarts.count("point (1, 0)") == 2  # both submissions started, once each
    np.testing.assert_array_equal(first["lyapunov"].values, second["lyapunov"].values)
    assert "[rerun]" not in capsys.readouterr().err


def test_a_grid_below_zero_reaches_the_grid_parser(tmp_path, capsys):
    """``-g c_nominal -1:x:3`` is a value, not an option: the grid parser refuses it naming the parameter and form."""
    from vibration.book.publishing.sweep import main

    status = main(["04_frequency_response", "-g", "c_nominal", "-1:x:3", "--out", str(tmp_path), "--no-progress"])
    err = capsys.readouterr().err
    assert status == 2 and "expected 2 arguments" not in err
    assert "c_nominal grid '-1:x:3'" in err and "allowed" in err, err


def test_a_list_parameter_is_refused_as_an_axis_and_taken_as_a_fixed_value():
    with pytest.raises(ParameterError, match=r"parameter 'dampings' is a list and cannot be swept"):
        sw.make_grid("04_frequency_response", {"dampings": "1:2:3"})
    grid = sw.make_grid("04_frequency_response", {"omega_res": "4:5:2"}, params={"dampings": "[0.3, 1]"})
    assert grid.fixed["dampings"] == (0.3, 1.0)
    with pytest.raises(ParameterError, match=r"dampings\[1\] = 0.3 N s/m repeats dampings\[0\]"):
        sw.make_grid("04_frequency_response", {"omega_res": "4:5:2"}, params={"dampings": "[0.3, 0.3]"})
