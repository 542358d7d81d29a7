"""Figures of chapter 4, each a function of a :class:`FrequencyStudy` returning a :class:`Captioned` figure.

The run's dampings take the book's colours by their place in the list
(:func:`vibration.book.presentation.style.series_style`: the paper's three keep vermillion, blue and green).
Captions name the panels from the figure's layout (:func:`panel_words`) and the colours and line styles
actually drawn; each figure's remark says what it shows (curves that coincide, the largest value, how well a
balance closes)."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.colors import LogNorm

from vibration.book.chapters.frequency_response.study import TOL_CLOSED, FrequencyStudy
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.narrative import listing
from vibration.book.presentation.numbers import sig as num
from vibration.book.presentation.style import COLOUR_WORDS, OKABE_ITO, case_style, figure, place_legend, series_style
from vibration.physics.exact import steady_state
from vibration.physics.model import SineForce

TWO_PI = 2.0 * math.pi

#: Two curves closer than this (largest relative difference) are said to coincide.
COINCIDE = 0.01

#: The word a caption uses for each colour of the book's palette (the palette's own words).
COLOUR_WORD = COLOUR_WORDS

#: Colours of the energy terms (not cases of the book): black, the damper's grey, the stored energy's sky blue.
ENERGY_STYLE = {
    "W": {"color": OKABE_ITO["black"], "linestyle": "-"},
    "D": {"color": OKABE_ITO["black"], "linestyle": "--"},
    "E": {"color": OKABE_ITO["grey"], "linestyle": "-"},
}


def style_of(case) -> dict:
    """A damping's colour: its place in the list, or the nominal blue when the list leaves the nominal damping out."""
    return series_style(case.case) if case.case >= 0 else case_style("c_nominal")


def _hz_axis(ax) -> None:
    """A top axis in Hz on an axis whose x is the angular frequency in rad/s."""
    sec = ax.secondary_xaxis("top", functions=(lambda w: w / TWO_PI, lambda f: f * TWO_PI))
    sec.set_xlabel(r"forcing frequency $f$ (Hz)")


def coinciding(study: FrequencyStudy) -> list[tuple[str, str]]:
    """Pairs of drawn dampings whose magnification curves agree within :data:`COINCIDE` everywhere."""
    drawn = [c for c in study.cases if c.steady]
    out = []
    for i, a in enumerate(drawn):
        for b in drawn[i + 1 :]:
            with np.errstate(divide="ignore", invalid="ignore"):
                rel = np.max(np.abs(a.magnification / b.magnification - 1))
            if np.isfinite(rel) and rel < COINCIDE:
                out.append((a.name, b.name))
    return out


def _marks(study: FrequencyStudy):
    """The operating points with a steady state: the reference run (nominal damping at ω_ref) and each damping
    at ω_res, as (name, omega rad/s, c N s/m, magnification, phase rad)."""
    p, out = study.params, []
    points = [("reference", p.omega_ref, study.nominal.osc)] + [(c.name, p.omega_res, c.osc) for c in study.cases]
    for name, w, osc in points:
        if osc.c <= 0:
            continue
        ss = steady_state(osc, SineForce(F0=p.F0, omega=w))
        if math.isfinite(ss.magnification):
            out.append((name, w, osc.c, ss.magnification, ss.phase))
    return out


def _dampings_words(study: FrequencyStudy, drawn) -> str:
    return listing([f"damping {c.name} ({COLOUR_WORD[style_of(c)['color']]})" for c in drawn])


def response_figure(study: FrequencyStudy) -> Captioned:
    """Magnification (log-log) and phase lag against the forcing frequency for the run's dampings."""
    fig, (ax_m, ax_p) = figure(2, 1, height=6.2, sharex=True)
    drawn = [c for c in study.cases if c.steady]
    for c in drawn:
        style = style_of(c)
        label = f"$c$ = {num(c.c)} N s/m"
        ax_m.loglog(study.omegas, c.magnification, label=label, **style)
        ax_p.semilogx(study.omegas, np.degrees(c.phase), label=label, **style)
    marks = _marks(study)
    for name, w, _c, mag, ph in marks:
        ax_m.plot(w, mag, "o", ms=6, mfc="none", mew=1.2, color=OKABE_ITO["black"])
        ax_m.annotate(name, (w, mag), textcoords="offset points", xytext=(6, 4), fontsize=8)
        ax_p.plot(w, math.degrees(ph), "o", ms=6, mfc="none", mew=1.2, color=OKABE_ITO["black"])
    for ax in (ax_m, ax_p):
        ax.axvline(study.omega_n, color=OKABE_ITO["grey"], lw=0.8, ls=":")
    lo, hi = ax_m.get_ylim()
    ax_m.set_ylim(lo, hi * 4.0)  # room above the highest peak for its label
    ax_m.set_ylabel(r"magnification $|X|\,/\,(F_0/k)$")
    ax_p.set_ylabel(r"phase lag $\varphi$ (deg)")
    ax_p.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
    ax_p.set_yticks([0, 45, 90, 135, 180])
    _hz_axis(ax_m)
    place_legend(ax_p)
    top, bottom = panel_words(fig)
    caption = (
        f"Magnification ({top}, logarithmic axes; forcing frequency in rad/s below, Hz above) and phase lag "
        f"({bottom}) of the {_dampings_words(study, drawn)}; the natural frequency "
        f"$\\omega_n$ = {num(study.omega_n)} rad/s dotted; the reference run and each damping at the resonant forcing "
        "circled."
    )
    remark = " ".join(f"The {a} and {b} curves coincide to within 1 %." for a, b in coinciding(study))
    missing = [c for c in study.cases if not c.steady]
    if missing:
        caption += f" The damping {listing([c.name for c in missing])} has no steady state and is not drawn."
    peaks = [c for c in drawn if c.omega_peak is not None and math.isfinite(c.M_peak or math.inf)]
    alt = (
        f"Two plots against forcing frequency: the magnification of {len(drawn)} dampings on log axes"
        + (
            f", peaking near {num(study.omega_n, 3)} radians per second at up to {num(max(c.M_peak for c in peaks), 3)}"
            if peaks
            else ""
        )
        + ", and the phase lag rising from 0 to 180 degrees through 90 degrees at the natural frequency."
    )
    return Captioned(fig, caption, "fig-frequency-response", alt, remark=remark)


def decomposition_figure(study: FrequencyStudy) -> Captioned:
    """The resonance case from rest (top, with its steady state) and its transient (bottom)."""
    res = study.resonance
    case = study.nominal
    d = study.decomposition
    t_end = study.params.t_end
    fig, (ax, ax_h) = figure(2, 1, height=4.8, sharex=True)
    ax.plot(study.t, study.total.x, lw=1.0, label=r"total $x(t)$", **style_of(case))
    ax.plot(study.t, study.steady, lw=0.8, label=r"steady state $x_\mathrm{ss}(t)$", **case_style("exact"))
    ax_h.plot(study.t, study.transient.x, lw=0.9, color=OKABE_ITO["grey"], linestyle="-")
    settled = d.t_s <= t_end
    if settled:
        for a in (ax, ax_h):
            a.axvline(d.t_s, color=OKABE_ITO["grey"], lw=0.8, ls=":")
    ax.set_ylabel(r"displacement $x$ (m)")
    ax_h.set_ylabel(r"transient $x_h = x - x_\mathrm{ss}$ (m)")
    ax_h.set_xlabel(r"time $t$ (s)")
    lo, hi = ax.get_ylim()
    ax.set_ylim(lo, hi + 0.4 * (hi - lo))
    place_legend(ax, ncols=2)
    top, bottom = panel_words(fig)
    colour = COLOUR_WORD[style_of(case)["color"]]
    remark = (
        "The total displacement and its steady state coincide to within 2 % of the steady amplitude from the "
        f"settling time t = {num(d.t_s, 3)} s on."
        if settled
        else "The total displacement and its steady state still differ by more than 2 % of the steady amplitude at "
        f"the end of the {num(t_end)} s window."
    )
    caption = (
        f"The resonance case (c = {num(res.oscillator.c)} N s/m, ω = {num(res.force.omega)} rad/s) from rest, "
        f"exactly. {top.capitalize()}: the total displacement ({colour}) and its steady state (black, dashed)"
        + (f", the settling time t = {num(d.t_s, 3)} s dotted" if settled else "")
        + f". {bottom.capitalize()}: the transient (grey), computed separately as the free motion from what the "
        "steady state leaves over at t = 0."
    )
    alt = (
        f"Displacement against time for {num(t_end)} s: an oscillation growing from rest onto a steady sine of "
        f"amplitude {num(d.X, 3)} m; below, the transient starting at {num(d.x_h0, 3)} m and decaying."
    )
    return Captioned(fig, caption, "fig-frequency-decomposition", alt, remark=remark)


def energy_figure(study: FrequencyStudy) -> Captioned:
    """Work, dissipation and stored energy of the exact resonance case (top), and the residual (bottom)."""
    eb = study.energy[0][1]
    t = study.energy_t
    fig, (ax, ax_r) = figure(2, 1, height=5.0, sharex=True, gridspec_kw={"height_ratios": (2.2, 1.0)})
    ax.plot(t, eb.work, label=r"work of the force $W$", **ENERGY_STYLE["W"])
    ax.plot(t, eb.dissipated, label=r"dissipated by the damper $D$", **ENERGY_STYLE["D"])
    ax.plot(t, eb.stored, label=r"stored $\Delta E$ (kinetic + potential)", **ENERGY_STYLE["E"])
    ax.set_ylabel("energy (J)")
    place_legend(ax)
    ax_r.plot(t, eb.residual, color=OKABE_ITO["grey"], lw=0.8)
    ax_r.set_ylabel(r"$W - D - \Delta E$ (J)")
    ax_r.set_xlabel(r"time $t$ (s)")
    top, bottom = panel_words(fig)
    w_max = float(np.max(np.abs(eb.work)))
    gap = float(np.max(np.abs(eb.work - eb.dissipated))) / w_max if w_max > 0 else 0.0
    together = (
        "The work W and the dissipation D coincide to within 1 % of the largest work"
        if gap < COINCIDE
        else f"The work W and the dissipation D part by up to {num(100 * gap, 2)} % of the largest work, the energy "
        "stored in the motion"
    )
    rel = study.energy_residual(0)
    residual = (
        f"stays below {num(TOL_CLOSED)} of the largest work, quadrature error only"
        if rel < TOL_CLOSED
        else f"reaches {num(rel, 2)} of the largest work"
    )
    caption = (
        f"Energy of the exact resonance case (c = {num(study.resonance.oscillator.c)} N s/m). {top.capitalize()}: "
        "work of the force W (black), energy dissipated by the damper D (black, dashed) and change of stored energy "
        f"ΔE (grey). {bottom.capitalize()}: the residual W − D − ΔE."
    )
    remark = f"{together}; the residual {residual}."
    alt = (
        f"Energy against time: the work and the dissipation grow almost linearly to about {num(w_max, 3)} J while "
        "the stored energy levels off; below, a residual many orders of magnitude smaller."
    )
    return Captioned(fig, caption, "fig-frequency-energy", alt, remark=remark)


def design_figure(study: FrequencyStudy) -> Captioned:
    """Heat map of the window's peak |x| over forcing frequency and damping, the paper's scenarios circled."""
    dm = study.design
    fig, ax = figure(1, 1, height=4.6)
    mesh = ax.pcolormesh(dm.omegas, dm.dampings, dm.peaks, norm=LogNorm(), shading="nearest", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=r"peak $|x|$ in the window (m)")
    ax.set_yscale("log")
    ax.grid(False)
    marks = [
        (n, w, c) for n, w, c, _m, _p in _marks(study) if dm.dampings[0] <= c <= dm.dampings[-1] and w <= dm.omegas[-1]
    ]
    for name, w, c in marks:
        ax.plot(w, c, "o", mfc="none", mec="w", ms=9, mew=1.5)
        ax.annotate(name, (w, c), textcoords="offset points", xytext=(8, 4), color="w", fontsize=8)
    shown = dm.omegas[0] <= study.omega_n <= dm.omegas[-1]
    if shown:
        ax.axvline(study.omega_n, color="w", lw=0.6, ls=":")
    ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
    ax.set_ylabel(r"damping coefficient $c$ (N s/m)")
    _hz_axis(ax)
    w, c, peak = dm.largest
    caption = (
        f"Largest displacement in the {num(study.params.t_end)} s window from rest on a {dm.dampings.size} × "
        f"{dm.omegas.size} grid of forcing frequency and damping (logarithmic damping axis and colour scale)"
        + (f"; the natural frequency $\\omega_n$ = {num(study.omega_n)} rad/s dotted" if shown else "")
        + ("; the operating points inside the grid circled" if marks else "")
        + "."
    )
    remark = f"The largest displacement on the grid, {num(peak)} m, is at ω = {num(w)} rad/s and c = {num(c, 3)} N s/m."
    alt = (
        "Colour map of peak displacement over forcing frequency and damping: a bright narrow ridge at the natural "
        "frequency for light damping that widens and fades as the damping grows."
    )
    return Captioned(fig, caption, "fig-frequency-design", alt, remark=remark)
