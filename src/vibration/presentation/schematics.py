"""Schematics of the book's models, each with the free-body diagram of its mass(es) beside it.

One function per model, each returning a :class:`~vibration.presentation.captions.Captioned`
figure at the column width: the schematic on the left, the free-body diagram on the right (and,
where the model needs it, a third or fourth panel). Everything is drawn with matplotlib
patches and lines: springs as zigzags, dashpots as pistons in cylinders, fixed ground hatched.
One colour language throughout: structure black, forces and torques vermillion
(:data:`FORCE`), coordinates blue (:data:`COORDINATE`); a device that is a case of the book's
visual language (the skyhook, the semi-active damper, the Duffing springs) takes the colour of
its case from :func:`~vibration.presentation.style.case_style`.

Free-body diagrams are in Newton's form: the arrows are the forces (torques) that act on the
body, drawn in the directions they act when the coordinates and their rates are positive; the
mass times the acceleration is their sum, not a force, and is not drawn. Each force arrow
carries the label it has in the caption (its ``gid`` is ``"force:" + label``), so a test can
count the arrows against the caption.

Functions: :func:`single_mass` (the paper's model, chapters 1-6), :func:`base_excitation`
(chapter 6's isolation, chapter 7's suspension), :func:`two_mass_absorber` (chapter 8),
:func:`shear_building` (chapter 8), :func:`skyhook` (chapter 7), :func:`duffing_spring`
(chapter 9) and :func:`torsional_oscillator` (chapter 12).

Examples
--------
>>> cap = single_mass()
>>> cap.name, [ax.get_label() for ax in cap.fig.axes]
('fig-schematic-single-mass', ['schematic', 'free-body diagram'])
>>> from vibration.presentation.style import WIDTH_IN
>>> float(cap.fig.get_size_inches()[0]) == WIDTH_IN
True
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Rectangle
from matplotlib.path import Path

from vibration.physics.model import check_int

from .captions import Captioned, panel_words
from .style import OKABE_ITO, case_style, figure, place_legend

__all__ = [
    "COORDINATE",
    "FORCE",
    "base_excitation",
    "duffing_spring",
    "shear_building",
    "single_mass",
    "skyhook",
    "torsional_oscillator",
    "two_mass_absorber",
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

_LW = 1.3  # line width of the structure, points
_TEXT = 9.5  # label size, points (the book's figure text)

# ------------------------------------------------------------------------------------------ drawing kit


def _blank(ax, label: str, title: str, xlim: tuple[float, float], ylim: tuple[float, float]) -> None:
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


def _spring(ax, a, b, coils: int = 5, width: float = 0.26, lead: float = 0.18, color: str = INK) -> None:
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
    ax.plot(pts[:, 0], pts[:, 1], color=color, lw=_LW, solid_joinstyle="miter", solid_capstyle="butt")


def _dashpot(ax, a, b, width: float = 0.3, color: str = INK, variable: bool = False) -> None:
    """A dashpot from ``a`` (the cylinder's end) to ``b`` (the piston rod's end); ``variable`` adds the
    through-arrow of an adjustable damper."""
    a = np.asarray(a, float)
    u, n, length = _unit(a, b)
    s0, s1 = 0.25 * length, 0.72 * length  # cylinder bottom, cylinder mouth
    sp = 0.55 * length  # piston
    h = 0.5 * width
    at = lambda s, o: a + s * u + o * n  # noqa: E731

    def seg(p, q, **kw):
        ax.plot([p[0], q[0]], [p[1], q[1]], color=color, lw=_LW, solid_capstyle="butt", **kw)

    seg(at(0, 0), at(s0, 0))
    seg(at(s0, -h), at(s0, h))
    seg(at(s0, -h), at(s1, -h))
    seg(at(s0, h), at(s1, h))
    ax.plot(*zip(at(sp, -0.72 * h), at(sp, 0.72 * h), strict=True), color=color, lw=2.2 * _LW, solid_capstyle="butt")
    seg(at(sp, 0), at(length, 0))
    if variable:
        tail, head = at(0.18 * length, -1.6 * h), at(0.84 * length, 1.6 * h)
        ax.add_patch(
            FancyArrowPatch(tail, head, arrowstyle="-|>", mutation_scale=8, lw=0.9, color=color, shrinkA=0, shrinkB=0)
        )


def _ground(ax, x0: float, x1: float, y: float, depth: float = 0.22, below: bool = True) -> None:
    """Fixed ground: a line from ``x0`` to ``x1`` at height ``y``, hatched on the side away from the model."""
    y_box = y - depth if below else y
    ax.add_patch(Rectangle((x0, y_box), x1 - x0, depth, facecolor="none", edgecolor=HATCH, lw=0, hatch="////"))
    ax.plot([x0, x1], [y, y], color=INK, lw=1.6 * _LW, solid_capstyle="butt")


def _wall(ax, x: float, y0: float, y1: float, depth: float = 0.22, left: bool = True) -> None:
    """A fixed wall at ``x`` from ``y0`` to ``y1``, hatched on the side away from the model."""
    x_box = x - depth if left else x
    ax.add_patch(Rectangle((x_box, y0), depth, y1 - y0, facecolor="none", edgecolor=HATCH, lw=0, hatch="////"))
    ax.plot([x, x], [y0, y1], color=INK, lw=1.6 * _LW, solid_capstyle="butt")


def _mass(ax, x0: float, y0: float, w: float, h: float, label: str | None = None, fill: str = BODY) -> None:
    """A rigid block with its lower left corner at (``x0``, ``y0``), labelled in its middle."""
    ax.add_patch(Rectangle((x0, y0), w, h, facecolor=fill, edgecolor=INK, lw=_LW, zorder=2))
    if label:
        ax.text(x0 + 0.5 * w, y0 + 0.5 * h, label, ha="center", va="center", fontsize=10, zorder=3)


def _rollers(ax, x0: float, w: float, y: float, r: float = 0.11) -> None:
    """Two frictionless rollers under a block of width ``w`` whose bottom is at ``y + 2 r``."""
    for xc in (x0 + 0.25 * w, x0 + 0.75 * w):
        ax.add_patch(Circle((xc, y + r), r, facecolor="white", edgecolor=INK, lw=_LW, zorder=2))


def _arrow(ax, tail, head, color: str, gid: str, lw: float = 1.5, scale: float = 11.0) -> FancyArrowPatch:
    arrow = FancyArrowPatch(
        tail, head, arrowstyle="-|>", mutation_scale=scale, lw=lw, color=color, shrinkA=0, shrinkB=0, zorder=4
    )
    arrow.set_gid(gid)
    ax.add_patch(arrow)
    return arrow


def _force(ax, tail, head, label: str, at, ha: str = "center", va: str = "center") -> None:
    """A force arrow (vermillion) from ``tail`` to ``head`` with its label at ``at``."""
    _arrow(ax, tail, head, FORCE, "force:" + label)
    ax.text(*at, label, color=FORCE, ha=ha, va=va, fontsize=_TEXT, zorder=5)


def _load(ax, tail, head, label: str, at, ha: str = "center", va: str = "center") -> None:
    """An applied load drawn in a schematic (vermillion, not counted as a free-body force)."""
    _arrow(ax, tail, head, FORCE, "load:" + label)
    ax.text(*at, label, color=FORCE, ha=ha, va=va, fontsize=_TEXT, zorder=5)


def _coordinate(ax, origin, length: float, label: str, vertical: bool = False, tick: float = 0.18, side: str = "end"):
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
    _arrow(ax, origin, head, COORDINATE, "coordinate:" + label, lw=1.1, scale=9.0)
    ax.text(*at, label, color=COORDINATE, ha=ha, va=va, fontsize=_TEXT, zorder=5)


def _arc_path(centre, radius: float, start_deg: float, end_deg: float, n: int = 40) -> Path:
    t = np.radians(np.linspace(start_deg, end_deg, n))
    return Path(np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)]))


def _arc_arrow(ax, centre, radius, start_deg, end_deg, color: str, gid: str, lw: float = 1.5, scale: float = 11.0):
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


def _sentence_panels(fig, parts: list[str]) -> str:
    """``"Left: ... Right: ..."`` with the position words taken from the figure's layout."""
    words = panel_words(fig)
    return " ".join(f"{w[0].upper()}{w[1:]}: {p}" for w, p in zip(words, parts, strict=True))


# ------------------------------------------------------------------------------------------ the paper's model

_NEWTON = (
    "Free-body diagrams in Newton's form: the arrows are the forces on the body, drawn as they act when the "
    "coordinates and their rates are positive; the mass times the acceleration is their sum and is not drawn."
)
_NEWTON_TORQUES = (
    "Free-body diagram in Newton's form: the arrows are the torques on the wheel, drawn as they act when the angle "
    "and its rate are positive; the moment of inertia times the angular acceleration is their sum and is not drawn."
)


def single_mass() -> Captioned:
    """The paper's model: wall, spring k, dashpot c, mass m, force F0 sin(omega t), coordinate x."""
    fig, (left, right) = figure(1, 2, height=2.5)
    _blank(left, "schematic", "schematic", (-0.35, 6.0), (-0.35, 2.6))
    _wall(left, 0.3, 0.0, 2.1)
    _ground(left, 0.3, 5.7, 0.0)
    x0, y0, w, h = 2.8, 0.22, 1.2, 1.6
    _rollers(left, x0, w, 0.0)
    _mass(left, x0, y0, w, h, "$m$")
    _spring(left, (0.3, 1.42), (x0, 1.42))
    left.text(1.55, 1.72, "$k$", ha="center", va="bottom", fontsize=_TEXT)
    _dashpot(left, (0.3, 0.62), (x0, 0.62))
    left.text(1.55, 0.3, "$c$", ha="center", va="top", fontsize=_TEXT)
    _load(left, (x0 + w, 1.02), (x0 + w + 1.0, 1.02), r"$F_0\sin\omega t$", (x0 + w + 0.08, 1.14), "left", "bottom")
    _coordinate(left, (x0, 2.1), 0.8, "$x$")

    _blank(right, "free-body diagram", "free-body diagram of the mass", (-0.45, 5.9), (-1.1, 2.6))
    x0, y0 = 2.0, 0.2
    _mass(right, x0, y0, w, h, "$m$")
    _force(right, (x0, 1.3), (x0 - 1.1, 1.3), "$kx$", (x0 - 0.55, 1.42), va="bottom")
    _force(right, (x0, 0.55), (x0 - 1.1, 0.55), r"$c\dot x$", (x0 - 0.55, 0.43), va="top")
    _force(right, (x0 + w, 1.0), (x0 + w + 1.0, 1.0), r"$F_0\sin\omega t$", (x0 + w + 0.08, 1.12), "left", "bottom")
    _force(right, (x0 + 0.35, y0), (x0 + 0.35, y0 - 0.9), "$mg$", (x0 + 0.27, y0 - 0.6), "right")
    _force(right, (x0 + w - 0.35, y0 - 0.9), (x0 + w - 0.35, y0), "$N$", (x0 + w - 0.27, y0 - 0.6), "left")
    _coordinate(right, (x0, 2.1), 0.8, "$x$")

    caption = (
        r"The paper's model, $m\ddot x + c\dot x + kx = F_0\sin\omega t$. "
        + _sentence_panels(
            fig,
            [
                "a block of mass $m$ (kg) on frictionless rollers, tied to a fixed wall (hatched) by a spring of "
                "stiffness $k$ (N/m) and a viscous dashpot of damping coefficient $c$ (N s/m), and driven by the force "
                r"$F_0\sin\omega t$ (amplitude $F_0$ in N, angular frequency $\omega$ in rad/s, time $t$ in s); its "
                "displacement $x$ (m, blue) is measured from the position where the spring is relaxed.",
                r"the free-body diagram of the block: the spring force $kx$ and the damper force $c\dot x$ (N) against "
                r"the motion, the drive $F_0\sin\omega t$, and the weight $mg$ and the rollers' normal force $N$ "
                "(N, $g$ the acceleration of gravity in m/s²), which balance each other.",
            ],
        )
        + " Forces are vermillion. "
        + _NEWTON
    )
    alt = (
        "A block on rollers tied to a wall by a spring and a dashpot and pushed by a sinusoidal force, and beside it "
        "the block alone with the spring and damper forces pointing back towards the wall and the drive pointing away."
    )
    return Captioned(fig, caption, "fig-schematic-single-mass", alt)


# ------------------------------------------------------------------------------------------ base excitation


def base_excitation() -> Captioned:
    """A mass on a spring and a dashpot whose base moves as y(t): chapter 6's isolation, chapter 7's suspension."""
    fig, (left, right) = figure(1, 2, height=3.0)
    _blank(left, "schematic", "schematic", (-2.4, 2.4), (-0.2, 3.3))
    bw, bh = 2.6, 0.35  # base plate
    _mass(left, -0.5 * bw, 0.0, bw, bh)
    left.text(-0.5 * bw - 0.1, 0.5 * bh, "base", ha="right", va="center", fontsize=_TEXT)
    _coordinate(left, (0.5 * bw + 0.3, 0.5 * bh), 0.6, "$y(t)$", vertical=True)
    mw, mh, my = 1.7, 0.9, 1.85
    _spring(left, (-0.45, bh), (-0.45, my))
    left.text(-0.75, 0.5 * (bh + my), "$k$", ha="right", va="center", fontsize=_TEXT)
    _dashpot(left, (0.45, bh), (0.45, my))
    left.text(0.75, 0.5 * (bh + my), "$c$", ha="left", va="center", fontsize=_TEXT)
    _mass(left, -0.5 * mw, my, mw, mh, "$m$")
    _coordinate(left, (0.5 * mw + 0.3, my + 0.5 * mh), 0.6, "$x$", vertical=True)

    _blank(right, "free-body diagram", "free-body diagram of the mass", (-2.4, 2.4), (-0.2, 3.3))
    my = 1.55
    _mass(right, -0.5 * mw, my, mw, mh, "$m$")
    _force(right, (-0.45, my), (-0.45, my - 1.0), "$k(x - y)$", (-0.55, my - 0.5), "right")
    _force(right, (0.45, my), (0.45, my - 1.0), r"$c(\dot x - \dot y)$", (0.55, my - 0.5), "left")
    _coordinate(right, (0.5 * mw + 0.3, my + 0.5 * mh), 0.6, "$x$", vertical=True)

    caption = (
        r"Base excitation: $m\ddot x + c\dot x + kx = c\dot y + ky$, or, in the relative displacement $z = x - y$, "
        r"$m\ddot z + c\dot z + kz = -m\ddot y$. "
        + _sentence_panels(
            fig,
            [
                "a mass $m$ (kg) on a spring of stiffness $k$ (N/m) and a dashpot of damping coefficient $c$ "
                "(N s/m) whose base moves as $y(t)$ (m, in chapter 6 $Y\\sin\\omega t$); the displacement $x$ (m) of "
                "the mass and $y$ are absolute, measured from the static equilibrium (blue).",
                "the free-body diagram of the mass: the spring force $k(x - y)$ and the damper force "
                r"$c(\dot x - \dot y)$ (N), which depend on the motion relative to the base only; the weight and the "
                "static spring force balance at the equilibrium and are left out.",
            ],
        )
        + " Forces are vermillion. "
        + _NEWTON
    )
    alt = (
        "A mass on a spring and a dashpot standing on a base that moves up and down, and beside it the mass alone "
        "with the spring and damper forces, both set by the stretch relative to the base, pointing down."
    )
    return Captioned(fig, caption, "fig-schematic-base-excitation", alt)


# ------------------------------------------------------------------------------------------ tuned mass damper


def two_mass_absorber() -> Captioned:
    """The primary (m_p, k_p, c_p) with the absorber (m_a, k_a, c_a) on top and the force on the primary."""
    fig, (left, right) = figure(1, 2, height=3.6)
    _blank(left, "schematic", "schematic", (-2.7, 2.2), (-0.3, 4.2))
    _ground(left, -1.4, 1.4, 0.0)
    pw, ph, py = 1.8, 0.8, 1.3  # primary
    aw, ah, ay = 1.2, 0.6, 3.05  # absorber
    sw = 2.3  # the primary's width in the schematic, with room under it for the drive
    _spring(left, (-0.3, 0.0), (-0.3, py))
    left.text(-0.56, 0.5 * py, "$k_p$", ha="right", va="center", fontsize=_TEXT)
    _dashpot(left, (0.5, 0.0), (0.5, py))
    left.text(0.78, 0.5 * py, "$c_p$", ha="left", va="center", fontsize=_TEXT)
    _mass(left, -0.5 * sw, py, sw, ph, "$m_p$")
    _spring(left, (-0.32, py + ph), (-0.32, ay), width=0.22, coils=4)
    left.text(-0.56, 0.5 * (py + ph + ay), "$k_a$", ha="right", va="center", fontsize=_TEXT)
    _dashpot(left, (0.32, py + ph), (0.32, ay), width=0.26)
    left.text(0.56, 0.5 * (py + ph + ay), "$c_a$", ha="left", va="center", fontsize=_TEXT)
    _mass(left, -0.5 * aw, ay, aw, ah, "$m_a$")
    _load(left, (-1.0, py - 0.75), (-1.0, py), r"$F_0\sin\omega t$", (-1.1, py - 0.45), "right")
    _coordinate(left, (0.5 * sw + 0.25, py + 0.5 * ph), 0.55, "$x_p$", vertical=True)
    _coordinate(left, (0.5 * aw + 0.3, ay + 0.5 * ah), 0.55, "$x_a$", vertical=True)

    _blank(right, "free-body diagram", "free-body diagrams of the masses", (-2.4, 2.4), (-0.3, 4.2))
    py, ay = 0.95, 3.2
    _mass(right, -0.5 * aw, ay, aw, ah, "$m_a$")
    d = 0.3
    _force(right, (-d, ay), (-d, ay - 0.7), "$k_a(x_a - x_p)$", (-d - 0.1, ay - 0.35), "right")
    _force(right, (d, ay), (d, ay - 0.7), r"$c_a(\dot x_a - \dot x_p)$", (d + 0.1, ay - 0.35), "left")
    _mass(right, -0.5 * pw, py, pw, ph, "$m_p$")
    top = py + ph
    _force(right, (-d, top), (-d, top + 0.7), "$k_a(x_a - x_p)$", (-d - 0.1, top + 0.35), "right")
    _force(right, (d, top), (d, top + 0.7), r"$c_a(\dot x_a - \dot x_p)$", (d + 0.1, top + 0.35), "left")
    _force(right, (-0.6, py), (-0.6, py - 0.75), "$k_px_p$", (-0.7, py - 0.4), "right")
    _force(right, (0.6, py), (0.6, py - 0.75), r"$c_p\dot x_p$", (0.7, py - 0.4), "left")
    _force(right, (0.0, py - 0.75), (0.0, py), r"$F_0\sin\omega t$", (0.0, py - 0.8), va="top")
    _coordinate(right, (0.5 * pw + 0.3, py), 0.5, "$x_p$", vertical=True)
    _coordinate(right, (0.5 * aw + 0.3, ay + 0.5 * ah), 0.5, "$x_a$", vertical=True)

    caption = (
        "The tuned mass damper of chapter 8. "
        + _sentence_panels(
            fig,
            [
                "the primary of mass $m_p$ (kg) on a spring $k_p$ (N/m) and a dashpot $c_p$ (N s/m) to the fixed "
                "ground (hatched), driven by the force $F_0\\sin\\omega t$ (N; $\\omega$ in rad/s, $t$ in s), "
                "carries the absorber of mass $m_a$ (kg; $m_a = \\mu m_p$) on its own spring $k_a$ (N/m) and dashpot "
                "$c_a$ (N s/m); $x_p$ and $x_a$ (m, blue) are the displacements from the static equilibrium.",
                "the free-body diagrams of the absorber (above) and the primary (below): the absorber's spring and "
                "dashpot pull the two masses together with the equal and opposite forces $k_a(x_a - x_p)$ and "
                r"$c_a(\dot x_a - \dot x_p)$ (N); on the primary also act $k_px_p$, $c_p\dot x_p$ and the drive "
                r"$F_0\sin\omega t$. The weights and the static spring forces balance and are left out.",
            ],
        )
        + " Forces are vermillion. "
        + _NEWTON
    )
    alt = (
        "A large mass on a spring and a dashpot carrying a small mass on its own spring and dashpot, and beside it "
        "the two masses apart with the equal and opposite spring and damper forces between them and the drive on "
        "the large mass."
    )
    return Captioned(fig, caption, "fig-schematic-absorber", alt)


# ------------------------------------------------------------------------------------------ shear building


def _column(ax, x0: float, y0: float, x1: float, y1: float) -> None:
    """A column bent in double curvature from its foot (``x0``, ``y0``) to its head (``x1``, ``y1``)."""
    s = np.linspace(0.0, 1.0, 40)
    ax.plot(x0 + (x1 - x0) * (3 * s**2 - 2 * s**3), y0 + (y1 - y0) * s, color=INK, lw=_LW)


def shear_building(n: int = 5) -> Captioned:
    """An ``n``-storey shear frame with a roof absorber under ground acceleration, and the free-body diagram of a
    floor (2 <= n <= 8)."""
    n = check_int("n", n, low=2, high=8)
    hs, half, t = 3.6 / n, 1.0, 0.14  # storey height, half the floor's width, floor thickness
    sway = 0.3 * np.sin(0.5 * np.pi * np.arange(n + 1) / n)  # drawn in the first mode's shape
    top = n * hs + 0.75
    fig, (left, right) = figure(1, 2, height=4.2)
    _blank(left, "schematic", "schematic", (-2.1, 2.4), (-0.75, top + 0.2))
    _ground(left, -1.6, 1.9, 0.0)
    for j in range(1, n + 1):
        y = j * hs
        for side in (-1, 1):
            _column(left, sway[j - 1] + side * 0.8 * half, y - hs + (t if j > 1 else 0.0), sway[j] + side * 0.8 * half,
                    y - t)  # fmt: skip
        _mass(left, sway[j] - half, y - t, 2 * half, t)
        left.text(sway[j] - half - 0.12, y - 0.5 * t, "$m$", ha="right", va="center", fontsize=_TEXT)
        left.text(sway[j - 1] - 0.8 * half - 0.12, y - 0.5 * hs, "$k$", ha="right", va="center", fontsize=_TEXT)
        _coordinate(left, (1.45, y - 0.5 * t), 0.4, f"$x_{j}$", tick=0.1)
    roof = n * hs
    xr = sway[n]
    post = xr - 0.85
    _wall(left, post, roof, roof + 0.62, depth=0.12)
    aw, ah = 0.5, 0.48
    ax0 = xr + 0.3
    _rollers(left, ax0, aw, roof, r=0.06)
    _mass(left, ax0, roof + 0.12, aw, ah)
    left.text(ax0 + 0.5 * aw, roof + 0.12 + ah + 0.04, "$m_a$", ha="center", va="bottom", fontsize=_TEXT)
    _spring(left, (post, roof + 0.48), (ax0, roof + 0.48), coils=4, width=0.14, lead=0.08)
    left.text(post - 0.22, roof + 0.48, "$k_a$", ha="right", va="center", fontsize=_TEXT)
    _dashpot(left, (post, roof + 0.24), (ax0, roof + 0.24), width=0.14)
    left.text(post - 0.22, roof + 0.24, "$c_a$", ha="right", va="center", fontsize=_TEXT)
    _coordinate(left, (1.45, roof + 0.36), 0.4, "$x_a$", tick=0.1)
    _coordinate(left, (-0.9, -0.5), 0.6, r"$\ddot u_g$", tick=0.1, side="start")

    _blank(right, "free-body diagram", "free-body diagram of floor $j$", (-2.1, 2.4), (-0.75, top + 0.2))
    yc, th = 0.5 * top - 0.2, 0.5  # floor j, drawn thicker
    for xcol in (-0.55 * half, 0.55 * half):
        for y0, y1 in ((yc + 0.5 * th, yc + 0.5 * th + 0.45), (yc - 0.5 * th - 0.45, yc - 0.5 * th)):
            right.plot([xcol, xcol], [y0, y1], color=INK, lw=_LW)
        for y in (yc + 0.5 * th + 0.45, yc - 0.5 * th - 0.45):  # the cuts
            right.plot([xcol - 0.12, xcol + 0.12], [y - 0.04, y + 0.04], color=INK, lw=0.8)
    _mass(right, -half, yc - 0.5 * th, 2 * half, th, "$m$")
    above, below = "$k(x_{j+1} - x_j)$", "$k(x_j - x_{j-1})$"
    _force(right, (half, yc + 0.12), (half + 1.1, yc + 0.12), above, (half + 0.55, yc + 0.3), va="bottom")
    _force(right, (-half, yc - 0.12), (-half - 1.1, yc - 0.12), below, (-half - 0.55, yc - 0.3), va="top")
    _coordinate(right, (-half, yc + 0.5 * th + 0.75), 0.6, "$x_j$", tick=0.1)

    xs = ", ".join(f"$x_{j}$" for j in range(1, n + 1))
    caption = (
        f"The {n}-storey shear building of chapter 8 with its roof absorber. "
        + _sentence_panels(
            fig,
            [
                f"rigid floors of mass $m$ (kg) on storeys of lateral stiffness $k$ (N/m, all columns of a storey "
                f"together), drawn swayed in the first mode's shape; the floors' displacements {xs} (m, blue) are "
                "relative to the ground, which moves with the acceleration $\\ddot u_g$ (m/s², $a_g\\sin\\omega t$ in "
                "chapter 8); the absorber of mass $m_a$ (kg) rolls on the roof on its spring $k_a$ (N/m) and dashpot "
                "$c_a$ (N s/m), with displacement $x_a$ (m).",
                "the free-body diagram of floor $j$, displacement $x_j$, cut through the columns above and below: "
                "the storey shears "
                "$k(x_{j+1} - x_j)$ from the storey above and $k(x_j - x_{j-1})$ from the storey below (N); "
                "with the absolute acceleration, $m(\\ddot x_j + \\ddot u_g) = k(x_{j+1} - x_j) - k(x_j - x_{j-1})$. "
                "On the roof the absorber's spring and dashpot forces take the place of the storey above; the "
                "building's damping is modal (one ratio $\\zeta_b$ for every mode) and is not drawn, nor are the "
                "vertical forces (weights and column forces), which balance.",
            ],
        )
        + " Forces are vermillion. "
        + _NEWTON
    )
    alt = (
        f"A {n}-storey frame of rigid floors on flexible columns, swaying to one side over a moving ground, with a "
        "small mass on a spring and a dashpot on its roof, and beside it one floor cut free, pulled one way by the "
        "storey above and the other way by the storey below."
    )
    return Captioned(fig, caption, "fig-schematic-building", alt)


# ------------------------------------------------------------------------------------------ skyhook


def _suspension(ax, device: str) -> None:
    """Chapter 7's suspension: base plate, spring k and damper c to the mass, and the device (``"sky"`` or
    ``"semi"``)."""
    bw, bh, my, mw, mh = 2.4, 0.3, 1.7, 1.8, 0.8
    _mass(ax, -0.5 * bw, 0.0, bw, bh)
    _coordinate(ax, (0.5 * bw + 0.25, 0.5 * bh), 0.55, "$y(t)$", vertical=True)
    xs = (-0.6, 0.0, 0.6) if device == "semi" else (-0.4, 0.4)
    _spring(ax, (xs[0], bh), (xs[0], my), width=0.24)
    ax.text(xs[0] - 0.25, 0.5 * (bh + my), "$k$", ha="right", va="center", fontsize=_TEXT)
    _dashpot(ax, (xs[1], bh), (xs[1], my), width=0.26)
    if device == "semi":
        ax.text(xs[1] - 0.17, 0.5 * (bh + my) + 0.12, "$c$", ha="right", va="bottom", fontsize=_TEXT)
        col = case_style("semi-active")["color"]
        _dashpot(ax, (xs[2], bh), (xs[2], my), width=0.26, color=col, variable=True)
        ax.text(xs[2] + 0.3, 0.5 * (bh + my), r"$c_\mathrm{sa}$", ha="left", va="center", fontsize=_TEXT, color=col)
    else:
        ax.text(xs[1] + 0.25, 0.5 * (bh + my), "$c$", ha="left", va="center", fontsize=_TEXT)
    _mass(ax, -0.5 * mw, my, mw, mh, "$m$")
    _coordinate(ax, (0.5 * mw + 0.25, my + 0.5 * mh), 0.55, "$x$", vertical=True)
    if device == "sky":
        col = case_style("skyhook")["color"]
        sky = my + mh + 1.0
        _ground(ax, -1.0, 1.0, sky, below=False, depth=0.18)
        _dashpot(ax, (0.0, sky), (0.0, my + mh), width=0.26, color=col)
        ax.text(0.25, my + mh + 0.5, r"$c_\mathrm{sky}$", ha="left", va="center", fontsize=_TEXT, color=col)
        ax.text(-1.1, sky + 0.09, "sky", ha="right", va="center", fontsize=_TEXT)


def skyhook() -> Captioned:
    """The ideal skyhook (a damper to an inertial reference) beside the realisable semi-active damper between body and
    base, the body's free-body diagram and the forces a semi-active damper can produce."""
    fig, axes = figure(2, 2, height=5.6)
    (sky_ax, semi_ax), (fbd, fmap) = axes
    box = ((-2.0, 2.2), (-0.15, 3.75))
    _blank(sky_ax, "schematic", "ideal skyhook", *box)
    _suspension(sky_ax, "sky")
    _blank(semi_ax, "schematic", "semi-active damper", *box)
    _suspension(semi_ax, "semi")

    _blank(fbd, "free-body diagram", "free-body diagram of the mass", (-2.0, 2.2), (-0.1, 3.3))
    mw, mh, my = 1.8, 0.8, 1.25
    _mass(fbd, -0.5 * mw, my, mw, mh, "$m$")
    _force(fbd, (-0.45, my), (-0.45, my - 0.9), "$k(x - y)$", (-0.55, my - 0.45), "right")
    _force(fbd, (0.45, my), (0.45, my - 0.9), r"$c(\dot x - \dot y)$", (0.55, my - 0.45), "left")
    _force(fbd, (0.0, my + mh), (0.0, my + mh + 0.8), "$f$", (0.12, my + mh + 0.45), "left")
    _coordinate(fbd, (0.5 * mw + 0.25, my + 0.5 * mh), 0.55, "$x$", vertical=True)

    fmap.set_label("force map")
    fmap.set_title("forces a semi-active damper can produce", fontsize=10)
    v = np.linspace(-1.0, 1.0, 3)
    c_lo, c_hi = 0.3, 1.2  # drawn slopes (the figure has no scale), not the chapter's values
    sa = case_style("semi-active")
    grey = {"color": OKABE_ITO["grey"], "alpha": 0.15, "lw": 0}
    fmap.fill_between([-1.0, 0.0], [0.0, 0.0], [1.0, 1.0], **grey)
    fmap.fill_between([0.0, 1.0], [-1.0, -1.0], [0.0, 0.0], **grey)
    fmap.fill_between(v, -c_lo * v, np.clip(-c_hi * v, -1.0, 1.0), color=sa["color"], alpha=0.3, lw=0)
    for c in (c_lo, c_hi):
        fmap.plot(v, np.clip(-c * v, -1.0, 1.0), color=sa["color"], ls=sa["linestyle"], lw=1.3)
    fmap.text(-0.04, 0.95, "dissipative", ha="right", va="top", fontsize=_TEXT)
    fmap.text(0.04, -0.95, "dissipative", ha="left", va="bottom", fontsize=_TEXT)
    fmap.text(0.5, 0.45, "needs power", ha="center", va="center", fontsize=_TEXT)
    fmap.text(-0.5, -0.45, "needs power", ha="center", va="center", fontsize=_TEXT)
    fmap.text(0.98, 0.04, r"$v_\mathrm{rel}$", ha="right", va="bottom", fontsize=_TEXT)
    fmap.text(0.04, 0.98, "$f$", ha="left", va="top", fontsize=_TEXT)
    fmap.set_xlim(-1.0, 1.0)
    fmap.set_ylim(-1.0, 1.0)
    fmap.set_xticks([])
    fmap.set_yticks([])
    fmap.grid(False)
    for side in ("left", "bottom"):
        fmap.spines[side].set_position("zero")

    words = dict(zip(("sky", "semi", "fbd", "map"), panel_words(fig), strict=True))
    caption = (
        "Chapter 7's suspension, $m\\ddot x + c(\\dot x - \\dot y) + k(x - y) = f$, with two devices. "
        f"{words['sky'].capitalize()}: the ideal skyhook, a damper $c_\\mathrm{{sky}}$ (N s/m, green) from the mass "
        "$m$ (kg) to an inertial reference (the sky, hatched), beside the passive spring $k$ (N/m) and damper $c$ "
        "(N s/m) to the base, which moves as $y(t)$ (m); $x$ (m) is the displacement of the mass, both measured from "
        "the static equilibrium (blue). "
        f"{words['semi'].capitalize()}: the realisable semi-active damper, whose coefficient $c_\\mathrm{{sa}}$ "
        "(N s/m, purple, the arrow marking it adjustable) is set between $c_\\mathrm{min}$ and $c_\\mathrm{max}$ and "
        "acts between the body and the base. "
        f"{words['fbd'].capitalize()}: the free-body diagram of the mass: the spring force $k(x - y)$ and the damper "
        "force $c(\\dot x - \\dot y)$ (N), and the device force $f$ (N), drawn positive: "
        "$f = -c_\\mathrm{sky}\\dot x$ for the skyhook, $f = -c_\\mathrm{sa}(\\dot x - \\dot y)$ for the semi-active "
        "damper; the weight and the static spring force balance and are left out. "
        f"{words['map'].capitalize()}: the device force $f$ against the relative velocity "
        "$v_\\mathrm{rel} = \\dot x - \\dot y$ (m/s; a sketch without scale): in the grey quadrants "
        "$f\\,v_\\mathrm{rel} < 0$ and the device dissipates; a semi-active damper can only produce forces in the "
        "purple sector between the dashed lines $f = -c_\\mathrm{min}v_\\mathrm{rel}$ (the shallower) and "
        "$f = -c_\\mathrm{max}v_\\mathrm{rel}$ (the steeper); the skyhook force, which "
        "follows $\\dot x$ and not $v_\\mathrm{rel}$, also falls in the quadrants that need power, where only an "
        "actuator can produce it. Forces are vermillion. " + _NEWTON
    )
    alt = (
        "A mass on a spring and a damper over a moving base, once with an extra damper up to a fixed sky and once "
        "with an adjustable damper beside the passive one, then the mass alone with its forces, and a plot of force "
        "against relative velocity in which a semi-active damper is confined to a sector of the two dissipative "
        "quadrants."
    )
    return Captioned(fig, caption, "fig-schematic-skyhook", alt)


# ------------------------------------------------------------------------------------------ Duffing


def duffing_spring() -> Captioned:
    """A mass on a cubic spring k x + k3 x^3: schematic, free-body diagram and the restoring force of the hardening,
    linear and softening springs."""
    fig, (left, middle, right) = figure(1, 3, height=2.5, gridspec_kw={"width_ratios": [1.45, 1.45, 1.0]})
    w, h = 1.1, 1.6
    _blank(left, "schematic", "schematic", (-0.1, 4.6), (-0.35, 2.6))
    _wall(left, 0.2, 0.0, 2.1)
    _ground(left, 0.2, 4.5, 0.0)
    x0 = 2.2
    _rollers(left, x0, w, 0.0)
    _mass(left, x0, 0.22, w, h, "$m$")
    _spring(left, (0.2, 1.42), (x0, 1.42), coils=4)
    left.text(1.2, 1.72, "$k$, $k_3$", ha="center", va="bottom", fontsize=_TEXT)
    _dashpot(left, (0.2, 0.74), (x0, 0.74))
    left.text(1.2, 0.5, "$c$", ha="center", va="top", fontsize=_TEXT)
    _load(left, (x0 + w, 0.6), (x0 + w + 0.9, 0.6), r"$F_0\cos\omega t$", (x0 + w + 0.05, 0.72), "left", "bottom")
    _coordinate(left, (x0, 2.15), 0.7, "$x$")

    _blank(middle, "free-body diagram", "free-body diagram", (-0.1, 4.6), (-1.0, 2.6))
    x0, y0 = 1.75, 0.2
    _mass(middle, x0, y0, w, h, "$m$")
    _force(middle, (x0, 1.3), (x0 - 1.0, 1.3), "$kx + k_3x^3$", (x0 - 0.05, 1.42), "right", "bottom")
    _force(middle, (x0, 0.55), (x0 - 1.0, 0.55), r"$c\dot x$", (x0 - 0.5, 0.43), va="top")
    _force(middle, (x0 + w, 0.75), (x0 + w + 0.9, 0.75), r"$F_0\cos\omega t$", (x0 + w + 0.05, 0.87), "left",
           "bottom")  # fmt: skip
    _force(middle, (x0 + 0.3, y0), (x0 + 0.3, y0 - 0.85), "$mg$", (x0 + 0.22, y0 - 0.55), "right")
    _force(middle, (x0 + w - 0.3, y0 - 0.85), (x0 + w - 0.3, y0), "$N$", (x0 + w - 0.22, y0 - 0.55), "left")
    _coordinate(middle, (x0, 2.15), 0.7, "$x$")

    right.set_label("restoring force")
    xi = np.linspace(-1.0, 1.0, 201)
    curves = (("hardening", 1.0, "$k_3 > 0$"), ("linear", 0.0, "$k_3 = 0$"), ("softening", -1.0, "$k_3 < 0$"))
    for case, sign, text in curves:
        right.plot(xi, xi + sign * xi**3, label=text, **case_style(case))
    right.set_xlim(-1.0, 1.0)
    right.set_ylim(-2.0, 2.0)
    right.set_xlabel("$x/x_0$")
    right.set_ylabel("$F/(kx_0)$")
    right.set_title("restoring force", fontsize=10)
    place_legend(right, fontsize=8.5, handlelength=1.5, borderaxespad=0.3)

    words = panel_words(fig)
    colours = {"hardening": "vermillion", "linear": "blue", "softening": "sky blue"}
    caption = (
        r"The Duffing oscillator of chapter 9, $m\ddot x + c\dot x + kx + k_3x^3 = F_0\cos\omega t$. "
        f"{words[0].capitalize()}: a mass $m$ (kg) on a nonlinear spring with linear stiffness $k$ (N/m) and cubic "
        "stiffness $k_3$ (N/m³), a dashpot $c$ (N s/m) and the drive $F_0\\cos\\omega t$ (N; $\\omega$ in rad/s, $t$ "
        "in s); $x$ (m, blue) is measured from the relaxed spring. "
        f"{words[1].capitalize()}: its free-body diagram, with the spring force $kx + k_3x^3$, the damper force "
        r"$c\dot x$, the drive $F_0\cos\omega t$, and the weight $mg$ and the normal force $N$ (N), which balance. "
        f"{words[2].capitalize()}: the spring's restoring force $F = kx + k_3x^3$ (N) against the displacement, "
        "drawn as $F/(kx_0)$ against $x/x_0$ with $x_0 = \\sqrt{k/|k_3|}$ (m), where the cubic term equals the "
        "linear one: the hardening spring "
        f"($k_3 > 0$, {colours['hardening']}) stiffens, the softening spring ($k_3 < 0$, {colours['softening']}) "
        f"weakens, loses all stiffness at $x_0/\\sqrt{{3}}$ and no longer restores beyond $x_0$; the linear spring "
        f"($k_3 = 0$, {colours['linear']}) between them. Forces are vermillion. " + _NEWTON
    )
    alt = (
        "A mass on rollers tied to a wall by a spring and a dashpot and driven by a sinusoidal force, its free-body "
        "diagram, and the restoring force against displacement: a straight line for the linear spring, a curve "
        "bending up for the hardening spring and one bending back to zero for the softening spring."
    )
    return Captioned(fig, caption, "fig-schematic-duffing", alt)


# ------------------------------------------------------------------------------------------ the torsional wheel


def _spiral(ax, r0: float, r1: float, turns: float, end_deg: float) -> tuple[float, float]:
    """An Archimedean spiral about the origin from radius ``r0`` to ``r1`` ending at ``end_deg``; returns its end."""
    phi = np.linspace(0.0, 2 * np.pi * turns, 400)
    r = r0 + (r1 - r0) * phi / phi[-1]
    a = np.radians(end_deg) - 2 * np.pi * turns + phi
    ax.plot(r * np.cos(a), r * np.sin(a), color=INK, lw=1.0, zorder=3)
    return r1 * math.cos(a[-1]), r1 * math.sin(a[-1])


def _block(ax, centre, radial_deg: float, length: float, width: float, **kw) -> None:
    """A rectangle centred at ``centre`` with its long side along the direction ``radial_deg``."""
    u = np.array([math.cos(math.radians(radial_deg)), math.sin(math.radians(radial_deg))])
    n = np.array([-u[1], u[0]])
    c = np.asarray(centre, float)
    pts = [c + sa * 0.5 * length * u + sb * 0.5 * width * n for sa, sb in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    ax.add_patch(Polygon(pts, closed=True, **kw))


def _rig_sentence(description: str | None, max_angle_rad: float | None, encoder_step_rad: float | None) -> str:
    """What the data folder says about the rig, and what it does not document (leading space)."""
    known = []
    if description and description.strip():
        known.append(description.strip().rstrip("."))
    if encoder_step_rad:
        known.append(
            f"the wheel's angle is read in steps of {encoder_step_rad:.3g} rad ({math.degrees(encoder_step_rad):.4g}°)"
        )
    if max_angle_rad:
        known.append(f"the wheel can turn at most {max_angle_rad:.3g} rad ({math.degrees(max_angle_rad):.4g}°)")
    missing = [
        "the values of $I$, $\\kappa$, $b$ and $\\tau_c$ (the chapter measures only $\\omega_n$, $\\zeta$ and "
        "$\\Delta$)",
        "the linkage from drive to spring (drawn as the usual push rod and lever)",
        "where the dry friction acts (drawn at the bearing)",
    ]
    if not max_angle_rad:
        missing.append("the largest angle the wheel can turn")
    out = (
        " Known of this rig from its data: " + "; ".join(known) + "." if known else " The data do not describe the rig."
    )
    return out + " Not documented: " + ", ".join(missing[:-1]) + " and " + missing[-1] + "."


def torsional_oscillator(
    *, description: str | None = None, max_angle_rad: float | None = None, encoder_step_rad: float | None = None
) -> Captioned:
    """Chapter 12's torsional wheel: a spiral spring, a motor-driven crank winding the spring's outer end, an
    eddy-current brake and dry friction at the bearing; beside it the wheel's free-body diagram with its torques.

    Parameters
    ----------
    description : str, optional
        What the data folder says the rig is (its ``rig.csv`` description); quoted in the caption.
    max_angle_rad, encoder_step_rad : float, optional
        The largest angle the wheel can turn and the angle sensor's step (rad), when the folder documents them.
        The caption says which of these, and what else the drawing assumes, the data do not document.
    """
    fig, (left, right) = figure(1, 2, height=3.7)
    R = 1.3
    _blank(left, "schematic", "schematic", (-2.2, 2.9), (-2.35, 2.75))
    _ground(left, -1.4, 1.4, -1.95)
    left.add_patch(Rectangle((-0.09, -1.95), 0.18, 1.95, facecolor=BODY, edgecolor=INK, lw=_LW, zorder=1))
    left.add_patch(Circle((0, 0), R, facecolor=BODY, edgecolor=INK, lw=_LW, zorder=2))
    left.text(-0.85, 0.3, "$I$", ha="center", va="center", fontsize=10, zorder=5)
    # the pointer and its rest position; the angle theta
    theta = 32.0
    t = math.radians(theta)
    left.plot([0.62 * R, 1.12 * R], [0.0, 0.0], color=INK, lw=0.9, ls="--", zorder=3)
    left.plot([0.62 * R * math.cos(t), R * math.cos(t)], [0.62 * R * math.sin(t), R * math.sin(t)], color=INK,
              lw=2.2, zorder=3)  # fmt: skip
    _arc_arrow(left, (0, 0), 0.8 * R, 2.0, theta - 2.0, COORDINATE, "coordinate:$\\theta$", lw=1.1, scale=9.0)
    left.text(0.8 * R + 0.06, 0.26, "$\\theta$", color=COORDINATE, ha="left", va="center", fontsize=_TEXT, zorder=5)
    # spiral spring from the axle to the lever, the lever, the push rod, the crank and the motor
    xe, ye = _spiral(left, 0.2, 0.62, 2.25, 90.0)
    left.text(-0.45, 0.62, "$\\kappa$", ha="center", va="center", fontsize=_TEXT, zorder=5)
    top = (0.0, R + 0.7)
    left.plot([xe, top[0]], [ye, top[1]], color=INK, lw=2.4, solid_capstyle="round", zorder=4)
    crank_c, crank_r = (2.2, R + 0.7), 0.32
    pin = (crank_c[0] + crank_r * math.cos(math.radians(150)), crank_c[1] + crank_r * math.sin(math.radians(150)))
    left.add_patch(Rectangle((1.75, R - 0.3), 0.9, 1.0, facecolor=BODY, edgecolor=INK, lw=_LW, zorder=2))
    left.text(2.2, R - 0.02, "motor", ha="center", va="center", fontsize=_TEXT, zorder=5)
    left.add_patch(Circle(crank_c, crank_r, facecolor="white", edgecolor=INK, lw=_LW, zorder=3))
    left.plot([top[0], pin[0]], [top[1], pin[1]], color=INK, lw=1.6, zorder=4)
    for p, r in ((top, 0.06), (pin, 0.05), (crank_c, 0.04)):
        left.add_patch(Circle(p, r, facecolor="white", edgecolor=INK, lw=1.0, zorder=5))
    _arc_arrow(left, crank_c, crank_r + 0.14, 20.0, 120.0, COORDINATE, "coordinate:$\\omega t$", lw=1.1, scale=9.0)
    left.text(crank_c[0] + 0.45, crank_c[1] + 0.3, "$\\omega t$", color=COORDINATE, ha="left", va="bottom",
              fontsize=_TEXT)  # fmt: skip
    # the eddy-current brake astride the rim, and the bearing
    at = math.radians(225.0)
    _block(left, (0.93 * R * math.cos(at), 0.93 * R * math.sin(at)), 225.0, 0.55, 0.42, facecolor=OKABE_ITO["grey"],
           edgecolor=INK, lw=_LW, zorder=4)  # fmt: skip
    left.text(-1.48, -1.0, "$b$", ha="right", va="center", fontsize=_TEXT)
    left.add_patch(Circle((0, 0), 0.12, facecolor="white", edgecolor=INK, lw=1.2, zorder=5))
    left.add_patch(Circle((0, 0), 0.06, facecolor=BODY, edgecolor=INK, lw=1.0, zorder=5))
    left.plot([0.09, 0.5], [-0.09, -0.58], color=INK, lw=0.7, zorder=5)
    left.text(0.52, -0.58, "$\\tau_c$", ha="left", va="top", fontsize=_TEXT, zorder=5)

    _blank(right, "free-body diagram", "free-body diagram of the wheel", (-2.55, 2.55), (-2.35, 2.75))
    Rf = 1.05
    right.add_patch(Circle((0, 0), Rf, facecolor=BODY, edgecolor=INK, lw=_LW, zorder=2))
    right.add_patch(Circle((0, 0), 0.08, facecolor="white", edgecolor=INK, lw=1.2, zorder=3))
    right.text(-0.45, 0.5, "$I$", ha="center", va="center", fontsize=10, zorder=5)
    right.plot([0.1, 0.95 * Rf], [0.0, 0.0], color=INK, lw=0.9, ls="--", zorder=3)
    right.plot([0.1 * math.cos(t), Rf * math.cos(t)], [0.1 * math.sin(t), Rf * math.sin(t)], color=INK, lw=2.2,
               zorder=3)  # fmt: skip
    _arc_arrow(right, (0, 0), 0.7 * Rf, 2.0, theta - 2.0, COORDINATE, "coordinate:$\\theta$", lw=1.1, scale=9.0)
    right.text(0.7 * Rf + 0.06, 0.2, "$\\theta$", color=COORDINATE, ha="left", va="center", fontsize=_TEXT, zorder=5)
    ra = Rf + 0.28
    torques = (
        (r"$\tau_0\sin\omega t$", 60.0, 120.0, (0.0, ra + 0.2), "center", "bottom"),
        (r"$\kappa\theta$", 25.0, -25.0, (ra + 0.2, 0.0), "left", "center"),
        (r"$b\dot\theta$", 290.0, 250.0, (0.0, -ra - 0.2), "center", "top"),
        (r"$\tau_c\,\mathrm{sgn}\,\dot\theta$", 205.0, 155.0, (-ra - 0.2, 0.0), "right", "center"),
    )
    for label, a0, a1, at_xy, ha, va in torques:
        _arc_arrow(right, (0, 0), ra, a0, a1, FORCE, "force:" + label)
        right.text(*at_xy, label, color=FORCE, ha=ha, va=va, fontsize=_TEXT, zorder=5)

    caption = (
        r"The real oscillator of chapter 12, a torsional wheel: $I\ddot\theta + b\dot\theta + "
        r"\tau_c\,\mathrm{sgn}\,\dot\theta + \kappa\theta = \tau_0\sin\omega t$. "
        + _sentence_panels(
            fig,
            [
                "a wheel of moment of inertia $I$ (kg m²) turns on a bearing about its axle; the spiral spring of "
                "torsional stiffness $\\kappa$ (N m/rad) joins the axle to a lever; a motor turns an eccentric (a "
                "crank) through the angle $\\omega t$ ($\\omega$ in rad/s, $t$ in s) and, through a push rod, rocks "
                "the lever, which winds the spring's outer end; an eddy-current (magnetic) brake (grey) astride the "
                "rim damps the wheel viscously with coefficient $b$ (N m s/rad), and the bearing adds dry friction "
                "of torque $\\tau_c$ (N m). The wheel's angle $\\theta$ (rad, blue) is the pointer's turn from its "
                "rest position "
                "(dashed).",
                "the torques on the wheel about its axle (N m): the drive $\\tau_0\\sin\\omega t$ that the rocked "
                "spring passes on, the spring's $\\kappa\\theta$, the brake's $b\\dot\\theta$ and the bearing's "
                "Coulomb friction $\\tau_c\\,\\mathrm{sgn}\\,\\dot\\theta$, the last three against positive "
                "$\\theta$ and $\\dot\\theta$; the weight and the bearing's reaction act through the axle and have "
                "no moment about it.",
            ],
        )
        + " Torques are vermillion. Divided by $I$, this is the chapter's model with $\\omega_n^2 = \\kappa/I$, "
        "$2\\zeta\\omega_n = b/I$ and the friction angle $\\Delta = \\tau_c/\\kappa$ (the spring's resting angle "
        "$c$ taken as zero); the drive there is the measured drive signal $u(t)$ times the gain $g$, the torque "
        "$\\kappa g u(t)$, nearly $\\tau_0\\sin\\omega t$ while the eccentric turns steadily."
        + _rig_sentence(description, max_angle_rad, encoder_step_rad)
        + " "
        + _NEWTON_TORQUES
    )
    alt = (
        "A wheel on a spiral spring whose outer end is rocked by a motor through a crank and a push rod, with a "
        "magnetic brake at its rim, and beside it the wheel alone with the drive torque turning it one way and the "
        "spring, brake and friction torques turning it back."
    )
    return Captioned(fig, caption, "fig-schematic-torsional", alt)
