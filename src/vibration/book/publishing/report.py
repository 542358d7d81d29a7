"""Run the report's chapters with papermill and build them into a book (HTML and PDF).

Usage::

    python -m vibration.report [CHAPTER ...] [-p NAME VALUE ...] [--out DIR] [--jobs N | --scheduler ADDRESS]
    python -m vibration.report sweep CHAPTER -g NAME START:STOP:N ... --out DIR   # see publishing/sweep.py
    python -m vibration.report --list
    python -m vibration.report --in-place      # re-execute notebooks/ (nbval references)

Chapters are the notebooks in ``notebooks/`` (``01_reproduction`` may be given
as ``01``, ``1`` or ``reproduction``). ``-p NAME VALUE`` applies to every
selected chapter that declares NAME; unknown names, values of the wrong type
and values out of range are refused before any kernel starts. Output goes to
``DIR/report`` (HTML, ``index.html``), ``DIR/tables`` (CSV) and
``DIR/notebooks`` (executed copies); it is built in a temporary folder and
moved into place only when every chapter succeeded.

The chapters and their parameters are :mod:`~vibration.book.publishing.notebooks`, their execution
:mod:`~vibration.book.publishing.execution`; this module runs them (with the cache) and builds the book.
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import sys
import tempfile
import time
from pathlib import Path

from ...physics.model import ParameterError
from .book import build as build_book
from .cache import ChapterCache, manifest
from .cli import SUBCOMMANDS, protect_negative_values, terminate
from .engine import cluster
from .execution import (
    CELL_TIMEOUT_S,
    KERNEL,
    KERNEL_ARGS,
    CellTimeout,
    ChapterTask,
    execute_in_place,
    execute_notebooks,
    kernel_name,
    run_chapter,
)
from .notebooks import Chapter, chapter_parameters, check_parameters, discover, select
from .pages import ChapterPage
from .registry import chapter_schemas as chapter_schemas  # importable from here, as before
from .registry import project_root, read_contents
from .template import new_chapter

__all__ = [
    "CELL_TIMEOUT_S",
    "KERNEL",
    "KERNEL_ARGS",
    "CellTimeout",
    "Chapter",
    "ChapterTask",
    "book_from_sources",
    "chapter_parameters",
    "check_parameters",
    "discover",
    "execute_in_place",
    "execute_notebooks",
    "kernel_name",
    "main",
    "run",
    "run_chapter",
    "select",
]


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def run(
    chapters: list[Chapter],
    values: dict,
    out: Path,
    *,
    jobs: int = 2,
    log=print,
    pdf: bool = True,
    cell_timeout: float = CELL_TIMEOUT_S,
    cache: bool = True,
    scheduler: str | None = None,
) -> list[dict]:
    """Execute ``chapters`` with papermill and build the book into ``out`` (replaced only on success).

    A chapter whose notebook, parameter values, imported modules, data and environment are those of a
    cached run (``out/cache``) is not executed again; the runner says which chapters ran and why.
    The others run as tasks on a Dask cluster (:mod:`~vibration.book.publishing.engine`): a local one of
    ``jobs`` workers, or the one at ``scheduler``; the longest (by their last recorded time) first.
    """
    import logging

    out = out.resolve()  # kernels run in notebooks/: every path they get must be absolute
    out.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=".report-", dir=out))
    for name in ("papermill", "traitlets", "nbclient", "sphinx"):
        logging.getLogger(name).setLevel(logging.ERROR)
    store = ChapterCache(out / "cache")
    try:
        for sub in ("notebooks", "report", "tables", "tables-of"):
            (work / sub).mkdir()
        total = len(chapters)
        t0 = time.perf_counter()
        results, manifests, todo = _plan(chapters, values, store, cache, log)
        book_key = _book_digest(chapters, manifests, values, pdf)
        if not todo and cache and store.book_matches(book_key) and _tree_complete(out, pdf):
            log(
                f"report: nothing changed ({_plural(total, 'chapter')} and the book as built), checked in "
                f"{time.perf_counter() - t0:.1f} s -> {out / 'report' / 'index.html'}"
            )
            return _cached_summary(chapters, results)
        store.forget_book()  # the tree is about to change: no record may describe it until it is complete
        for name in list(results):  # the cached chapters enter the new tree
            store.restore(name, work / "notebooks" / f"{name}.ipynb", work / "tables")
            results[name]["executed"] = work / "notebooks" / f"{name}.ipynb"
        if todo:
            _execute_all(todo, work, store, manifests, results, total, jobs, scheduler, cell_timeout, log)
        t_run = time.perf_counter() - t0
        pages = _build_into_place(chapters, values, results, work, out, pdf=pdf, cache=cache, log=log)
        store.remember_book(book_key)
        ran = len(todo)
        log(
            f"report: {_plural(ran, 'chapter')} executed and {total - ran} reused from the cache in {t_run:.1f} s, "
            f"{time.perf_counter() - t0:.1f} s in all -> {out / 'report' / 'index.html'}"
        )
        return [{"name": p.name, "title": p.title, "elapsed_s": p.elapsed_s} for p in pages]
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _cached_summary(chapters: list[Chapter], results: dict) -> list[dict]:
    """What :func:`run` returns when nothing changed: each chapter's name, title and time, from the cache."""
    import nbformat

    return [
        {"name": ch.name,
         "title": ChapterPage(name=ch.name, notebook=nbformat.read(results[ch.name]["executed"],
                              as_version=4), parameters=[]).title,
         "elapsed_s": results[ch.name]["elapsed_s"]}
        for ch in chapters
    ]  # fmt: skip


def _build_into_place(chapters, values, results, work: Path, out: Path, *, pdf, cache, log) -> list[ChapterPage]:
    """Build the book of the executed notebooks in ``work``, then move the finished tree into ``out``; the pages."""
    import nbformat

    contents = _contents(chapters)
    pages = [
        ChapterPage(
            name=ch.name,
            notebook=nbformat.read(results[ch.name]["executed"], as_version=4),
            parameters=chapter_parameters(ch, values),
            elapsed_s=results[ch.name]["elapsed_s"],
            part=_part(contents, ch),
        )
        for ch in chapters
    ]
    t1 = time.perf_counter()
    state = out / "book-state" if cache else None  # Sphinx's folder, kept: only changed pages are rebuilt
    info = build_book(pages, work / "report", work / "book", pdf=pdf, state=state, title=contents.title)
    shutil.rmtree(work / "book", ignore_errors=True)
    log(f"book: built in {time.perf_counter() - t1:.1f} s{_build_summary(info)}")
    _move_into_place(work, out)
    return pages


def _plan(chapters: list[Chapter], values: dict, store: ChapterCache, cache: bool, log):
    """Which chapters the cache holds and which run again: ``(results, manifests, todo)``, the cached chapters'
    executed notebooks and times, every chapter's manifest, and ``(chapter, parameters, why, last seconds)`` of
    each chapter to run."""
    import grimp

    graph = grimp.build_graph("vibration", cache_dir=None)
    results, manifests, todo = {}, {}, []
    for ch in chapters:
        params = {k: v for k, v in values.items() if k in ch.params}
        manifests[ch.name] = _manifest(ch, params, graph)
        found = store.lookup(ch.name, manifests[ch.name]) if cache else None
        if found is not None and found.hit:
            results[ch.name] = {"executed": store.notebook(ch.name), "elapsed_s": found.elapsed_s}
            log(f"[cached] {ch.name}: nothing it depends on changed")
        else:
            why = _why(found.reasons) if found is not None else "the cache is off"
            todo.append((ch, params, why, store.last_elapsed(ch.name)))
    return results, manifests, todo


def _build_summary(info: dict) -> str:
    """What the book's build did, for the runner's log (leading comma): the pages changed, the PDF's pages.

    >>> _build_summary({"changed": ["04_x.ipynb", "_static/a.css"], "pdf_pages": 3})
    ', 1 page changed (04_x.ipynb) (and 1 static file), PDF 3 pages (no page changed: not reprinted)'
    """
    pdf_text = f", PDF {_plural(info['pdf_pages'], 'page')}" if "pdf_pages" in info else ""
    if "pdf_pages" in info and "pdf_s" not in info:
        pdf_text += " (no page changed: not reprinted)"
    pages_text = ""
    if "changed" in info:
        names = [n for n in info["changed"] if not n.startswith("_static/")]  # pages, not their downloads
        shown = f" ({', '.join(names)})" if 0 < len(names) <= 4 else ""
        pages_text = f", {_plural(len(names), 'page')} changed{shown}"
        if len(info["changed"]) > len(names):
            pages_text += f" (and {_plural(len(info['changed']) - len(names), 'static file')})"
    return pages_text + pdf_text


def _move_into_place(work: Path, out: Path) -> None:
    """The finished notebooks, book and tables of ``work`` replace those of ``out`` (the old ones stay in ``work``)."""
    for sub in ("notebooks", "report", "tables"):
        target = out / sub
        if target.exists():
            target.rename(work / f"old-{sub}")
        (work / sub).rename(target)


def _execute_all(todo, work, store, manifests, results, total, jobs, scheduler, cell_timeout, log) -> None:
    """Run the chapters of ``todo`` as tasks, longest first; store each as it finishes (the client writes all)."""
    from distributed import wait

    # longest first by the last run's time; chapters never timed after those, the later chapters first (Parts II
    # and III hold the long studies), so a cold build does not end with its longest chapters on one worker
    rank_of = {item[0].name: i for i, item in enumerate(todo)}
    order = sorted(todo, key=lambda item: (item[3] is None, -(item[3] or 0.0), -rank_of[item[0].name]))
    with cluster(jobs, scheduler, log=log) as client:
        pending = {}
        for rank, (ch, params, why, _) in enumerate(order):
            task = ChapterTask(name=ch.name, source=str(ch.path.resolve()), notebook=ch.path.read_bytes(),
                               params=params, cell_timeout=cell_timeout)  # fmt: skip
            future = client.submit(run_chapter, task, key=f"chapter-{ch.name}-{os.getpid()}-{time.time_ns()}",
                                   pure=False, priority=len(order) - rank)  # fmt: skip
            pending[future] = ch
            log(f"[start] {ch.name}: {why}")
        while pending:
            try:
                done, _ = wait(list(pending), timeout=0.5, return_when="FIRST_COMPLETED")
            except TimeoutError:
                done = ()
            for line in client.restarts.drain():
                log(line)
            for future in done:
                ch = pending.pop(future)
                exc = future.exception()
                if exc is not None:  # a chapter failed: report it, keep the old tree (leaving the block stops the rest)
                    raise RuntimeError(f"chapter {ch.name} failed: {_short(exc)}") from exc
                res = future.result()
                executed, tables = work / "notebooks" / ch.path.name, work / "tables-of" / ch.name
                tables.mkdir()
                executed.write_bytes(res["notebook"])
                for name, data in res["tables"].items():
                    (tables / name).write_bytes(data)
                    (work / "tables" / name).write_bytes(data)
                store.store(ch.name, manifests[ch.name], executed, tables=tables, elapsed_s=res["elapsed_s"])
                results[ch.name] = {"executed": executed, "elapsed_s": res["elapsed_s"]}
                log(f"[{len(results)}/{total}] {ch.name} done in {res['elapsed_s']:.1f} s")


def _book_digest(chapters: list[Chapter], manifests: dict, values: dict, pdf: bool) -> str:
    """What the book depends on beyond the chapters' manifests: the publishing and presentation code, the pdf
    switch and the run's values (SHA-256)."""
    import hashlib
    import json

    import vibration

    h = hashlib.sha256()
    h.update(json.dumps({"pdf": pdf, "values": values, "chapters": [ch.name for ch in chapters],
                         "manifests": manifests}, sort_keys=True, default=repr).encode())  # fmt: skip
    package = Path(vibration.__file__).resolve().parent
    for folder in (package / "book" / "publishing", package / "book" / "presentation"):
        for path in sorted(folder.rglob("*")):
            if path.is_file() and "__pycache__" not in path.parts:
                h.update(str(path.relative_to(package)).encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


def _tree_complete(out: Path, pdf: bool) -> bool:
    """Whether ``out`` holds a finished tree (the book, its PDF when asked, the notebooks and tables)."""
    report_dir = out / "report"
    return (
        (report_dir / "index.html").is_file()
        and (not pdf or (report_dir / "report.pdf").is_file())
        and (out / "notebooks").is_dir()
        and (out / "tables").is_dir()
    )


def _manifest(ch: Chapter, params: dict, graph) -> dict[str, str]:

    return manifest(ch.path, params, ch.path.parent.parent, graph=graph)


def _why(reasons: tuple[str, ...]) -> str:
    """The first reasons a chapter runs again, e.g. "src/vibration/book/chapters/tmd/study.py changed"."""
    shown = ", ".join(reasons[:3])
    return shown + (f" and {len(reasons) - 3} more" if len(reasons) > 3 else "")


def _contents(chapters: list[Chapter]):
    """The table of contents of the project the chapters come from."""
    return read_contents(chapters[0].path.parent.parent) if chapters else read_contents()


def _part(contents, ch: Chapter) -> str:
    """The heading of the part ``ch`` belongs to ("" for the front page)."""
    part = contents.part_of(ch.name)
    return part.title if part else ""


def book_from_sources(chapters: list[Chapter], out: Path, pdf: bool = True) -> dict:
    """Build the book from the committed notebooks as they are (their stored outputs), no kernel.

    For checking the publishing stack quickly (tests, previews); ``make report`` executes.
    """
    import nbformat

    out = Path(out).resolve()
    out.parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=".book-", dir=out.parent))
    try:
        contents = _contents(chapters)
        pages = [
            ChapterPage(
                name=ch.name,
                notebook=nbformat.read(ch.path, as_version=4),
                parameters=chapter_parameters(ch, {}),
                part=_part(contents, ch),
            )
            for ch in chapters
        ]
        return build_book(pages, out, work, pdf=pdf, title=contents.title)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _short(exc: Exception) -> str:
    """``Name: message`` of the error a chapter raised (papermill keeps both)."""
    name, value = getattr(exc, "ename", None), getattr(exc, "evalue", None)
    if name:
        return f"{name}: {value}"
    lines = [ln for ln in str(exc).splitlines() if ln.strip()]
    return lines[-1].strip() if lines else type(exc).__name__


def _subcommand(name: str, argv: list[str]) -> int:
    import importlib

    module, _, function = SUBCOMMANDS[name].partition(":")
    return getattr(importlib.import_module(module), function)(argv)


def _argument_parser() -> argparse.ArgumentParser:
    """The runner's options (the subcommands have their own)."""
    parser = argparse.ArgumentParser(prog="python -m vibration.report", description=__doc__.split("\n\n")[0])
    parser.add_argument("chapters", nargs="*", help="chapters to run (default: all)")
    parser.add_argument(
        "-p",
        "--parameter",
        nargs=2,
        action="append",
        default=[],
        metavar=("NAME", "VALUE"),
        help="set a parameter in every chapter that declares it",
    )
    parser.add_argument("--out", default="build", help="output folder (default: build)")
    parser.add_argument(
        "--jobs", type=int, default=2, help="worker processes of the local Dask cluster, chapters at once (default: 2)"
    )
    parser.add_argument(
        "--scheduler", metavar="ADDRESS", help="run the chapters on this Dask scheduler (tcp://host:8786) instead"
    )
    parser.add_argument("--no-pdf", action="store_true", help="skip the PDF (faster previews)")
    parser.add_argument(
        "--no-cache", action="store_true", help="execute every chapter, even those whose inputs did not change"
    )
    parser.add_argument("--list", action="store_true", help="list chapters and their parameters")
    parser.add_argument(
        "--new-chapter", metavar="NN_topic", help="write a new chapter from the template (package, notebook, test)"
    )
    parser.add_argument(
        "--part", type=int, default=2, help="with --new-chapter: the part of the contents it joins (default: 2)"
    )
    parser.add_argument("--in-place", action="store_true", help="re-execute notebooks/ in place (no parameters)")
    parser.add_argument(
        "--check-lab", metavar="DIR", help="validate a lab data folder (runs.csv, logger files) and exit"
    )
    return parser


def _list_chapters(chapters: list[Chapter]) -> None:
    """Print each chapter's name and its parameters (type, default, help)."""
    for ch in chapters:
        print(ch.name)
        for name, info in ch.params.items():
            print(f"  {name}: {info['inferred_type_name']} = {info['default']}  # {info['help']}")


def _run_command(args: argparse.Namespace) -> int:
    """Do what the parsed options ask: check lab data, write a new chapter, list, re-execute in place, or run."""
    if args.check_lab:
        from ...physics.lab.manifest import check_lab_data

        print(check_lab_data(args.check_lab).summary())
        return 0
    if args.new_chapter:
        for path in new_chapter(args.new_chapter, project_root(), part=args.part):
            print(f"wrote {path.relative_to(project_root())}")
        return 0
    chapters = select(discover(), args.chapters)
    if args.list:
        _list_chapters(chapters)
        return 0
    if args.in_place:
        if args.parameter:
            raise ParameterError("--in-place re-executes the references with their defaults: -p is not allowed")
        execute_in_place(chapters)
        return 0
    values = check_parameters(chapters, [tuple(p) for p in args.parameter])
    run(
        chapters,
        values,
        Path(args.out).resolve(),
        jobs=args.jobs,
        pdf=not args.no_pdf,
        cache=not args.no_cache,
        scheduler=args.scheduler,
    )
    return 0


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv and argv[0] in SUBCOMMANDS:  # every subcommand is dispatched here
        return _subcommand(argv[0], argv[1:])
    args = _argument_parser().parse_args(protect_negative_values(argv))
    previous = signal.signal(signal.SIGTERM, terminate)
    try:
        return _run_command(args)
    except ParameterError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except RuntimeError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("interrupted: the previous output was left as it was", file=sys.stderr)
        return 130
    finally:
        signal.signal(signal.SIGTERM, previous)


if __name__ == "__main__":
    sys.exit(main())
