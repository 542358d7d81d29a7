"""A chapter's run starts its kernel again when the kernel died before its first reply, and only then."""

from __future__ import annotations

from pathlib import Path

import papermill
import pytest

from vibration.book.publishing.execution import KERNEL_START_ATTEMPTS, ChapterTask, run_chapter, with_kernel_restarts

START_FAILED = "Kernel died before replying to kernel_info"


def _task(tmp_path: Path) -> ChapterTask:
    source = tmp_path / "01_reproduction.ipynb"
    source.write_text("{}", encoding="utf-8")
    return ChapterTask(name="01_reproduction", source=str(source), notebook=source.read_bytes(), params={},
                       tables=False, vector_figures=False, kernel="python3")  # fmt: skip


def _papermill_failing(monkeypatch, failures: list[Exception]) -> list[str]:
    """papermill.execute_notebook raising ``failures`` in turn, then writing its output; returns the calls."""
    calls = []

    def execute(source, output, **kwargs):
        calls.append(source)
        if len(calls) <= len(failures):
            raise failures[len(calls) - 1]
        Path(output).write_text('{"cells": []}', encoding="utf-8")

    monkeypatch.setattr(papermill, "execute_notebook", execute)
    return calls


def test_a_kernel_that_died_at_start_is_started_again(monkeypatch, tmp_path):
    calls = _papermill_failing(monkeypatch, [RuntimeError(START_FAILED)] * (KERNEL_START_ATTEMPTS - 1))
    result = run_chapter(_task(tmp_path))
    assert len(calls) == KERNEL_START_ATTEMPTS
    assert result["notebook"] == b'{"cells": []}'


def test_the_attempts_are_bounded_and_the_last_failure_propagates(monkeypatch, tmp_path):
    calls = _papermill_failing(monkeypatch, [RuntimeError(START_FAILED)] * (KERNEL_START_ATTEMPTS + 5))
    with pytest.raises(RuntimeError, match=START_FAILED):
        run_chapter(_task(tmp_path))
    assert len(calls) == KERNEL_START_ATTEMPTS


def test_any_other_error_is_not_retried(monkeypatch, tmp_path):
    calls = _papermill_failing(monkeypatch, [RuntimeError("Kernel didn't respond in 60 seconds")])
    with pytest.raises(RuntimeError, match="didn't respond"):
        run_chapter(_task(tmp_path))
    assert len(calls) == 1


def test_attempts_below_one_are_refused():
    with pytest.raises(ValueError, match="attempts = 0"):
        with_kernel_restarts(lambda: None, attempts=0)
