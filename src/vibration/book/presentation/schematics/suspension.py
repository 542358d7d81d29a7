"""Chapter 7's suspension with its two devices: the ideal skyhook and the semi-active damper."""

from __future__ import annotations

import numpy as np

from ..captions import Captioned, panel_words
from ..style import OKABE_ITO, case_style, figure
from .kit import TEXT, blank, coordinate, dashpot, force, ground, mass, spring


def _suspension(ax, device: str) -> None:
    """Chapter 7's suspension: base plate, spring k and damper c to the mass, and the device (``"sky"`` or
    ``"semi"``)."""
    bw, bh, my, mw, mh = 2.4, 0.3, 1.7, 1.8, 0.8
    mass(ax, -0.5 * bw, 0.0, w=bw, h=bh)
    coordinate(ax, (0.5 * bw + 0.25, 0.5 * bh), 0.55, label="$y(t)$", vertical=True)
    xs = (-0.6, 0.0, 0.6) if device == "semi" else (-0.4, 0.4)
    spring(ax, (xs[0], bh), (xs[0], my), width=0.24)
    ax.text(xs[0] - 0.25, 0.5 * (bh + my), "$k$", ha="right", va="center", fontsize=TEXT)
    dashpot(ax, (xs[1], bh), (xs[1], my), width=0.26)
    if device == "semi":
        ax.text(xs[1] - 0.17, 0.5 * (bh + my) + 0.12, "$c$", ha="right", va="bottom", fontsize=TEXT)
        col = case_style("semi-active")["color"]
        dashpot(ax, (xs[2], bh), (xs[2], my), width=0.26, color=col, variable=True)
        ax.text(xs[2] + 0.3, 0.5 * (bh + my), r"$c_\mathrm{sa}$", ha="left", va="center", fontsize=TEXT, color=col)
    else:
        ax.text(xs[1] + 0.25, 0.5 * (bh + my), "$c$", ha="left", va="center", fontsize=TEXT)
    mass(ax, -0.5 * mw, my, w=mw, h=mh, label="$m$")
    coordinate(ax, (0.5 * mw + 0.25, my + 0.5 * mh), 0.55, label="$x$", vertical=True)
    if device == "sky":
        col = case_style("skyhook")["color"]
        sky = my + mh + 1.0
        ground(ax, -1.0, 1.0, y=sky, below=False, depth=0.18)
        dashpot(ax, (0.0, sky), (0.0, my + mh), width=0.26, color=col)
        ax.text(0.25, my + mh + 0.5, r"$c_\mathrm{sky}$", ha="left", va="center", fontsize=TEXT, color=col)
        ax.text(-1.1, sky + 0.09, "sky", ha="right", va="center", fontsize=TEXT)


def skyhook() -> Captioned:
    """The ideal skyhook (a damper to an inertial reference) beside the realisable semi-active damper between body and
    base, the body's free-body diagram and the forces a semi-active damper can produce."""
    fig, axes = figure(2, 2, height=5.6)
    (sky_ax, semi_ax), (fbd, fmap) = axes
    box = {"xlim": (-2.0, 2.2), "ylim": (-0.15, 3.75)}
    blank(sky_ax, "schematic", "ideal skyhook", **box)
    _suspension(sky_ax, "sky")
    blank(semi_ax, "schematic", "semi-active damper", **box)
    _suspension(semi_ax, "semi")

    blank(fbd, "free-body diagram", "free-body diagram of the mass", xlim=(-2.0, 2.2), ylim=(-0.1, 3.3))
    mw, mh, my = 1.8, 0.8, 1.25
    mass(fbd, -0.5 * mw, my, w=mw, h=mh, label="$m$")
    force(fbd, (-0.45, my), (-0.45, my - 0.9), label="$k(x - y)$", at=(-0.55, my - 0.45), ha="right")
    force(fbd, (0.45, my), (0.45, my - 0.9), label=r"$c(\dot x - \dot y)$", at=(0.55, my - 0.45), ha="left")
    force(fbd, (0.0, my + mh), (0.0, my + mh + 0.8), label="$f$", at=(0.12, my + mh + 0.45), ha="left")
    coordinate(fbd, (0.5 * mw + 0.25, my + 0.5 * mh), 0.55, label="$x$", vertical=True)

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
    fmap.text(-0.04, 0.95, "dissipative", ha="right", va="top", fontsize=TEXT)
    fmap.text(0.04, -0.95, "dissipative", ha="left", va="bottom", fontsize=TEXT)
    fmap.text(0.5, 0.45, "needs power", ha="center", va="center", fontsize=TEXT)
    fmap.text(-0.5, -0.45, "needs power", ha="center", va="center", fontsize=TEXT)
    fmap.text(0.98, 0.04, r"$v_\mathrm{rel}$", ha="right", va="bottom", fontsize=TEXT)
    fmap.text(0.04, 0.98, "$f$", ha="left", va="top", fontsize=TEXT)
    fmap.set_xlim(-1.0, 1.0)
    fmap.set_ylim(-1.0, 1.0)
    fmap.set_xticks([])
    fmap.set_yticks([])
    fmap.grid(False)
    for side in ("left", "bottom"):
        fmap.spines[side].set_position("zero")

    words = dict(zip(("sky", "semi", "fbd", "map"), panel_words(fig), strict=True))
    caption = (
        "Chapter 7's suspension, $m\\ddot x + c(\\dot x - \\dot y) + k(x - y) = f$. "
        f"{words['sky'].capitalize()}: a skyhook damper $c_\\mathrm{{sky}}$ (green) ties the mass $m$, on $k$ "
        "and $c$ over the base $y(t)$, to the sky; $x$ in blue. "
        f"{words['semi'].capitalize()}: a semi-active damper $c_\\mathrm{{sa}}$ (purple) instead. "
        f"{words['fbd'].capitalize()}: the mass's forces $k(x - y)$, $c(\\dot x - \\dot y)$ and $f$ (vermillion). "
        f"{words['map'].capitalize()}: what a semi-active damper can produce, $f$ against $v_\\mathrm{{rel}}$."
    )
    remark = (
        "The skyhook is ideal, its sky (hatched) an inertial reference. With $m$ in kg, $k$ in N/m and the damping "
        "coefficients in N s/m, the base moves as $y(t)$ and the mass as $x$ (m), both from the static equilibrium; "
        "forces are in N. The semi-active coefficient $c_\\mathrm{sa}$, adjustable (the arrow through it), is set "
        "between $c_\\mathrm{min}$ and $c_\\mathrm{max}$ and acts between body and base in the skyhook's place. "
        "The device force $f$ is drawn positive, as Newton's form draws every force for positive coordinates and "
        "rates: $f = -c_\\mathrm{sky}\\dot x$ for the skyhook, $f = -c_\\mathrm{sa}(\\dot x - \\dot y)$ for the "
        "semi-active damper; the weight and the static spring force balance and are left out. The force map, a sketch "
        "without scale, plots $f$ against the relative velocity $v_\\mathrm{rel} = \\dot x - \\dot y$ (m/s). In the "
        "grey quadrants $f\\,v_\\mathrm{rel} < 0$ and the device dissipates; a semi-active damper is confined to "
        "the purple sector between the dashed lines $f = -c_\\mathrm{min}v_\\mathrm{rel}$ (the shallower) and "
        "$f = -c_\\mathrm{max}v_\\mathrm{rel}$ (the steeper). The skyhook force follows $\\dot x$, not "
        "$v_\\mathrm{rel}$, so it also falls in the quadrants that need power, where only an actuator can produce "
        "it."
    )
    alt = (
        "A mass on a spring and a damper over a moving base, once with an extra damper up to a fixed sky and once "
        "with an adjustable damper beside the passive one, then the mass alone with its forces, and a plot of force "
        "against relative velocity in which a semi-active damper is confined to a sector of the two dissipative "
        "quadrants."
    )
    return Captioned(fig, caption, "fig-schematic-skyhook", alt, remark=remark)
