"""An executed chapter as the book sees it: its declared parameters with the values the run used, its title,
its one-line summary and the part of the contents it belongs to."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import nbformat

__all__ = ["ChapterPage", "Parameter", "differs", "parts", "split_help", "summary"]


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


@dataclass(kw_only=True)
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


def parts(pages: list[ChapterPage]) -> list[tuple[str, list[ChapterPage]]]:
    """The parts that ``pages`` fill, in the order of their first pages, each with its pages (the front
    page belongs to none)."""
    out: dict[str, list[ChapterPage]] = {}
    for p in pages:
        if not p.is_front:
            out.setdefault(p.part, []).append(p)
    return list(out.items())
