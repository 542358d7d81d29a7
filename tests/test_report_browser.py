"""The rendered report itself, opened from disk with the network blocked: figures, equations, sliders."""

from __future__ import annotations

import pytest
from conftest import open_offline
from test_static_page import SCREENSHOTS, _panel_state

from vibration.publishing import report


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    assert report.main(["01", "05", "--out", str(out)]) == 0
    return out / "report"


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
@pytest.mark.parametrize(("chapter", "panels"), [("01_reproduction", 2), ("05_explore", 1)])
def test_rendered_chapter_works_offline(built, browser, chapter, panels):
    page, outside, errors = open_offline(browser, built / f"{chapter}.html")
    try:
        images = page.evaluate("() => [...document.images].map(i => [i.complete, i.naturalWidth])")
        assert all(ok and width > 0 for ok, width in images), images
        assert page.locator("div.vib-panel").count() == panels
        if chapter == "01_reproduction":
            assert len(images) >= 2  # Figures 1 and 2
            assert page.locator("math").count() > 0  # equations render as MathML, no MathJax
        for i in range(panels):
            before = _panel_state(page, i)
            _move(page, i, "input.vib-omega", "3")
            after_w = _panel_state(page, i)
            assert after_w["points"] != before["points"] and after_w["readout"] != before["readout"]
            assert after_w["frf"] != before["frf"]
            _move(page, i, "input.vib-logc", "900")
            after_c = _panel_state(page, i)
            assert after_c["points"] != after_w["points"] and after_c["readout"] != after_w["readout"]
            assert "overdamped" in after_c["readout"]
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.locator("div.vib-panel").first.screenshot(path=str(SCREENSHOTS / f"report_{chapter}_sliders.png"))
        assert outside == [], outside
        assert errors == [], errors
    finally:
        page.close()


@pytest.mark.browser
def test_index_links_every_chapter(built, browser):
    page, outside, errors = open_offline(browser, built / "index.html")
    try:
        hrefs = page.evaluate("() => [...document.querySelectorAll('a')].map(a => a.getAttribute('href'))")
        assert {"01_reproduction.html", "05_explore.html"} <= set(hrefs)
        assert all((built / h).is_file() for h in hrefs if h.endswith(".html"))
        assert outside == [] and errors == []
    finally:
        page.close()
