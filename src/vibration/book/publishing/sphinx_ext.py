"""Sphinx extension for the book: MathML equations and figure numbers per chapter.

* ``html_math_renderer = "mathml"``: every math node is converted to MathML at build time
  with latex2mathml (:func:`vibration.book.publishing.mathml.latex_to_mathml`), so pages need no
  MathJax and no network; Chromium and Firefox render MathML natively.
* Figures and tables are numbered ``<chapter>.<n>`` where the chapter number is the
  leading number of the document name (``06_stability`` -> 6), without Sphinx's section
  numbering (which would renumber the chapters of Part II from 1).
* A mention of another chapter in the text ("chapter 4", "chapters 1 and 4") links to that chapter's
  page, the number read from the table of contents' document names, so a reader can follow it.
* Search results show the text around the words searched for, also from disk (:mod:`.search_text`).
"""

from __future__ import annotations

import re

from docutils import nodes

from . import search_text
from .mathml import latex_to_mathml


def _visit_math(self, node) -> None:
    self.body.append(latex_to_mathml(node.astext(), display=False))
    raise nodes.SkipNode


def _visit_displaymath(self, node) -> None:
    tex = node.astext()
    label = node.get("label")
    number = node.get("number")
    self.body.append('<div class="math-wrapper docutils container">')
    if label and number is not None:
        self.body.append(f'<span class="eqno">({number})</span>')
    self.body.append(latex_to_mathml(tex, display=True))
    self.body.append("</div>")
    raise nodes.SkipNode


_CHAPTER = re.compile(r"^(\d+)_")


def chapter_number(docname: str) -> int | None:
    """Leading number of a chapter's document name.

    Examples
    --------
    >>> chapter_number("06_stability"), chapter_number("index")
    (6, None)
    """
    m = _CHAPTER.match(docname.rsplit("/", 1)[-1])
    return int(m.group(1)) if m else None


def _prefix_numbers(app, env):
    """Renumber figures and tables ``<chapter>.<n>``, n counting from 1 in each chapter.

    Without section numbers Sphinx counts each kind through the whole book; here each
    chapter's items keep their order and restart at 1 under the chapter's number.
    """
    for docname, kinds in env.toc_fignumbers.items():
        chap = chapter_number(docname)
        for ids in kinds.values():
            ordered = sorted(ids.items(), key=lambda item: item[1])
            for i, (ident, _) in enumerate(ordered, start=1):
                ids[ident] = (i,) if chap is None else (chap, i)
    return []


#: "chapter 4", "Chapters 1 and 4", "chapters 1-5", "chapters 1 to 4": the word and its run of numbers.
_MENTION = re.compile(r"\b([Cc]hapters?)(\s+)(\d{1,2}(?:(?:\s*[,\u2013-]\s*|\s+(?:and|or|to)\s+)\d{1,2})*)\b")
_NUMBER = re.compile(r"\d{1,2}")
#: Nodes whose text is left as it is: code, formulas, links already, headings and raw markup.
_NO_LINKS = (nodes.literal, nodes.literal_block, nodes.math, nodes.math_block, nodes.reference, nodes.title,
             nodes.raw, nodes.target)  # fmt: skip


def chapter_mentions(text: str) -> list[tuple[str, int | None]]:
    """``text`` cut into pieces, each with the chapter number it names (or ``None``); the word goes with the
    first number.

    >>> chapter_mentions("see chapters 1 and 4, then chapter 12.")
    [('see ', None), ('chapters 1', 1), (' and ', None), ('4', 4), (', then ', None), ('chapter 12', 12), ('.', None)]
    """
    pieces, at = [], 0
    for mention in _MENTION.finditer(text):
        for i, number in enumerate(_NUMBER.finditer(mention.group(3))):
            start = mention.start(1) if i == 0 else mention.start(3) + number.start()  # "chapter 4" as one link
            end = mention.start(3) + number.end()
            pieces += [(text[at:start], None), (text[start:end], int(number.group()))]
            at = end
    pieces.append((text[at:], None))
    return [(piece, n) for piece, n in pieces if piece]


def _link_chapter_mentions(app, doctree, docname) -> None:
    """Each mention of another chapter in the page's text becomes a link to that chapter's page."""
    pages = {chapter_number(d): d for d in app.env.found_docs if chapter_number(d) not in (None, 0)}
    here = chapter_number(docname)
    for text in list(doctree.findall(nodes.Text)):
        parent = text.parent
        if parent is None or any(isinstance(a, _NO_LINKS) for a in _ancestors(text)):
            continue
        pieces = chapter_mentions(str(text))
        if not any(n in pages and n != here for _, n in pieces):
            continue
        replacement = []
        for piece, n in pieces:
            if n in pages and n != here:
                uri = app.builder.get_relative_uri(docname, pages[n])
                replacement.append(nodes.reference(piece, piece, refuri=uri, internal=True))
            else:
                replacement.append(nodes.Text(piece))
        parent.replace(text, replacement)


def _ancestors(node):
    node = node.parent
    while node is not None:
        yield node
        node = node.parent


def _stable_build_info(app) -> None:
    """Record the HTML configuration after the themes have set theirs, so an unchanged book is not rewritten.

    The HTML builder hashes its configuration before the ``builder-inited`` handlers run, and the themes
    append their template folders to ``templates_path`` there; a persistent build folder then finds the hash
    of the previous build (taken with those folders, from its pickled environment) different every time and
    rewrites every page. Taken after the themes (priority 900), the hash is the same from build to build.
    """
    if hasattr(app.builder, "create_build_info"):
        app.builder.build_info = app.builder.create_build_info()


def setup(app):
    app.add_html_math_renderer(
        "mathml", inline_renderers=(_visit_math, None), block_renderers=(_visit_displaymath, None)
    )
    app.connect("env-get-updated", _prefix_numbers, priority=900)
    app.connect("builder-inited", _stable_build_info, priority=900)
    app.connect("build-finished", _accessible_pages)
    app.connect("doctree-resolved", _link_chapter_mentions)
    search_text.setup(app)  # search results with their text, also from disk
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}


#: Fixes of the theme's markup, applied to every written page (each one an axe-core finding): accessible
#: names that contain the visible text (a button reading "Search Ctrl+K" named "Search", a toggle reading
#: "Show code cell source" named "Toggle hidden content"); the primary sidebar (the book's title link) inside
#: a landmark. (The page's one search control is the sidebar's field: the configuration leaves the header
#: without the theme's copy of it.)
PAGE_FIXES = (
    (
        re.compile(
            r'(<button class="btn search-button-field search-button__button pst-js-only" title="Search")'
            r' aria-label="Search"'
        ),
        r"\1",
    ),
    (re.compile(r'(<summary[^>]*?) aria-label="Toggle hidden content"'), r"\1"),
    (
        re.compile(r'<div id="pst-primary-sidebar" class="bd-sidebar-primary bd-sidebar">'),
        '<div id="pst-primary-sidebar" class="bd-sidebar-primary bd-sidebar" role="complementary" aria-label="Book">',
    ),
)


def fix_page(text: str) -> str:
    """One written page with :data:`PAGE_FIXES` applied.

    >>> fix_page('<summary aria-label="Toggle hidden content">')
    '<summary>'
    """
    for pattern, replace in PAGE_FIXES:
        text = pattern.sub(replace, text)
    return text


def _accessible_pages(app, exception) -> None:
    if exception is not None or app.builder.format != "html":
        return
    from pathlib import Path

    for page in Path(app.outdir).rglob("*.html"):
        text = page.read_text(encoding="utf-8")
        fixed = fix_page(text)
        if fixed != text:
            page.write_text(fixed, encoding="utf-8")
