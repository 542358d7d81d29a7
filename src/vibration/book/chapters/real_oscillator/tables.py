"""The real-oscillator chapter's tables, each a function of the study's record: the laws and the brake, the
driven runs and their sessions, the prediction, every pooled fit, and the machine-readable CSV tables.

Every number comes from :class:`~vibration.book.chapters.real_oscillator.study.RealOscillatorStudy`.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.real_oscillator.damping import brake_resolved
from vibration.book.chapters.real_oscillator.figures import LAW_WORDS
from vibration.book.chapters.real_oscillator.notation import NONE, ascii_detail, deg, pm
from vibration.book.chapters.real_oscillator.study import RealOscillatorStudy, best_prediction
from vibration.book.chapters.real_oscillator.verdicts import claims
from vibration.book.presentation.narrative import g
from vibration.book.presentation.numbers import pm_figures
from vibration.book.presentation.tables import Approx, Column, Composite, Missing, Table, columns

#: Tolerances of the power law's machine-dependent digits (declared for the regression comparison): ω_n and the
#: rms within 50 %, its coefficients and their run-to-run errors within a factor of 10 (the runs' own power fits,
#: several at the exponent's bound, move between numerical environments), its summed BIC within 1 %.
LOOSE_VALUE, LOOSE_FACTOR, LOOSE_BIC = 0.5, 10.0, 0.01
#: The power term's coefficient a itself is not resolved by the decays (its run-to-run error exceeds it by
#: orders of magnitude): any value within a factor of 1000 reads the same.
LOOSE_UNRESOLVED = 1000.0
_SYMBOL = {"viscous": "ζ", "coulomb": "θ_f", "quadratic": "β", "power": "α", "power_exponent": "n"}
_KEY = {
    "viscous": "zeta",
    "coulomb": "friction",
    "quadratic": "quadratic",
    "power": "power",
    "power_exponent": "power_exponent",
}


# ----------------------------------------------------------------------------- damping against amplitude


def _wins(s) -> str:
    return ", ".join(f"{LAW_WORDS[k]} {v}" for k, v in s.wins.items() if v)


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
    return Table(
        rows=rows,
        columns=columns(
            """
            brake    brake
            current  I (A)                   3
            law      law (summed BIC)
            wins     runs choosing each law
            range    X (rad)
            zeta     ζ_eq in the band
            """
        ),
        caption=f"The damping law each brake setting's free decays choose, and the mean equivalent damping ratio "
        f"with its run-to-run error over the common amplitude band{band}.",
        name="tab-real-laws",
        csv=False,
    )


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
    return Table(
        rows=rows,
        columns=columns(
            """
            pair      settings
            band      X band (rad)
            dz        ζ_eq difference (bootstrap)
            ci        95 % interval
            joint     brake-only ζ (joint fit)
            resolved  resolved
            """
        ),
        caption="The brake at matched amplitude: the difference of mean equivalent damping inside the band, by "
        "bootstrap over runs, and the brake-only viscous term of a joint fit with one shared amplitude law.",
        name="tab-real-brake",
        csv=False,
    )


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
    return Table(
        rows=rows,
        columns=columns(
            """
            brake    brake
            session  session
            omega    ω (rad/s)        4
            amp      amplitude (rad)
            deg      amplitude (°)    3
            steady   steady runs
            t90      t_90 (s)         2
            """
        ),
        caption="Driven runs grouped by measured drive frequency: the mean late amplitude of the steady runs with its "
        "run-to-run error, and the median time to 90 % of the final amplitude.",
        name="tab-real-groups",
        csv=False,
    )


def steadiness_table(st: RealOscillatorStudy) -> Table:
    """Every driven run: frequency, late drift, t90, label, drive-frequency and centre drift."""
    rows = [
        {
            "run": f"{d.run.session}/{d.run.run}",
            "brake": d.run.brake,
            "omega": d.omega,
            "drift": pm(100 * d.steady.drift, 100 * d.steady.drift_stderr, 2),
            "t90": d.steady.t90,
            "label": _label(d),
            "fdrift": 100 * d.frequency_drift,
            "centre": d.centre_drift,
        }
        for d in st.driven
    ]
    return Table(
        rows=rows,
        columns=columns(
            """
            run     session/run
            brake   brake
            omega   ω (rad/s)           4
            drift   late drift (%)
            t90     t_90 (s)            2
            label   state
            fdrift  drive drift (%)     2
            centre  centre drift (rad)  2
            """
        ),
        caption="Every driven run: late drift with its standard error, time to 90 % of the final amplitude, and the "
        "change of drive frequency and of the wheel's centre over the record.",
        name="tab-real-runs",
        csv=False,
    )


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
    return Table(
        rows=rows,
        columns=columns(
            """
            session  session
            runs     steady runs
            fdrift   drive drift (%), median (range)
            centre   centre drift (rad), median (range)
            hb       error, harmonic balance (%)         3
            sim      error, simulated (%)                3
            """
        ),
        caption="Each session's driven runs: how many are steady, the change of drive frequency from the first to "
        "the second half of each record and of the wheel's centre from the first to the last period, and the "
        f"prediction error of the best law{law}.",
        name="tab-real-sessions",
        csv=False,
    )


# ----------------------------------------------------------------------------- prediction and the fits


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
    return Table(
        rows=rows,
        columns=columns(
            """
            law     law
            brake   brake
            gain    g                            3
            err     error, harmonic balance (%)  3
            sim     error, simulated (%)         3
            res     resonance (rad)              3
            resdeg  resonance (°)                3
            """
        ),
        caption="Each law, its gain calibrated off resonance, predicting the other steady runs: pooled rms relative "
        "error by harmonic balance and by simulating each run from its measured start with its measured drive, and "
        "the law's largest steady amplitude at the mean drive.",
        name="tab-real-prediction",
        csv=False,
    )


def pooled_table(st: RealOscillatorStudy) -> Table:
    """Every law's pooled coefficients per brake setting, with run-to-run errors, BIC and residual over step."""
    rows = []
    for s in st.settings:
        for law, p in s.fits.items():
            loose = "power" in law  # a weakly determined exponent: its digits depend on the machine's rounding

            def num(value, digits, *, loose=loose, **tolerance):
                return (Approx(value=value, **tolerance), digits) if loose else g(value, digits)

            def pair(value, error, *, loose=loose, **tolerance):  # value ± error as the book writes it (numbers.pm)
                if not loose:
                    return (pm(value, error),)
                fv, fe = pm_figures(value, error)
                return (num(value, fv, **tolerance), " ± ", num(error, fe, factor=LOOSE_FACTOR))

            parts = []
            for k, v in p.coefficients.items():
                factor = LOOSE_UNRESOLVED if k == "power" else LOOSE_FACTOR
                parts += ["; " if parts else "", f"{_SYMBOL[k]} = ", *pair(v, p.stderr[_KEY[k]], factor=factor)]
            omega = ("", *pair(p.mean["omega_n"], p.stderr["omega_n"], rtol=LOOSE_VALUE))
            rows.append(
                {
                    "brake": s.brake,
                    "law": LAW_WORDS[law],
                    "omega_n": Composite(parts=omega) if loose else "".join(omega),
                    "coef": Composite(parts=tuple(parts)),  # its symbols carry subscripts (θ_f)
                    "bic": Approx(value=p.bic, rtol=LOOSE_BIC) if loose else p.bic,
                    "rms": Approx(value=p.rms_over_step, rtol=LOOSE_VALUE) if loose else p.rms_over_step,
                }
            )
    return Table(
        rows=rows,
        columns=columns(
            """
            brake    brake
            law      law
            omega_n  ω_n (rad/s)
            coef     coefficients (run-to-run error)
            bic      BIC (sum)                        6
            rms      rms / (step/√12)                 3
            """
        ),
        caption="Every law fitted to every free decay, pooled per brake setting: coefficients (ζ; θ_f in rad; β in "
        "1/rad; α; n) with run-to-run standard errors, summed BIC, and the residual rms over the encoder's "
        "rounding noise.",
        name="tab-real-fits",
        notes=(
            "The power law's exponent is weakly determined by the decays: the last digits of its rows depend on the "
            "computer's floating-point rounding.",
        ),
        csv=False,
    )


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
        rows=rows,
        columns=[Column(key=c, header=c, digits=6) for c in cols],
        caption="Equivalent damping per brake setting.",
        name="tab-real-damping",
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
    return Table(
        rows=rows,
        columns=[Column(key=c, header=c, digits=6) for c in cols],
        caption="Driven-run groups.",
        name="tab-real-resonance",
    )


def claims_csv(st: RealOscillatorStudy) -> Table:
    """tab-real-claims.csv: claim_id, claim, verdict, detail."""
    rows = [
        {"claim_id": c.claim_id, "claim": c.claim, "verdict": c.verdict, "detail": ascii_detail(c.detail)}
        for c in claims(st)
    ]
    cols = ["claim_id", "claim", "verdict", "detail"]
    return Table(
        rows=rows,
        columns=[Column(key=c, header=c) for c in cols],
        caption="The paper's claims on the hardware.",
        name="tab-real-claims",
    )


def write_csv_tables(st: RealOscillatorStudy, folder=None) -> list:
    """Write the three machine-readable tables (when the runner sets the tables folder, or to ``folder``)."""
    return [t.write_csv(folder) for t in (damping_csv(st), resonance_csv(st), claims_csv(st))]
