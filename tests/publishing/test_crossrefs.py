"""Cross-references in the notebooks' Markdown read as the book numbers them, also where no book numbers them
(JupyterLab's MyST renderer sees only the Markdown cells, not the outputs that hold the figures and tables)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import nbformat
import pytest

from vibration.book.publishing.crossrefs import book_text, number_references, number_text
from vibration.book.publishing.page_edits import prepare
from vibration.book.publishing.pages import ChapterPage
from vibration.book.publishing.registry import read_contents

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
FRONT = read_contents(ROOT).front
ROLE = re.compile(r"\{numref\}`([^`]*)`")


def _counted(cells: list, chapter: int | None) -> dict[str, str]:
    """Label -> "Figure 4.1": figures (label in the output's metadata) and tables (label on the Markdown's
    ``:name:`` line) counted in the order of the outputs, each kind from 1, under the chapter's number."""
    found, counts = {}, {"Figure": 0, "Table": 0}
    for c in cells:
        for o in c.get("outputs", []) if c["cell_type"] == "code" else []:
            labels = (
                [("Figure", o["metadata"]["vibration/figure"]["name"])]
                if "vibration/figure" in o.get("metadata", {})
                else []
            )
            labels += [
                ("Table", n)
                for n in re.findall(r"^:name: (\S+)$", "".join(o.get("data", {}).get("text/markdown", "")), re.M)
            ]
            for kind, label in labels:
                counts[kind] += 1
                found[label] = f"{kind} {counts[kind]}" if chapter is None else f"{kind} {chapter}.{counts[kind]}"
    return found


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_each_reference_of_the_markdown_cells_carries_its_number(path):
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    numbers = _counted(cells, None if path.stem == FRONT else int(path.stem[:2]))
    roles = [m.group(1) for c in cells if c["cell_type"] == "markdown" for m in ROLE.finditer("".join(c["source"]))]
    written = {f"{numbers[label]} <{label}>" for label in numbers}
    assert [r for r in roles if r not in written] == []


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_each_reference_of_the_markdown_outputs_carries_words_to_show(path):
    """A Markdown output's reference reads "the table" (or "the figure", "the next figure") in JupyterLab, which
    renders each output alone and numbers nothing."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    outputs = [
        "".join(o["data"]["text/markdown"])
        for c in cells
        if c["cell_type"] == "code"
        for o in c.get("outputs", [])
        if set(o.get("data", {})) - {"text/plain"} == {"text/markdown"}  # a table shows its HTML there ("the table")
    ]
    roles = [m.group(1) for t in outputs for m in ROLE.finditer(t)]
    words = re.compile(r"the (?:next )?(?:figure|table) <(?:fig|tab)-[a-z0-9-]+>")
    assert [r for r in roles if not words.fullmatch(r)] == []


def test_numbers_are_written_once_and_removed_for_the_book():
    nb = nbformat.v4.new_notebook()
    fig = nbformat.v4.new_code_cell("f")
    fig.outputs = [
        nbformat.v4.new_output(
            "display_data",
            {"image/png": "AA=="},
            metadata={"vibration/figure": {"name": "fig-a", "caption": "C.", "alt": "A."}},
        )
    ]
    tab = nbformat.v4.new_code_cell("t")
    tab.outputs = [nbformat.v4.new_output("execute_result", {"text/markdown": "```{list-table} T.\n:name: tab-b\n```"})]
    text = "{numref}`fig-a`, {numref}`tab-b`, {numref}`Table 9.9 <tab-b>`, {numref}`my own <fig-a>`, {numref}`eq-c`."
    nb.cells = [nbformat.v4.new_markdown_cell(text), fig, tab]
    assert number_references(nb, 7) == 1
    assert nb.cells[0].source == (
        "{numref}`Figure 7.1 <fig-a>`, {numref}`Table 7.1 <tab-b>`, {numref}`Table 7.1 <tab-b>`, "
        "{numref}`my own <fig-a>`, {numref}`eq-c`."
    )
    assert number_references(nb, 7) == 0  # already up to date
    assert number_text("{numref}`tab-b`", {"tab-b": "Table 2"}) == "{numref}`Table 2 <tab-b>`"  # the front page
    # the book's copy: Sphinx numbers and links each reference; the author's own text stays
    page = ChapterPage(name="07_x", notebook=nb, part="Part")
    assert prepare(page).cells[0].source == (
        "{numref}`fig-a`, {numref}`tab-b`, {numref}`tab-b`, {numref}`my own <fig-a>`, {numref}`eq-c`."
    )
    assert nb.cells[0].source.startswith("{numref}`Figure 7.1 <fig-a>`")  # the notebook itself is unchanged
    assert book_text("{numref}`Figure %s <fig-a>`") == "{numref}`Figure %s <fig-a>`"
    # a Markdown output's words go too
    said = nbformat.v4.new_code_cell("s")
    said.outputs = [
        nbformat.v4.new_output(
            "display_data", {"text/markdown": "Here ({numref}`the table <tab-b>`).", "text/plain": "M"}
        )
    ]
    nb.cells.append(said)
    assert prepare(page).cells[-1].outputs[0]["data"]["text/markdown"] == "Here ({numref}`tab-b`)."
