"""A new chapter from the template runs through the runner with no central edit (the README's guide)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from vibration.book.publishing.template import new_chapter
from vibration.physics.model import ParameterError


def test_bad_names_and_existing_chapters_are_refused(tmp_path):
    with pytest.raises(ParameterError, match=r"stem = 'Topic' is not a chapter name: allowed NN_topic"):
        new_chapter("Topic", tmp_path)
    new_chapter("13_topic", tmp_path)
    with pytest.raises(ParameterError, match=r"exists already"):
        new_chapter("13_topic", tmp_path)


@pytest.mark.slow
@pytest.mark.notebooks
def test_a_throw_away_chapter_runs_through_the_runner_and_its_own_test(tmp_path):
    root, extra = tmp_path / "project", tmp_path / "extra"
    written = new_chapter("13_throwaway", root, package_dir=extra, prefix="tpl_")
    assert {p.name for p in written} == {
        "__init__.py", "params.py", "study.py", "tables.py", "13_throwaway.ipynb", "test_throwaway.py"
    }  # fmt: skip
    env = {**os.environ, "VIBRATION_ROOT": str(root), "VIBRATION_EXTRA_CHAPTERS": str(extra)}
    # the chapter passes the project's lint as written (its settings; vibration first-party, as under src/)
    config = ["--config", str(Path(__file__).resolve().parents[2] / "pyproject.toml"),
              "--config", "lint.isort.known-first-party = ['vibration']"]  # fmt: skip
    for command in (("check",), ("format", "--check")):
        lint = subprocess.run([sys.executable, "-m", "ruff", *command, *config, *map(str, written)],
                              capture_output=True, text=True, timeout=60)  # fmt: skip
        assert lint.returncode == 0, lint.stdout + lint.stderr

    def runner(*args):
        cmd = [sys.executable, "-m", "vibration.report", *args, "--out", str(tmp_path / "out"), "--no-pdf"]
        return subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=300)

    refused = runner("-p", "tpl_zeta", "0.9")  # the chapter's own schema, before any kernel
    assert refused.returncode == 2 and "tpl_zeta = 0.9 is out of range: allowed tpl_zeta >= 0.001" in refused.stderr

    done = runner("-p", "tpl_zeta", "0.1")
    assert done.returncode == 0, done.stderr[-2000:]
    assert "[start] 13_throwaway" in done.stdout
    page = (tmp_path / "out" / "report" / "13_throwaway.html").read_text(encoding="utf-8")
    words = re.sub(r"<[^>]+>", "", page)  # the glued numbers sit in their own spans
    assert "Throwaway" in words and "At ζ = 0.1 the grid finds a peak magnification of 5.025" in words

    own_test = root / "tests" / "chapters" / "throwaway" / "test_throwaway.py"
    own = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(own_test)],
        env=env, capture_output=True, text=True, timeout=120, cwd=root,
    )  # fmt: skip
    assert own.returncode == 0, own.stdout[-2000:]
