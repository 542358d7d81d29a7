"""The print edition on a small single-page book: title page with its edition, lists of figures and tables,
bookmarks to section level, and no page marks left in the PDF's text layer."""

from __future__ import annotations

import re

import pytest
from conftest import open_offline

from vibration.publishing.print_edition import commit_date, edition_text, print_book

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

    from vibration.publishing.print_edition import page_texts

    css = files("vibration.publishing").joinpath("book.css").read_text(encoding="utf-8")
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
