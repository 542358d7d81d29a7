"""The chapter's figures, each returned as :class:`~vibration.book.presentation.captions.Captioned`.

Designs keep the book's look (:func:`~vibration.book.presentation.style.case_style`: passive plant,
PD, LQR, PID, ideal skyhook, semi-active damper, best passive bound). Each caption is built from
the figure itself: the panel words come from :func:`~vibration.book.presentation.captions.panel_words`,
the colour and line style of every named curve from the drawn line, and a caption says two curves
coincide only when they do (:func:`closeness` below :data:`COINCIDE`).
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator

from vibration.book.chapters.control.notation import LABELS, cell, num, pct, signed_pct
from vibration.book.chapters.control.study import STEADY_PERIODS, ControlStudy
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.numbers import integer
from vibration.book.presentation.style import OKABE_ITO, case_style, figure, place_legend
from vibration.book.presentation.tables import cross_reference
from vibration.physics.control import force_floor

#: Two curves whose largest difference is below this fraction of their largest value coincide.
COINCIDE = 0.05

#: The shapers and the unshaped step, and the move's integrator treatments (not cases of the book).
SHAPER_STYLE = {
    "none": {"color": OKABE_ITO["grey"], "linestyle": "-"},
    "ZV": {"color": OKABE_ITO["vermillion"], "linestyle": "-."},
    "ZVD": {"color": OKABE_ITO["bluish green"], "linestyle": "-"},
}
MOVE_STYLE = {
    "unlimited": {"color": OKABE_ITO["grey"], "linestyle": "-"},
    "none": {"color": OKABE_ITO["vermillion"], "linestyle": "-"},
    "clamping": case_style("PID"),  # the chapter's PID design is the limited loop with clamping
    "back-calculation": {"color": OKABE_ITO["bluish green"], "linestyle": "--"},
}
#: Line styles in words; "dash-dot" rather than "dash-dotted", which the shared caption check reads as "dotted".
_LINESTYLE_WORD = {"-": "solid", "--": "dashed", ":": "dotted", "-.": "dash-dot"}
_COLOUR_WORD = {v.lower(): k for k, v in OKABE_ITO.items()}


def closeness(y1, y2) -> float:
    """Largest difference of two curves over the larger of their largest absolute values, 1."""
    y1, y2 = np.asarray(y1, float), np.asarray(y2, float)
    scale = max(float(np.max(np.abs(y1))), float(np.max(np.abs(y2))), 1e-300)
    return float(np.max(np.abs(y1 - y2))) / scale


def log_closeness(y1, y2) -> float:
    """Largest relative difference of two positive curves (as drawn on a logarithmic axis), 1."""
    return float(np.max(np.abs(np.asarray(y1, float) / np.asarray(y2, float) - 1.0)))


def look(line) -> str:
    """Colour and line style of a drawn line in words, e.g. 'orange dashed'."""
    from matplotlib.colors import to_hex

    colour = _COLOUR_WORD.get(to_hex(line.get_color()).lower(), "")
    ls = line.get_linestyle()
    style = _LINESTYLE_WORD.get({"dashed": "--", "dotted": ":", "dashdot": "-.", "solid": "-"}.get(ls, ls), "")
    if ls in ("None", "", " ", "none"):
        style = "markers"
    return " ".join(w for w in (colour, style) if w)


def _lines(ax) -> dict:
    return {ln.get_label(): ln for ln in ax.get_lines()}


def _panels(fig, texts: list[str]) -> str:
    """'Top: ... Bottom: ...' with the position words of the drawn layout, in ``fig.axes`` order."""
    words = panel_words(fig)
    if not words:
        return texts[0]
    return " ".join(f"{w[0].upper()}{w[1:]}: {t}" for w, t in zip(words, texts, strict=True))


def _coincide(
    panels: dict[str, dict[str, np.ndarray]], log: bool = False, verb: str = "nearly coincide: they differ by at most"
) -> str:
    """A sentence naming every pair of curves that coincides within :data:`COINCIDE`, per quantity drawn.

    ``panels`` maps what is drawn ("the displacement") to its curves by name; empty when none coincide.
    """
    found: dict[tuple[str, str], list[str]] = {}
    for where, curves in panels.items():
        names = list(curves)
        for i, a in enumerate(names):
            for b in names[i + 1 :]:
                d = log_closeness(curves[a], curves[b]) if log else closeness(curves[a], curves[b])
                if d < COINCIDE:
                    found.setdefault((a, b), []).append(f"{pct(d, 2)}{' in ' + where if where else ''}")
    what = "of each other" if log else "of their largest value"
    clauses = [
        f"the {a} and {b} curves {verb} {ds[0].replace(' in ', f' {what} in ', 1)}"
        + "".join(f" and {d}" for d in ds[1:])
        for (a, b), ds in found.items()
    ]
    return _join(clauses)


def _join(clauses: list[str]) -> str:
    if not clauses:
        return ""
    text = "; ".join(clauses)
    return f" {text[0].upper()}{text[1:]}."


# ----------------------------------------------------------------------------- active


#: Forcing periods at the end of the window that the close-up shows.
ZOOM_PERIODS = 3
#: Drawing order of the active designs: the PID underneath, the PD (drawn wider) and the LQR on top of it.
_ORDER = ("PID", "PD", "LQR")
_WIDTH = {"passive": 1.0, "PID": 1.3, "PD": 2.4, "LQR": 1.3}


def active_figure(study: ControlStudy) -> Captioned:
    """Displacement and control force of every active controller from rest, one above the other."""
    a = study.active
    fig, (ax1, ax2) = figure(2, 1, height=5.0, sharex=True)
    for name in ("passive", *_ORDER):
        ax1.plot(a.t, a.x[name], label=LABELS[name], lw=_WIDTH[name], **case_style(name))
        if name != "passive":
            ax2.plot(a.t, a.u[name], label=LABELS[name], lw=_WIDTH[name], **case_style(name))
    ax1.set_ylabel(r"$x$ (m)")
    ax2.set_ylabel(r"$u$ (N)")
    ax2.set_xlabel(r"$t$ (s)")
    place_legend(ax1, outside=True)
    lines = _lines(ax1)
    ratio = a.metrics["passive"].peak_x_ss / max(a.metrics[n].peak_x_ss for n in _ORDER)
    same = _coincide(
        {"the displacement": {n: a.x[n] for n in _ORDER}, "the force": {n: a.u[n] for n in _ORDER}},
        verb="lie on top of each other over the whole window, within",
    )
    caption = (
        f"Response from rest to $F_0 \\sin\\omega t$ at ω = {num(a.force.omega)} rad/s "
        f"($\\omega/\\omega_n$ = {cell(a.forcing_ratio)}): the passive plant ({look(lines['passive'])}), the PID "
        f"({look(lines['PID'])}, limited to ±{num(a.u_max)} N) and, drawn over it, the PD ({look(lines['PD'])}, "
        f"wider) and LQR ({look(lines['LQR'])}) loops. "
        + _panels(fig, ["displacement x.", "control force u of the three loops (the passive plant has none)."])
    )
    remark = (
        f"The largest steady controlled displacement is {num(ratio)} times smaller than the passive one; "
        f"{cross_reference('fig-control-active-zoom', 'the next figure')} shows the last forcing periods, where the "
        "loops can be told apart." + same
    )
    alt = (
        "Displacement and control force against time for the passive plant and the PD, LQR and PID loops: the "
        f"controlled displacements stay {num(ratio, 2)} times smaller than the passive one."
    )
    return Captioned(fig, caption, "fig-control-active", alt, remark=remark)


def active_zoom_figure(study: ControlStudy) -> Captioned:
    """The controlled displacement and force over the last forcing periods, side by side."""
    a = study.active
    t0 = a.t[-1] - ZOOM_PERIODS * 2.0 * math.pi / a.force.omega
    tail = a.t >= t0
    fig, (ax1, ax2) = figure(1, 2, height=3.2, sharex=True)
    for name in _ORDER:
        ax1.plot(a.t[tail], a.x[name][tail] * 1e3, label=LABELS[name], lw=_WIDTH[name], **case_style(name))
        ax2.plot(a.t[tail], a.u[name][tail], label=LABELS[name], lw=_WIDTH[name], **case_style(name))
    for ax in (ax1, ax2):
        ax.set_xlabel(r"$t$ (s)")
    ax1.set_ylabel(r"$x$ (mm)")
    ax2.set_ylabel(r"$u$ (N)")
    place_legend(ax2, outside=True)
    lines = _lines(ax1)
    same = _coincide(
        {"the displacement": {n: a.x[n][tail] for n in _ORDER}, "the force": {n: a.u[n][tail] for n in _ORDER}}
    )
    caption = (
        f"The last {ZOOM_PERIODS} forcing periods of {{numref}}`fig-control-active`, steady state: PID "
        f"({look(lines['PID'])}), PD ({look(lines['PD'])}, drawn wider underneath) and LQR ({look(lines['LQR'])}). "
        + _panels(fig, ["displacement in millimetres.", "control force."])
    )
    best = min(_ORDER, key=lambda n: a.metrics[n].peak_x_ss)
    alt = (
        f"Steady displacement and control force against time for the PD, LQR and PID loops over {ZOOM_PERIODS} "
        f"forcing periods; the {LABELS[best]} displacement is the smallest."
    )
    return Captioned(fig, caption, "fig-control-active-zoom", alt, remark=same.strip())


def tradeoff_figure(study: ControlStudy) -> Captioned:
    """LQR trade-off: steady amplitude against steady RMS force as r varies, design point and PD marked."""
    a = study.active
    tr = a.tradeoff
    fig, ax = figure(height=3.4)
    ax.loglog(tr.force_rms, tr.amplitude, label=r"LQR, $r$ varied", **case_style("LQR"))
    lqr_cl = a.loops["LQR"]
    pd_cl = a.loops["PD"]
    ax.loglog([tr.design_force], [lqr_cl.amplitude], ls="none", marker=case_style("LQR", marker=True)["marker"],
              color=case_style("LQR")["color"], ms=8, label=rf"LQR design, $r$ = {num(a.lqr.r)} 1/N$^2$")  # fmt: skip
    ax.loglog([tr.pd_force], [pd_cl.amplitude], ls="none", marker=case_style("PD", marker=True)["marker"],
              color=case_style("PD")["color"], ms=5, label="PD")  # fmt: skip
    ax.axhline(a.passive_amplitude, lw=1.0, label=rf"passive, $X$ = {num(a.passive_amplitude)} m",
               **case_style("passive"))  # fmt: skip
    xs = np.geomspace(float(np.min(tr.amplitude)), a.passive_amplitude, 200)
    ax.loglog(force_floor(a.osc, a.force, xs), xs, lw=1.0, label="least force for $X$", **case_style("optimum"))
    F_inf = a.force.F0 / math.sqrt(2.0)
    ax.axvline(F_inf, lw=0.8, label=r"$F_0/\sqrt{2}$", **case_style("threshold"))
    ax.set_xlabel(r"steady RMS control force $u_\mathrm{rms}$ (N)")
    ax.set_ylabel(r"steady amplitude $X$ (m)")
    place_legend(ax)
    lines = _lines(ax)
    passive = next(k for k in lines if k.startswith("passive"))
    decades = num(math.log10(tr.r[-1] / tr.r[0]), 2)
    clauses = []
    if tr.excess - 1.0 < COINCIDE:
        clauses.append(
            f"the LQR curve lies within {pct(tr.excess - 1.0, 2)} of the least-force curve, so the two coincide "
            "at this scale"
        )
    gap = max(abs(tr.pd_force / tr.design_force - 1.0), abs(pd_cl.amplitude / lqr_cl.amplitude - 1.0))
    if gap < COINCIDE:
        clauses.append(
            f"the PD marker sits on the LQR design (force and amplitude within {pct(gap, 2)}); it is drawn smaller "
            "so that both show"
        )
    caption = (
        "Steady amplitude against steady RMS control force, logarithmic axes: the LQR over "
        f"{decades} decades of its force weight $r$ ({look(lines['LQR, $r$ varied'])}), its design (cross), the "
        f"PD loop (diamond), the passive amplitude ({look(lines[passive])}), the least RMS force any controller "
        f"needs for each amplitude ({look(lines['least force for $X$'])}) and its zero-amplitude limit "
        f"$F_0/\\sqrt{{2}}$ = {num(F_inf)} N (grey dotted vertical)."
    )
    along = ", along the least force any controller needs" if tr.excess - 1.0 < COINCIDE else ""
    alt = (
        "Log-log plot of the LQR designs' steady amplitude against their RMS control force: the amplitude falls "
        f"as the force approaches {num(F_inf)} N{along}."
    )
    return Captioned(fig, caption, "fig-control-tradeoff", alt, remark=_join(clauses).strip())


def move_figure(study: ControlStudy) -> Captioned:
    """PID set-point move under the disturbance: displacement above, force below, per integrator treatment."""
    a = study.active
    fig, (ax1, ax2) = figure(2, 1, height=5.0, sharex=True)
    for scheme, mv in a.moves.items():
        lw = 1.0 if scheme == "unlimited" else 1.3
        ax1.plot(mv.run.t, mv.run.x, label=LABELS[scheme], lw=lw, **MOVE_STYLE[scheme])
        ax2.plot(mv.run.t, mv.run.u, label=LABELS[scheme], lw=lw, **MOVE_STYLE[scheme])
    ax1.axhline(a.x_ref, color="k", lw=0.8, ls=":")
    for sign in (1, -1):
        ax2.axhline(sign * a.u_max, color="k", lw=0.8, ls=":")
    ax1.set_ylabel(r"$x$ (m)")
    ax2.set_ylabel(r"$u$ (N)")
    ax2.set_xlabel(r"$t$ (s)")
    ax2.set_ylim(-2.2 * a.u_max, 2.2 * a.u_max)
    t_show = min(a.t[-1], 20.0)
    ax1.set_xlim(0, t_show)
    place_legend(ax1, outside=True)
    lines = _lines(ax1)
    shown = a.t <= t_show
    late = shown & (a.t >= 0.5 * t_show)
    limited = ("clamping", "back-calculation", "none")  # names as the caption uses them

    def curves(sel):
        return {
            "the displacement": {n: a.moves[n].run.x[sel] for n in limited},
            "the force": {n: a.moves[n].run.u[sel] for n in limited},
        }

    same = _coincide(curves(shown))
    if not same:
        later = f"nearly coincide from t = {num(0.5 * t_show)} s on: they differ by at most"
        same = _coincide(curves(late), verb=later)
    off = a.moves["unlimited"].peak_u
    off_scale = f" The force without a limit peaks at {num(off)} N, off the scale." if off > 2.2 * a.u_max else ""
    caption = (
        f"PID move to $x_\\mathrm{{ref}}$ = {num(a.x_ref)} m under the disturbance, first {num(t_show)} s: no force "
        f"limit ({look(lines[LABELS['unlimited']])}); limited to ±{num(a.u_max)} N without anti-windup "
        f"({look(lines[LABELS['none']])}), with clamping ({look(lines[LABELS['clamping']])}) and with "
        f"back-calculation ({look(lines[LABELS['back-calculation']])}, drawn over clamping). "
        + _panels(fig, ["displacement, set point black dotted.", "force, limits black dotted."])
    )
    remark = (off_scale + same).strip()
    alt = (
        "Displacement and force against time for the PID set-point move with and without a force limit and "
        f"anti-windup: without anti-windup the mass overshoots by {num(a.moves['none'].overshoot)} m."
    )
    return Captioned(fig, caption, "fig-control-windup", alt, remark=remark)


# ----------------------------------------------------------------------------- semi-active


def transmissibility_figure(study: ControlStudy) -> Captioned:
    """Transmissibility against frequency ratio: one panel per device law over the common references."""
    s = study.semi
    r = s.ratios
    fig, axes = figure(2, 2, height=5.2, sharex=True, sharey=True)
    panels = [
        ("passive dampers", [("soft", s.closed["soft"], case_style("passive")),
                             ("firm", s.closed["firm"], {**case_style("passive"), "linestyle": "-."})]),
        (LABELS["clipped"], [("clipped", s.sweeps["clipped"].peak, case_style("semi-active"))]),
        (LABELS["on-off"], [("on-off", s.sweeps["on-off"].peak, case_style("semi-active"))]),
        (LABELS["mr"], [("mr", s.sweeps["mr"].peak, case_style("semi-active"))]),
    ]  # fmt: skip
    clauses = []
    for ax, (title, curves) in zip(axes.flat, panels, strict=True):
        ax.loglog(r, s.closed["envelope"], lw=1.0, label="best passive (bound)", **case_style("optimum"))
        ax.loglog(r, s.closed["skyhook"], lw=1.2, label=LABELS["skyhook"], **case_style("skyhook"))
        for name, y, st in curves:
            ax.loglog(r, y, lw=1.5, label=LABELS[name], **st)
            if name != "soft" and name != "firm":
                d = log_closeness(y, s.closed["skyhook"])
                if d < COINCIDE:
                    clauses.append(f"the {LABELS[name]} coincides with the ideal skyhook to within {pct(d, 2)}")
        ax.axvline(math.sqrt(2.0), lw=0.8, **case_style("threshold"))
        ax.set_title(title)
        ax.xaxis.set_major_locator(FixedLocator([0.3, 0.5, 1.0, 1.41, 2.0, 4.0]))
        ax.xaxis.set_minor_locator(NullLocator())
        ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    for ax in axes[1]:
        ax.set_xlabel(r"$\omega/\omega_n$")
    for ax in axes[:, 0]:
        ax.set_ylabel(r"max$|x|/Y$")
    # the semi-active curves are drawn in the other panels: their style gets an entry in the one legend
    axes[0, 0].plot([], [], lw=1.5, label="semi-active law (its panel)", **case_style("semi-active"))
    place_legend(axes[0, 0], fontsize=7.5)
    lines = _lines(axes[0, 0])
    word = dict(zip(range(4), panel_words(fig), strict=True))
    caption = (
        "Suspension transmissibility (steady max|x| over base amplitude) against frequency ratio, "
        f"logarithmic axes. {word[0].capitalize()}: passive, soft ({look(lines[LABELS['soft']])}, "
        f"$c + c_\\mathrm{{min}}$) and firm ({look(lines[LABELS['firm']])}, $c + c_\\mathrm{{max}}$); {word[1]}: "
        f"clipped skyhook; {word[2]}: on-off skyhook; {word[3]}: MR damper, on-off (each "
        f"{look(_lines(axes[0, 1])[LABELS['clipped']])}, {integer(r.size)} frequencies). All panels: best passive "
        f"damper ({look(lines['best passive (bound)'])}), ideal skyhook ({look(lines[LABELS['skyhook']])}), "
        "$\\sqrt{2}$ (grey dotted)."
    )
    f = s.findings
    alt = (
        "Four log-log panels of transmissibility against frequency ratio for passive, clipped-skyhook, on-off and MR "
        f"dampers: at the natural frequency the clipped skyhook transmits {num(f.t_res['clipped'])} of the base "
        "motion, every passive damper more than 1."
    )
    return Captioned(fig, caption, "fig-control-transmissibility", alt, remark=_join(clauses).strip())


def _at_both_bounds(s) -> bool:
    """Does the clipped damper's coefficient -f/v_rel reach both bounds (within 1 %) in the steady tail?"""
    run = s.runs["clipped"]
    tail = run.t >= s.t_steady
    vr = (run.v - run.v_base)[tail]
    moving = np.abs(vr) > 1e-3 * np.max(np.abs(vr))
    coef = -run.f[tail][moving] / vr[moving]
    return bool(np.min(coef) <= s.c_min * 1.01 + 1e-12 and np.max(coef) >= s.c_max * 0.99)


def mr_figure(study: ControlStudy) -> Captioned:
    """Device force against relative velocity in steady state: the MR damper beside the clipped skyhook."""
    s = study.semi
    fig, axes = figure(1, 2, height=3.2, sharex=True, sharey=True)
    for ax, name in zip(axes, ("mr", "clipped"), strict=True):
        run = s.runs[name]
        tail = run.t >= s.t_steady
        ax.plot((run.v - run.v_base)[tail], -run.f[tail], lw=1.0, label=LABELS[name], **case_style("semi-active"))
        ax.set_title(LABELS[name])
        ax.set_xlabel(r"relative velocity $v - v_b$ (m/s)")
    axes[0].set_ylabel(r"damper force $-f$ (N)")
    line = axes[0].get_lines()[0]
    caption = (
        f"Force against relative velocity across the device ({look(line)}) in steady state at ω = {num(s.omega)} "
        f"rad/s ($\\omega/\\omega_n$ = {cell(s.omega / s.osc.natural_frequency)}), the last {STEADY_PERIODS} periods. "
        + _panels(
            fig,
            [
                "the MR damper switched on-off.",
                f"the clipped skyhook, its damping coefficient held between {num(s.c_min)} and {num(s.c_max)} N s/m.",
            ],
        )
    )
    remark = "The MR damper traces a hysteresis loop: its force depends on the motion's history, not on the " + (
        "velocity alone. The clipped skyhook's straight segments through the origin have the slopes of its two "
        "damping bounds."
        if _at_both_bounds(s)
        else "velocity alone."
    )
    alt = (
        "Damper force against relative velocity for the MR damper and the clipped skyhook: the MR damper traces a "
        "hysteresis loop, the clipped skyhook a force that switches between its damping bounds."
    )
    return Captioned(fig, caption, "fig-control-mr", alt, remark=remark)


# ----------------------------------------------------------------------------- input shaping


def shaping_figure(study: ControlStudy) -> Captioned:
    """The move on the real oscillator beside the residual vibration against the frequency ratio."""
    s = study.shaping
    fig, (ax1, ax2) = figure(1, 2, height=3.4)
    for name, x in s.x.items():
        ax1.plot(s.t, x * 1e3, label="unshaped step" if name == "none" else name, **SHAPER_STYLE[name])
    ax1.axhline(s.move * 1e3, color="k", lw=0.8, ls=":")
    ax1.set_xlabel(r"$t$ (s)")
    ax1.set_ylabel(r"$x$ (mm)")
    place_legend(ax1)
    q = 1.0 + s.freq_error
    for name, v in s.sensitivity.items():
        ax2.plot(s.ratios, 100 * v, label=name, **SHAPER_STYLE[name])
        ax2.plot([q], [100 * s.residual[name]], "o", color=SHAPER_STYLE[name]["color"], ms=4)
    ax2.axhline(5.0, lw=0.8, label="5 %", **case_style("threshold"))
    ax2.set_xlabel(r"real $\omega_n$ / model $\omega_n$")
    ax2.set_ylabel("residual vibration (%)")
    place_legend(ax2)
    l1 = _lines(ax1)
    caption = _panels(
        fig,
        [
            f"a {num(s.move * 1e3)} mm move (black dotted) on an oscillator whose natural frequency is "
            f"{signed_pct(s.freq_error)} off the model: unshaped ({look(l1['unshaped step'])}), ZV "
            f"({look(l1['ZV'])}) and ZVD ({look(l1['ZVD'])}) shapers designed on the model.",
            "residual vibration in % of the unshaped step's against real over model natural frequency; dots at "
            "this error, 5 % grey dotted.",
        ],
    )
    width = {n: s.bands[n][1] - s.bands[n][0] for n in ("ZV", "ZVD")}
    wider = "ZVD" if width["ZVD"] > width["ZV"] else "ZV"
    alt = (
        "The shaped and unshaped moves against time beside the residual vibration against the natural-frequency "
        f"ratio: {wider} stays below 5 % over the wider band."
    )
    return Captioned(fig, caption, "fig-control-shaping", alt)


def all_figures(study: ControlStudy) -> list[Captioned]:
    """Every figure of the chapter in reading order."""
    return [
        active_figure(study),
        active_zoom_figure(study),
        tradeoff_figure(study),
        move_figure(study),
        transmissibility_figure(study),
        mr_figure(study),
        shaping_figure(study),
    ]
