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
    min-height: 240mm; text-align: center; }
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
}
.vib-print-note { display: none; }
"""

_SETUP_JS = """
([css, title, subtitle, note, parts]) => {
  const style = document.createElement('style'); style.textContent = css; document.head.appendChild(style);
  const body = document.querySelector('#jb-print-docs-body') || document.querySelector('article') || document.body;
  const heads = [...body.querySelectorAll('section > h1')].filter(h => h.closest('.vib-title-page') === null);
  const front = document.createElement('div');
  front.innerHTML = `<div class="vib-title-page"><h1 class="vib-book-title">${title}</h1><p>${subtitle}</p></div>
    <nav class="vib-contents"><h2>Contents</h2><ol></ol></nav>`;
  const list = front.querySelector('ol');
  heads.forEach((h, i) => {
    const text = h.textContent.replace(/[#¶]\\s*$/, '').trim();
    const part = parts.find(p => p[1] === i);
    if (part) { const li = document.createElement('li'); li.className = 'vib-part'; li.textContent = part[0];
                list.appendChild(li); }
    const li = document.createElement('li');
    li.innerHTML = `<span class="vib-entry"></span><span class="vib-dots"></span><span class="vib-page">000</span>`;
    li.querySelector('.vib-entry').textContent = text;
    list.appendChild(li);
  });
  body.insertBefore(front, body.firstChild);
  document.querySelectorAll('.vib-panel, .vro-panel, [class$="-panel"]').forEach(p => {
    if (p.querySelector('input, select, button')) {
      const n = document.createElement('p'); n.className = 'vib-print-note'; n.textContent = note; p.appendChild(n);
    }
  });
  return heads.map(h => h.textContent.replace(/[#¶]\\s*$/, '').trim());
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


def _squash(text: str) -> str:
    """Text without spaces, ligatures undone, for finding a heading on a page whatever the line breaks."""
    for lig, plain in (("ﬁ", "fi"), ("ﬂ", "fl"), ("ﬀ", "ff"), ("ﬃ", "ffi"), ("ﬄ", "ffl")):
        text = text.replace(lig, plain)
    return re.sub(r"[\s\-‐]+", "", text).lower()


def chapter_pages(pdf: Path, titles: list[str], after: int) -> list[int]:
    """1-based page on which each title first appears, searching in order from page ``after + 1``."""
    from pypdf import PdfReader

    texts = [_squash(p.extract_text() or "") for p in PdfReader(str(pdf)).pages]
    out, start = [], after
    for title in titles:
        key = _squash(title)[:40]
        hit = next((i for i in range(start, len(texts)) if key in texts[i]), None)
        if hit is None:
            raise RuntimeError(f"the print edition lost the chapter {title!r}: its title is on no page after {start}")
        out.append(hit + 1)
        start = hit
    return out


def print_book(page, pdf_path: Path, title: str, parts: list[tuple[str, int]], pdf_options: dict) -> Edition:
    """Print the loaded single-page book (a playwright ``page``) to ``pdf_path`` as the print edition.

    ``parts`` are (caption, index of the part's first chapter heading) for the contents.
    """
    from pypdf import PdfReader

    titles = page.evaluate(_SETUP_JS, [_PRINT_CSS, html.escape(title), html.escape(SUBTITLE), NOTE, parts])
    options = {**pdf_options, "path": str(pdf_path), "outline": True, "tagged": True}
    page.pdf(**options)
    front_pages = _front_pages(pdf_path, titles)
    pages = chapter_pages(pdf_path, titles, front_pages)
    page.evaluate(_FILL_JS, [str(p) for p in pages])
    page.pdf(**options)
    check = chapter_pages(pdf_path, titles, front_pages)
    if check != pages:
        raise RuntimeError(f"the print edition's pages moved between passes: {pages} then {check}")
    return Edition(tuple(titles), tuple(pages), len(PdfReader(str(pdf_path)).pages))


def _front_pages(pdf: Path, titles: list[str]) -> int:
    """Pages taken by the title page and the contents: the contents ends on the first page after the
    title page that names the last chapter."""
    return chapter_pages(pdf, titles[-1:], 1)[0]
