"""The main text of each chapter page stays within the book's limits, read off the built HTML.

What a reader sees unfolded on a chapter page (its article without code cells, "Details" folds and worked
answers) holds at most five figures and five tables, no table wider than seven columns, no caption longer than
sixty words (its "Figure 4.1" label included, a formula one word), and all twelve chapters together at most
60 % of the 47,450 words their main text had before the book was cut (exercises left out of that count).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

bs4 = pytest.importorskip("bs4")

#: Words of chapters 1-12's main text when the limit was set (exercises, folds and code cells left out).
WORDS_BEFORE = 47_450
MAX_FIGURES = MAX_TABLES = 5
MAX_COLUMNS = 7
MAX_CAPTION_WORDS = 60


@pytest.fixture(scope="module")
def site(committed_book) -> Path:
    return committed_book


def _visible_article(path: Path, *, exercises: bool):
    """The page's article as a reader sees it unfolded: no code cells, folds, scripts or heading links; each
    formula replaced by one word."""
    soup = bs4.BeautifulSoup(path.read_text(encoding="utf-8"), "html.parser")
    article = soup.select_one("article")
    dropped = ["details", "div.cell_input", "script", "style", ".headerlink", "annotation"]
    if not exercises:
        dropped.append("section#exercises")
    for selector in dropped:
        for element in article.select(selector):
            element.decompose()
    for formula in article.find_all("math"):
        formula.replace_with(" formula ")
    return article


def _words(text: str) -> int:
    return sum(1 for w in text.split() if re.search(r"\w", w))


def _columns(table) -> int:
    rows = table.find_all("tr")
    return max((sum(int(c.get("colspan", 1)) for c in r.find_all(["td", "th"])) for r in rows), default=0)


def _chapters(site: Path) -> list[Path]:
    pages = sorted(site.glob("[01][0-9]_*.html"))
    assert len(pages) == 12, [p.name for p in pages]
    return pages


def test_words_are_counted_as_a_reader_counts_them():
    assert _words("Figure 4.1 The response # of — x, at ω = 4.47 rad/s.") == 10


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_each_chapter_shows_at_most_five_figures_and_five_tables_none_wider_than_seven_columns(site):
    over = {}
    for page in _chapters(site):
        article = _visible_article(page, exercises=True)
        tables, figures = article.find_all("table"), article.find_all("figure")
        wide = [_columns(t) for t in tables if _columns(t) > MAX_COLUMNS]
        if len(tables) > MAX_TABLES or len(figures) > MAX_FIGURES or wide:
            over[page.stem] = {"tables": len(tables), "figures": len(figures), "wide": wide}
    assert over == {}


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_no_caption_is_longer_than_sixty_words(site):
    long = [
        (page.stem, n, text[:80])
        for page in _chapters(site)
        for caption in _visible_article(page, exercises=True).select("figcaption, caption")
        if (n := _words(text := re.sub(r"\s+", " ", caption.get_text(" ")))) > MAX_CAPTION_WORDS
    ]
    assert long == []


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_the_main_text_is_at_most_sixty_percent_of_what_it_was(site):
    words = {page.stem: _words(_visible_article(page, exercises=False).get_text(" ")) for page in _chapters(site)}
    assert min(words.values()) > 500, words  # a page read as nearly empty would make the check pass for nothing
    assert sum(words.values()) <= 0.6 * WORDS_BEFORE, words
