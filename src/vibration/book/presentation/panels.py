"""What every kernel-free panel shares: its inline assets, with the book's plotting helper first, and the
book's line styles in the form the helper draws.

A chapter's panel is an HTML fragment with its own CSS and JavaScript (``panel/<name>.css`` and
``panel/<name>.js`` in the chapter's package). :func:`panel_assets` returns the ``<style>`` and
``<script>`` elements that inline them, preceded by ``assets/plot.js`` (``window.VibPlot``: axes, ticks, the
book's number format, legends, resizing), so a panel script keeps only its physics and its controls. A panel
built on the kit's parts (``<prefix>-panel``, ``-title``, ``-sub``, ``-controls``) names its prefix and gets
the kit's stylesheet (``assets/panel.css``: the frame, heading, controls and plots) before its own, so its
stylesheet keeps only what is its own.
:func:`line_style` and :func:`case_styles` turn the book's visual language (:data:`~.style.CASES`) into
``{"color", "dash"}`` records for ``VibPlot.draw``, so a case keeps its colour and dash in the panels too.

The Python side of a panel is shared too: :class:`PanelIds` numbers a chapter's panels on a page
(:func:`checked_panel_id` checks an id a caller gives), and :class:`KitExplorer` is the JupyterLab explorer
over the same views: ipywidgets controls, a matplotlib figure on an Agg canvas (:func:`agg_figure`) shown as
PNG and an HTML readout, displayed for renderers without a kernel as the chapter's panel. A chapter's explorer
supplies only its controls, values, figure, readout and panel.

Examples
--------
>>> block = panel_assets("vibration.book.chapters.control", "control.js", "control.css")
>>> block.index("window.VibPlot") < block.index("window.vibrationControl"), block.count("<script>")
(True, 2)
>>> kit = panel_assets("vibration.book.chapters.stability", "stability.js", "stability.css", kit="vst")
>>> kit.index(".vst-panel {") < kit.index(".vst-panel .vst-body"), ".kit-" in kit
(True, False)
>>> case_styles("passive", "LQR")
{'passive': {'color': '#0072B2', 'dash': ''}, 'LQR': {'color': '#E69F00', 'dash': '6 4'}}
"""

from __future__ import annotations

import base64
import hashlib
import io
import itertools
import json
import re
from importlib.resources import files

from matplotlib.colors import to_hex

from ...physics.model import ParameterError
from .style import CASES

#: SVG dash patterns (stroke-dasharray, px) of matplotlib's line styles, in the proportions matplotlib draws.
DASH = {"-": "", "solid": "", "--": "6 4", "dashed": "6 4", ":": "1.5 3", "dotted": "1.5 3", "-.": "7 3 1.5 3",
        "dashdot": "7 3 1.5 3", "": "", "none": "", "None": ""}  # fmt: skip


def _text(package: str, *path: str) -> str:
    return files(package).joinpath(*path).read_text(encoding="utf-8")


def plot_js() -> str:
    """The plotting helper's source (``vibration/presentation/assets/plot.js``)."""
    return _text("vibration.book.presentation", "assets", "plot.js")


def kit_css(prefix: str) -> str:
    """The kit's stylesheet (``assets/panel.css``, without its opening comment) for the panel ``.<prefix>-panel``.

    >>> kit_css("vst").splitlines()[0]
    '.vst-panel {'
    """
    if not re.fullmatch(r"[a-z][a-z0-9]*", prefix):
        raise ValueError(f"kit prefix {prefix!r} is not a class prefix: allowed lower-case letters and digits")
    text = re.sub(r"\A/\*.*?\*/\n", "", _text("vibration.book.presentation", "assets", "panel.css"), flags=re.S)
    return re.sub(r"(\.|--)kit-", rf"\g<1>{prefix}-", text)


def panel_assets(package: str, js: str, css: str, *, kit: str | None = None) -> str:
    """``<style>`` and ``<script>`` elements of a panel: its CSS, the plotting helper, then its script.

    Parameters
    ----------
    package : str
        The chapter's package, e.g. ``"vibration.book.chapters.control"``; the files live in its ``panel/``.
    js, css : str
        File names of the panel's script and style sheet in that folder.
    kit : str, optional
        The class prefix of a panel built on the kit's parts: its style then starts with :func:`kit_css`.
    """
    shared = kit_css(kit) if kit is not None else ""
    return (
        f"<style>\n{shared}{_text(package, 'panel', css)}</style>\n"
        f"<script>\n{plot_js()}</script>\n"
        f"<script>\n{_text(package, 'panel', js)}</script>\n"
    )


def line_style(style: dict | str, width: float | None = None) -> dict:
    """``{"color": "#rrggbb", "dash": "6 4"}`` (and ``"width"`` in px) of a matplotlib style or a case's name.

    The style is a dict with ``color`` and ``linestyle`` (or ``ls``), as :func:`~.style.case_style` returns.

    >>> line_style("exact"), line_style({"color": "0.35", "linestyle": ":"}, 1.2)
    ({'color': '#000000', 'dash': '6 4'}, {'color': '#595959', 'dash': '1.5 3', 'width': 1.2})
    """
    if isinstance(style, str):
        if style not in CASES:
            raise KeyError(f"{style!r} is not a case of the book's visual language: allowed {', '.join(CASES)}")
        style = CASES[style]
    colour = style["color"]
    dash = DASH[style.get("linestyle", style.get("ls", "-"))]
    out = {"color": colour if str(colour).startswith("#") else to_hex(colour), "dash": dash}
    if width is not None:
        out["width"] = width
    return out


def case_styles(*names: str) -> dict:
    """:func:`line_style` of each named case of :data:`~.style.CASES`, by name."""
    return {name: line_style(name) for name in names}


class PanelIds:
    """Element-id prefixes of one chapter's panels: ``<prefix>-<hash of the panel's values>-<count>``.

    The hash keeps a panel's id stable for its values, the count (one per chapter, from 1) tells apart
    panels of the same values on one page.

    >>> ids = PanelIds("vx")
    >>> ids.new({"m": 1.0}), ids.new({"m": 1.0})
    ('vx-adcada6c-1', 'vx-adcada6c-2')
    """

    def __init__(self, prefix: str) -> None:
        self.prefix = prefix
        self._count = itertools.count(1)

    def new(self, values: dict) -> str:
        """A fresh id prefix for a panel showing ``values`` (JSON-serialisable)."""
        digest = hashlib.sha1(json.dumps(values, sort_keys=True).encode()).hexdigest()[:8]
        return f"{self.prefix}-{digest}-{next(self._count)}"


def checked_panel_id(panel_id: str | None) -> str | None:
    """``panel_id`` when it is usable as an element id (a letter, then letters, digits, ``_`` or ``-``), or None.

    >>> checked_panel_id("p-1"), checked_panel_id(None)
    ('p-1', None)
    """
    if panel_id is not None and not re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]*", panel_id):
        raise ParameterError(f"panel_id = {panel_id!r}: allowed a letter followed by letters, digits, _ or -")
    return panel_id


#: The classes the book's style sheet shows on the screen only and in print only (``publishing/book.css``);
#: :func:`vibration.book.presentation.captions.web_only` writes the same spans in the chapters' prose.
SCREEN_ONLY, PRINT_ONLY = "vib-web-only", "vib-print-only"


def screen_words(screen: str, printed: str = "") -> str:
    """Words of a panel that hold only on the screen ("computed in your browser", "move the slider"), and the
    printed edition's words in their place (HTML, both).

    The print style sheet hides the screen words and shows the printed ones. The printed words also carry an
    inline ``display: none``, so a page without the book's style sheet (JupyterLab) shows the screen words only;
    the print rule's ``!important`` overrides it.

    >>> print(screen_words(", computed in your browser", ", computed from the closed form"))
    <span class="vib-web-only">, computed in your browser</span><span class="vib-print-only" \
style="display: none">, computed from the closed form</span>
    """
    out = f'<span class="{SCREEN_ONLY}">{screen}</span>'
    return out + (f'<span class="{PRINT_ONLY}" style="display: none">{printed}</span>' if printed else "")


def range_control(pid: str, key: str, cls: str, label: str, *, low, high, step, value) -> str:
    """One slider of a panel's controls: its label, range input (id ``<pid>-<key>``, class ``cls``) and output.

    ``pid`` is the panel's id prefix, HTML-escaped; ``label`` is HTML; ``low``, ``high``, ``step`` and ``value`` are
    written as given (a caller formats its numbers).

    >>> print(range_control("p", "z", "vx-zeta", "ζ", low=0, high=10, step=1, value=3))
    <label for="p-z">ζ</label>
    <input type="range" class="vx-zeta" id="p-z" min="0" max="10" step="1" value="3">
    <output class="vx-zeta-out" for="p-z"></output>
    <BLANKLINE>
    """
    return (
        f'<label for="{pid}-{key}">{label}</label>\n'
        f'<input type="range" class="{cls}" id="{pid}-{key}" min="{low}" max="{high}" step="{step}" value="{value}">\n'
        f'<output class="{cls}-out" for="{pid}-{key}"></output>\n'
    )


def agg_figure(width: float, height: float):
    """A matplotlib figure of ``width`` x ``height`` inches at 90 dpi on its own Agg canvas (no pyplot state)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), dpi=90, layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def png_bytes(fig) -> bytes:
    """The PNG of ``fig`` at its own size and resolution."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()


class KitExplorer:
    """A chapter's JupyterLab explorer: controls over a figure and a readout, and its panel for the book.

    A subclass builds ``widget`` (the ipywidgets container shown in JupyterLab), ``image`` (an
    ``ipywidgets.Image`` of format PNG) and ``readout`` (an ``ipywidgets.HTML``), calls :meth:`watch` with its
    controls and then :meth:`update`; it supplies :meth:`values`, :meth:`figure`, :meth:`readout_html`,
    :meth:`panel_html` and :meth:`summary`. ``_repr_mimebundle_`` returns the widget view and, for renderers
    without a kernel, the panel at the current values, the figure as PNG and the summary as text.
    """

    widget = image = readout = None

    def values(self) -> dict:
        """The numbers the views show at the controls' current values."""
        raise NotImplementedError

    def figure(self, v: dict):
        """The matplotlib figure of the numbers ``v``."""
        raise NotImplementedError

    def readout_html(self, v: dict) -> str:
        """The readout (HTML) of the numbers ``v``."""
        raise NotImplementedError

    def panel_html(self) -> str:
        """The chapter's kernel-free panel at the controls' current values."""
        raise NotImplementedError

    def summary(self) -> str:
        """One line of text: the explorer and its current values."""
        raise NotImplementedError

    def watch(self, *controls) -> None:
        """Redraw whenever one of ``controls`` changes its value."""
        for control in controls:
            control.observe(lambda _change: self.update(), names="value")

    def update(self) -> None:
        """Redraw the figure and the readout at the controls' current values."""
        v = self.values()
        self.image.value = png_bytes(self.figure(v))
        self.readout.value = self.readout_html(v)

    def _repr_mimebundle_(self, **kwargs):
        data = self.widget._repr_mimebundle_(**kwargs) or {}
        data["text/html"] = self.panel_html()
        data["image/png"] = base64.b64encode(self.image.value).decode("ascii")
        data["text/plain"] = self.summary()
        return data
