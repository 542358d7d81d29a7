"""Chapter 9's Duffing oscillator: a mass on a cubic spring and the restoring force of its three springs."""

from __future__ import annotations

import numpy as np

from ..captions import Captioned, panel_words
from ..style import case_style, figure, place_legend
from .kit import TEXT, blank, coordinate, dashpot, drive, force, ground, mass, rollers, spring, wall, weight_and_support


def duffing_spring() -> Captioned:
    """A mass on a cubic spring k x + k3 x^3: schematic, free-body diagram and the restoring force of the hardening,
    linear and softening springs."""
    fig, (left, middle, right) = figure(1, 3, height=2.5, gridspec_kw={"width_ratios": [1.45, 1.45, 1.0]})
    w, h = 1.1, 1.6
    blank(left, "schematic", "schematic", xlim=(-0.1, 4.6), ylim=(-0.35, 2.6))
    wall(left, 0.2, 0.0, y1=2.1)
    ground(left, 0.2, 4.5, y=0.0)
    x0 = 2.2
    rollers(left, x0, w, y=0.0)
    mass(left, x0, 0.22, w=w, h=h, label="$m$")
    spring(left, (0.2, 1.42), (x0, 1.42), coils=4)
    left.text(1.2, 1.72, "$k$, $k_3$", ha="center", va="bottom", fontsize=TEXT)
    dashpot(left, (0.2, 0.74), (x0, 0.74))
    left.text(1.2, 0.5, "$c$", ha="center", va="top", fontsize=TEXT)
    drive(left, (x0 + w, 0.6), 0.9, label=r"$F_0\cos\omega t$", gap=0.05)
    coordinate(left, (x0, 2.15), 0.7, label="$x$")

    blank(middle, "free-body diagram", "free-body diagram", xlim=(-0.1, 4.6), ylim=(-1.0, 2.6))
    x0, y0 = 1.75, 0.2
    mass(middle, x0, y0, w=w, h=h, label="$m$")
    force(middle, (x0, 1.3), (x0 - 1.0, 1.3), label="$kx + k_3x^3$", at=(x0 - 0.05, 1.42), ha="right", va="bottom")
    force(middle, (x0, 0.55), (x0 - 1.0, 0.55), label=r"$c\dot x$", at=(x0 - 0.5, 0.43), va="top")
    drive(middle, (x0 + w, 0.75), 0.9, label=r"$F_0\cos\omega t$", gap=0.05, free_body=True)
    weight_and_support(middle, x0, y0, w=w, inset=0.3, drop=0.85)
    coordinate(middle, (x0, 2.15), 0.7, label="$x$")

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
        f"{words[0].capitalize()}: a mass $m$ on a spring ($k$, $k_3$) and a dashpot $c$, driven "
        r"by $F_0\cos\omega t$; $x$ in blue. "
        f"{words[1].capitalize()}: its free-body diagram: $kx + k_3x^3$, $c\\dot x$, $F_0\\cos\\omega t$, "
        "$mg$ and $N$ in vermillion. "
        f"{words[2].capitalize()}: the restoring force $F/(kx_0)$ against $x/x_0$, hardening ($k_3 > 0$, "
        f"{colours['hardening']}), linear ($k_3 = 0$, {colours['linear']}) and softening ($k_3 < 0$, "
        f"{colours['softening']})."
    )
    remark = (
        "The oscillator's quantities are in SI units: $m$ in kg, the linear stiffness $k$ in N/m, the cubic stiffness "
        "$k_3$ in N/m³, $c$ in N s/m, the drive in N with $\\omega$ in rad/s and $t$ in s; $x$ (m) is measured from "
        "the relaxed spring. In the free-body diagram, whose arrows follow Newton's form (each force as it acts for "
        "positive $x$ and $\\dot x$, the inertia term $m\\ddot x$ being their sum and so not drawn), the weight $mg$ "
        "and the normal force $N$ balance. The restoring force $F = kx + k_3x^3$ (N) is scaled by "
        "$x_0 = \\sqrt{k/|k_3|}$ (m), where the cubic term equals the linear one: the hardening spring stiffens, "
        "the softening spring weakens, loses all stiffness at $x_0/\\sqrt{3}$ and no longer restores beyond $x_0$, "
        "and the linear spring lies between them."
    )
    alt = (
        "A mass on rollers tied to a wall by a spring and a dashpot and driven by a sinusoidal force, its free-body "
        "diagram, and the restoring force against displacement: a straight line for the linear spring, a curve "
        "bending up for the hardening spring and one bending back to zero for the softening spring."
    )
    return Captioned(fig, caption, "fig-schematic-duffing", alt, remark=remark)
