"""A panel's words that hold only on the screen ("computed in your browser") are not printed.

The printed edition (Chromium printing the book with its style sheet) shows each panel at its starting values,
with no browser computing anything: the panels with such words must put them in the screen-only span and
may give the printed words instead. Checked on the HTML, against the book's style sheet, and in Chromium with
print media emulated.
"""

from __future__ import annotations

import re
from importlib.resources import files

import pytest

from vibration.book.presentation.panels import screen_words

SCREEN, PRINT = "vib-web-only", "vib-print-only"
#: What a printed page must not claim.
BROWSER = re.compile(r"in your browser", re.I)


def _book_css() -> str:
    return files("vibration.book.publishing").joinpath("book.css").read_text(encoding="utf-8")


def _without(html: str, cls: str) -> str:
    """``html`` without the spans of class ``cls`` (the panels' spans hold no nested span)."""
    return re.sub(rf'<span class="{cls}"[^>]*>.*?</span>', "", html, flags=re.S)


def _text(html: str) -> str:
    html = re.sub(r"<(script|style)\b.*?</\1>", " ", html, flags=re.S)
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", html))


def test_screen_words_are_a_screen_span_and_the_printed_words_a_hidden_print_span():
    html = screen_words(", computed in your browser", ", drawn from the closed form")
    assert html.count("<span") == 2
    screen = re.fullmatch(
        r'<span class="vib-web-only">(.*?)</span><span class="(.*?)" style="(.*?)">(.*?)</span>', html
    )
    assert screen is not None, html
    assert screen.group(1) == ", computed in your browser"
    assert screen.group(2) == PRINT and screen.group(3) == "display: none"  # hidden without the book's style sheet
    assert screen.group(4) == ", drawn from the closed form"
    assert screen_words("on screen") == '<span class="vib-web-only">on screen</span>'  # no printed words: none


def test_the_books_print_rules_hide_the_screen_words_and_show_the_printed_ones_over_the_inline_style():
    css = _book_css()
    blocks = re.findall(r"@media print\s*\{(.*?)\n\}", css, flags=re.S)
    assert blocks, "the book's style sheet has a print block"
    rules = " ".join(blocks)
    assert re.search(rf"\.{SCREEN}\s*\{{\s*display:\s*none\s*!important", rules)
    assert re.search(rf"\.{PRINT}\s*\{{\s*display:\s*inline\s*!important", rules)  # beats style="display: none"
    screen_rules = css.replace(rules, "")
    assert re.search(rf"\.{PRINT}\s*\{{\s*display:\s*none", screen_rules)


def _panels(request) -> dict:
    from vibration.book.chapters.duffing.panel import hb_panel_html
    from vibration.book.chapters.real_oscillator.panel import decay_panel_html
    from vibration.book.chapters.stability.panel import stability_panel_html
    from vibration.book.chapters.tmd.panel import tmd_panel_html

    return {
        "stability": stability_panel_html,
        "tmd": lambda: tmd_panel_html(0.05),
        "duffing": hb_panel_html,
        "real_oscillator": lambda: decay_panel_html(request.getfixturevalue("real_oscillator_default")),
    }


#: The panels whose sub-heading said the readout is computed in the reader's browser.
PANELS = ("stability", "tmd", "duffing", "real_oscillator")


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.parametrize("name", PANELS)
def test_a_panel_says_computed_in_your_browser_on_the_screen_only(request, name):
    html = _panels(request)[name]()
    assert BROWSER.search(_text(_without(html, PRINT))), "the screen still says where the panel is computed"
    printed = _text(_without(html, SCREEN))
    assert not BROWSER.search(printed), (name, printed[:400])
    assert not re.search(r"\b(move|drag)\b", printed, flags=re.I), "the printed panel names no control to move"


@pytest.mark.browser
@pytest.mark.parametrize(
    "name", [pytest.param(n, marks=pytest.mark.slow) if n == "real_oscillator" else n for n in PANELS]
)
def test_printed_panel_shows_no_browser_words_and_the_screen_shows_them(browser, tmp_path, request, name):
    page_html = f"<!doctype html><html><head><meta charset='utf-8'><style>{_book_css()}</style></head><body>"
    page_html += _panels(request)[name]() + "</body></html>"
    path = tmp_path / f"{name}.html"
    path.write_text(page_html, encoding="utf-8")
    page = browser.new_page()
    try:
        page.goto(path.as_uri())
        seen = {}
        for media in ("screen", "print"):
            page.emulate_media(media=media)
            seen[media] = page.evaluate("() => document.body.innerText")
        assert BROWSER.search(seen["screen"]), seen["screen"][:300]
        assert not BROWSER.search(seen["print"]), seen["print"][:300]
    finally:
        page.close()
