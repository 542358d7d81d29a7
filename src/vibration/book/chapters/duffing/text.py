"""Chapter 9's sentences: the key-results box, one sentence per result, and what a designer takes away.

Every number, comparison and verdict is computed from the :class:`DuffingStudy` of the run's parameters.
Digits of the chaotic runs depend on the machine's rounding (a chaotic trajectory amplifies the last bit):
the sentences write them like any other number, with the tolerances of :mod:`.notation` declared beside them.

Word conventions (the tests check them against the numbers): a spring is "hardening" or "softening" by the
sign of k₃; a jump "brackets" the fold when the fold lies in its refined bracket; the exponent is "positive"
or "negative" when it is beyond three standard errors from zero, otherwise "not distinguishable from zero";
runs "agree within their errors" when their χ² is at most its degrees of freedom plus three standard
deviations; the pooled exponent "agrees" with the published one within two standard errors.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.duffing.keyresults import KEY_RESULTS
from vibration.book.chapters.duffing.notation import (
    CHI2_FACTOR,
    DIFFERENCE_FACTOR,
    ERROR_FACTOR,
    LENGTH_FACTOR,
    Z_ATOL,
    apm,
    inverse,
    k3_text,
)
from vibration.book.chapters.duffing.study import DuffingStudy, SpringCase
from vibration.book.presentation.numbers import Approx, integer, sig, signed

#: The pooled exponent agrees with the published one within this many standard errors.
AGREE_Z = 2.0
#: The periodic case's running exponent "agrees" with its Floquet exponent within this relative difference.
FLOQUET_AGREE = 0.02


def _k3(case: SpringCase) -> str:
    return k3_text(case.duffing.k3)


def _rel(a: float, b: float) -> str:
    """``a`` relative to ``b`` in per cent, signed."""
    return f"{signed(100 * (a / b - 1), 2)} %"


# ------------------------------------------------------------------------------------- harmonic balance


def hb_sentence(study: DuffingStudy) -> str:
    """Where each spring moves the peak, against the linear spring's, and how close the backbone estimate is."""
    w_lin = study.hardening.linear_peak_omega
    parts = [f"the linear spring's resonance peak lies at {sig(w_lin, 4)} rad/s"]
    for case in study.cases:
        f = case.folds
        if not math.isfinite(f.peak_amplitude):
            parts.append(f"the {case.label} spring's curve does not close: the response has no peak")
            continue
        side = "above" if f.peak_omega > w_lin else "below"
        change = "lowers" if f.peak_amplitude < case.linear_peak else "raises"
        parts.append(
            f"the {case.label} spring ({_k3(case)}) moves the peak {side} the linear spring's, to "
            f"{sig(f.peak_omega, 4)} rad/s, and {change} it to {sig(f.peak_amplitude, 3)} m "
            f"({_rel(f.peak_amplitude, case.linear_peak)})"
        )
    errors = [abs(c.backbone_peak / c.folds.peak_amplitude - 1) for c in study.cases if math.isfinite(c.backbone_peak)]
    estimate = (
        f" The estimate $F_0/(c\\,\\omega)$ on the backbone is within {sig(100 * max(errors), 2)} % of the peak in "
        f"{'both cases' if len(errors) == 2 else 'the case with a peak'}."
        if errors
        else ""
    )
    text = "; ".join(parts)
    return text[:1].upper() + text[1:] + "." + estimate


def stability_sentence(study: DuffingStudy) -> str:
    """Whether the slow flow's and the Floquet multipliers' verdicts agree, and the pattern of the roots."""
    checks = [ch for c in study.cases for ch in c.checks]
    if not checks:
        return "Neither spring has a band of three amplitudes at these parameters, so there is no root to check."
    done = [ch for ch in checks if ch.agree is not None]
    agree = sum(ch.agree for ch in done)
    failed = len(checks) - len(done)
    head = (
        f"The slow flow and the Floquet multipliers agree on all {len(done)} amplitudes checked"
        if agree == len(done)
        else f"The slow flow and the Floquet multipliers agree on {agree} of the {len(done)} amplitudes checked"
    )
    if failed:
        head += f" (shooting did not converge from {failed} more)"
    triples = []
    for c in study.cases:
        for w in sorted({ch.omega for ch in c.checks}):
            roots = sorted((ch for ch in c.checks if ch.omega == w), key=lambda ch: ch.amplitude)
            triples.append([ch.stable for ch in roots])
    saddle = [r for r in triples if r == [True, False, True]]
    mus = [ch.max_multiplier for ch in done if ch.floquet_stable is False]
    pattern = (
        f": at each of the {len(triples)} frequencies the smallest and the largest amplitude are stable and the "
        "middle one is a saddle"
        + (f", whose orbit has a multiplier outside the unit circle (up to |μ| = {sig(max(mus), 3)})" if mus else "")
        if triples and len(saddle) == len(triples)
        else f"; {len(saddle)} of the {len(triples)} frequencies show the pattern stable, saddle, stable"
    )
    return head + pattern + "."


# ----------------------------------------------------------------------------------------------- folds


def fold_sentence(study: DuffingStudy) -> str:
    """Jumps against the folds of the periodic orbit, and how far one harmonic misplaces them."""
    rows = study.folds_compared
    judged = [r for r in rows if r.inside is not None]
    if not judged:
        return (
            "No sweep jumps next to a fold of the periodic orbit in this frequency range, so time integration has "
            "no fold to confirm here."
        )
    inside = sum(bool(r.inside) for r in judged)
    widest = max(r.bracket for r in judged)
    head = (
        f"Each of the {len(judged)} jumps brackets the fold of the periodic orbit: time integration and "
        f"continuation agree to the refined step, {sig(widest, 2)} rad/s"
        if inside == len(judged)
        else f"{inside} of the {len(judged)} jumps bracket the fold of the periodic orbit; the others miss it by up "
        f"to {sig(max(abs(r.jump_error) for r in judged if not r.inside), 2)} rad/s"
    )
    with_hb = [r for r in rows if math.isfinite(r.hb_error)]
    if not with_hb:
        return head + "."
    worst = max(with_hb, key=lambda r: abs(r.hb_error))
    case = next(c for c in study.cases if c.label == worst.case)
    low, high = case.orbit_folds
    share = abs(worst.hb_error) / (high - low)
    below = all(r.hb_error < 0 for r in with_hb)
    above = all(r.hb_error > 0 for r in with_hb)
    side = (
        " and every one-harmonic fold lies below the true one, so a sweep up runs past the one-harmonic fold before "
        "it jumps while a sweep down jumps before reaching it"
        if below
        else " and every one-harmonic fold lies above the true one"
        if above
        else ""
    )
    return (
        f"{head}. One harmonic misplaces the folds by up to {sig(abs(worst.hb_error), 2)} rad/s (the {worst.case} "
        f"spring's {'upper' if worst.direction == 'up' else 'lower'} fold, {sig(100 * share, 2)} % of its band's "
        f"width){side}."
    )


# ------------------------------------------------------------------------------------ the paper's scenario


def trust_sentence(study: DuffingStudy) -> str:
    """The amplitude where the paper's linear answer stops being trustworthy, against its own amplitude."""
    d = study.hardening.duffing
    a = study.trust_amplitude
    if not math.isfinite(a):
        return (
            "The backbone of this spring never leaves the half-power band, so the linear answer holds at any amplitude."
        )
    verdict = (
        "so the paper's resonant amplitude is already beyond it"
        if study.linear_amplitude > a
        else "so the paper's resonant amplitude stays below it"
    )
    return (
        f"With {_k3(study.hardening)} the backbone moves one half-power bandwidth ($c/m$ = {d.c / d.m:g} rad/s) "
        f"away from $\\omega_n$ = {sig(d.natural_frequency, 4)} rad/s at an amplitude of {sig(a, 3)} m. The linear "
        f"steady amplitude at ω = {study.params.omega_res:g} rad/s is {sig(study.linear_amplitude, 4)} m, {verdict}."
    )


def paper_sentence(study: DuffingStudy) -> str:
    """What the paper's resonance scenario becomes with the hardening spring."""
    p = study.params
    lin, duf = np.abs(study.paper_x_linear).max(), np.abs(study.paper_x_duffing).max()
    h = study.history[0]
    f = study.hardening.folds
    where = (
        f"Its steady amplitude there is {sig(h.hb_low, 4)} m whichever way the frequency is approached (sweep up "
        f"{sig(h.up, 4)} m, sweep down {sig(h.down, 4)} m)"
        if not h.depends_on_history
        else f"There the sweep up ends at {sig(h.up, 4)} m and the sweep down at {sig(h.down, 4)} m: the paper's "
        "frequency lies in the band where the amplitude depends on the motion's history"
    )
    band = ""
    if f.bistable and not h.depends_on_history:
        side = "above" if f.omega_low > p.omega_res else "below" if f.omega_high < p.omega_res else "around"
        band = (
            f": the resonance has moved {side} it, to the band {sig(f.omega_low, 4)} to {sig(f.omega_high, 4)} rad/s, "
            f"where two stable amplitudes coexist"
        )
    return (
        f"From rest under the paper's forcing F₀ sin ωt, the largest |x| in its {p.t_end:g} s window at "
        f"ω = {p.omega_res:g} rad/s is "
        f"{sig(lin, 4)} m with the linear spring and {sig(duf, 4)} m with {_k3(study.hardening)}. {where}{band}."
    )


# ------------------------------------------------------------------------------------------------ chaos


def chaos_verdict(study: DuffingStudy) -> str:
    """ "positive: the motion is chaotic", "negative: ..." or "not distinguishable from zero ..."."""
    return {
        1: "positive: the motion is chaotic",
        -1: "negative: the motion is not chaotic (it settles on a stable orbit)",
        0: "not distinguishable from zero at three standard errors",
    }[study.pooled.sign]


def lyapunov_sentence(study: DuffingStudy) -> str:
    """The largest exponent with its uncertainty, and what the two methods' agreement does and does not show."""
    p, main, partner, pooled = study.params, study.main_run, study.lyap_benettin, study.pooled
    starts = {(e.x0, e.v0) for e in study.lyap_runs}
    steps = sorted({e.period / e.steps_per_period for e in study.lyap_runs})
    lam_main = apm(main.exponent, main.standard_error, main.n_periods)
    lam_partner = apm(partner.exponent, partner.standard_error, partner.n_periods)
    lam_pooled = apm(pooled.mean, pooled.standard_error, _pooled_periods(study))
    chi2 = Approx(value=pooled.chi2, factor=CHI2_FACTOR).html(sig(pooled.chi2, 2))
    agree = (
        f"agree within their errors (χ² = {chi2} for {pooled.dof} degrees of freedom)"
        if pooled.consistent
        else f"scatter more than their errors allow (χ² = {chi2} for {pooled.dof} degrees of freedom)"
    )
    floq = ""
    if math.isfinite(study.floquet_periodic):
        close = abs(study.periodic_exponent - study.floquet_periodic) <= FLOQUET_AGREE * abs(study.floquet_periodic)
        floq = (
            f", as the Floquet multipliers of its orbit give ({sig(study.floquet_periodic, 3)} 1/s)"
            if close
            else f"; the Floquet multipliers of its orbit give {sig(study.floquet_periodic, 3)} 1/s, which the "
            f"running estimate has not reached after {integer(study.periodic_qr.running.size)} periods"
        )
    return (
        f"At F = {p.F0_ueda:g} N the main run of {integer(main.n_periods)} periods gives λ₁ "
        f"{lam_main} 1/s (standard error by batch means over {integer(main.block_means.size)} "
        f"blocks of {integer(main.block_periods)} periods). The {len(study.lyap_runs)} runs from {len(starts)} initial "
        f"states and step sizes h = {sig(steps[0], 2)} to {sig(steps[-1], 2)} s share no trajectory; they {agree} "
        f"and pool to λ₁ {lam_pooled} 1/s, {chaos_verdict(study)}. The two-trajectory "
        f"method gives {lam_partner} 1/s on the main run's trajectory: the two "
        "methods follow one trajectory, so their agreement checks the code, not the estimate. Likewise "
        "λ₁ + λ₂ = −c/m holds by construction of the QR method (the trace of the Jacobian), so it checks the "
        f"integration, not λ₁. At F = {p.F0_ueda_periodic:g} N the largest exponent is "
        f"{sig(study.periodic_exponent, 3)} 1/s{floq}."
    )


def _pooled_periods(study: DuffingStudy) -> int:
    """Forcing periods of all the runs the pooled exponent averages."""
    return sum(e.n_periods for e in study.lyap_runs)


def _round_count(n: float) -> str:
    """A length (periods, seconds) rounded to two figures and written whole, as a count: 4300, 27 000."""
    return integer(round(float(f"{n:.2g}")))


def _z(z: float) -> str:
    """A z-score (a difference in standard errors) of the chaotic runs, signed, with its tolerance."""
    return Approx(value=z, atol=Z_ATOL).html(signed(z, 2))


def _difference(value: float, text: str) -> str:
    """``text`` of a quantity computed from the pooled exponent's small difference from the published one."""
    return Approx(value=value, factor=DIFFERENCE_FACTOR).html(text)


def published_sentence(study: DuffingStudy) -> str:
    """The pooled exponent against the published one, with what can and cannot explain the difference."""
    pub, pooled, main = study.published, study.pooled, study.main_run
    lam_pooled = apm(pooled.mean, pooled.standard_error, _pooled_periods(study))
    p = study.params
    if not pub.applies:
        return (
            f"The published exponent ({pub.exponent:g} 1/s) is for c = {pub.c:g} N s/m and F = {pub.F0:g} N; with "
            f"c = {p.c_ueda:g} N s/m and F = {p.F0_ueda:g} N there is no published value to compare with."
        )
    head = (
        f"Sprott's table gives {pub.exponent:g} 1/s for this oscillator (per unit time, natural logarithm, as here; "
        f"per forcing period it would be 2π times larger, {sig(2 * math.pi * pub.exponent, 2)})."
    )
    if abs(pub.z) <= AGREE_Z:
        return head + (f" The pooled {lam_pooled} 1/s agrees with it within two standard errors ({_z(pub.z)}).")
    by_step = ", ".join(f"{integer(spp)} steps per period {_z(z)}" for spp, z in pub.step_z) or "no run"
    step_ok = all(abs(z) <= AGREE_Z for _, z in pub.step_z)
    # the averaging length needed grows as (σ₁/Δ)²: it takes the standard error's tolerance squared
    n_text = Approx(value=pub.n_needed, factor=LENGTH_FACTOR).html(_round_count(pub.n_needed))
    t_text = Approx(value=pub.n_needed * main.period, factor=LENGTH_FACTOR).html(
        _round_count(pub.n_needed * main.period)
    )
    z_text = Approx(value=abs(pub.z), factor=DIFFERENCE_FACTOR).html(sig(abs(pub.z), 2))
    delta, share = (
        _difference(pub.delta, signed(pub.delta, 2)),
        _difference(pub.delta, signed(100 * pub.delta / pub.exponent, 2)),
    )
    sigma1 = Approx(value=pub.sigma1, factor=ERROR_FACTOR).html(sig(pub.sigma1, 2))
    miss = _difference(abs(pub.delta), sig(abs(pub.delta), 2))
    return head + (
        f" The pooled {lam_pooled} 1/s is {z_text} standard errors "
        f"{'above' if pub.z > 0 else 'below'} it ({delta} 1/s, {share} %). "
        f"{'The step size does not explain this' if step_ok else 'The step size may contribute'}: runs with other "
        f"steps differ from the pooled value by {by_step} standard errors (the published run used h = {pub.step:g} "
        f"s, {integer(round(2 * math.pi / pub.step))} steps per period), and the definitions are the same (the "
        "published third exponent, 0, is that of time taken as a variable). The averaging length can: a single run of "
        "N periods "
        f"scatters about the long-run value with standard deviation {sigma1}/√N 1/s (from the main "
        f"run's batch means), so a run shorter than {n_text} periods ({t_text} s) misses it by "
        f"{miss} 1/s or more with a probability above 5 %. The published value states no "
        "averaging length; a finite-time average is the likeliest explanation."
    )


# ------------------------------------------------------------------------------- opening and closing


def key_results(study: DuffingStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    return "\n".join(["> **Key results**", ">"] + [f"> * {s}" for s in key_findings(study)])


def key_findings(study: DuffingStudy) -> list[str]:
    """Three or four computed sentences for the key-results box."""
    p, hard = study.params, study.hardening
    out = []
    low, high = hard.orbit_folds
    if math.isfinite(low):
        mid = next((h for h in study.history if h.where == "the middle of the band"), None)
        amps = f", about {sig(mid.hb_low, 2)} m and {sig(mid.hb_high, 2)} m mid-band," if mid else ""
        history = (
            "; which one the machine runs at depends on how it got there"
            if mid is not None and mid.depends_on_history
            else ""
        )
        out.append(
            f"**Two steady states.** With a hardening spring ({_k3(hard)}) two stable amplitudes{amps} coexist "
            f"between {sig(low, 4)} and {sig(high, 4)} rad/s (folds of the full equation){history}."
        )
    h = study.history[0]
    out.append(
        f"**The paper's linear answer.** At the paper's {p.omega_res:g} rad/s the linear model's steady amplitude is "
        f"{sig(h.linear, 3)} m; with the hardening spring the motion settles at {sig(h.rest, 3)} m "
        f"({_rel(h.rest, h.linear)})."
    )
    errs = [abs(r.hb_error) for r in study.folds_compared if math.isfinite(r.hb_error)]
    judged = [r.inside for r in study.folds_compared if r.inside is not None]
    if errs:
        sweeps = (
            "; stepped sweeps by time integration jump where continuation of the periodic orbit puts them"
            if judged and all(judged)
            else ""
        )
        out.append(
            f"**One harmonic is close, not exact.** Harmonic balance misses the true folds by at most "
            f"{sig(max(errs), 2)} rad/s{sweeps}."
        )
    pooled, key = study.pooled, KEY_RESULTS.values(study)  # the declared key results (keyresults.py)
    lam_key = apm(key["lyapunov"], key["lyapunov_se"], _pooled_periods(study))
    out.append(
        f"**Chaos.** Ueda's oscillator at F = {p.F0_ueda:g} N has λ₁ {lam_key} "
        f"1/s from {len(study.lyap_runs)} independent runs, {chaos_verdict(study)}"
        + (f"; nearby motions separate by a factor e every {inverse(1.0, pooled.mean)} s." if pooled.sign > 0 else ".")
    )
    return out


def summary(study: DuffingStudy) -> str:
    """What a designer takes away, in new words (no sentence of the body repeated), as Markdown bullets."""
    p = study.params
    lines = []
    a = study.trust_amplitude
    if math.isfinite(a):
        lines.append(
            f"* **Size the amplitude before trusting a linear model.** For this spring the linear resonance curve "
            f"is good for amplitudes up to about {sig(a, 2)} m; beyond that, the frequency of the peak itself moves "
            "and the design must use the nonlinear curve."
        )
    mid = next((h for h in study.history if h.where == "the middle of the band"), None)
    if mid is not None and mid.depends_on_history:
        big = "up" if mid.up > mid.down else "down"
        lines.append(
            f"* **Plan the run-up through the band.** Sweeping {big} through it keeps the hardening oscillator on the "
            f"large branch ({sig(max(mid.up, mid.down), 2)} m against {sig(min(mid.up, mid.down), 2)} m mid-band); "
            "sweeping the other way ends on the small one."
        )
    errs = [abs(r.hb_error) / max(r.orbit, 1e-300) for r in study.folds_compared if math.isfinite(r.hb_error)]
    if errs:
        lines.append(
            f"* **One harmonic is a design tool.** It locates the band edges within {sig(100 * max(errs), 2)} % of "
            "their frequency in closed form; check the edges that matter with the full equation."
        )
    if study.pooled.sign > 0:
        tenfold = inverse(math.log(10), study.pooled.mean)
        lines.append(
            f"* **Strong forcing can make the response unpredictable.** At F = {p.F0_ueda:g} N an error in the "
            f"initial state grows tenfold in {tenfold} s, so only "
            "statistics of the motion, not its course, can be predicted beyond that."
        )
    else:
        lines.append(
            f"* **At these forcings the motion stays predictable.** Ueda's oscillator at F = {p.F0_ueda:g} N has no "
            "positive exponent, so nearby motions do not separate."
        )
    return "\n".join(lines)
