"""Chapter 8's absorbers: the tuned mass damper on its primary and the shear building with a roof absorber."""

from __future__ import annotations

import numpy as np

from vibration.physics.model import check_int

from ..captions import Captioned
from ..style import figure
from .kit import (
    INK,
    LW,
    TEXT,
    blank,
    coordinate,
    dashpot,
    force,
    ground,
    load,
    mass,
    rollers,
    sentence_panels,
    spring,
    wall,
)


def two_mass_absorber() -> Captioned:
    """The primary (m_p, k_p, c_p) with the absorber (m_a, k_a, c_a) on top and the force on the primary."""
    fig, (left, right) = figure(1, 2, height=3.6)
    blank(left, "schematic", "schematic", xlim=(-2.7, 2.2), ylim=(-0.3, 4.2))
    ground(left, -1.4, 1.4, y=0.0)
    pw, ph, py = 1.8, 0.8, 1.3  # primary
    aw, ah, ay = 1.2, 0.6, 3.05  # absorber
    sw = 2.3  # the primary's width in the schematic, with room under it for the drive
    spring(left, (-0.3, 0.0), (-0.3, py))
    left.text(-0.56, 0.5 * py, "$k_p$", ha="right", va="center", fontsize=TEXT)
    dashpot(left, (0.5, 0.0), (0.5, py))
    left.text(0.78, 0.5 * py, "$c_p$", ha="left", va="center", fontsize=TEXT)
    mass(left, -0.5 * sw, py, w=sw, h=ph, label="$m_p$")
    spring(left, (-0.32, py + ph), (-0.32, ay), width=0.22, coils=4)
    left.text(-0.56, 0.5 * (py + ph + ay), "$k_a$", ha="right", va="center", fontsize=TEXT)
    dashpot(left, (0.32, py + ph), (0.32, ay), width=0.26)
    left.text(0.56, 0.5 * (py + ph + ay), "$c_a$", ha="left", va="center", fontsize=TEXT)
    mass(left, -0.5 * aw, ay, w=aw, h=ah, label="$m_a$")
    load(left, (-1.0, py - 0.75), (-1.0, py), label=r"$F_0\sin\omega t$", at=(-1.1, py - 0.45), ha="right")
    coordinate(left, (0.5 * sw + 0.25, py + 0.5 * ph), 0.55, label="$x_p$", vertical=True)
    coordinate(left, (0.5 * aw + 0.3, ay + 0.5 * ah), 0.55, label="$x_a$", vertical=True)

    blank(right, "free-body diagram", "free-body diagrams of the masses", xlim=(-2.4, 2.4), ylim=(-0.3, 4.2))
    py, ay = 0.95, 3.2
    mass(right, -0.5 * aw, ay, w=aw, h=ah, label="$m_a$")
    d = 0.3
    force(right, (-d, ay), (-d, ay - 0.7), label="$k_a(x_a - x_p)$", at=(-d - 0.1, ay - 0.35), ha="right")
    force(right, (d, ay), (d, ay - 0.7), label=r"$c_a(\dot x_a - \dot x_p)$", at=(d + 0.1, ay - 0.35), ha="left")
    mass(right, -0.5 * pw, py, w=pw, h=ph, label="$m_p$")
    top = py + ph
    force(right, (-d, top), (-d, top + 0.7), label="$k_a(x_a - x_p)$", at=(-d - 0.1, top + 0.35), ha="right")
    force(right, (d, top), (d, top + 0.7), label=r"$c_a(\dot x_a - \dot x_p)$", at=(d + 0.1, top + 0.35), ha="left")
    force(right, (-0.6, py), (-0.6, py - 0.75), label="$k_px_p$", at=(-0.7, py - 0.4), ha="right")
    force(right, (0.6, py), (0.6, py - 0.75), label=r"$c_p\dot x_p$", at=(0.7, py - 0.4), ha="left")
    force(right, (0.0, py - 0.75), (0.0, py), label=r"$F_0\sin\omega t$", at=(0.0, py - 0.8), va="top")
    coordinate(right, (0.5 * pw + 0.3, py), 0.5, label="$x_p$", vertical=True)
    coordinate(right, (0.5 * aw + 0.3, ay + 0.5 * ah), 0.5, label="$x_a$", vertical=True)

    caption = "The tuned mass damper of chapter 8. " + sentence_panels(
        fig,
        [
            r"the primary $m_p$ (spring $k_p$, dashpot $c_p$, drive $F_0\sin\omega t$) carries the absorber $m_a$ "
            r"($\mu m_p$) on a spring $k_a$ and a dashpot $c_a$; displacements $x_p$ and $x_a$ in blue.",
            r"both masses' free-body diagrams: $k_a(x_a - x_p)$ and $c_a(\dot x_a - \dot x_p)$ on each, $k_px_p$ "
            r"and $c_p\dot x_p$ on the primary, forces in vermillion.",
        ],
    )
    remark = (
        "Masses are in kg, stiffnesses in N/m, damping coefficients in N s/m, $\\omega$ in rad/s and $t$ in s; $x_p$ "
        "and $x_a$ (m) are measured from the static equilibrium, where the weights and the static spring forces "
        "balance, so these are left out. The primary stands on fixed ground (hatched). In the free-body diagrams the "
        "absorber is drawn above the primary. The absorber's spring and dashpot pull the two masses together with "
        "equal and opposite forces (N); on the primary also act $k_px_p$ and $c_p\\dot x_p$, towards the ground, and "
        "the drive. Every arrow points the way its force acts when the displacements and velocities are positive "
        "(Newton's form), and each mass times its acceleration is the sum of its arrows rather than one of them."
    )
    alt = (
        "A large mass on a spring and a dashpot carrying a small mass on its own spring and dashpot, and beside it "
        "the two masses apart with the equal and opposite spring and damper forces between them and the drive on "
        "the large mass."
    )
    return Captioned(fig, caption, "fig-schematic-absorber", alt, remark=remark)


# ------------------------------------------------------------------------------------------ shear building


def _column(ax, x0: float, y0: float, x1: float, y1: float) -> None:
    """A column bent in double curvature from its foot (``x0``, ``y0``) to its head (``x1``, ``y1``)."""
    s = np.linspace(0.0, 1.0, 40)
    ax.plot(x0 + (x1 - x0) * (3 * s**2 - 2 * s**3), y0 + (y1 - y0) * s, color=INK, lw=LW)


def shear_building(n: int = 5) -> Captioned:
    """An ``n``-storey shear frame with a roof absorber under ground acceleration, and the free-body diagram of a
    floor (2 <= n <= 8)."""
    n = check_int("n", n, low=2, high=8)
    hs, half, t = 3.6 / n, 1.0, 0.14  # storey height, half the floor's width, floor thickness
    sway = 0.3 * np.sin(0.5 * np.pi * np.arange(n + 1) / n)  # drawn in the first mode's shape
    top = n * hs + 0.75
    fig, (left, right) = figure(1, 2, height=4.2)
    blank(left, "schematic", "schematic", xlim=(-2.1, 2.4), ylim=(-0.75, top + 0.2))
    ground(left, -1.6, 1.9, y=0.0)
    for j in range(1, n + 1):
        y = j * hs
        for side in (-1, 1):
            _column(left, sway[j - 1] + side * 0.8 * half, y - hs + (t if j > 1 else 0.0), sway[j] + side * 0.8 * half,
                    y - t)  # fmt: skip
        mass(left, sway[j] - half, y - t, w=2 * half, h=t)
        left.text(sway[j] - half - 0.12, y - 0.5 * t, "$m$", ha="right", va="center", fontsize=TEXT)
        left.text(sway[j - 1] - 0.8 * half - 0.12, y - 0.5 * hs, "$k$", ha="right", va="center", fontsize=TEXT)
        coordinate(left, (1.45, y - 0.5 * t), 0.4, label=f"$x_{j}$", tick=0.1)
    roof = n * hs
    xr = sway[n]
    post = xr - 0.85
    wall(left, post, roof, y1=roof + 0.62, depth=0.12)
    aw, ah = 0.5, 0.48
    ax0 = xr + 0.3
    rollers(left, ax0, aw, y=roof, r=0.06)
    mass(left, ax0, roof + 0.12, w=aw, h=ah)
    left.text(ax0 + 0.5 * aw, roof + 0.12 + ah + 0.04, "$m_a$", ha="center", va="bottom", fontsize=TEXT)
    spring(left, (post, roof + 0.48), (ax0, roof + 0.48), coils=4, width=0.14, lead=0.08)
    left.text(post - 0.22, roof + 0.48, "$k_a$", ha="right", va="center", fontsize=TEXT)
    dashpot(left, (post, roof + 0.24), (ax0, roof + 0.24), width=0.14)
    left.text(post - 0.22, roof + 0.24, "$c_a$", ha="right", va="center", fontsize=TEXT)
    coordinate(left, (1.45, roof + 0.36), 0.4, label="$x_a$", tick=0.1)
    coordinate(left, (-0.9, -0.5), 0.6, label=r"$\ddot u_g$", tick=0.1, side="start")

    blank(right, "free-body diagram", "free-body diagram of floor $j$", xlim=(-2.1, 2.4), ylim=(-0.75, top + 0.2))
    yc, th = 0.5 * top - 0.2, 0.5  # floor j, drawn thicker
    for xcol in (-0.55 * half, 0.55 * half):
        for y0, y1 in ((yc + 0.5 * th, yc + 0.5 * th + 0.45), (yc - 0.5 * th - 0.45, yc - 0.5 * th)):
            right.plot([xcol, xcol], [y0, y1], color=INK, lw=LW)
        for y in (yc + 0.5 * th + 0.45, yc - 0.5 * th - 0.45):  # the cuts
            right.plot([xcol - 0.12, xcol + 0.12], [y - 0.04, y + 0.04], color=INK, lw=0.8)
    mass(right, -half, yc - 0.5 * th, w=2 * half, h=th, label="$m$")
    above, below = "$k(x_{j+1} - x_j)$", "$k(x_j - x_{j-1})$"
    force(right, (half, yc + 0.12), (half + 1.1, yc + 0.12), label=above, at=(half + 0.55, yc + 0.3), va="bottom")
    force(right, (-half, yc - 0.12), (-half - 1.1, yc - 0.12), label=below, at=(-half - 0.55, yc - 0.3), va="top")
    coordinate(right, (-half, yc + 0.5 * th + 0.75), 0.6, label="$x_j$", tick=0.1)

    xs = ", ".join(f"$x_{j}$" for j in range(1, n + 1))
    span = xs if n == 2 else f"$x_1$ to $x_{n}$"
    caption = f"The {n}-storey shear building of chapter 8 with its roof absorber. " + sentence_panels(
        fig,
        [
            "floors $m$ on storeys of stiffness $k$ over ground accelerating at $\\ddot u_g$; the roof absorber "
            f"$m_a$ on a spring $k_a$ and dashpot $c_a$; {span} and $x_a$ in blue.",
            "floor $j$ cut free at $x_j$: the storey shears $k(x_{j+1} - x_j)$ and $k(x_j - x_{j-1})$ (vermillion).",
        ],
    )
    remark = (
        f"The floors' displacements {xs} (m) are relative to the ground, whose acceleration (m/s²) is "
        "$a_g\\sin\\omega t$ in chapter 8; $x_a$ (m) is the absorber's. The floors are rigid, the absorber rolls on "
        "the roof, and the frame is drawn swayed in the first mode's shape. The floor mass $m$ and the absorber's "
        "$m_a$ are in kg, the storey stiffness $k$ (all columns of a storey together) and $k_a$ in N/m, $c_a$ in N "
        "s/m. Floor $j$ is cut free through the columns above and below it. Following Newton's form, the shears (N) "
        "are drawn for positive displacements: the storey above pulls floor $j$ in the positive direction, the storey "
        "below pulls it back, and with the absolute acceleration $m(\\ddot x_j + \\ddot u_g) = k(x_{j+1} - x_j) - "
        "k(x_j - x_{j-1})$. On the roof the absorber's spring and dashpot forces take the place of the storey "
        "above. The building's damping is modal (one ratio $\\zeta_b$ for every mode) and is not drawn, nor are the "
        "vertical forces (weights and column forces), which balance."
    )
    alt = (
        f"A {n}-storey frame of rigid floors on flexible columns, swaying to one side over a moving ground, with a "
        "small mass on a spring and a dashpot on its roof, and beside it one floor cut free, pulled one way by the "
        "storey above and the other way by the storey below."
    )
    return Captioned(fig, caption, "fig-schematic-building", alt, remark=remark)
