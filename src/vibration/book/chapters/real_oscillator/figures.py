"""Figures of the real-oscillator chapter, each a function of a :class:`RealOscillatorStudy`.

Colours follow the book's Okabe–Ito palette: one colour per brake setting (in manifest order), one per
damping law (the paper's viscous law blue); steady runs filled, others open. Each function returns a
:class:`~vibration.book.presentation.captions.Captioned` figure whose caption is built from what it draws.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.real_oscillator.study import LAWS, RealOscillatorStudy, law_amplitude
from vibration.book.presentation.captions import Captioned
from vibration.book.presentation.narrative import g
from vibration.book.presentation.numbers import pm
from vibration.book.presentation.style import OKABE_ITO, figure, place_legend
from vibration.physics.lab import FreeDecayFit, equivalent_zeta

SETTING_COLORS = ("blue", "vermillion", "bluish green", "orange", "reddish purple", "sky blue", "black")
LAW_STYLE = {
    "viscous": {"color": OKABE_ITO["blue"], "ls": "--", "label": "viscous (the paper's)"},
    "coulomb": {"color": OKABE_ITO["vermillion"], "ls": ":", "label": "Coulomb"},
    "coulomb+viscous": {"color": OKABE_ITO["bluish green"], "ls": "-", "label": "Coulomb + viscous"},
    "coulomb+quadratic": {"color": OKABE_ITO["orange"], "ls": "-.", "label": "Coulomb + quadratic"},
    "coulomb+power": {"color": OKABE_ITO["reddish purple"], "ls": (0, (5, 1.5)), "label": "Coulomb + power"},
}
#: The panel's model line (kept for the kernel-free panel).
MODEL_STYLE = {"combined": {"color": OKABE_ITO["bluish green"], "ls": "-", "label": "Coulomb + viscous"}}
LAW_WORDS = {
    "viscous": "viscous",
    "coulomb": "Coulomb",
    "coulomb+viscous": "Coulomb + viscous",
    "coulomb+quadratic": "Coulomb + quadratic",
    "coulomb+power": "Coulomb + power",
}
SESSION_MARKERS = ("o", "s", "^", "D", "v", "P")


def setting_color(i: int) -> str:
    """The colour of the i-th brake setting."""
    return OKABE_ITO[SETTING_COLORS[i % len(SETTING_COLORS)]]


def law_zeta_eq(fit, amplitude):
    """Equivalent damping ratio of a pooled law at amplitudes X (rad), the Coulomb term as 2 Δ/(π X)."""
    m = fit.mean
    x = np.asarray(amplitude, dtype=float)
    z = equivalent_zeta(
        x,
        m["omega_n"],
        zeta=max(m["zeta"], 0.0),
        quadratic=max(m["quadratic"], 0.0),
        power=max(m["power"], 0.0),
        power_exponent=m["power_exponent"] if m["power"] > 0 else 2.0,
    )
    return z + 2.0 * max(m["friction"], 0.0) / (math.pi * x)


def damping_figure(st: RealOscillatorStudy) -> Captioned:
    """The central figure: ζ_eq against the half-period amplitude X for every brake setting, with each chosen law."""
    fig, ax = figure(1, 1, height=3.8)
    for i, s in enumerate(st.settings):
        col = setting_color(i)
        x = np.concatenate([c.amplitude for c in s.curves])
        z = np.concatenate([c.zeta_eq for c in s.curves])
        ax.plot(x, z, ls="none", marker=".", ms=3, color=col, alpha=0.45)
        xx = np.linspace(max(s.amplitude_range[0], 1e-3), s.amplitude_range[1], 200)
        ax.plot(xx, law_zeta_eq(s.fits[s.law], xx), color=col, lw=1.4, label=f"brake {s.brake}: {LAW_WORDS[s.law]}")
    if st.band is not None:
        ax.axvspan(*st.band, color="0.9", zorder=0)
    ax.set_xlabel("half-period amplitude $X$ (rad)")
    ax.set_ylabel(r"$\zeta_{eq}$")
    ax.set_ylim(
        0.0,
        min(0.3, float(np.nanpercentile(np.concatenate([c.zeta_eq for s in st.settings for c in s.curves]), 99)) * 1.3),
    )
    place_legend(ax)
    n = sum(len(s.runs) for s in st.settings)
    band = (
        f" Shaded: the common amplitude band every setting covers ({g(st.band[0], 3)} to {g(st.band[1], 3)} rad)."
        if st.band is not None
        else ""
    )
    caption = (
        f"Equivalent damping ratio of each half period against its amplitude, {n} free decays at "
        f"{len(st.settings)} brake settings (dots), with the law the data choose for each setting (lines).{band}"
    )
    alt = "Scatter of equivalent damping ratio against amplitude for each brake setting, with one fitted curve each."
    return Captioned(fig, caption, "fig-real-damping", alt)


def current_figure(st: RealOscillatorStudy) -> Captioned | None:
    """ζ against brake current with the eddy-current law ζ = ζ₀ + k I² (only with more than two currents)."""
    cl = st.current_law
    if cl is None:
        return None
    fig, ax = figure(1, 1, height=3.2)
    cur = np.array(cl["currents"])
    ax.errorbar(
        cur,
        cl["zeta"],
        yerr=cl["zeta_stderr"],
        ls="none",
        marker="o",
        color=OKABE_ITO["blue"],
        label="free decays (Coulomb + viscous)",
    )
    ii = np.linspace(0.0, cur.max() * 1.05, 100)
    ax.plot(ii, cl["zeta0"] + cl["k"] * ii**2, color="0.2", lw=1.2, label="ζ₀ + k I²")
    ax.set_xlabel("brake current $I$ (A)")
    ax.set_ylabel(r"viscous $\zeta$")
    place_legend(ax)
    caption = (
        f"Viscous damping ratio of the free decays against the brake current at {len(cur)} settings, with the "
        f"eddy-current law ζ = ζ₀ + k I² fitted by weighted least squares: k = {pm(cl['k'], cl['k_stderr'])} "
        f"per A², χ² = {g(cl['chi2'], 2)} on {cl['dof']} degrees of freedom."
    )
    return Captioned(fig, caption, "fig-real-current", "Damping ratio rising with brake current, with a parabola.")


def resonance_figure(st: RealOscillatorStudy) -> Captioned:
    """Steady amplitude of the driven runs against drive frequency, with each law's calibrated prediction."""
    fig, ax = figure(1, 1, height=3.8)
    brakes = list(dict.fromkeys(d.run.brake for d in st.driven))
    sessions = list(dict.fromkeys(d.run.session for d in st.driven))
    names = [s.brake for s in st.settings]
    for b in brakes:
        col = setting_color(names.index(b)) if b in names else "0.3"
        for si, sess in enumerate(sessions):
            ds = [d for d in st.driven if d.run.brake == b and d.run.session == sess]
            if not ds:
                continue
            m = SESSION_MARKERS[si % len(SESSION_MARKERS)]
            st_ = [d for d in ds if d.steady.steady]
            un = [d for d in ds if not d.steady.steady]
            ax.plot(
                [d.omega for d in st_],
                [d.steady.amplitude for d in st_],
                ls="none",
                marker=m,
                color=col,
                ms=4,
                label=f"brake {b}, session {sess}",
            )
            ax.plot(
                [d.omega for d in un],
                [d.steady.amplitude for d in un],
                ls="none",
                marker=m,
                mfc="none",
                color=col,
                ms=4,
            )
    shown = []
    top = max((d.steady.amplitude for d in st.driven), default=1.0)
    for (b, law), p in st.predictions.items():
        if b != brakes[0]:
            continue
        ws = np.linspace(min(d.omega for d in st.driven) * 0.95, max(d.omega for d in st.driven) * 1.05, 300)
        u = float(np.nanmean([d.drive_amp for d in st.driven if d.run.brake == b]))
        amp = law_amplitude(st.settings[names.index(b)].fits[law], ws, p.gain * u)
        sty = LAW_STYLE[law]
        ax.plot(
            ws, np.where(np.isfinite(amp), amp, np.nan), color=sty["color"], ls=sty["ls"], lw=1.1, label=sty["label"]
        )
        shown.append(law)
    ax.set_ylim(0.0, 1.4 * top)
    ax.set_xlabel(r"drive frequency $\omega$ (rad/s)")
    ax.set_ylabel("late amplitude (rad)")
    place_legend(ax, outside=True, fontsize=7)
    n_st = sum(d.steady.steady for d in st.driven)
    caption = (
        f"Late amplitude of the {len(st.driven)} driven runs against drive frequency (filled: the {n_st} steady runs; "
        "open: drifting or beating), with each law's steady amplitude by harmonic balance at its calibrated gain "
        f"and the mean measured drive (lines, brake {brakes[0]})."
    )
    return Captioned(
        fig, caption, "fig-real-resonance", "Resonance curve of the wheel with measured points and model curves."
    )


def gain_figure(st: RealOscillatorStudy) -> Captioned:
    """The pooled prediction error of every law against the drive gain (times its calibrated value)."""
    fig, ax = figure(1, 1, height=3.2)
    for (b, law), p in st.predictions.items():
        f = [x for x, _ in p.sensitivity]
        e = [100 * y if math.isfinite(y) else np.nan for _, y in p.sensitivity]
        sty = LAW_STYLE[law]
        ax.plot(f, e, color=sty["color"], ls=sty["ls"], marker=".", label=f"{sty['label']}, brake {b}")
        if p.sim_sensitivity:
            fs = [x for x, _ in p.sim_sensitivity]
            es = [100 * y if math.isfinite(y) else np.nan for _, y in p.sim_sensitivity]
            ax.plot(fs, es, color=sty["color"], ls="none", marker="o", mfc="none", ms=4)
    simulated = any(p.sim_sensitivity for p in st.predictions.values())
    if simulated:
        ax.plot([], [], color="0.3", ls="none", marker="o", mfc="none", ms=4, label="simulated runs")
    ax.set_yscale("log")
    ax.set_xlabel("drive gain / calibrated gain")
    ax.set_ylabel("pooled rms error (%)")
    place_legend(ax, outside=True, fontsize=7)
    caption = (
        "Sensitivity of each law's pooled prediction error (rms relative error of the predicted steady "
        "amplitudes, logarithmic axis) to the drive gain, from 0.8 to 1.2 times its calibrated value"
        + (
            ": lines by harmonic balance, open circles by simulating each run from its measured start."
            if simulated
            else "."
        )
    )
    return Captioned(fig, caption, "fig-real-gain", "Prediction error against drive gain, one curve per law.")


def drift_figure(st: RealOscillatorStudy) -> Captioned:
    """Late drift of every driven run against drive frequency, with the tolerance band."""
    fig, ax = figure(1, 1, height=3.2)
    tol = st.params.tolerance
    ax.axhspan(-100 * tol, 100 * tol, color="0.9", zorder=0)
    sessions = list(dict.fromkeys(d.run.session for d in st.driven))
    for si, sess in enumerate(sessions):
        ds = [d for d in st.driven if d.run.session == sess]
        col = setting_color(si + 3)
        ax.errorbar(
            [d.omega for d in ds],
            [100 * d.steady.drift for d in ds],
            yerr=[200 * d.steady.drift_stderr for d in ds],
            ls="none",
            marker=SESSION_MARKERS[si % len(SESSION_MARKERS)],
            ms=3,
            color=col,
            label=f"session {sess}",
        )
    ax.set_xlabel(r"drive frequency $\omega$ (rad/s)")
    ax.set_ylabel("late drift (%)")
    place_legend(ax)
    caption = (
        f"Relative change of each driven run's amplitude over its last {st.params.periods} drive periods, with two "
        f"standard errors; shaded: the tolerance ±{100 * tol:g} %, within which (or within its errors) a run "
        "counts as steady."
    )
    return Captioned(fig, caption, "fig-real-drift", "Late drift of each run against frequency, most inside a band.")


@dataclass(frozen=True, kw_only=True, eq=False)
class TypicalDecay:
    """A free decay for the panel: samples, run number and its Coulomb + viscous fit."""

    t: np.ndarray
    angle: np.ndarray
    run: int
    combined: FreeDecayFit


def typical_decay(st: RealOscillatorStudy, brake: str = "on") -> TypicalDecay:
    """The run of median Coulomb + viscous residual of a brake setting (the last setting if ``brake`` is absent)."""
    s = next((x for x in st.settings if x.brake == brake), st.settings[-1])
    pooled = s.fits["coulomb+viscous"]
    order = sorted(range(len(s.runs)), key=lambda i: pooled.fits[i].residual_rms)
    i = order[len(order) // 2]
    r = s.runs[i]
    return TypicalDecay(t=np.asarray(r.t), angle=np.asarray(r.angle), run=r.run, combined=pooled.fits[i])


__all__ = [
    "LAWS",
    "LAW_STYLE",
    "MODEL_STYLE",
    "current_figure",
    "damping_figure",
    "drift_figure",
    "gain_figure",
    "resonance_figure",
    "typical_decay",
]
