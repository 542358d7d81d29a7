"""The schematics' drawing kit: the colour language, the panels, and the parts every model is drawn from
(springs as zigzags, dashpots as pistons in cylinders, hatched ground and walls, blocks on rollers) with the force,
load and coordinate arrows, and the panel words a caption opens its sentences with."""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Circle, FancyArrowPatch, Rectangle
from matplotlib.path import Path

from ..captions import panel_words
from ..style import OKABE_ITO

__all__ = [
    "BODY",
    "COORDINATE",
    "FORCE",
    "HATCH",
    "INK",
    "LW",
    "TEXT",
    "arc_arrow",
    "arrow",
    "blank",
    "coordinate",
    "dashpot",
    "drive",
    "force",
    "ground",
    "load",
    "mass",
    "rollers",
    "sentence_panels",
    "spring",
    "wall",
    "weight_and_support",
]

#: Colour of every force and torque arrow.
FORCE = OKABE_ITO["vermillion"]
#: Colour of every coordinate (displacement, angle) and prescribed motion.
COORDINATE = OKABE_ITO["blue"]
#: Structure: lines, springs, dashpots, outlines.
INK = OKABE_ITO["black"]
#: Hatching of fixed ground and walls.
HATCH = OKABE_ITO["grey"]
#: Fill of a rigid body (mass, floor, wheel).
BODY = "#ededed"

LW = 1.3  # line width of the structure, points
TEXT = 9.5  # label size, points (the book's figure text)


def blank(ax, label: str, title: str, *, xlim: tuple[float, float], ylim: tuple[float, float]) -> None:
    """A drawing panel: no ticks, spines or grid, equal scales, the given box; still a panel for the caption."""
    ax.set_label(label)
    ax.set_title(title, fontsize=10)
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_visible(False)
    ax.grid(False)
    ax.patch.set_visible(False)
    ax.set_xmargin(0.0)
    ax.set_ymargin(0.0)
    ax.update_datalim([(xlim[0], ylim[0]), (xlim[1], ylim[1])])
    ax.autoscale(enable=True, tight=True)
    ax.set_aspect("equal", adjustable="datalim")  # the box is widened or heightened to fill the panel


def _unit(a, b) -> tuple[np.ndarray, np.ndarray, float]:
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    length = float(np.hypot(*d))
    u = d / length
    return u, np.array([-u[1], u[0]]), length


def spring(ax, a, b, *, coils: int = 5, width: float = 0.26, lead: float = 0.18, color: str = INK) -> None:
    """A zigzag spring from point ``a`` to point ``b`` with straight leads at both ends."""
    u, n, length = _unit(a, b)
    lead = min(lead, 0.2 * length)
    zig = length - 2.0 * lead
    s = [0.0, lead]
    off = [0.0, 0.0]
    for i in range(2 * coils):
        s.append(lead + (i + 0.5) * zig / (2 * coils))
        off.append(0.5 * width * (1 if i % 2 == 0 else -1))
    s += [length - lead, length]
    off += [0.0, 0.0]
    pts = np.asarray(a, float) + np.outer(s, u) + np.outer(off, n)
    ax.plot(pts[:, 0], pts[:, 1], color=color, lw=LW, solid_joinstyle="miter", solid_capstyle="butt")


def dashpot(ax, a, b, *, width: float = 0.3, color: str = INK, variable: bool = False) -> None:
    """A dashpot from ``a`` (the cylinder's end) to ``b`` (the piston rod's end); ``variable`` adds the
    through-arrow of an adjustable damper."""
    a = np.asarray(a, float)
    u, n, length = _unit(a, b)
    s0, s1 = 0.25 * length, 0.72 * length  # cylinder bottom, cylinder mouth
    sp = 0.55 * length  # piston
    h = 0.5 * width
    at = lambda s, o: a + s * u + o * n  # noqa: E731

    def seg(p, q, **kw):
        ax.plot([p[0], q[0]], [p[1], q[1]], color=color, lw=LW, solid_capstyle="butt", **kw)

    seg(at(0, 0), at(s0, 0))
    seg(at(s0, -h), at(s0, h))
    seg(at(s0, -h), at(s1, -h))
    seg(at(s0, h), at(s1, h))
    ax.plot(*zip(at(sp, -0.72 * h), at(sp, 0.72 * h), strict=True), color=color, lw=2.2 * LW, solid_capstyle="butt")
    seg(at(sp, 0), at(length, 0))
    if variable:
        tail, head = at(0.18 * length, -1.6 * h), at(0.84 * length, 1.6 * h)
        ax.add_patch(
            FancyArrowPatch(tail, head, arrowstyle="-|>", mutation_scale=8, lw=0.9, color=color, shrinkA=0, shrinkB=0)
        )


def ground(ax, x0: float, x1: float, *, y: float, depth: float = 0.22, below: bool = True) -> None:
    """Fixed ground: a line from ``x0`` to ``x1`` at height ``y``, hatched on the side away from the model."""
    y_box = y - depth if below else y
    ax.add_patch(Rectangle((x0, y_box), x1 - x0, depth, facecolor="none", edgecolor=HATCH, lw=0, hatch="////"))
    ax.plot([x0, x1], [y, y], color=INK, lw=1.6 * LW, solid_capstyle="butt")


def wall(ax, x: float, y0: float, *, y1: float, depth: float = 0.22, left: bool = True) -> None:
    """A fixed wall at ``x`` from ``y0`` to ``y1``, hatched on the side away from the model."""
    x_box = x - depth if left else x
    ax.add_patch(Rectangle((x_box, y0), depth, y1 - y0, facecolor="none", edgecolor=HATCH, lw=0, hatch="////"))
    ax.plot([x, x], [y0, y1], color=INK, lw=1.6 * LW, solid_capstyle="butt")


def mass(ax, x0: float, y0: float, *, w: float, h: float, label: str | None = None, fill: str = BODY) -> None:
    """A rigid block with its lower left corner at (``x0``, ``y0``), labelled in its middle."""
    ax.add_patch(Rectangle((x0, y0), w, h, facecolor=fill, edgecolor=INK, lw=LW, zorder=2))
    if label:
        ax.text(x0 + 0.5 * w, y0 + 0.5 * h, label, ha="center", va="center", fontsize=10, zorder=3)


def rollers(ax, x0: float, w: float, *, y: float, r: float = 0.11) -> None:
    """Two frictionless rollers under a block of width ``w`` whose bottom is at ``y + 2 r``."""
    for xc in (x0 + 0.25 * w, x0 + 0.75 * w):
        ax.add_patch(Circle((xc, y + r), r, facecolor="white", edgecolor=INK, lw=LW, zorder=2))


def arrow(ax, tail, head, *, color: str, gid: str, lw: float = 1.5, scale: float = 11.0) -> FancyArrowPatch:
    arrow = FancyArrowPatch(
        tail, head, arrowstyle="-|>", mutation_scale=scale, lw=lw, color=color, shrinkA=0, shrinkB=0, zorder=4
    )
    arrow.set_gid(gid)
    ax.add_patch(arrow)
    return arrow


def force(ax, tail, head, *, label: str, at, ha: str = "center", va: str = "center") -> None:
    """A force arrow (vermillion) from ``tail`` to ``head`` with its label at ``at``."""
    arrow(ax, tail, head, color=FORCE, gid="force:" + label)
    ax.text(*at, label, color=FORCE, ha=ha, va=va, fontsize=TEXT, zorder=5)


def load(ax, tail, head, *, label: str, at, ha: str = "center", va: str = "center") -> None:
    """An applied load drawn in a schematic (vermillion, not counted as a free-body force)."""
    arrow(ax, tail, head, color=FORCE, gid="load:" + label)
    ax.text(*at, label, color=FORCE, ha=ha, va=va, fontsize=TEXT, zorder=5)


def drive(ax, tail, length: float, *, label: str, gap: float, free_body: bool = False) -> None:
    """The horizontal drive of a block, pointing away from its wall, labelled above the arrow ``gap`` past its tail.

    A :func:`load` in a schematic; with ``free_body``, a :func:`force` on the block in its free-body diagram.
    """
    x, y = tail
    draw = force if free_body else load
    draw(ax, (x, y), (x + length, y), label=label, at=(x + gap, y + 0.12), ha="left", va="bottom")


def weight_and_support(ax, x0: float, y0: float, *, w: float, inset: float, drop: float) -> None:
    """The weight ``mg`` and the rollers' normal force ``N`` on a block of width ``w`` whose bottom left is at
    (``x0``, ``y0``): two vertical force arrows of length ``drop``, ``inset`` in from its sides."""
    left, right, y = x0 + inset, x0 + w - inset, y0 - drop
    force(ax, (left, y0), (left, y), label="$mg$", at=(left - 0.08, y + 0.3), ha="right")
    force(ax, (right, y), (right, y0), label="$N$", at=(right + 0.08, y + 0.3), ha="left")


def coordinate(ax, origin, length: float, *, label: str, vertical: bool = False, tick: float = 0.18, side: str = "end"):
    """A coordinate: a thin reference tick at ``origin`` and a blue arrow of ``length`` in its positive direction."""
    ox, oy = origin
    if vertical:
        ax.plot([ox - tick, ox + tick], [oy, oy], color=COORDINATE, lw=1.0, solid_capstyle="butt")
        head = (ox, oy + length)
        at, ha, va = (ox + 0.08, oy + length), "left", "center"
    else:
        ax.plot([ox, ox], [oy - tick, oy + tick], color=COORDINATE, lw=1.0, solid_capstyle="butt")
        head = (ox + length, oy)
        at, ha, va = (ox + length + 0.08, oy), "left", "center"
    if side == "start" and not vertical:
        at, ha = (ox - 0.08, oy), "right"
    arrow(ax, origin, head, color=COORDINATE, gid="coordinate:" + label, lw=1.1, scale=9.0)
    ax.text(*at, label, color=COORDINATE, ha=ha, va=va, fontsize=TEXT, zorder=5)


def _arc_path(centre, radius: float, start_deg: float, end_deg: float, n: int = 40) -> Path:
    t = np.radians(np.linspace(start_deg, end_deg, n))
    return Path(np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)]))


def arc_arrow(ax, centre, radius, *, start_deg, end_deg, color: str, gid: str, lw: float = 1.5, scale: float = 11.0):
    """A curved arrow along a circle from ``start_deg`` to ``end_deg`` (head at the end)."""
    arrow = FancyArrowPatch(
        path=_arc_path(centre, radius, start_deg, end_deg),
        arrowstyle="-|>",
        mutation_scale=scale,
        lw=lw,
        color=color,
        shrinkA=0,
        shrinkB=0,
        zorder=4,
    )
    arrow.set_gid(gid)
    ax.add_patch(arrow)
    return arrow


def sentence_panels(fig, parts: list[str]) -> str:
    """``"Left: ... Right: ..."`` with the position words taken from the figure's layout."""
    words = panel_words(fig)
    return " ".join(f"{w[0].upper()}{w[1:]}: {p}" for w, p in zip(words, parts, strict=True))
