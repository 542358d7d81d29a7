"""The digital-twin chapter's figures, tables and sliders (the kernel-free panel in headless Chromium)."""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from conftest import open_offline

from vibration import Oscillator, ParameterError
from vibration.book.chapters.digital_twin import figures, tables, text
from vibration.book.chapters.digital_twin.panel import twin_panel_html
from vibration.book.chapters.digital_twin.study import digital_twin_study
from vibration.book.presentation.captions import check_caption
from vibration.book.presentation.style import legend_overlap
from vibration.book.publishing.mathml import external_urls
from vibration.physics import twin

# every test here builds on a study or a book that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

matplotlib.use("Agg")

SCREENSHOTS = Path(__file__).resolve().parents[3] / "build" / "screenshots"
OSC = Oscillator(m=1.0, c=0.5, k=20.0)
#: A short chapter run: every part of the study, few runs.
SMALL = dict(t_record=30.0, runs=20, sweep_runs=5, assumption_runs=20, t_monitor=120.0, detect_runs=5)


@pytest.fixture(scope="module")
def small():
    return digital_twin_study(**SMALL)


def test_figures_have_free_legends_and_true_captions(small):
    for make in (figures.identification_figure, figures.scaling_figure, figures.tracking_figure,
                 figures.tradeoff_figure):  # fmt: skip
        cap = make(small)
        check_caption(cap.fig, cap.caption)
        assert cap.name.startswith("fig-twin-") and "/" not in cap.alt
        assert "{" not in cap.caption, cap.caption  # every placeholder formatted
        for ax in cap.fig.axes:
            if ax.get_legend() is not None:
                assert legend_overlap(ax) == 0.0, ax.get_title()


def test_tables_and_sentences_follow_the_results(small):
    fit = small.fit
    tab = repr(tables.identification_table(small))
    assert "tab-twin-identified" in tab and "k (N/m)" in tab and not re.search(r"\bnan\b", tab)
    assert f"{fit.k:.5g}" in tab
    cov = repr(tables.coverage_table(small))
    assert "coverage k" in cov and f"{small.coverage.runs}" in cov
    det = repr(tables.detection_table(small))
    assert "sudden drop" in det and "slow decline" in det
    s = text.identification_sentence(small)
    assert "standard errors" in s
    # the sentence states k with its standard error, rounded to the error's last digit
    shown = re.search(r"k = (\d+\.?\d*) ± (\d+\.?\d*) N/m", s)
    assert shown, s
    k, err = float(shown.group(1)), float(shown.group(2))
    last = 10.0 ** -len(shown.group(2).partition(".")[2])
    assert abs(k - fit.k) <= 0.5 * last + 1e-12 and abs(err - fit.stderr[2]) <= 0.5 * last + 1e-12
    checks = repr(tables.checks_table(small))
    assert "measured difference" in checks and "yes" in checks


def test_panel_fragment_is_self_contained():
    g = twin.estimate_grid(OSC, noises=(0.01, 0.1), durations=(20.0, 40.0))
    frag = twin_panel_html(g)
    assert frag.startswith('<div class="twin-panel"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == [] and "http" not in frag
    with pytest.raises(ParameterError, match="panel_id"):
        twin_panel_html(g, panel_id="x</script>")


@pytest.mark.browser
def test_panel_in_chromium_matches_the_grid(browser, tmp_path):
    g = twin.estimate_grid(OSC, noises=(0.005, 0.02, 0.1, 0.4), durations=(10.0, 20.0, 40.0))
    frag = twin_panel_html(g)
    path = tmp_path / "twin.html"
    path.write_text(
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>twin</title></head><body>{frag}'
        "</body></html>",
        encoding="utf-8",
    )
    page, outside, errors = open_offline(browser, path, viewport=(900, 700))
    try:
        rng = np.random.default_rng(0)
        for _ in range(6):
            i, j = int(rng.integers(4)), int(rng.integers(3))
            page.eval_on_selector(
                "input.twin-noise", f"el => {{ el.value = '{i}'; el.dispatchEvent(new Event('input')); }}"
            )
            page.eval_on_selector(
                "input.twin-len", f"el => {{ el.value = '{j}'; el.dispatchEvent(new Event('input')); }}"
            )
            shown = page.evaluate(
                """() => Array.from(document.querySelectorAll('.twin-estimates tbody tr')).map(r =>
                    ['.twin-est', '.twin-lo', '.twin-hi', '.twin-in'].map(s => r.querySelector(s).textContent
                        .replace('\u2212', '-')))"""  # the book's minus sign, read back as a number
            )
            for p in range(3):
                est, lo, hi, inside = shown[p]
                # 5 significant figures shown: relative 5e-5
                assert float(est) == pytest.approx(g.estimates[i, j, p], rel=5e-5)
                assert float(lo) == pytest.approx(g.ci95[i, j, p, 0], rel=5e-5)
                assert float(hi) == pytest.approx(g.ci95[i, j, p, 1], rel=5e-5)
                covers = g.ci95[i, j, p, 0] <= g.truth[p] <= g.ci95[i, j, p, 1]
                assert inside == ("yes" if covers else "no")
            rel = page.evaluate(
                f"""() => {{ const root = document.querySelector('.twin-panel');
                    const grid = JSON.parse(root.getAttribute('data-grid'));
                    return window.vibrationTwin.relative(grid, window.vibrationTwin.cell(grid, {i}, {j})); }}"""
            )
            expect = 100 * (g.estimates[i, j] - g.truth) / g.truth
            np.testing.assert_allclose(rel["est"], expect, rtol=1e-12, atol=1e-12)
            assert page.eval_on_selector_all("svg.twin-plot circle.twin-dot", "c => c.length") == 3
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.locator(".twin-panel").screenshot(path=str(SCREENSHOTS / "twin_panel.png"))
        assert outside == [] and errors == []
    finally:
        page.close()


def test_the_explorer_is_on_the_panel_kit_and_reads_its_own_identification(small):
    """The explorer's readout gives the identification it draws, each 95 % interval against the true value,
    and a slider move re-identifies and redraws."""
    from vibration.book.chapters.digital_twin.panel import panel
    from vibration.book.presentation.numbers import sig
    from vibration.book.presentation.panels import KitExplorer

    ex = panel(small)
    assert isinstance(ex, KitExplorer)
    fit, before = ex.fit, ex.image.value
    for est, (lo, hi) in zip((fit.m, fit.c, fit.k), fit.ci95, strict=True):
        assert all(sig(x, 5) in ex.readout.value for x in (est, lo, hi))
    truth = (small.asset.m, small.asset.c, small.asset.k)
    covers = [lo <= true <= hi for true, (lo, hi) in zip(truth, fit.ci95, strict=True)]
    assert ex.readout.value.count(">yes<") == sum(covers)
    ex.noise_slider.value = ex.noise_slider.options[-1][1]
    assert ex.fit is not fit and ex.image.value != before
    bundle = ex._repr_mimebundle_()
    assert bundle["text/html"].startswith('<div class="twin-panel"') and "data-grid" in bundle["text/html"]
    assert bundle["text/plain"].startswith("TwinExplorer(") and bundle["image/png"]
