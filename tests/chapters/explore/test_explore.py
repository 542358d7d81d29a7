"""Chapter 5, explore: the readout against independent formulas, the prose under other parameters, and the
descriptions of the explorer and of the book's panel read from what they draw (the panel unclipped on a phone)."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import open_offline
from prose import header_problems, repeated, table_texts

from vibration import Oscillator, SineForce, exact_response, settling_time
from vibration.book.chapters.explore import ExploreStudy, Params, explore_study, panel, readout, tables
from vibration.book.chapters.explore.figure import build_figure, figure_words
from vibration.book.chapters.explore.widget import live_explorer
from vibration.physics.audit import resonant_peak

# every test here builds on a study, a figure set or a browser that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

PACKAGE = Path(__file__).resolve().parents[3] / "src" / "vibration" / "book" / "chapters" / "explore"

PARAMETER_SETS = {
    "paper": {},
    "heavy-stiff": {"m": 4.0, "k": 400.0, "F0": 40.0, "omega_res": 10.0, "c_nominal": 2.0, "t_end": 20.0},
    "soft-light": {"k": 5.0, "F0": 1.0, "omega_res": 2.2, "c_nominal": 0.05, "t_end": 100.0},
    "negative": {"c_nominal": -0.1, "t_end": 20.0},
}


@pytest.fixture(scope="module", params=list(PARAMETER_SETS))
def study(request) -> ExploreStudy:
    return explore_study(Params.from_values(PARAMETER_SETS[request.param]))


def test_readout_against_independent_formulas(study):
    p, r = study.params, study.start
    X = p.F0 / abs(complex(p.k - p.m * p.omega_res**2, study.c_start * p.omega_res))
    assert r.amplitude == pytest.approx(X, rel=1e-12)
    assert r.magnification == pytest.approx(X / (p.F0 / p.k), rel=1e-12)
    osc, force = Oscillator(m=p.m, c=study.c_start, k=p.k), SineForce(F0=p.F0, omega=p.omega_res)
    x = exact_response(osc, force, np.linspace(0.0, p.t_end, 5001)).x
    assert r.peak == pytest.approx(float(np.max(np.abs(x))), rel=1e-12)
    assert r.settling == settling_time(osc, force)
    assert r.steady_reached == ("yes" if r.settling <= p.t_end else "no")
    assert r.omega_n == pytest.approx(math.sqrt(p.k / p.m), rel=1e-15)


def test_peak_and_oscillation_thresholds(study):
    p = study.params
    below, above = (
        Oscillator(m=p.m, c=0.999 * study.c_no_peak, k=p.k),
        Oscillator(m=p.m, c=1.001 * study.c_no_peak, k=p.k),
    )
    assert resonant_peak(below)[0] is not None and resonant_peak(above) == (None, None)
    assert Oscillator(m=p.m, c=0.999 * study.c_critical, k=p.k).regime == "underdamped"
    assert Oscillator(m=p.m, c=1.001 * study.c_critical, k=p.k).regime == "overdamped"


def test_halving_the_damping_near_resonance_doubles_the_amplitude():
    """At ω = ω_n exactly, X = F0/(cω): halving c doubles X (independent of the readout's route)."""
    st = explore_study(omega_res=math.sqrt(20.0))
    assert st.halved.amplitude / st.start.amplitude == pytest.approx(2.0, rel=1e-12)
    assert st.far_halved.amplitude / st.far.amplitude == pytest.approx(1.0, abs=0.01)


def test_a_run_without_positive_damping_starts_the_sliders_at_a_positive_one(study):
    assert study.clamped == (study.params.c_nominal <= 0)
    assert study.c_start > 0 and all(r.settling < math.inf for r in (study.start, study.critical))


def test_the_readout_table_is_for_readers(study):
    assert header_problems(tables.readout_table(study)) == []
    assert repeated(table_texts([tables.readout_table(study)])) == []


def test_layout_words_are_read_from_the_figure():
    fig, axes, art = build_figure()
    w = figure_words(fig, axes, art)
    assert (w["x"], w["v"], w["m"]) == ("top left", "bottom left", "right, full height")
    assert (w["envelope"], w["settle"], w["natural"], w["hz"]) == ("dashed", "dotted", "dotted", "Hz above")
    art["omega_n"].set_linestyle("--")  # the words follow the drawing
    assert figure_words(fig, axes, art)["natural"] == "dashed"


def test_panel_facts_are_read_from_its_css_and_script():
    f = panel.panel_facts()
    assert (f.envelope, f.settle, f.natural) == ("dashed", "dotted", "dotted")
    assert f.stack_below_px == 720 and f.log_magnification and not f.hz_axis
    assert panel._dash_word(".vib-envelope { stroke-dasharray: 2 3; }", "vib-envelope") == "dotted"
    assert panel._dash_word(".vib-envelope { stroke: red; }", "vib-envelope") == "solid"
    frag = panel.slider_panel_html()
    assert panel.time_caption(f) in frag and panel.frequency_caption(f) in frag
    assert "dashed: ± steady-state amplitudes" in frag and "dotted: ω<sub>n</sub>" in frag


def test_live_explorer_starts_at_the_study_and_carries_the_panel():
    st = explore_study(c_nominal=-0.1, t_end=20.0)
    ex = live_explorer(st)
    try:
        assert ex.values["zeta"] == pytest.approx(st.start.zeta, rel=1e-12)
        assert ex.values["amplitude"] == pytest.approx(st.start.amplitude, rel=1e-12)
        data = ex._repr_mimebundle_()
        assert data["text/html"].startswith('<div class="vib-panel"') and "&quot;c&quot;: 0.01," in data["text/html"]
    finally:
        ex.close()


def test_readout_function_refuses_an_overflow():
    from vibration.physics.model import ParameterError

    with pytest.raises(ParameterError, match="beyond the float range"):
        readout(Oscillator(m=1.0, c=-50.0, k=20.0), SineForce(F0=5.0, omega=4.47), 50.0)


def test_usage_example_runs_on_its_own():
    md = (PACKAGE / "usage.md").read_text(encoding="utf-8")
    assert md.startswith("# Chapter 5, ")
    blocks = re.findall(r"```python\n(.*?)```", md, flags=re.S)
    assert len(blocks) == 1
    out = subprocess.run([sys.executable, "-c", blocks[0]], capture_output=True, text=True, timeout=120, check=True)
    assert "underdamped" in out.stdout and "halving c multiplies the amplitude by" in out.stdout


_CLIPPED = """() => {
    const p = document.querySelector('div.vib-panel');
    const pr = p.getBoundingClientRect();
    const out = [];
    for (const el of p.querySelectorAll('*')) {
        const skip = ['STYLE', 'SCRIPT', 'NOSCRIPT'].includes(el.tagName);
        if (skip || (el.closest('svg') && el.tagName !== 'svg')) continue;
        const r = el.getBoundingClientRect();
        if (r.width === 0 && r.height === 0) continue;
        const hidden = el.scrollWidth > el.clientWidth + 1 && getComputedStyle(el).overflowX !== 'visible';
        if (r.right > pr.right + 0.5 || r.left < pr.left - 0.5 || hidden) out.push(el.tagName + '.' + el.className);
    }
    return {out, page: document.documentElement.scrollWidth};
}"""


@pytest.mark.browser
@pytest.mark.parametrize("width", [390, 320, 1280])
def test_panel_is_not_clipped_on_a_phone(browser, tmp_path, width):
    path = tmp_path / "panel.html"
    path.write_text(
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1"><title>panel</title></head>\n'
        f"<body>\n{panel.slider_panel_html()}\n</body></html>\n",
        encoding="utf-8",
    )
    page, outside, errors = open_offline(browser, path, viewport=(width, 900))
    try:
        page.wait_for_function("() => document.querySelector('table.vib-readout td.vib-r-wn').textContent !== ''")
        res = page.evaluate(_CLIPPED)
        assert res["out"] == [] and res["page"] <= width, res
        assert outside == [] and errors == []
    finally:
        page.close()
