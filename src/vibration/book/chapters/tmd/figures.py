r"""Chapter 8's figures, each a function of a :class:`~vibration.book.chapters.tmd.study.TMDStudy` returning a
:class:`~vibration.book.presentation.captions.Captioned` figure.

Each caption is built from the figure itself (its panel layout through
:func:`~vibration.book.presentation.captions.panel_words`) and from the study's numbers; curves that
coincide are found numerically (:func:`coinciding`) and said to coincide. The tunings keep the book's
visual language (:func:`~vibration.book.presentation.style.case_style`): the primary without absorber is the
paper's nominal damping (blue), Den Hartog's rule orange, the closed-form H∞ optimum of an undamped
primary black dashed (a closed-form optimum), the H2 tunings sky blue dash-dot, the H∞ optimum for
the actual damping purple and the robust min-max design green dashed.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.tmd.designs import CLOSED, DEN_HARTOG, OPTIMA, TUNINGS
from vibration.book.chapters.tmd.digits import sig
from vibration.book.chapters.tmd.study import TMDStudy, band_top
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.style import OKABE_ITO, case_style, figure, place_legend
from vibration.physics.tmd import ground_acceleration_load, tmd_fixed_points, tmd_magnification

__all__ = [
    "building_frf_figure",
    "building_ground_figure",
    "coinciding",
    "fixed_points_figure",
    "magnification_figure",
    "modes_figure",
    "robustness_figure",
    "time_response_figure",
]

#: Curves closer than this (largest relative difference) are said to coincide, 1.
COINCIDE = 0.01
GREY = OKABE_ITO["grey"]
R_WINDOW = (0.6, 1.4)
MAG_LABEL = r"$|X_p|\,/\,(F_0/k_p)$"
R_LABEL = r"frequency ratio $r = \omega/\omega_p$"


def coinciding(curves: dict[str, np.ndarray], rtol: float = COINCIDE) -> list[tuple[str, str, float]]:
    """Pairs of curves (same abscissae) whose largest relative difference is below ``rtol``, with that difference.

    >>> x = np.linspace(1.0, 2.0, 5)
    >>> [(a, b, round(d, 6)) for a, b, d in coinciding({"a": x, "b": 1.001 * x, "c": 2 * x})]
    [('a', 'b', 0.000999)]
    """
    names = list(curves)
    out = []
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            ya, yb = np.asarray(curves[a], float), np.asarray(curves[b], float)
            ok = np.isfinite(ya) & np.isfinite(yb) & (yb != 0)
            if ok.any():
                d = float(np.max(np.abs(ya[ok] / yb[ok] - 1.0)))
                if d < rtol:
                    out.append((a, b, d))
    return out


def _cap(word: str) -> str:
    return word[:1].upper() + word[1:]


def _groups(fig) -> str:
    """'Left, for an undamped primary: Den Hartog's rule (orange), ... Right, optima for the actual damping: ...'."""
    w = panel_words(fig)
    heads = ("for an undamped primary", "optima for the actual damping")
    return " ".join(
        f"{_cap(w[i])}, {heads[i]}: " + ", ".join(f"{n.curve} ({n.look})" for n in g) + "."
        for i, g in enumerate((CLOSED, OPTIMA))
    )


def _coincidences(curves: dict[str, np.ndarray]) -> str:
    """'The curves of Den Hartog's rule and the closed-form H∞ optimum coincide to within 0.02 %. ' per coinciding
    pair of a group (the two panels), or ''."""
    pairs = [p for g in (CLOSED, OPTIMA) for p in coinciding({n: curves[n] for n in g})]
    within = "The curves of {} and {} coincide to within {} %. "
    return "".join(within.format(a.noun, b.noun, sig(max(100 * d, 1e-3), 1)) for a, b, d in pairs)


# ----------------------------------------------------------------------------- the absorber


def fixed_points_figure(st: TMDStudy) -> Captioned:
    """Undamped primary, Den Hartog's tuning: the limits of the absorber damping define P and Q (left);
    every finite damping passes through them (right)."""
    mu = st.mu
    t = st.tunings[mu][DEN_HARTOG]
    r = np.linspace(*R_WINDOW, 4001)
    rp, hp = tmd_fixed_points(mu, t.f)
    top = 2.2 * float(hp.max())
    fig, (left, right) = figure(1, 2, height=3.3, sharey=True)

    def draw(ax, y, **kw):
        ax.plot(r, np.where(y > top, np.nan, y), **kw)

    draw(left, tmd_magnification(mu, t.f, 0.0, r=r), color=GREY, linestyle="--", label=r"$\zeta_a = 0$")
    locked = np.abs(1.0 / (1.0 - (1.0 + mu) * r * r))
    draw(left, locked, color="black", linestyle=":", label=r"$\zeta_a \to \infty$")
    dampings = {"low": t.zeta_a / 3, "Den Hartog": t.zeta_a, "high": 3 * t.zeta_a}
    styles = {"low": dict(color=GREY, linestyle="-."), "Den Hartog": dict(case_style("Den Hartog"), lw=2.0),
              "high": dict(color=GREY, linestyle="--")}  # fmt: skip
    through = True
    for key, za in dampings.items():
        draw(right, tmd_magnification(mu, t.f, za, r=r), label=rf"$\zeta_a$ = {sig(za)}", **styles[key])
        through &= bool(np.allclose(tmd_magnification(mu, t.f, za, r=rp), hp, rtol=1e-9))
    for ax in (left, right):
        ax.plot(rp, hp, "o", color="black", ms=5, label="fixed points P, Q", zorder=5)
        ax.set_xlim(*R_WINDOW)
        ax.set_ylim(0.0, top)
        ax.set_xlabel(R_LABEL)
        place_legend(ax, fontsize=7.5)
    left.set_ylabel(MAG_LABEL)
    left.set_title("limits of the absorber damping")
    right.set_title("finite absorber dampings")
    w = panel_words(fig)
    equal = math.isclose(float(hp[0]), float(hp[1]), rel_tol=1e-9)
    caption = (
        f"Undamped primary ($\\zeta_p = 0$) with an absorber of μ = {mu:g} at Den Hartog's tuning $f = 1/(1+\\mu)$ = "
        f"{sig(t.f)}. {_cap(w[0])}: the limits of the absorber damping, $\\zeta_a = 0$ (grey dashed) and "
        f"$\\zeta_a \\to \\infty$ (black dotted), and the fixed points P and Q (black dots). {_cap(w[1])}: "
        f"$\\zeta_a$ = {sig(dampings['low'])} (grey dash-dot), Den Hartog's {sig(t.zeta_a)} (orange) and "
        f"{sig(dampings['high'])} (grey dashed)."
    )
    remark = (
        "The two limits cross at P and Q; the three finite dampings "
        + ("all pass" if through else "do not all pass")
        + " through them. "
        + (
            f"Den Hartog's tuning makes P and Q equally high, {sig(float(hp[0]))}."
            if equal
            else f"P and Q have the heights {sig(float(hp[0]))} and {sig(float(hp[1]))}."
        )
    )
    alt = (
        "Magnification of an undamped primary against the frequency ratio for several absorber dampings: "
        "every curve crosses the same two fixed points."
    )
    return Captioned(fig, caption, "fig-tmd-fixed", alt, remark=remark)


def _actual_tunings(st: TMDStudy) -> dict:
    return {n: st.scores[n].tuning for n in TUNINGS}


def magnification_figure(st: TMDStudy) -> Captioned:
    """The primary without and with each tuning: undamped-primary rules (left), optima (right)."""
    r = np.linspace(*R_WINDOW, 4001)
    tun = _actual_tunings(st)
    with np.errstate(divide="ignore"):
        bare = 1.0 / np.hypot((1 - r) * (1 + r), 2 * st.zeta_p * r)
    curves = {n: tmd_magnification(st.mu, tun[n].f, tun[n].zeta_a, r=r, zeta_p=st.zeta_p) for n in TUNINGS}
    peak = max(float(np.max(c)) for c in curves.values())
    top = 1.75 * min(float(np.max(bare)), 2.5 * peak)  # room above the curves for the legends
    fig, axes = figure(1, 2, height=3.4, sharey=True)
    groups = (CLOSED, OPTIMA)
    for ax, group in zip(axes, groups, strict=True):
        ax.plot(r, np.where(bare > top, np.nan, bare), label="no absorber", **case_style("c_nominal"))
        for n in group:
            ax.plot(r, curves[n], label=n.legend, **case_style(n.case))
        ax.axvline(st.r_force, color=GREY, linestyle=":", lw=0.9, label=rf"paper's $\omega$ = {st.omega_res:g} rad/s")
        ax.set_xlim(*R_WINDOW)
        ax.set_ylim(0.0, top)
        ax.set_xlabel(R_LABEL)
        place_legend(ax, fontsize=7.5)
    axes[0].set_ylabel(MAG_LABEL)
    axes[0].set_title("tunings for an undamped primary")
    axes[1].set_title(r"optima for the actual $\zeta_p$")
    caption = (
        f"Magnification of the primary ($\\zeta_p$ = {sig(st.zeta_p, 3)}) against $r = \\omega/\\omega_p$, without "
        f"absorber (blue) and with absorbers of μ = {st.mu:g}; grey dotted: the paper's forcing frequency. "
        + _groups(fig)
    )
    peaks = [st.scores[n].nominal_peak for n in TUNINGS]
    lowered = all(p < st.bare_peak for p in peaks)
    remark = (
        f"The paper's forcing frequency lies at $r$ = {sig(st.r_force)}. "
        + _coincidences(curves)
        + (
            f"Every absorber lowers the resonance peak, from {sig(st.bare_peak)} to between {sig(min(peaks))} and "
            f"{sig(max(peaks))}."
            if lowered
            else f"Not every absorber lowers the resonance peak of {sig(st.bare_peak)}: the peaks with an absorber run "
            f"from {sig(min(peaks))} to {sig(max(peaks))}."
        )
    )
    alt = (
        "Magnification of the primary against the frequency ratio without and with six absorber tunings in two "
        "plots: "
        + (
            f"every absorber lowers the resonance peak, from {sig(st.bare_peak)} to between {sig(min(peaks))} and "
            f"{sig(max(peaks))}."
            if lowered
            else "not every absorber lowers the resonance peak."
        )
    )
    return Captioned(fig, caption, "fig-tmd-magnification", alt, remark=remark)


def time_response_figure(st: TMDStudy) -> Captioned:
    """Primary displacement from rest at the paper's forcing frequency, with and without the absorber."""
    fig, ax = figure(height=3.2)
    bare, hinf = case_style("c_nominal"), case_style("H∞")
    ax.plot(st.t, st.x_without, lw=0.9, label="without absorber", **bare)
    ax.plot(st.t, st.x_with, lw=0.9, label=rf"with the H$\infty$ optimum, $\mu$ = {st.mu:g}", **hinf)
    for a, style in ((st.amp_without, bare), (st.amp_with, hinf)):
        for s in (1, -1):
            ax.axhline(s * a, color=style["color"], linestyle="--", lw=0.8)
    ax.set_xlim(0, st.t_end)
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"primary displacement $x_p$ (m)")
    place_legend(ax, outside=True)
    caption = (
        f"Primary displacement from rest under $F_0 \\sin \\omega t$ with ω = {st.omega_res:g} rad/s and "
        f"$F_0$ = {st.F0:g} N: without absorber (blue) and with the H∞ optimum's absorber of μ = {st.mu:g} (purple); "
        f"the dashed lines mark ± each steady amplitude, {sig(st.amp_without)} m and {sig(st.amp_with)} m."
    )
    alt = (
        "Displacement of the primary against time from rest at the paper's forcing frequency: with the absorber "
        f"it settles at an amplitude {sig(100 * (1 - st.amp_with / st.amp_without), 3)} per cent "
        f"{'below' if st.amp_with < st.amp_without else 'above'} the one without."
    )
    return Captioned(fig, caption, "fig-tmd-time", alt)


def robustness_figure(st: TMDStudy) -> Captioned:
    """Peak magnification against the error of the primary's stiffness: undamped-primary rules (left), optima."""
    fig, axes = figure(1, 2, height=3.3, sharey=True)
    e = 100 * st.eps
    groups = (CLOSED, OPTIMA)
    for ax, group in zip(axes, groups, strict=True):
        for n in group:
            ax.plot(e, st.robust[n], label=n.legend, **case_style(n.case))
        ax.set_xlabel(r"error of the primary's stiffness $\Delta k_p/k_p$ (%)")
        if e[-1] > e[0]:
            ax.set_xlim(e[0], e[-1])
        place_legend(ax, fontsize=7.5)
    axes[0].set_ylabel(r"peak " + MAG_LABEL)
    axes[0].set_title("tunings for an undamped primary")
    axes[1].set_title(r"optima for the actual $\zeta_p$")
    best = min(TUNINGS, key=lambda n: st.scores[n].worst_peak)
    w = panel_words(fig)
    caption = (
        f"Largest magnification against the error of the primary's stiffness over ±{100 * st.mistuning:g} %, with "
        f"the absorber unchanged (μ = {st.mu:g}, $\\zeta_p$ = {sig(st.zeta_p, 3)}). {_cap(w[0])}: the tunings for an "
        f"undamped primary; {w[1]}: the optima for the actual damping. Each tuning keeps its line of "
        "{numref}`fig-tmd-magnification`."
    )
    remark = (
        _coincidences(st.robust)
        + f"Of all six, {best.noun} has the lowest worst peak, {sig(st.scores[best].worst_peak)}."
    )
    spread = {n: float(np.ptp(st.robust[n])) for n in TUNINGS}
    flattest = min(spread, key=spread.get)
    alt = (
        "Peak magnification against the error of the primary's stiffness for six absorber tunings in two plots; "
        f"{flattest.noun} has the flattest curve."
    )
    return Captioned(fig, caption, "fig-tmd-robustness", alt, remark=remark)


# ----------------------------------------------------------------------------- the building


#: Mode shapes drawn, at most (one panel each).
MAX_MODES = 5


def modes_figure(st: TMDStudy) -> Captioned:
    """The building's mode shapes, one panel per mode (at most five), against the floor."""
    b = st.building
    n_show = min(b.n, MAX_MODES)
    floors = np.arange(0, b.n + 1)
    fig, axes = figure(1, n_show, height=3.3, sharey=True, squeeze=False)
    periods = 2 * math.pi / b.natural_frequencies
    for i, ax in enumerate(axes[0]):
        phi = b.modes[:, i] / np.max(np.abs(b.modes[:, i]))
        phi = phi * np.sign(phi[-1]) if phi[-1] != 0 else phi
        ax.axvline(0.0, color=GREY, lw=0.8)
        ax.plot(np.r_[0.0, phi], floors, color="black", marker="o", ms=3.5)
        ax.set_xlim(-1.15, 1.15)
        ax.set_title(f"mode {i + 1}\nT = {sig(periods[i], 3)} s", fontsize=8.5)
        ax.set_xlabel("shape")
    axes[0, 0].set_ylabel("floor (0 = ground)")
    axes[0, 0].set_yticks(floors if b.n <= 10 else floors[:: max(1, b.n // 10)])
    words = panel_words(fig)
    order = "from left to right" if words and words[0] == "left" else "in order"
    which = (
        (f"all {b.n} of its modes" if n_show == b.n else f"its first {n_show} of {b.n} modes")
        if n_show > 1
        else "its only mode"
    )
    caption = (
        f"Mode shapes of the {b.n}-storey shear building, {which}"
        + (f", one panel per mode {order}" if n_show > 1 else "")
        + ", scaled to a largest component of 1 with the roof moving positively (black), against the floor "
        f"(0 = ground); the periods run from {sig(periods[0], 3)} s"
        + (f" to {sig(periods[n_show - 1], 3)} s." if n_show > 1 else ".")
    )
    alt = (
        f"Mode shapes of a {b.n}-storey shear building, one small plot per mode: the first mode moves every floor "
        "the same way, each higher mode adds a change of direction along the height."
    )
    return Captioned(fig, caption, "fig-tmd-modes", alt)


def _roof_frf(st: TMDStudy, ground: bool):
    b, bt = st.building, st.building_tmd
    w1 = b.natural_frequencies[0]
    w = np.linspace(0.3 * w1, min(1.8 * w1, band_top(b)), 3001)
    if ground:
        h0 = np.abs(b.frf(w, ground_acceleration_load(b))[:, -1]) * 1e3  # s² -> mm/(m/s²)
        h1 = np.abs(bt.frf(w, ground_acceleration_load(bt))[:, -2]) * 1e3
    else:
        load = np.zeros(b.n)
        load[-1] = 1.0
        h0 = np.abs(b.frf(w, load)[:, -1]) * 1e6  # m/N -> mm/kN
        h1 = np.abs(bt.frf(w, np.r_[load, 0.0])[:, -2]) * 1e6
    return w / (2 * math.pi), h0, h1


def _building_figure(st: TMDStudy, ground: bool) -> Captioned:
    hz, h0, h1 = _roof_frf(st, ground)
    fig, ax = figure(height=3.2)
    ax.plot(hz, h0, color=GREY, linestyle="-", label="without absorber")
    ax.plot(hz, h1, label=rf"with the roof absorber, $\mu$ = {st.mu_building:g} of the modal mass", **case_style("H∞"))
    ax.set_xlim(hz[0], hz[-1])
    place_legend(ax, outside=True)
    case = st.load_cases[1 if ground else 0]
    before, after = case.scale * case.peak_without, case.scale * case.peak_with
    verb = "falls" if after <= before else "rises"
    if ground:
        ax.set_xlabel(r"frequency of the ground acceleration $f$ (Hz)")
        ax.set_ylabel(r"roof displacement / ground acceleration (mm per m/s$^2$)")
        what = "Roof displacement relative to the ground per unit ground acceleration"
        name, unit = "fig-tmd-building-ground", "mm per m/s²"
    else:
        ax.set_xlabel(r"forcing frequency $f$ (Hz)")
        ax.set_ylabel("roof displacement / roof force (mm/kN)")
        what = "Roof displacement per unit roof force"
        name, unit = "fig-tmd-building-frf", "mm/kN"
    caption = (
        f"{what} near the first mode of the {st.building.n}-storey building, without absorber (grey) and with a "
        f"roof absorber of {st.mu_building:g} of the first modal mass tuned by the H∞ optimum for the mode's "
        f"damping (purple); the largest response {verb} from {sig(before)} to {sig(after)} {unit}."
    )
    alt = (
        f"{what} against frequency near the first mode, without and with the roof absorber: the peak {verb} by "
        f"{sig(100 * abs(case.reduction), 3)} per cent."
    )
    return Captioned(fig, caption, name, alt)


def building_frf_figure(st: TMDStudy) -> Captioned:
    """Roof receptance (roof displacement per roof force) with and without the roof absorber."""
    return _building_figure(st, ground=False)


def building_ground_figure(st: TMDStudy) -> Captioned:
    """Roof displacement relative to the ground per ground acceleration, with and without the roof absorber."""
    return _building_figure(st, ground=True)


#: Storeys the building schematic can draw legibly.
SCHEMATIC_STOREYS = (2, 8)


def building_schematic(st: TMDStudy) -> Captioned:
    """The schematic of this run's shear building: its own number of storeys, drawn with at most eight.

    >>> from vibration.book.chapters.tmd.study import tmd_study
    >>> st = tmd_study(n_storeys=3, n_points=201)
    >>> building_schematic(st).caption.startswith("The 3-storey shear building")
    True
    >>> building_schematic(tmd_study(n_storeys=12, n_points=201)).caption.split(". ")[0]
    'The 12-storey shear building of chapter 8 with its roof absorber (drawn with 8 storeys)'
    """
    from vibration.book.presentation.schematics import shear_building

    n = st.building.n
    low, high = SCHEMATIC_STOREYS
    drawn = min(max(n, low), high)
    cap = shear_building(drawn)
    if drawn == n:
        return cap
    head = f"The {drawn}-storey shear building of chapter 8 with its roof absorber."
    caption = cap.caption.replace(
        head, f"The {n}-storey shear building of chapter 8 with its roof absorber (drawn with {drawn} storeys).", 1
    )
    alt = cap.alt.replace(f"A {drawn}-storey frame", f"A {n}-storey frame (drawn with {drawn} storeys)", 1)
    return Captioned(cap.fig, caption, cap.name, alt, remark=cap.remark)
