"""The paper's three names for its dampings, judged on the axes of the trade-off at the run's values.

The discussion calls its low damping "comfort", its nominal one the "optimised compromise" and its
high one "absolute stability". :func:`label_verdicts` judges each name by the values of c of this
run (any order, any sign); :func:`labels_table` shows them and :func:`labels_sentence` says in one
paragraph what the judgement comes to, without repeating the table's rows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from vibration.book.chapters.stability.study import LABELS, StabilityStudy
from vibration.book.chapters.stability.tables import (
    WHY_NO_SETTLING_0,
    WHY_NO_STEADY,
    WHY_NO_VARIANCE,
    WHY_UNDAMPED_PEAK,
)
from vibration.book.chapters.stability.words import WN_CELL, c_text, join, sig
from vibration.book.presentation.tables import Table, columns


@dataclass(frozen=True, kw_only=True)
class LabelVerdict:
    """One of the paper's names, judged."""

    name: str  # "low", "nominal" or "high"
    label: str  # the paper's name for it
    c: float  # N s/m
    holds: bool  # does the name describe what this damping does, on these axes
    verdict: str  # short judgement (table cell)
    check: str  # where it lands, with the numbers (table cell)


def label_verdicts(st: StabilityStudy) -> list[LabelVerdict]:
    """One verdict per paper label, judged by the values of c (any order, any sign)."""
    d = st.design
    stable = [n for n, _c in st.positive()]
    not_stable = [n for n, _c in st.by_value() if n not in stable]
    r = f"{st.isolation_ratio:g} {WN_CELL}"
    out = []
    for n, c in st.dampings.items():
        x = d[n]
        others = [o for o in stable if o != n]
        if n not in stable:
            check = f"{x.stability}: no finite resonant peak, no settling, no stationary random response"
            holds = n == "low"
            verdict = {
                "low": f"“prone to instability” is literally true here: c = {sig(c, 3)} N s/m is {x.stability}",
                "nominal": "not a compromise: it is not stable",
                "high": f"contradicted: c = {sig(c, 3)} N s/m is {x.stability}",
            }[n]
        elif n == "low":
            best_iso = min(stable, key=lambda o: d[o].transmissibility)
            if others:
                nxt = min(others, key=lambda o: d[o].transmissibility)
                o = d[nxt]
                check = (
                    f"best isolation at {r} of the stable ones: {'yes' if best_iso == n else 'no'}; against the "
                    f"{nxt} damping (c = {sig(o.c, 3)} N s/m): T {sig(x.transmissibility / o.transmissibility, 3)} "
                    f"times, resonant peak {sig(x.peak_magnification / o.peak_magnification, 3)} times, settling "
                    f"{sig(x.settling_time / o.settling_time, 3)} times"
                )
            else:
                check = "the only stable damping of the three: nothing to compare its isolation with"
            holds = best_iso == n and bool(others)
            verdict = "supported only in the isolation sense, at a high price" if holds else "not supported"
        elif n == "high":
            lowest_peak = min(stable, key=lambda o: d[o].peak_magnification)
            fastest = min(stable, key=lambda o: d[o].settling_time)
            best_iso = min(stable, key=lambda o: d[o].transmissibility)
            check = (
                f"lowest resonant peak of the stable ones: {'yes' if n == lowest_peak else 'no'}; "
                f"fastest settling of the stable ones: {'yes' if n == fastest else 'no'}; "
                f"transmits {sig(x.transmissibility / d[best_iso].transmissibility, 3)} times the best isolator's T "
                f"at {r}"
            )
            if not not_stable:
                holds, verdict = False, "not a distinction: all three are asymptotically stable"
            elif len(stable) == 1:
                holds, verdict = True, "the only asymptotically stable one of the three"
            else:
                holds = True
                verdict = f"stable, unlike c = {join([sig(st.dampings[o], 3) for o in not_stable])} N s/m"
        else:
            ratio = sig(x.settling_time / st.star_step.settling_time, 3)
            if len(others) == 2:
                lo, hi = d[others[0]], d[others[1]]
                between = all(
                    min(getattr(lo, a), getattr(hi, a)) <= getattr(x, a) <= max(getattr(lo, a), getattr(hi, a))
                    for a in ("peak_magnification", "transmissibility")
                )
                check = (
                    f"between the other two on peak and isolation: {'yes' if between else 'no'}; settling "
                    f"{ratio} times the optimum at ζ* = {st.zeta_star:.3f}"
                )
                holds = between
                verdict = (
                    "a compromise, not an optimum: no stated weighting, and every ζ is Pareto-optimal on these axes"
                    if between
                    else "not a compromise on these axes"
                )
            else:
                check = (
                    f"fewer than two other stable dampings to lie between; settling {ratio} times the optimum "
                    f"at ζ* = {st.zeta_star:.3f}"
                )
                holds, verdict = False, "no compromise to judge: the others are not both stable"
        out.append(LabelVerdict(name=n, label=LABELS[n], c=c, holds=holds, verdict=verdict, check=check))
    return out


def labels_table(st: StabilityStudy) -> Table:
    """The paper's three labels checked against where each damping lands."""
    rows = []
    for v in label_verdicts(st):
        x = st.design[v.name]
        c = v.c
        rows.append(
            {
                "label": f"“{v.label}”",
                "c": sig(c, 3),
                "zeta": sig(x.zeta, 3),
                "peak": sig(x.peak_magnification, 4)
                if x.peak_magnification is not None
                else (WHY_UNDAMPED_PEAK if c == 0.0 else WHY_NO_STEADY),
                "iso": sig(x.transmissibility, 3) if x.transmissibility is not None else WHY_NO_STEADY,
                "ts": sig(x.settling_time, 3)
                if x.settling_time is not None
                else (WHY_NO_SETTLING_0 if c == 0.0 else WHY_NO_STEADY),
                "rms": sig(x.rms_per_sqrt_S0 * math.sqrt(st.S0), 3)
                if x.rms_per_sqrt_S0 is not None
                else WHY_NO_VARIANCE,
                "check": v.check,
                "verdict": v.verdict,
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            f"""
            label    paper's label
            c        c (N s/m)
            zeta     ζ
            peak     resonant peak
            iso      T at {st.isolation_ratio:g} ω_n
            ts       t_s, 2 % (s)
            rms      σ_x, white noise (m)
            check    where it lands
            verdict  verdict
            """
        ),
        caption="The paper's names for its three dampings, checked on the axes of the trade-off.",
        name="tab-stability-labels",
    )


def labels_sentence(st: StabilityStudy) -> str:
    """What the table's verdicts come to, in one paragraph (the rows themselves are not repeated)."""
    vs = label_verdicts(st)
    held = [f"“{v.label}”" for v in vs if v.holds]
    failed = [f"“{v.label}” ({c_text(v.c)})" for v in vs if not v.holds]
    if not failed:
        head = f"On this run's numbers all three names describe what their dampings do: {join(held)}."
    elif not held:
        head = f"On this run's numbers none of the three names survives as a distinction: {join(failed)}."
    else:
        head = (
            f"On this run's numbers {join(held)} {'holds' if len(held) == 1 else 'hold'} in a narrow sense, while "
            f"{join(failed)} {'does' if len(failed) == 1 else 'do'} not."
        )
    if st.distinct_positive():
        return (
            head + " No damping wins on every axis at once: the peak, the isolation and the settling time pull "
            "in different directions, so a name like these is a choice of weights, which the paper does not state."
        )
    return head + " With fewer than two stable dampings there is no trade-off between them to weigh."
