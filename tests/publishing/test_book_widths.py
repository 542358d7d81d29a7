"""The book's pages at a phone's width (390 px) and at a desktop's (1280 px), opened offline in Chromium: wide tables'
captions stay readable, one search control is shown, wide equations can be scrolled from the keyboard.

The site is built from the committed notebooks, as in tests/publishing/test_book.py.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import open_offline

PHONE, DESKTOP = (390, 844), (1280, 900)
#: Chapters with tables wider than a phone's column (their containers scroll sideways at 390 px).
WIDE_TABLES = ("08_tmd.html", "12_real_oscillator.html")

#: Each table in a sideways-scrolling box: whether its box scrolls, and its caption's left and right edges with the
#: box scrolled to its start and to its end, beside the viewport's width. Tables inside closed folds are opened.
CAPTIONS_JS = """() => {
  document.querySelectorAll('details').forEach(d => { d.open = true; });
  const vw = document.documentElement.clientWidth;
  return [...document.querySelectorAll('.pst-scrollable-table-container')].map(box => {
    const cap = box.querySelector(':scope > table > caption');
    const edges = () => { const r = cap.getBoundingClientRect(); return [r.left, r.right]; };
    box.scrollLeft = 0;
    const start = cap ? edges() : null;
    box.scrollLeft = box.scrollWidth;
    const end = cap ? edges() : null;
    const scrolls = box.scrollLeft > 0;
    box.scrollLeft = 0;
    return {text: cap ? cap.textContent.slice(0, 50) : '', scrolls, start, end, vw};
  });
}"""

#: The search controls a reader can see: tag, accessible name given by aria-label (or null), visible text.
SEARCH_JS = """() => [...document.querySelectorAll('button, input, form')]
  .filter(e => /search/i.test(e.className + ' ' + (e.getAttribute('aria-label') || '') + ' ' + (e.title || '')))
  .filter(e => { const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0
                 && getComputedStyle(e).visibility !== 'hidden' && !e.closest('dialog:not([open])'); })
  .map(e => [e.tagName, e.getAttribute('aria-label'), (e.innerText || '').replace(/\\s+/g, ' ').trim()])"""


@pytest.fixture(scope="module")
def site(committed_book) -> Path:
    return committed_book


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
@pytest.mark.parametrize("name", WIDE_TABLES)
def test_wide_tables_keep_their_captions_inside_a_phones_viewport(browser, site, name):
    page, _, _ = open_offline(browser, site / name, viewport=PHONE)
    try:
        tables = page.evaluate(CAPTIONS_JS)
    finally:
        page.close()
    assert any(t["scrolls"] for t in tables), f"no table of {name} scrolls at {PHONE[0]} px: the check would be empty"
    outside = [
        (t["text"], where, [round(x) for x in edges])
        for t in tables
        if t["start"] is not None
        for where, edges in (("at the start", t["start"]), ("scrolled to the end", t["end"]))
        if edges[0] < -0.5 or edges[1] > t["vw"] + 0.5
    ]
    assert outside == [], f"captions past the {PHONE[0]} px viewport on {name}: {outside}"


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
@pytest.mark.parametrize("viewport", [PHONE, DESKTOP], ids=["phone", "desktop"])
def test_a_chapter_shows_one_search_control_whose_name_holds_its_text(browser, site, viewport):
    page, _, _ = open_offline(browser, site / "04_frequency_response.html", viewport=viewport)
    try:
        page.wait_for_timeout(200)
        shown = page.evaluate(SEARCH_JS)
    finally:
        page.close()
    assert len(shown) == 1, f"search controls shown at {viewport[0]} px: {shown}"
    _tag, label, text = shown[0]
    # WCAG 2.5.3: a name given by aria-label must contain the visible text (an icon alone has none)
    assert label is None or text.lower() in label.lower(), shown[0]


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_equations_wider_than_a_phones_column_are_tab_stops(browser, site):
    page, _, _ = open_offline(browser, site / "04_frequency_response.html", viewport=PHONE)
    try:
        page.wait_for_timeout(300)
        found = page.evaluate(
            """() => [...document.querySelectorAll('math[display="block"]')]
                 .filter(m => m.getClientRects().length && m.scrollWidth > m.clientWidth + 1)
                 .map(m => m.tabIndex)"""
        )
    finally:
        page.close()
    assert found, f"no displayed equation overflows at {PHONE[0]} px: the check would be empty"
    assert all(i == 0 for i in found), found
