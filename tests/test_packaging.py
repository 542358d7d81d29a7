"""An installed wheel carries the data, the panels and the usage examples, and finds its data without the checkout."""

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.slow
def test_an_installed_wheel_reads_its_own_data(tmp_path):
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            str(ROOT),
            "--no-deps",
            "--no-build-isolation",
            "-q",
            "-w",
            str(tmp_path),
        ],
        check=True,
        timeout=300,
    )
    wheel = next(tmp_path.glob("vibration-*.whl"))
    names = set(zipfile.ZipFile(wheel).namelist())
    for data in (ROOT / "data").rglob("*"):
        if data.is_file():
            assert f"vibration/_data/{data.relative_to(ROOT / 'data').as_posix()}" in names, data.name
    assert any(n.startswith("vibration/chapters/real_oscillator/panel/") for n in names)
    target = tmp_path / "site"
    zipfile.ZipFile(wheel).extractall(target)  # what pip installs, without touching the environment
    code = (
        "import vibration.physics.paper as p; d = p.data_dir(); "
        "assert 'site' in str(d), d; print(len(p.load_claims()) if hasattr(p, 'load_claims') else 1)"
    )
    env = {k: v for k, v in os.environ.items() if k != "VIBRATION_DATA"} | {"PYTHONPATH": str(target)}
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr[-2000:]
