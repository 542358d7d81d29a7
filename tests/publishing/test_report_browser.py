"""The kernel-free slider panel inside the book, opened from disk with the network blocked."""

from __future__ import annotations

import pytest
from conftest import SCREENSHOT_DIR as SCREENSHOTS
from conftest import open_offline, panel_state

from vibration.book.publishing import report

# every test here builds on a study or a book that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("book") / "report"
    chapters = report.select(report.discover(), ["05"])
    report.book_from_sources(chapters, out, pdf=False)
    return out


def _move(page, index: int, selector: str, value: str) -> None:
    page.evaluate(
        """([i, sel, v]) => {
            const el = document.querySelectorAll('div.vib-panel')[i].querySelector(sel);
            el.value = v;
            el.dispatchEvent(new Event('input', {bubbles: true}));
        }""",
        [index, selector, value],
    )


@pytest.mark.browser
def test_slider_panel_works_in_the_book(built, browser):
    page, outside, errors = open_offline(browser, built / "05_explore.html", viewport=(1280, 900))
    try:
        images = page.evaluate("() => [...document.images].map(i => [i.complete, i.naturalWidth])")
        assert all(ok and width > 0 for ok, width in images), images
        assert page.locator("div.vib-panel").count() == 1
        before = panel_state(page, 0)
        _move(page, 0, "input.vib-omega", "3")
        after_w = panel_state(page, 0)
        assert after_w["points"] != before["points"] and after_w["readout"] != before["readout"]
        assert after_w["frf"] != before["frf"]
        _move(page, 0, "input.vib-logc", "900")
        after_c = panel_state(page, 0)
        assert after_c["points"] != after_w["points"] and after_c["readout"] != after_w["readout"]
        assert "overdamped" in after_c["readout"]
        width = page.evaluate("() => document.querySelector('div.vib-panel').getBoundingClientRect().width")
        column = page.evaluate("() => document.querySelector('article.bd-article').getBoundingClientRect().width")
        assert width <= column + 1, (width, column)
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.locator("div.vib-panel").first.screenshot(path=str(SCREENSHOTS / "book_05_explore_sliders.png"))
        assert outside == [], outside
        assert errors == [], errors
    finally:
        page.close()
