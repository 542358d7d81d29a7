r"""Chapter 1's sentences and tables, all from a :class:`ReproductionStudy`.

Word conventions (tests check them against the numbers): a case is named in bold, ``**low damping**``,
as in the tables' "case" column; its regime word is the table's ("underdamped", "undamped",
"unstable", ...); "settles after T s" when the 2 % settling time is inside the window, "has not
settled by t = T s" otherwise; "the largest response is the **case**" names the damping case with
the largest peak $|x|$. The paper's resonance case and its nominal damping are one run: the tables
show it once, as "resonance = nominal damping".
"""

from __future__ import annotations

import csv
import math
import os
from pathlib import Path

from vibration.book.chapters.reproduction.study import DAMPING_IDS, CaseRun, ReproductionStudy
from vibration.book.presentation.findings import NO_STEADY, case_name
from vibration.book.presentation.narrative import fixed, g, parameters_sentence, regime_clause, sig
from vibration.book.presentation.tables import TABLES_ENV, Missing, Table, columns, fmt
from vibration.physics.audit import half_power_band

#: RK45's error (relative to the window's peak) below which the chapter calls it negligible.
SMALL_ERROR = 0.05
#: The paper's numbers for its resonance (section 3.1), quoted: amplitude (m) and amplification.
PAPER_RESONANCE_AMPLITUDE = 5.0
PAPER_AMPLIFICATION = 10.0
#: Two amplitude ratios count as proportional (x_ss following 1/c) when they agree to this fraction.
PROPORTIONAL = 0.1

X_SS = r"$x_\mathrm{ss}$"
PEAK_X = r"peak $|x|$"


# ----------------------------------------------------------------------------- clauses


def run_name(st: ReproductionStudy, sid: str) -> str:
    """The name of ``sid``'s run: "resonance = nominal damping" when two scenarios are one run."""
    return " = ".join(case_name(s) for s in st.run_of(sid))


def settle_clause(f: CaseRun, t_end: float) -> str:
    """ "it settles after T s" or "it has not settled by t = T s", from one case."""
    if f.settles:
        return f"it settles after {g(f.t_settle, 3)} s, inside the {g(t_end)} s window"
    if f.c <= 0:
        why = "it has no steady state to settle to" if f.c < 0 else "its free vibration never decays"
        return f"it has not settled by t = {g(t_end)} s and never will: {why}"
    return f"it has not settled by t = {g(t_end)} s (its 2 % settling time is {g(f.t_settle, 3)} s)"


def _amplitude_clause(f: CaseRun) -> str:
    if f.c < 0:
        return "no steady amplitude (it is never reached)"
    if not math.isfinite(f.x_ss):
        return "no finite steady amplitude (undamped at exact resonance)"
    return f"steady amplitude {X_SS} = {g(f.x_ss)} m"


def case_sentence(st: ReproductionStudy, sid: str) -> str:
    """One scenario in a sentence: damping, regime, peak, steady amplitude, settling."""
    sc, f = st.scenarios[sid], st.cases[sid]
    return (
        f"**{case_name(sid)}** (c = {sig(f.c)} N s/m, ω = {g(f.omega)} rad/s): "
        f"{regime_clause(sc.oscillator, sc.force, sc.t_end)}; {PEAK_X} = {g(f.peak_x)} m in the window, "
        f"{_amplitude_clause(f)}; {settle_clause(f, st.t_end)}."
    )


def largest_sentence(st: ReproductionStudy) -> str:
    """Which damping case has the largest peak |x| in the window."""
    f = st.largest
    return (
        f"The largest response is the **{case_name(f.scenario_id)}** case: {PEAK_X} = {g(f.peak_x)} m in the "
        f"{g(st.t_end)} s window."
    )


def band_clause(st: ReproductionStudy) -> str:
    """Where the resonance case's forcing frequency lies against the half-power band of its damping."""
    sc = st.scenarios["resonance"]
    lo, hi = half_power_band(sc.oscillator)
    w = sc.force.omega
    if sc.oscillator.c < 0:
        return "but with negative damping there is no steady state, so no half-power band"
    if sc.oscillator.c == 0:
        return "but undamped its resonant peak is infinite, so there is no half-power band"
    if lo is None or hi is None:
        return "but at this damping the response has no resonant peak, so no half-power band"
    where = "inside" if lo <= w <= hi else "outside"
    text = f"{where} the half-power band ({g(lo)} to {g(hi)} rad/s) of its damping"
    if where == "outside":
        text += ", so this run's resonance case is not at resonance"
    return text


# ----------------------------------------------------------------------------- the chapter's text


def key_results(st: ReproductionStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    res, ref = st.cases["resonance"], st.cases["reference"]
    items = []
    if math.isfinite(st.ratio):
        items.append(
            f"At ω = {g(res.omega)} rad/s the exact steady amplitude is {g(res.x_ss)} m, {g(st.ratio, 3)} times the "
            f"{g(ref.x_ss)} m at the reference frequency ω = {g(ref.omega)} rad/s (the paper reports "
            f"±{g(PAPER_RESONANCE_AMPLITUDE)} m and about {g(PAPER_AMPLIFICATION)} times)."
        )
    else:
        items.append(
            f"With c = {sig(res.c)} N s/m the resonance case has no finite steady amplitude: its largest displacement "
            f"in the window is {g(res.peak_x)} m."
        )
    worst = st.worst
    verdict = (
        "so the gaps between the paper's text and the exact numbers are not numerical"
        if worst.rel_err < SMALL_ERROR
        else "large enough that the solver's tolerances matter with these parameters"
    )
    items.append(
        f"The paper's own solver's worst displacement error, measured against the exact solution and relative to "
        f"each run's largest displacement, is {g(100 * worst.rel_err, 2)} % or less, {verdict}."
    )
    for sid in ("damping_low", "damping_high"):
        items.append(_key_damping(st, sid))
    lines = ["> **Key results**", ">"] + [f"> * {s}" for s in items]
    note = changed_note(st.params)
    return "\n".join(lines + ([">", f"> *{note}*"] if note else []))


#: The paper's parameters a Part I chapter may change (the others are numerical choices).
PAPER_PARAMETERS = ("m", "k", "F0", "t_end", "omega_ref", "omega_res", "c_low", "c_nominal", "c_high")


def changed_note(params) -> str | None:
    """The sentence naming the paper's parameters this run changed, or ``None`` when it changed none."""
    text = parameters_sentence(**{n: getattr(params, n) for n in PAPER_PARAMETERS})
    return None if text.startswith("This run uses") else text


def _key_damping(st: ReproductionStudy, sid: str) -> str:
    f = st.cases[sid]
    head = f"{case_name(sid).capitalize()} (c = {sig(f.c)} N s/m)"
    if f.c < 0:
        return f"{head} is unstable: the displacement grows to {g(f.peak_x)} m in the window and keeps growing."
    if f.c == 0:
        return (
            f"{head} is undamped: nothing removes the energy the force puts in, and the displacement reaches "
            f"{g(f.peak_x)} m in the window."
        )
    if f.settles:
        return (
            f"{head} is stable and has reached its steady amplitude {g(f.x_ss)} m within {g(f.t_settle, 3)} s; "
            f"its largest displacement is {g(f.peak_x)} m."
        )
    return (
        f"{head} is stable, but slow: at the end of the {g(st.t_end)} s window the displacement ({g(f.peak_x)} m) "
        f"is still rising toward {g(f.x_ss)} m, which it reaches (2 %) only after {g(f.t_settle, 3)} s."
    )


def resonance_text(st: ReproductionStudy) -> str:
    """What the resonance figure shows: the resonance case against the reference case, from the run's numbers."""
    sc = st.scenarios["resonance"]
    f = st.cases["resonance"]
    lines = [
        f"The resonance case forces the oscillator at ω = {g(sc.force.omega)} rad/s, $\\omega/\\omega_n$ = "
        f"{g(f.detuning, 5)} of its natural frequency $\\omega_n = \\sqrt{{k/m}}$ = {g(f.omega_n)} rad/s, "
        f"{band_clause(st)}.",
        "",
        "- " + case_sentence(st, "resonance"),
        "- " + case_sentence(st, "reference"),
    ]
    ref = st.cases["reference"]
    if math.isfinite(st.ratio):
        lines += [
            "",
            f"Moving the forcing from ω = {g(ref.omega)} to {g(f.omega)} rad/s multiplies the steady amplitude by "
            f"{g(st.ratio, 3)} and the window's peak by {g(f.peak_x / ref.peak_x, 3)} ({g(f.peak_x)} m against "
            f"{g(ref.peak_x)} m).",
        ]
    return "\n".join(lines)


def damping_text(st: ReproductionStudy) -> str:
    """What the damping figure shows, case by case; the nominal damping named as the resonance run."""
    lines = []
    for sid in DAMPING_IDS:
        run = st.run_of(sid)
        if sid == "damping_nominal" and "resonance" in run:
            lines.append(
                f'- **{case_name(sid)}** is the resonance run of the previous section (the paper: "This is the case '
                f'also examined in Figure 1"): the same c = {sig(st.cases[sid].c)} N s/m at the same forcing, '
                "computed once."
            )
        else:
            lines.append("- " + case_sentence(st, sid))
    return "\n".join(lines) + "\n\n" + largest_sentence(st)


def accuracy_text(st: ReproductionStudy) -> str:
    """How close the paper's method comes to the exact solution, and where it strays most."""
    worst = st.worst
    best = min(st.cases.values(), key=lambda f: f.rel_err)
    text = (
        f"The paper's method strays most from the exact displacement in the **{run_name(st, worst.scenario_id)}** "
        f"run, by {g(worst.max_err_x, 3)} m or {g(100 * worst.rel_err, 2)} % of its peak, and least in the "
        f"**{run_name(st, best.scenario_id)}** run ({g(100 * best.rel_err, 2)} %)."
    )
    if worst.rel_err < SMALL_ERROR:
        return text + (
            f" Below {g(100 * SMALL_ERROR)} % everywhere, this error cannot explain a factor between the paper's "
            "numbers and the exact ones; chapter 3 measures what tighter tolerances cost."
        )
    return text + (
        f" That is more than {g(100 * SMALL_ERROR)} %: with these parameters the default tolerances matter "
        "(chapter 3 measures them)."
    )


def designer_text(st: ReproductionStudy) -> str:
    """The summary: what a designer takes away, in new words, each from the run's numbers."""
    low, nom, high = (st.cases[s] for s in DAMPING_IDS)
    ref = st.cases["reference"]
    bullets = []
    if low.has_steady and nom.has_steady and low.c > 0 and nom.c > 0 and low.c != nom.c:
        amp, fewer = low.x_ss / nom.x_ss, nom.c / low.c
        if abs(amp / fewer - 1) < PROPORTIONAL:
            head = f"At this forcing damping alone sets the amplitude: {X_SS} follows 1/c"
        else:
            head = f"At this forcing {X_SS} does not follow 1/c (the forcing is away from $\\omega_n$)"
        text = (
            f"{head}, and changing c from {g(nom.c)} to {g(low.c)} N s/m (a factor {g(fewer, 3)}) changes it by a "
            f"factor {g(amp, 3)}."
        )
        if ref.has_steady and ref.x_ss < nom.x_ss:
            text += (
                f" Detuning is the other lever: the reference frequency, {g(100 * abs(1 - ref.detuning), 2)} % away "
                f"from $\\omega_n$, gives {g(ref.x_ss)} m with the same damper."
            )
        bullets.append(text)
    if low.c > 0 and nom.c > 0:
        slower = "Lighter damping is slower too" if low.t_settle > nom.t_settle else "The settling times compare"
        longer = low.t_settle > st.t_end
        bullets.append(
            f"{slower}: the 2 % settling time is {g(low.t_settle, 3)} s at c = {g(low.c)} N s/m against "
            f"{g(nom.t_settle, 3)} s at {g(nom.c)} N s/m"
            + (
                f"; the first is longer than the {g(st.t_end)} s record, so a response still growing at the end of "
                "a record is no proof of instability: the sign of c decides, through the roots of $m s^2 + c s + k$."
                if longer
                else f", both inside the {g(st.t_end)} s record."
            )
        )
    elif low.c < 0:
        bullets.append(
            f"With c = {sig(low.c)} N s/m the damper feeds energy in instead of taking it out: a root of "
            "$m s^2 + c s + k$ lies in the right half-plane and the response grows without bound at any forcing; "
            "only positive damping makes it settle."
        )
    elif low.c == 0:
        bullets.append(
            "With c = 0 the roots of $m s^2 + c s + k$ sit on the imaginary axis: the free vibration never decays, "
            "and forced exactly at $\\omega_n$ the response would grow without bound; only positive damping makes "
            "it settle."
        )
    if high.has_steady and high.c > 0:
        sc = st.scenarios["damping_high"]
        static = sc.force.F0 / sc.oscillator.k
        word = "below" if high.x_ss < static else "above"
        if high.zeta >= 1 / math.sqrt(2):
            head = f"Heavy damping (ζ = {g(high.zeta, 3)} ≥ 1/√2) removes the resonant peak altogether"
        else:
            head = f"At ζ = {g(high.zeta, 3)} < 1/√2 the resonant peak remains, lowered"
        bullets.append(
            f"{head}: {X_SS} = {g(high.x_ss)} m is {g(high.x_ss / static, 3)} times the static deflection "
            f"$F_0/k$ = {g(static)} m ({word} it), and the damper then carries a force amplitude of "
            f"c $v_\\mathrm{{ss}}$ = {g(high.c * high.v_ss, 3)} N against $F_0$ = {g(sc.force.F0)} N."
        )
    return "\n".join("- " + b for b in bullets)


# ----------------------------------------------------------------------------- tables


def _xss_cell(f: CaseRun, value: float, digits: int = 4):
    if f.c < 0:
        return Missing(reason=NO_STEADY)
    return fixed(value, digits) if math.isfinite(value) else Missing(reason="infinite at undamped exact resonance")


def _settle_cell(f: CaseRun):
    return fixed(f.t_settle, 3) if math.isfinite(f.t_settle) else Missing(reason=NO_STEADY)


def _tau_cell(f: CaseRun):
    if f.c < 0:
        return Missing(reason="the free vibration grows when c < 0: no decay time")
    return fixed(f.tau, 3) if math.isfinite(f.tau) else Missing(reason="the free vibration never decays when c = 0")


def _by_run(st: ReproductionStudy, cells) -> list[dict]:
    """One row per distinct run: its name, then the cells ``cells(findings)`` gives for its findings."""
    return [{"case": run_name(st, run[0]), **cells(st.cases[run[0]])} for run in st.runs]


def findings_table(st: ReproductionStudy) -> Table:
    """One row per distinct run: regime, steady amplitude, window peak, settling (exact)."""
    rows = _by_run(
        st,
        lambda f: {
            "c": f.c,
            "omega": f.omega,
            "zeta": fixed(f.zeta, 3),
            "regime": f.regime,
            "xss": _xss_cell(f, f.x_ss),
            "peak": fixed(f.peak_x, 4),
            "ts": _settle_cell(f),
            "settled": f.settles,
        },
    )
    notes = ()
    if any(len(run) > 1 for run in st.runs):
        notes = (
            "resonance = nominal damping: the paper's resonance case (its Figure 1) and its nominal damping (in its "
            "Figure 2) are the same run, shown once.",
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            case     case
            c        c (N s/m)         4  nozeros
            omega    ω (rad/s)         4  nozeros
            zeta     ζ
            regime   regime
            xss      x_ss (m)
            peak     peak |x| (m)
            ts       t_s (s)
            settled  settles by t_end
            """
        ),
        caption=(
            f"Findings per run, exact: steady amplitude x_ss, largest |x| in the window [0, {g(st.t_end)}] s from "
            "rest, and the 2 % settling time t_s (the transient stays below 2 % of x_ss after it)."
        ),
        name="tab-reproduction-findings",
        notes=notes,
    )


def methods_table(st: ReproductionStudy) -> Table:
    """The paper's method beside the exact solution: peaks of x and v, worst error, time constant."""
    rows = _by_run(
        st,
        lambda f: {
            "vss": _xss_cell(f, f.v_ss),
            "pv": fixed(f.peak_v, 4),
            "pv45": fixed(f.peak_v_rk45, 4),
            "px45": fixed(f.peak_x_rk45, 4),
            "err": fixed(100 * f.rel_err, 2),
            "tau": _tau_cell(f),
        },
    )
    return Table(
        rows=rows,
        columns=columns(
            """
            case  case
            vss   v_ss (m/s)
            pv    peak |v| (m/s)
            pv45  peak |v| RK45 (m/s)
            px45  peak |x| RK45 (m)
            err   max |x_RK45 − x| (% of peak |x|)
            tau   τ (s)
            """
        ),
        caption=(
            "The paper's method (RK45 at its default tolerances) beside the exact solution: velocity amplitude "
            "v_ss = ω x_ss, peaks in the window, RK45's worst displacement error, and the time constant τ of the "
            "slowest free mode."
        ),
        name="tab-reproduction-methods",
    )


def findings_rows(st: ReproductionStudy) -> list[dict]:
    """Every scenario's findings at full precision, one dict per scenario (the columns of ``findings.csv``)."""
    return [
        {
            "scenario": f.scenario_id,
            "omega_rad_s": f.omega,
            "c_Ns_m": f.c,
            "omega_n_rad_s": f.omega_n,
            "zeta": f.zeta,
            "regime": f.regime,
            "x_ss_m": f.x_ss,
            "v_ss_m_s": f.v_ss,
            "peak_x_rk45_m": f.peak_x_rk45,
            "peak_x_exact_m": f.peak_x,
            "peak_v_rk45_m_s": f.peak_v_rk45,
            "peak_v_exact_m_s": f.peak_v,
            "max_err_x_rk45_m": f.max_err_x,
            "tau_s": f.tau,
            "t_settle_2pct_s": f.t_settle,
            "steady_in_window": f.settles,
        }
        for f in st.cases.values()
    ]


def write_findings_csv(st: ReproductionStudy, folder=None) -> Path | None:
    """Write ``findings.csv`` (one row per scenario, 10 significant figures) into ``folder`` or the tables folder."""
    folder = folder or os.environ.get(TABLES_ENV)
    if not folder:
        return None
    rows = findings_rows(st)
    path = Path(folder) / "findings.csv"
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(list(rows[0]))
        writer.writerows([fmt(r[c], 10) for c in rows[0]] for r in rows)
    return path


__all__ = [
    "accuracy_text",
    "case_sentence",
    "damping_text",
    "designer_text",
    "findings_table",
    "key_results",
    "largest_sentence",
    "methods_table",
    "resonance_text",
    "settle_clause",
    "write_findings_csv",
]
