"""Sentences, verdicts and tables of the real-oscillator chapter, all from a :class:`RealOscillatorStudy`.

Word conventions (the tests check them against the numbers): a free-decay law is "viscous",
"Coulomb" or "combined"; a driven run is "steady" or "a transient"; two estimators "agree" when
they differ by at most :data:`AGREE_Z` combined standard errors; a model "fails" on a run whose
relative prediction error exceeds :data:`FAIL_REL`.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.chapters.real_oscillator.study import (
    LAWS,
    QUANT_FLOOR,
    QUANT_STEP,
    SUBSTEPS,
    DrivenRun,
    RealOscillatorStudy,
    at_bound,
)
from vibration.presentation.narrative import g
from vibration.presentation.tables import Column, Missing, Table

#: Two estimates agree when they differ by at most this many combined standard errors.
AGREE_Z = 2.0
#: A model fails on a run when its rms prediction error exceeds this fraction of the run's rms.
FAIL_REL = 0.3
#: The paper's amplification at resonance ("approximately 10-fold") and the factor read as "about".
PAPER_AMPLIFICATION = 10.0
ABOUT_FACTOR = 1.5
#: The paper's "almost completely suppressed": a steady amplitude below this fraction (claim C18).
SUPPRESSED = 0.1

LAW_TEXT = {"viscous": "viscous", "coulomb": "Coulomb", "combined": "combined"}
BRAKE_TEXT = {"off": "without the brake", "on": "with the brake"}
MODEL_TEXT = {"linear": "linear viscous (the paper's)", "combined": "viscous + Coulomb"}
PAR_TEXT = {"omega_n": ("ωₙ", "rad/s"), "zeta": ("ζ", ""), "friction": ("Δ", "rad")}
FIXED = Missing("fixed at 0 by the law")


def _pm(x: float, s: float, digits: int = 4) -> str:
    return f"{g(x, digits)} ± {g(s, 2)}"


def _amp(x: float) -> str:
    return f"{g(x, 3)} rad" if math.isfinite(x) else "unbounded"


def _median_duration(st: RealOscillatorStudy) -> float:
    ds = sorted(d.duration for d in st.driven)
    return ds[len(ds) // 2]


def _u(par: str) -> str:
    sym, unit = PAR_TEXT[par]
    return f"{sym} ({unit})" if unit else sym


# ----------------------------------------------------------------------------- opening


def provenance_text(st: RealOscillatorStudy) -> str:
    """Where the data come from, citing the source repository and commit."""
    p = st.provenance
    n_off, n_on = len(st.decays["off"].runs), len(st.decays["on"].runs)
    s1 = sum(d.session == 1 for d in st.driven)
    s2 = sum(d.session == 2 for d in st.driven)
    return (
        f"The measurements are raw logger exports from a first-year teaching lab, measured on {p.date} and "
        f"published in the GitHub repository `{p.repository}` (folder `{p.folder}`, commit `{p.commit}`); "
        f"cite that repository and commit wherever they are used. This chapter uses {n_off} free decays without "
        f"and {n_on} with the magnetic brake, and {s1} + {s2} driven runs from two sessions, sampled at 20 Hz; the "
        f"wheel's encoder reads whole degrees ({g(QUANT_STEP, 3)} rad), so rounding alone leaves an rms error of "
        f"{g(QUANT_FLOOR, 3)} rad (the step over √12)."
    )


def key_results(st: RealOscillatorStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    lines = ["> **Key results**", ">"] + [f"> * {s}" for s in front_findings(st)]
    return "\n".join(lines)


def front_page_findings() -> str:
    """The front page's Part III paragraph: the chapter's findings at its default parameters, as bullets."""
    from vibration.chapters.real_oscillator.study import real_oscillator_study

    return "\n".join(f"* {line}" for line in front_findings(real_oscillator_study()))


def front_findings(st: RealOscillatorStudy) -> list[str]:
    """Three to five computed sentences for the book's front page."""
    off, on = st.decays["off"], st.decays["on"]
    wn = on.pooled[("combined", "omega_n")]
    lin_all, lin_rel, n_pred = st.pooled_error("linear")
    com_all, com_rel, _ = st.pooled_error("combined")
    better = "linear viscous" if lin_rel < com_rel else "viscous + Coulomb"
    amp = st.peak_ratio / st.low_ratio
    return [
        f"Dry (Coulomb) friction, absent from the paper's model, dominates the real wheel's free decays: the "
        "information criterion picks a law with friction in "
        f"{off.law_counts['coulomb'] + off.law_counts['combined']} of "
        f"{len(off.runs)} runs without the brake and {on.law_counts['coulomb'] + on.law_counts['combined']} of "
        f"{len(on.runs)} with it; Δ = "
        f"{_pm(off.pooled[('combined', 'friction')].mean, off.pooled[('combined', 'friction')].stderr, 3)} rad "
        f"without the brake.",
        f"The magnetic brake adds Δζ = {_pm(st.brake_dzeta, st.brake_dzeta_se, 2)} of viscous damping "
        f"(ζ = {_pm(on.pooled[('combined', 'zeta')].mean, on.pooled[('combined', 'zeta')].stderr, 2)} with it); "
        f"ωₙ = {_pm(wn.mean, wn.stderr)} rad/s.",
        f"At resonance the wheel swings {g(amp, 3)} times as far as at the lowest drive frequency (the paper: about "
        "10)"
        + (
            f", and the resonant runs are still growing when the {g(_median_duration(st), 2)} s records end."
            if not st.peak_group_steady
            else "; the resonant runs are steady."
        ),
        f"Calibrated on the {len(st.calibration_runs)} slowest runs only, the {better} model predicts the other "
        f"{n_pred} runs' wheel angle best: pooled rms error {g(lin_all, 3)} rad ({g(100 * lin_rel, 3)} % of the "
        "motion) "
        f"for the linear viscous model, {g(com_all, 3)} rad ({g(100 * com_rel, 3)} %) for viscous + Coulomb.",
    ]


# ----------------------------------------------------------------------------- free decays


def decay_table(st: RealOscillatorStudy) -> Table:
    """Per free decay: the combined fit, its residuals against the encoder floor, and the BIC of each law."""
    rows = []
    for b in ("off", "on"):
        for d in st.decays[b].runs:
            c = d.combined
            rows.append(
                {
                    "brake": b,
                    "run": d.run,
                    "wn": c.omega_n,
                    "zeta": at_bound(c.zeta),
                    "zeta_se": c.stderr["zeta"],
                    "delta": c.friction,
                    "delta_se": c.stderr["friction"],
                    "offset": c.offset,
                    "floor": c.residual_rms / QUANT_FLOOR,
                    "dw": c.durbin_watson,
                    "dbic_viscous": d.fits["viscous"].bic - d.fits["coulomb"].bic,
                    "dbic_combined": d.fits["combined"].bic - d.fits["coulomb"].bic,
                    "chosen": LAW_TEXT[d.chosen],
                }
            )
    cols = [
        Column("brake", "brake"),
        Column("run", "run"),
        Column("wn", "ωₙ (rad/s)", 4),
        Column("zeta", "ζ", 2),
        Column("zeta_se", "s(ζ)", 2),
        Column("delta", "Δ (rad)", 3),
        Column("delta_se", "s(Δ) (rad)", 2),
        Column("offset", "c (rad)", 2),
        Column("floor", "rms / floor", 2),
        Column("dw", "DW", 2),
        Column("dbic_viscous", "ΔBIC viscous", 4),
        Column("dbic_combined", "ΔBIC combined", 4),
        Column("chosen", "law chosen"),
    ]
    return Table(
        rows,
        cols,
        "Free decays: the combined viscous + Coulomb fit to each whole trace, its rms residual over the encoder's "
        "rounding floor (step/√12), its Durbin–Watson statistic (DW), and the Bayesian information criterion of "
        "the viscous and of the combined law less that of the Coulomb law (ΔBIC; the lowest BIC is chosen, so a "
        "positive ΔBIC means Coulomb beats that law).",
        "tab-real-decays",
        notes=(
            "Standard errors s(·) are the larger of the least-squares and the Newey–West (correlated residuals) "
            "estimates; a Durbin–Watson statistic near 2 means white residuals, near 0 strongly correlated ones.",
        ),
    )


def pooled_table(st: RealOscillatorStudy) -> Table:
    """Per brake setting and law: pooled parameters with standard errors, runs choosing the law."""
    rows = []
    for b in ("off", "on"):
        ds = st.decays[b]
        for law in LAWS:
            row = {"brake": b, "law": LAW_TEXT[law], "chosen": ds.law_counts[law], "n": len(ds.runs)}
            for par in ("omega_n", "zeta", "friction"):
                pl = ds.pooled.get((law, par))
                row[par] = pl.mean if pl else FIXED
                row[par + "_se"] = pl.stderr if pl else FIXED
                row[par + "_b"] = pl.birge if pl else FIXED
            fits = [d.fits[law] for d in ds.runs]
            row["rms"] = float(sorted(f.residual_rms for f in fits)[len(fits) // 2])
            rows.append(row)
    cols = [
        Column("brake", "brake"),
        Column("law", "law"),
        Column("chosen", "runs choosing it"),
        Column("n", "runs"),
        Column("omega_n", "ωₙ (rad/s)", 4),
        Column("omega_n_se", "s(ωₙ) (rad/s)", 2),
        Column("zeta", "ζ", 2),
        Column("zeta_se", "s(ζ)", 2),
        Column("zeta_b", "Birge ratio of ζ", 2),
        Column("friction", "Δ (rad)", 3),
        Column("friction_se", "s(Δ) (rad)", 2),
        Column("friction_b", "Birge ratio of Δ", 2),
        Column("rms", "median rms residual (rad)", 2),
    ]
    return Table(
        rows,
        cols,
        "Free decays pooled per brake setting and law: inverse-variance weighted means; each standard error is "
        "multiplied by the Birge ratio √(χ²/(n − 1)) when that exceeds 1.",
        "tab-real-pooled",
        notes=("A Birge ratio above 1 means the runs scatter more than their own standard errors allow.",),
    )


def law_sentence(st: RealOscillatorStudy) -> str:
    """Which law the data choose, with and without the brake (counts of runs)."""
    parts = []
    for b in ("off", "on"):
        ds = st.decays[b]
        top = max(LAWS, key=lambda law: ds.law_counts[law])
        parts.append(
            f"{BRAKE_TEXT[b]} the Bayesian information criterion chooses the **{LAW_TEXT[top]}** law in "
            f"{ds.law_counts[top]} of {len(ds.runs)} runs (viscous {ds.law_counts['viscous']}, Coulomb "
            f"{ds.law_counts['coulomb']}, combined {ds.law_counts['combined']})"
        )
    never = all(st.decays[b].law_counts["viscous"] == 0 for b in ("off", "on"))
    tail = " The paper's purely viscous law is never chosen." if never else ""
    return parts[0][0].upper() + parts[0][1:] + "; " + parts[1] + "." + tail


def brake_sentence(st: RealOscillatorStudy) -> str:
    """What the brake adds: zeta with minus zeta without, with its standard error."""
    on, off = st.decays["on"].pooled, st.decays["off"].pooled
    z = st.brake_dzeta / st.brake_dzeta_se
    d_on, d_off = on[("combined", "friction")], off[("combined", "friction")]
    dd = d_on.mean - d_off.mean
    dd_se = math.hypot(d_on.stderr, d_off.stderr)
    word = "resolved" if abs(z) > AGREE_Z else "not resolved"
    return (
        f"With the combined law, the brake raises the viscous damping ratio from "
        f"{_pm(off[('combined', 'zeta')].mean, off[('combined', 'zeta')].stderr, 2)} to "
        f"{_pm(on[('combined', 'zeta')].mean, on[('combined', 'zeta')].stderr, 2)}: the brake adds "
        f"Δζ = {_pm(st.brake_dzeta, st.brake_dzeta_se, 2)} ({g(z, 2)} standard errors, {word}). The friction angle "
        f"changes by {_pm(dd, dd_se, 2)} rad at the same time ({g(dd / dd_se, 2)} standard errors)"
        + (
            ": with the brake, part of the loss that the fit without it books as friction is taken by the viscous term."
            if dd / dd_se < -AGREE_Z
            else "."
        )
    )


def residual_sentence(st: RealOscillatorStudy) -> str:
    """Residuals against the quantisation floor and their whiteness: model discrepancy or noise."""
    fits = [d.combined for b in ("off", "on") for d in st.decays[b].runs]
    ratios = sorted(f.residual_rms / QUANT_FLOOR for f in fits)
    dws = sorted(f.durbin_watson for f in fits)
    lo, hi = ratios[0], ratios[-1]
    verdict = (
        "far above rounding: what is left is model discrepancy, not measurement noise"
        if lo > 3
        else "close to the rounding floor"
    )
    return (
        f"The combined fits leave residuals of {g(fits and min(f.residual_rms for f in fits), 2)} to "
        f"{g(max(f.residual_rms for f in fits), 2)} rad rms, {g(lo, 2)} to {g(hi, 2)} times the encoder's rounding "
        f"floor ({g(QUANT_FLOOR, 3)} rad): {verdict}. The Durbin–Watson statistic is {g(dws[0], 2)} to {g(dws[-1], 2)} "
        f"(2 for white residuals): the residuals are slow, smooth deviations from the model (for example a period "
        f"that shortens as the swing dies), so each run's standard errors use the Newey–West estimate. The "
        f"offsets c differ from run to run because the logger zeroes the encoder at each start."
    )


def peak_table(st: RealOscillatorStudy) -> Table:
    """Whole-trace fit against the independent peak estimator (combined law), pooled per brake setting."""
    rows = []
    for b in ("off", "on"):
        ds = st.decays[b]
        for par in ("omega_n", "zeta", "friction"):
            a, p = ds.pooled[("combined", par)], ds.peak_pooled.get(par)
            if p is None:
                continue
            z = (p.mean - a.mean) / math.hypot(a.stderr, p.stderr)
            rows.append(
                {
                    "brake": b,
                    "par": _u(par),
                    "fit": a.mean,
                    "fit_se": a.stderr,
                    "peak": p.mean,
                    "peak_se": p.stderr,
                    "z": z,
                    "agree": "agree" if abs(z) <= AGREE_Z else "disagree",
                }
            )
    cols = [
        Column("brake", "brake"),
        Column("par", "parameter"),
        Column("fit", "whole-trace fit", 4),
        Column("fit_se", "s (fit)", 2),
        Column("peak", "peak estimator", 4),
        Column("peak_se", "s (peaks)", 2),
        Column("z", "difference (std. errors)", 2),
        Column("agree", f"within {g(AGREE_Z)} s"),
    ]
    return Table(
        rows,
        cols,
        "Cross-check: the whole-trace fit against the classical peak analysis (extrema only, the recursion of "
        "the half-period amplitudes), both with the combined law, pooled per brake setting.",
        "tab-real-peaks",
        notes=("The peak estimator drops the extrema after the swing falls below 0.2 of the first one.",),
    )


def peak_sentence(st: RealOscillatorStudy) -> str:
    """Where the two estimators disagree, said plainly."""
    rows = peak_table(st).rows
    bad = [r for r in rows if r["agree"] == "disagree"]
    if not bad:
        return "The peak estimator agrees with the whole-trace fit on every pooled parameter."
    items = "; ".join(
        f"{r['par'].split(' ')[0]} {BRAKE_TEXT[r['brake']]} ({g(r['fit'], 3)} from the whole trace, "
        f"{g(r['peak'], 3)} from the peaks, {g(abs(r['z']), 2)} standard errors apart)"
        for r in bad
    )
    return (
        f"The two estimators disagree on {len(bad)} of {len(rows)} pooled parameters: {items}. The peak analysis "
        f"splits the loss per half period into a part proportional to the amplitude (ζ) and a constant part (Δ) "
        f"from the extrema alone; over the narrow range of amplitudes it keeps the two are nearly collinear, so it "
        f"trades one for the other, while the whole trace also fits the shape between extrema. Neither estimator "
        f"checks the model; their agreement on ωₙ only says the period is well measured."
    )


# ----------------------------------------------------------------------------- driven runs


def _role(st: RealOscillatorStudy, d: DrivenRun) -> str:
    return "calibration" if st.is_calibration(d) else "prediction"


def driven_table(st: RealOscillatorStudy) -> Table:
    """Per driven run: drive frequency, amplitude ratio and lag in the early and late windows, steadiness."""
    wn = st.models["combined"].omega_n
    rows = []
    for d in sorted(st.driven, key=lambda d: (d.session, d.omega)):
        rows.append(
            {
                "session": d.session,
                "run": d.run,
                "V": d.voltage,
                "w": d.omega,
                "r": d.omega / wn,
                "Au": d.late.drive_amp,
                "early": d.early.ratio,
                "late": d.late.ratio,
                "late_se": d.late.ratio_se,
                "lag": d.late.lag,
                "lag_se": d.late.lag_se,
                "z": d.amp_change_z,
                "periods": f"{d.early.periods} + {d.late.periods}",
                "state": "steady" if d.steady else "transient",
            }
        )
    cols = [
        Column("session", "session"),
        Column("run", "run"),
        Column("V", "motor (V)", 3),
        Column("w", "ω (rad/s)", 4),
        Column("r", "ω/ωₙ", 3),
        Column("Au", "drive amplitude (rad)", 3),
        Column("early", "ratio, early", 3),
        Column("late", "ratio, late", 3),
        Column("late_se", "s(ratio)", 2),
        Column("lag", "lag, late (rad)", 3),
        Column("lag_se", "s(lag) (rad)", 2),
        Column("z", "late − early (std. errors)", 2),
        Column("periods", "periods early + late"),
        Column("state", "state"),
    ]
    p = st.params
    return Table(
        rows,
        cols,
        f"Driven runs: wheel-to-drive amplitude ratio and phase lag from one-harmonic fits over whole drive "
        f"periods, the first {p.n_early} (early) and the last {p.n_late} (late; fewer in short runs); a run is "
        f"steady when early and late wheel amplitudes differ by at most {g(p.z_steady)} standard errors and the "
        f"model's build-up time 1/(ζωₙ) is shorter than the record.",
        "tab-real-driven",
        notes=("Standard errors: the larger of the fit's and the scatter of one-period fits (batch means).",),
    )


def driven_sentence(st: RealOscillatorStudy) -> str:
    """How many runs are steady, and where the transients are."""
    tr = [d for d in st.driven if not d.steady]
    wn = st.models["combined"].omega_n
    n = len(st.driven)
    if not tr:
        return f"All {n} driven runs are steady by the test."
    r = sorted(d.omega / wn for d in tr)
    dur = _median_duration(st)
    if math.isfinite(st.build_up_time):
        build = (
            f"The model's build-up time 1/(ζωₙ) is {g(st.build_up_time, 3)} s against records of about {g(dur, 3)} s, "
            f"so a transient started at the beginning still has $e^{{-{g(dur / st.build_up_time, 2)}}}$ of its size at "
            f"the end."
        )
    else:
        build = "The model has no viscous damping (ζ = 0), so by the model no transient ever dies out."
    return (
        f"{n - len(tr)} of {n} driven runs are steady; {len(tr)} are transients, at ω/ωₙ between {g(r[0], 3)} "
        f"and {g(r[-1], 3)}; their late amplitude is up to "
        f"{g(max(d.late.wheel_amp / d.early.wheel_amp for d in tr), 3)} times the early one. {build} The "
        f"transients' late ratios are lower bounds of the steady ones."
    )


# ----------------------------------------------------------------------------- prediction


def model_table(st: RealOscillatorStudy) -> Table:
    """The two models: parameters from the free decays, gain from the calibration runs."""
    rows = []
    for name in ("linear", "combined"):
        m = st.models[name]
        steady = st.steady_peak_linear if name == "linear" else st.steady_peak_combined
        rows.append(
            {
                "model": MODEL_TEXT[name],
                "wn": m.omega_n,
                "zeta": m.zeta,
                "zeta_se": m.zeta_se,
                "delta": m.friction if name == "combined" else FIXED,
                "g": m.gain,
                "peak": steady if math.isfinite(steady) else Missing("unbounded: friction cannot stop the growth"),
            }
        )
    cols = [
        Column("model", "model"),
        Column("wn", "ωₙ (rad/s)", 4),
        Column("zeta", "ζ", 3),
        Column("zeta_se", "s(ζ)", 2),
        Column("delta", "Δ (rad)", 3),
        Column("g", "g (rad/rad)", 3),
        Column("peak", "steady amplitude at ωₙ (rad)", 3),
    ]
    return Table(
        rows,
        cols,
        "The two models predicting the driven runs: ωₙ, ζ and Δ pooled from the free decays "
        f"{BRAKE_TEXT[st.params.brake]} "
        f"(linear: the viscous-law fits; viscous + Coulomb: the combined-law fits), the drive gain g calibrated on the "
        f"{len(st.calibration_runs)} lowest-frequency runs; steady amplitude at resonance for the mean drive amplitude "
        f"{g(st.drive_amp, 3)} rad.",
        "tab-real-models",
    )


def calibration_sentence(st: RealOscillatorStudy) -> str:
    """Which runs calibrate the gain, and how."""
    runs = st.calibration_runs
    names = ", ".join(f"{d.run}" for d in sorted(runs, key=lambda d: d.run))
    sess = sorted({d.session for d in runs})
    w = [d.omega for d in runs]
    lin, com = st.models["linear"], st.models["combined"]
    return (
        f"The drive gain g is calibrated on the {len(runs)} lowest-frequency runs only (session "
        f"{', '.join(map(str, sess))}, run{'s' if len(runs) > 1 else ''} {names}; ω = {g(min(w), 3)} to "
        f"{g(max(w), 3)} rad/s, "
        f"ω/ωₙ ≈ {g(sum(w) / len(w) / com.omega_n, 2)}): for each model, g minimises the squared difference between "
        "the "
        f"measured late amplitude ratio and the one of the model simulated from the same start under the same "
        f"measured drive. This gives g = {g(lin.gain, 3)} (linear viscous) and {g(com.gain, 3)} (viscous + Coulomb). "
        f"Every other run is then predicted, not fitted: simulated from its own measured start (angle, and velocity "
        f"from a parabola through its first five samples) under its own measured drive, with classical Runge–Kutta "
        f"steps of 0.05/{SUBSTEPS} s and velocity reversals located exactly (stick-slip). The one number taken from "
        f"each run is the spring's rest angle in the logger's frame (the record's mean wheel angle minus g times the "
        f"mean drive angle), which the logger does not measure because it zeroes both encoders at each start."
    )


def prediction_table(st: RealOscillatorStudy) -> Table:
    """Per driven run: each model's rms prediction error, absolute and relative to the run's rms."""
    rows = []
    for d in sorted(st.driven, key=lambda d: (d.session, d.omega)):
        pl, pc = st.prediction("linear", d), st.prediction("combined", d)
        rows.append(
            {
                "session": d.session,
                "run": d.run,
                "w": d.omega,
                "role": _role(st, d),
                "state": "steady" if d.steady else "transient",
                "lin": pl.rms_error,
                "lin_rel": pl.rel_error,
                "com": pc.rms_error,
                "com_rel": pc.rel_error,
                "better": "linear" if pl.rel_error < pc.rel_error else "viscous + Coulomb",
            }
        )
    cols = [
        Column("session", "session"),
        Column("run", "run"),
        Column("w", "ω (rad/s)", 4),
        Column("role", "role"),
        Column("state", "state"),
        Column("lin", "linear: rms error (rad)", 2),
        Column("lin_rel", "linear: relative", 2),
        Column("com", "viscous + Coulomb: rms error (rad)", 2),
        Column("com_rel", "viscous + Coulomb: relative", 2),
        Column("better", "better"),
    ]
    return Table(
        rows,
        cols,
        "Prediction of every driven run's wheel angle over its whole record: rms of measured minus simulated, and "
        "that over the rms of the measured angle about its mean (relative).",
        "tab-real-prediction",
    )


def prediction_pooled_table(st: RealOscillatorStudy) -> Table:
    """Pooled prediction errors per model: calibration runs apart, prediction runs all, steady, transients."""
    rows = []
    for name in ("linear", "combined"):
        for label, cal, steady in (
            ("calibration runs (fitted)", True, None),
            ("predicted runs", False, None),
            ("predicted, steady", False, True),
            ("predicted, transients", False, False),
        ):
            e, rel, n = st.pooled_error(name, cal, steady)
            rows.append(
                {
                    "model": MODEL_TEXT[name],
                    "runs": label,
                    "n": n,
                    "e": e if n else Missing("no such runs"),
                    "rel": rel if n else Missing("no such runs"),
                }
            )
    cols = [
        Column("model", "model"),
        Column("runs", "runs"),
        Column("n", "number"),
        Column("e", "rms error (rad)", 3),
        Column("rel", "relative", 3),
    ]
    return Table(
        rows,
        cols,
        "Prediction errors pooled over runs (rms over all their samples; relative: over the rms of the measured "
        "motion); the calibration runs are reported apart and are not part of the prediction.",
        "tab-real-prediction-pooled",
    )


def prediction_sentence(st: RealOscillatorStudy) -> str:
    """Which model predicts better, pooled and by region."""
    el, rl, n = st.pooled_error("linear")
    ec, rc, _ = st.pooled_error("combined")
    els, rls, ns = st.pooled_error("linear", steady=True)
    ecs, rcs, _ = st.pooled_error("combined", steady=True)
    elt, rlt, nt = st.pooled_error("linear", steady=False)
    ect, rct, _ = st.pooled_error("combined", steady=False)
    win = "linear viscous" if rl < rc else "viscous + Coulomb"

    def w(a, b):
        return "viscous + Coulomb" if b < a else "linear viscous"

    text = (
        f"Over the {n} predicted runs the **{win}** model predicts better: pooled rms error {g(el, 3)} rad "
        f"({g(100 * rl, 3)} % of the motion) for the linear viscous model against {g(ec, 3)} rad ({g(100 * rc, 3)} %) "
        f"for viscous + Coulomb."
    )
    clauses = []
    if ns:
        clauses.append(
            f"on the {ns} steady runs the {w(rls, rcs)} model is better (linear {g(100 * rls, 3)} %, "
            f"viscous + Coulomb {g(100 * rcs, 3)} %)"
        )
    if nt:
        clauses.append(
            f"on the {nt} transients the {w(rlt, rct)} model is better (linear {g(100 * rlt, 3)} %, "
            f"viscous + Coulomb {g(100 * rct, 3)} %)"
        )
    if clauses:
        joined = "; ".join(clauses)
        text += " " + joined[0].upper() + joined[1:] + "."
    return text


def failure_sentence(st: RealOscillatorStudy) -> str:
    """Where each model fails, and why (from the numbers)."""
    lin, com = st.models["linear"], st.models["combined"]
    fail = {}
    for name in ("linear", "combined"):
        fail[name] = [d for d in st.driven if not st.is_calibration(d) and st.prediction(name, d).rel_error > FAIL_REL]
    wn = com.omega_n
    meas = max(d.late.wheel_amp for d in st.driven)
    zeta_eq = com.zeta + 2.0 * com.friction / (math.pi * meas)

    def where(ds):
        if not ds:
            return "on no predicted run"
        r = sorted(d.omega / wn for d in ds)
        return f"on {len(ds)} predicted runs (ω/ωₙ from {g(r[0], 3)} to {g(r[-1], 3)})"

    cal = st.calibration_runs
    cal_lin = max(st.prediction("linear", d).rel_error for d in cal)
    cal_com = max(st.prediction("combined", d).rel_error for d in cal)
    _, rlt, nt = st.pooled_error("linear", steady=False)
    _, rct, _ = st.pooled_error("combined", steady=False)
    text = (
        f"A model fails here when its rms error exceeds {g(100 * FAIL_REL)} % of the run's motion. The viscous + "
        f"Coulomb model fails {where(fail['combined'])}; the linear viscous one {where(fail['linear'])}."
    )
    if nt and rct > rlt and st.steady_peak_combined > meas:
        text += (
            f" Near resonance the viscous + Coulomb model lets the wheel grow too far: its steady amplitude at "
            f"resonance is {_amp(st.steady_peak_combined)}, while the wheel reaches {g(meas, 3)} rad. At that "
            "swing "
            f"its friction acts like a viscous damping ratio ζ + 2Δ/(πX) = {g(zeta_eq, 2)}, "
            f"{'below' if zeta_eq < lin.zeta else 'above'} the {g(lin.zeta, 2)} of the viscous-law fits: the large "
            f"swings lose more energy than a constant friction torque plus the small viscous term of the free decays "
            f"explains (a loss that grows faster than the amplitude, such as air drag, would do it), while the "
            f"viscous-law fit, dominated by the large early swings of each decay, carries more damping."
        )
    elif nt and rlt > rct:
        text += (
            f" Near resonance the linear viscous model is worse ({g(100 * rlt, 3)} % against {g(100 * rct, 3)} % on "
            f"the transients): its damping ratio {g(lin.zeta, 2)} does not follow the friction's loss at large swings."
        )
    if cal_lin > cal_com:
        text += (
            f" Far from resonance the linear model misses the friction's stops and flat tops: on the calibration "
            f"runs its relative error reaches {g(cal_lin, 2)}, against {g(cal_com, 2)} with friction."
        )
    if nt:
        text += f" The {nt} runs near resonance are transients, where the start matters as much as the model."
    return text


def above_steady(st: RealOscillatorStudy, model: str) -> list[DrivenRun]:
    """Transients whose late amplitude ratio lies above the model's steady curve by more than two standard errors."""
    c = st.curves
    curve = c.linear_ratio if model == "linear" else c.combined_ratio
    out = []
    for d in st.driven:
        if d.steady:
            continue
        y = float(np.interp(d.omega, c.omega, curve))
        if math.isfinite(y) and d.late.ratio - AGREE_Z * d.late.ratio_se > y:
            out.append(d)
    return out


def resonance_sentence(st: RealOscillatorStudy) -> str:
    """The steady curves: exact Den Hartog against harmonic balance, and against the measured points."""
    c = st.curves
    n_tr = sum(not d.steady for d in st.driven)
    text = (
        f"The steady curve of the viscous + Coulomb model is Den Hartog's exact solution (continuous motion, two "
        f"velocity reversals per period), drawn where his non-stop condition holds; the harmonic-balance "
        f"approximation agrees with it within {g(100 * c.hb_max_rel_diff, 2)} % wherever both exist. Both curves use "
        f"the mean drive amplitude {g(c.drive_amp, 3)} rad."
    )
    if n_tr:
        parts = []
        for model in ("linear", "combined"):
            k = len(above_steady(st, model))
            parts.append(
                f"{k} of the {n_tr} transients lie above the {MODEL_TEXT[model]} steady curve by more than "
                f"{g(AGREE_Z)} standard errors"
            )
        text += (
            " A transient still building up should stay below the steady amplitude it approaches: "
            + "; ".join(parts)
            + "."
        )
    return text


# ----------------------------------------------------------------------------- summary


def summary_text(st: RealOscillatorStudy) -> str:
    """What a designer takes away, from the numbers."""
    off = st.decays["off"]
    el, rl, _ = st.pooled_error("linear")
    ec, rc, _ = st.pooled_error("combined")
    return "\n".join(
        [
            f"* **Model.** The paper's linear viscous model misses the dominant loss of the real wheel: dry friction "
            f"(Δ ≈ {g(off.pooled[('combined', 'friction')].mean, 2)} rad of equivalent angle). The combined law wins "
            "the "
            "information criterion on the free decays, but its residuals remain "
            f"{g(min(d.combined.residual_rms for b in ('off', 'on') for d in st.decays[b].runs) / QUANT_FLOOR, 2)} "
            "to "
            f"{g(max(d.combined.residual_rms for b in ('off', 'on') for d in st.decays[b].runs) / QUANT_FLOOR, 2)} "
            "times the "
            f"rounding floor.",
            f"* **Prediction.** Calibrated on the slowest runs only, the linear viscous model predicts the driven runs "
            f"with {g(100 * rl, 3)} % relative error, the viscous + Coulomb one with {g(100 * rc, 3)} %"
            + (
                ": the better free-decay law is not the better predictor, because near resonance the damping at large "
                "swings decides."
                if rl < rc
                else ": the better free-decay law is also the better predictor."
            ),
            f"* **Resonance.** Amplification at resonance is {g(st.peak_ratio / st.low_ratio, 3)} relative to the "
            "slowest "
            f"runs"
            + (" and still growing" if not st.peak_group_steady else "")
            + "; "
            + (
                "dry friction bounds nothing at this drive (the wheel only sticks below "
                f"{g(st.stick_drive_exact, 3)} rad "
                f"of drive, the drive is {g(st.drive_amp, 3)} rad), the viscous part does."
                if st.drive_amp > st.stick_drive_exact
                else f"the drive ({g(st.drive_amp, 3)} rad) is below the {g(st.stick_drive_exact, 3)} rad at which "
                "the wheel sticks."
            ),
            f"* **Designer's takeaway.** Damping matters only within about ±{g(100 * st.brake_band, 2)} % of ωₙ; "
            "there, "
            f"identify it at the amplitudes of use, from repeated runs ({st.tests[0].runs_needed} per setting "
            "suffice to "
            f"tell the brake apart), because one run's standard error understates the scatter.",
        ]
    )
