"""The book's copy of an executed chapter (:func:`prepare`): its parameters as a table, the banner of a run whose
parameters differ from the defaults, code folded behind toggles, figures captioned from their outputs, live widget
views replaced by their HTML, and the cells a chapter tags :data:`DETAILS` folded into ``<details>`` sections."""

from __future__ import annotations

import copy
import html
import re

import nbformat

from .crossrefs import book_references
from .pages import ChapterPage, Parameter

__all__ = ["DETAILS", "WIDGET_VIEW", "banner_html", "fold_details", "parameters_table", "prepare", "run_changes"]

WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


def _value_text(value) -> str:
    """A parameter value in the book's number format (×10ⁿ, true minus), to 6 significant figures."""
    from ..presentation.tables import fmt

    if isinstance(value, list | tuple):  # a list parameter: its numbers, comma-separated
        return ", ".join(_value_text(float(v)) for v in value)
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
    book_references(nb)  # the book numbers and links each cross-reference itself
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
            remarks = _caption_from_output(cell)
            if "show-input" not in tags and not {"hide-input", "remove-input", "remove-cell"} & set(tags):
                cell.metadata.setdefault("tags", []).append("hide-input")
            cells.append(cell)
            cells.extend(remarks)  # a figure's remark: a paragraph under it, outside the figure
            continue
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
    summary is the heading the run opens with ("Details" when it opens with none); a tagged cell that
    opens with a heading of that level or higher starts a fold of its own, and the other headings inside
    become bold lines, so no section of the page starts inside a fold. The print edition unfolds them.

    >>> md = nbformat.v4.new_markdown_cell
    >>> a, b, c = md("### Convergence\\n\\nText."), md("## More\\nx"), md("after")
    >>> a.metadata["tags"] = b.metadata["tags"] = ["details"]
    >>> [x.source for x in fold_details([a, b, c])]  # doctest: +NORMALIZE_WHITESPACE
    ['<details class="vib-details"><summary>Details: Convergence</summary>', '\\nText.', '</details>',
     '<details class="vib-details"><summary>Details: More</summary>', '\\nx', '</details>', 'after']
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
            if run and _level(run[0]) and _level(cell) and _level(cell) <= _level(run[0]):
                flush()  # the next section at the fold's own level opens a fold of its own
            run.append(cell)
        else:
            flush()
            out.append(cell)
    flush()
    return out


def _level(cell) -> int:
    """The level of the heading a markdown cell opens with (0: none)."""
    head = _HEADING.match(cell.source.lstrip()) if cell.cell_type == "markdown" else None
    return len(head[1]) if head else 0


def _caption_from_output(cell) -> list:
    """A figure's caption, label and alt text, carried by its output (a ``Captioned`` figure), become the
    cell's myst-nb figure options; the output's text form (the caption again) is dropped. The Markdown
    outputs after the figure (its remark) leave the cell as markdown cells, returned with the cell's tags:
    myst-nb would frame every output of a figure cell as the figure, caption and all.

    >>> cell = nbformat.v4.new_code_cell("fig", outputs=[
    ...     nbformat.v4.new_output("display_data", {"image/png": "AA==", "text/plain": "Figure"},
    ...                            metadata={"vibration/figure": {"caption": "C.", "name": "fig-x", "alt": "A."}}),
    ...     nbformat.v4.new_output("display_data", {"text/markdown": "It rises.", "text/plain": "<Markdown>"})])
    >>> [c.source for c in _caption_from_output(cell)], len(cell.outputs), cell.metadata["mystnb"]["figure"]["caption"]
    (['It rises.'], 1, 'C.')
    """
    from ..presentation.captions import METADATA_KEY

    remarks, moved, figure = [], [], False
    for i, out in enumerate(cell.get("outputs", [])):
        facts = out.get("metadata", {}).get(METADATA_KEY)
        if figure and "text/markdown" in out.get("data", {}):
            remark = nbformat.v4.new_markdown_cell("".join(out["data"]["text/markdown"]))
            if _tags(cell):
                remark.metadata["tags"] = _tags(cell)
            remarks.append(remark)
            moved.append(i)
        if facts:
            figure = True
            mystnb = cell.metadata.setdefault("mystnb", {})
            mystnb["figure"] = {"caption": facts["caption"], "name": facts["name"]}
            image = {"alt": facts["alt"]}
            width = out["metadata"].get("image/png", {}).get("width")
            if width:  # the HiDPI PNG shown at its CSS size (the column scales it down further, never up)
                image["width"] = f"{width}px"
            mystnb["image"] = image
            out.get("data", {}).pop("text/plain", None)
    if moved:
        cell.outputs = [o for i, o in enumerate(cell.outputs) if i not in moved]
    return remarks


def _drop_widget_views(cell) -> None:
    """Outputs carrying a live widget view keep only their HTML (the kernel-free panel) or text."""
    for out in cell.get("outputs", []):
        data = out.get("data")
        if data and WIDGET_VIEW in data:
            data.pop(WIDGET_VIEW)
            if "text/html" in data:
                data.pop("image/png", None)
                data.pop("text/plain", None)
