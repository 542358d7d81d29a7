"""The panels' shared plotting helper (``presentation/assets/plot.js``, ``window.VibPlot``) and the panels drawn
with it: its number format against Python's :func:`vibration.book.presentation.tables.fmt`, its ticks, and every
refactored panel in headless Chromium at a phone's and a desktop's width.

Number format. ``VibPlot.fmt`` follows ``tables.fmt`` character for character: Python's "g" rules, rounding
half to even, ×10ⁿ instead of e-notation, a true minus sign "−".
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from conftest import SCREENSHOTS, open_offline

from vibration import Oscillator
from vibration.book.presentation.panels import DASH, case_styles, line_style, panel_assets, plot_js
from vibration.book.presentation.style import CASES
from vibration.book.presentation.tables import fmt
from vibration.book.publishing.mathml import external_urls

#: Widths of the viewport: a phone (390 CSS px) and a desktop (1280 CSS px).
WIDTHS = (390, 1280)
#: The panels drawn with the helper (chapter packages).
PANELS = ("control", "stability", "tmd", "digital_twin", "real_oscillator", "duffing", "explore")
#: The panels whose layout `make test` checks (one of Part I, one of Part II, the lab's); the others run with the
#: slow tests, which CI runs too.
SAMPLE = ("explore", "control", "real_oscillator")
#: Tolerance of the bounding-box comparisons, CSS px (sub-pixel rounding of text boxes).
SLACK = 0.5

_SUPER = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _number(text: str) -> float:
    """The value of a label in the book's format ("−2.5", "3×10⁻⁵", "10⁴")."""
    t = text.replace("−", "-")
    m = re.fullmatch(r"(-?[0-9.]+×)?(-?)10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)", t)
    if m:
        mant = float(m.group(1)[:-1]) if m.group(1) else (-1.0 if m.group(2) else 1.0)
        return mant * 10.0 ** int(m.group(3).translate(_SUPER))
    return float(t)


def _blank(tmp_path: Path, body: str = "", name: str = "plot.html") -> Path:
    path = tmp_path / name
    path.write_text(
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><meta name="viewport" '
        f'content="width=device-width"><title>plot</title></head><body>{body}</body></html>\n',
        encoding="utf-8",
    )
    return path


@pytest.fixture(scope="module")
def helper_page(browser, tmp_path_factory):
    """A page with the helper alone (offline): (page, outside requests, console errors)."""
    path = _blank(tmp_path_factory.mktemp("plot"), f"<script>\n{plot_js()}</script>")
    page, outside, errors = open_offline(browser, path)
    yield page, outside, errors
    page.close()


# ----------------------------------------------------------------------------- Python side


def test_assets_put_the_helper_first_and_name_no_url():
    block = panel_assets("vibration.book.chapters.tmd", "tmd.js", "tmd.css")
    assert block.startswith("<style>") and block.count("<script>") == 2
    assert block.index("window.VibPlot") < block.index("window.vibrationTMD")
    assert external_urls(block) == [] and "http" not in plot_js()


def test_line_styles_are_the_books_cases():
    styles = case_styles(*CASES)
    for name, case in CASES.items():
        assert styles[name]["color"].lower() == case["color"].lower()
        assert styles[name]["dash"] == DASH[case["linestyle"]]
    assert DASH["-"] == "" and len({DASH["--"], DASH[":"], DASH["-."]}) == 3  # three distinct dash patterns
    assert line_style({"color": "0.35", "ls": "--"}, 2.0) == {"color": "#595959", "dash": DASH["--"], "width": 2.0}
    with pytest.raises(KeyError, match="allowed"):
        line_style("no such case")


# ----------------------------------------------------------------------------- the helper in Chromium


def _random_numbers(n: int, seed: int) -> list[tuple[float, int, bool]]:
    """(value, digits, zeros): magnitudes log-uniform from 1e-12 to 1e9, both signs, 2 to 5 digits."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        v = float(10 ** rng.uniform(-12, 9)) * float(rng.choice([-1.0, 1.0]))
        out.append((v, int(rng.integers(2, 6)), bool(rng.integers(2))))
    return out


#: Hand-picked cases: ties (Python rounds half to even), powers of ten, the fixed/exponent boundaries, zero.
EDGES = [(0.125, 2, False), (0.375, 2, False), (12.5, 2, True), (2.5, 1, False), (1234.5, 4, False),
         (9999.5, 4, False), (99999.0, 5, False), (100000.0, 5, True), (1e-5, 2, True), (1e-5, 1, False),
         (-1e-12, 3, False), (0.0001, 3, True), (0.00012345, 4, False), (0.1, 3, True), (15.0, 3, True),
         (-2.5e-9, 2, False), (31540.0, 3, False), (1.273e5, 4, False), (0.0, 3, False), (0.0, 3, True)]  # fmt: skip


@pytest.mark.browser
def test_number_format_equals_python(helper_page):
    page, outside, errors = helper_page
    cases = _random_numbers(60, 20250101) + EDGES
    got = page.evaluate("cs => cs.map(c => window.VibPlot.fmt(c[0], c[1], c[2]))", [list(c) for c in cases])
    for (v, digits, zeros), js in zip(cases, got, strict=True):
        assert js == fmt(v, digits, zeros), (v, digits, zeros)
        assert "e" not in js and "-" not in js
    special = page.evaluate("() => [NaN, Infinity, -Infinity].map(v => window.VibPlot.fmt(v, 3))")
    assert special == [fmt(math.nan), fmt(math.inf), fmt(-math.inf)]
    fixed = page.evaluate("() => [window.VibPlot.fixed(-0.0001, 3), window.VibPlot.fixed(-1.5, 2)]")
    assert fixed == ["0.000", "−1.50"]  # a slider's readout: never "−0.000", a true minus
    assert outside == [] and errors == []


@pytest.mark.browser
def test_ticks_are_nice_and_cover_the_range(helper_page):
    page, outside, errors = helper_page
    rng = np.random.default_rng(5)
    ranges = []
    for _ in range(60):
        scale = 10 ** rng.uniform(-9, 8)
        a, b = sorted(rng.uniform(-1, 1, 2) * scale)
        ranges.append((float(a), float(b), int(rng.integers(2, 9))))
    ranges += [(0.0, 10.0, 5), (0.4, 1.6, 6), (-2.0, 2.0, 4), (0.0, 1e-5, 4), (-0.05, 2.05, 4)]
    out = page.evaluate(
        """rs => rs.map(r => {
            const t = window.VibPlot.ticks(r[0], r[1], r[2]);
            const step = window.VibPlot.niceStep(r[1] - r[0], r[2]);
            return {t, step, labels: t.map(v => window.VibPlot.tickText(v, step))};
        })""",
        [list(r) for r in ranges],
    )
    for (lo, hi, n), res in zip(ranges, out, strict=True):
        t, step = np.array(res["t"]), res["step"]
        mant = step / 10 ** math.floor(math.log10(step) + 1e-12)
        assert min(abs(mant - m) for m in (1, 2, 5, 10)) < 1e-9, (lo, hi, step)  # 1, 2 or 5 times 10ⁿ
        assert (hi - lo) / (2.5 * n) <= step <= 2.5 * (hi - lo) / n  # about n intervals
        tol = 1e-9 * step
        assert np.all(t >= lo - tol) and np.all(t <= hi + tol)  # inside the range
        assert t[0] - lo < step + tol and hi - t[-1] < step + tol  # and none missing at its ends
        np.testing.assert_allclose(np.diff(t), step, rtol=1e-9)  # evenly spaced
        np.testing.assert_allclose(t / step, np.round(t / step), atol=1e-6)  # on multiples of the step
        labels = res["labels"]
        assert len(set(labels)) == len(labels)  # distinct labels for distinct ticks
        for v, label in zip(t, labels, strict=True):
            assert abs(_number(label) - v) <= 1e-6 * step, (label, v)
            assert "e" not in label and "-" not in label
    decades = page.evaluate(
        "rs => rs.map(r => window.VibPlot.logTicks(r[0], r[1]))", [[0.3, 4.0], [0.01, 1000.0], [1e-9, 1e6], [2.0, 3.0]]
    )
    assert decades[0] == [0.5, 1, 2]  # under three decades: 1, 2 and 5 times a power of ten
    assert decades[1] == [0.01, 0.1, 1, 10, 100, 1000]
    assert decades[2][0] >= 1e-9 and decades[2][-1] == 1e6 and len(decades[2]) <= 9  # thinned, ends kept in range
    assert len(decades[3]) >= 2 and all(2.0 <= v <= 3.0 for v in decades[3])  # within a decade: linear ticks
    assert outside == [] and errors == []


@pytest.mark.slow  # over 1 s: make test-slow runs it
@pytest.mark.browser
def test_helper_loads_twice_and_redraws_at_the_new_width(browser, tmp_path):
    js = plot_js()
    body = (
        f'<div id="box"><svg id="s" role="img" aria-label="test"></svg></div><script>{js}</script>'
        "<script>window.VibPlot.mark = 1;</script>"
        f"<script>{js}</script>"
        """<script>window.VibPlot.draw(document.getElementById('s'), {height: 200,
            x: {label: "ω/ω_n", log: true}, y: {label: "|X/Y|", log: true},
            series: [{type: "line", x: [0.1, 1, 10], y: [1, 10, 0.01], label: "curve"},
                     {type: "line", x: [0.1, 1, 10], y: [NaN, 2, 3], dash: "6 4", label: "other"}]});</script>"""
    )
    page, outside, errors = open_offline(browser, _blank(tmp_path, body), viewport=(1280, 700))
    try:
        assert page.evaluate("() => window.VibPlot.mark") == 1  # the second copy changed nothing
        # the first draw may come before layout; the resize observer redraws at the laid-out width
        page.wait_for_function(
            "() => { const s = document.getElementById('s');"
            " return Math.abs(s.viewBox.baseVal.width - s.clientWidth) <= 1; }",
            timeout=10_000,
        )
        assert page.evaluate("() => document.getElementById('s').clientWidth") > 1000
        sub = page.evaluate("() => [...document.querySelectorAll('#s tspan')].map(t => t.textContent)")
        assert "n" in sub  # ω_n: the n is a subscript
        assert page.evaluate("() => document.querySelectorAll('#s polyline').length") == 2  # NaN breaks the line
        page.set_viewport_size({"width": 390, "height": 700})
        page.wait_for_function("() => document.getElementById('s').viewBox.baseVal.width < 400")
        assert page.evaluate("() => document.getElementById('s').viewBox.baseVal.width") == pytest.approx(
            page.evaluate("() => document.getElementById('s').clientWidth"), abs=1
        )
        assert outside == [] and errors == []
    finally:
        page.close()


# ----------------------------------------------------------------------------- the panels


def _fragment(name: str, request) -> tuple[str, str]:
    """The panel ``name``'s CSS selector and HTML fragment, built only for the panels a run tests."""
    from vibration.book.chapters.control.panel import control_panel_html
    from vibration.book.chapters.digital_twin.panel import twin_panel_html
    from vibration.book.chapters.duffing.panel import hb_panel_html
    from vibration.book.chapters.explore.panel import slider_panel_html
    from vibration.book.chapters.real_oscillator.panel import decay_panel_html
    from vibration.book.chapters.stability.panel import stability_panel_html
    from vibration.book.chapters.tmd.panel import tmd_panel_html
    from vibration.physics import twin

    def twin_html():
        osc = Oscillator(m=1.0, c=0.5, k=20.0)
        return twin_panel_html(twin.estimate_grid(osc, noises=(0.005, 0.1, 0.4), durations=(10.0, 40.0)))

    build = {
        "control": ("div.vc-panel", control_panel_html),
        "stability": ("div.vst-panel", stability_panel_html),
        "tmd": ("div.vtm-panel", lambda: tmd_panel_html(0.05)),
        "digital_twin": ("div.twin-panel", twin_html),
        "real_oscillator": (
            "div.vro-panel",
            lambda: decay_panel_html(request.getfixturevalue("real_oscillator_default")),
        ),
        "duffing": ("div.vib-duffing", hb_panel_html),
        "explore": ("div.vib-panel", slider_panel_html),
    }
    sel, make = build[name]
    return sel, make()


#: Every element of a panel inside the panel (left and right), every SVG element inside its SVG (lines clipped
#: to the plot area excepted: their clip rectangle is the drawn frame), and no two texts of a plot overlapping.
LAYOUT = """([sel, s]) => {
  const bad = [], overlaps = [];
  const box = b => ({l: b.left, r: b.right, t: b.top, b: b.bottom});
  document.querySelectorAll(sel).forEach(panel => {
    const pb = box(panel.getBoundingClientRect());
    panel.querySelectorAll('*').forEach(e => {
      if (['STYLE', 'SCRIPT', 'NOSCRIPT', 'defs', 'clipPath', 'title'].includes(e.tagName)) return;
      if (e.closest('defs') || e.closest('[clip-path]')) return;
      const b = box(e.getBoundingClientRect());
      if (b.r - b.l === 0 && b.b - b.t === 0) return;
      const svg = e.closest('svg');
      const inner = svg && svg !== e;
      const c = inner ? box(svg.getBoundingClientRect()) : pb;
      if (b.l < c.l - s || b.r > c.r + s || (inner && (b.t < c.t - s || b.b > c.b + s))) {
        bad.push([e.tagName, e.getAttribute('class'), (e.textContent || '').slice(0, 30)]);
      }
    });
    panel.querySelectorAll('svg').forEach(svg => {
      const texts = [...svg.querySelectorAll('text')].filter(t => !t.closest('[clip-path]'))
        .map(t => [t.textContent, box(t.getBoundingClientRect())]).filter(x => x[0].trim());
      for (let i = 0; i < texts.length; i++) for (let j = i + 1; j < texts.length; j++) {
        const a = texts[i][1], b = texts[j][1];
        if (Math.min(a.r, b.r) - Math.max(a.l, b.l) > 1 && Math.min(a.b, b.b) - Math.max(a.t, b.t) > 1) {
          overlaps.push([texts[i][0], texts[j][0]]);
        }
      }
    });
  });
  return {bad, overlaps, scroll: document.documentElement.scrollWidth, inner: window.innerWidth,
          svgs: document.querySelectorAll(sel + ' svg').length};
}"""


@pytest.mark.slow  # over 1 s: make test-slow runs it
@pytest.mark.browser
@pytest.mark.parametrize("name", [n if n in SAMPLE else pytest.param(n, marks=pytest.mark.slow) for n in PANELS])
def test_panel_fits_a_phone_and_a_desktop(browser, tmp_path, request, name):
    sel, frag = _fragment(name, request)
    path = _blank(tmp_path, frag, f"{name}.html")
    for width in WIDTHS:
        page, outside, errors = open_offline(browser, path, viewport=(width, 900))
        try:
            page.wait_for_timeout(100)  # one animation frame for the resize observer
            res = page.evaluate(LAYOUT, [sel, SLACK])
            assert res["svgs"] >= 1
            assert res["bad"] == [], (name, width, res["bad"])
            assert res["overlaps"] == [], (name, width, res["overlaps"])
            assert res["scroll"] <= res["inner"], (name, width)  # no sideways scrolling
            drawn = page.evaluate(
                f"() => [...document.querySelectorAll('{sel} svg')].map(s => [s.viewBox.baseVal.width, s.clientWidth,"
                " s.querySelectorAll('polyline, circle, path, line').length])"
            )
            for vb, css, marks in drawn:
                assert vb == pytest.approx(css, abs=1) and marks > 0  # drawn at its width: text keeps its size
            Path(SCREENSHOTS).mkdir(parents=True, exist_ok=True)
            page.locator(sel).screenshot(path=str(Path(SCREENSHOTS) / f"panel_{name}_{width}.png"))
            assert outside == [] and errors == [], (name, width, outside, errors)
        finally:
            page.close()
