"""The Duffing chapter's presentation: figures, tables, sentences and the kernel-free panel (JS vs Python)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import open_offline

from vibration import Duffing, ParameterError, folds, hb_amplitudes, response_curve
from vibration.presentation import duffing as pres
from vibration.presentation.style import legend_overlap
from vibration.publishing.mathml import external_urls


@pytest.fixture(scope="module")
def study():
    return pres.duffing_study(n_sweep=60, n_lyapunov=300)


def test_figures_keep_legends_off_the_data(study):
    import matplotlib.pyplot as plt

    for make in (pres.frequency_response_figure, pres.sweep_figure, pres.chaos_figure):
        fig = make(study)
        for ax in fig.axes:
            if ax.get_legend() is not None:
                assert legend_overlap(ax) == 0.0, make.__name__
        plt.close(fig)
    fig = pres.paper_figure(study)
    assert fig.axes[0].get_legend() is not None
    plt.close(fig)


def test_tables_have_names_units_and_no_nan(study):
    for make in (pres.hb_table, pres.stability_table, pres.fold_table, pres.history_table, pres.lyapunov_table,
                 pres.lyapunov_runs_table, pres.lyapunov_convergence_table, pres.checks_table):  # fmt: skip
        t = make(study)
        assert t.name.startswith("tab-duffing-")
        text = repr(t)
        assert "nan" not in text.lower()
    assert all(r["agree"] is True for r in pres.stability_table(study).rows)


def test_sentences_follow_the_results(study):
    note = pres.closing_note(study)
    for r in pres.fold_comparison(study):
        assert f"{r['hb']:.5g}" in note and f"{r['time']:.5g}" in note
    assert "chaotic" in pres.lyapunov_sentence(study)
    for r in pres.fold_comparison(study):
        assert f"{r['orbit']:.6g}" in note and r["inside"] is True
    pooled, se, _, _ = study.pooled
    assert f"{pres._pm(pooled, se)}" in pres.lyapunov_sentence(study)
    assert "share no trajectory" in pres.lyapunov_sentence(study) and "by construction" in pres.lyapunov_sentence(study)


def test_published_comparison_keeps_to_its_scope(study):
    import dataclasses

    text = pres.published_sentence(study)
    assert "0.0999" in text and "standard errors" in text
    other = dataclasses.replace(study, F0_ueda=5.0)
    assert "no published value to compare with" in pres.published_sentence(other)
    assert "beyond it" in pres.trust_sentence(study)  # 2.237 m > 1.77 m at k3 = 2 N/m^3
    assert "whichever way" in pres.paper_sentence(study)


def test_panel_fragment_is_self_contained():
    frag = pres.hb_panel_html()
    assert frag.startswith('<div class="vib-duffing"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == [] and "http" not in frag.replace("http://www.w3.org/2000/svg", "")
    assert "window.vibrationDuffing" in frag and 'type="range"' in frag and "N/m" in frag
    with pytest.raises(ParameterError, match="k3"):
        pres.hb_panel_html(k3=10.0, k3_range=5.0)
    with pytest.raises(ParameterError, match="c"):
        pres.hb_panel_html(c=0.0)


def test_explorer_bundle_carries_the_static_panel():
    ex = pres.hb_explorer()
    ex.F0_slider.value = 10.0
    bundle = ex._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert bundle["text/html"].startswith('<div class="vib-duffing"') and "10.0" in bundle["text/html"]


def _page(tmp_path, frag):
    path = tmp_path / "duffing.html"
    path.write_text(f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"></head><body>{frag}</body></html>')
    return path


#: JavaScript against Python: amplitudes and folds relative, same number of roots and stabilities.
RTOL_JS = 1e-9


@pytest.mark.browser
def test_js_roots_and_folds_match_python(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, pres.hb_panel_html()))
    try:
        rng = np.random.default_rng(12)
        cases = [(1.0, 0.5, 20.0, 2.0, 5.0), (1.0, 0.5, 20.0, -1.0, 5.0), (1.0, 0.05, 1.0, 0.5, 0.3)]
        for _ in range(25):
            m, k = 10 ** rng.uniform(-0.5, 0.5), 10 ** rng.uniform(0, 1.5)
            c = 10 ** rng.uniform(-2, -0.5) * math.sqrt(k * m)
            cases.append((m, c, k, rng.uniform(-0.3, 3) * k, 10 ** rng.uniform(-1, 0.5) * k))
        n_roots = 0
        for m, c, k, k3, F0 in cases:
            d = Duffing(m, c, k, k3)
            p = {"m": m, "c": c, "k": k, "k3": k3, "F0": F0, "omega_max": 3 * d.natural_frequency}
            for w in rng.uniform(0.2, 2.0, 8) * d.natural_frequency:
                js = page.evaluate("([p, w]) => window.vibrationDuffing.hbAmplitudes(p, w)", [p, float(w)])
                py = hb_amplitudes(d, F0, float(w))
                assert len(js) == len(py)
                for (aj, sj), (ap, sp) in zip(js, py, strict=True):
                    assert aj == pytest.approx(ap, rel=RTOL_JS) and sj == sp
                n_roots += len(py)
            fj = page.evaluate("p => window.vibrationDuffing.folds(p)", p)
            fp = folds(d, F0)
            if fp.bistable:
                assert fj["omega_low"] == pytest.approx(fp.omega_low, rel=RTOL_JS)
                assert fj["omega_high"] == pytest.approx(fp.omega_high, rel=RTOL_JS)
            elif math.isnan(fp.omega_high):
                assert fj["omega_low"] is None or fj["omega_low"] != fj["omega_low"]  # NaN arrives as None
            cj = page.evaluate("p => window.vibrationDuffing.responseCurve(p, 400)", p)
            if math.isfinite(fp.peak_amplitude):
                w_py, a_py, s_py = response_curve(d, F0, p["omega_max"], n=400)
                np.testing.assert_allclose(cj["omega"], w_py, rtol=RTOL_JS)
                np.testing.assert_allclose(cj["A"], a_py, rtol=RTOL_JS)
                assert cj["stable"] == list(s_py)
        assert n_roots > 200
        assert outside == [] and errors == []
    finally:
        page.close()


@pytest.mark.browser
def test_panel_sliders_redraw_offline(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, pres.hb_panel_html()))
    try:

        def state():
            return page.evaluate(
                """() => { const p = document.querySelector('div.vib-duffing');
                   return {n: p.querySelectorAll('polyline.vd-unstable').length,
                           folds: p.querySelectorAll('circle.vd-fold').length,
                           text: p.querySelector('p.vd-readout').textContent,
                           k3: p.querySelector('output.vd-k3-out').textContent}; }"""
            )

        s0 = state()
        f = folds(Duffing(1.0, 0.5, 20.0, 2.0), 5.0)
        assert s0["folds"] == 2 and s0["n"] >= 1 and f"{f.omega_low:.5g}" in s0["text"]
        page.eval_on_selector(
            "input.vd-k3", "el => { el.value = '0.1'; el.dispatchEvent(new Event('input', {bubbles: true})); }"
        )
        s1 = state()
        assert s1["folds"] == 0 and s1["n"] == 0 and "No folds" in s1["text"] and s1["k3"].startswith("0.1")
        page.eval_on_selector(
            "input.vd-k3", "el => { el.value = '-1'; el.dispatchEvent(new Event('input', {bubbles: true})); }"
        )
        assert state()["folds"] == 2
        page.locator("div.vib-duffing").screenshot(path="/tmp/duffing_panel.png")
        assert outside == [] and errors == []
    finally:
        page.close()
