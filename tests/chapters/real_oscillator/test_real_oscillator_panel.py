"""The real-oscillator panel: self-contained, and its JavaScript free decay equals the Python closed form."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import open_offline

from vibration.book.chapters.real_oscillator.panel import decay_panel, decay_panel_html
from vibration.book.publishing.mathml import external_urls
from vibration.physics.lab import free_decay_response

# every test here builds on a chapter study that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

#: JavaScript against Python: the same closed form, evaluated with each language's exp/cos/sin.
RTOL = 1e-9


@pytest.fixture(scope="module")
def study(real_oscillator_default):
    return real_oscillator_default


def test_fragment_is_self_contained(study):
    frag = decay_panel_html(study)
    assert frag.startswith('<div class="vro-panel"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == [] and "http:" not in frag.replace("http://www.w3.org/2000/svg", "")
    assert frag.count('<input type="range"') == 3 and "window.vibrationRealDecay" in frag
    assert repr(decay_panel(study)).startswith("DecayPanel(brake=on")


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_js_decay_matches_python(browser, tmp_path: Path, study):
    page_path = tmp_path / "real.html"
    page_path.write_text(
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>real</title></head><body>\n'
        + decay_panel_html(study)
        + "\n</body></html>\n",
        encoding="utf-8",
    )
    page, outside, errors = open_offline(browser, page_path)
    try:
        rng = np.random.default_rng(20241210)
        for _ in range(40):
            wn, zeta, fr = rng.uniform(1.0, 10.0), rng.uniform(0.0, 0.3), rng.uniform(0.0, 0.3)
            off, th0, t0 = rng.uniform(-0.5, 0.5), rng.uniform(-5.0, 5.0), rng.uniform(0.0, 2.0)
            t = np.sort(rng.uniform(0.0, 20.0, 400))
            py = free_decay_response(t, wn, zeta, friction=fr, offset=off, theta0=th0, t0=t0)
            js = np.array(
                page.evaluate(
                    "a => window.vibrationRealDecay.response(a[0], a[1], a[2], a[3], a[4], a[5], a[6])",
                    [t.tolist(), wn, zeta, fr, off, th0, t0],
                )
            )
            np.testing.assert_allclose(js, py, rtol=RTOL, atol=RTOL * abs(th0))
        assert page.locator(".vro-rms").inner_text().endswith(" rad")
        page.locator(".vro-zeta").fill("0.05")
        assert page.locator(".vro-zeta-out").inner_text() == "0.0500"
        assert outside == [] and errors == []
    finally:
        page.close()
