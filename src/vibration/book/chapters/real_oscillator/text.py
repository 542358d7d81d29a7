"""Sentences of the real-oscillator chapter, each a function of the study's record, and the key-results box.

Every number comes from :class:`~vibration.book.chapters.real_oscillator.study.RealOscillatorStudy`; every
sentence is chosen by the data it describes (a second brake setting, driven runs at two settings, a
rig's documented largest angle), so a run on another laboratory's folder never leaves a statement its
tables contradict. The tables are in :mod:`.tables` and how numbers are written in :mod:`.notation`; both
are importable from here as well.
"""

from __future__ import annotations

import math
import re

import numpy as np

from vibration.book.chapters.real_oscillator.damping import PAPER_LAW, brake_resolved
from vibration.book.chapters.real_oscillator.figures import LAW_WORDS
from vibration.book.chapters.real_oscillator.notation import NONE, angle, ascii_detail, deg, pm
from vibration.book.chapters.real_oscillator.study import RealOscillatorStudy, best_prediction, omega_n, steady_counts
from vibration.book.chapters.real_oscillator.tables import (
    LOOSE_BIC,
    LOOSE_FACTOR,
    LOOSE_UNRESOLVED,
    LOOSE_VALUE,
    brake_table,
    claims_csv,
    damping_csv,
    law_table,
    pooled_table,
    prediction_table,
    resonance_csv,
    resonance_table,
    session_table,
    steadiness_table,
    write_csv_tables,
)
from vibration.book.chapters.real_oscillator.verdicts import claims
from vibration.book.presentation.narrative import g


def provenance_text(st: RealOscillatorStudy) -> str:
    """Where the data come from: the folder's README when it names a repository and commit, else the manifest."""
    d = st.data
    n_free, n_driven = len(d.select(kind="free")), len(d.select(kind="driven"))
    formats = ", ".join(sorted(set(d.formats.values())))
    base = (
        f"The folder holds {n_free} free decays at {len(st.settings)} brake settings and {n_driven} driven runs "
        f"in {len(set(r.session for r in d.select(kind='driven')))} sessions, exported by {formats}."
    )
    readme = d.folder and (st.folder + "/README.md")
    text = ""
    try:
        with open(readme, encoding="utf-8") as fh:
            text = fh.read()
    except OSError:
        pass
    repo = re.search(r"GitHub repository\s+`([^`]+)`", text)
    commit = re.search(r"commit\s+`([0-9a-f]{40})`", text)
    if repo and commit:
        base = (
            f"The measurements are raw logger exports from a teaching lab, published in the GitHub repository "
            f"`{repo.group(1)}` (commit `{commit.group(1)}`); cite them wherever they are used. " + base
        )
    rig = d.rig
    if rig.encoder_step_rad:
        base += f" The angle sensor's step is {g(rig.encoder_step_rad, 3)} rad."
    if rig.max_angle_rad:
        base += f" The wheel can turn at most {angle(rig.max_angle_rad)}."
    else:
        base += " The largest angle the wheel can turn is not documented."
    return base


# ----------------------------------------------------------------------------- damping against amplitude


def law_sentence(st: RealOscillatorStudy) -> str:
    """Which law the data choose, per setting and over which amplitudes."""
    parts = []
    for s in st.settings:
        n = len(s.runs)
        won = s.wins.get(s.law, 0)
        parts.append(
            f"with the brake {s.brake}, {LAW_WORDS[s.law]} ({won} of {n} runs on their own, over amplitudes "
            f"{g(s.amplitude_range[0], 2)} to {angle(s.amplitude_range[1], 2)})"
        )
    amp_dep = [s for s in st.settings if s.law in ("coulomb+quadratic", "coulomb+power")]
    tail = (
        " An amplitude-dependent loss is chosen: at large amplitudes the loss per half period grows faster than "
        "dry friction (a constant loss) and a viscous term (a loss in proportion to the amplitude) allow."
        if amp_dep
        else " No setting's decays need an amplitude-dependent loss beyond dry friction and a viscous term."
    )
    return "By the information criterion summed over runs, the data choose: " + "; ".join(parts) + "." + tail


def brake_sentence(st: RealOscillatorStudy) -> str:
    """A plain statement whether the brake effect is resolved."""
    if not st.comparisons:
        return (
            "The free decays come from one brake setting only, so the brake's effect cannot be measured here; "
            "free decays at a second setting would measure it."
        )
    out = []
    for a, b, d, j in st.comparisons:
        verdict = "is resolved" if brake_resolved(d, j) else "is not resolved"
        out.append(
            f"Brake {b} against {a}, at matched amplitudes of {g(d.band[0], 3)} to {g(d.band[1], 3)} rad: "
            "ζ<sub>eq</sub> differs by "
            f"{pm(d.delta_zeta, d.stderr, 2)} (95 % interval {g(d.ci_low, 2)} to {g(d.ci_high, 2)}, {d.method}); "
            f"the joint fit gives a brake-only viscous ratio of {pm(j.delta_zeta, j.stderr, 2)}. The brake effect "
            f"{verdict}."
        )
    return " ".join(out)


# ----------------------------------------------------------------------------- driven runs


def steadiness_sentence(st: RealOscillatorStudy) -> str:
    """How many runs are steady, near resonance and elsewhere, and what the others do."""
    n_st, n, n_near_st, n_near = steady_counts(st)
    near = [d for d in st.driven if abs(d.omega / omega_n(st) - 1.0) <= 0.05]
    t90 = float(np.median([d.steady.t90 for d in near if d.steady.steady])) if n_near_st else math.nan
    drift = [d.steady.drift for d in near if d.steady.steady]
    grow = sum(1 for d in st.driven if not d.steady.steady and d.steady.drift > 0)
    fdrift = max((abs(d.frequency_drift) for d in st.driven), default=0.0)
    cd = max((abs(d.centre_drift) for d in st.driven), default=0.0)
    s = (
        f"{n_st} of {n} driven runs are steady by their late drift (tolerance {g(100 * st.params.tolerance, 2)} % "
        f"over the last {st.params.periods} drive periods)"
    )
    if n_near:
        s += f", {n_near_st} of the {n_near} within 5 % of ω<sub>n</sub>"
    if n_near_st:
        s += f"; these reach 90 % of their final amplitude in a median {g(t90, 2)} s"
        if drift:
            s += f" and drift by {g(100 * float(np.mean(drift)), 2)} % on average over their last periods"
    s += (
        f". Of the others, {grow} end rising and {n - n_st - grow} end falling (still building up, beating or "
        "decaying): their amplitudes are not used as steady ones. The drive frequency changes by up to "
        f"{g(100 * fdrift, 2)} % within a run and the wheel's "
        f"centre moves by up to {angle(cd, 2)}."
    )
    return s


def session_sentence(st: RealOscillatorStudy) -> str:
    """How far apart the sessions are at matched drive frequency (the systematic error across sessions)."""
    if len(st.sessions) < 2:
        return "All driven runs come from one session, so no comparison crosses sessions."
    sp = st.spread
    if not sp.pairs:
        return (
            f"The driven runs come from {len(st.sessions)} sessions with no drive frequency in common, so the "
            "session-to-session spread is unknown and no comparison across sessions is made with a stated error."
        )
    first, second = st.sessions[0].session, st.sessions[1].session
    return (
        f"At matched drive frequency ({sp.pairs} pairs of groups within "
        f"{g(100 * st.params.frequency_tolerance, 2)} %), "
        f"the steady amplitude per unit drive differs between sessions by {g(100 * sp.spread, 2)} % rms "
        f"(session {first} over session {second}: {g(100 * sp.mean_log_ratio, 2)} % on average, both as logarithmic "
        "ratios). "
        "Settings are compared within a session; a comparison across sessions carries this spread as a systematic "
        "error, and the single gain used here for all sessions leaves part of it in the prediction errors."
    )


# ----------------------------------------------------------------------------- prediction


def prediction_sentence(st: RealOscillatorStudy) -> str:
    """Which law predicts best, how sensitive that is to the gain, and the rig's limit."""
    best = best_prediction(st)
    if best is None:
        return (
            "No prediction is possible with these data: it needs steady driven runs with a recorded drive signal, "
            "some of them away from resonance to calibrate the gain, and free decays at the same brake setting."
        )
    paper = st.predictions.get((best.brake, PAPER_LAW))
    n_cal, n_pred = len(best.calibration), len(best.predicted)
    lo = min(e for _, e in best.sensitivity)
    hi = max(e for _, e in best.sensitivity)
    s = (
        f"Calibrated on {n_cal} steady runs away from resonance and predicting the other {n_pred}, the "
        f"{LAW_WORDS[best.law]} law does best: pooled error {g(100 * best.pooled_error, 2)} %, between "
        f"{g(100 * lo, 2)} % and {g(100 * hi, 2)} % for gains 0.8 to 1.2 times the calibrated one"
    )
    if paper is not None and paper is not best:
        s += f"; the paper's viscous law errs by {g(100 * paper.pooled_error, 2)} %"
    s += "."
    chosen = next((x.law for x in st.settings if x.brake == best.brake), None)
    if chosen is not None and chosen != best.law and (best.brake, chosen) in st.predictions:
        c = st.predictions[(best.brake, chosen)]
        s += (
            f" The law the free decays choose, {LAW_WORDS[chosen]}, errs by {g(100 * c.pooled_error, 2)} %: the "
            "better description of the decays is not the better predictor of the driven runs, whose amplitudes "
            "lie beyond most of the decays' range."
            if max((d.steady.amplitude for d in best.predicted), default=0.0)
            > max(x.amplitude_range[1] for x in st.settings if x.brake == best.brake)
            else f" The law the free decays choose, {LAW_WORDS[chosen]}, errs by {g(100 * c.pooled_error, 2)} %."
        )
    s += simulation_sentence(st)
    measured = max((gr.amplitude for gr in st.groups if gr.n_steady), default=math.nan)
    res = max((a for _, a in best.resonance.values()), default=math.nan)
    if math.isfinite(measured):
        s += (
            f" The largest steady amplitude measured is {angle(measured)}; the best law's steady resonance is "
            f"{angle(res)}."
        )
    limit = st.data.rig.max_angle_rad
    over = [
        LAW_WORDS[p.law]
        for p in st.predictions.values()
        if limit and max((a for _, a in p.resonance.values()), default=0.0) > limit
    ]
    if limit and over:
        s += f" The steady resonance of {', '.join(over)} exceeds the {angle(limit)} the wheel can turn."
    elif not limit:
        s += " Whether the wheel can physically turn that far is not documented for this rig."
    return s


def simulation_sentence(st: RealOscillatorStudy) -> str:
    """The prediction by simulation beside harmonic balance (leading space; empty without simulations)."""
    sims = [p for p in st.predictions.values() if math.isfinite(p.sim_pooled_error)]
    if not sims:
        return " No run could be simulated from its measured start, so the prediction rests on harmonic balance alone."
    best = min(sims, key=lambda p: p.sim_pooled_error)
    hb = best_prediction(st)
    finite = [p for p in sims if math.isfinite(p.pooled_error)]
    s = (
        f" Simulating each predicted run from its own measured angle and velocity with its measured drive, the gain "
        f"calibrated the same way, and comparing the amplitudes over the same final {st.params.periods} drive "
        f"periods, the {LAW_WORDS[best.law]} law does best, with a pooled error of "
        f"{g(100 * best.sim_pooled_error, 2)} % (harmonic balance: {g(100 * best.pooled_error, 2)} %)"
    )
    if hb is not None and hb.law != best.law:
        s += f"; by harmonic balance the best is {LAW_WORDS[hb.law]}"
    s += "."
    if finite:
        worst = max(finite, key=lambda p: abs(p.sim_pooled_error - p.pooled_error))
        own = abs(best.sim_pooled_error - best.pooled_error)
        s += (
            f" The two methods differ most for the {LAW_WORDS[worst.law]} law "
            f"({g(100 * worst.pooled_error, 2)} % against {g(100 * worst.sim_pooled_error, 2)} %)"
        )
        if math.isfinite(best.pooled_error) and own <= 0.25 * best.sim_pooled_error:
            s += (
                f"; for the best law they differ by {g(100 * own, 2)} percentage points, so the one-harmonic "
                "approximation is not what limits its prediction"
            )
        s += "."
    return s


# ----------------------------------------------------------------------------- the chapter


def key_results(st: RealOscillatorStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    n_st, n, n_near_st, n_near = steady_counts(st)
    lines = [
        "Damping law chosen by the free decays: "
        + "; ".join(
            f"brake {s.brake}, {LAW_WORDS[s.law]} ({s.wins.get(s.law, 0)} of {len(s.runs)} runs)" for s in st.settings
        )
        + "."
    ]
    lines.append(brake_sentence(st).split(". ")[-1] if st.comparisons else brake_sentence(st))
    lines.append(f"{n_st} of {n} driven runs are steady by late drift ({n_near_st} of {n_near} near resonance).")
    best = best_prediction(st)
    if best is not None:
        line = (
            f"Best predictor of the steady runs: {LAW_WORDS[best.law]}, pooled error {g(100 * best.pooled_error, 2)} % "
            "by harmonic balance"
        )
        if math.isfinite(best.sim_pooled_error):
            line += f", {g(100 * best.sim_pooled_error, 2)} % simulated from each run's measured start"
        lines.append(line + ".")
    lines.append("Verdicts: " + "; ".join(f"{c.short}: {c.verdict}" for c in claims(st)) + ".")
    return "\n".join(["> **Key results**", ">"] + [f"> * {s}" for s in lines])


def summary_text(st: RealOscillatorStudy) -> str:
    """The chapter's closing paragraph: what a lab instructor takes away, in new words (the sections' sentences
    are not repeated; their numbers are in the key results)."""
    laws = {s.law for s in st.settings}
    if laws == {"viscous"}:
        out = ["On this wheel one damping ratio describes every amplitude the decays cover, as the paper's model "
               "assumes."]  # fmt: skip
    else:
        chosen = " and ".join(sorted(LAW_WORDS[law] for law in laws))
        out = [
            f"On this wheel the damping is not one ratio: the decays choose {chosen}, so a damping ratio quoted for "
            "the wheel holds only at the amplitude it was measured at, and settings must be compared at matched "
            "amplitude."
        ]
    if st.comparisons and not any(brake_resolved(d, j) for _, _, d, j in st.comparisons):
        out.append("At matched amplitude these decays cannot tell the brake settings apart; more decays per setting "
                   "over one amplitude range would.")  # fmt: skip
    elif st.comparisons:
        out.append("At matched amplitude the decays tell the brake settings apart.")
    n_st, n, _, _ = steady_counts(st)
    best = best_prediction(st)
    if best is not None:
        decays_law = next((x.law for x in st.settings if x.brake == best.brake), best.law)
        which = (
            "which is also the law the decays choose"
            if decays_law == best.law
            else "not the law that describes the decays best"
        )
        out.append(
            f"To predict the driven wheel, read only the runs that have settled ({n_st} of {n} here), calibrate the "
            f"drive's gain away from resonance, and use the law that predicts best ({LAW_WORDS[best.law]} here, "
            f"{g(100 * best.pooled_error, 2)} %), {which}."
        )
    else:
        out.append(f"{n_st} of {n} driven runs settle, and these data allow no prediction of them.")
    return " ".join(out)


__all__ = [
    "LOOSE_BIC",
    "LOOSE_FACTOR",
    "LOOSE_UNRESOLVED",
    "LOOSE_VALUE",
    "NONE",
    "angle",
    "ascii_detail",
    "best_prediction",
    "brake_resolved",
    "brake_sentence",
    "brake_table",
    "claims_csv",
    "damping_csv",
    "deg",
    "key_results",
    "law_sentence",
    "law_table",
    "pm",
    "pooled_table",
    "prediction_sentence",
    "prediction_table",
    "provenance_text",
    "resonance_csv",
    "resonance_table",
    "session_sentence",
    "session_table",
    "simulation_sentence",
    "steadiness_sentence",
    "steadiness_table",
    "steady_counts",
    "summary_text",
    "write_csv_tables",
]
