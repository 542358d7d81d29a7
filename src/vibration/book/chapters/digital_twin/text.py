"""Sentences of the digital-twin chapter and its key-results box, each a function of a :class:`DigitalTwinStudy`.

Every comparison a sentence states is computed here from the study's numbers, so the words follow the
parameters of the run; :func:`paragraphs` lists every paragraph so a test can check that none repeats.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.stats import chi2

from vibration.book.chapters.digital_twin.study import HALFWIDTH_TARGET, MIN_ALARMS, DigitalTwinStudy
from vibration.book.chapters.digital_twin.tables import flag_halfwidth
from vibration.book.presentation.numbers import column, integer, percent, pm, sig
from vibration.book.presentation.tables import cross_reference
from vibration.physics.twin import cusum_variance_ratio

NAMES = ("m", "c", "k")


def sci(value: float, digits: int = 2) -> str:
    """A number for prose, two significant figures unless told (:func:`vibration.book.presentation.numbers.sig`).

    >>> sci(123456.0), sci(0.5), sci(3.2e-7, 2), sci(512.3)
    ('1.2×10⁵', '0.5', '3.2×10⁻⁷', '5.1×10²')
    """
    return sig(value, digits)


def _rel_err(est: float, truth: float) -> float:
    return abs(est / truth - 1.0)


# ----------------------------------------------------------------------------- the key results


def key_results(st: DigitalTwinStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    fit, cov = st.fit, st.coverage
    a = st.assumptions.experiments
    broken = {k: v for k, v in a.items() if k != "as assumed"}
    worst_label = min(broken, key=lambda k: float(np.min(broken[k].coverage)))
    flagged = min(ex.flagged() for ex in broken.values())
    const = next(c for c in st.kalman if c.truth == "constant")
    walk = next(c for c in st.kalman if c.truth == "random walk")
    j = st.threshold_index
    delays = ", ".join(f"{sig(float(ex.mean_delay[j]), 3)} s for the {label}" for label, ex in st.detection.items())
    rl = st.run_lengths
    i = int(np.argmin(np.abs(rl.thresholds - st.params.threshold)))
    arl_h = rl.theory[i] * rl.dt / 3600.0
    arl_text = (
        f"the Markov-chain theory puts the mean time to a false alarm at {sci(arl_h)} h"
        if math.isfinite(arl_h)
        else "the mean time to a false alarm is beyond the Markov chain's numerical reach"
    )
    lines = [
        f"A {sig(fit.n * fit.dt, 3)} s broadband test identifies the stiffness as k = "
        f"{pm(fit.k, fit.stderr[2])} N/m (true {sig(st.asset.k, 6)} N/m); over {integer(cov.runs)} noisy repeats its "
        f"95 % intervals cover the truth in {pm(cov.coverage[2], cov.coverage_uncertainty[2])} of the runs.",
        f"When the records break an assumption the coverage drops, down to "
        f"{sig(float(np.min(a[worst_label].coverage)), 2)} "
        f"({worst_label}); the residual whiteness test flags at least {percent(flagged, 2)} of those records.",
        f"The Kalman filter's stated σ of k is honest when k wanders as the filter assumes (actual/stated "
        f"{pm(walk.ratio, walk.halfwidth)}) and {sig(1 / const.ratio, 2)} times too cautious when k is constant.",
        f"At the threshold h = {st.params.threshold:g} the CUSUM finds the faults after {delays}; {arl_text}, "
        f"and {sig(next(iter(st.detection.values())).monitored_hours * len(st.detection), 3)} h of healthy records "
        "agree with it.",
    ]
    return "\n".join(["> **Key results**", ">"] + [f"> * {s}" for s in lines])


# ----------------------------------------------------------------------------- identification


def identification_sentence(st: DigitalTwinStudy) -> str:
    """What was estimated, how far from the truth in standard errors, and the noise found."""
    fit, truth = st.fit, st.asset
    tv = np.array([truth.m, truth.c, truth.k])
    z = (np.array([fit.m, fit.c, fit.k]) - tv) / fit.stderr
    inside = int(np.sum((fit.ci95[:, 0] <= tv) & (tv <= fit.ci95[:, 1])))
    which = (
        "all three 95 % intervals" if inside == 3 else f"{('none', 'one', 'two')[inside]} of the three 95 % intervals"
    )
    return (
        f"From {integer(fit.n)} samples ({sig((fit.n - 1) * fit.dt, 4)} s at {sig(1 / fit.dt, 4)} Hz) the "
        f"least-squares fit gives m = {pm(fit.m, fit.stderr[0])} kg, c = {pm(fit.c, fit.stderr[1])} N s/m and "
        f"k = {pm(fit.k, fit.stderr[2])} N/m (± one standard error). The estimates sit "
        f"{sig(np.abs(z).max(), 2)} standard errors or less from the truth, and {which} contain it. The residual's "
        f"standard deviation, {sci(fit.sigma, 3)} m, is the estimated sensor noise."
    )


def frf_sentence(st: DigitalTwinStudy) -> str:
    """The frequency-domain estimates against the time-domain fit, read on k."""
    fit, truth = st.fit, st.asset
    ls = _rel_err(fit.k, truth.k)
    fd = {name: _rel_err(e.k, truth.k) for name, e in (("half-power", st.half_power), ("circle-fit", st.circle))
          if e.k is not None and math.isfinite(e.k)}  # fmt: skip
    if not fd:
        return (
            "Neither frequency-domain estimate exists on this record (the resonance peak is not resolved), so the "
            f"time-domain fit, {sig(100 * ls, 2)} % off in k, stands alone."
        )
    best = min(fd, key=fd.get)
    verdict = "more" if fd[best] > ls else "less"
    return (
        "The frequency-domain estimates need a resolved resonance peak, so they read a record "
        f"{integer(round(st.frf_record / (fit.n * fit.dt)))} times longer than the test. Even so the better of "
        "them, the "
        f"{best} estimate, is {sig(100 * fd[best], 2)} % off in k, {verdict} than the time-domain fit's "
        f"{sig(100 * ls, 2)} % on the short record ({cross_reference('tab-twin-identified')})."
    )


# ----------------------------------------------------------------------------- Monte Carlo


def _exponent(x, err, runs) -> tuple[float, float]:
    """Slope of log(err) on log(x) and its 95 % half-width (each log rms error has sd about 1/sqrt(2 R))."""
    lx, ly = np.log(np.asarray(x, float)), np.log(np.asarray(err, float))
    slope = float(np.polyfit(lx, ly, 1)[0])
    sd = 1.0 / np.sqrt(2.0 * np.asarray(runs, float))
    w = (lx - lx.mean()) / float(np.sum((lx - lx.mean()) ** 2))
    return slope, 1.96 * float(np.sqrt(np.sum((w * sd) ** 2)))


def exponents(st: DigitalTwinStudy) -> tuple[tuple[float, float], tuple[float, float]]:
    """Fitted error-scaling exponents of k (noise, record length), each with its 95 % half-width."""
    s = [e.noise for e in st.by_noise]
    d = [e.duration for e in st.by_length]
    return (
        _exponent(s, [e.rel_rmse[2] for e in st.by_noise], [e.runs for e in st.by_noise]),
        _exponent(d, [e.rel_rmse[2] for e in st.by_length], [e.runs for e in st.by_length]),
    )


def _within(value: float, half: float, theory: float) -> str:
    return "consistent" if abs(value - theory) <= half else "not within the uncertainty"


def coverage_sentence(st: DigitalTwinStudy) -> str:
    """Measured coverage with its half-width, and the fitted error-scaling exponents."""
    main = st.coverage
    cov, hw = main.coverage, main.coverage_uncertainty
    ok = bool(np.all(np.abs(cov - 0.95) <= hw))
    (p_s, u_s), (p_d, u_d) = exponents(st)
    verdict = (
        "each within its binomial uncertainty of 95 %, so the intervals are honest"
        if ok
        else "not all within their binomial uncertainty of 95 %, so the intervals are not exactly calibrated here"
    )
    return (
        f"Over {integer(main.runs)} noisy realisations the 95 % intervals contained the true m, c and k in "
        f"{pm(cov[0], hw[0])}, {pm(cov[1], hw[1])} and {pm(cov[2], hw[2])} of the runs, {verdict}. The "
        f"stiffness error grows as the noise level to the power {pm(p_s, u_s)} (least-squares theory: 1, "
        f"{_within(p_s, u_s, 1.0)}) and falls as the record length to the power {pm(p_d, u_d)} (theory "
        f"for a stationary random force: −0.5, {_within(p_d, u_d, -0.5)}); every point of both sweeps draws its "
        "own noise, so neither exponent is fixed by construction."
    )


def assumption_sentence(st: DigitalTwinStudy) -> str:
    """What breaking each assumption does to the coverage, whether the residual tests see it, and the precision."""
    a = st.assumptions
    ref = a.experiments["as assumed"]
    near = abs(ref.flagged() - ref.alpha) <= ref.flagged_uncertainty()
    parts = [
        f"With the records as assumed the whiteness test flags {pm(ref.flagged(), ref.flagged_uncertainty())} of "
        f"the runs ({'consistent with' if near else 'not within the uncertainty of'} its {100 * ref.alpha:g} % "
        "level)."
    ]
    for label, ex in a.experiments.items():
        if label == "as assumed":
            continue
        c = ex.coverage
        parts.append(
            f"{label[:1].upper() + label[1:]}: coverage {column(min(c), 2)} to {column(max(c), 2)}, "
            "whiteness test flags "
            f"{pm(ex.flagged(), ex.flagged_uncertainty())}."
        )
    flags = [ex.flagged() for lb, ex in a.experiments.items() if lb != "as assumed"]
    if min(flags) >= 0.5:
        parts.append(
            "At these magnitudes every broken assumption is flagged in "
            + ("every one of its runs" if min(flags) == 1.0 else f"at least {percent(min(flags), 2)} of its runs")
            + ": a flagged record's intervals should not be read at face value (the test's power at milder "
            "violations is not measured here)."
        )
    else:
        parts.append(
            f"The whiteness test misses some broken assumptions at these magnitudes (flag share as low as "
            f"{percent(min(flags), 2)}): passing it does not make the intervals trustworthy."
        )
    pred = a.predicted.get("coloured sensor noise")
    if pred is not None:
        ex = a.experiments["coloured sensor noise"]
        agree = bool(np.all(np.abs(ex.coverage - pred) <= ex.coverage_uncertainty))
        parts.append(
            f"For coloured noise the first-order (sandwich) coverage, {sig(pred[0], 2)}, {sig(pred[1], 2)} and "
            f"{sig(pred[2], 2)}, {'agrees with' if agree else 'differs from'} the Monte Carlo within its uncertainty."
        )
    largest = flag_halfwidth(st)
    need = math.ceil(1.96**2 * 0.25 / HALFWIDTH_TARGET**2)
    parts.append(
        f"The largest half-width in the table is ± {sig(largest, 2)}"
        + (
            f", within the ± {sig(HALFWIDTH_TARGET, 2)} aimed at."
            if largest <= HALFWIDTH_TARGET
            else f", above the ± {sig(HALFWIDTH_TARGET, 2)} aimed at: a share near one half needs about {need} "
            "runs per "
            "case for that, and the run count is a parameter of the chapter."
        )
    )
    return " ".join(parts)


# ----------------------------------------------------------------------------- tracking and detection


def alarm_sentence(st: DigitalTwinStudy) -> str:
    """Where the single demonstration record raised its alarm, and how much stiffness was lost by then."""
    det, sc = st.alarm, st.scenario
    start = sc.decline_start
    if det.alarm_time is None:
        return (
            f"On this record the detector raised no alarm (threshold {det.threshold:g}): the fault starting at "
            f"{start:g} s stayed below what the noise hides."
        )
    i = int(np.searchsorted(sc.t, det.alarm_time))
    loss = 100.0 * (1.0 - float(sc.k[i]) / float(sc.k[0]))
    when = "after" if det.alarm_time >= start else "before"
    return (
        f"On this record the alarm comes at t = {sig(det.alarm_time, 4)} s, {sig(abs(det.alarm_time - start), 3)} s "
        f"{when} the fault starts ({start:g} s), when the stiffness has lost {sig(loss, 2)} %; the CUSUM's last "
        f"restart puts the onset at {sig(det.change_time, 4)} s."
    )


def kalman_sentence(st: DigitalTwinStudy) -> str:
    """Is the filter's stated standard deviation its actual error? Both truths, with the ratio's uncertainty."""
    const = next(c for c in st.kalman if c.truth == "constant")
    walk = next(c for c in st.kalman if c.truth == "random walk")
    honest = abs(walk.ratio - 1.0) <= walk.halfwidth
    cautious = const.ratio + const.halfwidth < 1.0
    first = (
        f"When the stiffness wanders as a random walk of the filter's own intensity, the actual rms error of k is "
        f"{sig(walk.actual, 3)} N/m against a stated {sig(walk.stated, 3)} N/m: the ratio "
        f"{pm(walk.ratio, walk.halfwidth)} "
        + ("is one within its uncertainty, so the filter's noise model (the calibrated sensor variance and the "
           "linearised step) is not mis-specified." if honest else
           "is not one within its uncertainty, so the filter's noise model is mis-specified.")
    )  # fmt: skip
    second = (
        f"When the stiffness is constant the error is {sig(const.actual, 3)} N/m against the same kind of statement, "
        f"{sig(const.stated, 3)} N/m (ratio {pm(const.ratio, const.halfwidth)})"
        + (
            f": the stated σ is then {sig(1 / const.ratio, 2)} times too cautious. That is the price of the random "
            "walk, an allowance for changes nobody announced; it is what lets the estimate follow a sudden drop, "
            "so read the band as an upper bound on a healthy asset's error."
            if cautious
            else ": the statement holds here too."
        )
    )
    return first + " " + second


def cusum_sentence(st: DigitalTwinStudy) -> str:
    """What the drift is tuned to, the false-alarm rate with its upper bound, and the threshold's margin."""
    label, ex = next(iter(st.detection.items()))
    j = st.threshold_index
    rho = cusum_variance_ratio(st.drift)
    hours = sum(e.monitored_hours for e in st.detection.values())
    alarms = int(sum(round(e.false_alarm_rate[j] * e.monitored_hours) for e in st.detection.values()))
    upper = float(chi2.ppf(0.95, 2 * alarms + 2) / (2.0 * hours))
    peak = max(e.healthy_max for e in st.detection.values())
    h = float(ex.thresholds[j])
    margin = h / peak if peak > 0 else math.inf
    return (
        f"With ν = {st.drift:g} the increment r²/σ² − 1 − ν is the log-likelihood ratio of a Gaussian residual "
        f"whose variance grows by the factor ρ with ln ρ / (1 − 1/ρ) = 1 + ν: the detector is tuned to a "
        f"{sig(rho, 3)}-fold increase of the residual power, not a doubling (a doubling needs ν = "
        f"{sig(2 * math.log(2) - 1, 3)}). Over {2 * ex.runs} healthy records ({sig(hours, 3)} h monitored) it raised "
        f"{alarms} false alarm{'s' if alarms != 1 else ''} at h = {h:g}: a rate below {sig(upper, 2)} per hour at 95 % "
        f"confidence. The highest value the statistic reached on a healthy record was {sig(peak, 3)}, "
        + (f"so the threshold has a margin of {sig(margin, 2)} times." if margin >= 1 else "above the threshold.")
    )


def run_length_sentence(st: DigitalTwinStudy, min_alarms: int = MIN_ALARMS) -> str:
    """Does the theory predict the measured run lengths? The largest disagreement in standard errors."""
    rl = st.run_lengths
    rows = (rl.alarms >= min_alarms) & np.isfinite(rl.theory)
    z = np.abs(rl.measured[rows] - rl.theory[rows]) / rl.stderr[rows]
    j = st.threshold_index
    dz = []
    for label, ex in st.detection.items():
        d = ex.first_crossing[:, j] - ex.change_time
        d = d[np.isfinite(d) & (d >= 0.0)]
        th = st.delay_theory[label].mean_delay
        if d.size > 1 and math.isfinite(th):
            dz.append(abs(float(np.mean(d)) - th) / (float(np.std(d, ddof=1)) / math.sqrt(d.size)))
    worst = float(max(np.max(z, initial=0.0), max(dz, default=0.0)))
    i = int(np.argmin(np.abs(rl.thresholds - st.params.threshold)))
    chosen = rl.theory[i] * rl.dt / 3600.0
    tail = (
        f" At the chosen threshold the chain predicts one false alarm per {sci(chosen)} h of healthy monitoring; "
        f"the {sig(rl.samples * rl.dt / 3600, 3)} h simulated can only bound it, and their {int(rl.alarms[i])} "
        f"alarm{'s' if rl.alarms[i] != 1 else ''} agree{'s' if rl.alarms[i] == 1 else ''} with it."
        if math.isfinite(chosen)
        else " At the chosen threshold the run length is beyond the chain's numerical reach."
    )
    return (
        f"Where the healthy records raise at least {min_alarms} false alarms ({int(np.count_nonzero(rows))} "
        f"thresholds) and for both faults' delays at h = {st.params.threshold:g}, the Markov chain of Brook and "
        f"Evans (1972) predicts the Monte Carlo to within {sig(worst, 2)} standard errors "
        f"({cross_reference('tab-twin-arl')}, {cross_reference('fig-twin-tradeoff')})." + tail
    )


# ----------------------------------------------------------------------------- summary


def summary(st: DigitalTwinStudy) -> str:
    """What a designer takes away, against the best alternative in each comparison (new words, no repeats)."""
    fit, truth = st.fit, st.asset
    ls = _rel_err(fit.k, truth.k)
    fd = [_rel_err(e.k, truth.k) for e in (st.half_power, st.circle) if e.k is not None and math.isfinite(e.k)]
    best = min(fd) if fd else math.nan
    test = fit.n * fit.dt
    bullets = []
    if fd:
        bullets.append(
            "For identification, fit the exact discrete model in the time domain: on a "
            f"{sig(test, 3)} s test it misses "
            f"k by {sig(100 * ls, 2)} %, where the better frequency-domain method, given "
            f"{integer(round(st.frf_record / test))} "
            f"times the data, misses by {sig(100 * best, 2)} %."
        )
    broken = {k: v for k, v in st.assumptions.experiments.items() if k != "as assumed"}
    low = min(float(np.min(v.coverage)) for v in broken.values())
    bullets.append(
        "Trust an interval only from a record whose residual passes the whiteness test: a broken assumption can "
        f"leave a nominal 95 % interval covering the truth as rarely as {percent(low, 2)} of the time."
    )
    const = next(c for c in st.kalman if c.truth == "constant")
    bullets.append(
        f"Read the tracker's band as cautious by about {sig(1 / const.ratio, 2)} times on a steady asset and as exact "
        "only when the stiffness really drifts at random."
    )
    j = st.threshold_index
    slow = max(float(ex.mean_delay[j]) for ex in st.detection.values())
    fast = min(float(ex.mean_delay[j]) for ex in st.detection.values())
    bullets.append(
        f"Size the CUSUM threshold with the Markov chain rather than by trial: it gives the false-alarm rate a "
        f"field trial could not measure in its duration, while the delays it costs stay between {sig(fast, 2)} s and "
        f"{sig(slow, 3)} s for the faults studied here."
    )
    return "\n".join(f"* {b}" for b in bullets)


def paragraphs(st: DigitalTwinStudy) -> list[str]:
    """Every paragraph and bullet the chapter prints, in order (for the no-repetition test)."""
    out = [line[4:] for line in key_results(st).splitlines() if line.startswith("> * ")]
    out += [
        identification_sentence(st),
        frf_sentence(st),
        coverage_sentence(st),
        assumption_sentence(st),
        alarm_sentence(st),
        kalman_sentence(st),
        cusum_sentence(st),
        run_length_sentence(st),
    ]
    out += [line[2:] for line in summary(st).splitlines()]
    return out
