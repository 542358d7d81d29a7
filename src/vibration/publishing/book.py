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
* equations are MathML (:mod:`vibration.publishing.sphinx_ext`), search is Sphinx's own;
* one PDF of the whole book, printed by Chromium from Sphinx's single-page build.
"""

from __future__ import annotations

import copy
import html
import io
import json
import re
import shutil
import time
import warnings as _py_warnings
from dataclasses import dataclass, field
from pathlib import Path

import nbformat

from .appendices import (
    APPENDICES,
    answers_markdown,
    glossary_markdown,
    licences_markdown,
    references_markdown,
    symbols_markdown,
    usage_markdown,
)
from .mathml import external_urls
from .print_edition import print_book
from .registry import chapter_packages, chapter_schemas
from .sheets import chapter_blurb, course_plan_markdown, download_cell, fold_answers, write_downloads

#: The title when a build is given none (the runner passes the table of contents' title).
BOOK_TITLE = "Resonance and damping, reproduced and audited"
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


@dataclass(frozen=True, kw_only=True)
class Parameter:
    """One declared notebook parameter and the value a run used."""

    name: str
    value: object
    default: object
    meaning: str
    unit: str  # "" when dimensionless or a count
    paper: bool  # the default is the paper's value
    symbol: str = ""  # how the book writes it ("ω_res"); the name when empty

    @property
    def symbol_html(self) -> str:
        from ..presentation.tables import symbol_html

        return symbol_html(self.symbol or self.name)

    @property
    def changed(self) -> bool:
        return differs(self.value, self.default)


@dataclass
class ChapterPage:
    """An executed chapter, ready for the book."""

    name: str  # e.g. "06_stability"
    notebook: nbformat.NotebookNode
    parameters: list[Parameter] = field(default_factory=list)
    elapsed_s: float | None = None
    part: str = ""  # the heading of its part in the table of contents; "" for the front page

    @property
    def is_front(self) -> bool:
        return not self.part

    @property
    def number(self) -> int | None:
        m = re.match(r"^(\d+)_", self.name)
        return int(m.group(1)) if m else None

    @property
    def title(self) -> str:
        for cell in self.notebook.cells:
            if cell.cell_type == "markdown" and cell.source.lstrip().startswith("# "):
                return cell.source.lstrip()[2:].splitlines()[0].strip()
        return self.name

    @property
    def summary(self) -> str:
        return summary(self.notebook)


def differs(a, b) -> bool:
    """Whether two parameter values differ (numerically when both are numbers, else as text)."""
    try:
        return float(a) != float(b)
    except (TypeError, ValueError):
        return str(a) != str(b)


def split_help(text: str) -> tuple[str, str]:
    """``"mass, kg"`` -> ``("mass", "kg")``; a trailing unit ``1`` (dimensionless) reads ``""``.

    Examples
    --------
    >>> split_help("mass, kg"), split_help("output samples on [0, t_end], 1"), split_help("a flag")
    (('mass', 'kg'), ('output samples on [0, t_end]', ''), ('a flag', ''))
    """
    text = (text or "").strip()
    if "," in text:
        meaning, unit = text.rsplit(",", 1)
        unit = unit.strip()
        if unit and len(unit) <= 16 and not unit.endswith("."):
            return meaning.strip(), "" if unit in ("1", "-", "count") else unit
    return text, ""


def summary(nb) -> str:
    """First sentence after "Overview." without LaTeX or code in it (the chapter's one-liner).

    Examples
    --------
    >>> nb = nbformat.v4.new_notebook()
    >>> nb.cells = [nbformat.v4.new_markdown_cell("**Overview.** It solves $x$. It maps `c`. Done.")]
    >>> summary(nb)
    'It maps c.'
    """
    for cell in nb.cells:
        if cell.cell_type == "markdown" and "Overview." in cell.source:
            text = cell.source.split("Overview.", 1)[1].replace("**", "").replace("`", "").strip()
            text = re.sub(r"\$\$.*?\$\$", "$", " ".join(text.split()))
            text = re.sub(r"\{[a-z]+\}", "", text)
            sentences = re.split(r"(?<=[.!?])\s", text)
            plain = [x for x in sentences if "$" not in x]
            return plain[0] if plain else sentences[0]
    return ""


# ----------------------------------------------------------------- notebook edits


def _value_text(value) -> str:
    """A parameter value in the book's number format (×10ⁿ, true minus), to 6 significant figures."""
    from ..presentation.tables import fmt

    return fmt(value, 6) if isinstance(value, float) else str(value)


def _unit_text(value, unit: str) -> str:
    return f"{_value_text(value)} {unit}".strip()


def _items(params: list[Parameter]) -> str:
    return "".join(
        f"<li>{p.symbol_html} ({html.escape(p.meaning)}, <code>-p {html.escape(p.name)}</code>) = "
        f"<strong>{html.escape(_unit_text(p.value, p.unit))}</strong>; "
        f"{'the paper' if p.paper else 'default'}: {html.escape(_unit_text(p.default, p.unit))}</li>"
        for p in params
    )


def banner_html(params: list[Parameter], run_changes: list[Parameter] = ()) -> str:
    """The changed-parameters banner of a page (empty when the run changed nothing).

    ``params`` are the page's own parameters; ``run_changes`` every parameter the run changed
    in any chapter. Those this page does not declare are listed as not used here, so every
    page of a changed run says so, and says whether its own numbers moved.
    """
    changed = [p for p in params if p.changed]
    own = {p.name for p in params}
    elsewhere = [p for p in run_changes if p.changed and p.name not in own]
    if not changed and not elsewhere:
        return ""
    parts = ['<div class="vib-banner" role="note">']
    if changed:
        parts.append(
            "<p><strong>Not the paper's parameters.</strong> This page was computed with these values changed:</p>"
            f"<ul>{_items(changed)}</ul>"
        )
    if elsewhere:
        lead = "Also changed in this run" if changed else "<strong>This run changed parameters.</strong> Changed"
        parts.append(
            f"<p>{lead}, but not used on this page (its numbers are those of its own parameters, "
            f"shown below):</p><ul>{_items(elsewhere)}</ul>"
        )
    parts.append("</div>")
    return "".join(parts)


def run_changes(pages: list[ChapterPage]) -> list[Parameter]:
    """Every parameter some chapter of the run changed, once per name, in chapter order."""
    seen: dict[str, Parameter] = {}
    for page in pages:
        for p in page.parameters:
            if p.changed and p.name not in seen:
                seen[p.name] = p
    return list(seen.values())


def parameters_table(params: list[Parameter]) -> str:
    """HTML table of the chapter's parameters: name, value, unit, meaning (changed ones marked)."""
    changed_attr = ' class="vib-changed"'
    rows = "".join(
        f"<tr{changed_attr if p.changed else ''}><td>{p.symbol_html}</td>"
        f"<td>{html.escape(_value_text(p.value))}</td>"
        f"<td>{html.escape(p.unit)}</td><td>{html.escape(p.meaning)}</td><td><code>{html.escape(p.name)}</code></td></tr>"
        for p in params
    )
    return (
        '<div class="vib-parameters"><table><caption>Parameters of this run (the book\'s <a href="symbols.html">'
        "parameters appendix</a> lists them all)</caption><thead><tr><th>symbol</th><th>value</th><th>unit</th>"
        "<th>meaning</th><th>set with <code>-p</code></th></tr></thead>"
        f"<tbody>{rows}</tbody></table></div>"
    )


def _tags(cell) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


def prepare(page: ChapterPage, changes: list[Parameter] = ()) -> nbformat.NotebookNode:
    """A copy of the executed notebook as the book shows it (see the module docstring)."""
    nb = copy.deepcopy(page.notebook)
    nb.metadata.pop("widgets", None)
    nb.metadata.pop("papermill", None)
    cells = []
    params_done = False
    for cell in nb.cells:
        cell.metadata.pop("papermill", None)
        cell.metadata.pop("execution", None)
        tags = _tags(cell)
        if cell.cell_type == "code" and ("parameters" in tags or "injected-parameters" in tags):
            if not params_done and page.parameters and not page.is_front:  # the front page: findings first
                cells.append(nbformat.v4.new_markdown_cell(parameters_table(page.parameters)))
                params_done = True
            continue
        if cell.cell_type == "code":
            _drop_widget_views(cell)
            _caption_from_output(cell)
            if "show-input" not in tags and not {"hide-input", "remove-input", "remove-cell"} & set(tags):
                cell.metadata.setdefault("tags", []).append("hide-input")
        cells.append(cell)
    cells = fold_details(cells)
    banner = banner_html(page.parameters, changes)
    if banner:
        at = 1 if cells and cells[0].cell_type == "markdown" and cells[0].source.lstrip().startswith("# ") else 0
        if at == 1:  # keep the title first, banner right under it
            title, _, rest = cells[0].source.lstrip().partition("\n")
            cells[0] = nbformat.v4.new_markdown_cell(title)
            if rest.strip():
                cells.insert(1, nbformat.v4.new_markdown_cell(rest))
        cells.insert(at, nbformat.v4.new_markdown_cell(banner))
    if page.is_front and page.parameters:
        cells.append(nbformat.v4.new_markdown_cell("## Parameters of this run\n\n" + parameters_table(page.parameters)))
    # The execution time stays in the runner's log and return value, not in the reader's text.
    nb.cells = cells
    return nb


#: The cell tag of what a chapter folds away from its main text (checks, convergence, long comparisons).
DETAILS = "details"
_HEADING = re.compile(r"^(#{1,6})\s+(.+?)\s*$", re.M)


def fold_details(cells: list) -> list:
    """Each run of consecutive cells tagged :data:`DETAILS` folded into one ``<details>`` section: its
    summary is the heading the run opens with ("Details" when it opens with none); headings inside it
    become bold lines, so no section of the page starts inside a fold. The print edition unfolds them.

    >>> md = nbformat.v4.new_markdown_cell
    >>> a, b, c = md("### Convergence\\n\\nText."), md("## More\\nx"), md("after")
    >>> a.metadata["tags"] = b.metadata["tags"] = ["details"]
    >>> [x.source for x in fold_details([a, b, c])]  # doctest: +NORMALIZE_WHITESPACE
    ['<details class="vib-details"><summary>Details: Convergence</summary>', '\\nText.', '**More**\\nx',
     '</details>', 'after']
    """
    out, run = [], []

    def _what(cells) -> str:
        """What a run without a heading holds: ": 1 figure, 2 tables"."""
        figures = tables = 0
        for cell in cells:
            for output in cell.get("outputs", []) if cell.cell_type == "code" else []:
                data = output.get("data", {})
                figures += "image/png" in data
                tables += "<table" in "".join(data.get("text/html", ""))
        parts = [f"{n} {word}{'s' if n > 1 else ''}" for n, word in ((figures, "figure"), (tables, "table")) if n]
        return f": {', '.join(parts)}" if parts else ""

    def flush():
        if not run:
            return
        first = run[0]
        title = "Details" + _what(run)
        if first.cell_type == "markdown":
            head = _HEADING.match(first.source.lstrip())
            if head:
                title = "Details" if head[2] == "Details" else f"Details: {head[2]}"
                first.source = first.source.lstrip()[head.end() :]
        for cell in run:
            if cell.cell_type == "markdown":
                cell.source = _HEADING.sub(lambda m: f"**{m[2]}**", cell.source)
        summary = f"<summary>{html.escape(title)}</summary>"
        out.append(nbformat.v4.new_markdown_cell(f'<details class="vib-details">{summary}'))
        out.extend(c for c in run if c.cell_type == "code" or c.source.strip())
        out.append(nbformat.v4.new_markdown_cell("</details>"))
        run.clear()

    for cell in cells:
        if DETAILS in _tags(cell):
            run.append(cell)
        else:
            flush()
            out.append(cell)
    flush()
    return out


KEY_RESULTS = "> **Key results**"


def key_results(nb) -> str:
    """The chapter's key-results box (a Markdown output starting with :data:`KEY_RESULTS`), or ``""``."""
    for cell in nb.cells:
        for out in cell.get("outputs", []) if cell.cell_type == "code" else []:
            text = out.get("data", {}).get("text/markdown", "")
            text = "".join(text) if isinstance(text, list) else text
            if text.lstrip().startswith(KEY_RESULTS):
                return text.strip()
    return ""


def findings_markdown(pages: list[ChapterPage]) -> str:
    """The front page's findings of every part: each chapter's key results, as this run computed them."""
    lines = ["## What Parts II and III find", "", "Each chapter opens with its key results; here are those "
             "beyond the paper, computed by this run.", ""]  # fmt: skip
    for caption, members in parts(pages)[1:]:  # the front page states Part I's findings itself
        members = [(p, key_results(p.notebook)) for p in members]
        members = [(p, box) for p, box in members if box]
        if not members:
            continue
        lines += [f"### {caption}", ""]
        for p, box in members:
            bullets = [ln[1:].strip() for ln in box.splitlines()[1:] if ln.strip(" >")]
            lines += [f"**[{p.title}]({p.name}.ipynb)**", ""] + [b if b.startswith(("*", "-")) else f"* {b}"
                                                                  for b in bullets] + [""]  # fmt: skip
    return "\n".join(lines)


def _caption_from_output(cell) -> None:
    """A figure's caption, label and alt text, carried by its output (a ``Captioned`` figure), become the
    cell's myst-nb figure options; the output's text form (the caption again) is dropped."""
    from ..presentation.captions import METADATA_KEY

    for out in cell.get("outputs", []):
        facts = out.get("metadata", {}).get(METADATA_KEY)
        if facts:
            mystnb = cell.metadata.setdefault("mystnb", {})
            mystnb["figure"] = {"caption": facts["caption"], "name": facts["name"]}
            image = {"alt": facts["alt"]}
            width = out["metadata"].get("image/png", {}).get("width")
            if width:  # the HiDPI PNG shown at its CSS size (the column scales it down further, never up)
                image["width"] = f"{width}px"
            mystnb["image"] = image
            out.get("data", {}).pop("text/plain", None)


def _drop_widget_views(cell) -> None:
    """Outputs carrying a live widget view keep only their HTML (the kernel-free panel) or text."""
    for out in cell.get("outputs", []):
        data = out.get("data")
        if data and WIDGET_VIEW in data:
            data.pop(WIDGET_VIEW)
            if "text/html" in data:
                data.pop("image/png", None)
                data.pop("text/plain", None)


def _markdown_outputs(nb) -> list[str]:
    """The Markdown outputs of a notebook's code cells (the exercise section's among them)."""
    out = []
    for cell in nb.cells:
        for o in cell.get("outputs", []) if cell.cell_type == "code" else []:
            text = o.get("data", {}).get("text/markdown", "")
            out.append("".join(text) if isinstance(text, list) else text)
    return out


# ------------------------------------------------------------------------- Sphinx

CONF = """# Generated by vibration.publishing.book: the book's Sphinx configuration.
project = {title!r}
author = ""
copyright = ""
extensions = ["myst_nb", "vibration.publishing.sphinx_ext"]
root_doc = "index"
exclude_patterns = ["_build", "_static"]
templates_path = []  # a list of this build's own: the themes append their folders to it (not to a shared default)
html_theme = "sphinx_book_theme"
html_title = {title!r}
html_static_path = ["_static"]
html_css_files = ["vibration-book.css"]
html_show_sourcelink = False
html_show_sphinx = False
html_copy_source = False
html_last_updated_fmt = None
html_math_renderer = "mathml"
html_search_language = "en"
html_show_search_summary = False
html_theme_options = {{
    "show_toc_level": 2,
    "use_download_button": False,
    "use_fullscreen_button": False,
    "use_repository_button": False,
    "home_page_in_toc": True,
    "show_navbar_depth": 1,
    "navigation_with_keys": False,
    "extra_footer": {footer!r},
}}
html_context = {{"default_mode": "light"}}
numfig = True
numfig_format = {{"figure": "Figure %s", "table": "Table %s", "code-block": "Listing %s", "section": "Section %s"}}
nb_execution_mode = "off"
nb_render_markdown_format = "myst"
nb_merge_streams = True
nb_mime_priority_overrides = [
    ("*", "application/vnd.jupyter.widget-view+json", None),
    ("html", "text/markdown", 5),
    ("singlehtml", "text/markdown", 5),
]
nb_number_source_lines = False
nb_scroll_outputs = False
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "html_image"]
myst_heading_anchors = 3
myst_dmath_double_inline = True
suppress_warnings = ["mystnb.unknown_mime_type", "myst.header", "toc.not_included", "misc.highlighting_failure"]
"""


def write_appendices(src: Path, pages: list[ChapterPage] = ()) -> None:
    """The generated appendices: glossary, parameters, using the package, answers, licences, references."""
    text = {
        "glossary": glossary_markdown(),
        "symbols": symbols_markdown(chapter_schemas()),
        "using": usage_markdown(list(chapter_packages().values())),
        "answers": answers_markdown([(p.title, p.name, _markdown_outputs(p.notebook)) for p in pages]),
        "licences": licences_markdown(),
        "references": references_markdown(),
    }
    for name, _ in APPENDICES:
        (src / f"{name}.md").write_text(text[name], encoding="utf-8")


def parts(pages: list[ChapterPage]) -> list[tuple[str, list[ChapterPage]]]:
    """The parts that ``pages`` fill, in the order of their first pages, each with its pages (the front
    page belongs to none)."""
    out: dict[str, list[ChapterPage]] = {}
    for p in pages:
        if not p.is_front:
            out.setdefault(p.part, []).append(p)
    return list(out.items())


def _toctree(pages: list[ChapterPage]) -> str:
    blocks = []
    for caption, members in parts(pages):
        entries = "\n".join(p.name for p in members)
        blocks.append(f"```{{toctree}}\n:caption: {caption}\n:maxdepth: 1\n:hidden:\n\n{entries}\n```")
    entries = "\n".join(name for name, _ in APPENDICES)
    blocks.append(f"```{{toctree}}\n:caption: Appendices\n:maxdepth: 1\n:hidden:\n\n{entries}\n```")
    return "\n\n".join(blocks)


def contents_markdown(pages: list[ChapterPage]) -> str:
    """The front page's list of parts and chapters, one plain sentence each."""
    lines = ["## Chapters", ""]
    for caption, members in parts(pages):
        lines += [f"**{caption}**", ""]
        for p in members:
            lines.append(f"- [{p.title}]({p.name}.ipynb): {chapter_blurb(p.name) or p.summary}")
        lines.append("")
    lines += [course_plan_markdown(), ""]
    lines += ["**Appendices**", ""] + [f"- [{title}]({name}.md)" for name, title in APPENDICES]
    return "\n".join(lines)


def _css() -> str:
    from importlib.resources import files

    return files("vibration.publishing").joinpath("book.css").read_text(encoding="utf-8")


def write_source(pages: list[ChapterPage], src: Path, title: str = BOOK_TITLE) -> None:
    """Write the Sphinx source tree: conf.py, prepared notebooks, the front page, CSS."""
    src.mkdir(parents=True, exist_ok=True)
    (src / "_static").mkdir(exist_ok=True)
    (src / "_static" / "vibration-book.css").write_text(_css(), encoding="utf-8")
    footer = "Every number on these pages was computed by this run of the chapters."
    (src / "conf.py").write_text(CONF.format(title=title, footer=footer), encoding="utf-8")
    front = [p for p in pages if p.is_front]
    chapters = [p for p in pages if not p.is_front]
    changes = run_changes(pages)
    if front:
        nb = prepare(front[0], changes)
    else:
        nb = nbformat.v4.new_notebook()
        nb.cells = [nbformat.v4.new_markdown_cell(f"# {title}")]
        banner = banner_html([], changes)
        if banner:
            nb.cells.append(nbformat.v4.new_markdown_cell(banner))
    findings = findings_markdown(chapters)
    at = next((i for i, c in enumerate(nb.cells) if c.cell_type == "markdown" and "Parameters of this run" in c.source),
              len(nb.cells))  # fmt: skip
    nb.cells.insert(at, nbformat.v4.new_markdown_cell(findings))
    nb.cells.insert(at + 1, nbformat.v4.new_markdown_cell(contents_markdown(chapters)))
    nb.cells.append(nbformat.v4.new_markdown_cell(_toctree(chapters)))
    nbformat.write(nb, src / "index.ipynb")
    write_downloads(chapters, src / "_static" / "downloads")  # the notebooks as students get them: no answers
    for p in chapters:
        fold_answers(p.notebook)  # the book folds each worked answer under its exercise
    write_appendices(src, chapters)
    for p in chapters:
        book_nb = prepare(p, changes)
        book_nb.cells.insert(1, download_cell(p.name))
        nbformat.write(book_nb, src / f"{p.name}.ipynb")


def sphinx_build(src: Path, out: Path, builder: str, incremental: bool = False) -> None:
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


def print_pdf(html_path: Path, pdf_path: Path, pages: list[ChapterPage] = (), title: str = BOOK_TITLE):
    """The print edition of ``html_path`` in ``pdf_path`` (A4, title page, contents with page numbers,
    bookmarks, page numbers; see :mod:`vibration.publishing.print_edition`); returns its :class:`Edition`."""
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
                return print_book(page, pdf_path, title, starts, options)
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
    pages: list[ChapterPage], out: Path, work: Path, state: Path, *, pdf: bool = True, title: str = BOOK_TITLE
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
        return build_incremental(pages, out, work, state, pdf=pdf, title=title)
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
