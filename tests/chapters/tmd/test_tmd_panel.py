"""Chapter 8 sliders: the kernel-free panel's JavaScript against the Python physics, the panel offline
in Chromium, and the JupyterLab explorer.

Tolerances. The magnification, the fixed points and the three tunings are the same closed forms in
both languages (the complex products written out in JavaScript): relative 1e-12. The peak is found
differently (Python: the real roots of the stationarity polynomial in r², JavaScript: a dense grid
and a golden-section refinement of each local maximum): relative 1e-9, which the golden section
reaches with a margin (the error in |H| is quadratic in the error in r).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from conftest import SCREENSHOTS, open_offline

import vibration
from vibration import den_hartog, h2_tuning, hinf_tuning, tmd_fixed_points, tmd_magnification, tmd_peak
from vibration.book.chapters.tmd import panel as pres
from vibration.book.publishing.mathml import external_urls

RTOL_CLOSED = 1e-12
RTOL_PEAK = 1e-9


def _page(tmp_path: Path, *fragments: str) -> Path:
    path = tmp_path / "tmd.html"
    path.write_text(
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>tmd</title></head>\n<body>\n'
        + "\n".join(fragments)
        + "\n</body></html>\n",
        encoding="utf-8",
    )
    return path


def _inf(v) -> bool:
    """Infinity from the page (Playwright passes it through; a JSON round trip would give None)."""
    return v is None or v == math.inf


def _random_points(n: int, seed: int) -> list[dict]:
    """Seeded points over the sliders' ranges (μ and ζ_a log-uniform), plus corners."""
    rng = np.random.default_rng(seed)
    lg = np.log10
    pts = []
    for _ in range(n):
        pts.append(
            {
                "mu": float(10 ** rng.uniform(lg(pres.MU_RANGE[0]), lg(pres.MU_RANGE[1]))),
                "f": float(rng.uniform(*pres.F_RANGE)),
                "zeta_a": float(10 ** rng.uniform(lg(pres.ZETA_A_RANGE[0]), lg(pres.ZETA_A_RANGE[1]))),
                "zeta_p": float(rng.choice([0.0, rng.uniform(*pres.ZETA_P_RANGE)])),
            }
        )
    pts += [
        {"mu": pres.MU_RANGE[0], "f": pres.F_RANGE[0], "zeta_a": pres.ZETA_A_RANGE[0], "zeta_p": 0.0},
        {"mu": pres.MU_RANGE[1], "f": pres.F_RANGE[1], "zeta_a": pres.ZETA_A_RANGE[1], "zeta_p": pres.ZETA_P_RANGE[1]},
        {"mu": 0.05, "f": 1 / 1.05, "zeta_a": 0.005, "zeta_p": 0.0},  # sharp twin peaks
        {"mu": 0.05, "f": 1.0, "zeta_a": 0.9, "zeta_p": 0.3},  # heavily damped: the peak moves toward r = 0
    ]
    return pts


# ----------------------------------------------------------------------------- Python side


def test_panel_fragment_is_self_contained_and_validated():
    frag = pres.tmd_panel_html(0.05, zeta_p=0.0559)
    assert frag.startswith('<div class="vtm-panel"') and frag.rstrip().endswith("</div>")
    assert external_urls(frag) == [] and "http" not in frag and "src=" not in frag
    assert "window.vibrationTMD" in frag and frag.count("<svg") == 1 and frag.count('<input type="range"') == 4
    assert frag.count('class="vtm-rule"') == 3
    for kwargs, name in (
        ({"mu": 0.5}, "mu"),
        ({"f": 2.0}, "f"),
        ({"zeta_a": 0.0}, "zeta_a"),
        ({"zeta_p": -0.1}, "zeta_p"),
        ({"mu": float("nan")}, "mu"),
    ):
        with pytest.raises(vibration.ParameterError, match=name):
            pres.tmd_panel_html(**kwargs)


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_explorer_bundle_widget_panel_and_values():
    ex = pres.tmd_explorer(0.05)
    bundle = ex._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert bundle["text/html"].startswith('<div class="vtm-panel"') and "image/png" in bundle
    opt = hinf_tuning(0.05)
    assert ex.values()["peak"] == pytest.approx(opt.peak, rel=1e-9)  # starts at the H∞ optimum
    ex.rule_buttons.value = "Den Hartog"  # the button sets f and ζ_a to the rule
    dh = den_hartog(0.05)
    v = ex.values()
    assert v["f"] == pytest.approx(dh.f, abs=1e-12) and v["zeta_a"] == pytest.approx(dh.zeta_a, abs=1e-12)
    assert v["peak"] == pytest.approx(dh.peak, rel=1e-9) and ex.rule_buttons.value is None
    ex.zeta_p_slider.value = 0.0559
    assert ex.values()["peak"] == pytest.approx(tmd_peak(0.05, dh.f, dh.zeta_a, zeta_p=0.0559), rel=1e-12)
    assert "0.0559" in ex._repr_mimebundle_()["text/plain"]
    # out-of-range starts are moved into the sliders' ranges; bad values are named
    far = pres.tmd_explorer(2.0, f=3.0, zeta_a=5.0, zeta_p=0.6).values()
    assert (far["mu"], far["f"], far["zeta_a"], far["zeta_p"]) == pytest.approx((0.25, 1.3, 1.0, 0.3))
    for kwargs, name in (
        ({"mu": 0.0}, "mu"),
        ({"f": -1.0}, "f"),
        ({"zeta_a": 0.0}, "zeta_a"),
        ({"zeta_p": -1}, "zeta_p"),
    ):
        with pytest.raises(vibration.ParameterError, match=name):
            pres.tmd_explorer(**kwargs)


# ----------------------------------------------------------------------------- browser


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_js_matches_python_on_random_points(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, pres.tmd_panel_html()))
    try:
        points = _random_points(60, 20240811)
        rng = np.random.default_rng(7)
        rs = np.concatenate([[0.0, 1.0], rng.uniform(0.0, 3.0, 20)]).tolist()
        js = page.evaluate(
            """([pts, rs]) => pts.map(p => {
                const T = window.vibrationTMD;
                return {
                    h: rs.map(r => T.magnification(p.mu, p.f, p.zeta_a, r, p.zeta_p)),
                    bare: rs.map(r => T.bare(r, p.zeta_p)),
                    fixed: T.fixedPoints(p.mu, p.f),
                    peak: T.peak(p.mu, p.f, p.zeta_a, p.zeta_p),
                    dh: T.denHartog(p.mu), hinf: T.hinf(p.mu), h2: T.h2(p.mu),
                    res: T.compute(p),
                };
            })""",
            [points, rs],
        )
        r = np.array(rs)
        for p, out in zip(points, js, strict=True):
            mu, f, za, zp = p["mu"], p["f"], p["zeta_a"], p["zeta_p"]
            np.testing.assert_allclose(out["h"], tmd_magnification(mu, f, za, r=r, zeta_p=zp), rtol=RTOL_CLOSED)
            with np.errstate(divide="ignore"):
                bare = 1.0 / np.abs(1.0 - r * r + 2j * zp * r)
            got_bare = np.array([math.inf if b is None else b for b in out["bare"]])
            np.testing.assert_allclose(got_bare, bare, rtol=RTOL_CLOSED)
            fr, fh = tmd_fixed_points(mu, f)
            np.testing.assert_allclose(out["fixed"]["r"], fr, rtol=RTOL_CLOSED)
            np.testing.assert_allclose(out["fixed"]["h"], fh, rtol=1e-10)  # 1/(1-(1+μ)r²) amplifies r's rounding
            assert out["peak"]["peak"] == pytest.approx(tmd_peak(mu, f, za, zeta_p=zp), rel=RTOL_PEAK)
            for key, rule in (("dh", den_hartog), ("hinf", hinf_tuning), ("h2", h2_tuning)):
                t = rule(mu)
                assert out[key]["f"] == pytest.approx(t.f, rel=RTOL_CLOSED)
                assert out[key]["zeta_a"] == pytest.approx(t.zeta_a, rel=RTOL_CLOSED)
            assert out["hinf"]["peak"] == pytest.approx(hinf_tuning(mu).peak, rel=RTOL_CLOSED)
            res = out["res"]
            for name, rule in (("Den Hartog", den_hartog), ("H∞", hinf_tuning), ("H2", h2_tuning)):
                t = rule(mu)
                assert res["rules"][name]["peak0"] == pytest.approx(t.peak, rel=RTOL_PEAK)
                assert res["rules"][name]["peak"] == pytest.approx(
                    tmd_peak(mu, t.f, t.zeta_a, zeta_p=zp), rel=RTOL_PEAK
                )
            if zp == 0.0:
                assert _inf(res["bare_peak"])
            else:  # ζ_p <= 0.3 < 1/√2: the bare primary peaks at 1/(2 ζ_p sqrt(1 - ζ_p²))
                assert res["bare_peak"] == pytest.approx(1.0 / (2 * zp * math.sqrt(1 - zp * zp)), rel=RTOL_CLOSED)
        # both dampings zero: no finite peak, in both languages
        inf = page.evaluate("() => window.vibrationTMD.peak(0.05, 1, 0, 0).peak")
        assert _inf(inf) and math.isinf(tmd_peak(0.05, 1.0, 0.0, zeta_p=0.0))
        assert outside == [] and errors == []
    finally:
        page.close()


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.browser
def test_panel_sliders_and_buttons_move_the_curve_offline(browser, tmp_path):
    page, outside, errors = open_offline(browser, _page(tmp_path, pres.tmd_panel_html(0.05)), viewport=(1180, 900))
    try:

        def state():
            return page.evaluate(
                """() => {
                const p = document.querySelector('div.vtm-panel');
                const pts = s => p.querySelector('svg.vtm-plot polyline.' + s).getAttribute('points');
                return {
                    curve: pts('vtm-curve'), opt: pts('vtm-opt'), bare: pts('vtm-bare'),
                    fixed: [...p.querySelectorAll('svg circle.vtm-fixed')].map(c => c.getAttribute('cx')),
                    peak: p.querySelector('.vtm-r-peak').textContent,
                    pq: p.querySelector('.vtm-r-p').textContent + p.querySelector('.vtm-r-q').textContent,
                    dh_f: p.querySelector('.vtm-dh-f').textContent,
                    f: p.querySelector('output.vtm-f-out').textContent,
                };
            }"""
            )

        def move(cls, value):
            page.eval_on_selector(
                f"input.vtm-{cls}",
                f"el => {{ el.value = '{value!r}'; el.dispatchEvent(new Event('input', {{bubbles: true}})); }}",
            )

        before = state()
        opt = hinf_tuning(0.05)
        assert before["peak"].startswith(f"{opt.peak:.4g}") and before["f"] == f"{opt.f:.4f}"
        assert before["dh_f"] == f"{den_hartog(0.05).f:.4f}"
        move("za", math.log10(0.02))  # less absorber damping: twin peaks, fixed points stay
        after = state()
        assert after["curve"] != before["curve"] and after["opt"] == before["opt"] and after["pq"] == before["pq"]
        assert float(after["peak"].split()[0]) == pytest.approx(tmd_peak(0.05, opt.f, 0.02), rel=1e-3)
        move("f", 1.0)  # the fixed points move with the tuning
        tuned = state()
        assert tuned["fixed"] != after["fixed"] and tuned["curve"] != after["curve"]
        move("zp", 0.0559)  # the paper's primary damping: the bare curve becomes finite
        damped = state()
        assert damped["bare"] != tuned["bare"] and damped["curve"] != tuned["curve"]
        page.click("button.vtm-rule[data-rule='h2']")
        h2 = h2_tuning(0.05)
        clicked = state()
        assert clicked["f"] == f"{h2.f:.4f}".rstrip("0")
        assert float(clicked["peak"].split()[0]) == pytest.approx(
            tmd_peak(0.05, h2.f, h2.zeta_a, zeta_p=0.0559), rel=1e-3
        )
        move("mu", math.log10(0.1))  # a heavier absorber: the rules' tunings are for the new μ
        heavy = state()
        assert heavy["dh_f"] == f"{den_hartog(0.1).f:.4f}" and heavy["opt"] != clicked["opt"]
        Path(SCREENSHOTS).mkdir(parents=True, exist_ok=True)
        move("mu", math.log10(0.05))
        move("zp", 0.0)
        move("f", 0.97)
        move("za", math.log10(0.06))
        page.locator("div.vtm-panel").screenshot(path=str(Path(SCREENSHOTS) / "tmd_panel.png"))
        assert outside == [] and errors == []
    finally:
        page.close()
