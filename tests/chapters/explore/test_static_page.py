"""The static slider panel: offline behaviour in Chromium and its numbers against the Python closed form.

Browser tests drive Debian's Chromium (``/usr/bin/chromium``) through playwright's
sync API, with every request that is not ``file:`` or ``data:`` aborted and recorded.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from conftest import SCREENSHOT_DIR as SCREENSHOTS
from conftest import open_offline, panel_state

from vibration import Oscillator, ParameterError, SineForce, exact_response, settling_time, steady_state
from vibration.book.chapters.explore.panel import slider_panel_html
from vibration.book.chapters.explore.study import C_MIN
from vibration.book.publishing.mathml import external_urls

#: Tolerances of the JavaScript against vibration.physics.exact: x samples relative to max|x|, amplitude and
#: peak relative, settling time relative.
RTOL_X = 1e-9
RTOL_SETTLING = 1e-6

#: (m kg, k N/m, F0 N, c N s/m, omega rad/s): reference, resonance at three dampings, critical, other m, k.
CASES = {
    "reference w=3 c=0.5": (1.0, 20.0, 5.0, 0.5, 3.0),
    "resonance c=0.5": (1.0, 20.0, 5.0, 0.5, 4.47),
    "resonance c=0.1": (1.0, 20.0, 5.0, 0.1, 4.47),
    "resonance c=15": (1.0, 20.0, 5.0, 15.0, 4.47),
    "critical w=4.47": (1.0, 20.0, 5.0, 2.0 * math.sqrt(20.0), 4.47),
    "critical w=3": (1.0, 20.0, 5.0, 2.0 * math.sqrt(20.0), 3.0),
    "m=2 k=7 F0=3": (2.0, 7.0, 3.0, 0.8, 1.5),
    "c at slider minimum": (1.0, 20.0, 5.0, C_MIN, 4.47),
}


def _page(tmp_path: Path, *fragments: str) -> Path:
    body = "\n".join(fragments)
    path = tmp_path / "sliders.html"
    path.write_text(
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>sliders</title></head>\n'
        f"<body>\n{body}\n</body></html>\n",
        encoding="utf-8",
    )
    return path


# ----------------------------------------------------------------------------- no browser


def test_fragment_is_self_contained():
    frag = slider_panel_html()
    assert frag.startswith('<div class="vib-panel"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == []
    assert "http" not in frag
    assert "window.vibrationSliders" in frag and "<svg" in frag
    assert 'type="range"' in frag and "rad/s" in frag and "N s/m" in frag


def test_two_fragments_have_distinct_ids():
    a, b = slider_panel_html(), slider_panel_html()
    ida = a.split('id="', 1)[1].split('"', 1)[0]
    idb = b.split('id="', 1)[1].split('"', 1)[0]
    assert ida != idb


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [({"c": 0.0}, "c"), ({"c": -1.0}, "c"), ({"m": 0.0}, "m"), ({"omega": -1.0}, "omega"),
     ({"n_points": 1}, "n_points"), ({"panel_id": "x</script>"}, "panel_id")],
)  # fmt: skip
def test_bad_parameters_are_named(kwargs, name):
    with pytest.raises(ParameterError, match=name):
        slider_panel_html(**kwargs)


# ---------------------------------------------------------------------------- browser


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_sliders_work_offline(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, slider_panel_html(), slider_panel_html(c=15.0)))
    try:
        before, other_before = panel_state(page, 0), panel_state(page, 1)
        assert before["vel"] and "velocity amplitude" in before["readout"] and "9.9996 m/s" in before["readout"]
        assert "4.47 rad/s (0.7114 Hz)" in before["omega"]
        assert "0.5 N s/m" in before["c"] and "0.0559" in before["c"]
        assert "underdamped" in before["readout"] and "2.2371 m" in before["readout"]
        assert "overdamped" in other_before["readout"]

        # forcing-frequency slider: set the value and fire the input event, as a drag does
        page.eval_on_selector(
            "div.vib-panel input.vib-omega",
            "el => { el.value = '3'; el.dispatchEvent(new Event('input', {bubbles: true})); }",
        )
        after_w = panel_state(page, 0)
        assert after_w["points"] != before["points"] and after_w["frf"] != before["frf"]
        assert after_w["readout"] != before["readout"]
        assert "3 rad/s (0.4775 Hz)" in after_w["omega"]
        assert "0.45038 m" in after_w["readout"]  # steady-state amplitude at w = 3 rad/s, c = 0.5 N s/m
        assert panel_state(page, 1) == other_before  # the second panel is untouched

        # damping slider, by keyboard: End reaches 20 N s/m, Home reaches 0.01 N s/m (log scale)
        page.focus("div.vib-panel input.vib-logc")
        page.keyboard.press("End")
        at_max = panel_state(page, 0)
        assert at_max["c"].startswith("20 N s/m") and "overdamped" in at_max["readout"]
        assert at_max["points"] != after_w["points"]
        page.keyboard.press("Home")
        at_min = panel_state(page, 0)
        assert at_min["c"].startswith("0.01 N s/m") and "underdamped" in at_min["readout"]
        for _ in range(5):  # up the log scale, one step of 1/1000 of the log range at a time
            page.keyboard.press("ArrowRight")
        c_shown = float(panel_state(page, 0)["c"].split()[0])
        assert c_shown == pytest.approx(0.01 * 2000.0 ** (5 / 1000), rel=1e-3)
        page.eval_on_selector(
            "div.vib-panel input.vib-logc",
            "el => { el.value = '300'; el.dispatchEvent(new Event('input', {bubbles: true})); }",
        )
        c_shown = float(panel_state(page, 0)["c"].split()[0])
        assert c_shown == pytest.approx(0.01 * 2000.0 ** (300 / 1000), rel=1e-3)

        page.eval_on_selector(
            "div.vib-panel input.vib-omega",
            "el => { el.value = '4.47'; el.dispatchEvent(new Event('input', {bubbles: true})); }",
        )
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.locator("div.vib-panel").first.screenshot(path=str(SCREENSHOTS / "static_sliders.png"))
        assert outside == []
        assert errors == []
    finally:
        page.close()


def _python_reference(m, k, F0, c, omega, t_end=50.0, n_points=2001):
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=omega)
    t = np.linspace(0.0, t_end, n_points)
    r = exact_response(osc, force, t)
    x = r.x
    return {
        "t": t,
        "x": x,
        "v": r.v,
        "peak_v": float(np.max(np.abs(r.v))),
        "velocity_amplitude": steady_state(osc, force).velocity_amplitude,
        "peak": float(np.max(np.abs(x))),
        "amplitude": steady_state(osc, force).amplitude,
        "settling": settling_time(osc, force),
        "regime": osc.regime,
        "zeta": osc.damping_ratio,
        "wn": osc.natural_frequency,
    }


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_js_numbers_match_python(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, slider_panel_html()))
    try:
        for label, (m, k, F0, c, omega) in CASES.items():
            js = page.evaluate(
                "p => window.vibrationSliders.compute(p)",
                {"m": m, "k": k, "F0": F0, "c": c, "omega": omega, "t_end": 50.0, "n_points": 2001},
            )
            py = _python_reference(m, k, F0, c, omega)
            np.testing.assert_allclose(js["t"], py["t"], rtol=0, atol=1e-12, err_msg=label)
            scale = np.max(np.abs(py["x"]))
            err_x = np.max(np.abs(np.asarray(js["x"]) - py["x"])) / scale
            assert err_x <= RTOL_X, f"{label}: max |x_js - x_py| / max|x| = {err_x:.2e}"
            err_v = np.max(np.abs(np.asarray(js["v"]) - py["v"])) / np.max(np.abs(py["v"]))
            assert err_v <= RTOL_X, f"{label}: max |v_js - v_py| / max|v| = {err_v:.2e}"
            assert js["peak_v"] == pytest.approx(py["peak_v"], rel=RTOL_X), label
            assert js["velocity_amplitude"] == pytest.approx(py["velocity_amplitude"], rel=RTOL_X), label
            assert js["amplitude"] == pytest.approx(py["amplitude"], rel=RTOL_X), label
            assert js["peak"] == pytest.approx(py["peak"], rel=RTOL_X), label
            assert js["settling"] == pytest.approx(py["settling"], rel=RTOL_SETTLING), label
            assert js["settled"] == (py["settling"] <= 50.0), label
            assert js["regime"] == py["regime"], label
            assert js["zeta"] == pytest.approx(py["zeta"], rel=1e-15), label
            assert js["wn"] == pytest.approx(py["wn"], rel=1e-15), label
        assert outside == [] and errors == []
    finally:
        page.close()


def test_panel_range_widens_to_include_the_starting_damping():
    import html
    import json
    import re

    for c, lo, hi in ((0.005, 0.005, 20.0), (100.0, 0.01, 100.0), (0.5, 0.01, 20.0)):
        frag = slider_panel_html(c=c)
        cfg = json.loads(html.unescape(re.search(r'data-params="([^"]*)"', frag).group(1)))
        assert cfg["c_min"] == pytest.approx(lo) and cfg["c_max"] == pytest.approx(hi)
