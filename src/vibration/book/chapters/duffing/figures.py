"""Chapter 9's figures, each a :class:`~vibration.book.presentation.captions.Captioned` with a caption built from
the figure's own layout and the study's numbers.

Colours follow the book's visual language (:data:`vibration.book.presentation.style.CASES`): the hardening
spring, the softening spring and the linear spring keep their colours in every figure; a stable branch is
solid, an unstable one dashed, a backbone dotted.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.duffing.notation import k3_text, within
from vibration.book.chapters.duffing.study import DuffingStudy, SpringCase
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.numbers import integer, minus, sig
from vibration.book.presentation.style import OKABE_ITO, case_style, colour_word, figure, place_legend
from vibration.physics.duffing import backbone

STABLE_LS, UNSTABLE_LS = "-", "--"
#: How a caption names each case's colour (the colours of :data:`vibration.book.presentation.style.CASES`).
COLOUR_WORD = {case: colour_word(case_style(case)["color"]) for case in ("hardening", "softening", "linear")}
#: One-harmonic curve under the sweeps: light grey, behind the data.
CURVE_GREY = "#bbbbbb"
#: The alt text's axes of the two frequency-response figures.
AXES = "Two panels of steady amplitude in metres against forcing frequency in radians per second: "
#: Two curves "coincide" in a caption when they differ by less than this fraction of their scale.
COINCIDE = 1e-3


def _k3(case: SpringCase) -> str:
    return k3_text(case.duffing.k3)


def plot_curve(ax, omega, amplitude, *, stable, color, label) -> bool:
    """Response curve, stable parts solid and unstable parts dashed; returns whether a dashed part was drawn."""
    breaks = np.flatnonzero(np.diff(stable.astype(int))) + 1
    first = {True: True, False: True}
    dashed = False
    for seg in np.split(np.arange(omega.size), breaks):
        if seg.size == 0:
            continue
        s = bool(stable[seg[0]])
        idx = np.concatenate([[seg[0] - 1] if seg[0] > 0 else [], seg]).astype(int)  # join the pieces
        lab = None
        if first[s]:
            lab = f"{label}, {'stable' if s else 'unstable'}"
            first[s] = False
        ax.plot(omega[idx], amplitude[idx], color=color, ls=STABLE_LS if s else UNSTABLE_LS, lw=1.5 if s else 1.1,
                label=lab)  # fmt: skip
        dashed |= not s
    return dashed


def _join(parts: list[str]) -> str:
    """Clauses joined by semicolons, the first letter capitalised (and nothing else changed)."""
    text = "; ".join(parts)
    return text[:1].upper() + text[1:]


def _legends_and_panels(fig, axes, cases, describe) -> str:
    """Place each panel's legend, then name the panels for the caption: ``"left, <describe(case)>; right, ..."``."""
    for ax in axes:
        place_legend(ax)
    return "; ".join(f"{word}, {describe(case)}" for word, case in zip(panel_words(fig), cases, strict=True))


# ------------------------------------------------------------------------------ frequency response


def frequency_response_figure(study: DuffingStudy) -> Captioned:
    """Harmonic-balance response curves of the hardening and the softening spring, backbones, folds, linear curve."""
    fig, axes = figure(1, 2, height=3.7, sharey=True)
    p = study.params
    lin = case_style("linear")
    drew_unstable = {}
    for ax, case in zip(axes, study.cases, strict=True):
        ax.plot(study.linear_omega, study.linear_amplitude_curve, color=lin["color"], ls=lin["linestyle"], lw=0.9,
                label="linear spring")  # fmt: skip
        drew_unstable[case.label] = plot_curve(
            ax, case.curve_omega, case.curve_amplitude, stable=case.curve_stable, color=case_style(case.label)["color"],
            label=minus(f"$k_3$ = {case.duffing.k3:g} N/m$^3$"),
        )  # fmt: skip
        a_bb = np.linspace(0.0, 1.1 * np.nanmax(case.curve_amplitude), 200)
        ax.plot(backbone(case.duffing, a_bb), a_bb, color="k", lw=0.8, ls=":", label="backbone")
        f = case.folds
        if f.bistable:
            ax.plot([f.omega_low, f.omega_high], [f.amplitude_low, f.amplitude_high], "o", ms=4.5, mfc="white",
                    color="k", label="folds")  # fmt: skip
        ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
        ax.set_title(f"{case.label} spring")
        ax.set_xlim(case.curve_omega.min(), case.curve_omega.max())
    axes[0].set_ylabel(r"amplitude $A$ (m)")
    axes[0].set_ylim(0.0, 1.7 * max(np.nanmax(c.curve_amplitude) for c in study.cases))  # room for the legends
    panels = _legends_and_panels(fig, axes, study.cases, lambda c: f"{c.label}, {_k3(c)} ({COLOUR_WORD[c.label]})")
    dashed = any(c.folds.bistable and drew_unstable[c.label] for c in study.cases)
    branches = "Stable branches solid, unstable dashed, folds open circles" if dashed else "Stable curves solid"
    caption = (
        f"One-harmonic response of the paper's oscillator (m = {p.m:g} kg, k = {p.k:g} N/m, "
        f"c = {p.c_nominal:g} N s/m, F₀ = {p.F0:g} N) with cubic springs: {panels}. {branches}; "
        f"backbones dotted black; linear spring {COLOUR_WORD['linear']}."
    )
    folded = [c for c in study.cases if c.folds.bistable and drew_unstable[c.label]]
    band = " and ".join(
        f"{sig(c.folds.omega_low, 4)} and {sig(c.folds.omega_high, 4)} rad/s ({c.label})" for c in folded
    )
    two = "two stable branches joined by an unstable one between the folds at"
    single = "a single-valued, stable curve"
    if len(folded) == len(study.cases):
        remark = f"Both springs give {two} {band}."
    elif not folded:
        remark = f"Both springs give {single}."
    else:
        remark = _join([f"the {c.label} spring gives " + (f"{two} {band.rsplit(' (', 1)[0]}" if c in folded else single)
                        for c in study.cases]) + "."  # fmt: skip
    lean = [
        f"the {c.label} spring's leans to {'higher' if c.folds.peak_omega > c.linear_peak_omega else 'lower'}"
        for c in study.cases
    ]
    alt = AXES + f"next to the linear resonance curve, {lean[0]} frequencies and {lean[1]} ones."
    return Captioned(fig, caption, "fig-duffing-hb", alt, remark=remark)


# ------------------------------------------------------------------------------------------ sweeps


def sweep_figure(study: DuffingStudy) -> Captioned:
    """Stepped sweeps up and down over the harmonic-balance curve and the continued periodic orbit."""
    fig, axes = figure(1, 2, height=3.7, sharey=True)
    any_dashed, any_branch = False, False
    for ax, case in zip(axes, study.cases, strict=True):
        col = case_style(case.label)["color"]
        any_dashed |= plot_curve(ax, case.curve_omega, case.curve_amplitude, stable=case.curve_stable, color=CURVE_GREY,
                                 label="one harmonic")  # fmt: skip
        if case.branch is not None:
            any_branch = True
            b = case.branch
            ax.plot(b.omega, b.amplitude, color="k", lw=0.7, label="periodic orbit (continuation)")
            ax.plot([f.omega for f in b.folds], [f.amplitude for f in b.folds], "s", ms=4.5, mfc="white", color="k",
                    label="folds of the orbit")  # fmt: skip
        ax.plot(case.up.omega, case.up.amplitude, "^", ms=3.2, color=col, label="sweep up")
        ax.plot(case.down.omega, case.down.amplitude, "v", ms=3.2, mfc="none", color="k", mew=0.7, label="sweep down")
        for jump, res in ((case.jump_up, case.up), (case.jump_down, case.down)):
            if jump is None:
                continue
            wj = 0.5 * (jump[0] + jump[1])
            a_before, a_after = case.jump_amplitudes(res)
            if not math.isfinite(a_before):
                continue
            ax.annotate("", xy=(wj, a_after), xytext=(wj, a_before),
                        arrowprops={"arrowstyle": "->", "color": col, "lw": 1.0})  # fmt: skip
        ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
        ax.set_title(minus(f"{case.label}, $k_3$ = {case.duffing.k3:g} N/m$^3$"))
        ax.set_xlim(case.up.omega.min(), case.up.omega.max())
    axes[0].set_ylabel(r"steady amplitude $A$ (m)")
    axes[0].set_ylim(0.0, 1.75 * max(np.nanmax(c.curve_amplitude) for c in study.cases))
    panels = _legends_and_panels(fig, axes, study.cases, lambda c: f"the {c.label} spring ({COLOUR_WORD[c.label]})")
    parts = []
    for case in study.cases:
        jumps = sum(j is not None for j in (case.jump_up, case.jump_down))
        jump_text = {0: "neither sweep jumps off its branch in this range", 1: "one sweep jumps (arrow)",
                     2: "both sweeps jump (arrows)"}  # fmt: skip
        if not case.folds.bistable:
            jump_text[0] = "the response is single-valued, so the sweeps have no branch to leave"
        parts.append(jump_text[jumps])
    gaps = [c.sweep_orbit_gap() for c in study.cases]
    gaps = [g for g in gaps if math.isfinite(g)]
    unstable = ", unstable branch dashed" if any_dashed else ""
    over = (
        " and the periodic orbit of the full equation (thin black line, its folds open squares)" if any_branch else ""
    )
    agree = (
        f" Where the continued orbit is drawn, the sweep amplitudes lie on it to within {within(max(gaps))}."
        if gaps
        else ""
    )
    caption = (
        "Stepped frequency sweeps by time integration: filled triangles in the spring's colour sweeping up, open "
        f"black triangles sweeping down, over the one-harmonic curve (grey{unstable}){over}. {_join([panels])}."
    )
    each = (
        f"for both springs, {parts[0]}"
        if len(set(parts)) == 1
        else "; ".join(f"for the {c.label} spring, {t}" for c, t in zip(study.cases, parts, strict=True))
    )
    remark = f"{_join([each])}.{agree}"
    alt = (
        AXES + "the amplitudes of stepped sweeps "
        "up and down follow different branches of the response curve and jump between them at different "
        "frequencies."
        if any(c.jump_up or c.jump_down for c in study.cases)
        else AXES + "the sweeps up and down follow the response curve without jumping."
    )
    return Captioned(fig, caption, "fig-duffing-sweeps", alt, remark=remark)


# ------------------------------------------------------------------------------- the paper's scenario


def paper_figure(study: DuffingStudy) -> Captioned:
    """The paper's resonance scenario from rest, linear and with the hardening spring."""
    fig, ax = figure(1, 1, height=3.2)
    p, hard = study.params, study.hardening
    lin, hs, th = case_style("linear"), case_style("hardening"), case_style("threshold")
    ax.plot(study.paper_t, study.paper_x_linear, color=lin["color"], ls=lin["linestyle"], lw=0.9,
            label="linear spring (the paper)")  # fmt: skip
    ax.plot(study.paper_t, study.paper_x_duffing, color=hs["color"], ls=hs["linestyle"], lw=1.0,
            label=f"$k_3$ = {hard.duffing.k3:g} N/m$^3$")  # fmt: skip
    trust = study.trust_amplitude
    drawn = math.isfinite(trust)
    if drawn:
        label = "±amplitude where the linear answer fails"
        ax.axhline(trust, color=th["color"], ls=th["linestyle"], lw=1.0, label=label)
        ax.axhline(-trust, color=th["color"], ls=th["linestyle"], lw=1.0)
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"displacement $x$ (m)")
    top = 1.1 * max(np.abs(study.paper_x_linear).max(), trust if drawn else 0.0)
    ax.set_ylim(-top, top)
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02, 1.0, 0.1), ncol=3, borderaxespad=0.0, frameon=False)
    x_lin, x_duf = np.abs(study.paper_x_linear).max(), np.abs(study.paper_x_duffing).max()

    def past(x: float) -> str:
        return "crosses the lines" if x > trust else "stays inside the lines"

    verdict = (
        f"the linear response (largest |x| {sig(x_lin, 3)} m) {past(x_lin)}, the cubic one (largest |x| "
        f"{sig(x_duf, 3)} m) {'too' if past(x_lin) == past(x_duf) else past(x_duf)}"
    )
    lines = (
        f" The dotted grey lines at ±{sig(trust, 3)} m mark the amplitude beyond which the linear answer is not "
        "trustworthy."
        if drawn
        else ""
    )
    caption = (
        f"The paper's resonance scenario from rest, forced by its F₀ sin ωt at ω = {p.omega_res:g} rad/s for "
        f"{p.t_end:g} s: "
        f"displacement with the linear spring ({COLOUR_WORD['linear']}, the paper's model) and with the hardening "
        f"spring {_k3(hard)} ({COLOUR_WORD['hardening']}).{lines}"
    )
    remark = f"{verdict[:1].upper()}{verdict[1:]}." if drawn else ""
    alt = (
        "Displacement in metres against time in seconds from rest: the response with the hardening spring "
        f"{'stays smaller than' if x_duf < x_lin else 'grows larger than'} the linear one."
    )
    return Captioned(fig, caption, "fig-duffing-paper", alt, remark=remark)


# ------------------------------------------------------------------------------------------- chaos


def _draw_sections(ax, study: DuffingStudy, chaos_col: str, per_col: str) -> None:
    """Left panel: the Poincaré sections of the chaotic (dots) and the periodic (circles) forcing."""
    p = study.params
    strobe = r"2\pi n" if p.omega_ueda == 1.0 else rf"2\pi n/{p.omega_ueda:g}"
    ax.plot(study.section_chaos[:, 0], study.section_chaos[:, 1], ".", ms=1.2, color=chaos_col,
            label=f"$F$ = {p.F0_ueda:g} N")  # fmt: skip
    ax.plot(study.section_periodic[:, 0], study.section_periodic[:, 1], "o", ms=6, color=per_col,
            label=f"$F$ = {p.F0_ueda_periodic:g} N")  # fmt: skip
    ax.set_xlabel(rf"$x$ at $t = {strobe}$ (m)")
    ax.set_ylabel(rf"$\dot x$ at $t = {strobe}$ (m/s)")
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02, 1.0, 0.1), ncol=2, borderaxespad=0.0, frameon=False)


def _draw_running(ax, study: DuffingStudy, chaos_col: str, per_col: str) -> None:
    """Middle panel: the running largest exponent of both forcings, QR solid and Benettin dashed."""
    styles = {"qr": "-", "benettin": "--"}
    for which, col in (("chaotic", chaos_col), ("periodic", per_col)):
        for method in ("qr", "benettin"):
            t, lam = study.running(which, method)
            ax.plot(t, lam, color=col, ls=styles[method], lw=1.0)
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set_xscale("log")
    ax.set_xlabel(r"averaging time (s)")
    ax.set_ylabel(r"largest exponent $\lambda_1$ (1/s)")


def _draw_chaos_map(fig, ax, study: DuffingStudy, chaos_col: str, per_col: str) -> None:
    """Right panel: Ueda's chaos map (the pooled exponent over forcing frequency and amplitude), both forcings
    circled."""
    p = study.params
    cmap = study.chaos_map
    top = max(float(np.max(np.abs(cmap.exponent))), 1e-12)
    mesh = ax.pcolormesh(cmap.omegas, cmap.forces, cmap.exponent, shading="nearest", cmap="RdBu_r", vmin=-top,
                         vmax=top)  # fmt: skip
    fig.colorbar(mesh, ax=ax, location="top", label=r"$\lambda_1$ (1/s)")
    ax.plot([p.omega_ueda], [p.F0_ueda], "o", ms=6, mfc="none", color=chaos_col)
    ax.plot([p.omega_ueda], [p.F0_ueda_periodic], "o", ms=6, mfc="none", color=per_col)
    ax.set_xlabel(r"frequency $\omega_U$ (rad/s)")
    ax.set_ylabel(r"amplitude $F_U$ (N)")


def _section_words(n: int, total: int) -> str:
    """What a Poincaré section of ``n`` distinct points out of ``total`` shows."""
    if n == 1:
        return "a single point: a periodic motion of the forcing period"
    if n < total:
        return f"{integer(n)} points: a periodic motion of {integer(n)} forcing periods"
    return f"{integer(n)} distinct points spread over a folded set, no repeating pattern"


def _chaos_remark(study: DuffingStudy, n_chaos: int, n_per: int) -> str:
    """What the chaos figure shows: the sections' points, whether the two methods agree, the map's grid."""
    p, cmap = study.params, study.chaos_map
    dot = f"a {COLOUR_WORD['hardening']} circle" if n_per == 1 else f"{COLOUR_WORD['hardening']} circles"
    gaps = {w: study.method_gap(w) for w in ("chaotic", "periodic")}
    both = all(g < COINCIDE for g in gaps.values())
    coincide = (
        f"for each forcing the two methods' curves coincide (they differ by less than {100 * COINCIDE:g} % of the "
        "final estimate after the first 10 periods)"
        if both
        else "; ".join(
            f"at F = {f:g} N the two methods' curves "
            + ("coincide" if gaps[w] < COINCIDE else f"differ by up to {within(gaps[w], COINCIDE)}")
            for w, f in (("chaotic", p.F0_ueda), ("periodic", p.F0_ueda_periodic))
        )
    )
    return (
        f"The section at F = {p.F0_ueda:g} N holds {_section_words(n_chaos, len(study.section_chaos))}; at "
        f"F = {p.F0_ueda_periodic:g} N it holds {_section_words(n_per, len(study.section_periodic))} ({dot}). The "
        f"exponent's estimates take the colours of the forcings; {coincide}. The map computes the exponent over "
        f"{integer(cmap.n_periods)} periods at each point of a {integer(cmap.omegas.size)} × "
        f"{integer(cmap.forces.size)} grid of forcings; red (a positive exponent) means chaotic motion."
    )


def _chaos_alt(study: DuffingStudy, n_chaos: int, n_per: int) -> str:
    """The chaos figure's alt text: the sections' sizes and the sign each running exponent settles to."""
    final = {w: study.running(w, "qr")[1][-1] for w in ("chaotic", "periodic")}
    return (
        f"Left, a Poincaré section of {integer(n_chaos)} points for the stronger forcing and {integer(n_per)} for "
        "the weaker one; middle, running estimates of the largest Lyapunov exponent against averaging time, settling "
        + ("above zero" if final["chaotic"] > 0 else "below zero")
        + " for the stronger forcing and "
        + ("below zero" if final["periodic"] < 0 else "above zero")
        + " for the weaker one; right, a colour map of the exponent over forcing frequency and amplitude."
    )


def chaos_figure(study: DuffingStudy) -> Captioned:
    """Poincaré sections of Ueda's oscillator, the running largest Lyapunov exponent by both methods, and
    Ueda's chaos map (the pooled exponent over forcing frequency and amplitude)."""
    fig, (ax1, ax2, ax3) = figure(1, 3, height=3.9, layout="constrained")
    p = study.params
    chaos_col, per_col = OKABE_ITO["black"], case_style("hardening")["color"]
    _draw_sections(ax1, study, chaos_col, per_col)
    _draw_running(ax2, study, chaos_col, per_col)
    _draw_chaos_map(fig, ax3, study, chaos_col, per_col)

    left, middle, right = (w[:1].upper() + w[1:] for w in panel_words(fig)[:3])
    n_chaos, n_per = study.section_points("chaotic"), study.section_points("periodic")
    forcing = r"F\cos t" if p.omega_ueda == 1.0 else rf"F\cos({p.omega_ueda:g}t)"
    caption = (
        rf"Ueda's oscillator $\ddot x + {p.c_ueda:g}\,\dot x + x^3 = {forcing}$. {left}: Poincaré sections (state "
        f"once per period) at F = {p.F0_ueda:g} N (black dots) and {p.F0_ueda_periodic:g} N "
        f"({COLOUR_WORD['hardening']}). {middle}: the largest Lyapunov exponent's running estimate (logarithmic time "
        f"axis), by variational equations with QR (solid) and by two trajectories (dashed). {right}: the exponent over "
        "forcing frequency and amplitude (red positive, blue negative); circles mark both forcings."
    )
    remark = _chaos_remark(study, n_chaos, n_per)
    alt = _chaos_alt(study, n_chaos, n_per)
    return Captioned(fig, caption, "fig-duffing-chaos", alt, remark=remark)
