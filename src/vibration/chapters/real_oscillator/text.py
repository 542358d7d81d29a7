"""Sentences and tables of the real-oscillator chapter, each a function of the study's record.

Every number comes from :class:`~vibration.chapters.real_oscillator.study.RealOscillatorStudy`; every
sentence is chosen by the data it describes (a second brake setting, driven runs at two settings, a
rig's documented largest angle), so a run on another laboratory's folder never leaves a statement its
tables contradict.
"""

from __future__ import annotations

import math
import re

import numpy as np

from vibration.chapters.real_oscillator.figures import LAW_WORDS
from vibration.chapters.real_oscillator.study import PAPER_LAW, RealOscillatorStudy
from vibration.presentation.narrative import g
from vibration.presentation.tables import Approx, Column, Composite, Missing, Table

NONE = Missing(reason="not available with these data")


def deg(x: float) -> float:
    """Radians to degrees."""
    return math.degrees(x)


def angle(x: float, digits: int = 3) -> str:
    """An angle in rad and degrees for a sentence."""
    if not math.isfinite(x):
        return "unbounded"
    d = deg(x)
    return f"{g(x, digits)} rad ({d:.0f}°)" if abs(d) >= 10 else f"{g(x, digits)} rad ({g(d, 2)}°)"


def pm(x: float, s: float, digits: int = 3) -> str:
    """x ± s for a sentence (the error with two figures)."""
    if not math.isfinite(s):
        return g(x, digits)
    return f"{g(x, digits)} ± {g(s, 2)}"


def _wins(s) -> str:
    return ", ".join(f"{LAW_WORDS[k]} {v}" for k, v in s.wins.items() if v)


def best_prediction(st: RealOscillatorStudy):
    """The prediction of smallest pooled error (None without predictions)."""
    ps = [p for p in st.predictions.values() if math.isfinite(p.pooled_error)]
    return min(ps, key=lambda p: p.pooled_error) if ps else None


def steady_counts(st: RealOscillatorStudy) -> tuple[int, int, int, int]:
    """Steady runs, runs, steady runs within 5 % of ω_n, runs within 5 % of ω_n."""
    wn = _omega_n(st)
    near = [d for d in st.driven if abs(d.omega / wn - 1.0) <= 0.05]
    return (
        sum(d.steady.steady for d in st.driven),
        len(st.driven),
        sum(d.steady.steady for d in near),
        len(near),
    )


def _omega_n(st: RealOscillatorStudy) -> float:
    s = st.settings[-1]
    return s.fits["coulomb+viscous"].mean["omega_n"] if "coulomb+viscous" in s.fits else s.fits[s.law].mean["omega_n"]


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


def law_table(st: RealOscillatorStudy) -> Table:
    """The law each brake setting's free decays choose, and its equivalent damping in the common band."""
    rows = []
    for s in st.settings:
        rows.append(
            {
                "brake": s.brake,
                "current": s.current if s.current is not None else NONE,
                "law": LAW_WORDS[s.law],
                "wins": _wins(s),
                "range": f"{g(s.amplitude_range[0], 2)}–{g(s.amplitude_range[1], 2)}",
                "zeta": pm(s.zeta_eq, s.zeta_eq_stderr, 3) if math.isfinite(s.zeta_eq) else NONE,
            }
        )
    band = f" ({g(st.band[0], 3)} to {g(st.band[1], 3)} rad)" if st.band else ""
    t = Table(
        rows,
        [
            Column(key="brake", header="brake"),
            Column(key="current", header="I (A)", digits=3),
            Column(key="law", header="law (summed BIC)"),
            Column(key="wins", header="runs choosing each law"),
            Column(key="range", header="X (rad)"),
            Column(key="zeta", header="ζ_eq in the band"),
        ],
        f"The damping law each brake setting's free decays choose, and the mean equivalent damping ratio "
        f"with its run-to-run error over the common amplitude band{band}.",
        "tab-real-laws",
    )
    t.csv = False
    return t


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


def brake_table(st: RealOscillatorStudy) -> Table | None:
    """The brake at matched amplitude: bootstrap difference and the joint fit, per compared pair."""
    if not st.comparisons:
        return None
    rows = []
    for a, b, d, j in st.comparisons:
        rows.append(
            {
                "pair": f"{b} − {a}",
                "band": f"{g(d.band[0], 3)}–{g(d.band[1], 3)}",
                "dz": pm(d.delta_zeta, d.stderr, 2),
                "ci": f"{g(d.ci_low, 2)} to {g(d.ci_high, 2)}",
                "joint": pm(j.delta_zeta, j.stderr, 2),
                "resolved": brake_resolved(d, j),
            }
        )
    t = Table(
        rows,
        [
            Column(key="pair", header="settings"),
            Column(key="band", header="X band (rad)"),
            Column(key="dz", header="ζ_eq difference (bootstrap)"),
            Column(key="ci", header="95 % interval"),
            Column(key="joint", header="brake-only ζ (joint fit)"),
            Column(key="resolved", header="resolved"),
        ],
        "The brake at matched amplitude: the difference of mean equivalent damping inside the band, by bootstrap "
        "over runs, and the brake-only viscous term of a joint fit with one shared amplitude law.",
        "tab-real-brake",
    )
    t.csv = False
    return t


def brake_resolved(d, j) -> bool:
    """Resolved when both estimates exclude 0 (two standard errors) with the same sign."""
    joint_out = abs(j.delta_zeta) > 2.0 * j.stderr
    return bool(d.resolved and joint_out and np.sign(d.delta_zeta) == np.sign(j.delta_zeta))


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


def _label(d) -> str:
    if d.steady.steady:
        return "steady"
    return "growing" if d.steady.drift > 0 else "decaying or beating"


def resonance_table(st: RealOscillatorStudy) -> Table:
    """Driven-run groups: steady amplitude per brake setting, session and drive frequency."""
    rows = []
    for gr in st.groups:
        rows.append(
            {
                "brake": gr.brake,
                "session": gr.session,
                "omega": gr.omega,
                "amp": pm(gr.amplitude, gr.amplitude_stderr, 3) if gr.n_steady else NONE,
                "deg": deg(gr.amplitude) if gr.n_steady else NONE,
                "steady": f"{gr.n_steady} of {len(gr.runs)}",
                "t90": float(np.median([d.steady.t90 for d in gr.runs])),
            }
        )
    t = Table(
        rows,
        [
            Column(key="brake", header="brake"),
            Column(key="session", header="session"),
            Column(key="omega", header="ω (rad/s)", digits=4),
            Column(key="amp", header="amplitude (rad)"),
            Column(key="deg", header="amplitude (°)", digits=3),
            Column(key="steady", header="steady runs"),
            Column(key="t90", header="t_90 (s)", digits=2),
        ],
        "Driven runs grouped by measured drive frequency: the mean late amplitude of the steady runs with its "
        "run-to-run error, and the median time to 90 % of the final amplitude.",
        "tab-real-groups",
    )
    t.csv = False
    return t


def steadiness_sentence(st: RealOscillatorStudy) -> str:
    """How many runs are steady, near resonance and elsewhere, and what the others do."""
    n_st, n, n_near_st, n_near = steady_counts(st)
    near = [d for d in st.driven if abs(d.omega / _omega_n(st) - 1.0) <= 0.05]
    t90 = float(np.median([d.steady.t90 for d in near])) if near else math.nan
    drift = [d.steady.drift for d in near if d.steady.steady]
    grow = sum(1 for d in st.driven if not d.steady.steady and d.steady.drift > 0)
    fdrift = max((abs(d.frequency_drift) for d in st.driven), default=0.0)
    cd = max((abs(d.centre_drift) for d in st.driven), default=0.0)
    s = (
        f"{n_st} of {n} driven runs are steady by their late drift (tolerance {g(100 * st.params.tolerance, 2)} % "
        f"over the last {st.params.periods} drive periods)"
    )
    if n_near:
        s += (
            f", {n_near_st} of the {n_near} within 5 % of ω<sub>n</sub>; these reach 90 % of their final amplitude "
            f"in a median {g(t90, 2)} s"
        )
        if drift:
            s += f" and drift by {g(100 * float(np.mean(drift)), 2)} % on average over their last periods"
    s += (
        f". Of the others, {grow} end rising and {n - n_st - grow} end falling (still building up, beating or "
        "decaying): their amplitudes are not used as steady ones. The drive frequency changes by up to "
        f"{g(100 * fdrift, 2)} % within a run and the wheel's "
        f"centre moves by up to {angle(cd, 2)}."
    )
    return s


# ----------------------------------------------------------------------------- prediction


def prediction_table(st: RealOscillatorStudy) -> Table | None:
    """Each law's calibrated gain, pooled prediction error (overall and per session) and steady resonance."""
    if not st.predictions:
        return None
    rows = []
    for (b, law), p in st.predictions.items():
        res = max((a for _, a in p.resonance.values()), default=math.nan)
        rows.append(
            {
                "law": LAW_WORDS[law],
                "brake": b,
                "gain": p.gain,
                "err": 100 * p.pooled_error if math.isfinite(p.pooled_error) else Missing(reason="unbounded"),
                "sim": 100 * p.sim_pooled_error
                if math.isfinite(p.sim_pooled_error)
                else Missing(reason="not simulated"),
                "res": res if math.isfinite(res) else Missing(reason="unbounded"),
                "resdeg": deg(res) if math.isfinite(res) else Missing(reason="unbounded"),
            }
        )
    t = Table(
        rows,
        [
            Column(key="law", header="law"),
            Column(key="brake", header="brake"),
            Column(key="gain", header="g", digits=3),
            Column(key="err", header="error, harmonic balance (%)", digits=3),
            Column(key="sim", header="error, simulated (%)", digits=3),
            Column(key="res", header="resonance (rad)", digits=3),
            Column(key="resdeg", header="resonance (°)", digits=3),
        ],
        "Each law, its gain calibrated off resonance, predicting the other steady runs: pooled rms relative error "
        "by harmonic balance and by simulating each run from its measured start with its measured drive, and the "
        "law's largest steady amplitude at the mean drive.",
        "tab-real-prediction",
    )
    t.csv = False
    return t


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


# ----------------------------------------------------------------------------- details


def steadiness_table(st: RealOscillatorStudy) -> Table:
    """Every driven run: frequency, late drift, t90, label, drive-frequency and centre drift."""
    rows = [
        {
            "run": f"{d.run.session}/{d.run.run}",
            "brake": d.run.brake,
            "omega": d.omega,
            "drift": f"{g(100 * d.steady.drift, 2)} ± {g(100 * d.steady.drift_stderr, 1)}",
            "t90": d.steady.t90,
            "label": _label(d),
            "fdrift": 100 * d.frequency_drift,
            "centre": d.centre_drift,
        }
        for d in st.driven
    ]
    t = Table(
        rows,
        [
            Column(key="run", header="session/run"),
            Column(key="brake", header="brake"),
            Column(key="omega", header="ω (rad/s)", digits=4),
            Column(key="drift", header="late drift (%)"),
            Column(key="t90", header="t_90 (s)", digits=2),
            Column(key="label", header="state"),
            Column(key="fdrift", header="drive drift (%)", digits=2),
            Column(key="centre", header="centre drift (rad)", digits=2),
        ],
        "Every driven run: late drift with its standard error, time to 90 % of the final amplitude, and the "
        "change of drive frequency and of the wheel's centre over the record.",
        "tab-real-runs",
    )
    t.csv = False
    return t


def session_table(st: RealOscillatorStudy) -> Table | None:
    """Per session: runs, steady runs, drive-frequency and centre drift, and the best law's errors."""
    if not st.sessions:
        return None
    best = best_prediction(st)
    rows = []
    for ss in st.sessions:
        fm, fl, fh = (100 * x for x in ss.frequency_drift)
        cm, cl, ch = ss.centre_drift
        hb = best.session_errors.get(ss.session, math.nan) if best else math.nan
        sim = best.sim_session_errors.get(ss.session, math.nan) if best else math.nan
        rows.append(
            {
                "session": ss.session,
                "runs": f"{ss.steady} of {ss.runs}",
                "fdrift": f"{g(fm, 2)} ({g(fl, 2)} to {g(fh, 2)})",
                "centre": f"{g(cm, 2)} ({g(cl, 2)} to {g(ch, 2)})",
                "hb": 100 * hb if math.isfinite(hb) else Missing(reason="no predicted run"),
                "sim": 100 * sim if math.isfinite(sim) else Missing(reason="no predicted run"),
            }
        )
    law = f" ({LAW_WORDS[best.law]})" if best else ""
    t = Table(
        rows,
        [
            Column(key="session", header="session"),
            Column(key="runs", header="steady runs"),
            Column(key="fdrift", header="drive drift (%), median (range)"),
            Column(key="centre", header="centre drift (rad), median (range)"),
            Column(key="hb", header="error, harmonic balance (%)", digits=3),
            Column(key="sim", header="error, simulated (%)", digits=3),
        ],
        "Each session's driven runs: how many are steady, the change of drive frequency from the first to the second "
        f"half of each record and of the wheel's centre from the first to the last period, and the prediction "
        f"error of the best law{law}.",
        "tab-real-sessions",
    )
    t.csv = False
    return t


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


def pooled_table(st: RealOscillatorStudy) -> Table:
    """Every law's pooled coefficients per brake setting, with run-to-run errors, BIC and residual over step."""
    rows = []
    for s in st.settings:
        for law, p in s.fits.items():
            loose = "power" in law  # a weakly determined exponent: its digits depend on the machine's rounding

            def num(value, digits, *, loose=loose, **tolerance):
                return (Approx(value=value, **tolerance), digits) if loose else g(value, digits)

            parts = []
            for k, v in p.coefficients.items():
                factor = LOOSE_UNRESOLVED if k == "power" else LOOSE_FACTOR
                parts += ["; " if parts else "", f"{_SYMBOL[k]} = ", num(v, 3, factor=factor), " ± "]
                parts += [num(p.stderr[_KEY[k]], 2, factor=LOOSE_FACTOR)]
            omega = (
                "",
                num(p.mean["omega_n"], 4, rtol=LOOSE_VALUE),
                " ± ",
                num(p.stderr["omega_n"], 2, factor=LOOSE_FACTOR),
            )
            rows.append(
                {
                    "brake": s.brake,
                    "law": LAW_WORDS[law],
                    "omega_n": Composite(parts=omega) if loose else "".join(omega),
                    "coef": Composite(parts=tuple(parts)) if loose else "".join(parts),
                    "bic": Approx(value=p.bic, rtol=LOOSE_BIC) if loose else p.bic,
                    "rms": Approx(value=p.rms_over_step, rtol=LOOSE_VALUE) if loose else p.rms_over_step,
                }
            )
    t = Table(
        rows,
        [
            Column(key="brake", header="brake"),
            Column(key="law", header="law"),
            Column(key="omega_n", header="ω_n (rad/s)"),
            Column(key="coef", header="coefficients (run-to-run error)"),
            Column(key="bic", header="BIC (sum)", digits=6),
            Column(key="rms", header="rms / (step/√12)", digits=3),
        ],
        "Every law fitted to every free decay, pooled per brake setting: coefficients (ζ; Δ in rad; b in 1/rad; a; "
        "p) with run-to-run standard errors, summed BIC, and the residual rms over the encoder's rounding noise.",
        "tab-real-fits",
        notes=(
            "The power law's exponent is weakly determined by the decays: the last digits of its rows depend on the "
            "computer's floating-point rounding.",
        ),
    )
    t.csv = False
    return t


#: Tolerances of the power law's machine-dependent digits (declared for the regression comparison): ω_n and the
#: rms within 50 %, its coefficients and their run-to-run errors within a factor of 10 (a coefficient moved from
#: 5.4×10⁻⁶ to 2.1×10⁻⁵ between two numerical environments), its summed BIC within 1 %.
LOOSE_VALUE, LOOSE_FACTOR, LOOSE_BIC = 0.5, 10.0, 0.01
#: The power term's coefficient a itself is not resolved by the decays (its run-to-run error exceeds it by
#: orders of magnitude): any value within a factor of 1000 reads the same.
LOOSE_UNRESOLVED = 1000.0
_SYMBOL = {"viscous": "ζ", "coulomb": "Δ", "quadratic": "b", "power": "a", "power_exponent": "p"}
_KEY = {
    "viscous": "zeta",
    "coulomb": "friction",
    "quadratic": "quadratic",
    "power": "power",
    "power_exponent": "power_exponent",
}


# ----------------------------------------------------------------------------- CSV tables


def damping_csv(st: RealOscillatorStudy) -> Table:
    """tab-real-damping.csv: the equivalent damping per brake setting in the band."""
    lo, hi = st.band if st.band else (math.nan, math.nan)
    rows = [
        {
            "brake": s.brake,
            "brake_current_A": s.current if s.current is not None else Missing(reason="unknown"),
            "zeta_eq": s.zeta_eq if math.isfinite(s.zeta_eq) else Missing(reason="no band"),
            "zeta_eq_stderr": s.zeta_eq_stderr if math.isfinite(s.zeta_eq_stderr) else Missing(reason="one run"),
            "band_low_rad": lo if math.isfinite(lo) else Missing(reason="no band"),
            "band_high_rad": hi if math.isfinite(hi) else Missing(reason="no band"),
            "law": s.law,
            "n_runs": s.n_band,
        }
        for s in st.settings
    ]
    cols = ["brake", "brake_current_A", "zeta_eq", "zeta_eq_stderr", "band_low_rad", "band_high_rad", "law", "n_runs"]
    return Table(
        rows,
        [Column(key=c, header=c, digits=6) for c in cols],
        "Equivalent damping per brake setting.",
        "tab-real-damping",
    )


def resonance_csv(st: RealOscillatorStudy) -> Table:
    """tab-real-resonance.csv: the driven-run groups."""
    rows = [
        {
            "brake": gr.brake,
            "session": gr.session,
            "omega_rad_s": gr.omega,
            "amplitude_rad": gr.amplitude if gr.n_steady else Missing(reason="no steady run"),
            "amplitude_stderr_rad": gr.amplitude_stderr
            if math.isfinite(gr.amplitude_stderr)
            else Missing(reason="none"),
            "steady_runs": gr.n_steady,
            "runs": len(gr.runs),
        }
        for gr in st.groups
    ]
    cols = ["brake", "session", "omega_rad_s", "amplitude_rad", "amplitude_stderr_rad", "steady_runs", "runs"]
    if not rows:
        rows = [dict.fromkeys(cols, Missing(reason="no driven runs"))]
    return Table(rows, [Column(key=c, header=c, digits=6) for c in cols], "Driven-run groups.", "tab-real-resonance")


def claims_csv(st: RealOscillatorStudy) -> Table:
    """tab-real-claims.csv: claim_id, claim, verdict, detail."""
    from vibration.chapters.real_oscillator.verdicts import claims

    rows = [
        {"claim_id": c.claim_id, "claim": c.claim, "verdict": c.verdict, "detail": ascii_detail(c.detail)}
        for c in claims(st)
    ]
    cols = ["claim_id", "claim", "verdict", "detail"]
    return Table(
        rows, [Column(key=c, header=c) for c in cols], "The paper's claims on the hardware.", "tab-real-claims"
    )


def ascii_detail(text: str) -> str:
    """A detail for a CSV cell: ASCII minus, no ± (written out), degrees dropped (the radians stay)."""
    text = re.sub(r" \(-?[0-9.]+°\)", "", text.replace("−", "-"))
    return text.replace(" ± ", " with standard error ").replace("ωₙ", "omega_n")


def write_csv_tables(st: RealOscillatorStudy, folder=None) -> list:
    """Write the three machine-readable tables (when the runner sets the tables folder, or to ``folder``)."""
    return [t.write_csv(folder) for t in (damping_csv(st), resonance_csv(st), claims_csv(st))]


def key_results(st: RealOscillatorStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    from vibration.chapters.real_oscillator.verdicts import claims

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
    """The chapter's closing paragraph."""
    return " ".join([law_sentence(st), brake_sentence(st), steadiness_sentence(st), prediction_sentence(st)])
