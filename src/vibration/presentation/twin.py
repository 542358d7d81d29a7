"""Figures, tables, sentences and sliders of the digital-twin chapter.

Nothing physical is computed here: every number comes from :mod:`vibration.physics.twin`
(identification, frequency-domain estimates, Monte Carlo experiments, tracking, detection).
The kernel-free panel (:func:`twin_panel_html`) shows *precomputed* identifications on a
grid of noise levels and record lengths (:func:`vibration.physics.twin.estimate_grid`),
embedded as JSON and drawn by ``assets/twin.js``; the JupyterLab explorer
(:class:`TwinExplorer`) re-identifies live.
"""

from __future__ import annotations

import hashlib
import html
import itertools
import json
import math
from importlib.resources import files

import numpy as np

from ..physics.model import Oscillator, ParameterError
from ..physics.twin import (
    AssumptionStudy,
    ChangeDetection,
    CoverageExperiment,
    DetectionExperiment,
    EstimateGrid,
    FrequencyEstimate,
    FrequencyResponse,
    Identification,
    Measurements,
    StiffnessTrack,
    identify,
    random_force,
    synthetic_measurements,
)
from .style import figure, place_legend
from .tables import Column, Missing, Table

__all__ = [
    "TwinExplorer",
    "assumption_sentence",
    "assumption_table",
    "closing_note",
    "coverage_sentence",
    "coverage_table",
    "cusum_sentence",
    "detection_sentence",
    "detection_table",
    "identification_figure",
    "identification_sentence",
    "identification_table",
    "scaling_figure",
    "tracking_figure",
    "tradeoff_figure",
    "twin_checks_table",
    "twin_explorer",
    "twin_panel_html",
]

NAMES = ("m", "c", "k")
UNITS = ("kg", "N s/m", "N/m")


def _val(v, reason: str = "not available"):
    return Missing(reason or "not available") if v is None or (isinstance(v, float) and math.isnan(v)) else v


# ----------------------------------------------------------------------------- identification


def identification_figure(meas: Measurements, fit: Identification, frf: FrequencyResponse, window: float = 20.0):
    """Measured and identified response over the first ``window`` s, and the measured FRF against the model.

    Left: measured response (m or m/s^2) and the identified model's output; right: receptance magnitude
    (m/N) of the Welch estimate, of the identified model and its resonance.
    """
    fig, (ax1, ax2) = figure(1, 2, height=3.4, gridspec_kw={"width_ratios": [1.4, 1.0]})
    sel = meas.t <= meas.t[0] + window
    unit = "m" if fit.sensor == "x" else "m/s$^2$"
    sym = "x" if fit.sensor == "x" else "a"
    model = meas.response - fit.residual
    ax1.plot(meas.t[sel], meas.response[sel], ".", ms=2.0, color="0.55", label="measured")
    ax1.plot(meas.t[sel], model[sel], "-", lw=1.1, label="identified model")
    ax1.set_xlabel("$t$ (s)")
    ax1.set_ylabel(f"${sym}$ ({unit})")
    ax1.set_title("Response to the measured force", loc="left")
    ymax = np.max(np.abs(meas.response[sel]))
    ax1.set_ylim(-1.45 * ymax, 1.45 * ymax)
    place_legend(ax1, ncol=2)
    w = frf.omega
    osc = fit.oscillator
    h_model = 1.0 / np.abs(osc.k - osc.m * w**2 + 1j * osc.c * w)
    keep = frf.force_psd >= 1e-2 * np.max(frf.force_psd)
    ax2.semilogy(w[keep], np.abs(frf.H[keep]), ".", ms=3.0, color="0.55", label="Welch $H_1$")
    ax2.semilogy(w[keep], h_model[keep], "-", lw=1.2, label="identified")
    ax2.set_xlabel(r"$\omega$ (rad/s)")
    ax2.set_ylabel(r"$|H|$ (m/N)")
    ax2.set_title("Receptance", loc="left")
    place_legend(ax2)
    return fig


def identification_table(
    fit: Identification,
    truth: Oscillator,
    hp: FrequencyEstimate,
    cf: FrequencyEstimate,
    frf_record: float | None = None,
) -> Table:
    """Truth, least-squares estimate with standard error and 95 % interval, and the two FRF estimates.

    ``frf_record`` (s): length of the record the FRF estimates come from, when it is not the fit's.
    """
    tv = (truth.m, truth.c, truth.k)
    est = (fit.m, fit.c, fit.k)
    rows = []
    for i, (name, unit) in enumerate(zip(NAMES, UNITS, strict=True)):
        rows.append(
            {
                "p": f"{name} ({unit})",
                "truth": tv[i],
                "est": est[i],
                "se": float(fit.stderr[i]),
                "lo": float(fit.ci95[i, 0]),
                "hi": float(fit.ci95[i, 1]),
                "in": bool(fit.ci95[i, 0] <= tv[i] <= fit.ci95[i, 1]),
                "hp": _val((hp.m, hp.c, hp.k)[i], hp.reason),
                "cf": _val((cf.m, cf.c, cf.k)[i], cf.reason),
            }
        )
    return Table(
        rows,
        [
            Column("p", "parameter"),
            Column("truth", "true", 4),
            Column("est", "least squares", 5),
            Column("se", "std. error", 2),
            Column("lo", "95 % low", 5),
            Column("hi", "95 % high", 5),
            Column("in", "covers truth"),
            Column("hp", "half-power", 3),
            Column("cf", "circle fit", 3),
        ],
        caption="Identified parameters: output-error least squares on the exact discrete model, and the "
        "frequency-domain estimates from the measured FRF.",
        name="tab-twin-identified",
        notes=(
            (
                f"Half-power and circle fit from a separate {frf_record:g} s record (Welch estimate): on the fit's "
                f"{(fit.n - 1) * fit.dt:g} s the frequency bins are too coarse for the resonance peak.",
            )
            if frf_record
            else ()
        ),
    )


def _intervals(inside: int) -> str:
    """How many of the three 95 % intervals, in words.

    Examples
    --------
    >>> _intervals(3), _intervals(1), _intervals(0)
    ('all three 95 % intervals', 'one of the three 95 % intervals', 'none of the three 95 % intervals')
    """
    if inside == 3:
        return "all three 95 % intervals"
    return f"{('none', 'one', 'two')[inside]} of the three 95 % intervals"


def identification_sentence(fit: Identification, truth: Oscillator) -> str:
    """One paragraph: what was estimated, how far from the truth in standard errors, the noise found."""
    tv = np.array([truth.m, truth.c, truth.k])
    z = (np.array([fit.m, fit.c, fit.k]) - tv) / fit.stderr
    inside = int(np.sum((fit.ci95[:, 0] <= tv) & (tv <= fit.ci95[:, 1])))
    unit = "m" if fit.sensor == "x" else "m/s²"
    return (
        f"From {fit.n} samples ({(fit.n - 1) * fit.dt:.4g} s at {1 / fit.dt:.4g} Hz) the least-squares fit gives "
        f"m = {fit.m:.4g} ± {fit.stderr[0]:.2g} kg, c = {fit.c:.4g} ± {fit.stderr[1]:.2g} N s/m and "
        f"k = {fit.k:.5g} ± {fit.stderr[2]:.2g} N/m (± one standard error). The estimates sit "
        f"{np.abs(z).max():.2g} standard errors or less from the truth, and {_intervals(inside)} "
        f"contain it. The residual's standard deviation, {fit.sigma:.3g} {unit}, is the estimated sensor noise."
    )


# ----------------------------------------------------------------------------- Monte Carlo


def coverage_table(experiments: list[CoverageExperiment]) -> Table:
    """Coverage of the 95 % intervals and relative errors, one row per experiment."""
    rows = []
    halfwidth = {ex.runs: float(ex.coverage_halfwidth[0]) for ex in experiments}
    for ex in experiments:
        cov, rmse, se = ex.coverage, ex.rel_rmse, ex.rel_stderr
        rows.append(
            {
                "noise": ex.noise,
                "T": ex.duration,
                "R": ex.runs,
                "cm": cov[0],
                "cc": cov[1],
                "ck": cov[2],
                "em": 100 * rmse[0],
                "ec": 100 * rmse[1],
                "ek": 100 * rmse[2],
                "ratio": float(np.mean(rmse / se)),
            }
        )
    return Table(
        rows,
        [
            Column("noise", "noise / rms", 2),
            Column("T", "T (s)", 3),
            Column("R", "runs"),
            Column("cm", "coverage m", 3),
            Column("cc", "coverage c", 3),
            Column("ck", "coverage k", 3),
            Column("em", "rms error m (%)", 2),
            Column("ec", "rms error c (%)", 2),
            Column("ek", "rms error k (%)", 2),
            Column("ratio", "rms error / std. error", 3),
        ],
        caption="Monte Carlo: how often the 95 % intervals contain the truth, and the relative errors.",
        name="tab-twin-coverage",
        notes=(
            "Coverage of R runs has a binomial 95 % half-width of about 1.96 √(0.95·0.05/R) ("
            + ", ".join(f"{halfwidth[r]:.3f} for {r} runs" for r in sorted(halfwidth, reverse=True))
            + ").",
        ),
    )


def _exponent(x, err, runs) -> tuple[float, float]:
    """Slope of log(err) on log(x) and its 95 % half-width (each log rms error has sd about 1/sqrt(2 R))."""
    lx, ly = np.log(np.asarray(x, float)), np.log(np.asarray(err, float))
    slope = float(np.polyfit(lx, ly, 1)[0])
    sd = 1.0 / np.sqrt(2.0 * np.asarray(runs, float))
    w = (lx - lx.mean()) / float(np.sum((lx - lx.mean()) ** 2))
    return slope, 1.96 * float(np.sqrt(np.sum((w * sd) ** 2)))


def _within(value: float, half: float, theory: float) -> str:
    return "consistent" if abs(value - theory) <= half else "not within the uncertainty"


def coverage_sentence(main: CoverageExperiment, by_noise: list[CoverageExperiment], by_length) -> str:
    """Measured coverage and the fitted error scaling exponents (from the experiments)."""
    cov = main.coverage
    half = float(main.coverage_halfwidth[0])
    ok = bool(np.all(np.abs(cov - 0.95) <= half))
    s = np.array([ex.noise for ex in by_noise])
    e_s = np.array([ex.rel_rmse[2] for ex in by_noise])
    d = np.array([ex.duration for ex in by_length])
    e_d = np.array([ex.rel_rmse[2] for ex in by_length])
    p_s, u_s = _exponent(s, e_s, [ex.runs for ex in by_noise])
    p_d, u_d = _exponent(d, e_d, [ex.runs for ex in by_length])
    verdict = (
        "within the binomial uncertainty of 95 %, so the intervals are honest"
        if ok
        else "outside the binomial uncertainty of 95 %, so the intervals are not exactly calibrated here"
    )
    return (
        f"Over {main.runs} noisy realisations the 95 % intervals contained the true m, c and k in "
        f"{100 * cov[0]:.1f} %, {100 * cov[1]:.1f} % and {100 * cov[2]:.1f} % of the runs (± {100 * half:.1f} % "
        f"binomial), {verdict}. The stiffness error grows as the noise level to the power {p_s:.2f} ± {u_s:.2f} "
        f"(least-squares theory: 1, {_within(p_s, u_s, 1.0)}) and falls as the record length T to the power "
        f"{p_d:.2f} ± {u_d:.2f} (theory for a stationary random force: −0.5, {_within(p_d, u_d, -0.5)}); ± is "
        "the 95 % half-width from the sampling error of each point's rms error, every point with its own noise."
    )


def _pm(value: float, half: float) -> str:
    """A share with its 95 % half-width, two decimals: ``0.93 ± 0.04``."""
    return f"{value:.2f} ± {half:.2f}"


def _case_text(label: str, st: AssumptionStudy) -> str:
    return {
        "as assumed": f"white sensor noise, {st.noise:g} of the rms response",
        "noise on the force": f"white noise of {st.force_noise:g} of the rms force on the force, none on the response",
        "noise on both channels": f"{st.force_noise:g} of the rms force on the force, {st.noise:g} of the rms "
        "response on the response",
        "coloured sensor noise": f"AR(1) sensor noise, lag-one correlation {st.colour:g}, {st.noise:g} of the rms "
        "response",
        "unmodelled cubic spring": f"a cubic spring force k₃x³, k₃ = {st.k3:.3g} N/m³ ({100 * st.cubic:g} % of kx "
        "at the "
        f"rms displacement), white sensor noise {st.noise:g} of the rms response",
    }.get(label, label)


def assumption_table(st: AssumptionStudy) -> Table:
    """Per case: coverage of the 95 % intervals of m, c, k (± Wilson half-width), first-order prediction, bias of k,
    and the share of runs each residual test flags (± half-width)."""
    rows = []
    for label, ex in st.experiments.items():
        cov, hw = ex.coverage, ex.coverage_uncertainty
        pred = st.predicted.get(label)
        rows.append(
            {
                "case": label,
                "what": _case_text(label, st),
                "R": ex.runs,
                "cm": _pm(cov[0], hw[0]),
                "cc": _pm(cov[1], hw[1]),
                "ck": _pm(cov[2], hw[2]),
                "pk": float(pred[2]) if pred is not None else Missing("no first-order prediction"),
                "bk": 100 * float(ex.rel_bias[2]),
                "se": float(np.mean(ex.rel_rmse / ex.rel_stderr)),
                "lb": _pm(ex.flagged("whiteness"), ex.flagged_uncertainty("whiteness")),
                "ic": _pm(ex.flagged("input"), ex.flagged_uncertainty("input")),
            }
        )
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("what", "what the records carry"),
            Column("R", "runs"),
            Column("cm", "coverage m"),
            Column("cc", "coverage c"),
            Column("ck", "coverage k"),
            Column("pk", "first-order coverage k", 2),
            Column("bk", "mean error k (%)", 2),
            Column("se", "rms error / std. error", 3),
            Column("lb", "whiteness test flags"),
            Column("ic", "input-correlation test flags"),
        ],
        caption="Coverage of the 95 % intervals, and the share of runs the residual tests flag at the 5 % level, "
        "when the records break one assumption at a time.",
        name="tab-twin-assumptions",
        notes=(
            "± : half-width of the Wilson 95 % interval of the share (binomial, over the runs of the row). Each row "
            "draws its own noise; all rows share one force record (the coverage is conditional on that design).",
            f"Whiteness: Ljung–Box statistic of the output-error residual over {st.lags} lags, χ² with {st.lags} "
            f"degrees of freedom. Input correlation: residual against the measured force at lags 0 to {st.lags - 1} "
            "(χ² with the rank of the force's lag covariance); it assumes a white residual, so coloured noise "
            "trips it too.",
            "First-order coverage: 2Φ(q σ_assumed/σ_true) − 1 from the sandwich covariance with the exact "
            "Jacobian at the truth; it applies to Gaussian white or AR(1) noise on the response only (a noisy "
            "force biases the estimate at second order and a cubic spring is model error).",
        ),
    )


def assumption_sentence(st: AssumptionStudy, target: float = 0.03) -> str:
    """What breaking each assumption does to the coverage, whether the residual tests see it, and the precision."""
    ref = st.experiments["as assumed"]
    cov, hw = ref.coverage, ref.coverage_uncertainty
    near = abs(ref.flagged() - ref.alpha) <= ref.flagged_uncertainty()
    parts = [
        f"Under the stated assumptions the 95 % intervals of m, c and k cover the truth in "
        f"{_pm(cov[0], hw[0])}, {_pm(cov[1], hw[1])} and {_pm(cov[2], hw[2])} of {ref.runs} runs, and the "
        f"whiteness test flags {_pm(ref.flagged(), ref.flagged_uncertainty())} of them "
        f"({'consistent with' if near else 'not within the uncertainty of'} its {100 * ref.alpha:g} % level)."
    ]
    worst = []
    for label, ex in st.experiments.items():
        if label == "as assumed":
            continue
        c = ex.coverage
        worst.append(float(np.min(c)))
        parts.append(
            f"{label.capitalize()}: coverage {min(c):.2f} to {max(c):.2f}, whiteness test flags "
            f"{_pm(ex.flagged(), ex.flagged_uncertainty())}."
        )
    flags = [ex.flagged() for lb, ex in st.experiments.items() if lb != "as assumed"]
    parts.append(
        "At these magnitudes every broken assumption is flagged in "
        + ("every one of its runs" if min(flags) == 1.0 else f"at least {100 * min(flags):.0f} % of its runs")
        + ": "
        "a flagged record's intervals should not be read at face value (the test's power at milder violations "
        "is not measured here)."
        if min(flags) >= 0.5
        else f"The whiteness test misses some broken assumptions at these magnitudes (flag share as low as "
        f"{100 * min(flags):.0f} %): passing it does not make the intervals trustworthy."
    )
    pred = st.predicted.get("coloured sensor noise")
    if pred is not None:
        ex = st.experiments["coloured sensor noise"]
        agree = bool(np.all(np.abs(ex.coverage - pred) <= ex.coverage_uncertainty))
        parts.append(
            f"For coloured noise the first-order (sandwich) coverage, {pred[0]:.2f}, {pred[1]:.2f} and "
            f"{pred[2]:.2f}, {'agrees with' if agree else 'differs from'} the Monte Carlo within its uncertainty."
        )
    largest = max(float(np.max(ex.coverage_uncertainty)) for ex in st.experiments.values())
    need = math.ceil(1.96**2 * 0.25 / target**2)
    parts.append(
        f"The largest half-width in the table is ± {largest:.2f}"
        + (
            f"; every share is within ± {100 * target:g} %."
            if largest <= target
            else f", above the ± {100 * target:g} % aimed at: a coverage near one half needs about {need} runs per "
            "case for "
            "that, more than this chapter's time budget; the run count is a parameter of the chapter."
        )
    )
    return " ".join(parts)


def scaling_figure(by_noise: list[CoverageExperiment], by_length: list[CoverageExperiment]):
    """Relative rms error of m, c, k against noise level and record length, with the reported standard errors."""
    fig, (ax1, ax2) = figure(1, 2, height=3.3)
    for ax, exps, xs, xlabel in (
        (ax1, by_noise, [e.noise for e in by_noise], "noise std. / rms response"),
        (ax2, by_length, [e.duration for e in by_length], "record length $T$ (s)"),
    ):
        for i, name in enumerate(NAMES):
            color = f"C{i}"
            ax.loglog(xs, [100 * e.rel_rmse[i] for e in exps], "o", color=color, ms=4, label=f"${name}$ rms error")
            ax.loglog(xs, [100 * e.rel_stderr[i] for e in exps], "-", color=color, lw=1.0, label=f"${name}$ std. error")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("relative error (%)")
        _plain_log_ticks(ax, "x")
        _plain_log_ticks(ax, "y")
    ax1.set_title(f"$T$ = {by_noise[0].duration:g} s", loc="left")
    ax2.set_title(f"noise = {by_length[0].noise:g} of rms", loc="left")
    place_legend(ax2, outside=True)
    return fig


# ----------------------------------------------------------------------------- tracking and detection


def tracking_figure(track: StiffnessTrack, k_true, detection: ChangeDetection):
    """Top: tracked stiffness with ±2 standard deviations and the true history; bottom: CUSUM and threshold."""
    fig, (ax1, ax2) = figure(2, 1, height=4.6, sharex=True)
    t = track.t
    ax1.fill_between(t, track.k - 2 * track.k_std, track.k + 2 * track.k_std, color="C0", alpha=0.25, lw=0)
    ax1.plot(t, track.k, "-", color="C0", lw=1.0, label=r"Kalman estimate $\pm 2\sigma$")
    ax1.plot(t, k_true, "--", color="k", lw=1.2, label="true $k$")
    ax1.set_ylabel("$k$ (N/m)")
    lo, hi = float(np.min(k_true)), float(np.max(k_true))
    pad = 0.35 * (hi - lo) + 0.02 * hi
    ax1.set_ylim(lo - pad, hi + pad)
    g = np.maximum(detection.statistic, 1e-1)
    ax2.semilogy(t, g, "-", color="C1", lw=1.0, label="CUSUM $g$")
    ax2.axhline(detection.threshold, color="C3", ls=":", lw=1.2, label="threshold")
    ax2.axvspan(t[0], detection.calibration_end, color="0.85", alpha=0.6, lw=0, label="calibration")
    if detection.alarm_time is not None:
        for ax in (ax1, ax2):
            ax.axvline(detection.alarm_time, color="C3", lw=1.0)
        ax2.plot([detection.alarm_time], [detection.threshold], "v", color="C3", ms=6, label="alarm")
    ax2.set_ylim(1e-1, max(10 * detection.threshold, float(np.max(g)) * 2))
    ax2.set_xlabel("$t$ (s)")
    ax2.set_ylabel("$g$ (1)")
    place_legend(ax1, outside=True)
    place_legend(ax2, outside=True)
    return fig


def tradeoff_figure(experiments: dict[str, DetectionExperiment]):
    """As the CUSUM threshold varies: false alarm probability per record (left), mean detection delay (right)."""
    fig, (ax1, ax2) = figure(1, 2, height=3.3)
    for i, (label, ex) in enumerate(experiments.items()):
        ax1.plot(ex.thresholds, ex.false_alarm_probability, "o-", color=f"C{i}", ms=3.5, lw=1.1, label=label)
        ok = np.isfinite(ex.mean_delay)
        ax2.plot(ex.thresholds[ok], ex.mean_delay[ok], "o-", color=f"C{i}", ms=3.5, lw=1.1, label=label)
    for ax in (ax1, ax2):
        ax.set_xscale("log")
        ax.set_xlabel("threshold $h$ (1)")
        _plain_log_ticks(ax, "x")
    ax1.set_ylabel("false alarm probability per record")
    ax2.set_ylabel("mean detection delay (s)")
    ax2.set_ylim(bottom=0)
    place_legend(ax1)
    place_legend(ax2)
    return fig


def _plain_log_ticks(ax, which: str) -> None:
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    axis = ax.xaxis if which == "x" else ax.yaxis
    axis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def detection_table(experiments: dict[str, DetectionExperiment], threshold: float) -> Table:
    """False alarms and detection at the chosen threshold, one row per fault scenario."""
    rows = []
    for label, ex in experiments.items():
        j = int(np.argmin(np.abs(ex.thresholds - threshold)))
        delay = float(ex.mean_delay[j])
        rows.append(
            {
                "fault": label,
                "h": float(ex.thresholds[j]),
                "R": ex.runs,
                "fa": float(ex.false_alarm_probability[j]),
                "far": float(ex.false_alarm_rate[j]),
                "faru": float(ex.false_alarm_rate_upper[j]),
                "gmax": ex.healthy_max,
                "margin": float(ex.thresholds[j]) / ex.healthy_max if ex.healthy_max > 0 else Missing("g stayed 0"),
                "pd": float(ex.detection_probability[j]),
                "delay": delay if math.isfinite(delay) else Missing("no fault detected"),
            }
        )
    return Table(
        rows,
        [
            Column("fault", "fault"),
            Column("h", "threshold h", 3),
            Column("R", "runs of each kind"),
            Column("fa", "false alarm probability", 3),
            Column("far", "false alarms (1/h)", 3),
            Column("faru", "95 % upper bound (1/h)", 2),
            Column("gmax", "largest healthy g", 3),
            Column("margin", "h / largest healthy g", 3),
            Column("pd", "detection probability", 3),
            Column("delay", "mean delay (s)", 3),
        ],
        caption="Change detection at the chosen CUSUM threshold over seeded healthy and faulty records.",
        name="tab-twin-detection",
        notes=(
            "False alarm probability: fraction of records (healthy, plus faulty ones alarmed before the fault) "
            "with an alarm; false alarms per hour count the healthy records only, with the exact one-sided 95 % "
            "Poisson upper bound over their monitored hours. Largest healthy g: the highest value the CUSUM reached "
            "on any healthy record; the threshold's margin is h over it. Delay: alarm time minus fault start.",
        ),
    )


def cusum_sentence(experiments: dict[str, DetectionExperiment], threshold: float) -> str:
    """What the CUSUM's drift is tuned to, and the false-alarm rate with its upper bound and the threshold's margin."""
    from ..physics.twin import cusum_variance_ratio

    label, ex = next(iter(experiments.items()))
    j = int(np.argmin(np.abs(ex.thresholds - threshold)))
    rho = cusum_variance_ratio(ex.drift)
    alarms = int(round(ex.false_alarm_rate[j] * ex.monitored_hours))
    margin = float(ex.thresholds[j]) / ex.healthy_max if ex.healthy_max > 0 else math.inf
    return (
        f"With ν = {ex.drift:g} the increment r²/σ² − 1 − ν is the log-likelihood ratio of a Gaussian residual whose "
        f"variance grows by the factor ρ with ln ρ / (1 − 1/ρ) = 1 + ν: the detector is tuned to a {rho:.3g}-fold "
        f"increase of the residual power, not a doubling (a doubling needs ν = {2 * math.log(2) - 1:.3f}). "
        f"Over the {label} experiment's {ex.runs} healthy records ({ex.monitored_hours:.3g} h monitored) it "
        f"raised {alarms} "
        f"false alarm{'s' if alarms != 1 else ''} at h = {ex.thresholds[j]:g}: a rate below "
        f"{ex.false_alarm_rate_upper[j]:.2g} per hour at 95 % confidence. The highest value the statistic reached "
        f"on a healthy record was {ex.healthy_max:.3g}, "
        + (f"so the threshold has a margin of {margin:.2g} times." if margin >= 1 else "above the threshold.")
    )


def detection_sentence(detection: ChangeDetection, change_time: float, k_true, t) -> str:
    """Where the single demonstration record raised its alarm, and how much stiffness was lost by then."""
    if detection.alarm_time is None:
        return (
            f"On this record the detector raised no alarm (threshold {detection.threshold:g}): the fault starting "
            f"at {change_time:g} s stayed below what the noise hides."
        )
    i = int(np.searchsorted(t, detection.alarm_time))
    loss = 100.0 * (1.0 - float(k_true[i]) / float(k_true[0]))
    when = "after" if detection.alarm_time >= change_time else "before"
    return (
        f"On this record the alarm comes at t = {detection.alarm_time:.4g} s, "
        f"{abs(detection.alarm_time - change_time):.3g} s "
        f"{when} the fault starts ({change_time:g} s), when the stiffness has lost {loss:.2g} %; the CUSUM's last "
        f"restart puts the onset at {detection.change_time:.4g} s."
    )


def twin_checks_table(checks: dict[str, tuple[float, float]]) -> Table:
    """Self-checks printed as bounds: name -> (measured value, bound)."""
    rows = []
    for name, (value, bound) in checks.items():
        mant, exp = f"{bound:.0e}".split("e")  # "1e-8" as the other chapters print bounds, not "1e-08"
        rows.append({"check": name, "bound": f"< {mant}e{int(exp)}", "ok": bool(value < bound)})
    return Table(
        rows,
        [Column("check", "check"), Column("bound", "measured difference"), Column("ok", "passes")],
        caption="Checks of the exact discretisation against independent methods.",
        name="tab-twin-checks",
    )


def closing_note(
    main: CoverageExperiment, by_noise, by_length, experiments: dict[str, DetectionExperiment], threshold: float
) -> str:
    """The chapter's closing numbers: coverage, errors, detection delay and false alarm rate."""
    parts = [coverage_sentence(main, by_noise, by_length)]
    err = ", ".join(f"{n} {100 * e:.2g} %" for n, e in zip(NAMES, main.rel_rmse, strict=True))
    parts.append(f"At noise {main.noise:g} of the rms response and T = {main.duration:g} s the rms errors are {err}.")
    for label, ex in experiments.items():
        j = int(np.argmin(np.abs(ex.thresholds - threshold)))
        d = ex.mean_delay[j]
        delay = f"a mean delay of {d:.3g} s" if math.isfinite(d) else "no detection"
        parts.append(
            f"{label.capitalize()}: at threshold {ex.thresholds[j]:.3g} the detector found "
            f"{100 * ex.detection_probability[j]:.0f} % "
            f"of the faults with {delay}, and raised false alarms on {100 * ex.false_alarm_probability[j]:.1f} % of "
            f"the records ({ex.false_alarm_rate[j]:.2g} per hour of healthy monitoring)."
        )
    return " ".join(parts)


# ----------------------------------------------------------------------------- sliders

_counter = itertools.count(1)


def _asset(name: str) -> str:
    return files("vibration.presentation").joinpath("assets", name).read_text(encoding="utf-8")


def _grid_payload(grid: EstimateGrid) -> dict:
    return {
        "names": list(NAMES),
        "units": list(UNITS),
        "truth": grid.truth.tolist(),
        "noises": grid.noises.tolist(),
        "durations": grid.durations.tolist(),
        "estimates": grid.estimates.tolist(),
        "ci95": grid.ci95.tolist(),
    }


def twin_panel_html(grid: EstimateGrid, *, panel_id: str | None = None) -> str:
    """Self-contained HTML (no kernel, no network): noise and record-length sliders over precomputed fits.

    Parameters
    ----------
    grid : EstimateGrid
        One identification per (noise, record length), from
        :func:`vibration.physics.twin.estimate_grid`.
    panel_id : str, optional
        Element id prefix (a letter, then letters, digits, ``_`` or ``-``).

    Examples
    --------
    >>> from vibration.physics.twin import EstimateGrid
    >>> g = EstimateGrid(np.array([1.0, 0.5, 20.0]), np.array([0.01]), np.array([10.0]),
    ...                  np.ones((1, 1, 3)), np.ones((1, 1, 3, 2)))
    >>> frag = twin_panel_html(g)
    >>> frag.startswith('<div class="twin-panel"'), "http" in frag
    (True, False)
    """
    import re

    if panel_id is not None and not re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]*", panel_id):
        raise ParameterError(f"panel_id = {panel_id!r}: allowed a letter followed by letters, digits, _ or -")
    payload = _grid_payload(grid)
    text = json.dumps(payload, sort_keys=True)
    pid = panel_id or f"twin-{hashlib.sha1(text.encode()).hexdigest()[:8]}-{next(_counter)}"
    e = html.escape
    ni, nj = grid.noises.size, grid.durations.size
    i0, j0 = ni // 2, nj // 2
    rows = "\n".join(
        f'<tr><th scope="row">{n} ({u})</th><td class="twin-true"></td><td class="twin-est"></td>'
        f'<td class="twin-lo"></td><td class="twin-hi"></td><td class="twin-in"></td></tr>'
        for n, u in zip(NAMES, UNITS, strict=True)
    )
    return f"""<div class="twin-panel" id="{e(pid)}" data-grid="{e(text)}">
<style>
{_asset("twin.css")}</style>
<h3 class="twin-title">Noise and record length against the estimates (precomputed)</h3>
<p class="twin-sub">Each position of the sliders shows one identification computed when the report was built \
(same force and noise draw throughout; only the slider's quantity changes). Bars: 95 % intervals of the \
relative error; dashed line: the truth.</p>
<noscript>This panel needs JavaScript to draw its plot.</noscript>
<div class="twin-controls">
<label for="{e(pid)}-noise">noise std. / rms response</label>
<input type="range" class="twin-noise" id="{e(pid)}-noise" min="0" max="{ni - 1}" step="1" value="{i0}">
<output class="twin-noise-out" for="{e(pid)}-noise"></output>
<label for="{e(pid)}-len">record length T</label>
<input type="range" class="twin-len" id="{e(pid)}-len" min="0" max="{nj - 1}" step="1" value="{j0}">
<output class="twin-len-out" for="{e(pid)}-len"></output>
</div>
<svg class="twin-plot" viewBox="0 0 640 200" role="img" \
aria-label="relative error of m, c and k in percent with 95 % intervals"></svg>
<table class="twin-readout">
<thead><tr><th>parameter</th><th>true</th><th>estimate</th><th>95 % low</th><th>95 % high</th>\
<th>covers truth</th></tr></thead>
<tbody>
{rows}
</tbody></table>
<script>
{_asset("twin.js")}</script>
<script>window.vibrationTwin.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


class TwinExplorer:
    """JupyterLab explorer: noise and record-length sliders re-identifying a seeded record live.

    Its ``_repr_mimebundle_`` returns the widget view and, for renderers without a
    kernel (the book), :func:`twin_panel_html` over ``grid``.
    """

    def __init__(
        self,
        osc: Oscillator,
        grid: EstimateGrid,
        *,
        dt: float = 0.02,
        seed: int = 0,
        band: tuple[float, float] = (0.1, 2.0),
        rms: float = 2.0,
    ):
        import ipywidgets as widgets

        self.osc, self.grid, self.dt, self.seed = osc, grid, dt, seed
        t = np.arange(int(round(float(np.max(grid.durations)) / dt)) + 1) * dt
        self._t = t
        self._force = random_force(t, band=band, rms=rms, seed=seed)
        self._clean = synthetic_measurements(osc, t, self._force).x
        self._draw = np.random.default_rng(seed + 1).standard_normal(t.size)
        self.noise_slider = widgets.SelectionSlider(
            options=[(f"{v:g}", float(v)) for v in grid.noises],
            value=float(grid.noises[grid.noises.size // 2]),
            description="noise / rms",
            continuous_update=False,
        )
        self.length_slider = widgets.SelectionSlider(
            options=[(f"{v:g} s", float(v)) for v in grid.durations],
            value=float(grid.durations[grid.durations.size // 2]),
            description="T",
            continuous_update=False,
        )
        self.readout = widgets.HTML()
        self.noise_slider.observe(lambda _: self.update(), "value")
        self.length_slider.observe(lambda _: self.update(), "value")
        self.box = widgets.VBox([self.noise_slider, self.length_slider, self.readout])
        self.fit: Identification | None = None
        self.update()

    def update(self) -> None:
        """Identify the record at the current slider values and refresh the readout."""
        n = int(round(self.length_slider.value / self.dt)) + 1
        clean = self._clean[:n]
        y = clean + self.noise_slider.value * float(np.sqrt(np.mean(clean**2))) * self._draw[:n]
        fit = identify(self._t[:n], self._force[:n], x=y, search="local")
        self.fit = fit
        truth = (self.osc.m, self.osc.c, self.osc.k)
        cells = []
        for i, (name, unit) in enumerate(zip(NAMES, UNITS, strict=True)):
            est, (lo, hi) = (fit.m, fit.c, fit.k)[i], fit.ci95[i]
            inside = "yes" if lo <= truth[i] <= hi else "no"
            cells.append(
                f"<tr><th>{name} ({unit})</th><td>{truth[i]:.4g}</td><td>{est:.5g}</td>"
                f"<td>{lo:.5g}</td><td>{hi:.5g}</td><td>{inside}</td></tr>"
            )
        self.readout.value = (
            "<table><tr><th>parameter</th><th>true</th><th>estimate</th><th>95 % low</th><th>95 % high</th>"
            "<th>covers truth</th></tr>" + "".join(cells) + "</table>"
        )

    def _repr_mimebundle_(self, **kwargs):
        data = self.box._repr_mimebundle_(**kwargs) or {}
        data["text/html"] = twin_panel_html(self.grid)
        data["text/plain"] = (
            f"TwinExplorer(noise={self.noise_slider.value:g} of rms, T={self.length_slider.value:g} s, "
            f"m={self.osc.m:g} kg, c={self.osc.c:g} N s/m, k={self.osc.k:g} N/m)"
        )
        return data


def twin_explorer(
    osc: Oscillator,
    grid: EstimateGrid,
    *,
    dt: float = 0.02,
    seed: int = 0,
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
) -> TwinExplorer:
    """The JupyterLab explorer (live) with the precomputed kernel-free panel for the book; see :class:`TwinExplorer`.

    ``dt`` (s), ``seed``, ``band`` (Hz) and ``rms`` (N) must be those the grid was computed with.
    """
    return TwinExplorer(osc, grid, dt=dt, seed=seed, band=band, rms=rms)
