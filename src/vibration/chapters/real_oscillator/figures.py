"""Figures of the real-oscillator chapter, each a function of a :class:`RealOscillatorStudy`.

Colours and markers per case follow the book's visual language (Okabe–Ito): the measurement is
grey, the viscous law (the paper's linear model) blue dashed, the Coulomb law vermillion dotted, the
combined law bluish green solid; session 1 reddish-purple circles, session 2 orange squares. Each
function returns a :class:`~vibration.presentation.captions.Captioned` figure whose caption is built
from what it draws and the study's numbers.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.chapters.real_oscillator.study import DecayRun, RealOscillatorStudy
from vibration.physics.lab import free_decay_peaks, half_period_losses
from vibration.presentation.captions import Captioned, panel_words
from vibration.presentation.style import OKABE_ITO, figure, place_legend

LAW_STYLE = {
    "viscous": {"color": OKABE_ITO["blue"], "ls": "--", "label": "viscous"},
    "coulomb": {"color": OKABE_ITO["vermillion"], "ls": ":", "label": "Coulomb"},
    "combined": {"color": OKABE_ITO["bluish green"], "ls": "-", "label": "viscous + Coulomb"},
}
MODEL_STYLE = {
    "linear": {"color": OKABE_ITO["blue"], "ls": "--", "label": "linear viscous (paper's model)"},
    "combined": {"color": OKABE_ITO["bluish green"], "ls": "-", "label": "viscous + Coulomb (Den Hartog)"},
}
MEASURED = "0.35"  # grey dots
SESSION_MARKER = {1: "o", 2: "s"}
SESSION_COLOR = {1: OKABE_ITO["reddish purple"], 2: OKABE_ITO["orange"]}
BRAKE_TITLE = {"off": "without the brake", "on": "with the brake"}


def typical_decay(st: RealOscillatorStudy, brake: str) -> DecayRun:
    """The run of median combined-fit residual (a typical run, not the best one)."""
    runs = sorted(st.decays[brake].runs, key=lambda d: d.combined.residual_rms)
    return runs[len(runs) // 2]


def decay_figure(st: RealOscillatorStudy):
    """One free decay per file, measured, with the three fitted laws over the fitted window."""
    fig, axes = figure(2, 1, height=5.6)
    for ax, brake in zip(axes, ("off", "on"), strict=True):
        d = typical_decay(st, brake)
        ax.plot(d.t, d.angle, color=MEASURED, lw=0.0, marker=".", ms=3, label="measured (20 Hz)")
        c = d.combined
        tt = np.linspace(c.t_start, c.t_end, 2000)
        for law in ("viscous", "coulomb", "combined"):
            f = d.fits[law]
            s = LAW_STYLE[law]
            ax.plot(tt, f.predict(tt), color=s["color"], ls=s["ls"], lw=1.1, label=f"{s['label']} fit")
        ax.set_title(f"{BRAKE_TITLE[brake]}, run {d.run}")
        ax.set_ylabel(r"$\theta$ (rad)")
        lo, hi = float(np.min(d.angle)), float(np.max(d.angle))
        ax.set_ylim(lo - 0.1 * (hi - lo), hi + 0.75 * (hi - lo))
        place_legend(ax, ncols=2)
    axes[-1].set_xlabel("$t$ (s)")
    top, bottom = panel_words(fig)
    runs = {b: typical_decay(st, b) for b in ("off", "on")}
    caption = (
        f"A typical free decay of each file (the run of median residual among the fits): {top} without the "
        f"magnetic brake (run {runs['off'].run}), {bottom} with it (run {runs['on'].run}). Grey dots: the "
        "measured wheel angle θ (rad) at 20 Hz; lines: the exact free decay fitted over the whole trace under "
        "three damping laws, viscous (blue, dashed), Coulomb (vermillion, dotted) and viscous + Coulomb "
        "(green, solid)."
    )
    alt = (
        "Two decaying oscillations of the wheel angle against time, with three fitted envelopes each; the "
        "viscous-plus-Coulomb fit follows the measured points most closely."
    )
    return Captioned(fig, caption, "fig-real-decay", alt)


def loss_figure(st: RealOscillatorStudy):
    """Amplitude loss per half period against amplitude, all runs, with each pooled law drawn."""
    fig, axes = figure(1, 2, height=3.6, sharey=True)
    for ax, brake in zip(axes, ("off", "on"), strict=True):
        ds = st.decays[brake]
        amax = 0.0
        for i, d in enumerate(ds.runs):
            peaks = free_decay_peaks(d.t, d.angle)
            a, loss = half_period_losses(peaks, d.combined.offset)
            keep = peaks.t[:-1] >= d.combined.t_start - 1e-9
            ax.plot(
                a[keep],
                loss[keep],
                ls="none",
                marker="o",
                ms=3,
                color=MEASURED,
                alpha=0.7,
                label="measured, all runs" if i == 0 else None,
            )
            amax = max(amax, float(np.max(a[keep], initial=0.0)))
        aa = np.linspace(0.0, amax * 1.05, 50)
        for law in ("viscous", "coulomb", "combined"):
            z = ds.pooled.get((law, "zeta"))
            dlt = ds.pooled.get((law, "friction"))
            zeta = z.mean if z else 0.0
            delta = dlt.mean if dlt else 0.0
            q = math.exp(-math.pi * zeta / math.sqrt(1 - zeta * zeta))
            s = LAW_STYLE[law]
            ax.plot(aa, (1 - q) * aa + (1 + q) * delta, color=s["color"], ls=s["ls"], label=s["label"])
        ax.set_title(BRAKE_TITLE[brake])
        ax.set_xlabel(r"amplitude $|\theta_k - c|$ (rad)")
        ax.set_ylim(bottom=0.0, top=float(ax.get_ylim()[1]) * 1.45)
    axes[0].set_ylabel("loss per half period (rad)")
    place_legend(axes[0])
    left, right = panel_words(fig)
    n_off, n_on = len(st.decays["off"].runs), len(st.decays["on"].runs)
    caption = (
        f"Amplitude lost per half period against the amplitude, every extremum of every run ({left}: without "
        f"the brake, {n_off} runs; {right}: with it, {n_on} runs). Grey dots: measured. Lines: each law's "
        "pooled fit, where viscous damping loses a fixed fraction (a line through the origin, blue, dashed), "
        "Coulomb friction a fixed angle (a horizontal line, vermillion, dotted) and the combined law both "
        "(green, solid)."
    )
    alt = (
        "Two scatter plots of loss per half period against amplitude; the points rise with amplitude from a "
        "non-zero intercept, which only the combined law's line follows."
    )
    return Captioned(fig, caption, "fig-real-losses", alt)


def response_figure(st: RealOscillatorStudy, models: bool = True):
    """Late amplitude ratio and phase lag against drive frequency, both sessions, with the models' steady curves."""
    fig, (a1, a2) = figure(2, 1, height=6.0, sharex=True)
    c = st.curves
    if models:
        for name in ("linear", "combined"):
            s = MODEL_STYLE[name]
            ratio = c.linear_ratio if name == "linear" else c.combined_ratio
            lag = c.linear_lag if name == "linear" else c.combined_lag
            a1.plot(c.omega, ratio, color=s["color"], ls=s["ls"], label=s["label"] + ", steady")
            a2.plot(c.omega, lag, color=s["color"], ls=s["ls"])
        a1.plot(c.omega, c.combined_hb, color=OKABE_ITO["bluish green"], ls=":", lw=1.0,
                label="viscous + Coulomb, harmonic balance")  # fmt: skip
    for session in (1, 2):
        for steady in (True, False):
            ds = [d for d in st.driven if d.session == session and d.steady == steady]
            if not ds:
                continue
            w = np.array([d.omega for d in ds])
            kw = dict(
                ls="none",
                marker=SESSION_MARKER[session],
                ms=4,
                color=SESSION_COLOR[session],
                capsize=2,
                mfc=SESSION_COLOR[session] if steady else "white",
            )
            a1.errorbar(
                w,
                [d.late.ratio for d in ds],
                yerr=[d.late.ratio_se for d in ds],
                label=f"session {session}, {'steady' if steady else 'transient'}",
                **kw,
            )
            a2.errorbar(w, [d.late.lag for d in ds], yerr=[d.late.lag_se for d in ds], **kw)
    a1.set_yscale("log")
    a1.set_ylabel("amplitude ratio wheel/drive")
    lo, hi = a1.get_ylim()
    a1.set_ylim(lo, hi * 40)
    a2.set_ylabel("phase lag (rad)")
    a2.set_xlabel(r"drive frequency $\omega$ (rad/s)")
    a2.axvline(st.models["combined"].omega_n, color="0.6", lw=0.8, ls="-.")  # ω_n
    a2.set_ylim(-0.5, math.pi + 0.5)
    place_legend(a1, outside=False, ncols=2, fontsize=8)
    top, bottom = panel_words(fig)
    n = len(st.driven)
    n_steady = sum(d.steady for d in st.driven)
    models_text = (
        " Lines: the steady response the free-decay fits predict, linear viscous (the paper's model; blue, "
        "dashed) and viscous + Coulomb (green, solid, with its one-harmonic balance dotted)."
        if models
        else " No model is drawn: these are the measurements alone."
    )
    caption = (
        f"The driven runs ({n}, of which {n_steady} reached a steady state): {top}, the late amplitude ratio of "
        f"wheel to drive on a logarithmic axis; {bottom}, the phase lag, with the fitted natural frequency "
        f"ωₙ = {st.models['combined'].omega_n:.4g} rad/s dash-dotted. Filled markers: steady runs; open: "
        f"transient ones; circles session 1, squares session 2; bars: ± one standard error.{models_text}"
    )
    alt = (
        "A resonance curve: the amplitude ratio peaks and the phase lag rises through π/2 near the natural "
        "frequency, for both measurement sessions" + (", with the two models' predicted curves." if models else ".")
    )
    return Captioned(fig, caption, "fig-real-response-models" if models else "fig-real-response", alt)


def prediction_figure(st: RealOscillatorStudy):
    """Measured wheel angle and both models' predictions for a calibration run, a steady run and a transient."""
    cal = st.calibration_runs[0]
    pred = [d for d in st.driven if not st.is_calibration(d)]
    steady = [d for d in pred if d.steady]
    trans = [d for d in pred if not d.steady]
    picks = [("calibration", cal)]
    if steady:
        picks.append(("steady, predicted", max(steady, key=lambda d: d.late.ratio)))
    if trans:
        picks.append(("transient, predicted", max(trans, key=lambda d: d.late.ratio)))
    fig, axes = figure(len(picks), 1, height=2.3 * len(picks) + 0.6, squeeze=False)
    for ax, (label, d) in zip(axes[:, 0], picks, strict=True):
        ax.plot(d.t, d.angle, color=MEASURED, lw=0.0, marker=".", ms=2.5, label="measured")
        for name in ("linear", "combined"):
            s = MODEL_STYLE[name]
            ax.plot(
                d.t, st.prediction(name, d).theta, color=s["color"], ls=s["ls"], lw=1.0, label=s["label"].split(" (")[0]
            )
        ax.set_title(f"session {d.session}, run {d.run}, ω = {d.omega:.3g} rad/s ({label})")
        ax.set_ylabel(r"$\theta$ (rad)")
        lo, hi = ax.get_ylim()
        ax.set_ylim(lo, hi + 0.6 * (hi - lo))
        place_legend(ax, ncols=3)
    axes[-1, 0].set_xlabel("$t$ (s)")
    words = panel_words(fig) or ["the panel"]
    parts = [f"{w}: session {d.session}, run {d.run} at ω = {d.omega:.3g} rad/s ({label})"
             for w, (label, d) in zip(words, picks, strict=True)]  # fmt: skip
    caption = (
        "Measured wheel angle θ (grey dots) and the angle both models predict from the drive alone, with the "
        "parameters of the free decays and the drive gain of the calibration runs: linear viscous (blue, "
        "dashed) and viscous + Coulomb (green, solid). " + "; ".join(parts) + "."
    )
    caption = caption[0].upper() + caption[1:]
    alt = "Driven oscillations of the wheel angle against time with the two models' predictions overlaid."
    return Captioned(fig, caption, "fig-real-prediction", alt)
