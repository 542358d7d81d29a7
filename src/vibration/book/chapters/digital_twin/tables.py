"""Tables of the digital-twin chapter, each a function of a :class:`DigitalTwinStudy`.

One number of significant digits per column; a share is printed with its Wilson 95 % half-width; a
quantity that does not exist is :class:`~vibration.book.presentation.tables.Missing` with the reason.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.digital_twin.study import KALMAN_BLOCK, KALMAN_SETTLE, MIN_ALARMS, DigitalTwinStudy
from vibration.book.presentation.numbers import integer, pm, sig
from vibration.book.presentation.tables import Approx, Missing, Table, columns
from vibration.physics.twin import binomial_halfwidth

#: A rounding-level check value is compared with its reference within this fraction of its bound.
ROUNDING_MARGIN = 0.01

NAMES = ("m", "c", "k")
UNITS = ("kg", "N s/m", "N/m")


def _val(v, reason: str):
    return Missing(reason=reason or "not available") if v is None or (isinstance(v, float) and math.isnan(v)) else v


def checks_table(st: DigitalTwinStudy) -> Table:
    """The exact discretisation against three independent references: measured difference and its bound."""
    rows = []
    for name, (value, bound, rounding) in st.checks.items():
        cell = Approx(value=value, atol=ROUNDING_MARGIN * bound) if rounding else value
        rows.append({"check": name, "value": cell, "bound": bound, "ok": value < bound})
    rows.append(
        {
            "check": "batch Monte Carlo fit against the one-record fit (relative, m, c, k and their standard errors)",
            "value": Approx(value=st.batch_agreement, atol=ROUNDING_MARGIN * 1e-5),
            "bound": 1e-5,
            "ok": st.batch_agreement < 1e-5,
        }
    )
    p = st.params
    return Table(
        rows=rows,
        columns=columns(
            """
            check  check
            value  measured difference  2
            bound  bound                2
            ok     passes
            """
        ),
        caption="Checks of the exact discretisation and of the batch identification against independent methods.",
        name="tab-twin-checks",
        notes=(
            f"Sine check: rms force {p.F_rms:g} N at the band's upper edge {p.f_max:g} Hz, sampled every {p.dt:g} s; "
            "its bound is h²ω²F₀/8 times the integral of the impulse response's magnitude (m). The other "
            "differences are relative and at the level of floating-point rounding, so their last digits vary "
            "from one computer to another.",
        ),
    )


def identification_table(st: DigitalTwinStudy) -> Table:
    """Truth, least-squares estimate with standard error and 95 % interval, and the two FRF estimates."""
    fit, truth, hp, cf = st.fit, st.asset, st.half_power, st.circle
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
        rows=rows,
        columns=columns(
            """
            p      parameter
            truth  true           4
            est    least squares  5
            se     std. error     2
            lo     95 % low       5
            hi     95 % high      5
            in     covers truth
            hp     half-power     3
            cf     circle fit     3
            """
        ),
        caption="Identified parameters: output-error least squares on the exact discrete model, and the "
        "frequency-domain estimates from the measured frequency response.",
        name="tab-twin-identified",
        notes=(
            f"Half-power and circle fit read a separate {st.frf_record:g} s record (Welch estimate): on the fit's "
            f"{(fit.n - 1) * fit.dt:g} s the frequency bins are too coarse for the resonance peak.",
        ),
    )


def coverage_table(st: DigitalTwinStudy) -> Table:
    """Coverage of the 95 % intervals (Wilson half-widths), one row per experiment; the errors go to the CSV file."""
    rows = []
    exps = [("main", st.coverage)] + [("noise sweep", e) for e in st.by_noise]
    exps += [("length sweep", e) for e in st.by_length]
    for what, ex in exps:
        cov, hw, rmse, se = ex.coverage, ex.coverage_uncertainty, ex.rel_rmse, ex.rel_stderr
        rows.append(
            {
                "what": what,
                "noise": ex.noise,
                "T": ex.duration,
                "R": ex.runs,
                "cm": pm(cov[0], hw[0]),
                "cc": pm(cov[1], hw[1]),
                "ck": pm(cov[2], hw[2]),
                "em": 100 * rmse[0],
                "ec": 100 * rmse[1],
                "ek": 100 * rmse[2],
                "ratio": float(np.mean(rmse / se)),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            what   experiment
            noise  noise / rms             2
            T      T (s)                   3
            R      runs
            cm     coverage m
            cc     coverage c
            ck     coverage k
            em     rms error m (%)         2  hidden
            ec     rms error c (%)         2  hidden
            ek     rms error k (%)         2  hidden
            ratio  rms error / std. error  3  hidden
            """
        ),
        # the errors (in the CSV file and the plain text) are drawn in the next figure
        caption="Monte Carlo: how often the 95 % intervals contain the truth; the next figure draws the errors.",
        name="tab-twin-coverage",
        notes=(
            "± : half-width of the Wilson 95 % interval of the coverage over the row's runs. Every row draws its own "
            "noise; all rows share one force record of their length.",
        ),
    )


def _case_text(label: str, st: DigitalTwinStudy) -> str:
    a = st.assumptions
    return {
        "as assumed": f"white sensor noise, {a.noise:g} of the rms response",
        "noise on the force": f"white noise of {a.force_noise:g} of the rms force on the force, none on the response",
        "noise on both channels": f"{a.force_noise:g} of the rms force on the force, {a.noise:g} of the rms "
        "response on the response",
        "coloured sensor noise": f"AR(1) sensor noise, lag-one correlation {a.colour:g}, {a.noise:g} of the rms "
        "response",
        "unmodelled cubic spring": f"a cubic spring force k₃x³, k₃ = {sig(a.k3, 3)} N/m³ ({100 * a.cubic:g} % of kx "
        f"at the rms displacement), white sensor noise {a.noise:g} of the rms response",
    }.get(label, label)


def assumption_table(st: DigitalTwinStudy) -> Table:
    """Per case: coverage of m, c, k (± Wilson half-width), first-order prediction, bias of k, and the test flags."""
    rows = []
    a = st.assumptions
    for label, ex in a.experiments.items():
        cov, hw = ex.coverage, ex.coverage_uncertainty
        pred = a.predicted.get(label)
        rows.append(
            {
                "case": label,
                "R": ex.runs,
                "cm": pm(cov[0], hw[0]),
                "cc": pm(cov[1], hw[1]),
                "ck": pm(cov[2], hw[2]),
                "pk": float(pred[2]) if pred is not None else Missing(reason="no first-order prediction"),
                "bk": 100 * float(ex.rel_bias[2]),
                "se": float(np.mean(ex.rel_rmse / ex.rel_stderr)),
                "lb": pm(ex.flagged("whiteness"), ex.flagged_uncertainty("whiteness")),
                "ic": pm(ex.flagged("input"), ex.flagged_uncertainty("input")),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            case  case
            R     runs
            cm    coverage m
            cc    coverage c
            ck    coverage k
            pk    predicted k      2
            bk    error k (%)      2
            se    rms / s.e.       3
            lb    whiteness flags
            ic    input flags
            """
        ),
        caption="Coverage of the 95 % intervals, and the share of runs the residual tests flag at the 5 % level, "
        "when the records break one assumption at a time.",
        name="tab-twin-assumptions",
        notes=(
            "Cases: " + "; ".join(f"{label}: {_case_text(label, st)}" for label in a.experiments) + ".",
            "Predicted k: the first-order coverage of k; error k: its mean relative error; rms / s.e.: the rms "
            "error over the stated standard error, averaged over m, c and k.",
            "± : half-width of the Wilson 95 % interval of the share over the row's runs. Each row draws its own "
            "noise; all rows share one force record (the coverage is conditional on that design).",
            f"Whiteness: Ljung–Box statistic of the output-error residual over {a.lags} lags, χ² with {a.lags} "
            f"degrees of freedom. Input correlation: residual against the measured force at lags 0 to {a.lags - 1} "
            "(χ² with the rank of the force's lag covariance); it assumes a white residual, so coloured noise "
            "trips it too.",
            "First-order coverage: 2Φ(q σₐ/σₜ) − 1, σₐ the assumed and σₜ the true standard deviation, from the "
            "sandwich covariance with the exact Jacobian at the truth; it applies to Gaussian white or AR(1) "
            "noise on the response only (a noisy force biases the estimate at second order and a cubic spring is "
            "model error).",
        ),
    )


def kalman_table(st: DigitalTwinStudy) -> Table:
    """The filter's stated standard deviation of k against its actual rms error."""
    rows = [
        {
            "truth": {"constant": "constant k", "random walk": "k a random walk (the filter's own model)"}[c.truth],
            "R": c.records,
            "n": c.samples,
            "stated": c.stated,
            "actual": c.actual,
            "ratio": pm(c.ratio, c.halfwidth),
        }
        for c in st.kalman
    ]
    return Table(
        rows=rows,
        columns=columns(
            """
            truth   true stiffness
            R       records
            n       samples
            stated  rms stated σ_k (N/m)  3
            actual  rms error of k (N/m)  3
            ratio   error / stated
            """
        ),
        caption="The Kalman filter's stated standard deviation of the stiffness against its actual error.",
        name="tab-twin-kalman",
        notes=(
            f"Samples from {0.25 * st.params.t_monitor + KALMAN_SETTLE:g} s (the calibration window and "
            f"{KALMAN_SETTLE:g} s for the filter to settle) to the end of each {st.params.t_monitor:g} s record; "
            f"± : 95 % half-width from batch means over blocks of {KALMAN_BLOCK:g} s.",
        ),
    )


def detection_table(st: DigitalTwinStudy) -> Table:
    """False alarms and detection at the chosen threshold, one row per fault scenario."""
    j = st.threshold_index
    rows = []
    for label, ex in st.detection.items():
        delay = float(ex.mean_delay[j])
        rows.append(
            {
                "fault": label,
                "R": ex.runs,
                "fa": float(ex.false_alarm_probability[j]),
                "far": float(ex.false_alarm_rate[j]),
                "faru": float(ex.false_alarm_rate_upper[j]),
                "gmax": ex.healthy_max,
                "margin": float(ex.thresholds[j]) / ex.healthy_max
                if ex.healthy_max > 0
                else Missing(reason="g stayed 0"),
                "pd": float(ex.detection_probability[j]),
                "delay": delay if math.isfinite(delay) else Missing(reason="no fault detected"),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            fault   fault
            R       runs of each kind
            fa      false alarm probability  3
            far     false alarms (1/h)       3
            faru    95 % upper bound (1/h)   3
            gmax    largest healthy g        3
            margin  h / largest healthy g    3
            pd      detection probability    3
            delay   mean delay (s)           3
            """
        ),
        caption=f"Change detection at the chosen CUSUM threshold h = {st.params.threshold:g} over seeded healthy "
        "and faulty records.",
        name="tab-twin-detection",
        notes=(
            "False alarm probability: share of records (healthy, plus faulty ones alarmed before the fault) with an "
            "alarm; false alarms per hour count the healthy records only, with the exact one-sided 95 % Poisson "
            "upper bound over their monitored hours. Largest healthy g: the highest value the CUSUM reached on any "
            "healthy record. Delay: alarm time minus fault start.",
        ),
    )


def _delays(ex, j: int) -> np.ndarray:
    d = ex.first_crossing[:, j] - ex.change_time
    return d[np.isfinite(d) & (d >= 0.0)]


def run_length_table(st: DigitalTwinStudy, min_alarms: int = MIN_ALARMS) -> Table:
    """Measured run lengths (with standard errors) against the Markov-chain theory of Brook & Evans (1972)."""
    rl, dt = st.run_lengths, st.run_lengths.dt
    rows = []
    for i, h in enumerate(rl.thresholds):
        chosen = h == float(st.params.threshold)
        if rl.alarms[i] < min_alarms and not chosen:
            continue
        theory = rl.theory[i] * dt
        if rl.alarms[i] >= min_alarms:
            meas, se = rl.measured[i] * dt, rl.stderr[i] * dt
            z = (meas - theory) / se if math.isfinite(theory) else Missing(reason="theory out of numerical reach")
        else:
            meas = Missing(reason=f"fewer than {min_alarms} false alarms: the measurement only bounds the run length")
            se, z = meas, meas
        rows.append(
            {
                "what": "run length to a false alarm (s)",
                "h": float(h),
                "count": int(rl.alarms[i]),
                "meas": meas,
                "se": se,
                "bound": float(rl.lower95[i] * dt),
                "theory": theory if math.isfinite(theory) else Missing(reason="theory out of numerical reach"),
                "z": z,
            }
        )
    j = st.threshold_index
    for label, ex in st.detection.items():
        d = _delays(ex, j)
        th = st.delay_theory[label]
        meas = float(np.mean(d)) if d.size else math.nan
        se = float(np.std(d, ddof=1) / math.sqrt(d.size)) if d.size > 1 else math.nan
        rows.append(
            {
                "what": f"mean delay, {label} (s)",
                "h": float(ex.thresholds[j]),
                "count": int(d.size),
                "meas": _val(meas, "no fault detected"),
                "se": _val(se, "fewer than two detections"),
                "bound": Missing(reason="not a false-alarm row"),
                "theory": _val(th.mean_delay, "no detection in theory"),
                "z": _val((meas - th.mean_delay) / se if se > 0 else math.nan, "no spread"),
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            what    quantity
            h       h                        3
            count   alarms or detections
            meas    measured                 3
            se      std. error               3
            bound   95 % lower bound (s)     3
            theory  Markov chain             3
            z       difference / std. error  2
            """
        ),
        caption="CUSUM run lengths: Monte Carlo against the Markov-chain theory.",
        name="tab-twin-arl",
        notes=(
            f"False-alarm rows: {integer(rl.samples)} monitored samples of healthy records "
            f"({sig(rl.samples * dt / 3600, 3)} h), the CUSUM restarted after each alarm; measured: monitored time per "
            "alarm, standard error from the "
            "alarm count (Poisson). Theory: the Brook–Evans chain for a white Gaussian residual, averaged over the "
            "spread of each record's calibrated noise variance, extrapolated from two cell counts.",
            "Delay rows: mean over the faulty records detected after the fault starts; theory: the chain pushed "
            "forward sample by sample on the fault's noise-free response difference.",
        ),
    )


def flag_halfwidth(st: DigitalTwinStudy) -> float:
    """Largest Wilson half-width of any share in the assumption table (coverages and flags), 1."""
    out = 0.0
    for ex in st.assumptions.experiments.values():
        out = max(out, float(np.max(ex.coverage_uncertainty)))
        for which in ("whiteness", "input"):
            out = max(out, float(binomial_halfwidth(round(ex.flagged(which) * ex.runs), ex.runs)))
    return out
