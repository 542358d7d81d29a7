"""Offline HTML rendering of executed notebooks (vibration.publishing.render)."""

from __future__ import annotations

import base64
import re
from pathlib import Path

import nbformat
import pytest
from conftest import open_offline
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook, new_output

from vibration.presentation.static_page import slider_panel_html
from vibration.publishing.render import (
    EXTRA_HTML_MARKER,
    external_urls,
    latex_to_mathml,
    render_notebook_html,
    strip_widgets,
    write_index_html,
)

MARKDOWN = r"""# Forced response

The model is $m\ddot x + c\dot x + k x = F_0 \sin(\omega t)$, with $\omega_n = \sqrt{k/m}$ in rad/s.

$$\zeta = \frac{c}{2\sqrt{k m}}$$

\begin{equation}
X = \frac{F_0/k}{\sqrt{(1 - r^2)^2 + (2\zeta r)^2}}
\end{equation}
"""

CODE = """\
import matplotlib.pyplot as plt
import numpy as np

t = np.linspace(0.0, 2.0, 201)
fig, ax = plt.subplots(figsize=(4, 2.5))
ax.plot(t, np.sin(3.0 * t))
ax.set_xlabel("time, s")
ax.set_ylabel("displacement, m")
plt.show()
print(f"{'omega, rad/s':>14} {'amplitude, m':>14}")
for w in (1.0, 3.0):
    print(f"{w:14.3f} {w / 7:14.6f}")
"""

# A 1x1 transparent PNG, s.t. ipympl-like outputs carry an image next to their widget view.
PNG_1PX = base64.b64encode(
    bytes.fromhex(
        "89504e470d0a1a0a0000000d4948445200000001000000010806000000"
        "1f15c4890000000d49444154789c6360000002000154a24f6a0000000049454e44ae426082"
    )
).decode()


@pytest.fixture(scope="module")
def executed(tmp_path_factory) -> Path:
    """A small notebook executed with nbclient (kernel "vibration" of the venv)."""
    from nbclient import NotebookClient

    folder = tmp_path_factory.mktemp("nb")
    nb = new_notebook(cells=[new_markdown_cell(MARKDOWN), new_code_cell(CODE)])
    NotebookClient(nb, kernel_name="vibration", timeout=120, resources={"metadata": {"path": str(folder)}}).execute()
    path = folder / "chapter.ipynb"
    nbformat.write(nb, path)
    return path


@pytest.fixture(scope="module")
def rendered(executed) -> tuple[Path, str]:
    out = render_notebook_html(executed, executed.parent / "html" / "chapter.html", extra_html=slider_panel_html())
    return out, out.read_text(encoding="utf-8")


def test_page_loads_nothing_from_outside(rendered):
    _, html = rendered
    assert external_urls(html) == []
    assert "<script src" not in html and "<link" not in html
    assert "mathjax" not in html.lower() and "require.js" not in html and "require.min.js" not in html
    assert "http://" not in html and "https://" not in html


def test_page_shows_markdown_math_code_figure_and_table(rendered):
    _, html = rendered
    assert html.count("<math") >= 4  # two inline, one $$ block and the equation environment
    assert '<math display="block">' in html and '<math display="inline">' in html
    assert 'class="vib-tex-fallback"' not in html
    assert re.search(r'<img[^>]+src="data:image/png;base64,', html)
    assert "Forced response" in html and "<title>Forced response</title>" in html
    assert "amplitude, m" in html and "0.428571" in html  # the printed table
    assert "linspace" in html and "import" in html  # code input (highlighted)
    assert "$" not in re.sub(r"<(script|style)\b.*?</\1>", "", html, flags=re.S)  # no TeX left for MathJax


def test_extra_html_at_end_of_body_or_at_marker(tmp_path):
    nb = new_notebook(cells=[new_markdown_cell("# A\n\nfirst"), new_markdown_cell("last-words")])
    html = render_notebook_html(nb, tmp_path / "a.html", extra_html='<div id="extra">X</div>').read_text()
    assert html.index("last-words") < html.index('<div id="extra">') < html.index("</main>")

    nb.cells.insert(1, new_markdown_cell(f"text-before\n\n{EXTRA_HTML_MARKER}\n\ntext-after"))
    html = render_notebook_html(nb, tmp_path / "b.html", extra_html='<div id="extra">X</div>').read_text()
    assert html.index("text-before") < html.index('<div id="extra">') < html.index("text-after")
    assert html.count('<div id="extra">') == 1 and EXTRA_HTML_MARKER not in html


def _widget_notebook() -> nbformat.NotebookNode:
    view = {"version_major": 2, "version_minor": 0, "model_id": "0123456789abcdef"}
    cells = [
        new_markdown_cell("# Widgets"),
        new_code_cell(
            "ui",
            outputs=[
                new_output(
                    "display_data",
                    data={
                        "text/plain": "VBox(children=(FloatSlider(value=4.47, description='omega'),))",
                        "application/vnd.jupyter.widget-view+json": view,
                    },
                ),
                new_output(
                    "display_data",
                    data={"text/plain": "HBox()", "application/vnd.jupyter.widget-view+json": view},
                ),
            ],
        ),
        new_code_cell(
            "fig.canvas",
            outputs=[
                new_output(
                    "display_data",
                    data={
                        "text/plain": "Canvas(toolbar=Toolbar(...))",
                        "image/png": PNG_1PX,
                        "application/vnd.jupyter.widget-view+json": view,
                    },
                )
            ],
        ),
    ]
    nb = new_notebook(cells=cells)
    nb.metadata["widgets"] = {"application/vnd.jupyter.widget-state+json": {"state": {}, "version_major": 2}}
    return nb


def test_widget_views_are_not_shown_as_raw_text(tmp_path):
    nb = _widget_notebook()
    html = render_notebook_html(nb, tmp_path / "w.html").read_text()
    assert "VBox(" not in html and "HBox(" not in html and "Canvas(" not in html
    assert "widget-view+json" not in html and "widget-state+json" not in html
    assert html.count('class="vib-widget-note"') == 1  # one note for the cell with two widget views
    assert f"data:image/png;base64,{PNG_1PX}" in html  # ipympl-like output keeps its PNG
    assert external_urls(html) == []
    assert "application/vnd.jupyter.widget-view+json" in nb.cells[1].outputs[0].data  # input untouched


def test_strip_widgets_mentions_the_panel_only_when_there_is_one():
    nb = _widget_notebook()
    assert "slider panel" in strip_widgets(nb, has_panel=True).cells[1].outputs[0].data["text/plain"]
    assert "slider panel" not in strip_widgets(nb).cells[1].outputs[0].data["text/plain"]


@pytest.mark.parametrize(
    ("tex", "display", "piece"),
    [
        (r"\omega_n = \sqrt{k/m}", False, "<msqrt>"),
        (r"\begin{aligned} a &= b \\ c &= d \end{aligned}", True, "<mtable"),
        (r"\begin{equation} x = 1 \end{equation}", True, "<mn>1</mn>"),
        (r"|X|/(F_0/k)", False, 'lspace="0em" rspace="0em">&#x0007C;</mo>'),  # TeX spacing of | and /
    ],
)
def test_latex_to_mathml(tex, display, piece):
    out = latex_to_mathml(tex, display)
    assert out.startswith(f'<math display="{"block" if display else "inline"}">') and piece in out
    assert "<mi>&</mi>" not in out and "xmlns" not in out


def test_unsupported_latex_stays_visible():
    out = latex_to_mathml(r"x^", display=False)  # latex2mathml cannot parse it
    assert out == '<code class="vib-tex-fallback">$x^$</code>'


def test_index_page(tmp_path):
    chapters = [
        {
            "title": "Model & exact solution",
            "href": "01_model.html",
            "summary": "x(t) <from rest>",
            "elapsed_s": 3.21,
        },
        {
            "title": "Resonance",
            "href": "02_resonance.html",
            "summary": "Peak near omega_n.",
            "elapsed_s": None,
        },
    ]
    html = write_index_html(tmp_path / "index.html", chapters).read_text()
    assert external_urls(html) == []
    assert 'href="01_model.html"' in html and 'href="02_resonance.html"' in html
    assert "Model &amp; exact solution" in html and "x(t) &lt;from rest&gt;" in html
    assert "executed in 3.2 s" in html


def test_external_urls_finds_what_would_load():
    page = (
        '<link rel="stylesheet" href="https://cdn.ex/a.css"><img srcset="x.png 1x, //cdn.ex/y.png 2x">'
        '<div style="background: url(http://ex.org/b.png)"></div><a href="file:///etc/passwd">f</a>'
        '<style>/* https://only.a.comment */ .a { background: url("data:image/png;base64,AA==") }</style>'
    )
    assert external_urls(page) == [
        "https://cdn.ex/a.css",
        "//cdn.ex/y.png",
        "http://ex.org/b.png",
        "file:///etc/passwd",
    ]


# ---------------------------------------------------------------------------- browser


@pytest.mark.browser
def test_rendered_page_works_offline(rendered, browser):
    path, _ = rendered
    page, outside, errors = open_offline(browser, path)
    try:
        sizes = page.evaluate(
            """() => ({
                math: [...document.querySelectorAll('math')].map(m => m.getBoundingClientRect().height),
                img: [...document.querySelectorAll('img')].map(i => i.naturalWidth),
                panel: document.querySelector('div.vib-panel polyline.vib-x').getAttribute('points')
                    .length,
            })"""
        )
    finally:
        page.close()
    assert outside == []
    assert errors == []
    assert sizes["math"] and min(sizes["math"]) > 0  # MathML laid out by the browser
    assert sizes["img"] and min(sizes["img"]) > 0  # the figure decoded from its data URI
    assert sizes["panel"] > 1000  # the slider panel drew its curve
