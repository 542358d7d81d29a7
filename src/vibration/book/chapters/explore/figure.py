"""The live explorer's figure: its layout, its line styles, the words that describe it, and its PNG frames.

:func:`build_figure` makes the one figure the explorer redraws (a plain Agg figure, never registered with
pyplot); :func:`figure_words` reads its layout and line styles back, so the chapter's description of the
explorer follows the drawing. :func:`png` writes the canvas as PNG quickly for live frames.
"""

from __future__ import annotations

import io
import math
import struct
import zlib

import matplotlib as mpl
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from vibration.book.presentation.style import OKABE_ITO

TWO_PI = 2.0 * math.pi

#: The look of the figure's lines: the response in the book's blue, the steady-state amplitudes and the
#: operating point in vermillion (dashed lines), the settling time and the natural frequency grey dotted,
#: the paper's RK45 orange dashed.
STYLE = {
    "response": {"color": OKABE_ITO["blue"], "lw": 0.9},
    "curve": {"color": OKABE_ITO["blue"], "lw": 1.2},
    "envelope": {"color": OKABE_ITO["vermillion"], "lw": 0.9, "ls": "--"},
    "marker": {"color": OKABE_ITO["grey"], "lw": 1.0, "ls": ":"},
    "rk45": {"color": OKABE_ITO["orange"], "lw": 1.0, "ls": "--"},
    "point": {"color": OKABE_ITO["vermillion"], "marker": "o", "ms": 7, "ls": "none"},
}

#: Figure size (inches) and resolution (dots per inch) of the explorer's image.
FIGSIZE, DPI = (10.0, 5.4), 100

#: zlib level of the live PNG frames (1: fastest; level 6 costs about 13 ms more per frame here).
PNG_LEVEL = 1


def _hz(w):
    return np.asarray(w, dtype=float) / TWO_PI


def _rad(f):
    return np.asarray(f, dtype=float) * TWO_PI


def _nice_ceil(x: float) -> float:
    """Smallest of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten that is >= x (> 0)."""
    e = math.floor(math.log10(x))
    for mant in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0):
        v = mant * 10.0**e
        if v >= x * (1 - 1e-12):
            return v
    return 10.0 ** (e + 1)  # pragma: no cover - the loop always returns


def omega_range(omega_n: float, omega: float) -> tuple[float, float]:
    """Slider maximum and step (rad/s): at least 3 omega_n and 1.5 omega, about 1000-1500 steps."""
    top = _nice_ceil(max(3.0 * omega_n, 1.5 * omega, 1e-6))
    step = 10.0 ** (math.floor(math.log10(top)) - 3)
    return top, step


def omega_grid(omega_n: float, zeta: float, omega_max: float, *, n: int = 1201) -> np.ndarray:
    """Frequencies (rad/s) at which the magnification curve is drawn (display sampling only).

    A uniform grid on ``[0, omega_max]`` plus points clustered within a few
    multiples of ``zeta omega_n`` of ``omega_n``, so that the resonance peak
    is resolved at the lightest damping of the slider.
    """
    base = np.linspace(0.0, omega_max, n)
    near = omega_n * (1.0 + zeta * np.sinh(np.linspace(-6.0, 6.0, 241)))
    near = near[(near > 0.0) & (near < omega_max)]
    return np.unique(np.concatenate([base, near, [omega_n]]))


def build_figure() -> tuple[Figure, dict, dict]:
    """The explorer's figure, its axes (``x``, ``v``, ``m``) and its empty animated artists, by name.

    The time plots sit in the left column (displacement above velocity), the magnification plot fills the
    right column; :func:`figure_words` reads that layout back for the chapter's description.
    """
    fig = Figure(figsize=FIGSIZE, dpi=DPI, layout="none")  # fixed layout: blits need fixed axes
    FigureCanvasAgg(fig)
    gs = fig.add_gridspec(
        2,
        2,
        width_ratios=(1.55, 1.0),
        left=0.085,
        right=0.985,
        bottom=0.1,
        top=0.83,
        wspace=0.22,
        hspace=0.2,
    )
    with mpl.rc_context({"axes.autolimit_mode": "round_numbers"}):
        ax_x = fig.add_subplot(gs[0, 0])
        ax_v = fig.add_subplot(gs[1, 0], sharex=ax_x)
        ax_m = fig.add_subplot(gs[:, 1])
    ax_x.tick_params(labelbottom=False)
    for ax in (ax_x, ax_v):  # short tick labels (offset "1e-3" above), labels at a fixed place
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-1, 3), useMathText=True)
        ax.yaxis.set_label_coords(-0.095, 0.5)
    ax_x.set_ylabel("displacement x (m)")
    ax_v.set_ylabel("velocity v (m/s)")
    ax_v.set_xlabel("time t (s)")
    ax_m.set_xlabel("forcing frequency ω (rad/s)")
    ax_m.set_ylabel(r"magnification $|X|\,/\,(F_0/k)$ (1)")
    ax_m.set_yscale("log")
    sec = ax_m.secondary_xaxis("top", functions=(_hz, _rad))
    sec.set_xlabel("forcing frequency f (Hz)")
    for ax in (ax_x, ax_v, ax_m):
        ax.grid(alpha=0.3)
        ax.set_autoscalex_on(False)

    def line(ax, **kw):
        (ln,) = ax.plot([], [], animated=True, **kw)
        return ln

    def hline(ax, **kw):
        return ax.axhline(0.0, animated=True, **kw)

    art = {
        "x_env_hi": hline(ax_x, **STYLE["envelope"]),
        "x_env_lo": hline(ax_x, **STYLE["envelope"]),
        "v_env_hi": hline(ax_v, **STYLE["envelope"]),
        "v_env_lo": hline(ax_v, **STYLE["envelope"]),
        "x_settle": ax_x.axvline(0.0, animated=True, **STYLE["marker"]),
        "v_settle": ax_v.axvline(0.0, animated=True, **STYLE["marker"]),
        "x": line(ax_x, **STYLE["response"]),
        "v": line(ax_v, **STYLE["response"]),
        "x_rk45": line(ax_x, **STYLE["rk45"]),
        "v_rk45": line(ax_v, **STYLE["rk45"]),
        "omega_n": ax_m.axvline(1.0, animated=True, **STYLE["marker"]),
        "curve": line(ax_m, **STYLE["curve"]),
        "point": line(ax_m, **STYLE["point"]),
    }
    return fig, {"x": ax_x, "v": ax_v, "m": ax_m}, art


_LINESTYLE_WORD = {"--": "dashed", ":": "dotted", "-.": "dash-dotted", "-": "solid"}


def figure_words(fig: Figure, axes: dict, art: dict) -> dict[str, str]:
    """Where each plot sits and how its marked lines are drawn, read from the figure itself.

    Keys: ``x``, ``v``, ``m`` (position words of the displacement, velocity and magnification plots),
    ``envelope``, ``settle``, ``natural``, ``rk45`` (line-style words), ``hz`` ("Hz above" when the
    magnification plot has a second axis in Hz, else "").
    """
    pos = {k: ax.get_position() for k, ax in axes.items()}
    centre = {k: ((p.x0 + p.x1) / 2, (p.y0 + p.y1) / 2) for k, p in pos.items()}

    def where(k: str) -> str:
        others = [o for o in pos if o != k]
        side = (
            "left"
            if all(pos[k].x1 <= pos[o].x0 for o in others if pos[o].x0 >= pos[k].x1)
            and any(pos[o].x0 >= pos[k].x1 for o in others)
            else "right"
            if any(pos[o].x1 <= pos[k].x0 for o in others)
            else ""
        )
        column = [o for o in others if abs(centre[o][0] - centre[k][0]) < 0.05]
        if not column:
            return f"{side}, full height" if side else "alone"
        vertical = "top" if all(centre[k][1] > centre[o][1] for o in column) else "bottom"
        return f"{vertical} {side}".strip()

    def style(name: str) -> str:
        return _LINESTYLE_WORD.get(art[name].get_linestyle(), "solid")

    has_hz = any(getattr(child, "get_xlabel", lambda: "")().endswith("(Hz)") for child in axes["m"].child_axes)
    return {
        "x": where("x"),
        "v": where("v"),
        "m": where("m"),
        "envelope": style("x_env_hi"),
        "settle": style("x_settle"),
        "natural": style("omega_n"),
        "rk45": style("x_rk45"),
        "hz": "Hz above" if has_hz else "",
    }


def _chunk(tag: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))


def png(canvas: FigureCanvasAgg, level: int = PNG_LEVEL) -> bytes:
    """The canvas' current Agg buffer as PNG bytes (RGBA, 8 bit).

    Written directly with zlib at ``level`` and PNG filter 0 (none) on every
    row: half the time of Pillow's encoder at the same zlib level, which
    tries every row filter (about 9 ms against 18 ms for 1000 x 540 pixels
    here), for files about the same size on plots.
    """
    rgba = np.asarray(canvas.buffer_rgba())
    h, w, _ = rgba.shape
    raw = np.empty((h, 4 * w + 1), dtype=np.uint8)
    raw[:, 0] = 0  # filter type of each scanline: none
    raw[:, 1:] = rgba.reshape(h, 4 * w)
    header = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)  # 8-bit RGBA, no interlace
    return b"".join(
        (
            b"\x89PNG\r\n\x1a\n",
            _chunk(b"IHDR", header),
            _chunk(b"IDAT", zlib.compress(raw, level)),
            _chunk(b"IEND", b""),
        )
    )


def png_small(canvas: FigureCanvasAgg) -> bytes:
    """The canvas' current Agg buffer as a compact PNG (Pillow, zlib level 9), for storing."""
    with io.BytesIO() as buf:
        Image.fromarray(np.asarray(canvas.buffer_rgba())).save(buf, format="png", compress_level=9)
        return buf.getvalue()
