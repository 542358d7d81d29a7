"""One figure style for the whole report, and a check that legends leave the data free.

Every figure function calls :func:`figure` (or applies :data:`RC` itself) so sizes, fonts,
grid and colours agree between chapters; labels use mathtext symbols (``r"$\\omega$ (rad/s)"``).
:func:`legend_overlap` measures how much of a legend's box covers plotted data, so tests
can check that legends sit outside the data or in a free corner instead of hoping so.

Examples
--------
>>> import numpy as np
>>> fig, ax = figure()
>>> t = np.linspace(0, 10, 200)
>>> _ = ax.plot(t, np.sin(t), label="sine")
>>> _ = place_legend(ax)
>>> legend_overlap(ax) == 0.0
True
>>> import matplotlib.pyplot as plt; plt.close(fig)
"""

from __future__ import annotations

import matplotlib as mpl
import numpy as np
from matplotlib.figure import Figure
from matplotlib.transforms import Bbox

#: Width of the text column of the book at 1280 px (672 CSS px), inches at the figure dpi: a figure is
#: drawn at the size it is shown, so 9.5 pt text reads as 9.5 pt (PNGs carry twice the pixels).
WIDTH_IN = 7.0
DPI = 96

#: The report's rcParams (applied inside :func:`figure` with ``rc_context``-free global update).
RC = {
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "figure.figsize": (WIDTH_IN, 3.6),
    "figure.constrained_layout.use": True,
    "font.size": 9.5,
    "axes.titlesize": 10,
    "axes.labelsize": 9.5,
    "legend.fontsize": 8.5,
    "xtick.labelsize": 8.5,
    "ytick.labelsize": 8.5,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "legend.framealpha": 0.9,
    "lines.linewidth": 1.4,
    "axes.prop_cycle": mpl.cycler(
        color=["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"]
    ),
    "mathtext.fontset": "dejavusans",
}


#: The Okabe–Ito palette (colour-blind safe), by name.
OKABE_ITO = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky blue": "#56B4E9",
    "bluish green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "reddish purple": "#CC79A7",
    "grey": "#7F7F7F",
}

#: The one word every caption and sentence uses for each colour of the palette (plain names a reader
#: tells apart: vermillion is never also called red, orange is never called yellow).
COLOUR_WORDS = {
    OKABE_ITO["black"]: "black",
    OKABE_ITO["orange"]: "orange",
    OKABE_ITO["sky blue"]: "sky blue",
    OKABE_ITO["bluish green"]: "green",
    OKABE_ITO["yellow"]: "yellow",
    OKABE_ITO["blue"]: "blue",
    OKABE_ITO["vermillion"]: "vermillion",
    OKABE_ITO["reddish purple"]: "purple",
    OKABE_ITO["grey"]: "grey",
}


def colour_word(color: str) -> str:
    """The palette's one word for ``color`` (a hex code of :data:`OKABE_ITO`).

    >>> colour_word("#d55e00"), colour_word(OKABE_ITO["bluish green"])
    ('vermillion', 'green')
    """
    for code, word in COLOUR_WORDS.items():
        if code.lower() == str(color).lower():
            return word
    raise KeyError(f"{color!r} is not a colour of the book's palette")


#: One colour, line style and marker per case for the whole book: a case keeps its look in every
#: chapter. The paper's three dampings (light, nominal, heavy) and its reference run come first;
#: the passive plant of Part II is the nominal damping, so it is drawn as the nominal case; a closed
#: form or exact optimum is black; designs of Part II take the rest of the palette.
CASES: dict[str, dict] = {
    "c_low": {"color": OKABE_ITO["vermillion"], "linestyle": "-", "marker": "v"},
    "c_nominal": {"color": OKABE_ITO["blue"], "linestyle": "-", "marker": "o"},
    "c_high": {"color": OKABE_ITO["bluish green"], "linestyle": "-", "marker": "^"},
    "reference": {"color": OKABE_ITO["orange"], "linestyle": "-", "marker": "s"},
    "passive": {"color": OKABE_ITO["blue"], "linestyle": "-", "marker": "o"},
    "exact": {"color": OKABE_ITO["black"], "linestyle": "--", "marker": ""},
    "optimum": {"color": OKABE_ITO["black"], "linestyle": ":", "marker": "*"},
    "measured": {"color": OKABE_ITO["black"], "linestyle": "", "marker": "."},
    "best passive": {"color": OKABE_ITO["sky blue"], "linestyle": "--", "marker": "D"},
    "PD": {"color": OKABE_ITO["sky blue"], "linestyle": "-.", "marker": "D"},
    "PID": {"color": OKABE_ITO["reddish purple"], "linestyle": "-", "marker": "P"},
    "LQR": {"color": OKABE_ITO["orange"], "linestyle": "--", "marker": "X"},
    "skyhook": {"color": OKABE_ITO["bluish green"], "linestyle": "--", "marker": "h"},
    "semi-active": {"color": OKABE_ITO["reddish purple"], "linestyle": "--", "marker": "p"},
    "learned": {"color": OKABE_ITO["vermillion"], "linestyle": "--", "marker": "*"},
    "ARS": {"color": OKABE_ITO["vermillion"], "linestyle": "--", "marker": "*"},
    "CMA-ES": {"color": OKABE_ITO["orange"], "linestyle": "-", "marker": "d"},
    "undamped": {"color": OKABE_ITO["grey"], "linestyle": "-", "marker": "x"},
    "flutter": {"color": OKABE_ITO["reddish purple"], "linestyle": "-", "marker": "<"},
    "Den Hartog": {"color": OKABE_ITO["orange"], "linestyle": "-", "marker": "s"},
    "H∞": {"color": OKABE_ITO["reddish purple"], "linestyle": "-", "marker": "P"},
    "H2": {"color": OKABE_ITO["sky blue"], "linestyle": "-.", "marker": "D"},
    "robust": {"color": OKABE_ITO["bluish green"], "linestyle": "--", "marker": "^"},
    "hardening": {"color": OKABE_ITO["vermillion"], "linestyle": "-", "marker": "v"},
    "softening": {"color": OKABE_ITO["sky blue"], "linestyle": "-", "marker": "^"},
    "linear": {"color": OKABE_ITO["blue"], "linestyle": "-", "marker": "o"},
    "threshold": {"color": OKABE_ITO["grey"], "linestyle": ":", "marker": ""},
}


#: Colours of a list of cases by position (a chapter's dampings): the paper's three dampings keep their colours
#: (light vermillion, nominal blue, heavy green) and up to three more follow.
SERIES = ("vermillion", "blue", "bluish green", "reddish purple", "sky blue", "grey")


def series_style(i: int) -> dict:
    """Matplotlib keywords of the ``i``-th case of a list (solid lines, :data:`SERIES` colours).

    >>> series_style(0), series_style(2)
    ({'color': '#D55E00', 'linestyle': '-'}, {'color': '#009E73', 'linestyle': '-'})
    """
    if not 0 <= i < len(SERIES):
        raise KeyError(f"case {i} of a list: allowed 0 to {len(SERIES) - 1}")
    return {"color": OKABE_ITO[SERIES[i]], "linestyle": "-"}


def case_style(name: str, marker: bool = False) -> dict:
    """Matplotlib keywords (``color``, ``linestyle`` and, when ``marker``, ``marker``) of a case of :data:`CASES`.

    >>> case_style("c_low")
    {'color': '#D55E00', 'linestyle': '-'}
    """
    try:
        style = CASES[name]
    except KeyError:
        raise KeyError(f"{name!r} is not a case of the book's visual language: allowed {', '.join(CASES)}") from None
    out = {"color": style["color"], "linestyle": style["linestyle"]}
    if marker:
        out["marker"] = style["marker"]
    return out


def damping_case(c: float, c_low: float, c_nominal: float, *, c_high: float) -> str:
    """Which of the paper's damping cases ``c`` is (``"c_low"``, ``"c_nominal"``, ``"c_high"``); nominal first.

    >>> damping_case(15.0, 0.1, 0.5, c_high=15.0)
    'c_high'
    """
    for name, value in (("c_nominal", c_nominal), ("c_low", c_low), ("c_high", c_high)):
        if c == value:
            return name
    raise ValueError(f"c = {c!r} N s/m is none of the paper's dampings {c_low!r}, {c_nominal!r}, {c_high!r}")


def use() -> None:
    """Apply the report style: matplotlib's defaults, then :data:`RC` (nothing leaks in from an earlier style)."""
    mpl.rcdefaults()
    mpl.rcParams.update(RC)


def figure(nrows: int = 1, ncols: int = 1, height: float = 3.6, **kwargs):
    """A figure in the report style, the width of the text column: ``(fig, axes)``.

    The style is applied to matplotlib's settings (:func:`use`), so the labels, legends and
    lines drawn on the figure afterwards follow it too.
    """
    import matplotlib.pyplot as plt

    use()
    fig, axes = plt.subplots(nrows, ncols, figsize=(WIDTH_IN, height), **kwargs)
    return fig, axes


def place_legend(ax, outside: bool = False, **kwargs):
    """A legend in the corner that covers the least data, or to the right outside the axes.

    Tries the four corners and the four edge midpoints, keeps the first with no overlap
    (else the least), so the choice is measured, not hoped.
    """
    if outside:
        return ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **kwargs)
    best, best_loc = None, "best"
    for loc in (
        "upper right",
        "upper left",
        "lower right",
        "lower left",
        "upper center",
        "lower center",
        "center right",
        "center left",
    ):
        leg = ax.legend(loc=loc, **kwargs)
        frac = legend_overlap(ax)
        if best is None or frac < best:
            best, best_loc = frac, loc
        if frac == 0.0:
            return leg
    return ax.legend(loc=best_loc, **kwargs)


def _marker_points(ax) -> np.ndarray:
    """Display coordinates of the collections' points (scatter markers); lines are densified separately."""
    pts = []
    for coll in ax.collections:
        offs = coll.get_offsets()
        if len(offs):
            pts.append(coll.get_offset_transform().transform(np.asarray(offs, float)))
    return np.concatenate(pts) if pts else np.empty((0, 2))


def legend_overlap(ax) -> float:
    """Fraction of the plotted points (lines densified, markers) that fall inside the legend box.

    0.0 means the legend covers no data. Lines are densified to 2000 points per segment
    sequence so a legend sitting on a line between samples is still seen.
    """
    leg = ax.get_legend()
    if leg is None:
        return 0.0
    fig: Figure = ax.figure
    fig.canvas.draw()
    box: Bbox = leg.get_window_extent()
    ax_box = ax.get_window_extent()
    pts = []
    for line in ax.get_lines():
        x, y = (np.asarray(a, float) for a in line.get_data(orig=False))
        if x.size < 2:
            if x.size:
                pts.append(line.get_transform().transform(np.column_stack([x, y])))
            continue
        s = np.linspace(0, x.size - 1, max(2000, x.size))
        xs, ys = np.interp(s, np.arange(x.size), x), np.interp(s, np.arange(y.size), y)
        xy = line.get_transform().transform(np.column_stack([xs, ys]))
        inside_axes = (
            (xy[:, 0] >= ax_box.x0) & (xy[:, 0] <= ax_box.x1) & (xy[:, 1] >= ax_box.y0) & (xy[:, 1] <= ax_box.y1)
        )
        pts.append(xy[inside_axes & np.isfinite(xy).all(axis=1)])
    other = _marker_points(ax)
    if other.size:
        pts.append(other)
    if not pts:
        return 0.0
    allp = np.concatenate(pts)
    if not allp.size:
        return 0.0
    inside = (allp[:, 0] >= box.x0) & (allp[:, 0] <= box.x1) & (allp[:, 1] >= box.y0) & (allp[:, 1] <= box.y1)
    return float(inside.mean())
