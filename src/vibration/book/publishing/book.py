"""The report as a book: Sphinx + myst-nb + sphinx-book-theme over the executed notebooks.

Execution stays with papermill (``nb_execution_mode = "off"``); this module only prepares
copies of the executed notebooks and builds them:

* the front page is chapter ``00`` (its executed notebook becomes ``index``) followed by
  the parts and chapters, one plain sentence each;
* the ``parameters`` cell (and papermill's injected cell) become a table of name, value,
  unit and meaning; every other code cell is folded behind a toggle (``hide-input``)
  unless tagged ``show-input``;
* a run whose parameters differ from the defaults gets a banner on every page listing each
  changed parameter with the paper's (or the chapter's default) value beside it;
* live widget views give way to the HTML the same output carries (the kernel-free
  panels); no widget manager or require.js is loaded;
* equations are MathML (:mod:`vibration.book.publishing.sphinx_ext`), search is Sphinx's own;
* a figure shows as its PNG on the screen's pages and, where the executed copy carries one (the runner's
  copies do: :data:`vibration.book.presentation.captions.FORMATS_ENV`), as its SVG in the PDF, vector with
  selectable text; a book from the committed notebooks (:func:`~vibration.book.publishing.report.book_from_sources`)
  prints their PNGs;
* one PDF of the whole book, printed by Chromium from Sphinx's single-page build.

The pages are :mod:`~vibration.book.publishing.pages`, their edits :mod:`~vibration.book.publishing.page_edits`, the
front page's generated parts :mod:`~vibration.book.publishing.front_page` and the Sphinx source tree
:mod:`~vibration.book.publishing.sphinx_source`; this module builds the book from them (HTML, PDF, incremental).
"""

from __future__ import annotations

import html
import io
import json
import re
import shutil
import time
import warnings as _py_warnings
from pathlib import Path

import nbformat

from .front_page import KEY_RESULTS, contents_markdown, findings_markdown, key_results
from .mathml import external_urls
from .page_edits import DETAILS, WIDGET_VIEW, banner_html, fold_details, parameters_table, prepare, run_changes
from .pages import ChapterPage, Parameter, differs, parts, split_help, summary
from .print_edition import print_book
from .sphinx_source import BOOK_TITLE, CONF, write_appendices, write_source

__all__ = [
    "BOOK_TITLE",
    "CHROMIUM",
    "CHROMIUM_ARGS",
    "CONF",
    "DETAILS",
    "KEY_RESULTS",
    "WIDGET_VIEW",
    "ChapterPage",
    "Parameter",
    "banner_html",
    "build",
    "build_incremental",
    "contents_markdown",
    "differs",
    "findings_markdown",
    "fold_details",
    "key_results",
    "parameters_table",
    "parts",
    "prepare",
    "print_pdf",
    "run_changes",
    "sphinx_build",
    "split_help",
    "summary",
    "sync_tree",
    "write_appendices",
    "write_source",
]

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def sphinx_build(src: Path, out: Path, builder: str, *, incremental: bool = False) -> None:
    """Run Sphinx in this process: errors raise; its messages go to ``src/sphinx-<builder>.log``.

    ``incremental``: keep the environment in ``src/_build`` and rebuild only the pages whose sources
    changed (a persistent source folder whose unchanged files keep their times: :func:`sync_tree`).
    """
    from sphinx.application import Sphinx
    from sphinx.util.docutils import docutils_namespace

    status, warnings = io.StringIO(), io.StringIO()
    # The theme and myst-nb still use Sphinx APIs deprecated for Sphinx 10/11: their notices are not ours.
    with docutils_namespace(), _py_warnings.catch_warnings():
        _py_warnings.simplefilter("ignore", DeprecationWarning)
        _py_warnings.simplefilter("ignore", PendingDeprecationWarning)
        app = Sphinx(
            str(src),
            str(src),
            str(out),
            str(src / "_build" / f"doctrees-{builder}"),
            builder,
            status=status,
            warning=warnings,
            freshenv=not incremental,
            parallel=1,
        )
        app.build(force_all=not incremental)
    (src / f"sphinx-{builder}.log").write_text(status.getvalue() + warnings.getvalue(), encoding="utf-8")
    if app.statuscode:
        raise RuntimeError(f"Sphinx ({builder}) failed: {warnings.getvalue().strip()[-2000:]}")


def print_pdf(html_path: Path, pdf_path: Path, pages: list[ChapterPage] = (), *, title: str = BOOK_TITLE):
    """The print edition of ``html_path`` in ``pdf_path`` (A4, title page, contents with page numbers,
    bookmarks, page numbers; see :mod:`vibration.book.publishing.print_edition`); returns its :class:`Edition`."""
    from playwright.sync_api import sync_playwright

    if not Path(CHROMIUM).exists():
        raise RuntimeError(f"{CHROMIUM} is missing: the PDF needs Debian's chromium (make browser installs it)")
    # each part starts at its first page's heading, counted among all pages (the front page's comes first)
    starts = [(caption, list(pages).index(members[0])) for caption, members in parts(pages)]
    options = {
        "format": "A4",
        "print_background": True,
        "display_header_footer": True,
        "header_template": (
            f'<div style="font-size:7px;width:100%;text-align:center;color:#666">{html.escape(title)}</div>'
        ),
        "footer_template": '<div style="font-size:8px;width:100%;text-align:center;color:#444">'
        '<span class="pageNumber"></span> / <span class="totalPages"></span></div>',
        "margin": {"top": "16mm", "bottom": "16mm", "left": "14mm", "right": "14mm"},
    }

    def work():
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
            try:
                page = browser.new_page()
                page.route(
                    "**/*", lambda r: r.continue_() if r.request.url.startswith(("file:", "data:")) else r.abort()
                )
                page.goto(html_path.resolve().as_uri())
                page.wait_for_load_state("load")
                page.emulate_media(media="print")
                return print_book(page, pdf_path, title, parts=starts, pdf_options=options)
            finally:
                browser.close()

    # A thread of its own: playwright's sync API refuses a thread whose asyncio loop runs (a notebook's, or a
    # caller's own playwright session).
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(1) as pool:
        return pool.submit(work).result()


def sync_tree(fresh: Path, kept: Path, keep: tuple[str, ...] = ("_build",)) -> list[str]:
    """Make ``kept`` hold what ``fresh`` holds, touching only what differs; returns the changed paths.

    Unchanged files keep their modification times, so Sphinx sees only the changed pages as outdated.
    Top-level entries named in ``keep`` (Sphinx's environment) and ``*.log`` files are left alone.
    """
    changed = []
    kept.mkdir(parents=True, exist_ok=True)
    wanted = {p.relative_to(fresh) for p in fresh.rglob("*") if p.is_file()}
    for rel in sorted(wanted):
        src, dst = fresh / rel, kept / rel
        if dst.is_file() and dst.read_bytes() == src.read_bytes():
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(src, dst)
        changed.append(str(rel))
    for path in sorted(kept.rglob("*"), reverse=True):
        rel = path.relative_to(kept)
        if rel.parts[0] in keep or path.suffix == ".log":
            continue
        if path.is_file() and rel not in wanted:
            path.unlink()
            changed.append(f"{rel} (removed)")
        elif path.is_dir() and not any(path.iterdir()):
            path.rmdir()
    return changed


def _stable_cell_ids(src: Path) -> None:
    """Number the cells of every notebook in ``src`` (``cell-0``, ...): nbformat gives each new cell a random id,
    which would make an unchanged page look changed to :func:`sync_tree`."""
    for path in src.glob("*.ipynb"):
        nb = nbformat.read(path, as_version=4)
        for i, cell in enumerate(nb.cells):
            cell["id"] = f"cell-{i}"
        nbformat.write(nb, path)


def build_incremental(
    pages: list[ChapterPage], out: Path, work: Path, *, state: Path, pdf: bool = True, title: str = BOOK_TITLE
) -> dict:
    """:func:`build` with a persistent Sphinx folder ``state``: only changed pages are rebuilt, the PDF is
    reprinted only when a page changed, and ``out`` receives a finished copy (the caller swaps it into place).

    A failure removes ``state``, so the next build starts cold rather than from a half-updated folder.
    """
    t0 = time.perf_counter()
    try:
        write_source(pages, work / "book-src", title=title)
        _stable_cell_ids(work / "book-src")
        src = state / "book-src"
        changed = sync_tree(work / "book-src", src)
        html = state / "html"
        if changed or not (html / "index.html").is_file():
            sphinx_build(src, html, "html", incremental=True)
            _check_offline(html)
        shutil.copytree(html, out, ignore=shutil.ignore_patterns(".doctrees", ".buildinfo"), dirs_exist_ok=True)
        info = {"html_s": time.perf_counter() - t0, "changed": changed}
        if pdf:
            t1 = time.perf_counter()
            printed, record = state / "report.pdf", state / "report-pdf.json"
            if changed or not (printed.is_file() and record.is_file()):
                record.unlink(missing_ok=True)
                sphinx_build(src, state / "single", "singlehtml", incremental=True)
                edition = print_pdf(state / "single" / "index.html", state / "report.part.pdf", pages, title=title)
                (state / "report.part.pdf").replace(printed)
                record.write_text(json.dumps({"pages": edition.page_count}), encoding="utf-8")
                info["pdf_s"] = time.perf_counter() - t1
            info["pdf_pages"] = json.loads(record.read_text(encoding="utf-8"))["pages"]
            shutil.copy2(printed, out / "report.pdf")
        return info
    except BaseException:
        shutil.rmtree(state, ignore_errors=True)
        raise


def build(
    pages: list[ChapterPage],
    out: Path,
    work: Path,
    *,
    pdf: bool = True,
    state: Path | None = None,
    title: str = BOOK_TITLE,
) -> dict:
    """Build the HTML book into ``out`` (``out/index.html``) and ``out/report.pdf``.

    ``work`` holds the Sphinx sources and the single-page build used for the PDF; with ``state``, a
    persistent Sphinx folder, only what changed is rebuilt (:func:`build_incremental`).
    Returns timings and the PDF's page count.
    """
    if state is not None:
        return build_incremental(pages, out, work, state=state, pdf=pdf, title=title)
    t0 = time.perf_counter()
    src = work / "book-src"
    write_source(pages, src, title=title)
    sphinx_build(src, out, "html")
    _check_offline(out)
    info = {"html_s": time.perf_counter() - t0}
    if pdf:
        t1 = time.perf_counter()
        single = work / "book-single"
        sphinx_build(src, single, "singlehtml")
        edition = print_pdf(single / "index.html", out / "report.pdf", pages, title=title)
        info["pdf_pages"] = edition.page_count
        info["pdf_s"] = time.perf_counter() - t1
    shutil.rmtree(out / ".doctrees", ignore_errors=True)
    shutil.rmtree(out.parent / "jupyter_execute", ignore_errors=True)  # myst-nb's scratch folder
    (out / ".buildinfo").unlink(missing_ok=True)
    return info


def _check_offline(out: Path) -> None:
    """Refuse a build whose pages would load anything from outside the build folder."""

    bad = {}
    for page in out.glob("*.html"):
        text = page.read_text(encoding="utf-8")
        loads = [u for u in external_urls(_loading_tags(text))]
        if loads:
            bad[page.name] = loads[:3]
    if bad:
        raise RuntimeError(f"pages would load from the network: {bad}")


_LOADING = re.compile(r"<(script|link|img|iframe|source|video|audio)\b[^>]*>", re.I)


def _loading_tags(text: str) -> str:
    """Only the tags that load something (links to other sites are fine to show)."""
    return "".join(m.group(0) for m in _LOADING.finditer(text) if 'rel="canonical"' not in m.group(0))
