"""The Duffing chapter's slider panel: the kernel-free fragment, the JupyterLab widget, and its JavaScript
against the Python closed forms. The chapter's figures, tables and sentences: test_duffing_chapter.py."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import open_offline

from vibration import Duffing, ParameterError, folds, hb_amplitudes, response_curve
from vibration.book.chapters.duffing import panel as pres
from vibration.book.presentation.style import case_style
from vibration.book.publishing.mathml import external_urls


def test_panel_fragment_is_self_contained():
    frag = pres.hb_panel_html()
    assert frag.startswith('<div class="vib-duffing"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == [] and "http" not in frag.replace("http://www.w3.org/2000/svg", "")
    assert "window.vibrationDuffing" in frag and 'type="range"' in frag and "N/m" in frag
    assert case_style("hardening")["color"] in frag and case_style("softening")["color"] in frag  # the book's colours
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
    assert bundle["text/plain"] == "HBExplorer(k₃ = 2 N/m³, F₀ = 10 N)"
    assert bundle["image/png"] and "peak A" in ex.readout.value


def test_explorer_readout_follows_the_closed_form_folds():
    """The readout's peak and fold frequencies are those of the harmonic balance at the sliders' values, and
    the panel kit drives it (a slider move redraws the figure and the readout)."""
    from vibration.book.presentation.numbers import sig
    from vibration.book.presentation.panels import KitExplorer
    from vibration.physics.duffing import Duffing, folds

    ex = pres.hb_explorer(m=1.0, c=0.5, k=20.0, k3=2.0, F0=5.0)
    assert isinstance(ex, KitExplorer)
    before = ex.image.value
    ex.k3_slider.value = -0.8
    f = folds(Duffing(m=1.0, c=0.5, k=20.0, k3=-0.8), 5.0)
    assert f.bistable and ex.image.value != before
    for value in (f.peak_amplitude, f.peak_omega, f.omega_low, f.omega_high):
        assert sig(value, 3) in ex.readout.value
    assert ex.summary() == "HBExplorer(k₃ = −0.8 N/m³, F₀ = 5 N)"
    ex.k3_slider.value = -1.5  # so soft that the curve never closes: one fold, no peak
    f = folds(Duffing(m=1.0, c=0.5, k=20.0, k3=-1.5), 5.0)
    assert not f.bistable and sig(f.omega_high, 3) in ex.readout.value and "no peak" in ex.readout.value


def _page(tmp_path, frag):
    path = tmp_path / "duffing.html"
    path.write_text(f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"></head><body>{frag}</body></html>')
    return path


#: JavaScript against Python: amplitudes and folds relative, same number of roots and stabilities.
RTOL_JS = 1e-9


@pytest.mark.slow  # over 2 s: make test-slow runs it
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
            d = Duffing(m=m, c=c, k=k, k3=k3)
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


@pytest.mark.slow  # over 1 s: make test-slow runs it
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
        f = folds(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0), 5.0)
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
        assert outside == [] and errors == []
    finally:
        page.close()
