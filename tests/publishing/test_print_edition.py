"""The print edition on a small single-page book: title page with its edition, lists of figures and tables,
bookmarks to section level, and no page marks left in the PDF's text layer; the runner's print edition draws
its figures as vectors."""

from __future__ import annotations

import html
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CHROMIUM, open_offline

from vibration.book.presentation.captions import METADATA_KEY
from vibration.book.publishing.print_edition import commit_date, edition_text, print_book

ROOT = Path(__file__).resolve().parents[2]

_PAGE = """<!doctype html><html><head><meta charset="utf-8"><title>t</title></head><body><article>
<section><h1>The book</h1><p>Front page.</p></section>
{docs}
</article></body></html>"""

_DOC = """<span id="document-ch{n}"></span><section><h2>{n}. Chapter {n}</h2><p>Intro.</p>
<section><h3>First section of {n}</h3><p>{filler}</p>
<figure id="fig-{n}"><svg width="200" height="100"></svg><figcaption><span class="caption-number">Figure {n}.1 </span>
Response of case {n}: <math><semantics><mi>x</mi><annotation encoding="application/x-tex">x_\\mathrm{{ref}}
</annotation></semantics></math> at rest (left: case {n}. right). More words.</figcaption></figure></section>
<section><h3>Second section of {n}</h3><table id="tab-{n}"><caption><span class="caption-number">Table {n}.1 </span>
Values of case {n}.</caption><tr><td>1</td></tr></table><p>{filler}</p></section></section>"""


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_print_edition_title_lists_and_section_bookmarks(browser, tmp_path):
    from pypdf import PdfReader

    filler = " ".join(["Words that fill a page."] * 300)
    html = _PAGE.format(docs="".join(_DOC.format(n=n, filler=filler) for n in (1, 2)))
    src = tmp_path / "book.html"
    src.write_text(html, encoding="utf-8")
    page, outside, errors = open_offline(browser, src)
    pdf = tmp_path / "book.pdf"
    try:
        edition = print_book(page, pdf, "The book", parts=[("Part I: Chapters", 1)], pdf_options={"format": "A4"})
    finally:
        page.close()
    assert not errors and not outside, (errors, outside)
    reader = PdfReader(str(pdf))
    texts = [page.extract_text() or "" for page in reader.pages]
    assert "The book" in texts[0] and edition_text() in " ".join(texts[0].split())
    assert not any(re.search(r"vib(doc|sec)\d", t) for t in texts)
    lists = " ".join(texts[:6])
    # the entry is the caption's first sentence as read: no TeX of its mathematics, not cut at a colon or in brackets
    assert "List of figures" in lists and "Figure 1.1 Response of case 1: x at rest (left: case 1. right)." in lists
    assert "mathrm" not in lists
    assert "List of tables" in lists and "Table 2.1 Values of case 2." in lists

    def flat(items, depth=0):
        for item in items:
            if isinstance(item, list):
                yield from flat(item, depth + 1)
            else:
                yield depth, item.title, reader.get_destination_page_number(item)

    marks = list(flat(reader.outline))
    chapter = next(d for d, t, _ in marks if t == "1. Chapter 1")
    sections = [(d, t, p) for d, t, p in marks if t.startswith(("First section", "Second section"))]
    assert len(sections) == 4 and all(d == chapter + 1 for d, _, _ in sections), marks
    for _, title, number in sections:  # each section's bookmark opens the page its heading is on
        assert title in texts[number], (title, number)
    assert edition.titles[1:] == ("1. Chapter 1", "2. Chapter 2")


def test_edition_line_names_version_and_commit_date():
    date = commit_date()
    assert date is None or re.fullmatch(r"\d{4}-\d{2}-\d{2}", date)
    text = edition_text()
    assert text.startswith("Edition ") and (date is None or date in text)


_FOLDS = """<!doctype html><html><head><meta charset="utf-8"><title>t</title><style>{css}</style></head><body><article>
{folds}</article></body></html>"""
_FOLD = """<p>{words}</p><details class="vib-details" open><summary>Details: fold {n}</summary>
<figure><svg width="300" height="420"></svg><figcaption>Figure of fold {n}.</figcaption></figure></details>"""


@pytest.mark.browser
def test_print_keeps_each_folds_summary_on_the_page_of_what_it_opens(browser, tmp_path):
    """Folds after paragraphs of growing length: their summaries land at every height of a page, some at its foot,
    where the figure they open (too tall for what is left) moves to the next page; the summary must move with it."""
    from importlib.resources import files

    from vibration.book.publishing.print_edition import page_texts

    css = files("vibration.book.publishing").joinpath("book.css").read_text(encoding="utf-8")
    folds = "".join(_FOLD.format(n=n, words=" ".join(["Words that fill lines."] * (6 * n))) for n in range(1, 25))
    src = tmp_path / "folds.html"
    src.write_text(_FOLDS.format(css=css, folds=folds), encoding="utf-8")
    page, _, _ = open_offline(browser, src)
    pdf = tmp_path / "folds.pdf"
    try:
        page.emulate_media(media="print")
        page.pdf(path=str(pdf), format="A4")
    finally:
        page.close()
    texts = page_texts(pdf)
    assert len(texts) > 10, len(texts)  # enough pages that some summary meets a page's foot
    for n in range(1, 25):
        summary = next(i for i, t in enumerate(texts) if f"Details: fold {n}" in t)
        assert f"Figure of fold {n}." in texts[summary], f"fold {n}: its summary is on page {summary + 1} alone"


@pytest.fixture(scope="module")
def run_printed(tmp_path_factory) -> Path:
    """Chapter 1 run by the report runner (papermill, then the book and its print edition: about a minute)."""
    if not os.path.exists(CHROMIUM):
        pytest.skip(f"{CHROMIUM} is missing: make browser installs it")
    out = tmp_path_factory.mktemp("run-printed")
    proc = subprocess.run(
        [sys.executable, "-m", "vibration.report", "01", "--out", str(out)],
        capture_output=True,
        text=True,
        timeout=900,
        cwd=ROOT,
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    return out


@pytest.mark.slow
@pytest.mark.browser
def test_the_runners_print_edition_draws_its_figures_as_vectors(run_printed):
    """No image in the PDF has the printed size of a whole figure (a dense part of a figure, drawn as an image
    inside it, is smaller), and the words a figure draws (legends, titles) are in the PDF's text layer."""
    import nbformat
    import pypdfium2

    nb = nbformat.read(run_printed / "notebooks" / "01_reproduction.ipynb", as_version=4)
    figures = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if METADATA_KEY in o.get("metadata", {})]
    assert len(figures) >= 3, len(figures)
    # printed size in pt of each figure: its CSS size (96 px per inch) at 72 pt per inch
    sizes = [(0.75 * o.metadata["image/png"]["width"], 0.75 * o.metadata["image/png"]["height"]) for o in figures]
    doc = pypdfium2.PdfDocument(str(run_printed / "report" / "report.pdf"))
    images, text = [], []
    try:
        for i in range(len(doc)):
            page = doc[i]
            for obj in page.get_objects(max_depth=8):
                if obj.type == pypdfium2.raw.FPDF_PAGEOBJ_IMAGE:
                    left, bottom, right, top = obj.get_bounds()
                    images.append((i + 1, right - left, top - bottom))
            text.append(page.get_textpage().get_text_range())
    finally:
        doc.close()
    whole = [(n, round(w), round(h)) for n, w, h in images
             if any(abs(w - fw) < 0.02 * fw and abs(h - fh) < 0.02 * fh for fw, fh in sizes)]  # fmt: skip
    assert not whole, f"{len(whole)} of {len(figures)} figures printed whole as images (page, w, h in pt): {whole}"
    flat = "".join("".join(text).split())
    words = [html.unescape(w) for o in figures for w in re.findall(r"<text\b[^>]*>([^<]+)</text>",
             o.data.get("image/svg+xml", "")) if len(w) > 3 and re.search(r"[A-Za-z]", w)]  # fmt: skip
    assert words, "the figures carry no SVG with text"
    missing = [w for w in words if "".join(w.split()) not in flat]
    assert not missing, f"words the figures draw are not in the PDF's text: {missing}"


@pytest.mark.slow
@pytest.mark.browser
def test_the_screens_pages_and_downloads_keep_the_png(run_printed):
    """The SVG is the print edition's: the chapter's HTML page shows PNGs and its download carries no SVG."""
    import nbformat

    page = (run_printed / "report" / "01_reproduction.html").read_text(encoding="utf-8")
    sources = re.findall(r'<img\b[^>]*\bsrc="([^"]+)"', page)
    assert sources and all(s.endswith(".png") for s in sources), sources
    nb = nbformat.read(run_printed / "report" / "_static" / "downloads" / "01_reproduction.ipynb", as_version=4)
    kinds = {k for c in nb.cells if c.cell_type == "code" for o in c.outputs for k in o.get("data", {})}
    assert "image/png" in kinds and "image/svg+xml" not in kinds, kinds
