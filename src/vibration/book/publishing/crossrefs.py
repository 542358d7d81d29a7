"""Cross-references that read the same in JupyterLab and in the book.

A chapter's Markdown cells refer to its figures and tables with MyST's ``{numref}`` role. The book
(Sphinx) finds the targets in the outputs and numbers them ``<chapter>.<n>``
(:mod:`vibration.book.publishing.sphinx_ext`); JupyterLab's MyST renderer reads only the Markdown cells,
finds no target there and shows the bare label with "Cross Reference Not Found". So the notebooks
carry the number as the reference's own text, ``{numref}`Figure 4.1 <fig-frequency-response>```:

- :func:`number_references` writes it from the notebook's outputs (the in-place re-execution calls it,
  so the committed notebooks follow their figures and tables);
- :func:`book_references` removes it again for the book, which numbers and links every reference itself.

A sentence a chapter shows as a Markdown output cannot know its number (JupyterLab renders each output
alone): it carries words instead, ``{numref}`the table <tab-x>```
(:func:`vibration.book.presentation.tables.cross_reference`), which the book removes as well.

Examples
--------
>>> text = "See {numref}`fig-a` and {numref}`Table 9.9 <tab-b>`; {numref}`eq-c` stays."
>>> number_text(text, {"fig-a": "Figure 4.1", "tab-b": "Table 4.2"})
'See {numref}`Figure 4.1 <fig-a>` and {numref}`Table 4.2 <tab-b>`; {numref}`eq-c` stays.'
>>> book_text(number_text(text, {"fig-a": "Figure 4.1", "tab-b": "Table 4.2"}))
'See {numref}`fig-a` and {numref}`tab-b`; {numref}`eq-c` stays.'
>>> book_text("({numref}`the table <tab-b>`, {numref}`the next figure <fig-a>`, {numref}`my words <fig-a>`)")
'({numref}`tab-b`, {numref}`fig-a`, {numref}`my words <fig-a>`)'
"""

from __future__ import annotations

import re

from ..presentation.captions import METADATA_KEY
from ..presentation.tables import REFERENCE_WORDS

__all__ = ["book_references", "book_text", "number_references", "number_text", "reference_numbers"]

#: A ``{numref}`` role with or without its own text: ``{numref}`fig-x``` or ``{numref}`Figure 4.1 <fig-x>```.
_NUMREF = re.compile(r"\{numref\}`(?:(?P<text>[^`<]*?)\s*<(?P<target>[^`<>]+)>|(?P<label>[^`<>]+))`")
#: The text :func:`number_text` writes: a kind and a number, nothing else.
_NUMBER = re.compile(r"(?:Figure|Table) (?:\d+\.)?\d+")
#: What the book removes from a reference: a number, or the words of a Markdown output's reference.
_STAND_IN = re.compile(rf"{_NUMBER.pattern}|{REFERENCE_WORDS}")
#: A table's label in its Markdown output (a ``list-table`` directive's ``:name:`` option).
_TABLE_NAME = re.compile(r"^:name:\s*(\S+)\s*$", re.M)


def reference_numbers(nb, chapter: int | None) -> dict[str, str]:
    """Label -> "Figure 4.1" / "Table 4.2" for every figure and table among ``nb``'s outputs, in order.

    The book's numbering (:func:`vibration.book.publishing.sphinx_ext._prefix_numbers`): each kind counted
    from 1 through the page, under the chapter's number (none on the front page, ``chapter=None``).
    """
    numbers: dict[str, str] = {}
    counts = {"Figure": 0, "Table": 0}
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        for out in cell.get("outputs", []):
            found = []
            facts = out.get("metadata", {}).get(METADATA_KEY)
            if facts and facts.get("name"):
                found.append(("Figure", facts["name"]))
            markdown = out.get("data", {}).get("text/markdown", "")
            markdown = "".join(markdown) if isinstance(markdown, list) else markdown
            found += [("Table", name) for name in _TABLE_NAME.findall(markdown)]
            for kind, label in found:
                if label in numbers:
                    continue
                counts[kind] += 1
                numbers[label] = f"{kind} {counts[kind]}" if chapter is None else f"{kind} {chapter}.{counts[kind]}"
    return numbers


def number_text(text: str, numbers: dict[str, str]) -> str:
    """``text`` with each ``{numref}`` to a label of ``numbers`` carrying that number as its text."""

    def sub(m: re.Match) -> str:
        label = m.group("target") or m.group("label")
        if label not in numbers or (m.group("text") and not _NUMBER.fullmatch(m.group("text"))):
            return m.group(0)  # an unknown target, or a text of the author's own: left as written
        return f"{{numref}}`{numbers[label]} <{label}>`"

    return _NUMREF.sub(sub, text)


def book_text(text: str) -> str:
    """``text`` with each number written by :func:`number_text` (or each output's "the table") removed: the book
    numbers the reference."""

    def sub(m: re.Match) -> str:
        if m.group("target") and _STAND_IN.fullmatch(m.group("text") or ""):
            return f"{{numref}}`{m.group('target')}`"
        return m.group(0)

    return _NUMREF.sub(sub, text)


def number_references(nb, chapter: int | None) -> int:
    """Write the numbers of ``nb``'s figures and tables into its Markdown cells' references; how many cells changed."""
    numbers = reference_numbers(nb, chapter)
    changed = 0
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            new = number_text(cell.source, numbers)
            if new != cell.source:
                cell.source = new
                changed += 1
    return changed


def book_references(nb) -> None:
    """Remove the written numbers and words from ``nb``'s Markdown cells and Markdown outputs (the book's copy):
    Sphinx numbers and links the references."""
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            cell.source = book_text(cell.source)
        for out in cell.get("outputs", []) if cell.cell_type == "code" else []:
            data = out.get("data", {})
            if "text/markdown" in data:
                markdown = data["text/markdown"]
                data["text/markdown"] = book_text("".join(markdown) if isinstance(markdown, list) else markdown)
