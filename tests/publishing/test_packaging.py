"""An installed wheel carries the data, the panels and the usage examples, and finds its data without the checkout."""

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from vibration.book.publishing.sheets import build_wheel

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_an_installed_wheel_reads_its_own_data(tmp_path):
    wheel = build_wheel(tmp_path)  # from a copy of the sources, as the book's download is
    names = set(zipfile.ZipFile(wheel).namelist())
    for data in (ROOT / "data").rglob("*"):
        if data.is_file():
            assert f"vibration/_data/{data.relative_to(ROOT / 'data').as_posix()}" in names, data.name
    assert any(n.startswith("vibration/book/chapters/real_oscillator/panel/") for n in names)
    for params in (ROOT / "src" / "vibration" / "book" / "chapters").glob(
        "*/params.py"
    ):  # each declares its data there
        assert f"vibration/book/chapters/{params.parent.name}/params.toml" in names, params.parent.name
    for data in (ROOT / "src" / "vibration").rglob("*.toml"):  # exercise sheets, designs: whatever a chapter reads
        assert data.relative_to(ROOT / "src").as_posix() in names, data.name
    target = tmp_path / "site"
    zipfile.ZipFile(wheel).extractall(target)  # what pip installs, without touching the environment
    code = (
        "import vibration.physics.paper as p; d = p.data_dir(); assert 'site' in str(d), d; print(len(p.load_claims()))"
        "; import vibration.book.chapters.tmd.params as t; assert 'site' in t.__file__ and t.Params().mu == 0.05"
        "; import vibration.book.chapters.tmd.designs as g; assert len(g.TUNINGS) == 6, g.TUNINGS"
    )
    env = {k: v for k, v in os.environ.items() if k != "VIBRATION_DATA"} | {"PYTHONPATH": str(target)}
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr[-2000:]


@pytest.mark.slow
@pytest.mark.timeout(1800)
def test_the_wheel_installs_with_its_dependencies_in_a_fresh_venv_and_imports_every_public_name(tmp_path):
    """pip installs the wheel and its declared dependencies (every extra) at the pinned versions, nothing else."""
    wheel = build_wheel(tmp_path)  # from a copy of the sources, as the book's download is
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=300)
    py = venv / "bin" / "python"
    done = subprocess.run(
        [str(py), "-m", "pip", "install", "-q", f"{wheel}[all]", "-c", str(ROOT / "environment.txt")],
        capture_output=True,
        text=True,
        timeout=1500,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    code = (
        "import vibration, vibration.learn; missing = [n for n in vibration.__all__ if getattr(vibration, n, None) "
        "is None]; assert not missing, missing; "
        "import gymnasium; assert 'vibration/Oscillator-v0' in gymnasium.registry; "
        "from importlib.metadata import entry_points; "
        "assert [e.value for e in entry_points(group='gymnasium.envs') if e.name == 'vibration'] == "
        "['vibration.physics.learning.env:register']; print(len(vibration.__all__))"
    )
    env = {k: v for k, v in os.environ.items() if k not in ("VIBRATION_DATA", "PYTHONPATH")}
    ran = subprocess.run([str(py), "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600)
    assert ran.returncode == 0, ran.stderr[-3000:]
    import vibration

    assert int(ran.stdout) == len(vibration.__all__)
