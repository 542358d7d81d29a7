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

Examples
--------
>>> block = panel_assets("vibration.chapters.control", "control.js", "control.css")
>>> block.index("window.VibPlot") < block.index("window.vibrationControl"), block.count("<script>")
(True, 2)
>>> kit = panel_assets("vibration.chapters.stability", "stability.js", "stability.css", kit="vst")
>>> kit.index(".vst-panel {") < kit.index(".vst-panel .vst-body"), ".kit-" in kit
(True, False)
>>> case_styles("passive", "LQR")
{'passive': {'color': '#0072B2', 'dash': ''}, 'LQR': {'color': '#E69F00', 'dash': '6 4'}}
"""

from __future__ import annotations

import re
from importlib.resources import files

from matplotlib.colors import to_hex

from .style import CASES

#: SVG dash patterns (stroke-dasharray, px) of matplotlib's line styles, in the proportions matplotlib draws.
DASH = {"-": "", "solid": "", "--": "6 4", "dashed": "6 4", ":": "1.5 3", "dotted": "1.5 3", "-.": "7 3 1.5 3",
        "dashdot": "7 3 1.5 3", "": "", "none": "", "None": ""}  # fmt: skip


def _text(package: str, *path: str) -> str:
    return files(package).joinpath(*path).read_text(encoding="utf-8")


def plot_js() -> str:
    """The plotting helper's source (``vibration/presentation/assets/plot.js``)."""
    return _text("vibration.presentation", "assets", "plot.js")


def kit_css(prefix: str) -> str:
    """The kit's stylesheet (``assets/panel.css``, without its opening comment) for the panel ``.<prefix>-panel``.

    >>> kit_css("vst").splitlines()[0]
    '.vst-panel {'
    """
    if not re.fullmatch(r"[a-z][a-z0-9]*", prefix):
        raise ValueError(f"kit prefix {prefix!r} is not a class prefix: allowed lower-case letters and digits")
    text = re.sub(r"\A/\*.*?\*/\n", "", _text("vibration.presentation", "assets", "panel.css"), flags=re.S)
    return re.sub(r"(\.|--)kit-", rf"\g<1>{prefix}-", text)


def panel_assets(package: str, js: str, css: str, *, kit: str | None = None) -> str:
    """``<style>`` and ``<script>`` elements of a panel: its CSS, the plotting helper, then its script.

    Parameters
    ----------
    package : str
        The chapter's package, e.g. ``"vibration.chapters.control"``; the files live in its ``panel/``.
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
