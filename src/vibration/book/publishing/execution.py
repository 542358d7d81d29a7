"""Executing the chapters: one notebook with papermill as a task on a worker (:func:`run_chapter`), a list of
runs on a cluster (:func:`execute_notebooks`), and the source notebooks in place, the nbval references
(:func:`execute_in_place`)."""

from __future__ import annotations

import os
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from ..presentation.captions import FORMATS_ENV
from ..presentation.tables import TABLES_ENV
from .crossrefs import number_references
from .engine import announce, cluster
from .sphinx_ext import chapter_number

if TYPE_CHECKING:
    from .notebooks import Chapter

__all__ = [
    "CELL_TIMEOUT_S",
    "KERNEL",
    "KERNEL_ARGS",
    "KERNEL_START_ATTEMPTS",
    "CellTimeout",
    "ChapterTask",
    "execute_in_place",
    "execute_notebooks",
    "kernel_name",
    "run_chapter",
    "with_kernel_restarts",
]

KERNEL = "vibration"


def kernel_name() -> str:
    """The project's kernel if installed (``make setup`` installs it), else ``python3``."""
    from jupyter_client.kernelspec import KernelSpecManager

    return KERNEL if KERNEL in KernelSpecManager().find_kernel_specs() else "python3"


#: Kernel arguments: the runner's output carries no kernel log lines, such as the warning
#: that the kernel talks over TCP on the loopback interface, or the "KeyboardInterrupt caught"
#: an idle kernel logs at ERROR when its client interrupts it before every shutdown. A cell's
#: error still reaches the runner through papermill.
KERNEL_ARGS = ["--IPKernelApp.log_level=CRITICAL"]
#: Longest a single cell may run, s: a last resort that a run within the parameters' ranges never meets
#: (the longest cell of the default run takes about 10 s). A cell that exceeds it fails its chapter,
#: naming the chapter and the cell; a kernel message that never arrives becomes this failure, not a hang.
CELL_TIMEOUT_S = 180


#: Times a chapter's kernel may be started before its run fails. A kernel started beside others can die
#: before its first reply when another process takes one of the ports it was given (the ports are chosen,
#: freed, then bound by the kernel: jupyter_client's known race); no cell has run then, so starting again
#: is safe.
KERNEL_START_ATTEMPTS = 3
_KERNEL_START_FAILED = "Kernel died before replying to kernel_info"


class CellTimeout(RuntimeError):
    """A chapter's cell ran longer than :data:`CELL_TIMEOUT_S`."""


def with_kernel_restarts(execute, *, attempts: int = KERNEL_START_ATTEMPTS, log=None):
    """Call ``execute()``, again when its kernel died before its first reply, at most ``attempts`` times.

    Any other error, and the last start failure, propagates unchanged.

    >>> calls = []
    >>> def flaky():
    ...     calls.append(1)
    ...     if len(calls) < 2:
    ...         raise RuntimeError("Kernel died before replying to kernel_info")
    ...     return "ran"
    >>> with_kernel_restarts(flaky), len(calls)
    ('ran', 2)
    """
    if attempts < 1:
        raise ValueError(f"attempts = {attempts!r}: at least 1")
    for attempt in range(1, attempts + 1):
        try:
            return execute()
        except RuntimeError as exc:
            if _KERNEL_START_FAILED not in str(exc) or attempt == attempts:
                raise
            if log is not None:
                log(f"kernel died at start (attempt {attempt} of {attempts}); starting it again")
    raise AssertionError("unreachable")  # pragma: no cover


@dataclass(frozen=True, kw_only=True)
class ChapterTask:
    """One chapter's execution, as a task for the engine: everything a worker needs, by value."""

    name: str  # notebook stem
    source: str  # the notebook's path on the client (used as is when the worker sees the same file)
    notebook: bytes  # its content (a worker on another machine runs this copy)
    params: dict
    cell_timeout: float = CELL_TIMEOUT_S
    tables: bool = True  # collect the tables the notebook writes
    vector_figures: bool = True  # figures also as SVG, for the print edition (captions.FORMATS_ENV)
    kernel: str | None = None  # the kernel to start; None: the project's when the worker has it, else python3


def run_chapter(task: ChapterTask) -> dict:
    """Execute one notebook with papermill on a worker; returns the executed notebook, its tables and seconds.

    Runs on a single-threaded Dask worker (papermill's ``cwd`` changes the working directory of the
    whole process). The executed copy and the tables stay in a temporary folder of the worker and
    come back by value: only the client writes the output folder.
    """
    import hashlib
    import logging

    import papermill

    announce(task.name)
    for name in ("papermill", "traitlets", "nbclient"):
        logging.getLogger(name).setLevel(logging.ERROR)
    with tempfile.TemporaryDirectory(prefix="vibration-chapter-") as tmp:
        tmp = Path(tmp)
        source = Path(task.source)
        if not (source.is_file() and hashlib.sha256(source.read_bytes()).digest()
                == hashlib.sha256(task.notebook).digest()):  # fmt: skip
            source = tmp / "source" / Path(task.source).name  # another machine: the shipped copy
            source.parent.mkdir()
            source.write_bytes(task.notebook)
        output, tables = tmp / "executed.ipynb", tmp / "tables"
        tables.mkdir()
        if task.tables:
            os.environ[TABLES_ENV] = str(tables)
        else:
            os.environ.pop(TABLES_ENV, None)
        if task.vector_figures:  # the kernel inherits the worker's environment
            os.environ[FORMATS_ENV] = "svg"
        else:
            os.environ.pop(FORMATS_ENV, None)
        start = time.perf_counter()
        try:
            with_kernel_restarts(lambda: papermill.execute_notebook(
                str(source),
                str(output),
                parameters=dict(task.params),
                kernel_name=task.kernel or kernel_name(),
                cwd=str(source.parent),
                progress_bar=False,
                log_output=False,
                execution_timeout=task.cell_timeout,
                extra_arguments=KERNEL_ARGS,
            ))  # fmt: skip
        except TimeoutError as exc:
            raise CellTimeout(
                f"{_cell_preview(str(exc))} ran longer than the runner's limit of {task.cell_timeout:g} s"
            ) from None
        finally:
            os.environ.pop(TABLES_ENV, None)
            os.environ.pop(FORMATS_ENV, None)
        elapsed = time.perf_counter() - start
        return {
            "notebook": output.read_bytes(),
            "tables": {p.name: p.read_bytes() for p in sorted(tables.iterdir()) if p.is_file()},
            "elapsed_s": elapsed,
        }


def _cell_preview(message: str) -> str:
    """The timed-out cell's first line, from nbclient's message (which quotes the cell between dashed lines,
    a long cell as the list of its first and last lines).

    >>> _cell_preview("A cell timed out.\\n-------------------\\nstudy = run(a)\\nx = 1\\n-------------------\\n")
    'the cell starting "study = run(a)"'
    >>> _cell_preview("A cell timed out.\\n-------------------\\n['import numba', '']\\n...\\n-------------------\\n")
    'the cell starting "import numba"'
    """
    import ast

    parts = message.split("-------------------\n")
    lines = parts[1].strip().splitlines() if len(parts) > 2 else []
    if lines and lines[0].startswith("["):
        try:
            lines = [ln for ln in ast.literal_eval(lines[0]) if ln.strip()]
        except (ValueError, SyntaxError):
            pass
    return f'the cell starting "{lines[0]}"' if lines else "a cell the message does not quote"


def execute_notebooks(
    runs: list[tuple[Path, Path, dict]], jobs: int = 2, kernel: str | None = None, *, scheduler: str | None = None
) -> list[float]:
    """Execute ``(source, output, parameters)`` runs with papermill, ``jobs`` at a time; seconds each, in order.

    ``kernel`` names the kernel (default: the project's when the worker has it); ``scheduler`` an existing cluster.
    """

    with cluster(jobs, scheduler) as client:
        tasks = [
            ChapterTask(name=f"{Path(src).stem}#{i}", source=str(Path(src).resolve()), notebook=Path(src).read_bytes(),
                        params=dict(params), tables=False, vector_figures=False, kernel=kernel)
            for i, (src, _, params) in enumerate(runs)
        ]  # fmt: skip
        futures = [client.submit(run_chapter, task, key=f"chapter-{task.name}", pure=False) for task in tasks]
        results = client.gather(futures)
    for (_, out, _), res in zip(runs, results, strict=True):
        Path(out).write_bytes(res["notebook"])
    return [res["elapsed_s"] for res in results]


def execute_in_place(chapters: list[Chapter], log=print) -> None:
    """Re-execute the source notebooks and store their outputs (the nbval references).

    Uses nbclient directly, so no papermill timestamps enter the committed files. The Markdown cells'
    cross-references get the numbers of the figures and tables they name (:mod:`.crossrefs`).
    """
    import nbformat
    from nbclient import NotebookClient

    from .registry import read_contents

    kernel = kernel_name()
    front = read_contents(chapters[0].path.parent.parent).front if chapters else ""
    for ch in chapters:
        start = time.perf_counter()
        nb = nbformat.read(ch.path, as_version=4)
        client = NotebookClient(
            nb,
            kernel_name=kernel,
            timeout=CELL_TIMEOUT_S,
            extra_arguments=KERNEL_ARGS,
            record_timing=False,
            resources={"metadata": {"path": str(ch.path.parent)}},
        )
        with_kernel_restarts(client.execute)
        nb.metadata.pop("widgets", None)
        for cell in nb.cells:
            cell.metadata.pop("execution", None)
        # the Markdown's cross-references carry the numbers of the figures and tables, for JupyterLab
        number_references(nb, None if ch.name == front else chapter_number(ch.name))
        nbformat.write(nb, ch.path)
        log(f"{ch.name} re-executed in {time.perf_counter() - start:.1f} s")
