"""The chapter's verdicts: the paper's claims replayed on the hardware, and the digital-twin questions on
the lab data (tables and sentences, functions of the study's record)."""

from __future__ import annotations

import math

from vibration.chapters.real_oscillator.study import (
    ALPHA,
    BRAKE_MATTERS,
    POWER,
    RealOscillatorStudy,
)
from vibration.chapters.real_oscillator.text import (
    ABOUT_FACTOR,
    AGREE_Z,
    BRAKE_TEXT,
    PAPER_AMPLIFICATION,
    PAR_TEXT,
    SUPPRESSED,
    _amp,
    _pm,
    _u,
)
from vibration.physics.paper import load_claims
from vibration.presentation.narrative import g
from vibration.presentation.tables import Column, Table

# ----------------------------------------------------------------------------- claims


def claims_table(st: RealOscillatorStudy) -> Table:
    """The paper's claims checked on the hardware, with computed verdicts."""
    quotes = {c["claim_id"]: c["claim"] for c in load_claims()}
    amp = st.peak_ratio / st.low_ratio
    amp_se = amp * math.hypot(st.peak_ratio_se / st.peak_ratio, st.low_ratio_se / st.low_ratio)
    if abs(math.log(amp / PAPER_AMPLIFICATION)) <= math.log(ABOUT_FACTOR):
        v1 = "supported: about 10"
    elif amp > PAPER_AMPLIFICATION * ABOUT_FACTOR:
        v1 = "exceeded: well above 10"
    else:
        v1 = "not supported: well below 10"
    if not st.peak_group_steady:
        v1 += " (a lower bound: the resonant runs are still growing)"
    s, v = st.peak_group
    m1 = (
        f"ratio {_pm(st.peak_ratio, st.peak_ratio_se, 3)} (session {s}, {g(v, 3)} V) over "
        f"{_pm(st.low_ratio, st.low_ratio_se, 3)} at the lowest frequencies: {_pm(amp, amp_se, 3)}"
    )
    pb = st.steady_peak_brake
    z = st.brake_dzeta / st.brake_dzeta_se
    off_txt = g(pb["off"], 3) + " rad" if math.isfinite(pb["off"]) else "unbounded"
    frac = pb["on"] / pb["off"] if math.isfinite(pb["off"]) else 0.0
    if z <= AGREE_Z:
        v2 = "not supported: the brake's damping is not resolved"
    elif frac < SUPPRESSED:
        v2 = "supported by the free decays and the model (the driven runs have one brake setting)"
    elif frac < 1.0:
        v2 = f"partly supported: the brake lowers the resonant amplitude to {g(100 * frac, 2)} %, not almost to nothing"
    else:
        v2 = "not supported: the brake adds damping but the model shows no suppression"
    m2 = (
        f"the brake adds Δζ = {_pm(st.brake_dzeta, st.brake_dzeta_se, 2)}; steady resonance amplitude of the viscous + "
        f"Coulomb model {off_txt} without, {_amp(pb['on'])} with the brake"
    )
    growing = [d for d in st.driven if not d.steady and d.amp_change_z > 0]
    bounded = math.isfinite(st.steady_peak_combined) and math.isfinite(st.steady_peak_linear)
    v3 = (
        "not supported: a slow, bounded build-up, not an instability"
        if bounded
        else "supported: unbounded in the model"
    )
    m3 = (
        f"{len(growing)} runs near resonance grow throughout the record (largest "
        f"{g(max(d.late.wheel_amp for d in st.driven), 3)} rad), "
        f"but toward a bound: the steady resonance amplitude at the measured {g(st.drive_amp, 3)} rad of drive is "
        f"{_amp(st.steady_peak_combined)} (viscous + Coulomb), {_amp(st.steady_peak_linear)} (linear); below "
        f"{g(st.stick_drive_exact, 3)} rad of drive the wheel sticks (Den Hartog; 4Δ/(πg) = "
        f"{g(st.stick_drive_hb, 3)} rad)"
    )
    w_pk, w_det = st.detuning_omega
    v4 = "partly supported: only near resonance" if st.brake_band < 0.5 else "supported across the band"
    m4 = (
        f"the brake changes the model's steady amplitude by more than {g(100 * BRAKE_MATTERS)} % only for "
        f"|ω/ωₙ − 1| < {g(st.brake_band, 2)}; moving the drive from {g(w_pk, 3)} to {g(w_det, 3)} rad/s lowers the "
        f"measured ratio {g(st.detuning_factor, 3)}-fold"
    )
    rows = [
        {"claim": f"“{quotes['C09']}”", "measured": m1, "verdict": v1},
        {"claim": f"“{quotes['C18']}”", "measured": m2, "verdict": v2},
        {"claim": f"“{quotes['C19']}”", "measured": m3, "verdict": v3},
        {
            "claim": "damping is the most critical design parameter (the paper's conclusion, paraphrased)",
            "measured": m4,
            "verdict": v4,
        },
    ]
    return Table(
        rows,
        [Column("claim", "the paper"), Column("measured", "on the hardware"), Column("verdict", "verdict")],
        "The paper's claims on the real oscillator, with verdicts computed from the measurements and the calibrated "
        "models.",
        "tab-real-claims",
    )


def claims_sentence(st: RealOscillatorStudy) -> str:
    """The verdicts in one paragraph."""
    rows = claims_table(st).rows
    return " ".join(
        f"**{r['verdict'].split(':')[0].split(' (')[0].capitalize()}**: {r['claim']} — {r['measured']}." for r in rows
    )


# ----------------------------------------------------------------------------- digital twin


def coverage_table(st: RealOscillatorStudy) -> Table:
    """Per brake setting and parameter: a run's standard error against the scatter between runs."""
    rows = [
        {
            "brake": c.brake,
            "par": _u(c.parameter),
            "se": c.median_se,
            "sd": c.sd,
            "ratio": c.ratio,
            "covered": "yes" if c.covered else "no",
        }
        for c in st.coverage
    ]
    cols = [
        Column("brake", "brake"),
        Column("par", "parameter"),
        Column("se", "median s of one run", 2),
        Column("sd", "scatter between runs (sd)", 2),
        Column("ratio", "scatter / s", 2),
        Column("covered", f"covered (ratio ≤ {g(st.params.spread_ratio_max)})"),
    ]
    return Table(
        rows,
        cols,
        "Does one run's confidence interval cover the run-to-run spread? The combined-law fits' median standard "
        "error against the standard deviation of the estimates between repeated runs.",
        "tab-real-coverage",
    )


def two_sample_table(st: RealOscillatorStudy) -> Table:
    """Welch's test of brake on against off on the per-run parameters, and the runs a clean test needs."""
    rows = [
        {
            "par": _u(t.parameter),
            "off": t.mean_off,
            "sd_off": t.sd_off,
            "on": t.mean_on,
            "sd_on": t.sd_on,
            "t": t.t,
            "p": t.p,
            "mw": t.mann_whitney_p,
            "need": t.runs_needed,
        }
        for t in st.tests
    ]
    cols = [
        Column("par", "parameter"),
        Column("off", "mean, brake off", 3),
        Column("sd_off", "sd, off", 2),
        Column("on", "mean, brake on", 3),
        Column("sd_on", "sd, on", 2),
        Column("t", "Welch t", 3),
        Column("p", "p (Welch)", 2),
        Column("mw", "p (Mann–Whitney)", 2),
        Column("need", f"runs needed per setting ({g(100 * POWER)} % power)"),
    ]
    return Table(
        rows,
        cols,
        f"Can the two damping states be told apart from the data alone? Two-sample tests on the per-run combined-law "
        f"estimates (10 runs each), and the runs per setting a two-sided test at {g(100 * ALPHA)} % needs for "
        f"{g(100 * POWER)} % power at the observed difference and scatter (normal approximation).",
        "tab-real-two-sample",
    )


def twin_sentence(st: RealOscillatorStudy) -> str:
    """The digital twin's two questions, answered."""
    bad = [c for c in st.coverage if not c.covered]
    if bad:
        worst = max(bad, key=lambda c: c.ratio)
        cov = (
            f"One run's standard error does not cover the run-to-run spread for {len(bad)} of {len(st.coverage)} "
            f"parameters; worst is {PAR_TEXT[worst.parameter][0]} {BRAKE_TEXT[worst.brake]}, whose runs scatter "
            f"{g(worst.ratio, 2)} times their own standard error: a twin identified from one run is more confident "
            "than "
            "the hardware is repeatable, and its intervals must be widened by the scatter (as the pooled errors "
            "here are)."
        )
    else:
        cov = "Every run's standard error covers the run-to-run spread."
    z, d = st.tests
    sep = (
        f"The brake is told apart from the data alone: Welch's test on the per-run ζ gives p = {g(z.p, 2)} and on Δ "
        f"p = {g(d.p, 2)}; at the observed difference and scatter a test at {g(100 * ALPHA)} % with {g(100 * POWER)} "
        "% power "
        f"needs {z.runs_needed} runs per setting on ζ and {d.runs_needed} on Δ."
    )
    if z.p > ALPHA and d.p > ALPHA:
        sep = (
            f"The brake is not told apart from these runs (p = {g(z.p, 2)} on ζ, {g(d.p, 2)} on Δ); about "
            f"{z.runs_needed} runs per setting would be needed on ζ."
        )
    return cov + " " + sep
