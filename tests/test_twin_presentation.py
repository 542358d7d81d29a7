"""The digital-twin chapter's figures, tables and sliders (the kernel-free panel in headless Chromium)."""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from conftest import open_offline

from vibration import Oscillator, ParameterError
from vibration.physics import twin
from vibration.presentation import twin as show
from vibration.presentation.style import legend_overlap
from vibration.publishing.mathml import external_urls

matplotlib.use("Agg")

SCREENSHOTS = Path(__file__).resolve().parents[1] / "build" / "screenshots"
OSC = Oscillator(1.0, 0.5, 20.0)


@pytest.fixture(scope="module")
def small():
    """A short chapter run: fit, FRF estimates, small Monte Carlo and detection experiments."""
    test = twin.simulated_test(OSC, 40.0, 0.02, 0.05, seed=1)
    fit = twin.identify(**test)
    frf = twin.frf_estimate(**test)
    hp, cf = twin.frequency_estimates(frf)
    main = twin.identification_experiment(OSC, duration=20.0, runs=12, seed=2)
    by_noise, by_length = twin.identification_sweep(OSC, noises=(0.01, 0.1), durations=(20.0, 40.0), runs=6)
    sc = twin.fault_scenario(20.0, 120.0, 0.02, 0.001, 0.1)
    rec = twin.synthetic_measurements(OSC, sc.t, twin.random_force(sc.t, seed=3), noise=0.01, stiffness=sc.k)
    track = twin.track_stiffness(**rec, reference=fit)
    det = twin.detect_change(**rec, reference=fit)
    study = twin.detection_study(OSC, fit, 100.0, 0.02, 0.02, 0.001, 0.1, runs=4, thresholds=(10.0, 40.0, 160.0))
    return locals()


def test_figures_have_free_legends(small):
    figs = [
        show.identification_figure(small["test"], small["fit"], small["frf"]),
        show.scaling_figure(small["by_noise"], small["by_length"]),
        show.tracking_figure(small["track"], small["sc"].k, small["det"]),
        show.tradeoff_figure(small["study"]),
    ]
    for fig in figs:
        for ax in fig.axes:
            if ax.get_legend() is not None:
                assert legend_overlap(ax) == 0.0, ax.get_title()
        matplotlib.pyplot.close(fig)


def test_tables_and_sentences_follow_the_results(small):
    fit = small["fit"]
    tab = show.identification_table(fit, OSC, small["hp"], small["cf"], frf_record=160.0)
    text = repr(tab)
    assert "tab-twin-identified" in text and "k (N/m)" in text and not re.search(r"\bnan\b", text)
    assert f"{fit.k:.5g}" in text
    cov = repr(show.coverage_table([small["main"], *small["by_noise"]]))
    assert "coverage k" in cov and "12" in cov
    det = repr(show.detection_table(small["study"], 40.0))
    assert "sudden drop" in det and "slow decline" in det
    s = show.identification_sentence(fit, OSC)
    assert f"{fit.k:.5g}" in s and "standard errors" in s
    note = show.closing_note(small["main"], small["by_noise"], small["by_length"], small["study"], 40.0)
    assert "95 % intervals" in note and "mean delay" in note
    checks = repr(show.twin_checks_table({"a": (1e-12, 1e-10), "b": (2.0, 1.0)}))
    assert "< 1e-10" in checks and "yes" in checks and "no" in checks


def test_panel_fragment_is_self_contained():
    g = twin.estimate_grid(OSC, noises=(0.01, 0.1), durations=(20.0, 40.0))
    frag = show.twin_panel_html(g)
    assert frag.startswith('<div class="twin-panel"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == [] and "http" not in frag
    with pytest.raises(ParameterError, match="panel_id"):
        show.twin_panel_html(g, panel_id="x</script>")


@pytest.mark.browser
def test_panel_in_chromium_matches_the_grid(browser, tmp_path):
    g = twin.estimate_grid(OSC, noises=(0.005, 0.02, 0.1, 0.4), durations=(10.0, 20.0, 40.0))
    frag = show.twin_panel_html(g)
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
                """() => Array.from(document.querySelectorAll('.twin-readout tbody tr')).map(r =>
                    ['.twin-est', '.twin-lo', '.twin-hi', '.twin-in'].map(s => r.querySelector(s).textContent))"""
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
            assert page.eval_on_selector_all("svg.twin-plot circle", "c => c.length") == 3
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.locator(".twin-panel").screenshot(path=str(SCREENSHOTS / "twin_panel.png"))
        assert outside == [] and errors == []
    finally:
        page.close()
