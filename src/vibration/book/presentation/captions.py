"""Figures that carry their own caption and alt text, checked against what is drawn.

A chapter's figure function returns :class:`Captioned`: the matplotlib figure, a caption built by
code from the figure and the study's numbers, the figure's label and a one-sentence alt text.
:func:`check_caption` refuses a caption that contradicts its figure: position words (left,
middle, right, top, bottom) that do not match the panel layout or leave a panel out, line
styles, colours or logarithmic axes that are not drawn. The figure shows as a HiDPI PNG at the
book's column width; the caption, label and alt text travel in the output's metadata, where
the book build picks them up (:data:`METADATA_KEY`), and as the text a regression test compares.

The print edition's figures are vector: a kernel whose environment names ``svg`` in
:data:`FORMATS_ENV` (the report runner sets it; JupyterLab, nbval and the committed notebooks
do not) adds an SVG beside the PNG (:meth:`Captioned.svg`), with text as text, so the PDF
keeps it selectable, and each dense artist (more than :data:`DENSE_POINTS` points: a Poincaré
section, a long time series, a mesh) drawn as an image inside the vector figure, so the file
stays small. The screen's pages keep the PNG; the single page the PDF is printed from takes the
SVG (the book's mime priorities, :mod:`vibration.book.publishing.sphinx_source`).

Examples
--------
>>> from vibration.book.presentation.style import figure
>>> fig, (a, b) = figure(1, 2)
>>> _ = a.plot([0, 1], [0, 1], "k--"); _ = b.plot([0, 1], [1, 0])
>>> panel_words(fig)
['left', 'right']
>>> check_caption(fig, "Left: the exact line (dashed). Right: its mirror.")
>>> check_caption(fig, "Left, middle and right: three views.")
Traceback (most recent call last):
...
ValueError: caption names 'middle' but the figure's panels are left, right
>>> check_caption(fig, "The line (dotted).")
Traceback (most recent call last):
...
ValueError: caption says 'dotted' but no dotted line is drawn
>>> import matplotlib.pyplot as plt; plt.close(fig)
"""

from __future__ import annotations

import base64
import contextlib
import io
import os
import re

import numpy as np
from matplotlib.colors import to_hex

from . import style

#: Key of the output metadata that carries ``{"caption", "name", "alt"}`` to the book build.
METADATA_KEY = "vibration/figure"

#: PNG pixels per CSS pixel (a HiDPI image shown at the column width stays sharp).
PIXEL_RATIO = 2

#: Environment variable naming the figure formats a kernel's figures carry beside the PNG (comma-separated;
#: ``svg`` is the one known). The report runner sets it to ``svg`` for its executed copies.
FORMATS_ENV = "VIBRATION_FIGURE_FORMATS"

#: An artist with more points than this (a line's vertices, a scatter's markers, a mesh's corners) is drawn as
#: an image inside the SVG: as vector paths it would make the file large and slow to print.
DENSE_POINTS = 2000

#: Resolution of those images inside the SVG, dots per inch (print quality at the figure's printed size).
RASTER_DPI = 200

_POSITION = ("left", "middle", "right", "top", "bottom", "centre", "center", "above", "below", "upper", "lower")
_LINESTYLE = {"dashed": "--", "dotted": ":", "dash-dotted": "-."}
_COLOURS = {
    "black": ("#000000",),
    "grey": ("#7f7f7f", "#808080", "#888888", "#999999", "#666666", "#aaaaaa", "#bbbbbb", "#cccccc"),
    "gray": ("#7f7f7f", "#808080", "#888888", "#999999", "#666666", "#aaaaaa", "#bbbbbb", "#cccccc"),
    "orange": (style.OKABE_ITO["orange"], "#ff7f0e"),
    "sky blue": (style.OKABE_ITO["sky blue"],),
    "green": (style.OKABE_ITO["bluish green"], "#2ca02c"),
    "blue": (style.OKABE_ITO["blue"], style.OKABE_ITO["sky blue"], "#1f77b4"),
    "red": (style.OKABE_ITO["vermillion"], "#d62728"),
    "vermillion": (style.OKABE_ITO["vermillion"],),
    "purple": (style.OKABE_ITO["reddish purple"], "#9467bd"),
    "yellow": (style.OKABE_ITO["yellow"],),
}


def _panels(fig) -> list:
    """The figure's data axes (colour bars and invisible axes left out)."""
    return [ax for ax in fig.axes if ax.get_visible() and ax.get_label() != "<colorbar>" and ax.axison]


def _bands(intervals: list[tuple[float, float]]) -> list[int]:
    """Index of the band (column or row) of each interval: intervals that overlap by half the shorter share one."""
    order = sorted(range(len(intervals)), key=lambda i: intervals[i][0])
    band_of = [0] * len(intervals)
    bands: list[tuple[float, float]] = []
    for i in order:
        lo, hi = intervals[i]
        for j, (blo, bhi) in enumerate(bands):
            if min(hi, bhi) - max(lo, blo) > 0.5 * min(hi - lo, bhi - blo):
                band_of[i] = j
                bands[j] = (min(lo, blo), max(hi, bhi))
                break
        else:
            band_of[i] = len(bands)
            bands.append((lo, hi))
    rank = sorted(range(len(bands)), key=lambda j: bands[j][0])
    return [rank.index(b) for b in band_of]


def panel_words(fig) -> list[str]:
    """Position words of each panel, in ``fig.axes`` order: ``[]`` for one panel, else e.g. ``["left", "right"]``.

    One row: left, (middle,) right; one column: top, (middle,) bottom; a grid: "top left", ...;
    more than three in a line: "panel 1", "panel 2", ...
    """
    if fig.get_layout_engine() is not None:
        fig.get_layout_engine().execute(fig)
    axes = _panels(fig)
    if len(axes) <= 1:
        return []
    boxes = [ax.get_position() for ax in axes]
    col = _bands([(b.x0, b.x1) for b in boxes])
    row = _bands([(b.y0, b.y1) for b in boxes])
    n_cols, n_rows = max(col) + 1, max(row) + 1
    row = [n_rows - 1 - r for r in row]  # rows from the top
    if n_cols > 3 or n_rows > 3:
        return [f"panel {i + 1}" for i in range(len(axes))]

    def name(index: int, n: int, words: tuple[str, str, str]) -> str:
        return "" if n == 1 else words[0] if index == 0 else words[2] if index == n - 1 else words[1]

    out = []
    for c, r in zip(col, row, strict=True):
        words = [name(r, n_rows, ("top", "middle", "bottom")), name(c, n_cols, ("left", "middle", "right"))]
        out.append(" ".join(w for w in words if w))
    return out


def _drawn_linestyles(fig) -> set[str]:
    found = set()
    for ax in _panels(fig):
        for line in ax.get_lines():
            if line.get_visible() and len(line.get_xdata()) > 1:
                found.add({"--": "--", "dashed": "--", ":": ":", "dotted": ":", "-.": "-.", "dashdot": "-."}.get(
                    line.get_linestyle(), line.get_linestyle()))  # fmt: skip
        for coll in ax.collections:  # vlines/hlines and LineCollections
            for ls in getattr(coll, "get_linestyles", list)() or []:
                offset, dashes = ls if isinstance(ls, tuple) else (None, None)
                if dashes:
                    on = dashes[0]
                    found.add(":" if on < 2.0 else "-." if len(dashes) > 2 else "--")
    return found


def _drawn_colours(fig) -> set[str]:
    found = set()
    for ax in _panels(fig):
        for line in ax.get_lines():
            found.add(to_hex(line.get_color()).lower())
            found.add(to_hex(line.get_markerfacecolor()).lower() if line.get_marker() not in (None, "", "None") else "")
        for coll in ax.collections:
            for arr in (coll.get_edgecolor(), coll.get_facecolor()):
                for rgba in np.atleast_2d(arr):
                    if len(rgba) == 4 and rgba[3] > 0:
                        found.add(to_hex(rgba).lower())
        for patch in ax.patches:
            found.add(to_hex(patch.get_facecolor()).lower())
    return found - {""}


def _greyish(hex_colour: str) -> bool:
    """A neutral grey: equal channels, neither near black nor near white."""
    r, g, b = (int(hex_colour[i : i + 2], 16) / 255 for i in (1, 3, 5))
    return max(r, g, b) - min(r, g, b) < 0.04 and 0.2 < r < 0.9


def check_caption(fig, caption: str, *, layout: bool = True) -> None:
    """Raise ``ValueError`` where ``caption`` contradicts ``fig`` (layout, line styles, colours, log axes).

    ``layout=False`` leaves the panel words out (a remark's "on top of each other" names no panel).
    """
    text = caption.lower()
    words = panel_words(fig) if layout else []
    present = {w for phrase in words for w in phrase.split()}
    named = {w for w in _POSITION if re.search(rf"\b{w}\b", text)} if layout else set()
    layout = {"left", "right", "middle", "top", "bottom"}
    for w in sorted(named & layout):
        if w not in present:
            raise ValueError(f"caption names {w!r} but the figure's panels are {', '.join(words) or 'one panel'}")
    if named & {"left", "right"} and not {"left", "right"} <= named and {"left", "right"} <= present:
        raise ValueError(f"caption names only one side of the panels {', '.join(words)}")
    if "middle" in present and named & {"left", "right"} and "middle" not in named and "centre" not in named:
        raise ValueError(f"caption leaves out the middle panel of {', '.join(words)}")
    if named & {"top", "bottom"} and {"top", "bottom"} <= present and not {"top", "bottom"} <= named:
        raise ValueError(f"caption names only one of the panels {', '.join(words)}")
    styles = _drawn_linestyles(fig)
    for word, ls in _LINESTYLE.items():
        pattern = rf"(?<!dash-)\b{word}\b"  # "dash-dotted" is neither dashed nor dotted
        if re.search(pattern, text) and ls not in styles:
            raise ValueError(f"caption says {word!r} but no {word} line is drawn")
    colours = _drawn_colours(fig)
    if any(_greyish(h) for h in colours):
        colours |= {"#7f7f7f"}  # any neutral grey answers to "grey"
    for word, hexes in _COLOURS.items():
        if re.search(rf"(?<![-\w]){word}\b", text) and not colours & {h.lower() for h in hexes}:
            raise ValueError(f"caption says {word!r} but nothing {word} is drawn")
    if re.search(r"\blog(arithmic)?\b", text):
        if not any("log" in (ax.get_xscale(), ax.get_yscale())[i] for ax in _panels(fig) for i in (0, 1)):
            raise ValueError("caption says logarithmic but no axis is logarithmic")


#: The longest caption the book prints, in words; what a figure shows beyond it goes to its remark.
CAPTION_WORDS = 60


def caption_words(text: str) -> int:
    """Words of a caption as the reader counts them: a formula or a cross-reference is one word.

    >>> caption_words("Response to $F_0 x$ at ω = 4.47 rad/s; {numref}`fig-x` shows more.")
    10
    """
    text = re.sub(r"\$[^$]*\$", " formula ", text)
    text = re.sub(r"\{\w+\}`[^`]*`", " reference ", text)
    text = re.sub(r"<[^>]+>", "", text)
    return sum(1 for w in text.split() if re.search(r"\w", w))


class Captioned:
    """A figure with its caption, label and alt text (a HiDPI PNG, and an SVG for print; see the module's notes).

    The caption says what is drawn, in at most :data:`CAPTION_WORDS` words; ``remark``, when given, is
    what the figure shows (its computed findings), set as a paragraph of text under the figure.
    """

    def __init__(self, fig, caption: str, name: str, alt: str, *, remark: str = "") -> None:
        import matplotlib.pyplot as plt

        if not caption.strip() or not alt.strip():
            raise ValueError(f"figure {name!r}: caption and alt text must not be empty")
        if re.search(r"\.(png|svg|jpe?g|pdf)\b", alt) or re.fullmatch(r"[\w./\\-]+", alt.strip()):
            raise ValueError(f"figure {name!r}: alt text must describe the figure, not name a file: {alt!r}")
        check_caption(fig, caption)
        if remark:
            check_caption(fig, remark, layout=False)
        self.fig, self.caption, self.name, self.alt, self.remark = fig, caption, name, alt, remark
        plt.close(fig)

    def png(self) -> bytes:
        """The figure as PNG at :data:`PIXEL_RATIO` times the style's resolution."""
        buf = io.BytesIO()
        self.fig.savefig(buf, format="png", dpi=style.DPI * PIXEL_RATIO)
        return buf.getvalue()

    def svg(self) -> str:
        """The figure as SVG: text as text (in the style's fonts), each dense artist (:func:`dense_artists`) an
        image at :data:`RASTER_DPI` inside it; element ids and the file depend on the figure only (no date)."""
        import matplotlib as mpl

        buf = io.StringIO()
        with _rasterized(dense_artists(self.fig)), mpl.rc_context({"svg.fonttype": "none", "svg.hashsalt": self.name}):
            self.fig.savefig(buf, format="svg", dpi=RASTER_DPI, metadata={"Date": None})
        return buf.getvalue()

    def _repr_mimebundle_(self, include=None, exclude=None):
        width, height = self.fig.get_size_inches() * style.DPI
        size = {"width": int(round(width)), "height": int(round(height))}
        data = {
            "image/png": base64.b64encode(self.png()).decode("ascii"),
            "text/plain": f"Figure {self.name}: {self.caption}",
        }
        meta = {"image/png": size, METADATA_KEY: {"caption": self.caption, "name": self.name, "alt": self.alt}}
        if "svg" in figure_formats() or "image/svg+xml" in (include or ()):
            data["image/svg+xml"] = self.svg()
            meta["image/svg+xml"] = dict(size)  # shown at the PNG's CSS size
        return data, meta

    def _ipython_display_(self) -> None:
        """The figure, then its remark as a paragraph of Markdown (two outputs of one cell)."""
        from IPython.display import Markdown, display

        data, meta = self._repr_mimebundle_()
        display(data, raw=True, metadata=meta)
        if self.remark:
            display(Markdown(self.remark))

    def __repr__(self) -> str:
        return f"Figure {self.name}: {self.caption}" + (f"\n{self.remark}" if self.remark else "")


def figure_formats() -> set[str]:
    """The formats named in :data:`FORMATS_ENV` (lower case), beside the PNG every figure carries."""
    return {f.strip().lower() for f in os.environ.get(FORMATS_ENV, "").split(",") if f.strip()}


def _points(artist) -> int:
    """How many points ``artist`` draws: a line's vertices, a collection's markers or path vertices, a mesh's
    corners (0 for anything else)."""
    from matplotlib.collections import Collection, QuadMesh
    from matplotlib.lines import Line2D

    if isinstance(artist, Line2D):
        return len(artist.get_xydata())
    if isinstance(artist, QuadMesh):
        return int(np.prod(artist.get_coordinates().shape[:2]))
    if isinstance(artist, Collection):
        offsets = len(artist.get_offsets())
        vertices = sum(len(path.vertices) for path in artist.get_paths())
        return max(offsets, vertices)
    return 0


def dense_artists(fig) -> list:
    """The artists of ``fig`` with more than :data:`DENSE_POINTS` points, which the SVG draws as images.

    >>> from vibration.book.presentation.style import figure
    >>> fig, ax = figure()
    >>> line, = ax.plot(np.arange(3000.0)); dots = ax.scatter([0, 1], [0, 1])
    >>> dense_artists(fig) == [line]
    True
    >>> import matplotlib.pyplot as plt; plt.close(fig)
    """
    return [a for ax in fig.axes for a in (*ax.lines, *ax.collections) if _points(a) > DENSE_POINTS]


@contextlib.contextmanager
def _rasterized(artists: list):
    """``artists`` rasterized inside the block, their own setting restored after it."""
    before = [a.get_rasterized() for a in artists]
    for a in artists:
        a.set_rasterized(True)
    try:
        yield
    finally:
        for a, was in zip(artists, before, strict=True):
            a.set_rasterized(was)


def web_only(text: str, print_text: str = "") -> str:
    """Words that hold only on the screen (a layout, a button), with the printed edition's own words.

    Both are inline HTML spans in the Markdown: the print style sheet hides ``vib-web-only`` and shows
    ``vib-print-only``; the screen does the opposite.

    >>> web_only(" on a wide page", print_text=" here")
    '<span class="vib-web-only"> on a wide page</span><span class="vib-print-only"> here</span>'
    """
    out = f'<span class="vib-web-only">{text}</span>'
    return out + (f'<span class="vib-print-only">{print_text}</span>' if print_text else "")
