"""The chapter-7 kernel-free panel: its JavaScript closed forms against the Python physics, offline in Chromium."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import SCREENSHOTS, open_offline

import vibration
from vibration import Oscillator, ParameterError, SineForce, exact_response
from vibration.book.chapters.control.panel import control_panel, control_panel_html
from vibration.book.chapters.control.study import control_study
from vibration.book.publishing.mathml import external_urls
from vibration.physics.control import lqr_closed_form, shaped_move, shaper_residual

#: Tolerances of the JavaScript against Python: gains, transmissibility, residual (relative); x samples
#: relative to max |x|.
RTOL = 1e-10
RTOL_X = 1e-9


def test_panel_is_self_contained_and_validated():
    frag = control_panel_html()
    assert frag.startswith('<div class="vc-panel"') and external_urls(frag) == [] and "http" not in frag
    panel = control_panel(m=2.0)
    assert panel._repr_html_().count('class="vc-panel"') == 1 and "m = 2 kg" in panel._repr_html_()
    assert repr(panel).startswith("ControlPanel(")  # one stable line for nbval, no memory address
    with pytest.raises(ParameterError, match="c_sky"):
        control_panel_html(c_sky=-1.0)
    with pytest.raises(ParameterError, match="freq_error"):
        control_panel_html(freq_error=3.0)


def test_panel_sliders_reach_the_chapters_values():
    """A start value beyond the default slider range widens the slider instead of being clipped."""
    frag = control_panel_html(c_sky=200.0, freq_error=1.5, r_lqr=1e-9)
    assert 'class="vc-csky" min="0" max="200"' in frag
    assert 'class="vc-err" min="-50" max="150"' in frag and 'value="150"' in frag
    assert 'class="vc-logr" min="-9"' in frag


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_panel_takes_the_study():
    st = control_study(t_end=5.0, n_points=101, n_sweep=10, k=30.0)
    assert "k = 30 N/m" in control_panel(st)._repr_html_()


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_panel_javascript_matches_python(browser, tmp_path: Path):
    path = tmp_path / "control.html"
    path.write_text(
        '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>control</title></head><body>'
        + control_panel_html()
        + "</body></html>",
        encoding="utf-8",
    )
    page, outside, errors = open_offline(browser, path)
    try:
        rng = np.random.default_rng(7)
        for _ in range(12):
            m, c, k = (float(v) for v in (rng.uniform(0.2, 5), rng.uniform(0.0, 6), rng.uniform(1, 100)))
            qx, qv, r = (float(10**v) for v in (rng.uniform(-2, 3), rng.uniform(-3, 1), rng.uniform(-6, 1)))
            osc = Oscillator(m=m, c=c, k=k)
            js = page.evaluate(f"window.vibrationControl.lqrGains({m}, {c}, {k}, {qx}, {qv}, {r})")
            np.testing.assert_allclose(js, lqr_closed_form(osc, qx, qv, r=r), rtol=RTOL)
            np.testing.assert_allclose(js, vibration.lqr(osc, qx, qv, r=r).K, rtol=1e-8)
            ws = [float(v) for v in rng.uniform(0.1, 30, 7)]
            csky = float(rng.uniform(0, 40))
            js = page.evaluate(f"window.vibrationControl.skyhook({m}, {c}, {k}, {csky}, {ws})")
            np.testing.assert_allclose(js, vibration.skyhook_transmissibility(osc, csky, ws), rtol=RTOL)
            w = float(rng.uniform(0.5, 10))
            ts = [float(v) for v in np.linspace(0, 15, 301)]
            js = page.evaluate(f"window.vibrationControl.response({m}, {c}, {k}, 5.0, {w}, {ts})")
            ex = exact_response(osc, SineForce(F0=5.0, omega=w), ts)
            assert np.max(np.abs(np.array(js["x"]) - ex.x)) < RTOL_X * np.max(np.abs(ex.x))
            if osc.damping_ratio < 1:
                for kind, make in (("ZV", vibration.zv_shaper), ("ZVD", vibration.zvd_shaper)):
                    ka = float(k * rng.uniform(0.6, 1.5))
                    sh = make(osc)
                    res = page.evaluate(
                        f"(() => {{ const s = window.vibrationControl.shaper('{kind}', {m}, {c}, {k});"
                        f" return [s.times, s.amps, window.vibrationControl.residual(s, {m}, {c}, {ka}),"
                        f" window.vibrationControl.shapedMove(s, {m}, {c}, {ka}, 0.1, {ts})]; }})()"
                    )
                    np.testing.assert_allclose(res[0], sh.times, rtol=RTOL)
                    np.testing.assert_allclose(res[1], sh.amplitudes, rtol=RTOL)
                    assert abs(res[2] - shaper_residual(sh, Oscillator(m=m, c=c, k=ka))) < 1e-10
                    _, x, _, _ = shaped_move(Oscillator(m=m, c=c, k=ka), sh, 0.1, t_end=15.0, n_points=301)
                    assert np.max(np.abs(np.array(res[3]) - x)) < RTOL_X * 0.2
        before = page.eval_on_selector("svg.vc-sky polyline.vc-skyhook", "e => e.getAttribute('points')")
        page.eval_on_selector(
            "input.vc-csky", "e => { e.value = '30'; e.dispatchEvent(new Event('input', {bubbles: true})); }"
        )
        after = page.eval_on_selector("svg.vc-sky polyline.vc-skyhook", "e => e.getAttribute('points')")
        assert after != before
        assert "30 N s/m" in page.inner_text("output.vc-csky-out")
        SCREENSHOTS.mkdir(parents=True, exist_ok=True) if isinstance(SCREENSHOTS, Path) else None
        page.screenshot(path=str(Path(SCREENSHOTS) / "control_panel.png"), full_page=True)
        assert outside == [] and errors == []
    finally:
        page.close()
