"""Stability chapter (package ``vibration.book.chapters.stability``): tables, figures, sentences, and the kernel-free
panel against Python."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from conftest import open_offline

import vibration
from vibration import Oscillator
from vibration.book.chapters.stability import figures, panel, tables, text, verdicts
from vibration.book.chapters.stability.study import stability_study
from vibration.book.presentation.style import legend_overlap
from vibration.book.presentation.tables import Missing
from vibration.book.publishing.mathml import external_urls

SCREENSHOTS = Path(__file__).resolve().parents[3] / "build" / "screenshots"

#: JavaScript against Python: transmissibility, poles and the step response are the same closed forms
#: (relative 1e-12); the step metrics are roots found by bisection in JS and brentq in Python (relative 1e-9).
RTOL_CLOSED = 1e-12
RTOL_ROOTS = 1e-9


@pytest.fixture(scope="module")
def study():
    return stability_study(n_paths=20, t_growth=60.0)


def test_tables_have_names_units_and_no_nan(study):
    for f in (
        tables.poles_table,
        tables.growth_table,
        tables.transmissibility_table,
        tables.step_table,
        tables.random_table,
        tables.random_force_table,
        tables.cost_table,
        verdicts.labels_table,
        tables.checks_table,
    ):
        t = f(study)
        assert t.name.startswith("tab-stability-")
        plain = repr(t)
        assert not re.search(r"\b(nan|inf)\b", plain), plain
        assert t._repr_markdown_().startswith(("```{list-table}", "~~~{list-table}"))  # a caption with {sub}: ~~~
    step = tables.step_table(study)
    high = [r for r in step.rows if r["case"].startswith("high")][0]
    assert isinstance(high["tp"], Missing)
    checks = repr(tables.checks_table(study))
    assert "(above" not in checks and checks.count("< 10⁻") == 4  # every self-check within its bound


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_figures_keep_legends_off_the_data(study):
    for f in (
        figures.pole_figure,
        figures.growth_figure,
        figures.transmissibility_figure,
        figures.step_figure,
        figures.cost_figure,
        figures.labels_figure,
    ):
        fig = f(study).fig
        for ax in fig.axes:
            assert legend_overlap(ax) == 0.0, (f.__name__, ax.get_label())


def test_sentences_follow_the_numbers(study):
    assert f"{study.zeta_star:.4f}" in text.step_sentence(study)
    assert "asymptotically stable" in text.stability_sentence(study)
    assert "agrees with" in text.random_sentence(study)
    # another damping set moves the sentences and keeps the tables consistent
    other = stability_study(c_low=0.2, c_nominal=2.0, c_high=40.0, n_paths=10, t_growth=30.0)
    assert "$c$ = 0.2 N s/m" in text.stability_sentence(other)
    rows = {r["label"]: r for r in verdicts.labels_table(other).rows}
    assert rows["“absolute stability”"]["c"] == "40.0"
    assert "\n" not in verdicts.labels_sentence(other)  # one paragraph, not the table's rows again


def test_label_verdicts_on_the_paper(study):
    rows = {r["label"]: r for r in verdicts.labels_table(study).rows}
    assert rows["“absolute stability”"]["verdict"].startswith("not a distinction")
    assert rows["“comfort”"]["verdict"].startswith("supported only in the isolation sense")
    assert rows["“optimised compromise”"]["verdict"].startswith("a compromise, not an optimum")


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"c_low": float("nan")}, "c_low"),
        ({"c_high": 1e300}, "c_high"),
        ({"c_unstable": 0.1}, "c_unstable"),
        ({"isolation_ratio": 1.2}, "isolation_ratio"),
        ({"n_paths": 1}, "n_paths"),
        ({"S0": 0.0}, "S0"),
        ({"t_growth": -1.0}, "t_growth"),
    ],
)
def test_study_bad_input(kwargs, name):
    with pytest.raises(vibration.ParameterError, match=name):
        stability_study(**kwargs)


def test_panel_fragment_is_self_contained():
    frag = panel.stability_panel_html()
    assert frag.startswith('<div class="vst-panel"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == [] and "http" not in frag
    assert "window.vibrationStability" in frag and frag.count("<svg") == 3
    with pytest.raises(vibration.ParameterError, match="zeta"):
        panel.stability_panel_html(zeta=10.0)


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_explorer_bundle_has_widget_and_static_panel(study):
    ex = panel.stability_explorer(study)
    bundle = ex._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert bundle["text/html"].startswith('<div class="vst-panel"')
    ex.zeta_slider.value = 0.78
    v = ex.values()
    assert v["step"].overshoot == pytest.approx(math.exp(-math.pi * 0.78 / math.sqrt(1 - 0.78**2)), rel=1e-3)


# ----------------------------------------------------------------------------- browser


def _page(tmp_path: Path, *fragments: str) -> Path:
    path = tmp_path / "stability.html"
    path.write_text(
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>stability</title></head>\n<body>\n'
        + "\n".join(fragments)
        + "\n</body></html>\n",
        encoding="utf-8",
    )
    return path


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_js_matches_python_on_random_points(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, panel.stability_panel_html()))
    try:
        rng = np.random.default_rng(20240606)
        points = []
        for _ in range(60):
            m, k = 10 ** rng.uniform(-1, 1), 10 ** rng.uniform(0, 3)
            zeta = 10 ** rng.uniform(math.log10(panel.ZETA_MIN), math.log10(panel.ZETA_MAX))
            wn = math.sqrt(k / m)
            points.append({"m": m, "k": k, "zeta": zeta, "omega": rng.uniform(0.0, 4.0 * wn)})
        points.append({"m": 1.0, "k": 20.0, "zeta": 1.0, "omega": 4.47})  # critical
        js = page.evaluate(
            """pts => pts.map(p => {
                const S = window.vibrationStability;
                const r = S.compute(p);
                const ts = [0.1, 0.7, 2.3].map(f => f * r.settling_time);
                return {r, y: ts.map(t => S.stepResponse(p, t)), ts};
            })""",
            points,
        )
        for p, out in zip(points, js, strict=True):
            osc = Oscillator(m=p["m"], c=2 * p["zeta"] * math.sqrt(p["k"] * p["m"]), k=p["k"])
            r = out["r"]
            assert r["c"] == pytest.approx(osc.c, rel=1e-15)
            assert r["T"] == pytest.approx(vibration.transmissibility(osc, p["omega"]), rel=RTOL_CLOSED)
            ref = vibration.poles(osc)
            got = np.array([complex(*q) for q in r["poles"]])
            np.testing.assert_allclose(got, ref, rtol=RTOL_CLOSED, atol=1e-14 * osc.natural_frequency)
            s = vibration.step_metrics(osc)
            assert r["overshoot"] == pytest.approx(s.overshoot, rel=RTOL_CLOSED, abs=1e-300)
            assert r["rise_time"] == pytest.approx(s.rise_time, rel=RTOL_ROOTS)
            assert r["settling_time"] == pytest.approx(s.settling_time, rel=RTOL_ROOTS)
            if math.isinf(s.peak_time):
                assert r["peak_time"] is None or r["peak_time"] == math.inf  # JSON turns Infinity into null
            else:
                assert r["peak_time"] == pytest.approx(s.peak_time, rel=RTOL_CLOSED)
            y = vibration.step_response(osc, np.array(out["ts"]))
            np.testing.assert_allclose(out["y"], y, rtol=0, atol=RTOL_CLOSED * 10)
        assert outside == [] and errors == []
    finally:
        page.close()


@pytest.mark.slow  # over 1 s: make test-slow runs it
@pytest.mark.browser
def test_panel_sliders_move_all_three_views(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, panel.stability_panel_html()), viewport=(1180, 900))
    try:

        def state():
            return page.evaluate(
                """() => {
                const p = document.querySelector('div.vst-panel');
                return {
                    trans: p.querySelector('svg.vst-trans circle.vst-op').getAttribute('cy'),
                    step: p.querySelector('svg.vst-step polyline').getAttribute('points'),
                    poles: p.querySelector('svg.vst-poles path.vst-pole').getAttribute('d'),
                    ts: p.querySelector('.vst-r-ts').textContent,
                    c: p.querySelector('.vst-r-c').textContent,
                    zeta: p.querySelector('output.vst-zeta-out').textContent,
                };
            }"""
            )

        before = state()
        assert before["c"].startswith("0.5") and before["zeta"] == "0.0559"
        page.eval_on_selector(
            "input.vst-zeta", "el => { el.value = '450'; el.dispatchEvent(new Event('input', {bubbles: true})); }"
        )
        after = state()
        assert (
            after["step"] != before["step"] and after["poles"] != before["poles"] and after["trans"] != before["trans"]
        )
        zeta = panel.ZETA_MIN * (panel.ZETA_MAX / panel.ZETA_MIN) ** (450 / panel.ZETA_STEPS)
        s = vibration.step_metrics(Oscillator(m=1.0, c=2 * zeta * math.sqrt(20.0), k=20.0))
        assert float(after["ts"].split()[0]) == pytest.approx(s.settling_time, rel=1e-3)
        page.eval_on_selector(
            "input.vst-omega", "el => { el.value = '13'; el.dispatchEvent(new Event('input', {bubbles: true})); }"
        )
        moved = state()
        assert moved["trans"] != after["trans"] and moved["step"] == after["step"]
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.locator("div.vst-panel").screenshot(path=str(SCREENSHOTS / "stability_panel.png"))
        assert outside == [] and errors == []
    finally:
        page.close()
