"""One mass on a spring and a dashpot: the paper's model (chapters 1-6) and base excitation (chapter 6's
isolation, chapter 7's suspension)."""

from __future__ import annotations

from ..captions import Captioned
from ..style import figure
from .kit import (
    TEXT,
    blank,
    coordinate,
    dashpot,
    drive,
    force,
    ground,
    mass,
    rollers,
    sentence_panels,
    spring,
    wall,
    weight_and_support,
)


def single_mass() -> Captioned:
    """The paper's model: wall, spring k, dashpot c, mass m, force F0 sin(omega t), coordinate x."""
    fig, (left, right) = figure(1, 2, height=2.5)
    blank(left, "schematic", "schematic", xlim=(-0.35, 6.0), ylim=(-0.35, 2.6))
    wall(left, 0.3, 0.0, y1=2.1)
    ground(left, 0.3, 5.7, y=0.0)
    x0, y0, w, h = 2.8, 0.22, 1.2, 1.6
    rollers(left, x0, w, y=0.0)
    mass(left, x0, y0, w=w, h=h, label="$m$")
    spring(left, (0.3, 1.42), (x0, 1.42))
    left.text(1.55, 1.72, "$k$", ha="center", va="bottom", fontsize=TEXT)
    dashpot(left, (0.3, 0.62), (x0, 0.62))
    left.text(1.55, 0.3, "$c$", ha="center", va="top", fontsize=TEXT)
    drive(left, (x0 + w, 1.02), 1.0, label=r"$F_0\sin\omega t$", gap=0.08)
    coordinate(left, (x0, 2.1), 0.8, label="$x$")

    blank(right, "free-body diagram", "free-body diagram of the mass", xlim=(-0.45, 5.9), ylim=(-1.1, 2.6))
    x0, y0 = 2.0, 0.2
    mass(right, x0, y0, w=w, h=h, label="$m$")
    force(right, (x0, 1.3), (x0 - 1.1, 1.3), label="$kx$", at=(x0 - 0.55, 1.42), va="bottom")
    force(right, (x0, 0.55), (x0 - 1.1, 0.55), label=r"$c\dot x$", at=(x0 - 0.55, 0.43), va="top")
    drive(right, (x0 + w, 1.0), 1.0, label=r"$F_0\sin\omega t$", gap=0.08, free_body=True)
    weight_and_support(right, x0, y0, w=w, inset=0.35, drop=0.9)
    coordinate(right, (x0, 2.1), 0.8, label="$x$")

    caption = r"The paper's model, $m\ddot x + c\dot x + kx = F_0\sin\omega t$. " + sentence_panels(
        fig,
        [
            "a block of mass $m$ on rollers, tied to a wall by a spring $k$ and a dashpot $c$ and driven by the "
            r"force $F_0\sin\omega t$; its displacement $x$ in blue.",
            r"the block's free-body diagram, with the forces $kx$, $c\dot x$, $F_0\sin\omega t$, $mg$ and $N$ in "
            "vermillion.",
        ],
    )
    remark = (
        "The mass $m$ is in kg, the stiffness $k$ in N/m and the damping coefficient $c$ in N s/m; the drive has the "
        "amplitude $F_0$ (N) and the angular frequency $\\omega$ (rad/s), $t$ is the time (s), and $x$ (m) is "
        "measured from where the spring is relaxed; the wall and the ground are fixed (hatched). The free-body "
        "diagram is in Newton's form: each arrow is a force on the block (N), drawn the way it acts when $x$ and "
        "$\\dot x$ are positive. The spring force $kx$ and the damper force $c\\dot x$ point back towards the wall, "
        "the drive away from it; the weight $mg$ ($g$ the acceleration of gravity, m/s²) and the rollers' normal "
        "force $N$ balance each other. The mass times the acceleration, $m\\ddot x$, is the sum of these forces, not "
        "a force of its own, so it has no arrow."
    )
    alt = (
        "A block on rollers tied to a wall by a spring and a dashpot and pushed by a sinusoidal force, and beside it "
        "the block alone with the spring and damper forces pointing back towards the wall and the drive pointing away."
    )
    return Captioned(fig, caption, "fig-schematic-single-mass", alt, remark=remark)


# ------------------------------------------------------------------------------------------ base excitation


def base_excitation() -> Captioned:
    """A mass on a spring and a dashpot whose base moves as y(t): chapter 6's isolation, chapter 7's suspension."""
    fig, (left, right) = figure(1, 2, height=3.0)
    blank(left, "schematic", "schematic", xlim=(-2.4, 2.4), ylim=(-0.2, 3.3))
    bw, bh = 2.6, 0.35  # base plate
    mass(left, -0.5 * bw, 0.0, w=bw, h=bh)
    left.text(-0.5 * bw - 0.1, 0.5 * bh, "base", ha="right", va="center", fontsize=TEXT)
    coordinate(left, (0.5 * bw + 0.3, 0.5 * bh), 0.6, label="$y(t)$", vertical=True)
    mw, mh, my = 1.7, 0.9, 1.85
    spring(left, (-0.45, bh), (-0.45, my))
    left.text(-0.75, 0.5 * (bh + my), "$k$", ha="right", va="center", fontsize=TEXT)
    dashpot(left, (0.45, bh), (0.45, my))
    left.text(0.75, 0.5 * (bh + my), "$c$", ha="left", va="center", fontsize=TEXT)
    mass(left, -0.5 * mw, my, w=mw, h=mh, label="$m$")
    coordinate(left, (0.5 * mw + 0.3, my + 0.5 * mh), 0.6, label="$x$", vertical=True)

    blank(right, "free-body diagram", "free-body diagram of the mass", xlim=(-2.4, 2.4), ylim=(-0.2, 3.3))
    my = 1.55
    mass(right, -0.5 * mw, my, w=mw, h=mh, label="$m$")
    force(right, (-0.45, my), (-0.45, my - 1.0), label="$k(x - y)$", at=(-0.55, my - 0.5), ha="right")
    force(right, (0.45, my), (0.45, my - 1.0), label=r"$c(\dot x - \dot y)$", at=(0.55, my - 0.5), ha="left")
    coordinate(right, (0.5 * mw + 0.3, my + 0.5 * mh), 0.6, label="$x$", vertical=True)

    caption = (
        r"Base excitation, $m\ddot x + c\dot x + kx = c\dot y + ky$, or $m\ddot z + c\dot z + kz = -m\ddot y$ in "
        "the relative displacement $z = x - y$. "
        + sentence_panels(
            fig,
            [
                "a mass $m$ on a spring $k$ and a dashpot $c$ whose base moves as $y(t)$; $x$ and $y$ in blue.",
                r"the free-body diagram of the mass, with the spring force $k(x - y)$ and the damper force "
                r"$c(\dot x - \dot y)$ in vermillion.",
            ],
        )
    )
    remark = (
        "Here $m$ is in kg, $k$ in N/m, $c$ in N s/m, and the displacements $x$ and $y$ (m) are absolute, both "
        "measured from the static equilibrium; in chapter 6 the base moves as $Y\\sin\\omega t$. The two forces (N) "
        "depend only on the motion relative to the base. Drawn as they act for positive $x - y$ and "
        "$\\dot x - \\dot y$, the convention of Newton's form, both pull the mass down; their sum is $m\\ddot x$, "
        "which therefore is not an arrow. The weight and the static spring force cancel at the equilibrium and are "
        "left out."
    )
    alt = (
        "A mass on a spring and a dashpot standing on a base that moves up and down, and beside it the mass alone "
        "with the spring and damper forces, both set by the stretch relative to the base, pointing down."
    )
    return Captioned(fig, caption, "fig-schematic-base-excitation", alt, remark=remark)
