"""axe-core (bundled by axe-playwright-python, pinned) on the book's pages, in the theme's light and dark modes.

`make test` checks a sample of pages (the front page, one Part I and one Part II chapter with a panel);
`make test-slow` checks every page. The site is built from the committed notebooks, as in tests/publishing/test_book.py.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import open_offline

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ("index.html", "05_explore.html", "07_control.html")


@pytest.fixture(scope="module")
def site(committed_book) -> Path:
    return committed_book


def violations(browser, path: Path, mode: str, viewport=(1280, 900)) -> list[str]:
    """axe-core's violations on one page in ``mode`` ("light" or "dark"): rule id, impact and the first target."""
    from axe_playwright_python.sync_playwright import Axe

    page, _outside, errors = open_offline(browser, path, viewport=viewport)
    try:
        page.evaluate(
            "(mode) => { const d = document.documentElement.dataset; d.theme = mode; d.mode = mode; }",
            mode,
        )
        page.wait_for_timeout(200)
        results = Axe().run(page)
        found = []
        for v in results.response["violations"]:
            targets = [", ".join(n["target"]) for n in v["nodes"][:3]]
            found.append(
                f"{path.name} [{mode}, {viewport[0]} px] {v['id']} ({v['impact']}, {len(v['nodes'])} nodes): {targets}"
            )
        return found
    finally:
        page.close()


@pytest.mark.browser
@pytest.mark.parametrize(
    "mode",
    ["light", pytest.param("dark", marks=pytest.mark.slow)],  # dark mode: every page, with the slow tests
    ids=["lightmode", "darkmode"],
)
@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_sample_pages_have_no_axe_violations(browser, site, mode):
    found = [v for name in SAMPLE for v in violations(browser, site / name, mode)]
    assert not found, "\n".join(found)


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_a_chapter_at_a_phones_width_has_no_axe_violations(browser, site):
    """At 390 px wide tables and equations scroll sideways in their own boxes: each must be reachable by keyboard."""
    found = violations(browser, site / "04_frequency_response.html", "light", viewport=(390, 844))
    assert not found, "\n".join(found)


@pytest.mark.slow
@pytest.mark.browser
@pytest.mark.parametrize("mode", ["light", "dark"], ids=["lightmode", "darkmode"])  # "light" alone marks slow
def test_every_page_has_no_axe_violations(browser, site, mode):
    found = [v for path in sorted(site.glob("*.html")) for v in violations(browser, path, mode)]
    assert not found, "\n".join(found)


@pytest.mark.browser
@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_a_page_follows_the_readers_light_or_dark_preference(browser, site, scheme):
    """With no choice stored, a page opens in the operating system's preference (the theme's "auto" mode)."""
    context = browser.new_context(color_scheme=scheme, viewport={"width": 1280, "height": 900})
    try:
        page = context.new_page()
        page.goto((site / "01_reproduction.html").as_uri())
        page.wait_for_load_state("load")
        assert page.evaluate("document.documentElement.dataset.theme") == scheme
        background = page.evaluate("getComputedStyle(document.body).backgroundColor")
        rgb = [int(x) for x in background[background.index("(") + 1 : background.index(")")].split(",")[:3]]
        assert (sum(rgb) / 3 > 128) == (scheme == "light"), background
    finally:
        context.close()
