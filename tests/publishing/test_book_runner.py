"""The runner's book: a run with changed parameters carries its banner on every page; one chapter alone."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from conftest import SCREENSHOTS, open_offline

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.browser
@pytest.mark.slow
def test_runner_banner_with_changed_parameter(browser, tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "vibration.report", "00", "01", "08", "-p", "c_low", "0.05", "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=ROOT,
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    log = proc.stdout + proc.stderr
    assert "Kernel is running over TCP" not in log and "[IPKernelApp]" not in log, log[-1500:]
    assert "3 chapters" in log and "book: built in" in log
    for name in ("index.html", "01_reproduction.html"):
        page, outside, errors = open_offline(browser, tmp_path / "report" / name, viewport=(1280, 900))
        banner = page.locator(".vib-banner")
        assert banner.count() == 1, name
        text = banner.inner_text()
        assert "c_low" in text and "0.05 N s/m" in text and "0.1 N s/m" in text, text
        assert outside == [] and errors == []
        if name == "01_reproduction.html":
            page.screenshot(path=str(Path(SCREENSHOTS) / "book-banner.png"))
        page.close()
    # chapter 8 does not declare c_low: its banner says the run changed it but this page does not use it
    page, _, errors = open_offline(browser, tmp_path / "report" / "08_tmd.html", viewport=(1280, 900))
    text = page.locator(".vib-banner").inner_text()
    assert "not used on this page" in text and "c_low" in text and "0.05 N s/m" in text, text
    assert "Not the paper's parameters" not in text and errors == []
    page.close()
    assert (tmp_path / "report" / "report.pdf").is_file()


@pytest.mark.slow
@pytest.mark.notebooks
def test_runner_says_one_chapter(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "vibration.report", "02", "--out", str(tmp_path), "--no-pdf"],
        capture_output=True,
        text=True,
        timeout=300,
        cwd=ROOT,
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "1 chapter " in proc.stdout and "1 chapters" not in proc.stdout, proc.stdout
