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
  .vib-title-page p.vib-edition { font-size: 0.95em; margin-top: 2.5em; }
  .vib-contents { break-after: page; }
  .vib-contents h2 { font-size: 1.6em; margin-bottom: 0.8em; }
  .vib-contents ol { list-style: none; padding: 0; }
  .vib-contents li { display: flex; align-items: baseline; margin: 0.25em 0; }
  .vib-contents li.vib-part { font-weight: 600; margin-top: 0.8em; }
  .vib-contents li .vib-dots { flex: 1; border-bottom: 1px dotted #888; margin: 0 0.4em; }
  .vib-list { break-before: page; font-size: 0.9em; }
  .vib-list li { display: block; margin: 0.15em 0; }
  .vib-list a { color: inherit; text-decoration: none; }
  h1, h2, h3, h4 { break-after: avoid-page; }
  figure, .cell_output:has(img) { break-inside: avoid-page; }
  figcaption, table > caption { break-before: avoid-page; }
  input, select, button, .vib-reset, .vro-reset, .jupyter-widgets, .widget-output { display: none !important; }
  .vib-print-note { display: block !important; font-size: 0.85em; color: #555; font-style: italic; }
  .vib-page-mark { display: block !important; color: #fff; font-size: 1px; line-height: 1px; height: 1px; }
}
.vib-page-mark { display: none; }
.vib-print-note { display: none; }
"""

_SETUP_JS = """
([css, title, subtitle, note, parts, edition]) => {
  const style = document.createElement('style'); style.textContent = css; document.head.appendChild(style);
  // the front page's title, then each document's first heading (Sphinx's single page demotes them)
  const first = document.querySelector('article h1') || document.querySelector('h1');
  const docs = [...document.querySelectorAll('span[id^="document-"] + section')]
    .map(s => s.querySelector('h1, h2, h3'));
  const heads = [first, ...docs].filter(h => h);
  const front = document.createElement('div');
  front.innerHTML = `<div class="vib-title-page"><h1 class="vib-book-title">${title}</h1><p>${subtitle}</p>
    <p class="vib-edition">${edition}</p></div>
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
  // each document's sections (its heading's next level), marked like the documents, for the PDF's bookmarks
  const clean = h => h.textContent.replace(/[#¶]\\s*$/, '').trim();
  const sections = [];
  [...document.querySelectorAll('span[id^="document-"] + section')].forEach(doc => {
    const d = heads.indexOf(doc.querySelector('h1, h2, h3'));
    if (d < 0) return;
    doc.querySelectorAll(':scope > section > h1, :scope > section > h2, :scope > section > h3, :scope > section > h4')
      .forEach(h => {
        const mark = document.createElement('span');
        mark.className = 'vib-page-mark'; mark.setAttribute('aria-hidden', 'true');
        mark.textContent = `vibsec${sections.length}mark`; h.parentNode.insertBefore(mark, h);
        sections.push([d, clean(h)]);
      });
  });
  // lists of figures and tables after the contents: number and caption's first sentence, linked
  const lists = document.createElement('div');
  [['List of figures', 'figure', 'figcaption'], ['List of tables', 'table', 'caption']].forEach(([name, sel, cap]) => {
    const items = [...document.querySelectorAll(`article ${sel}`)].map(el => {
      const c = el.querySelector(cap); if (!c) return null;
      const num = c.querySelector('.caption-number'); if (!num) return null;
      // the caption's text as read, without the TeX source that MathML carries in its annotations
      const copy = c.cloneNode(true);
      copy.querySelectorAll('annotation, annotation-xml, .caption-number').forEach(a => a.remove());
      const rest = copy.textContent.replace(/\\s+/g, ' ').replace(/[#¶]\\s*$/, '').trim();
      // the first sentence: up to a full stop followed by a space, outside brackets
      let depth = 0, end = rest.length;
      for (let i = 0; i < rest.length; i++) {
        const ch = rest[i];
        if ('([{'.includes(ch)) depth++;
        else if (')]}'.includes(ch)) depth = Math.max(0, depth - 1);
        else if (ch === '.' && depth === 0 && /\\s/.test(rest[i + 1] || ' ')) {
          end = i + 1; break;
        }
      }
      const first = rest.slice(0, end).trim();
      const id = el.id || (el.closest('[id]') || {}).id || '';
      return [num.textContent.trim(), first, id];
    }).filter(x => x);
    if (!items.length) return;
    const nav = document.createElement('nav'); nav.className = 'vib-contents vib-list';
    nav.innerHTML = `<h2>${name}</h2><ol></ol>`;
    items.forEach(([n, text, id]) => {
      const li = document.createElement('li'); const a = document.createElement('a');
      a.textContent = `${n} ${text}`; if (id) a.href = `#${id}`;
      li.appendChild(a); nav.querySelector('ol').appendChild(li);
    });
    lists.appendChild(nav);
  });
  front.appendChild(lists);
  document.querySelectorAll('.vib-panel, .vro-panel, [class$="-panel"]').forEach(p => {
    if (p.querySelector('input, select, button')) {
      const n = document.createElement('p'); n.className = 'vib-print-note'; n.textContent = note; p.appendChild(n);
    }
  });
  return {titles: heads.map((h, i) => i === 0 ? 'Overview and findings' : clean(h)), sections};
}
"""

_FILL_JS = """
(pages) => { document.querySelectorAll('.vib-contents .vib-page').forEach((s, i) => { s.textContent = pages[i]; }); }
"""

_CLEAR_JS = """
() => { document.querySelectorAll('.vib-page-mark').forEach(m => { m.textContent = '\\u00a0'; }); }
"""


def page_texts(pdf: Path) -> list[str]:
    """The text layer of every page of ``pdf``, by PDFium (the engine of Chromium's own PDF viewer: a 220-page
    print in a quarter of a second, fifteen times faster than pypdf, which the marks are read with three times
    per print)."""
    import pypdfium2

    doc = pypdfium2.PdfDocument(str(pdf))
    try:
        texts = []
        for i in range(len(doc)):
            page = doc[i]
            textpage = page.get_textpage()
            texts.append(textpage.get_text_range())
            textpage.close()
            page.close()
        return texts
    finally:
        doc.close()


def _marks_left(pdf: Path) -> bool:
    """Whether any page of ``pdf`` still carries a page mark in its text."""
    return any(re.search(r"vib(doc|sec)\d", text) for text in page_texts(pdf))


NOTE = "In print: the panel at its starting values. The online book's sliders move it."


def commit_date(root: Path | None = None) -> str | None:
    """The date (YYYY-MM-DD) of the commit the book is built from, or ``None`` outside a git checkout."""
    import subprocess

    root = root or Path(__file__).resolve().parents[4]
    try:
        out = subprocess.run(
            ["git", "-C", str(root), "log", "-1", "--format=%cs"], capture_output=True, text=True, timeout=20
        )
    except (OSError, subprocess.TimeoutExpired):
        return None
    date = out.stdout.strip()
    return date if out.returncode == 0 and re.fullmatch(r"\d{4}-\d{2}-\d{2}", date) else None


def edition_text(root: Path | None = None) -> str:
    """The title page's edition line: the package version and the date of the commit it was built from."""
    from ... import __version__

    date = commit_date(root)
    built = f"built from the commit of {date}" if date else "built outside a version-controlled copy"
    return f"Edition {__version__}, {built}"


@dataclass(frozen=True, kw_only=True)
class Edition:
    """What was printed: the chapter titles in order and the page each starts on (1-based)."""

    titles: tuple[str, ...]
    pages: tuple[int, ...]
    page_count: int


def chapter_pages(pdf: Path, count: int, kind: str = "doc", *, texts: list[str] | None = None) -> list[int]:
    """1-based page on which each of ``count`` documents (``kind="doc"``) or sections (``"sec"``) opens,
    from the invisible marks the print carries (``texts``: the pages' text, read here when None)."""
    found: dict[int, int] = {}
    for number, text in enumerate(page_texts(pdf) if texts is None else texts, start=1):
        for m in re.finditer(rf"vib{kind}(\d+)mark", re.sub(r"\s", "", text)):
            found.setdefault(int(m.group(1)), number)
    missing = [i for i in range(count) if i not in found]
    if missing:
        what = "documents" if kind == "doc" else "sections"
        raise RuntimeError(f"the print edition lost the start of {what} {missing}: no page carries their mark")
    return [found[i] for i in range(count)]


def print_book(page, pdf_path: Path, title: str, *, parts: list[tuple[str, int]], pdf_options: dict) -> Edition:
    """Print the loaded single-page book (a playwright ``page``) to ``pdf_path`` as the print edition.

    ``parts`` are (caption, index of the part's first chapter heading) for the contents.
    """
    from pypdf import PdfReader

    setup = [_PRINT_CSS, html.escape(title), html.escape(SUBTITLE), NOTE, parts, html.escape(edition_text())]
    page.evaluate("document.querySelectorAll('details.vib-details').forEach((d) => { d.open = true; })")  # unfolded
    found = page.evaluate(_SETUP_JS, setup)
    titles, sections = found["titles"], [(int(d), str(t)) for d, t in found["sections"]]
    options = {**pdf_options, "path": str(pdf_path), "tagged": True}
    page.pdf(**options)
    texts = page_texts(pdf_path)
    pages = chapter_pages(pdf_path, len(titles), texts=texts)
    section_pages = chapter_pages(pdf_path, len(sections), "sec", texts=texts)
    page.evaluate(_FILL_JS, [str(p) for p in pages])
    page.pdf(**options)
    check = chapter_pages(pdf_path, len(titles))
    if check != pages:
        raise RuntimeError(f"the print edition's pages moved between passes: {pages} then {check}")
    count = len(PdfReader(str(pdf_path)).pages)
    # The last pass empties the marks, so they leave the PDF's text layer; their boxes keep their height.
    page.evaluate(_CLEAR_JS)
    page.pdf(**options)
    if len(PdfReader(str(pdf_path)).pages) != count or _marks_left(pdf_path):
        raise RuntimeError("the print edition changed when its page marks were cleared")
    marked = [(d, t, p) for (d, t), p in zip(sections, section_pages, strict=True)]
    add_bookmarks(pdf_path, titles, pages, parts=parts, sections=marked)
    return Edition(titles=tuple(titles), pages=tuple(pages), page_count=len(PdfReader(str(pdf_path)).pages))


def add_bookmarks(
    pdf: Path,
    titles: list[str],
    pages: list[int],
    *,
    parts: list[tuple[str, int]],
    sections: list[tuple[int, str, int]] = (),
) -> None:
    """PDF bookmarks: the title page, the contents, each part with its chapters and their sections
    (``sections``: document index, title, 1-based page), the appendices."""
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
        item = writer.add_outline_item(title=title, page_number=page - 1, parent=parent)
        for d, sec_title, sec_page in sections:
            if d == i:
                writer.add_outline_item(title=sec_title, page_number=sec_page - 1, parent=item)
    writer.page_mode = "/UseOutlines"
    with open(pdf, "wb") as fh:
        writer.write(fh)


def _is_chapter(title: str) -> bool:
    """Whether a heading is a numbered chapter ("12. The real oscillator ...")."""
    return bool(re.match(r"^\d+\.\s", title))
