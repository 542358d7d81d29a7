"""The runner's engine on an existing Dask cluster: a scheduler and two workers on 127.0.0.1, one killed mid-run."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

BIN = Path(sys.executable).parent


@pytest.fixture
def dask_cluster(tmp_path):
    """``dask scheduler`` and two single-threaded ``dask worker`` processes, each in its own process group."""
    info = tmp_path / "scheduler.json"
    procs = []

    def start(*args):
        proc = subprocess.Popen([str(BIN / "dask"), *args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)  # fmt: skip
        procs.append(proc)
        return proc

    start("scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard", "--scheduler-file", str(info))
    deadline = time.monotonic() + 60
    while not info.is_file() and time.monotonic() < deadline:
        time.sleep(0.2)
    assert info.is_file(), "the scheduler never wrote its address"
    time.sleep(0.5)
    address = json.loads(info.read_text())["address"]
    workers = [
        start(
            "worker",
            "--scheduler-file",
            str(info),
            "--nthreads",
            "1",
            "--nworkers",
            "1",
            "--no-dashboard",
            "--host",
            "127.0.0.1",
            "--name",
            f"w{i}",
        )  # fmt: skip
        for i in range(2)
    ]
    from distributed import Client

    with Client(address, timeout=30) as client:
        client.wait_for_workers(2, timeout=60)
    yield address, workers
    for proc in procs:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGTERM)
    for proc in procs:
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)


def _kill_when(proc_out: Path, ready, worker) -> None:
    deadline = time.monotonic() + 180
    while not ready() and time.monotonic() < deadline:
        time.sleep(0.2)
    os.killpg(worker.pid, signal.SIGKILL)  # the worker and its nanny, at once


def _runs_a_kernel(pid: int) -> bool:
    import psutil

    try:
        return any("ipykernel" in " ".join(p.cmdline()) for p in psutil.Process(pid).children(recursive=True))
    except psutil.Error:
        return False


@pytest.mark.slow
@pytest.mark.notebooks
def test_a_sweep_and_a_two_chapter_report_survive_a_killed_worker_on_an_existing_cluster(dask_cluster, tmp_path):
    address, workers = dask_cluster
    # the sweep: 16 points, a worker killed once some are stored
    out = tmp_path / "sweep"
    cmd = [sys.executable, "-m", "vibration.report", "sweep", "09", "-g", "F0_ueda", "3:11:16", "-p", "n_lyapunov",
           "400", "--scheduler", address, "--out", str(out), "--no-progress"]  # fmt: skip
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    points = out / "points.jsonl"
    _kill_when(out, lambda: points.is_file() and len(points.read_text().splitlines()) >= 3, workers[0])
    stdout, stderr = proc.communicate(timeout=600)
    assert proc.returncode == 0, stderr
    assert "16 points (0 failed)" in stdout
    import numpy as np
    import xarray as xr

    ds = xr.open_dataset(out / "sweep.nc", engine="h5netcdf")
    assert np.isfinite(ds["lyapunov"].values).all() and (ds["error"].values == "").all()
    from vibration.book.chapters.duffing.study import chaos_study

    assert float(ds["lyapunov"].values[5]) == chaos_study(F0_ueda=float(ds["F0_ueda"].values[5]),
                                                          n_lyapunov=400).pooled.mean  # fmt: skip

    # the report: two chapters on the one worker left and a new one; the new one killed inside a chapter
    fresh = subprocess.Popen([str(BIN / "dask"), "worker", address, "--nthreads", "1", "--nworkers", "1",
                              "--no-dashboard", "--host", "127.0.0.1", "--name", "w2"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)  # fmt: skip
    try:
        from distributed import Client

        with Client(address, timeout=30) as client:
            client.wait_for_workers(2, timeout=60)
        report_out = tmp_path / "report"
        proc = subprocess.Popen(
            [sys.executable, "-m", "vibration.report", "00", "05", "--scheduler", address, "--out", str(report_out),
             "--no-pdf"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )  # fmt: skip
        _kill_when(report_out, lambda: _runs_a_kernel(fresh.pid), fresh)  # inside a chapter: its kernel runs
        stdout, stderr = proc.communicate(timeout=900)
        assert proc.returncode == 0, stdout + stderr
        assert "[rerun]" in stdout and "the worker running it was lost" in stdout
        for name in ("00_overview", "05_explore"):
            assert f"{name} done in" in stdout
            assert (report_out / "notebooks" / f"{name}.ipynb").is_file()
        assert (report_out / "report" / "index.html").is_file()
    finally:
        if fresh.poll() is None:
            os.killpg(fresh.pid, signal.SIGKILL)
