"""Chapter 12's torsional wheel, drawn as far as its data document it."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import Circle, Polygon, Rectangle

from ..captions import Captioned
from ..style import OKABE_ITO, figure
from .kit import BODY, COORDINATE, FORCE, INK, LW, TEXT, arc_arrow, blank, ground, sentence_panels


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
        "the values of $I$, $\\kappa$, $c_\\theta$ and $\\tau_c$ (the chapter measures only $\\omega_n$, $\\zeta$ "
        "and $\\theta_f$)",
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
        What the data folder says the rig is (its ``rig.csv`` description); quoted in the remark.
    max_angle_rad, encoder_step_rad : float, optional
        The largest angle the wheel can turn and the angle sensor's step (rad), when the folder documents them.
        The remark says which of these, and what else the drawing assumes, the data do not document.
    """
    fig, (left, right) = figure(1, 2, height=3.7)
    R = 1.3
    _draw_wheel(left, R)
    top = _draw_spring(left, R)
    _draw_drive(left, R, top)
    _draw_brake_and_bearing(left, R)
    _draw_free_body(right)
    alt = (
        "A wheel on a spiral spring whose outer end is rocked by a motor through a crank and a push rod, with a "
        "magnetic brake at its rim, and beside it the wheel alone with the drive torque turning it one way and the "
        "spring, brake and friction torques turning it back."
    )
    remark = _REMARK + _rig_sentence(description, max_angle_rad, encoder_step_rad)
    return Captioned(fig, _caption(fig), "fig-schematic-torsional", alt, remark=remark)


#: The angle the pointer is drawn at, degrees.
_THETA = 32.0

#: The angle's arrow, drawn alike on the wheel and on its free-body diagram.
_THETA_ARROW = {"start_deg": 2.0, "end_deg": _THETA - 2.0, "color": COORDINATE, "gid": "coordinate:$\\theta$",
                "lw": 1.1, "scale": 9.0}  # fmt: skip


def _draw_angle(ax, r_in: float, r_rest: float, r_out: float, r_arrow: float, label_y: float) -> None:
    """The pointer from ``r_in`` to ``r_out`` at the angle theta, its rest position (dashed, out to ``r_rest``) and
    the angle's arrow at ``r_arrow`` with its label."""
    t = math.radians(_THETA)
    ax.plot([r_in, r_rest], [0.0, 0.0], color=INK, lw=0.9, ls="--", zorder=3)
    ax.plot([r_in * math.cos(t), r_out * math.cos(t)], [r_in * math.sin(t), r_out * math.sin(t)], color=INK, lw=2.2,
            zorder=3)  # fmt: skip
    arc_arrow(ax, (0, 0), r_arrow, **_THETA_ARROW)
    ax.text(r_arrow + 0.06, label_y, "$\\theta$", color=COORDINATE, ha="left", va="center", fontsize=TEXT, zorder=5)


def _draw_wheel(ax, R: float) -> None:
    """The schematic's panel, the wheel of radius ``R`` on its post, and its pointer at the angle theta."""
    blank(ax, "schematic", "schematic", xlim=(-2.2, 2.9), ylim=(-2.35, 2.75))
    ground(ax, -1.4, 1.4, y=-1.95)
    ax.add_patch(Rectangle((-0.09, -1.95), 0.18, 1.95, facecolor=BODY, edgecolor=INK, lw=LW, zorder=1))
    ax.add_patch(Circle((0, 0), R, facecolor=BODY, edgecolor=INK, lw=LW, zorder=2))
    ax.text(-0.85, 0.3, "$I$", ha="center", va="center", fontsize=10, zorder=5)
    _draw_angle(ax, 0.62 * R, 1.12 * R, R, 0.8 * R, 0.26)


def _draw_spring(ax, R: float) -> tuple[float, float]:
    """The spiral spring from the axle and the lever on its outer end; returns the lever's top (the rod's pin)."""
    xe, ye = _spiral(ax, 0.2, 0.62, 2.25, 90.0)
    ax.text(-0.45, 0.62, "$\\kappa$", ha="center", va="center", fontsize=TEXT, zorder=5)
    top = (0.0, R + 0.7)
    ax.plot([xe, top[0]], [ye, top[1]], color=INK, lw=2.4, solid_capstyle="round", zorder=4)
    return top


def _draw_drive(ax, R: float, top: tuple[float, float]) -> None:
    """The motor, its crank at the angle omega t and the push rod from the crank's pin to the lever's ``top``."""
    crank_c, crank_r = (2.2, R + 0.7), 0.32
    pin = (crank_c[0] + crank_r * math.cos(math.radians(150)), crank_c[1] + crank_r * math.sin(math.radians(150)))
    ax.add_patch(Rectangle((1.75, R - 0.3), 0.9, 1.0, facecolor=BODY, edgecolor=INK, lw=LW, zorder=2))
    ax.text(2.2, R - 0.02, "motor", ha="center", va="center", fontsize=TEXT, zorder=5)
    ax.add_patch(Circle(crank_c, crank_r, facecolor="white", edgecolor=INK, lw=LW, zorder=3))
    ax.plot([top[0], pin[0]], [top[1], pin[1]], color=INK, lw=1.6, zorder=4)
    for p, r in ((top, 0.06), (pin, 0.05), (crank_c, 0.04)):
        ax.add_patch(Circle(p, r, facecolor="white", edgecolor=INK, lw=1.0, zorder=5))
    arc_arrow(
        ax,
        crank_c,
        crank_r + 0.14,
        start_deg=20.0,
        end_deg=120.0,
        color=COORDINATE,
        gid="coordinate:$\\omega t$",
        lw=1.1,
        scale=9.0,
    )
    ax.text(crank_c[0] + 0.45, crank_c[1] + 0.3, "$\\omega t$", color=COORDINATE, ha="left", va="bottom",
            fontsize=TEXT)  # fmt: skip


def _draw_brake_and_bearing(ax, R: float) -> None:
    """The eddy-current brake astride the rim, and the bearing with its dry friction."""
    at = math.radians(225.0)
    _block(ax, (0.93 * R * math.cos(at), 0.93 * R * math.sin(at)), 225.0, 0.55, 0.42, facecolor=OKABE_ITO["grey"],
           edgecolor=INK, lw=LW, zorder=4)  # fmt: skip
    ax.text(-1.48, -1.0, "$c_\\theta$", ha="right", va="center", fontsize=TEXT)
    ax.add_patch(Circle((0, 0), 0.12, facecolor="white", edgecolor=INK, lw=1.2, zorder=5))
    ax.add_patch(Circle((0, 0), 0.06, facecolor=BODY, edgecolor=INK, lw=1.0, zorder=5))
    ax.plot([0.09, 0.5], [-0.09, -0.58], color=INK, lw=0.7, zorder=5)
    ax.text(0.52, -0.58, "$\\tau_c$", ha="left", va="top", fontsize=TEXT, zorder=5)


def _draw_free_body(ax) -> None:
    """The free-body diagram: the wheel alone, its angle, and the four torques on it."""
    blank(ax, "free-body diagram", "free-body diagram of the wheel", xlim=(-2.55, 2.55), ylim=(-2.35, 2.75))
    Rf = 1.05
    ax.add_patch(Circle((0, 0), Rf, facecolor=BODY, edgecolor=INK, lw=LW, zorder=2))
    ax.add_patch(Circle((0, 0), 0.08, facecolor="white", edgecolor=INK, lw=1.2, zorder=3))
    ax.text(-0.45, 0.5, "$I$", ha="center", va="center", fontsize=10, zorder=5)
    _draw_angle(ax, 0.1, 0.95 * Rf, Rf, 0.7 * Rf, 0.2)
    ra = Rf + 0.28
    torques = (
        (r"$\tau_0\sin\omega t$", 60.0, 120.0, (0.0, ra + 0.2), "center", "bottom"),
        (r"$\kappa\theta$", 25.0, -25.0, (ra + 0.2, 0.0), "left", "center"),
        (r"$c_\theta\dot\theta$", 290.0, 250.0, (0.0, -ra - 0.2), "center", "top"),
        (r"$\tau_c\,\mathrm{sgn}\,\dot\theta$", 205.0, 155.0, (-ra - 0.2, 0.0), "right", "center"),
    )
    for label, a0, a1, at_xy, ha, va in torques:
        arc_arrow(ax, (0, 0), ra, start_deg=a0, end_deg=a1, color=FORCE, gid="force:" + label)
        ax.text(*at_xy, label, color=FORCE, ha=ha, va=va, fontsize=TEXT, zorder=5)


def _caption(fig) -> str:
    """The figure's caption: the equation of motion and what each panel shows."""
    return (
        r"The real oscillator of chapter 12, a torsional wheel: $I\ddot\theta + c_\theta\dot\theta + "
        r"\tau_c\,\mathrm{sgn}\,\dot\theta + \kappa\theta = \tau_0\sin\omega t$. "
        + sentence_panels(
            fig,
            [
                "the wheel $I$ on a spiral spring $\\kappa$, rocked by a motor's crank at the angle $\\omega t$, "
                "with an eddy-current brake $c_\\theta$ (grey) and bearing friction $\\tau_c$; its angle "
                "$\\theta$ (blue) from rest (dashed).",
                "the torques $\\tau_0\\sin\\omega t$, $\\kappa\\theta$, $c_\\theta\\dot\\theta$ and "
                "$\\tau_c\\,\\mathrm{sgn}\\,\\dot\\theta$ on the wheel, in vermillion.",
            ],
        )
    )


#: The remark's account of the rig and its torques (the rig's data follow it, :func:`_rig_sentence`).
_REMARK = (
    "The wheel (moment of inertia $I$, kg m²) turns on a bearing; the spiral spring (torsional stiffness "
    "$\\kappa$, N m/rad) joins its axle to a lever, which a push rod from the motor's eccentric rocks, winding "
    "the spring's outer end ($\\omega$ in rad/s, $t$ in s). The magnetic brake astride the rim damps the wheel "
    "viscously ($c_\\theta$, N m s/rad); the bearing adds dry friction of torque $\\tau_c$ (N m). The angle "
    "$\\theta$ (rad) is the pointer's turn from rest. In Newton's form for a turning body, each torque about the "
    "axle (N m) is drawn as it acts for positive $\\theta$ and $\\dot\\theta$, and $I\\ddot\\theta$, their sum, is "
    "not drawn: the drive, passed on by the rocked spring, turns the wheel forward; the spring, the brake and "
    "the bearing's Coulomb friction turn it back; the weight and the bearing's reaction act through the axle "
    "and have no moment about it. Divided by $I$, this is the chapter's model with $\\omega_n^2 = \\kappa/I$, "
    "$2\\zeta\\omega_n = c_\\theta/I$ and the friction angle $\\theta_f = \\tau_c/\\kappa$ (the spring's resting "
    "angle $\\theta_0$ taken as zero); the drive there is the measured drive angle $\\theta_d(t)$ times the gain "
    "$G$, the torque $\\kappa G \\theta_d(t)$, nearly $\\tau_0\\sin\\omega t$ while the eccentric turns steadily."
)
