r"""Sentences of the stability chapter: the key-results box, one paragraph per result, the designer's take-aways.

Each function reads a :class:`StabilityStudy` and states only what the study's numbers say at the
run's parameters (which damping is largest, stable, fastest, ...). Markdown: symbols with a subscript
are maths (``$\omega_n$``), numbers never use e-notation (:func:`~vibration.book.chapters.stability.words.num`).
"""

from __future__ import annotations

import math

from vibration.book.chapters.stability.study import MAX_GROWTH, PAPER_LOW_ZETA, StabilityStudy
from vibration.book.chapters.stability.words import F0, S0, SX, TS, WN, ZSTAR, c_text, join, num
from vibration.physics.exact import steady_state
from vibration.physics.stability import (
    damper_load,
    stability_class,
    transmissibility,
    white_noise_force_variance,
    white_noise_variance,
)

#: Largest |deviation| of the Monte Carlo variance, in standard errors, that counts as agreement.
AGREE_Z = 4.0


# ----------------------------------------------------------------------------- numbers the sentences share


def lightest_heaviest(st: StabilityStudy) -> tuple[tuple[str, float], tuple[str, float], bool]:
    """The compared pair of the isolation trade-off: the run's lightest and heaviest positive dampings
    (``(name, c)`` each, and True), or ζ = 0.2 and ζ = 1 when fewer than two differ (and False)."""
    pos = st.positive()
    if st.distinct_positive():
        return pos[0], pos[-1], True
    return ("ζ = 0.2", 0.2 * st.c_crit), ("ζ = 1", st.c_crit), False


def isolation_ratio_of(st: StabilityStudy) -> float:
    """How many times the heavier of the compared pair transmits the lighter's base motion at the isolation ratio."""
    (_nl, cl), (_nh, ch), _run = lightest_heaviest(st)
    w = st.isolation_ratio * st.omega_n
    return float(transmissibility(st.osc(ch), w)) / float(transmissibility(st.osc(cl), w))


def resonance_powers(st: StabilityStudy) -> dict[str, float]:
    """Mean power (W) each positive damping dissipates at omega_n under F0."""
    return {n: float(damper_load(st.osc(c), st.F0, st.omega_n).mean_power) for n, c in st.positive()}


def random_deviations(st: StabilityStudy) -> dict[str, float]:
    """|Monte Carlo - closed form| of the displacement variance, in standard errors, per positive damping."""
    return {
        n: abs(st.monte_carlo[n].variance - white_noise_variance(st.osc(c), st.S0)) / st.monte_carlo[n].standard_error
        for n, c in st.by_value()
        if n in st.monte_carlo
    }


def low_damping_claim(st: StabilityStudy, *, detailed: bool) -> str:
    """What the run says of the low damping the paper calls unstable: for the key results, or in detail."""
    low = st.osc(st.dampings["low"])
    s_low = stability_class(low)
    if not s_low.asymptotic:
        agree = "as the paper says of its own" if detailed else "here the paper's word fits"
        return f"The low damping of this run ({c_text(low.c)}) is {s_low.verdict}{',' if detailed else ':'} {agree}."
    tau, bound = num(low.time_constant, 3), num(st.design["low"].peak_magnification * st.F0 / st.k, 3)
    if detailed:
        return (
            f"The low damping ({c_text(low.c)}) that the paper calls unstable is asymptotically stable: its slowest "
            f"free mode decays as $e^{{-t/\\tau}}$ with τ = {tau} s, and its steady response is bounded by {bound} m "
            "at any forcing frequency."
        )
    return (
        f"The low damping ({c_text(low.c)}), which the paper calls unstable, is stable: its free motion dies out with "
        f"time constant {tau} s, and its steady response to a sinusoidal force of {num(st.F0, 3)} N never exceeds "
        f"{bound} m."
    )


# ----------------------------------------------------------------------------- key results


def key_results(st: StabilityStudy) -> str:
    """The key-results box: computed headline numbers as a Markdown block quote."""
    first = low_damping_claim(st, detailed=False)
    lin = st.growth["linear"]
    rate = st.growth_rate()
    second = (
        f"Growth without bound needs $c \\le 0$: at exact undamped resonance the amplitude gains "
        f"{num(st.F0 / (2 * st.m * st.omega_n), 3)} m every second"
        + (
            f", and the flutter model ({c_text(st.c_unstable)}) multiplies its motion by e every {num(1 / rate, 3)} s."
            if rate > 0.0
            else f" (reaching {num(lin.peak, 3)} m in {num(lin.t_end, 3)} s)."
        )
    )
    (_nl, cl), (_nh, ch), _run = lightest_heaviest(st)
    third = (
        f"Damping is a trade-off only where the load allows one: under base motion at {st.isolation_ratio:g} {WN} "
        f"the damper of {num(ch, 3)} N s/m passes {num(isolation_ratio_of(st), 3)} times the motion that "
        f"{num(cl, 3)} N s/m passes; under a force on the mass more damping always lowers the displacement."
    )
    fourth = (
        f"A step load settles (2 %) soonest at {ZSTAR} = {st.zeta_star:.3f}, in {num(st.star_step.settling_time, 3)} s "
        f"({c_text(st.c_star)})."
    )
    c_opt, v_opt = st.support_optimum
    fifth = (
        f"Under white-noise force the support force varies least at $c = \\sqrt{{km}}$ = {num(c_opt, 3)} N s/m, "
        f"a variance of {num(v_opt, 3)} N²."
    )
    return "\n".join(["> **Key results**", ">"] + [f"> * {s}" for s in (first, second, third, fourth, fifth)])


# ----------------------------------------------------------------------------- stability


def stability_sentence(st: StabilityStudy) -> str:
    """Which of the run's dampings are stable, the paper's claim about the low one, and the flutter model."""
    groups: dict[str, list[str]] = {}
    for _n, c in st.by_value():
        groups.setdefault(stability_class(st.osc(c)).verdict, []).append(c_text(c))
    if list(groups) == ["asymptotically stable"]:
        head = (
            f"All three of this run's dampings ({join(groups['asymptotically stable'])}) put both poles in the open "
            "left half-plane: each is asymptotically stable and bounded-input bounded-output stable."
        )
    else:
        parts = []
        for verdict, why in (
            ("asymptotically stable", "both poles in the open left half-plane"),
            (
                "marginally stable",
                f"poles on the imaginary axis: bounded free motion, but a force at {WN} grows the "
                "response without bound, so not bounded-input bounded-output stable",
            ),
            ("unstable", "a pole in the right half-plane: the free motion itself grows"),
        ):
            if verdict in groups:
                cs = groups[verdict]
                parts.append(f"{join(cs)} {'is' if len(cs) == 1 else 'are'} {verdict} ({why})")
        head = "Of this run's dampings, " + "; ".join(parts) + "."
    claim = low_damping_claim(st, detailed=True)
    s_u = stability_class(st.osc(st.c_unstable))
    if st.c_unstable < 0.0:
        tail = (
            f" The flutter model ({c_text(st.c_unstable)}) has its largest pole at $\\mathrm{{Re}}\\,s$ = "
            f"{num(s_u.spectral_abscissa, 3)} 1/s: its free motion grows like "
            f"$e^{{{num(s_u.spectral_abscissa, 3)}\\,t}}$ (t in s)."
        )
    else:
        tail = " The flutter model is set to $c$ = 0 here: it is the undamped case, marginally stable, with no growth."
    return (
        f"{head} {claim}{tail} With a positive stiffness $k$, instability needs $c \\le 0$ "
        "(with $k \\le 0$ the equilibrium is unstable whatever $c$)."
    )


# ----------------------------------------------------------------------------- growth


def growth_sentence(st: StabilityStudy) -> str:
    """How the three cases compare at the end of their windows."""
    b, lin, ex = (st.growth[c] for c in ("bounded", "linear", "exponential"))
    ob = b.osc
    amp = steady_state(ob, b.force).amplitude
    if st.bounded_name:
        source = f"the lightest positive damping of this run ({st.bounded_name}, {c_text(ob.c)})"
    else:
        source = (
            f"{c_text(ob.c)} (none of this run's dampings is positive with oscillating poles; this is the paper's "
            f"damping ratio ζ = {PAPER_LOW_ZETA:.4f})"
        )
    text = (
        f"Over {st.t_growth:g} s, {source} forced at {num(st.omega_res, 4)} rad/s reaches at most "
        f"{num(b.peak, 3)} m and its envelope closes in on the steady amplitude {num(amp, 3)} m (beating at "
        f"$|\\omega_d - \\omega|$ = {num(abs(ob.damped_natural_frequency - st.omega_res), 2)} rad/s while it does); "
        f"exact undamped resonance reaches {num(lin.peak, 3)} m, growing by $F_0/(2m\\omega_n)$ = "
        f"{num(st.F0 / (2 * st.m * st.omega_n), 3)} m each second for ever; "
    )
    c = ex.osc.c
    if c < 0.0:
        rate = stability_class(ex.osc).spectral_abscissa
        window = (
            f"over {num(ex.t_end, 3)} s (drawn until the growth factor reaches $e^{{{MAX_GROWTH:g}}}$)"
            if ex.capped
            else f"over {st.t_growth:g} s"
        )
        text += (
            f"negative damping {c_text(c)} reaches {num(ex.peak, 3)} m {window} and multiplies by e every "
            f"{num(1.0 / rate, 3)} s. Only the last two are instability."
        )
    else:
        text += (
            f"the flutter model is set to $c$ = 0, so its case is undamped forcing at {num(st.omega_res, 4)} rad/s, "
            f"which stays below {num(float(ex.env.max()), 3)} m: no exponential growth. Only exact undamped "
            "resonance grows without bound here."
        )
    return text


# ----------------------------------------------------------------------------- transmissibility


def transmissibility_sentence(st: StabilityStudy) -> str:
    """The isolation trade-off between the lightest and heaviest positive dampings of the run."""
    r = st.isolation_ratio
    (nl, cl), (nh, ch), run = lightest_heaviest(st)
    if run:
        light = f"the lightest positive damping of this run ({nl}, {c_text(cl)})"
        heavy = f"the heaviest ({nh}, {c_text(ch)})"
    else:
        light, heavy = f"ζ = 0.2 ({c_text(cl)})", f"ζ = 1 ({c_text(ch)})"
    lo, hi = st.osc(cl), st.osc(ch)
    t_lo_res, t_hi_res = float(transmissibility(lo, st.omega_n)), float(transmissibility(hi, st.omega_n))
    t_lo, t_hi = float(transmissibility(lo, r * st.omega_n)), float(transmissibility(hi, r * st.omega_n))
    text = (
        f"Under base motion the trade-off is real. At resonance {heavy} transmits {num(t_hi_res, 3)} of the base "
        f"motion against {num(t_lo_res, 3)} for {light}; at $\\omega$ = {r:g} {WN} it transmits {num(t_hi, 3)} "
        f"against {num(t_lo, 3)}, {num(t_hi / t_lo, 3)} times as much: damping that tames the resonance lets high "
        "frequencies through."
    )
    if not run:
        text += " Fewer than two of this run's dampings are positive, so the comparison uses ζ = 0.2 and ζ = 1."
    bad = [n for n, c in st.by_value() if c < 0.0]
    if bad:
        text += f" Negative damping ({join([c_text(st.dampings[n]) for n in bad])}) has no steady state to transmit."
    return text


# ----------------------------------------------------------------------------- step response


def step_sentence(st: StabilityStudy) -> str:
    """The settling-optimal damping and where the run's three land, by value."""
    text = (
        f"The 2 % settling time is shortest at {ZSTAR} = {st.zeta_star:.4f} ({c_text(st.c_star)} here), where "
        f"the overshoot equals the band: {TS} = {num(st.star_step.settling_time, 3)} s."
    )
    parts = []
    for n, c in st.by_value():
        if n in st.steps:
            s = st.steps[n]
            over = f"overshoots by {num(100 * s.overshoot, 3)} %" if s.overshoot > 0.0 else "does not overshoot"
            parts.append(
                f"{n} ({c_text(c)}) {over} and settles in {num(s.settling_time, 3)} s, "
                f"{num(s.settling_time / st.star_step.settling_time, 3)} times the optimum"
            )
        elif c == 0.0:
            parts.append(f"{n} ({c_text(c)}) overshoots by 100 % and never settles: it oscillates for ever")
        else:
            parts.append(f"{n} ({c_text(c)}) never settles: its step response grows without bound")
    text += " By damping: " + "; ".join(parts) + "."
    if st.steps:
        fastest = min(st.steps, key=lambda n: st.steps[n].settling_time)
        text += f" Of this run's dampings the {fastest} one settles first."
    else:
        text += " None of this run's dampings settles."
    return text


# ----------------------------------------------------------------------------- random load


def random_sentence(st: StabilityStudy) -> str:
    """What damping does to the random response, and whether the simulation agrees."""
    pos = [(n, c) for n, c in st.by_value() if n in st.monte_carlo]
    bad = [(n, c) for n, c in st.by_value() if n not in st.monte_carlo]
    text = (
        f"Under a white-noise force the stationary variance is $\\pi S_0/(kc)$: the rms displacement {SX} falls "
        "as $1/\\sqrt{c}$."
    )
    if pos:
        rms = [f"{num(math.sqrt(white_noise_variance(st.osc(c), st.S0)), 3)} m ({n}, {c_text(c)})" for n, c in pos]
        largest = pos[0][0]
        z = max(random_deviations(st).values())
        agree = "agrees with" if z < AGREE_Z else "does not agree with"
        text += (
            f" By damping: {join(rms)}; the largest is the {largest} damping's. For the displacement, more "
            "damping helps at every level of the load; for the force passed to the support it does not (below). "
            f"The simulation {agree} the closed form (largest deviation {num(z, 2)} standard errors)."
        )
    if bad:
        text += (
            f" With {join([c_text(c) for _n, c in bad])} there is no stationary response: the variance grows "
            "without bound, like $t$ for $c$ = 0 and exponentially for $c$ < 0."
        )
    return text


def force_tradeoff_text(st: StabilityStudy) -> str:
    """The force passed to the support under white noise: least at c = sqrt(km)."""
    c_opt, v_opt = st.support_optimum
    pos = st.positive()
    if not pos:
        return (
            f"The force passed to the support under random load is least at $c = \\sqrt{{km}}$ = {num(c_opt, 3)} "
            f"N s/m ({num(v_opt, 3)} N²); none of this run's dampings is positive."
        )
    vals = [f"{num(white_noise_force_variance(st.osc(c), st.S0), 3)} N² ({n}, {c_text(c)})" for n, c in pos]
    return (
        "The force passed to the support is a trade-off even under the paper's own load: its variance "
        f"$\\pi S_0(k/c + c/m)$ is least at $c = \\sqrt{{km}}$ = {num(c_opt, 3)} N s/m ({num(v_opt, 3)} N² at "
        f"{S0} = {st.S0:g} N² s/rad), against {join(vals)}."
    )


# ----------------------------------------------------------------------------- cost


def cost_sentence(st: StabilityStudy) -> str:
    """The damper's load at resonance."""
    pos = st.positive()
    text = ""
    if pos:
        p = resonance_powers(st)
        hardest = max(p, key=p.get)
        powers = [f"{num(p[n], 3)} W ({n}, {c_text(c)})" for n, c in pos]
        text = (
            f"At {WN} the damper force equals the applied force {F0} = {num(st.F0, 4)} N for every positive damping "
            f"(it is what balances the force there), and the mean power it must dissipate is $F_0^2/(2c)$: "
            f"{join(powers)}. The {hardest} damping, the lightest, works hardest at resonance; away from resonance "
            "the heavier damper carries the larger force."
        )
    zero = [n for n, c in st.by_value() if c == 0.0]
    neg = [n for n, c in st.by_value() if c < 0.0]
    if zero:
        text += (
            f" With $c$ = 0 ({join(zero)}) there is no damper: zero force and power, and at {WN} the amplitude grows "
            "without bound."
        )
    if neg:
        text += (
            f" With $c$ < 0 ({join([f'{n}, {c_text(st.dampings[n])}' for n in neg])}) there is no steady state: "
            "the negative damper feeds power in and the motion grows."
        )
    return text.strip()


# ----------------------------------------------------------------------------- take-aways


def takeaways_text(st: StabilityStudy) -> str:
    """What a designer takes away, as Markdown bullets: advice, with the run's numbers, not the body's sentences."""
    pos = st.positive()
    bad = [(n, c) for n, c in st.by_value() if c <= 0.0]
    if bad:
        first = (
            "Treat non-positive damping as the real danger: in this run "
            + join([f"the {n} damping ({c_text(c)})" for n, c in bad])
            + " cannot hold a steady motion, while any positive value, however small, can."
        )
    else:
        lightest = st.osc(pos[0][1])
        first = (
            f"Do not fear light damping for stability: even {c_text(lightest.c)} brings the free motion back to rest "
            f"(in about {num(4 * lightest.time_constant, 2)} s, four time constants); the danger is $c \\le 0$, "
            "self-excitation."
        )
    lines = [first]
    if pos:
        p = resonance_powers(st)
        lightest, heaviest = min(p, key=lambda n: st.dampings[n]), max(p, key=lambda n: st.dampings[n])
        size = (
            f"; size the damper for the power at resonance, where the lightest one here dissipates "
            f"{num(p[lightest] / p[heaviest], 3)} times what the heaviest does"
            if st.dampings[lightest] < st.dampings[heaviest]
            else "; size the damper for the power it must dissipate at resonance"
        )
        lines.append(
            "When the load is a force on the mass and the motion is what matters, add damping: there is no optimum "
            "short of the damper's own limits" + size + "."
        )
    c_opt, _v = st.support_optimum
    lines.append(
        "When the base moves, or the force reaching the support is what matters, choose the damping for the "
        f"frequency band: it helps below $\\sqrt{{2}}\\,\\omega_n$ = {num(math.sqrt(2) * st.omega_n, 3)} rad/s "
        f"and hurts above; for broadband (white-noise) load on the support aim at {num(c_opt, 3)} N s/m."
    )
    lines.append(
        f"When recovery after a shock matters, aim near ζ = {st.zeta_star:.2f} ({num(st.c_star, 3)} N s/m for this "
        "mass and spring)."
    )
    lines.append(
        "Names like “comfort” or “absolute stability” describe a weighting of these criteria; write the weights "
        "down, then the damping follows from them."
    )
    return "\n".join(f"* {line}" for line in lines)
