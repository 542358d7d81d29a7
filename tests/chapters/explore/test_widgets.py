"""The live explorer without a browser: callbacks, readout, one reused figure, input errors."""

from __future__ import annotations

import base64
import io
import math
import re

import numpy as np
import pytest
from numpy.testing import assert_allclose
from PIL import Image

from vibration import Oscillator, ParameterError, SineForce, settling_time, simulate, steady_state
from vibration.book.chapters.explore.bench import benchmark_updates
from vibration.book.chapters.explore.study import C_MAX, C_MIN
from vibration.book.chapters.explore.widget import Explorer, explorer

# every test here builds on a study, a figure set or a browser that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow


@pytest.fixture
def ex():
    e = explorer()
    yield e
    e.close()


def pixels(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGBA"))


def readout_number(html: str, label: str) -> float:
    """The value cell of the readout row whose quantity is ``label``."""
    m = re.search(re.escape(label) + r"</td><td[^>]*>([^<]+)</td>", html)
    assert m, f"no row {label!r} in the readout"
    return float(m.group(1))


def test_is_a_widget_container_with_the_documented_controls(ex):
    import ipywidgets

    assert isinstance(ex, ipywidgets.VBox) and ex.widget is ex
    assert isinstance(ex.omega_slider, ipywidgets.FloatSlider)
    assert isinstance(ex.c_slider, ipywidgets.FloatLogSlider)
    assert "rad/s" in ex.omega_slider.description and "N s/m" in ex.c_slider.description
    for w, unit in ((ex.m_text, "kg"), (ex.k_text, "N/m"), (ex.F0_text, "N"), (ex.t_end_text, "s")):
        assert f"({unit})" in w.description
    assert "RK45" in ex.rk45_checkbox.description and ex.rk45_checkbox.value is False
    assert ex.omega_hz.value == f"f = {4.47 / (2 * math.pi):.4g} Hz"
    assert ex.image.format == "png" and ex.image.value[:8] == b"\x89PNG\r\n\x1a\n"


def test_damping_slider_reaches_both_ends(ex):
    s = ex.c_slider
    assert s.base**s.min == pytest.approx(C_MIN, rel=1e-12)
    assert s.base**s.max == pytest.approx(C_MAX, rel=1e-12)
    for c in (C_MIN, C_MAX):
        s.value = c
        assert ex.error is None
        assert ex.values["zeta"] == pytest.approx(Oscillator(m=1.0, c=c, k=20.0).damping_ratio, rel=1e-12)


def test_omega_slider_updates_readout_line_and_image(ex):
    html0, x0, png0 = ex.readout.value, ex._art["x"].get_ydata().copy(), ex.png()
    ex.omega_slider.value = 3.0
    assert ex.error is None
    assert ex.readout.value != html0
    assert not np.array_equal(ex._art["x"].get_ydata(), x0)
    assert ex.png() != png0
    assert readout_number(ex.readout.value, "forcing frequency ω") == 3.0
    assert ex.omega_hz.value == f"f = {3.0 / (2 * math.pi):.4g} Hz"
    assert ex._art["point"].get_xdata()[0] == 3.0


def test_damping_slider_updates_readout_lines_and_curve(ex):
    html0 = ex.readout.value
    v0, curve0 = ex._art["v"].get_ydata().copy(), ex._art["curve"].get_ydata().copy()
    ex.c_slider.value = 15.0
    assert ex.readout.value != html0 and "overdamped" in ex.readout.value
    assert not np.array_equal(ex._art["v"].get_ydata(), v0)
    assert np.max(ex._art["curve"].get_ydata()) < np.max(curve0)


@pytest.mark.parametrize(
    ("omega", "c"), [(4.47, 0.5), (3.0, 0.5), (4.47, 0.1), (4.47, 15.0), (12.0, 20.0), (1.0, 0.01)]
)
def test_readout_equals_the_package(ex, omega, c):
    ex.omega_slider.value = omega
    ex.c_slider.value = c
    osc, force = Oscillator(m=1.0, c=c, k=20.0), SineForce(F0=5.0, omega=omega)
    ss, ts = steady_state(osc, force), settling_time(osc, force)
    v = ex.values
    assert v["amplitude"] == ss.amplitude and v["magnification"] == ss.magnification
    assert v["settling"] == ts
    assert v["steady_reached"] == ("yes" if ts <= 50.0 else "no")
    assert v["omega_n"] == osc.natural_frequency and v["zeta"] == osc.damping_ratio
    assert v["regime"] == osc.regime
    assert v["f"] == force.frequency_hz and v["f_n"] == osc.natural_frequency / (2 * math.pi)
    html = ex.readout.value
    assert_allclose(readout_number(html, "steady-state amplitude |X|"), ss.amplitude, rtol=1e-4)
    assert_allclose(readout_number(html, "2 % settling time"), ts, rtol=1e-4)
    assert_allclose(readout_number(html, "natural frequency f_n"), osc.natural_frequency / (2 * math.pi), rtol=1e-4)
    assert_allclose(readout_number(html, "peak |x| in the window"), np.max(np.abs(ex._art["x"].get_ydata())), rtol=1e-4)
    assert re.search(r"regime</td><td[^>]*>" + osc.regime + "</td>", html)


def test_one_figure_reused_and_blits_match_full_redraws(ex):
    fig, axes, lines = ex.figure, dict(ex._axes), dict(ex._art)
    for w in (4.48, 4.49, 4.5):
        ex.omega_slider.value = w
    ex.c_slider.value = 0.6
    ex.t_end_text.value = 20.0
    assert ex.figure is fig and ex._axes == axes and ex._art == lines
    assert ex.image.value is not None and ex.error is None
    assert ex.n_blits >= 1 and ex.n_full_draws >= 2  # t_end moved the time axis: background redrawn
    ex.omega_slider.value = 4.51
    blitted = pixels(ex.png())
    assert ex.update(force_full=True)
    assert np.array_equal(blitted, pixels(ex.png()))
    assert ex._axes["x"].get_xlim() == (0.0, 20.0)


def test_no_pyplot_figure_is_created(ex):
    import matplotlib.pyplot as plt

    before = set(plt.get_fignums())  # other tests' figures may be open in this process
    ex.omega_slider.value = 4.0
    assert set(plt.get_fignums()) == before
    assert all(plt.figure(n) is not ex.figure for n in before)


def test_every_axis_is_labelled_with_units(ex):
    ax_x, ax_v, ax_m = ex._axes["x"], ex._axes["v"], ex._axes["m"]
    assert ax_x.get_ylabel().endswith("(m)") and ax_v.get_ylabel().endswith("(m/s)")
    assert ax_v.get_xlabel().endswith("(s)") and ax_m.get_xlabel().endswith("(rad/s)")
    assert ax_m.get_ylabel().endswith("(1)")
    (hz,) = [c for c in ax_m.child_axes if c.get_xlabel()]
    assert hz.get_xlabel().endswith("(Hz)")


@pytest.mark.parametrize(
    ("control", "value", "message"),
    [
        ("m_text", 0.0, "m = 0.0 kg is out of range"),
        ("k_text", -20.0, "k = -20.0 N/m is out of range"),
        ("F0_text", -1.0, "F0 = -1.0 N is out of range"),
        ("t_end_text", 0.0, "t_end = 0.0 s is out of range"),
    ],
)
def test_bad_secondary_value_is_shown_not_raised(ex, control, value, message):
    png0, values0, x0 = ex.png(), dict(ex.values), ex._art["x"].get_ydata().copy()
    getattr(ex, control).value = value  # runs the callback; must not raise
    assert ex.error is not None and ex.error.startswith(message)
    assert "Input rejected" in ex.readout.value and message in ex.readout.value
    assert ex.png() == png0 and ex.values == values0
    assert np.array_equal(ex._art["x"].get_ydata(), x0)
    ex.omega_slider.value = 3.0  # still rejected while the bad value stands
    assert ex.error.startswith(message) and ex.png() == png0
    getattr(ex, control).value = {"m_text": 2.0, "k_text": 30.0, "F0_text": 1.0, "t_end_text": 10.0}[control]
    assert ex.error is None and "Input rejected" not in ex.readout.value and ex.png() != png0


def test_overflow_is_an_input_error(ex):
    png0 = ex.png()
    ex.F0_text.value = 1e308
    ex.k_text.value = 1e-3  # F0/k overflows
    assert ex.error.startswith("no finite response for m = 1 kg, c = 0.5 N s/m, k = 0.001 N/m, F0 = 1e+308 N")
    assert ex.png() == png0
    ex.F0_text.value = 5.0
    assert ex.error is None


def test_extreme_stiffness_keeps_the_forcing_frequency(ex):
    ex.m_text.value = 1e-30  # omega_n = 4.5e15 rad/s: the slider widens, its value stays
    assert ex.error is None and ex.omega_slider.value == 4.47 and ex.omega_slider.max >= 1.3e16
    ex.m_text.value = 1.0
    assert ex.omega_slider.value == 4.47 and ex.omega_slider.max == 15.0 and ex.omega_slider.step == 0.01


def test_rk45_overlay_is_the_papers_simulation(ex):
    ex.rk45_checkbox.value = True
    assert ex.error is None and ex._art["x_rk45"].get_visible()
    paper = simulate(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47), 50.0, n_points=5001)
    assert_allclose(ex._art["x_rk45"].get_ydata(), paper.x, rtol=0, atol=0)
    assert ex.values["rk45_nfev"] == paper.nfev
    assert ex.values["rk45_max_error"] == pytest.approx(np.max(np.abs(paper.x - ex._art["x"].get_ydata())))
    assert "RK45 max |x − x_exact|" in ex.table()
    ex.rk45_checkbox.value = False
    assert not ex._art["x_rk45"].get_visible() and "rk45_nfev" not in ex.values


def test_omega_slider_follows_the_natural_frequency(ex):
    ex.k_text.value = 2000.0  # omega_n = 44.7 rad/s
    assert ex.omega_slider.max >= 3 * ex.values["omega_n"]
    assert ex._axes["m"].get_xlim()[1] == ex.omega_slider.max
    ex.k_text.value = 20.0
    assert ex.omega_slider.max == 15.0 and ex.omega_slider.value == 4.47


def test_bad_starting_values_raise():
    with pytest.raises(ParameterError, match="m = 0.0 kg"):
        explorer(m=0.0)
    with pytest.raises(ParameterError, match="c = 0.0 N s/m"):
        explorer(c=0.0)
    with pytest.raises(ParameterError, match="n_points"):
        explorer(n_points=1)


def test_table_is_fixed_precision_text(ex):
    lines = ex.table().splitlines()
    assert lines[0].split() == ["quantity", "value", "unit"]
    assert "2 % settling time" in lines[11] and lines[11].split()[-2:] == ["15.652", "s"]
    assert ex.table() == explorer().table()


def test_display_bundle_has_a_static_fallback(ex):
    data = ex._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in data
    assert pixels(base64.b64decode(data["image/png"])).shape == (540, 1000, 4)
    assert data["text/plain"].startswith("Explorer(m=1.0 kg")


def test_png_frames_decode_to_the_canvas(ex):
    assert np.array_equal(pixels(ex.png()), np.asarray(ex.figure.canvas.buffer_rgba()))


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_benchmark_reports_medians():
    res = benchmark_updates(repeats=2)
    assert res["update_median_s"] > 0 and res["rebuild_median_s"] > 0 and res["full_draw_median_s"] > 0
    assert 0.0 <= res["full_draw_fraction"] <= 1.0 and res["repeats"] == 2 and res["n_points"] == 5001


def test_explorer_class_accepts_the_same_arguments():
    e = Explorer(m=2.0, k=50.0, F0=1.0, c=1.0, omega=5.0, t_end=10.0, n_points=1001, show_rk45=True)
    assert e.values["t_end"] == 10.0 and len(e._art["x"].get_xdata()) == 1001 and "rk45_nfev" in e.values
    e.close()
