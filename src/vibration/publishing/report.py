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
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from ..physics.model import ParameterError
from ..presentation.tables import TABLES_ENV
from .book import ChapterPage, Parameter, differs, split_help
from .book import build as build_book
from .cache import ChapterCache, manifest
from .cli import SUBCOMMANDS, convert, protect_negative_values, terminate
from .engine import announce, cluster
from .registry import chapter_schemas, project_root, read_contents
from .template import new_chapter

KERNEL = "vibration"


@dataclass(frozen=True, kw_only=True)
class Chapter:
    """One notebook of the report."""

    path: Path  # source notebook
    params: dict  # papermill's inspection: name -> {inferred_type_name, default, help}

    @property
    def name(self) -> str:
        """File stem, e.g. ``01_reproduction``."""
        return self.path.stem

    def matches(self, key: str) -> bool:
        """Whether ``key`` names this chapter (stem, number or stem without number)."""
        num, _, rest = self.name.partition("_")
        return key in (self.name, rest) or (key.isdigit() and num.isdigit() and int(key) == int(num))


def discover(root: Path | None = None) -> list[Chapter]:
    """All chapters in ``notebooks/``, in the order of the table of contents (``notebooks/contents.toml``)."""
    import papermill

    root = root or project_root()
    paths = [root / "notebooks" / f"{stem}.ipynb" for stem in read_contents(root).order]
    return [Chapter(path=p, params=papermill.inspect_notebook(str(p))) for p in paths]


def select(chapters: list[Chapter], keys: list[str]) -> list[Chapter]:
    """The chapters named by ``keys`` (all when empty), in report order."""
    if not keys:
        return chapters
    chosen = []
    for key in keys:
        hits = [c for c in chapters if c.matches(key)]
        if not hits:
            names = ", ".join(c.name for c in chapters)
            raise ParameterError(f"chapter {key!r} does not exist: allowed {names}")
        chosen += [c for c in hits if c not in chosen]
    return [c for c in chapters if c in chosen]


def check_parameters(chapters: list[Chapter], pairs: list[tuple[str, str]]) -> dict[str, object]:
    """Validate ``-p NAME VALUE`` pairs against the schemas of the chapters that declare them.

    Each chapter's schema (its package's ``params.SCHEMA``) is the one source of a parameter's type
    and range and of the rules that tie several together; a value shared by several chapters must
    suit each of them. Returns the typed values. Raises :class:`ParameterError` naming the
    parameter, its value and what is allowed.
    """
    schemas = chapter_schemas()
    asked = {name for name, _ in pairs}
    missing = [ch.name for ch in chapters if ch.name not in schemas and asked & set(ch.params)]
    if missing:  # a chapter without a schema runs at its notebook's own values, but takes no -p value
        raise ParameterError(
            f"chapter {missing[0]} has no parameter schema, so -p cannot set its parameters: allowed chapters with a "
            f"package vibration.chapters.<topic> holding params.SCHEMA (python -m vibration.report --new-chapter "
            f"writes one)"
        )
    declared: dict[str, str] = {}
    for ch in chapters:
        for name, info in ch.params.items():
            declared.setdefault(name, info.get("inferred_type_name") or "str")
    values: dict[str, object] = {}
    for name, text in pairs:
        if name not in declared:
            allowed = ", ".join(sorted(declared))
            raise ParameterError(
                f"parameter {name!r} (value {text!r}) is not declared by any chapter run: allowed {allowed}"
            )
        value = convert(name, text, declared[name])
        for ch in chapters:
            if name in ch.params and ch.name in schemas:
                value = schemas[ch.name][name].check(value)  # each chapter's own range
        values[name] = value
    for ch in chapters:  # the chapter's rules that tie several of its parameters together
        if ch.name in schemas:
            schemas[ch.name].check({k: v for k, v in values.items() if k in ch.params})
    return values


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


class CellTimeout(RuntimeError):
    """A chapter's cell ran longer than :data:`CELL_TIMEOUT_S`."""


@dataclass(frozen=True, kw_only=True)
class ChapterTask:
    """One chapter's execution, as a task for the engine: everything a worker needs, by value."""

    name: str  # notebook stem
    source: str  # the notebook's path on the client (used as is when the worker sees the same file)
    notebook: bytes  # its content (a worker on another machine runs this copy)
    params: dict
    cell_timeout: float = CELL_TIMEOUT_S
    tables: bool = True  # collect the tables the notebook writes
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
        start = time.perf_counter()
        try:
            papermill.execute_notebook(
                str(source),
                str(output),
                parameters=dict(task.params),
                kernel_name=task.kernel or kernel_name(),
                cwd=str(source.parent),
                progress_bar=False,
                log_output=False,
                execution_timeout=task.cell_timeout,
                extra_arguments=KERNEL_ARGS,
            )
        except TimeoutError as exc:
            raise CellTimeout(
                f"{_cell_preview(str(exc))} ran longer than the runner's limit of {task.cell_timeout:g} s"
            ) from None
        finally:
            os.environ.pop(TABLES_ENV, None)
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
    runs: list[tuple[Path, Path, dict]], jobs: int = 2, kernel: str | None = None, scheduler: str | None = None
) -> list[float]:
    """Execute ``(source, output, parameters)`` runs with papermill, ``jobs`` at a time; seconds each, in order.

    ``kernel`` names the kernel (default: the project's when the worker has it); ``scheduler`` an existing cluster.
    """

    with cluster(jobs, scheduler) as client:
        tasks = [
            ChapterTask(name=f"{Path(src).stem}#{i}", source=str(Path(src).resolve()), notebook=Path(src).read_bytes(),
                        params=dict(params), tables=False, kernel=kernel)
            for i, (src, _, params) in enumerate(runs)
        ]  # fmt: skip
        futures = [client.submit(run_chapter, task, key=f"chapter-{task.name}", pure=False) for task in tasks]
        results = client.gather(futures)
    for (_, out, _), res in zip(runs, results, strict=True):
        Path(out).write_bytes(res["notebook"])
    return [res["elapsed_s"] for res in results]


def chapter_parameters(ch: Chapter, values: dict) -> list:
    """The chapter's declared parameters with the values this run used (for the book)."""
    import ast

    from ..physics.paper import paper_defaults

    paper = paper_defaults()
    schema = chapter_schemas().get(ch.name)
    out = []
    for name, info in ch.params.items():
        try:
            default = ast.literal_eval(info.get("default", ""))
        except (ValueError, SyntaxError):
            default = info.get("default")
        meaning, unit = split_help(info.get("help", ""))
        symbol = ""
        if schema is not None and name in schema.names():  # the schema is the source; the cell's comment a fallback
            param = schema[name]
            meaning, unit, symbol = param.meaning or meaning, param.unit, param.symbol
        is_paper = name in paper and not differs(default, paper[name])
        out.append(
            Parameter(
                name=name,
                value=values.get(name, default),
                default=default,
                meaning=meaning,
                unit=unit,
                paper=is_paper,
                symbol=symbol,
            )
        )
    return out


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def run(
    chapters: list[Chapter],
    values: dict,
    out: Path,
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
    The others run as tasks on a Dask cluster (:mod:`~vibration.publishing.engine`): a local one of
    ``jobs`` workers, or the one at ``scheduler``; the longest (by their last recorded time) first.
    """
    import logging

    import grimp
    import nbformat

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
        book_key = _book_digest(chapters, manifests, values, pdf)
        if not todo and cache and store.book_matches(book_key) and _tree_complete(out, pdf):
            log(
                f"report: nothing changed ({_plural(total, 'chapter')} and the book as built), checked in "
                f"{time.perf_counter() - t0:.1f} s -> {out / 'report' / 'index.html'}"
            )
            return [
                {"name": ch.name, "title": ChapterPage(ch.name, nbformat.read(results[ch.name]["executed"],
                 as_version=4), []).title, "elapsed_s": results[ch.name]["elapsed_s"]}
                for ch in chapters
            ]  # fmt: skip
        store.forget_book()  # the tree is about to change: no record may describe it until it is complete
        for name in list(results):  # the cached chapters enter the new tree
            store.restore(name, work / "notebooks" / f"{name}.ipynb", work / "tables")
            results[name]["executed"] = work / "notebooks" / f"{name}.ipynb"
        if todo:
            _execute_all(todo, work, store, manifests, results, total, jobs, scheduler, cell_timeout, log)
        t_run = time.perf_counter() - t0
        contents = _contents(chapters)
        pages = [
            ChapterPage(
                ch.name,
                nbformat.read(results[ch.name]["executed"], as_version=4),
                chapter_parameters(ch, values),
                results[ch.name]["elapsed_s"],
                part=_part(contents, ch),
            )
            for ch in chapters
        ]
        t1 = time.perf_counter()
        state = out / "book-state" if cache else None  # Sphinx's folder, kept: only changed pages are rebuilt
        info = build_book(pages, work / "report", work / "book", pdf=pdf, state=state, title=contents.title)
        shutil.rmtree(work / "book", ignore_errors=True)
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
        log(f"book: built in {time.perf_counter() - t1:.1f} s{pages_text}{pdf_text}")
        for sub in ("notebooks", "report", "tables"):
            target = out / sub
            if target.exists():
                target.rename(work / f"old-{sub}")
            (work / sub).rename(target)
        store.remember_book(book_key)
        ran = len(todo)
        log(
            f"report: {_plural(ran, 'chapter')} executed and {total - ran} reused from the cache in {t_run:.1f} s, "
            f"{time.perf_counter() - t0:.1f} s in all -> {out / 'report' / 'index.html'}"
        )
        return [{"name": p.name, "title": p.title, "elapsed_s": p.elapsed_s} for p in pages]
    finally:
        shutil.rmtree(work, ignore_errors=True)


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
                store.store(ch.name, manifests[ch.name], executed, tables, res["elapsed_s"])
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
    for folder in (package / "publishing", package / "presentation"):
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

    return manifest(ch.path, params, ch.path.parent.parent, graph)


def _why(reasons: tuple[str, ...]) -> str:
    """The first reasons a chapter runs again, e.g. "src/vibration/chapters/tmd/study.py changed"."""
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
                ch.name, nbformat.read(ch.path, as_version=4), chapter_parameters(ch, {}), part=_part(contents, ch)
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


def execute_in_place(chapters: list[Chapter], log=print) -> None:
    """Re-execute the source notebooks and store their outputs (the nbval references).

    Uses nbclient directly, so no papermill timestamps enter the committed files.
    """
    import nbformat
    from nbclient import NotebookClient

    kernel = kernel_name()
    for ch in chapters:
        start = time.perf_counter()
        nb = nbformat.read(ch.path, as_version=4)
        NotebookClient(
            nb,
            kernel_name=kernel,
            timeout=CELL_TIMEOUT_S,
            extra_arguments=KERNEL_ARGS,
            record_timing=False,
            resources={"metadata": {"path": str(ch.path.parent)}},
        ).execute()
        nb.metadata.pop("widgets", None)
        for cell in nb.cells:
            cell.metadata.pop("execution", None)
        nbformat.write(nb, ch.path)
        log(f"{ch.name} re-executed in {time.perf_counter() - start:.1f} s")


def _subcommand(name: str, argv: list[str]) -> int:
    import importlib

    module, _, function = SUBCOMMANDS[name].partition(":")
    return getattr(importlib.import_module(module), function)(argv)


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv and argv[0] in SUBCOMMANDS:  # every subcommand is dispatched here
        return _subcommand(argv[0], argv[1:])
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
    args = parser.parse_args(protect_negative_values(argv))
    previous = signal.signal(signal.SIGTERM, terminate)
    try:
        if args.check_lab:
            from ..physics.lab.manifest import check_lab_data

            print(check_lab_data(args.check_lab).summary())
            return 0
        if args.new_chapter:
            for path in new_chapter(args.new_chapter, project_root(), part=args.part):
                print(f"wrote {path.relative_to(project_root())}")
            return 0
        chapters = select(discover(), args.chapters)
        if args.list:
            for ch in chapters:
                print(ch.name)
                for name, info in ch.params.items():
                    print(f"  {name}: {info['inferred_type_name']} = {info['default']}  # {info['help']}")
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
    return 0


if __name__ == "__main__":
    sys.exit(main())
