"""Captions checked against their figures; the book takes caption, label and alt text from the output."""

import matplotlib.pyplot as plt
import numpy as np
import pytest

from vibration.book.presentation.captions import METADATA_KEY, Captioned, check_caption, panel_words
from vibration.book.presentation.style import case_style, figure


def _three():
    fig, axes = figure(1, 3)
    for ax in axes:
        ax.plot([0, 1], [0, 1], **case_style("c_nominal"))
    return fig


def test_panel_words_follow_the_layout():
    fig = _three()
    assert panel_words(fig) == ["left", "middle", "right"]
    plt.close(fig)
    fig, axes = figure(2, 2)
    assert panel_words(fig) == ["top left", "top right", "bottom left", "bottom right"]
    plt.close(fig)
    fig, axes = figure(2, 1)
    im = axes[0].imshow(np.eye(3))
    fig.colorbar(im, ax=axes[0])
    assert panel_words(fig) == ["top", "bottom"], "a colour bar is not a panel"
    plt.close(fig)


@pytest.mark.parametrize(
    "caption, problem",
    [
        ("Left: one. Right: another.", "middle"),  # the 'Left/Right' for three panels of Fig 11.1
        ("Top: the response.", "top"),
        ("The exact curve is dotted.", "dotted"),
        ("The red curve is light damping.", "red"),
        ("Magnification on a logarithmic axis.", "logarithmic"),
    ],
)
def test_a_caption_that_contradicts_its_figure_is_refused(caption, problem):
    fig = _three()
    with pytest.raises(ValueError, match=problem):
        check_caption(fig, caption)
    plt.close(fig)


def test_a_true_caption_passes_and_travels_in_the_metadata():
    fig, ax = figure()
    ax.plot([1, 2], [1, 4], **case_style("exact"))
    ax.axhline(2.0, **case_style("threshold"))
    ax.set_yscale("log")
    caption = "The exact curve (black, dashed) above a dotted threshold, logarithmic axis."
    cap = Captioned(fig, caption, "fig-x", "A line.")
    data, meta = cap._repr_mimebundle_()
    assert data["image/png"] and meta[METADATA_KEY] == {
        "caption": cap.caption,
        "name": "fig-x",
        "alt": "A line.",
    }
    w, h = meta["image/png"]["width"], meta["image/png"]["height"]
    import base64
    import struct

    png = base64.b64decode(data["image/png"])
    pw, ph = struct.unpack(">II", png[16:24])
    assert (pw, ph) == pytest.approx((2 * w, 2 * h), abs=2), "a HiDPI image shown at the column width"
    assert plt.fignum_exists(fig.number) is False, "the pyplot figure is closed (no second inline copy)"


def test_alt_text_is_a_description_not_a_file():
    fig, ax = figure()
    ax.plot([0, 1], [0, 1])
    with pytest.raises(ValueError, match="alt text"):
        Captioned(fig, "A line.", "fig-y", "figures/fig-y.png")
    plt.close(fig)


def test_dash_dotted_is_not_dotted():
    fig, ax = figure()
    ax.plot([0, 1], [0, 1], linestyle="-.")
    check_caption(fig, "One dash-dotted line.")
    with pytest.raises(ValueError, match="dotted"):
        check_caption(fig, "One dotted line.")
    plt.close(fig)


def _dense_figure():
    """A sparse line with labelled axes beside a Poincaré-like cloud of 30,000 points and a long time series."""
    fig, (left, right) = figure(1, 2)
    rng = np.random.default_rng(1)
    t = np.linspace(0.0, 50.0, 20_000)
    left.plot(t, np.sin(t), color="0.5")
    left.plot([0.0, 50.0], [0.0, 0.5], **case_style("exact"))
    left.set_xlabel("time t (s)")
    right.scatter(rng.random(30_000), rng.random(30_000), s=1)
    right.set_ylabel("velocity v (m/s)")
    return fig


def test_figures_carry_no_svg_unless_asked(monkeypatch):
    """The committed notebooks (nbval's references) keep the PNG alone: an SVG only where the runner asks."""
    from vibration.book.presentation.captions import FORMATS_ENV

    monkeypatch.delenv(FORMATS_ENV, raising=False)
    cap = Captioned(_dense_figure(), "Left: a line. Right: dots.", "fig-d", "A cloud of dots.")
    data, meta = cap._repr_mimebundle_()
    assert sorted(data) == ["image/png", "text/plain"] and "image/svg+xml" not in meta


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_svg_when_asked_keeps_text_and_lines_vector_and_dense_parts_as_images(monkeypatch):
    import re

    from vibration.book.presentation.captions import FORMATS_ENV

    monkeypatch.setenv(FORMATS_ENV, "svg")
    fig = _dense_figure()
    caption = "Left: a grey line under the exact one (black, dashed). Right: dots."
    cap = Captioned(fig, caption, "fig-d", "A cloud of dots.")
    data, meta = cap._repr_mimebundle_()
    svg = data["image/svg+xml"]
    assert meta["image/svg+xml"] == meta["image/png"], "shown at the PNG's size"
    assert data["image/png"], "the screen's pages keep the PNG"
    # text stays text (selectable in the PDF), the axes' labels among it
    texts = re.findall(r"<text\b[^>]*>([^<]*)</text>", svg)
    assert "time t (s)" in texts and "velocity v (m/s)" in texts, texts
    # the dense cloud and the long series are images inside the SVG; the short dashed line stays a path
    assert svg.count("<image") == 2, svg.count("<image")
    assert 'id="line2d_' in svg and "stroke-dasharray" in svg
    assert len(svg) < 400_000, len(svg)  # 30,000 markers as paths would be several MB
    assert [a.get_rasterized() for a in fig.axes[0].lines] == [False, False], "the figure itself is left as it was"
    again = Captioned(_dense_figure(), cap.caption, "fig-d", "A cloud of dots.")._repr_mimebundle_()[0]
    assert again["image/svg+xml"] == svg, "a figure drawn again gives the same bytes (no date, fixed element ids)"
