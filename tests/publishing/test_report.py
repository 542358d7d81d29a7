"""The report runner: parameter checks before any kernel, chapter selection, output tree."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest

import vibration
from vibration.book.publishing import engine, report
from vibration.book.publishing.registry import add_chapter
from vibration.physics.model import ParameterError

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def chapters():
    return report.discover()


@pytest.fixture
def no_kernel(monkeypatch):
    import papermill

    def boom(*args, **kwargs):
        raise AssertionError("a kernel was started")

    monkeypatch.setattr(papermill, "execute_notebook", boom)
    monkeypatch.setattr(engine, "cluster", boom)  # chapters run as tasks on a Dask cluster


def test_selects_chapters_by_stem_number_and_name(chapters):
    assert [c.name for c in report.select(chapters, ["01"])] == ["01_reproduction"]
    assert [c.name for c in report.select(chapters, ["2"])] == ["02_claims_audit"]
    assert [c.name for c in report.select(chapters, ["reproduction", "04_frequency_response"])] == [
        "01_reproduction",
        "04_frequency_response",
    ]
    with pytest.raises(ParameterError, match="chapter 'nope' does not exist"):
        report.select(chapters, ["nope"])


def test_physical_parameters_are_declared_by_every_chapter_that_uses_them(chapters):
    for ch in [c for c in chapters if c.name[:2] in ("01", "02", "03", "04", "05")]:  # Part I: the paper's window
        for name in ("m", "k", "F0", "t_end"):
            assert name in ch.params, f"{ch.name} does not declare {name}"


@pytest.mark.parametrize(
    ("name", "value", "pattern"),
    [
        ("mass", "1", r"parameter 'mass' \(value '1'\) is not declared"),
        ("F0", "abc", r"F0 = 'abc' is not a number"),
        ("F0", "nan", r"F0 = 'nan' is not finite"),
        ("m", "0", r"m = 0.0 kg is out of range: allowed m >= 0.001 kg, m <= 1000 kg"),
        ("m", "1e-300", r"m = 1e-300 kg is out of range"),
        ("k", "1e300", r"k = 1e\+300 N/m is out of range"),
        ("k", "1e6", r"t_end = 50.0 s holds \d+ periods .* allowed at most 1000"),
        ("k", "-20", r"k = -20.0 N/m is out of range"),
        ("c_low", "-2e4", r"c_low = -20000.0 N s/m is out of range: allowed c_low >= -10000 N s/m"),
        ("c_low", "-3", r"c_low = -3.0 N s/m .* grows the response like exp\(75\): allowed \(-c/2m\) t_end at most 50"),
        ("n_points", "2.5", r"n_points = '2.5' is not an integer"),
        ("n_points", "1", r"n_points = 1 is out of range: allowed integer 2 <= n_points <= 200001"),
        ("t_end", "1e9", r"t_end = 1000000000.0 s is out of range"),
        ("c_min", "30", r"c_max = 20.0 N s/m must exceed c_min = 30.0 N s/m"),
        ("c_sa_min", "20", r"c_sa_max = 15.0 N s/m must exceed c_sa_min = 20.0 N s/m"),
        ("c_semi_min", "20", r"c_semi_max = 15.0 N s/m must exceed c_semi_min = 20.0 N s/m"),
        ("omega_sweep_min", "7", r"omega_sweep_max = 6.5 rad/s must exceed omega_sweep_min = 7.0 rad/s"),
        ("f_max", "30", r"f_max = 30.0 Hz is not below the Nyquist frequency 1/\(2 dt\) = 25 Hz of dt = 0.02 s"),
        ("dt", "0.5", r"f_max = 2.0 Hz is not below the Nyquist frequency 1/\(2 dt\) = 1 Hz of dt = 0.5 s"),
        ("t_record", "0.001", r"t_record = 0.001 s holds 0.05 samples of dt = 0.02 s: allowed at least 200"),
        ("n_sweep", "5", r"n_sweep = 5 is out of range: allowed integer 10 <= n_sweep <= 400"),
        ("pid_ki", "1e5", r"t_end = 50.0 s spans .* time scales of the PID loop"),
        ("dampings", "0.5", r"dampings = '0.5' is not a list: allowed a JSON list"),
        ("dampings", "[0.1, oops]", r"dampings = '\[0.1, oops\]' is not a list"),
        ("dampings", "[0.1, 0.1]", r"dampings\[1\] = 0.1 N s/m repeats dampings\[0\]: allowed distinct values"),
        ("dampings", "[0.1, 2e4]", r"dampings\[1\] = 20000.0 N s/m is out of range: allowed dampings\[1\] >= -10000"),
        ("dampings", "[1, 2, 3, 4, 5, 6, 7]", r"dampings holds 7 values: allowed 1 to 6"),
        ("dampings", '[0.5, "x"]', r"dampings\[1\] = 'x' is not a real number"),
        ("dampings", "[-3]", r"dampings\[0\] = -3.0 N s/m .* grows the response like exp\(75\)"),
    ],
)
def test_bad_parameters_are_refused_before_any_kernel(chapters, no_kernel, name, value, pattern, capsys):
    with pytest.raises(ParameterError, match=pattern):
        report.check_parameters(chapters, [(name, value)])
    assert report.main(["-p", name, value, "--out", "unused"]) == 2
    err = capsys.readouterr().err
    assert name in err and "error:" in err


def test_a_chapter_package_declares_its_notebooks_parameters_once(chapters):
    """The notebook's parameters cell holds exactly its schema's names, at the schema's defaults."""
    import ast

    schemas = report.chapter_schemas()
    by_name = {ch.name: ch for ch in chapters}
    for notebook, schema in schemas.items():
        params = by_name[notebook].params
        assert set(params) == {p.name for p in schema.params}, notebook
        for p in schema.params:
            default = list(p.default) if isinstance(p.default, tuple) else p.default  # a list parameter
            assert ast.literal_eval(params[p.name]["default"]) == default, (notebook, p.name)


def test_a_parameter_without_its_value_is_refused(chapters, no_kernel, capsys):
    with pytest.raises(SystemExit) as info:
        report.main(["-p", "m", "--no-pdf"])
    assert info.value.code == 2
    assert "expected 2 arguments" in capsys.readouterr().err


def test_combinations_the_papers_solver_could_not_finish_are_refused(chapters, no_kernel):
    with pytest.raises(ParameterError, match=r"\(c/m\) t_end = 5e\+07 is out of range: allowed at most 1e\+06"):
        report.check_parameters(chapters, [("c_high", "1e4"), ("m", "0.01")])
    with pytest.raises(ParameterError, match=r"holds 1592 periods"):
        report.check_parameters(chapters, [("omega_ref", "200")])
    assert report.check_parameters(chapters, [("c_high", "1e4")]) == {"c_high": 1e4}


def test_zero_and_negative_damping_are_accepted(chapters, no_kernel):
    assert report.check_parameters(chapters, [("c_low", "0")]) == {"c_low": 0.0}
    assert report.check_parameters(chapters, [("c_low", "-0.5")]) == {"c_low": -0.5}  # grows like exp(12.5)


def test_good_parameters_are_typed(chapters):
    got = report.check_parameters(chapters, [("F0", "10"), ("n_points", "2001")])
    assert got == {"F0": 10.0, "n_points": 2001}
    assert isinstance(got["n_points"], int)
    # a list parameter arrives as a list of floats (papermill writes it as a list literal)
    got = report.check_parameters(chapters, [("dampings", "[0.1, 0.5, 2, 15]")])
    assert got == {"dampings": [0.1, 0.5, 2.0, 15.0]} and all(isinstance(x, float) for x in got["dampings"])


def _read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@pytest.mark.slow
@pytest.mark.notebooks
def test_rerun_with_another_force_matches_exact_values_and_is_byte_identical(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a relative --out, as `make report` passes it
    out = tmp_path / "out"
    assert report.main(["01", "02", "-p", "F0", "10", "--out", "out", "--no-pdf"]) == 0
    assert {"claims.csv", "claims_summary.csv", "findings.csv"} <= {p.name for p in (out / "tables").iterdir()}
    rows = {r["claim_id"]: r for r in _read_csv(out / "tables" / "claims.csv")}
    sc = vibration.load_scenarios()
    ref = sc["reference"]
    doubled = vibration.steady_state(ref.oscillator, vibration.SineForce(F0=10.0, omega=ref.force.omega)).amplitude
    assert float(rows["C07"]["exact_value"]) == pytest.approx(doubled, rel=1e-9)
    assert float(rows["C07"]["exact_value"]) == pytest.approx(
        2 * vibration.steady_state(ref.oscillator, ref.force).amplitude, rel=1e-9
    )
    assert rows["C07"]["verdict"] == "number differs"  # 0.9 m is not "about 0.5 m"
    assert (out / "report" / "index.html").is_file()
    assert (out / "report" / "02_claims_audit.html").is_file()
    first = {p.name: p.read_bytes() for p in (out / "tables").iterdir()}
    assert report.main(["01", "02", "-p", "F0", "10", "--out", "out", "--no-pdf"]) == 0
    assert {p.name: p.read_bytes() for p in (out / "tables").iterdir()} == first
    assert not list(out.glob(".report-*")), "temporary folders left behind"


@pytest.mark.slow
@pytest.mark.notebooks
def test_failed_chapter_leaves_previous_tree_untouched(tmp_path, monkeypatch):
    root = tmp_path / "proj"
    (root / "notebooks").mkdir(parents=True)
    nb = json.loads((ROOT / "notebooks" / "02_claims_audit.ipynb").read_text(encoding="utf-8"))
    bad = {
        "cell_type": "code",
        "id": "broken-on-purpose",
        "execution_count": None,
        "metadata": {},
        "outputs": [],
        "source": "raise RuntimeError('chapter broke on purpose')",
    }
    nb["cells"].insert(3, bad)
    (root / "notebooks" / "02_claims_audit.ipynb").write_text(json.dumps(nb), encoding="utf-8")
    add_chapter("02_claims_audit", root, 1)
    out = tmp_path / "out"
    (out / "report").mkdir(parents=True)
    (out / "report" / "index.html").write_text("previous", encoding="utf-8")
    monkeypatch.setenv("VIBRATION_ROOT", str(root))
    assert report.main(["--out", str(out), "--no-pdf"]) == 1
    assert (out / "report" / "index.html").read_text(encoding="utf-8") == "previous"
    assert not list(out.glob(".report-*"))
    shutil.rmtree(root)


def test_every_notebook_declares_its_schema(chapters):
    """Each chapter's parameters cell names the schema's parameters, in its order, at its defaults and types."""
    import ast

    schemas = report.chapter_schemas()
    assert {ch.name for ch in chapters} <= set(schemas), "a chapter without a parameter schema"
    for ch in chapters:
        schema = schemas[ch.name]
        assert tuple(ch.params) == schema.names(), ch.name
        for name, info in ch.params.items():
            param = schema[name]
            default = ast.literal_eval(info["default"])
            if isinstance(param.default, tuple):  # a list parameter: the record holds it as a tuple
                default = tuple(default)
            assert default == param.default and type(default) is type(param.default), (ch.name, name)
        values = report.check_parameters([ch], [(n, info["default"]) for n, info in ch.params.items()])
        assert set(values) == set(ch.params)


def test_a_shared_parameter_is_declared_once():
    """Chapters that use m, k, F0, ... take the shared declaration: one range, one unit, one symbol."""
    import dataclasses

    from vibration.book.presentation.parameters import SHARED

    for schema in report.chapter_schemas().values():
        for param in schema.params:
            if param.name in SHARED:
                ours = dataclasses.replace(
                    param, meaning=SHARED[param.name].meaning, default=SHARED[param.name].default
                )
                assert ours == SHARED[param.name], (schema.notebook, param.name)


@pytest.mark.slow
@pytest.mark.notebooks
def test_sigterm_stops_the_running_chapters_at_once(tmp_path):
    """The runner ends within seconds of SIGTERM (it used to wait for every queued chapter) and leaves no output."""
    import signal
    import subprocess
    import sys
    import time

    out = tmp_path / "out"
    proc = subprocess.Popen(
        [sys.executable, "-m", "vibration.report", "07", "10", "11", "--out", str(out), "--no-pdf"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    time.sleep(8.0)  # both workers are inside a chapter (07 and 10 take 20 s each)
    proc.send_signal(signal.SIGTERM)
    start = time.perf_counter()
    _, err = proc.communicate(timeout=60)
    assert time.perf_counter() - start < 15.0
    assert proc.returncode == 130
    assert "interrupted: the previous output was left as it was" in err
    assert not (out / "report").exists() and not list(out.glob(".report-*"))


def _stuck_project(root: Path, seconds: float = 600.0) -> Path:
    """A throw-away project whose one chapter spins in compiled code (no Python bytecode to interrupt)."""
    import nbformat

    (root / "notebooks").mkdir(parents=True)
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    params = nbformat.v4.new_code_cell(f"seconds: float = {seconds}  # how long to spin, s")
    params.metadata["tags"] = ["parameters"]
    spin = (
        "from numba import njit\n\n\n@njit\ndef spin(n):\n    s = 0.0\n    for i in range(n):\n"
        "        s += (i % 7) * 1e-9\n    return s\n\n\nspin(int(seconds * 3e8))\n"
    )
    nb.cells = [params, nbformat.v4.new_code_cell(spin)]
    nbformat.write(nb, root / "notebooks" / "01_spin.ipynb")
    add_chapter("01_spin", root, 1)  # its table of contents: one part
    return root


@pytest.mark.slow
@pytest.mark.notebooks
def test_a_cell_over_the_limit_fails_its_chapter_naming_the_cell(tmp_path):
    """The cell limit is a last resort: the run fails at once, naming the chapter and the cell (no second run)."""
    root = _stuck_project(tmp_path / "project")
    chapters = report.discover(root)
    with pytest.raises(RuntimeError, match=r'chapter 01_spin failed: .*the cell starting "from numba import njit" '
                       r"ran longer than the runner's limit of 4 s"):  # fmt: skip
        report.run(chapters, {}, tmp_path / "out", jobs=1, log=lambda *_: None, pdf=False, cell_timeout=4)
    assert not (tmp_path / "out" / "report").exists()


@pytest.mark.slow
@pytest.mark.notebooks
def test_sigterm_stops_a_chapter_stuck_in_compiled_code_and_its_kernel(tmp_path):
    """One SIGTERM stops the runner, its pool and the kernel spinning in numba code, within seconds."""
    import os
    import signal
    import subprocess
    import sys
    import time

    import psutil

    root = _stuck_project(tmp_path / "project")
    proc = subprocess.Popen(
        [sys.executable, "-m", "vibration.report", "--out", str(tmp_path / "out"), "--no-pdf"],
        env={**os.environ, "VIBRATION_ROOT": str(root)},
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    deadline = time.monotonic() + 60
    kernels: list = []
    while not kernels and time.monotonic() < deadline:
        time.sleep(0.5)
        family = psutil.Process(proc.pid).children(recursive=True)
        kernels = [p for p in family if "ipykernel" in " ".join(p.cmdline())]
    assert kernels, "the chapter's kernel never started"
    time.sleep(3.0)  # the kernel is inside the compiled loop now
    family = psutil.Process(proc.pid).children(recursive=True)
    proc.send_signal(signal.SIGTERM)
    start = time.perf_counter()
    _, err = proc.communicate(timeout=30)
    assert time.perf_counter() - start < 10.0
    assert proc.returncode == 130, err
    gone, alive = psutil.wait_procs(family, timeout=10)
    assert not alive, [p.cmdline() for p in alive]


def test_a_chapter_without_a_schema_runs_but_takes_no_p_value(tmp_path):
    """A drafted notebook with no package runs at its own values; -p on its parameters is refused, naming it."""
    root = _stuck_project(tmp_path / "project")
    chapters = report.discover(root)
    assert report.check_parameters(chapters, []) == {}
    with pytest.raises(report.ParameterError, match="01_spin has no parameter schema"):
        report.check_parameters(chapters, [("seconds", "1")])


def test_an_empty_list_parameter_is_shown_as_the_values_it_stands_for(chapters):
    ch1 = next(ch for ch in chapters if ch.name == "01_reproduction")

    def dampings(values):
        return next(p for p in report.chapter_parameters(ch1, values) if p.name == "dampings")

    assert dampings({}).value == [0.1, 0.5, 15.0] and not dampings({}).changed
    moved = dampings({"c_low": 0.05})
    assert moved.value == [0.05, 0.5, 15.0] and not moved.changed  # c_low is the changed parameter
    given = dampings({"dampings": [1.0, 2.0]})
    assert given.value == [1.0, 2.0] and given.changed
