"""The front page's generated parts: the findings of Parts II and III (each chapter's headline result), the list of
parts and chapters, and the hidden tables of contents Sphinx builds its sidebar from."""

from __future__ import annotations

from .appendices import APPENDICES
from .pages import ChapterPage, parts
from .sheets import chapter_blurb, course_plan_markdown

__all__ = ["KEY_RESULTS", "contents_markdown", "findings_markdown", "key_results", "toctree_markdown"]

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
    """The front page's findings of Parts II and III: each chapter's headline (the first of its key results, as this
    run computed it) and a link to the rest, so the front page summarises the chapters instead of repeating them."""
    lines = ["## What Parts II and III find", "", "Each chapter opens with its key results; here is the first of "
             "each, as this run computed it.", ""]  # fmt: skip
    for caption, members in parts(pages)[1:]:  # the front page states Part I's findings itself
        members = [(p, key_results(p.notebook)) for p in members]
        members = [(p, box) for p, box in members if box]
        if not members:
            continue
        lines += [f"### {caption}", ""]
        for p, box in members:
            bullets = [ln[1:].strip().lstrip("*-").strip() for ln in box.splitlines()[1:] if ln.strip(" >")]
            more = len(bullets) - 1
            rest = f" ({more} more in [the chapter]({p.name}.ipynb))" if more > 0 else ""
            lines += [f"* **[{p.title}]({p.name}.ipynb).** {bullets[0]}{rest}"]
        lines.append("")
    return "\n".join(lines)


def toctree_markdown(pages: list[ChapterPage]) -> str:
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
