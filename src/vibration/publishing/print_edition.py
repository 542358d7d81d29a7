"""The print edition: Chromium prints the single-page book with a title page, a contents with page
numbers, PDF bookmarks and tagged structure; slider panels print as static snapshots.

Chromium knows no page numbers while it lays out, so the edition is printed twice: first with a
contents whose numbers are placeholders of the final width, then, after reading on which page
each chapter's title landed (pypdf), with the numbers filled in. The contents keeps its size
between the passes, so the pages do not move; :func:`print_book` checks that they did not.
Printing hides the panels' controls (sliders, buttons, menus): what remains is the panel's
drawing at its default state, which the panel's script drew when the page loaded.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass
from pathlib import Path

#: Text under the title on the title page.
SUBTITLE = "A reproducible study of the forced mass–spring–damper: the paper, beyond the paper, and a real oscillator"

_PRINT_CSS = """
@media print {
  .vib-title-page { break-after: page; display: flex; flex-direction: column; justify-content: center;
    min-height: 200mm; text-align: center; }
  .vib-title-page h1.vib-book-title { font-size: 2.4em; margin-bottom: 0.6em; border: none; }
  .vib-title-page p { font-size: 1.1em; color: #333; max-width: 34em; margin: 0.4em auto; }
  .vib-contents { break-after: page; }
  .vib-contents h2 { font-size: 1.6em; margin-bottom: 0.8em; }
  .vib-contents ol { list-style: none; padding: 0; }
  .vib-contents li { display: flex; align-items: baseline; margin: 0.25em 0; }
  .vib-contents li.vib-part { font-weight: 600; margin-top: 0.8em; }
  .vib-contents li .vib-dots { flex: 1; border-bottom: 1px dotted #888; margin: 0 0.4em; }
  input, select, button, .vib-reset, .vro-reset, .jupyter-widgets, .widget-output { display: none !important; }
  .vib-print-note { display: block !important; font-size: 0.85em; color: #555; font-style: italic; }
  .vib-page-mark { display: block !important; color: #fff; font-size: 1px; line-height: 1px; height: 1px; }
}
.vib-page-mark { display: none; }
.vib-print-note { display: none; }
"""

_SETUP_JS = """
([css, title, subtitle, note, parts]) => {
  const style = document.createElement('style'); style.textContent = css; document.head.appendChild(style);
  // the front page's title, then each document's first heading (Sphinx's single page demotes them)
  const first = document.querySelector('article h1') || document.querySelector('h1');
  const docs = [...document.querySelectorAll('span[id^="document-"] + section')]
    .map(s => s.querySelector('h1, h2, h3'));
  const heads = [first, ...docs].filter(h => h);
  const front = document.createElement('div');
  front.innerHTML = `<div class="vib-title-page"><h1 class="vib-book-title">${title}</h1><p>${subtitle}</p></div>
    <nav class="vib-contents"><h2>Contents</h2><ol></ol></nav>`;
  const list = front.querySelector('ol');
  heads.forEach((h, i) => {
    const text = i === 0 ? 'Overview and findings' : h.textContent.replace(/[#¶]\\s*$/, '').trim();
    const part = parts.find(p => p[1] === i);
    if (part) { const li = document.createElement('li'); li.className = 'vib-part'; li.textContent = part[0];
                list.appendChild(li); }
    const li = document.createElement('li');
    li.innerHTML = `<span class="vib-entry"></span><span class="vib-dots"></span><span class="vib-page">000</span>`;
    li.querySelector('.vib-entry').textContent = text;
    list.appendChild(li);
  });
  const anchor = first.closest('section') || first;
  anchor.parentNode.insertBefore(front, anchor);
  heads.forEach((h, i) => {  // an invisible mark on the page each document opens, found in the PDF's text
    const mark = document.createElement('span');
    mark.className = 'vib-page-mark'; mark.setAttribute('aria-hidden', 'true');
    mark.textContent = `vibdoc${i}mark`; h.parentNode.insertBefore(mark, h);
  });
  document.querySelectorAll('.vib-panel, .vro-panel, [class$="-panel"]').forEach(p => {
    if (p.querySelector('input, select, button')) {
      const n = document.createElement('p'); n.className = 'vib-print-note'; n.textContent = note; p.appendChild(n);
    }
  });
  return heads.map((h, i) => i === 0 ? 'Overview and findings' : h.textContent.replace(/[#¶]\\s*$/, '').trim());
}
"""

_FILL_JS = """
(pages) => { document.querySelectorAll('.vib-contents .vib-page').forEach((s, i) => { s.textContent = pages[i]; }); }
"""

NOTE = "In print: the panel at its starting values. The online book's sliders move it."


@dataclass(frozen=True)
class Edition:
    """What was printed: the chapter titles in order and the page each starts on (1-based)."""

    titles: tuple[str, ...]
    pages: tuple[int, ...]
    page_count: int


def chapter_pages(pdf: Path, count: int) -> list[int]:
    """1-based page on which each of ``count`` documents opens, from the invisible marks the print carries."""
    from pypdf import PdfReader

    found: dict[int, int] = {}
    for number, page in enumerate(PdfReader(str(pdf)).pages, start=1):
        for m in re.finditer(r"vibdoc(\d+)mark", (page.extract_text() or "").replace(" ", "")):
            found.setdefault(int(m.group(1)), number)
    missing = [i for i in range(count) if i not in found]
    if missing:
        raise RuntimeError(f"the print edition lost the start of documents {missing}: no page carries their mark")
    return [found[i] for i in range(count)]


def print_book(page, pdf_path: Path, title: str, parts: list[tuple[str, int]], pdf_options: dict) -> Edition:
    """Print the loaded single-page book (a playwright ``page``) to ``pdf_path`` as the print edition.

    ``parts`` are (caption, index of the part's first chapter heading) for the contents.
    """
    from pypdf import PdfReader

    titles = page.evaluate(_SETUP_JS, [_PRINT_CSS, html.escape(title), html.escape(SUBTITLE), NOTE, parts])
    options = {**pdf_options, "path": str(pdf_path), "tagged": True}
    page.pdf(**options)
    pages = chapter_pages(pdf_path, len(titles))
    page.evaluate(_FILL_JS, [str(p) for p in pages])
    page.pdf(**options)
    check = chapter_pages(pdf_path, len(titles))
    if check != pages:
        raise RuntimeError(f"the print edition's pages moved between passes: {pages} then {check}")
    add_bookmarks(pdf_path, titles, pages, parts)
    return Edition(tuple(titles), tuple(pages), len(PdfReader(str(pdf_path)).pages))


def add_bookmarks(pdf: Path, titles: list[str], pages: list[int], parts: list[tuple[str, int]]) -> None:
    """PDF bookmarks: the title page, the contents, each part with its chapters, the appendices."""
    import logging

    from pypdf import PdfReader, PdfWriter

    logging.getLogger("pypdf").setLevel(logging.ERROR)  # Chromium's trailer sizes draw a harmless warning
    writer = PdfWriter(clone_from=PdfReader(str(pdf)))
    writer.add_outline_item(title="Title page", page_number=0)
    writer.add_outline_item(title="Contents", page_number=1)
    starts = {index: caption for caption, index in parts}
    parent = None
    for i, (title, page) in enumerate(zip(titles, pages, strict=True)):
        if i in starts:
            parent = writer.add_outline_item(title=starts[i], page_number=page - 1)
        elif parent is not None and i > max(starts, default=0) and not _is_chapter(title):
            parent = None  # the appendices after the last part stand on their own
        writer.add_outline_item(title=title, page_number=page - 1, parent=parent)
    writer.page_mode = "/UseOutlines"
    with open(pdf, "wb") as fh:
        writer.write(fh)


def _is_chapter(title: str) -> bool:
    """Whether a heading is a numbered chapter ("12. The real oscillator ...")."""
    return bool(re.match(r"^\d+\.\s", title))
