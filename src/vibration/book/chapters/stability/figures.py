"""Figures of the stability chapter, each a function of a :class:`StabilityStudy` returning :class:`Captioned`.

The book's visual language: the paper's three dampings take their colour, line style and marker from
:func:`vibration.book.presentation.style.case_style` (``c_low``, ``c_nominal``, ``c_high``) in every figure;
closed forms (the envelopes) are the ``exact`` case (black dashed) and the settling-optimal damping the
``optimum`` case (black dotted, star). The undamped case and the flutter model, which only this chapter
draws, are grey and reddish purple (Okabe–Ito colours no damping case uses). Captions are built from
the figure's own layout (:func:`~vibration.book.presentation.captions.panel_words`) and the study's numbers,
and say when two curves coincide (checked numerically, :func:`coinciding`).
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib import colormaps
from matplotlib.colors import ListedColormap, LogNorm
from matplotlib.lines import Line2D
from matplotlib.ticker import FuncFormatter

from vibration.book.chapters.stability.study import BAND, GROWTH_CASES, LABELS, MAX_GROWTH, StabilityStudy
from vibration.book.chapters.stability.words import WN, ZSTAR, join, num
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.style import OKABE_ITO, case_style, figure, place_legend
from vibration.physics.model import Oscillator
from vibration.physics.stability import (
    damper_load,
    design_metrics,
    isolation_frequency,
    poles,
    stability_class,
    step_metrics,
    step_response,
    transmissibility,
)

#: The book's case of each of the paper's dampings.
CASE = {"low": "c_low", "nominal": "c_nominal", "high": "c_high"}
#: Cases only this chapter draws: no damping and the flutter model (negative damping).
OTHER = {
    "undamped": {"color": OKABE_ITO["grey"], "linestyle": "-", "marker": "X"},
    "unstable": {"color": OKABE_ITO["reddish purple"], "linestyle": "-", "marker": "P"},
}
#: Grey of reference lines and of the pole locus (a grey the caption check knows).
REF_GREY, LOCUS_GREY = "#666666", "#bbbbbb"
#: Two curves whose largest pointwise difference is below this fraction of the larger "coincide".
COINCIDE = 0.01


def look(key: str, marker: bool = False) -> dict:
    """Colour, line style (and marker) of a damping of the run or of ``undamped``/``unstable``/``optimum``."""
    if key in CASE:
        return case_style(CASE[key], marker)
    if key == "optimum":
        return case_style("optimum", marker)
    style = OTHER[key]
    return {k: v for k, v in style.items() if marker or k != "marker"}


def coinciding(curves: list[tuple[str, np.ndarray]], rtol: float = COINCIDE) -> list[tuple[str, str]]:
    """Pairs of named curves that agree to within ``rtol`` of the larger value at every (finite) point."""
    out = []
    for i, (a, ya) in enumerate(curves):
        for b, yb in curves[i + 1 :]:
            ya_, yb_ = np.asarray(ya, float), np.asarray(yb, float)
            ok = np.isfinite(ya_) & np.isfinite(yb_)
            scale = np.maximum(np.abs(ya_[ok]), np.abs(yb_[ok]))
            if ok.any() and np.all(np.abs(ya_[ok] - yb_[ok]) <= rtol * np.maximum(scale, 1e-300)):
                out.append((a, b))
    return out


def _coincide_text(pairs: list[tuple[str, str]]) -> str:
    if not pairs:
        return ""
    return " " + " ".join(f"The {a} and {b} curves coincide (to within {100 * COINCIDE:g} %)." for a, b in pairs)


#: Above sqrt(2) omega_n, two transmissibility curves this close (largest relative gap) are said to nearly coincide.
CLOSE = 0.1


def _close_above(curves: list[tuple[str, np.ndarray]], mask: np.ndarray) -> str:
    """Pairs of curves that differ overall but lie within :data:`CLOSE` of each other where ``mask`` holds."""
    out = []
    for i, (a, ya) in enumerate(curves):
        for b, yb in curves[i + 1 :]:
            gap = float(np.max(np.abs(ya[mask] - yb[mask]) / np.maximum(np.abs(ya[mask]), np.abs(yb[mask]))))
            if gap <= CLOSE and not coinciding([(a, ya), (b, yb)]):
                out.append(f"the {a} and {b} curves lie within {max(1, math.ceil(100 * gap))} % of each other")
    return f" Between $\\sqrt{{2}}\\,\\omega_n$ and $4\\,\\omega_n$ {join(out)}." if out else ""


def _cap(text: str) -> str:
    return text[:1].upper() + text[1:]


def _name(n: str) -> str:
    return {"undamped": "undamped case", "unstable": "flutter model"}.get(n, f"{n} damping")


# ----------------------------------------------------------------------------- poles


def pole_figure(st: StabilityStudy) -> Captioned:
    """Poles in the complex plane: the whole locus over c, and a zoom near the imaginary axis."""
    fig, (ax, az) = figure(1, 2, height=3.9, gridspec_kw={"width_ratios": (1.25, 1.0)})
    wn = st.omega_n
    cases = st.pole_cases()
    c_lo = min(min(c for _k, c in cases) * 1.5, -0.1 * st.c_crit)
    c_max = max(1.3 * max(st.dampings.values()), 2.2 * st.c_crit)
    cs = np.concatenate(
        [np.linspace(c_lo, 0.0, 400), np.linspace(0.0, st.c_crit, 400)[1:], np.linspace(st.c_crit, c_max, 600)[1:]]
    )
    locus = np.array([poles(st.osc(c)) for c in cs])
    for a in (ax, az):
        a.axvspan(-1e300, 0.0, color="0.5", alpha=0.08, lw=0)
        a.axvline(0.0, color=REF_GREY, lw=0.8)
        for j in (0, 1):
            a.plot(locus[:, j].real, locus[:, j].imag, color=LOCUS_GREY, lw=1.0, zorder=1)
    handles = [Line2D([], [], color=LOCUS_GREY, lw=1.0, label=r"locus as $c$ varies")]
    for key, c in cases:
        p = poles(st.osc(c))
        s = look(key, marker=True)
        for a in (ax, az):
            a.plot(p.real, p.imag, ls="none", marker=s["marker"], ms=7, color=s["color"], zorder=3)
        handles.append(
            Line2D(
                [], [], ls="none", marker=s["marker"], ms=7, color=s["color"], label=f"{_name(key)}: $c$ = {c:g} N s/m"
            )
        )
    marked = np.concatenate([poles(st.osc(c)) for _k, c in cases])
    lo = min(float(marked.real.min()), -0.2 * wn)
    hi = max(float(marked.real.max()), 0.0)
    pad = 0.08 * (hi - lo)
    ax.set_xlim(lo - pad, hi + pad)
    ax.set_ylim(-1.4 * wn, 1.4 * wn)
    near = [poles(st.osc(c))[0] for _k, c in cases if abs(c) < st.c_crit / 2]
    re = [p.real for p in near] + [0.0]
    im = [p.imag for p in near]
    span_re = max(max(re) - min(re), 1e-3 * wn)
    span_im = max(max(im) - min(im), 1e-3 * wn)
    az.set_xlim(min(re) - 0.3 * span_re, max(re) + 0.3 * span_re)
    az.set_ylim(min(im) - 0.5 * span_im, max(im) + 0.5 * span_im)
    ax.text(0.03, 0.04, "stable half-plane (shaded)", transform=ax.transAxes, color="0.3", fontsize=8.5)
    for a in (ax, az):
        a.set_xlabel(r"Re $s$ (1/s)")
    ax.set_ylabel(r"Im $s$ (rad/s)")
    az.set_title(r"zoom near $s = i\,\omega_n$", fontsize=9)
    fig.legend(handles=handles, loc="outside upper center", ncols=2, frameon=False, fontsize=8)
    left, right = panel_words(fig)
    verdicts = {k: stability_class(st.osc(c)).verdict for k, c in cases}
    stable = [_name(k) for k, v in verdicts.items() if v == "asymptotically stable"]
    on_axis = [_name(k) for k, v in verdicts.items() if v == "marginally stable"]
    growing = [_name(k) for k, v in verdicts.items() if v == "unstable"]
    groups: dict[float, list[str]] = {}
    for key, c in cases:
        groups.setdefault(c, []).append(f"the {_name(key)}")
    same = [g for g in groups.values() if len(g) > 1]
    caption = (
        f"{_cap(left)}: poles of $m s^2 + c s + k$ for the paper's three dampings "
        f"($c$ = {join([num(c, 4) for _k, c in st.by_value()])} N s/m), for $c$ = 0 and for the flutter model "
        f"($c$ = {num(st.c_unstable, 4)} N s/m); the grey curve is their locus as $c$ runs from "
        f"{num(cs[0], 3)} to {num(cs[-1], 3)} N s/m, the shaded half-plane the stable one. "
        f"{_cap(right)}: zoom near $s = i\\omega_n$."
    )
    remark = " ".join(f"The markers of {join(g)} coincide (equal $c$)." for g in same)
    parts = []
    for group, where in ((stable, "in the left half-plane"), (on_axis, "on the imaginary axis"),
                         (growing, "in the right half-plane")):  # fmt: skip
        if group:
            parts.append(f"{'the poles' if not parts else 'those'} of the {join(group)} lie {where}")
    alt = "Poles in the complex plane: " + join(parts) + "."
    return Captioned(fig, caption, "fig-stability-poles", alt, remark=remark)


# ----------------------------------------------------------------------------- growth


def growth_title(st: StabilityStudy, case: str) -> str:
    """What one growth panel shows (plain words, no numbers)."""
    c = st.growth[case].osc.c
    if case == "bounded":
        return "transient approaching a bounded steady state"
    if case == "linear":
        return "linear growth at exact undamped resonance"
    if c == 0.0:
        return "flutter model set to c = 0: no negative damping, no exponential growth"
    return "exponential growth with negative damping (flutter's linear model)"


def growth_figure(st: StabilityStudy) -> Captioned:
    """The three ways a response grows, each with its closed-form envelope."""
    same = len({g.t_end for g in st.growth.values()}) == 1
    fig, axes = figure(3, 1, height=6.4, sharex=same)
    colour = {
        "bounded": look(st.bounded_name or "low")["color"],
        "linear": look("undamped")["color"],
        "exponential": look("unstable")["color"],
    }
    exact = case_style("exact")
    for ax, case in zip(axes, GROWTH_CASES, strict=True):
        g = st.growth[case]
        ax.plot(g.t, g.x, color=colour[case], lw=0.5, label="exact response $x(t)$")
        ax.plot(g.t, g.env, lw=1.1, label="closed-form envelope (bound)", **exact)
        ax.plot(g.t, -g.env, lw=1.1, **exact)
        ax.set_title(
            f"{growth_title(st, case)}: $c$ = {num(g.osc.c, 4)} N s/m, $\\omega$ = {num(g.force.omega, 4)} rad/s",
            fontsize=9,
            loc="left",
        )
        ax.set_ylabel(r"$x$ (m)")
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4), useMathText=True)
        if not same or ax is axes[-1]:
            ax.set_xlabel(r"time $t$ (s)")
    axes[0].legend(loc="lower right", bbox_to_anchor=(1.0, 1.18), ncols=2, frameon=False)
    words = panel_words(fig)
    b, lin, ex = (st.growth[c] for c in GROWTH_CASES)
    if st.bounded_name:
        bounded = f"the {st.bounded_name} damping"
        why = f"The {words[0]} case is the run's lightest positive damping with oscillating poles."
    else:
        bounded = "the paper's low damping ratio"
        why = (
            f"None of the run's dampings is positive with oscillating poles, so the {words[0]} case takes the "
            "paper's low damping ratio."
        )
    if ex.osc.c < 0.0:
        bottom = f"negative damping ($c$ = {num(ex.osc.c, 4)} N s/m), growing exponentially"
        if ex.capped:
            why += (
                f" The {words[2]} response is drawn until its growth factor reaches $e^{{{MAX_GROWTH:g}}}$, at "
                f"{num(ex.t_end, 3)} s."
            )
    else:
        bottom = "the flutter model set to $c$ = 0: bounded, no exponential growth"
    caption = (
        f"Forced responses from rest (solid) with their closed-form envelopes (black dashed), under $F_0$ = "
        f"{num(st.F0, 4)} N at {num(st.omega_res, 4)} rad/s except in the {words[1]}. {_cap(words[0])}: {bounded} "
        f"($c$ = {num(b.osc.c, 4)} N s/m), approaching a bounded steady state; {words[1]}: $c$ = 0 at exact "
        f"resonance, $\\omega_n$ = {num(lin.force.omega, 4)} rad/s, growing linearly; {words[2]}: {bottom}."
    )
    alt = (
        f"Displacement against time in three stacked panels: the damped response stays below {num(b.peak, 3)} m, "
        f"the undamped resonant one grows linearly to {num(lin.peak, 3)} m and the last one reaches "
        f"{num(ex.peak, 3)} m."
    )
    return Captioned(fig, caption, "fig-stability-growth", alt, remark=why)


# ----------------------------------------------------------------------------- transmissibility


def transmissibility_family(st: StabilityStudy) -> list[tuple[str, str, float]]:
    """(key, label, c) of the drawn curves: the run's positive dampings and the settling-optimal one, by value.

    With fewer than two different positive dampings the family adds ζ = 0.2 and ζ = 1 (key ``zeta``),
    so that a trade-off can still be seen.
    """
    out = [(n, f"{n}: $c$ = {c:g} N s/m", c) for n, c in st.positive()]
    if not st.distinct_positive():
        out += [("zeta", r"$\zeta$ = 0.2", 0.2 * st.c_crit), ("zeta", r"$\zeta$ = 1", st.c_crit)]
    out.append(("optimum", rf"$\zeta^*$ = {st.zeta_star:.3f}", st.c_star))
    return sorted(out, key=lambda p: p[2])


def transmissibility_figure(st: StabilityStudy) -> Captioned:
    """|X/Y| against frequency for the run's dampings and the settling-optimal one; all cross 1 at sqrt(2) omega_n."""
    fig, ax = figure(height=3.8)
    wn = st.omega_n
    w = np.unique(np.concatenate([np.linspace(0.0, 4.0 * wn, 3001), wn * (1 + np.linspace(-0.05, 0.05, 801))]))
    curves = []
    extra = iter(("-", "-."))
    for key, label, c in transmissibility_family(st):
        s = look(key) if key != "zeta" else {"color": REF_GREY, "linestyle": next(extra)}
        y = transmissibility(st.osc(c), w)
        ax.semilogy(w, y, lw=1.8 if key in CASE else 1.2, label=label, **s)
        name = {"optimum": "settling-optimal"}.get(key, key if key in CASE else label.replace("$", ""))
        curves.append((name.replace(r"\zeta", "ζ"), y))
    w_iso = isolation_frequency(st.osc(1.0))
    ax.axvline(w_iso, color=REF_GREY, lw=0.8, ls="--")
    shown = st.isolation_ratio <= 4.0
    if shown:
        ax.axvline(st.isolation_ratio * wn, color=REF_GREY, lw=0.8, ls="-.")
        ax.text(st.isolation_ratio * wn, 1.5e-2, rf" $\omega$ = {st.isolation_ratio:g} $\omega_n$", fontsize=8.5)
    ax.axhline(1.0, color=REF_GREY, lw=0.6)
    ax.annotate(
        r"$\sqrt{2}\,\omega_n$: $T = 1$ for every $\zeta$",
        (w_iso, 1.0),
        xytext=(6, 30),
        textcoords="offset points",
        fontsize=8.5,
        arrowprops={"arrowstyle": "-", "color": "0.4", "lw": 0.6},
    )
    ax.set_ylim(1e-2, 200.0)
    ax.set_xlim(0.0, 4.0 * wn)
    ax.set_xlabel(r"base frequency $\omega$ (rad/s)")
    ax.set_ylabel(r"transmissibility $|X/Y|$ (1)")
    place_legend(ax, outside=True)
    fam = transmissibility_family(st)
    run = [f"{n} ($c$ = {num(c, 4)} N s/m)" for n, _l, c in fam if n in CASE]
    r = st.isolation_ratio
    stand_in = run and not st.distinct_positive()
    caption = (
        "Transmissibility of base motion $|X/Y|$, logarithmic, against the base frequency "
        + (f"for the positive damping{'s' if len(run) > 1 else ''} {join(run)}" if run else "")
        + (", " if stand_in else "")
        + ("for damping ratios 0.2 and 1 (grey)" if not run or stand_in else "")
        + f" and the settling-optimal {ZSTAR} = {st.zeta_star:.3f} (black dotted). The dashed line marks "
        f"$\\sqrt{{2}}\\,\\omega_n$ = {num(w_iso, 4)} rad/s; "
        + (
            f"the dash-dotted line {r:g} {WN}, where isolation is judged."
            if shown
            else f"{r:g} {WN}, where isolation is judged, lies beyond the plotted range."
        )  # fmt: skip
    )
    remark = (
        "Every curve passes through $T$ = 1 at $\\sqrt{2}\\,\\omega_n$, and above it the more heavily damped "
        "curves lie higher."
        + (" Damping ratios 0.2 and 1 stand in for the run's missing positive dampings." if stand_in else "")
        + _coincide_text(coinciding(curves))
        + _close_above(curves, w > w_iso)
    )
    alt = (
        f"Transmissibility against base frequency on a log scale: the lightly damped curves peak sharply near "
        f"{num(wn, 3)} radians per second, all curves cross 1 at {num(w_iso, 3)} radians per second, and beyond that "
        "the more heavily damped curves lie higher."
    )
    return Captioned(fig, caption, "fig-stability-transmissibility", alt, remark=remark)


# ----------------------------------------------------------------------------- step response


def step_figure(st: StabilityStudy) -> Captioned:
    """Normalised step responses (c >= 0), and settling and rise times against the damping ratio."""
    fig, (ax, am) = figure(1, 2, height=3.6, gridspec_kw={"width_ratios": (1.2, 1.0)})
    wn = st.omega_n
    t_end = 12.0 * 2 * math.pi / wn
    t = np.linspace(0.0, t_end, 4001)
    ax.axhspan(1 - BAND, 1 + BAND, color="0.85", lw=0, label="±2 % band")
    cases = [(n, f"{n}: $c$ = {c:g} N s/m", c) for n, c in st.by_value() if c >= 0.0]
    cases.append(("optimum", rf"$\zeta^*$ = {st.zeta_star:.3f}", st.c_star))
    curves = []
    for key, label, c in cases:
        y = step_response(st.osc(c), t)
        ax.plot(t, y, lw=1.2, label=label, **look(key))
        curves.append((key if key in CASE else "settling-optimal", y))
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"$k\,x / F$ (1)")
    ax.set_xlim(0.0, t_end)
    ax.set_ylim(-0.05, 2.05)
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02), ncols=2, frameon=False, fontsize=7.5)
    zetas = np.geomspace(0.005, 8.0, 700)
    metrics = [step_metrics(Oscillator(m=st.m, c=z * st.c_crit, k=st.k), BAND) for z in zetas]
    am.loglog(zetas, [s.settling_time for s in metrics], color="k", lw=1.0, label="2 % settling time")
    am.loglog(zetas, [s.rise_time for s in metrics], color=REF_GREY, lw=1.0, ls="--", label="10–90 % rise time")
    for n, s in st.steps.items():
        am.plot(
            [s.zeta], [s.settling_time], ls="none", ms=6, **{k: v for k, v in look(n, True).items() if k != "linestyle"}
        )
    opt = look("optimum", True)
    am.plot([st.zeta_star], [st.star_step.settling_time], ls="none", marker=opt["marker"], color=opt["color"], ms=11,
            label=r"$\zeta^*$ (fastest)")  # fmt: skip
    am.set_xlabel(r"damping ratio $\zeta$ (1)")
    am.set_ylabel(r"time (s)")
    am.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02), ncols=2, frameon=False, fontsize=7.5)
    left, right = panel_words(fig)
    drawn = [f"{n} ($c$ = {num(c, 4)} N s/m)" for n, _l, c in cases if n in CASE]
    left_out = [f"{n} ($c$ = {num(c, 4)} N s/m)" for n, c in st.by_value() if c < 0.0]
    caption = (
        f"{_cap(left)}: normalised step response $k x/F$ for "
        + (f"{join(drawn)} and " if drawn else "")
        + f"the settling-optimal {ZSTAR} = {st.zeta_star:.3f} (black dotted), ±2 % band shaded. "
        f"{_cap(right)}: 2 % settling time (black) and 10–90 % rise time (dashed) against the damping ratio, "
        f"logarithmic axes; markers at the run's positive dampings and at {ZSTAR} (star)."
    )
    remark = (
        (f"Of the run's dampings, {join(left_out)} grows without bound and is not drawn." if left_out else "")
        + _coincide_text(coinciding(curves))
    ).strip()
    alt = (
        f"Step responses over {num(t_end, 3)} s and, beside them, settling and rise times against the damping "
        f"ratio: the settling time is least, {num(st.star_step.settling_time, 3)} s, at ζ* = {st.zeta_star:.3f}."
    )
    return Captioned(fig, caption, "fig-stability-step", alt, remark=remark)


# ----------------------------------------------------------------------------- cost


def cost_figure(st: StabilityStudy) -> Captioned:
    """Damper force amplitude and mean dissipated power against forcing frequency (c > 0)."""
    fig, (af, ap) = figure(1, 2, height=3.3)
    wn = st.omega_n
    w = np.unique(np.concatenate([np.linspace(0.01 * wn, 3.0 * wn, 2001), wn * (1 + np.linspace(-0.03, 0.03, 601))]))
    forces = []  # the powers coincide exactly where the forces do (same frequencies, P = F omega |X| / 2)
    for n, c in st.positive():
        d = damper_load(st.osc(c), st.F0, w)
        af.semilogy(w, d.force_amplitude, label=f"{n}: $c$ = {c:g} N s/m", **look(n))
        ap.semilogy(w, d.mean_power, label=f"{n}: $c$ = {c:g} N s/m", **look(n))
        forces.append((n, d.force_amplitude))
    for a in (af, ap):
        a.axvline(wn, color=REF_GREY, lw=0.7, ls="--")
        a.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
    af.axhline(st.F0, color=REF_GREY, lw=0.7, ls=":")
    af.set_ylabel(r"damper force amplitude $c\,\omega |X|$ (N)")
    ap.set_ylabel(r"mean dissipated power (W)")
    if not st.positive():
        for a in (af, ap):
            a.set_yscale("log")
            a.text(0.5, 0.5, "no positive damping in this run", transform=a.transAxes, ha="center")
    else:
        fig.legend(*af.get_legend_handles_labels(), loc="outside upper center", ncols=3, frameon=False)
    left, right = panel_words(fig)
    run = [f"{n} ($c$ = {num(c, 4)} N s/m)" for n, c in st.positive()]
    what = (
        f"for the positive damping{'s' if len(run) > 1 else ''} {join(run)}"
        if run
        else "(no positive damping in this run: no curves)"
    )
    same = coinciding(forces)
    caption = (
        f"Steady load on the damper under $F_0$ = {num(st.F0, 4)} N on the mass against the forcing frequency "
        f"{what}, logarithmic vertical axes. {_cap(left)}: damper force amplitude, $F_0$ dotted; {right}: mean "
        f"dissipated power. Dashed: {WN} = {num(wn, 4)} rad/s."
    )
    remark = _coincide_text(same).strip()
    alt = (
        f"Damper force and dissipated power against forcing frequency: every positive damping's force reaches "
        f"{num(st.F0, 3)} N at {num(wn, 3)} radians per second, and the lightest damping dissipates the most power "
        "there."
        if run
        else "Two empty panels of damper force and power: no damping of this run is positive."
    )
    return Captioned(fig, caption, "fig-stability-cost", alt, remark=remark)


# ----------------------------------------------------------------------------- the paper's labels


def _greys() -> ListedColormap:
    """A light-to-dark grey scale that leaves the case colours to the marked dampings."""
    return ListedColormap(colormaps["Greys"](np.linspace(0.3, 1.0, 256)))


def labels_figure(st: StabilityStudy) -> Captioned:
    """Pareto view: resonant peak against isolation, shaded by step settling time, with the paper's labels."""
    fig, ax = figure(height=4.0)
    zetas = np.geomspace(0.004, 6.0, 400)
    pts = [design_metrics(Oscillator(m=st.m, c=z * st.c_crit, k=st.k), st.isolation_ratio, BAND) for z in zetas]
    x = np.array([p.transmissibility for p in pts])
    y = np.array([p.peak_magnification for p in pts])
    ts = np.array([p.settling_time for p in pts])
    sc = ax.scatter(x, y, c=ts, s=6, cmap=_greys(), norm=LogNorm(ts.min(), ts.max()), zorder=2)
    cb = fig.colorbar(sc, ax=ax, pad=0.02)
    cb.set_label(r"2 % step settling time $t_s$ (s)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    pos = st.positive()
    for i, (n, c) in enumerate(pos):
        d = st.design[n]
        right = i < len(pos) - 1 or len(pos) == 1
        s = look(n, marker=True)
        ax.plot(d.transmissibility, d.peak_magnification, s["marker"], color=s["color"], ms=9, mec="k", zorder=3)
        ax.annotate(
            f"“{LABELS[n]}”\n$c$ = {c:g} N s/m, $t_s$ = {num(d.settling_time, 3)} s",
            (d.transmissibility, d.peak_magnification),
            xytext=(10, 4) if right else (-10, 14),
            ha="left" if right else "right",
            textcoords="offset points",
            fontsize=8,
        )
    off = [f"“{LABELS[n]}” ($c$ = {num(c, 4)} N s/m)" for n, c in st.by_value() if c <= 0.0]
    if off:
        ax.text(0.98, 0.97, "not on these axes (no finite peak or settling):\n" + ", ".join(off),
                transform=ax.transAxes, ha="right", va="top", fontsize=7.5)  # fmt: skip
    s = st.star
    opt = look("optimum", True)
    ax.plot(s.transmissibility, s.peak_magnification, opt["marker"], color=opt["color"], ms=13, zorder=3)
    ax.annotate(
        rf"$\zeta^*$ = {st.zeta_star:.3f} (fastest settling)" + f"\n$c$ = {num(st.c_star, 3)} N s/m, $t_s$ = "
        f"{num(s.settling_time, 3)} s",
        (s.transmissibility, s.peak_magnification),
        xytext=(-6, -10),
        ha="right",
        va="top",
        textcoords="offset points",
        fontsize=8,
    )
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    ax.xaxis.set_minor_formatter(FuncFormatter(lambda v, _pos: f"{v:g}" if round(v / 10 ** math.floor(math.log10(v)))
                                               in (2, 3, 5) else ""))  # fmt: skip
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    ax.set_xlabel(rf"isolation: transmissibility at {st.isolation_ratio:g} $\omega_n$ (1, lower is better)")
    ax.set_ylabel(r"resonant peak $\max |X|/(F_0/k)$ (1, lower is better)")
    ax.set_ylim(0.5, max(y.max(), 1.5) * 1.6)
    marked = f"{join([n for n, _c in pos])} ($c$ = {join([num(c, 4) for _n, c in pos])} N s/m)"
    caption = (
        "Resonant peak under a force on the mass against transmissibility of base motion at "
        f"{st.isolation_ratio:g} {WN}, logarithmic axes, for damping ratios 0.004 to 6, shaded by 2 % step "
        "settling time (darker: slower). "
        + (f"Marked with the paper's label{'s' if len(pos) > 1 else ''}: {marked}; " if pos else "")
        + f"black star: the settling-optimal {ZSTAR} = {st.zeta_star:.3f}."
    )
    remark = f"Not on these axes, having no finite peak or settling time: {join(off)}." if off else ""
    alt = (
        "Resonant peak against isolation for a family of dampings: the points form a falling curve, so lowering "
        "one raises the other, and the settling time is least in the middle of the curve."
    )
    return Captioned(fig, caption, "fig-stability-labels", alt, remark=remark)
