"""Figures of the digital-twin chapter, each a function of a :class:`DigitalTwinStudy` returning a :class:`Captioned`.

The book's visual language: what was measured is black dots (case ``"measured"``), the truth black dashed
(``"exact"``), the twin's model of the asset the nominal damping's blue (``"c_nominal"``: the asset has the
paper's nominal damping), thresholds grey dotted (``"threshold"``). The two faults take the two Okabe-Ito colours
no case of the chapter uses. Captions are built from the drawn figure (:func:`panel_words`) and the study's numbers.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

from vibration.book.chapters.digital_twin.study import MIN_ALARMS, DigitalTwinStudy
from vibration.book.presentation.captions import Captioned, panel_words
from vibration.book.presentation.numbers import integer, sig
from vibration.book.presentation.style import OKABE_ITO, case_style, colour_word, figure, place_legend

#: The faults of the detection experiments: colour (and its caption word) and marker.
FAULT_STYLE = {
    "sudden drop": {"color": OKABE_ITO["reddish purple"], "marker": "o", "word": "purple"},
    "slow decline": {"color": OKABE_ITO["orange"], "marker": "s", "word": "orange"},
}
NAMES = ("m", "c", "k")
#: Left part of the identification figure, s.
WINDOW = 20.0


def _plain_log_ticks(ax, which: str) -> None:
    axis = ax.xaxis if which == "x" else ax.yaxis
    axis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def _cap(word: str) -> str:
    return word[:1].upper() + word[1:]


def receptance_gap(st: DigitalTwinStudy) -> float:
    """Largest relative difference between the identified and the true receptance over the plotted band, 1."""
    w = _fine(st)
    fit, tru = st.fit.oscillator, st.asset
    h_fit = np.abs(1.0 / (fit.k - fit.m * w**2 + 1j * fit.c * w))
    h_tru = np.abs(1.0 / (tru.k - tru.m * w**2 + 1j * tru.c * w))
    return float(np.max(np.abs(h_fit / h_tru - 1.0)))


def _band(st: DigitalTwinStudy) -> np.ndarray:
    return st.frf.force_psd >= 1e-2 * np.max(st.frf.force_psd)


def _fine(st: DigitalTwinStudy) -> np.ndarray:
    """A fine frequency grid over the plotted band, rad/s (the model curves are smooth; the bins are coarse)."""
    w = st.frf.omega[_band(st)]
    return np.linspace(float(w[0]), float(w[-1]), 2000)


def identification_figure(st: DigitalTwinStudy) -> Captioned:
    """Measured and identified response over the first seconds, and the measured receptance against the model."""
    fig, (ax1, ax2) = figure(1, 2, height=3.4, gridspec_kw={"width_ratios": [1.4, 1.0]})
    meas, fit = st.test, st.fit
    sel = meas.t <= meas.t[0] + WINDOW
    model = meas.response - fit.residual
    dots = case_style("measured", marker=True)
    ax1.plot(meas.t[sel], meas.response[sel], ls="none", marker=".", ms=2.5, color=dots["color"], label="measured")
    ax1.plot(meas.t[sel], model[sel], lw=1.1, **case_style("c_nominal"), label="identified model")
    ax1.set_xlabel("$t$ (s)")
    ax1.set_ylabel("$x$ (m)")
    ymax = float(np.max(np.abs(meas.response[sel])))
    ax1.set_ylim(-1.45 * ymax, 1.45 * ymax)
    place_legend(ax1, ncol=2)
    keep = _band(st)
    tru, osc = st.asset, fit.oscillator
    h_meas = np.abs(st.frf.H[keep])
    ax2.semilogy(st.frf.omega[keep], h_meas, ls="none", marker=".", ms=3.0, color=dots["color"], label="Welch $H_1$")
    w = _fine(st)
    ax2.semilogy(w, np.abs(1.0 / (osc.k - osc.m * w**2 + 1j * osc.c * w)), lw=1.2, **case_style("c_nominal"),
                 label="identified")  # fmt: skip
    ax2.semilogy(w, np.abs(1.0 / (tru.k - tru.m * w**2 + 1j * tru.c * w)), lw=1.2, **case_style("exact"),
                 label="true")  # fmt: skip
    ax2.set_xlabel(r"$\omega$ (rad/s)")
    ax2.set_ylabel(r"$|H|$ (m/N)")
    place_legend(ax2)
    left, right = panel_words(fig)
    gap = receptance_gap(st)
    same = "coincide to within" if gap < 0.01 else "differ by up to"
    caption = (
        f"{_cap(left)}: the first {WINDOW:g} s of the measured displacement (black dots, {1 / st.params.dt:.3g} Hz) "
        f"and the identified model's response to the same force (blue). {_cap(right)}: the measured receptance "
        "(Welch estimate, black dots) on a logarithmic axis, the identified model's (blue) and the true one "
        "(black dashed)."
    )
    remark = f"Over the force band the identified and true receptances {same} {100 * gap:.2g} %."
    alt = (
        f"Measured displacement and identified model over {WINDOW:g} s, and receptance magnitude against "
        "frequency: the model follows the measurements and the resonance peak."
    )
    return Captioned(fig, caption, "fig-twin-fit", alt, remark=remark)


def scaling_figure(st: DigitalTwinStudy) -> Captioned:
    """Small multiples: relative rms error of m, c, k (rows: noise sweep, length sweep; columns: m, c, k)."""
    fig, axes = figure(2, 3, height=4.6)
    sweeps = (
        (st.by_noise, [e.noise for e in st.by_noise], "noise / rms response"),
        (st.by_length, [e.duration for e in st.by_length], "record length $T$ (s)"),
    )
    dots = case_style("measured", marker=True)
    spread = 0.0
    for row, (exps, xs, xlabel) in enumerate(sweeps):
        for j, name in enumerate(NAMES):
            ax = axes[row, j]
            rmse = np.array([100 * e.rel_rmse[j] for e in exps])
            se = np.array([100 * e.rel_stderr[j] for e in exps])
            spread = max(spread, float(np.max(np.abs(rmse / se - 1.0))))
            ax.loglog(xs, rmse, ls="none", marker="o", ms=4, color=dots["color"], label="Monte Carlo rms error")
            ax.loglog(xs, se, lw=1.1, **case_style("c_nominal"), label="reported std. error")
            ax.set_xlabel(xlabel)
            if j == 0:
                ax.set_ylabel("relative error (%)")
            ax.set_title(f"${name}$", loc="left")
            _plain_log_ticks(ax, "x")
            _plain_log_ticks(ax, "y")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncols=2)
    words = panel_words(fig)
    runs = st.by_noise[0].runs
    caption = (
        "Relative rms error of the estimates over Monte Carlo runs (black dots) and the rms of the reported "
        "standard errors (blue lines), on logarithmic axes; columns m, c and k from left through middle to "
        f"right. Top row: against noise level at T = {st.by_noise[0].duration:g} s. Bottom row: against the "
        f"record length at noise {st.by_length[0].noise:g} of the rms response."
    )
    remark = (
        f"Each point has {integer(runs)} runs of its own noise; the dots lie within {100 * spread:.2g} % of the "
        f"lines (one point's rms error has a sampling error of about {100 / math.sqrt(2 * runs):.2g} %)."
    )
    assert {"top left", "bottom right"} <= set(words)  # the caption's words above describe this layout
    alt = (
        "Six log-log panels of relative estimation error of m, c and k against noise level and record length: "
        "the error grows with the noise and falls with the record length, and the reported standard errors "
        "track it."
    )
    return Captioned(fig, caption, "fig-twin-scaling", alt, remark=remark)


def tracking_figure(st: DigitalTwinStudy) -> Captioned:
    """Top: tracked stiffness with two standard deviations and the truth; bottom: CUSUM and threshold."""
    fig, (ax1, ax2) = figure(2, 1, height=4.6, sharex=True)
    tr, det, k_true = st.track, st.alarm, st.scenario.k
    t = tr.t
    blue = case_style("c_nominal")["color"]
    ax1.fill_between(t, tr.k - 2 * tr.k_std, tr.k + 2 * tr.k_std, color=blue, alpha=0.25, lw=0)
    ax1.plot(t, tr.k, lw=1.0, color=blue, label=r"Kalman estimate $\pm 2\sigma$")
    ax1.plot(t, k_true, lw=1.2, **case_style("exact"), label="true $k$")
    ax1.set_ylabel("$k$ (N/m)")
    lo, hi = float(np.min(k_true)), float(np.max(k_true))
    pad = 0.35 * (hi - lo) + 0.02 * hi
    ax1.set_ylim(lo - pad, hi + pad)
    g = np.maximum(det.statistic, 1e-1)
    ax2.semilogy(t, g, lw=1.0, color=blue, label="CUSUM $g$")
    ax2.axhline(det.threshold, lw=1.2, **case_style("threshold"), label="threshold $h$")
    ax2.axvspan(t[0], det.calibration_end, color="0.85", alpha=0.6, lw=0, label="calibration")
    red = OKABE_ITO["vermillion"]
    if det.alarm_time is not None:
        for ax in (ax1, ax2):
            ax.axvline(det.alarm_time, color=red, lw=1.0)
        ax2.plot([det.alarm_time], [det.threshold], "v", color=red, ms=6, label="alarm")
    ax2.set_ylim(1e-1, max(10 * det.threshold, float(np.max(g)) * 2))
    ax2.set_xlabel("$t$ (s)")
    ax2.set_ylabel("$g$ (1)")
    place_legend(ax1, outside=True)
    place_legend(ax2, outside=True)
    top, bottom = panel_words(fig)
    sc = st.scenario
    alarm = f"; a {colour_word(red)} line marks the alarm" if det.alarm_time is not None else ""
    caption = (
        f"{_cap(top)}: the Kalman filter's stiffness estimate (blue) with two standard deviations (shaded) and the "
        f"true stiffness (black dashed). {_cap(bottom)}: the CUSUM statistic (blue, logarithmic axis), the "
        f"threshold h = {det.threshold:g} (grey dotted) and the calibration window (shaded){alarm}."
    )
    when = f"the alarm comes at t = {sig(det.alarm_time, 4)} s" if det.alarm_time is not None else "no alarm is raised"
    remark = (
        f"The asset is healthy to {sc.decline_start:g} s, then its stiffness declines slowly and drops at "
        f"{sc.drop_time:g} s; {when}."
    )
    alt = (
        "Tracked stiffness against time following the true stiffness through its decline and drop, and the CUSUM "
        "statistic against time crossing its threshold after the fault starts."
    )
    return Captioned(fig, caption, "fig-twin-tracking", alt, remark=remark)


def tradeoff_figure(st: DigitalTwinStudy) -> Captioned:
    """Against the threshold h: run length to a false alarm (measured and theory), and the mean detection delay."""
    fig, (ax1, ax2) = figure(1, 2, height=3.4)
    rl = st.run_lengths
    ok = rl.alarms >= MIN_ALARMS
    dots = case_style("measured", marker=True)
    ax1.errorbar(rl.thresholds[ok], rl.measured[ok] * rl.dt, yerr=2 * rl.stderr[ok] * rl.dt, ls="none",
                 marker="o", ms=3.5, color=dots["color"], label="measured")  # fmt: skip
    th = np.isfinite(rl.theory)
    ax1.plot(rl.thresholds[th], rl.theory[th] * rl.dt, lw=1.2, **case_style("exact"), label="Markov chain")
    ax1.set_xscale("log")
    ax1.set_yscale("log")
    ax1.set_ylabel("run length to a false alarm (s)")
    for label, ex in st.detection.items():
        s = FAULT_STYLE[label]
        good = np.isfinite(ex.mean_delay)
        ax2.plot(ex.thresholds[good], ex.mean_delay[good], marker=s["marker"], ms=3.5, lw=1.1, color=s["color"],
                 label=label)  # fmt: skip
    ax2.set_xscale("log")
    ax2.set_ylim(bottom=0)
    ax2.set_ylabel("mean detection delay (s)")
    for ax in (ax1, ax2):
        ax.axvline(st.params.threshold, lw=1.0, **case_style("threshold"))
        ax.set_xlabel("threshold $h$ (1)")
        ax.set_xlim(0.9 * float(np.min(rl.thresholds)), 1.1 * float(np.max(rl.thresholds)))
        _plain_log_ticks(ax, "x")
    place_legend(ax1)
    place_legend(ax2)
    left, right = panel_words(fig)
    faults = " and ".join(f"the {label} ({FAULT_STYLE[label]['word']})" for label in st.detection)
    caption = (
        f"Against the CUSUM threshold h (logarithmic axis; grey dotted: the chosen h = {st.params.threshold:g}). "
        f"{_cap(left)}: the average run length to a false alarm on the healthy records, measured (black dots, ± two "
        f"standard errors) and from Markov-chain theory (black dashed). {_cap(right)}: the mean detection delay of "
        f"{faults}."
    )
    remark = (
        f"The measured run lengths restart the CUSUM after each alarm and are drawn where at least {MIN_ALARMS} "
        "alarms occurred; the theory is drawn as far as the chain computes it. Each mean delay is over its "
        f"{next(iter(st.detection.values())).runs} faulty records."
    )
    alt = (
        "Run length to a false alarm growing roughly exponentially with the threshold, measured points on the "
        "theory curve, and mean detection delays growing with the threshold, longer for the slow decline."
    )
    return Captioned(fig, caption, "fig-twin-tradeoff", alt, remark=remark)
