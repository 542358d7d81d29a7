"""Chapter 4's sentences: key results, what the tables show, and what a designer takes away.

Every number is read from the :class:`FrequencyStudy`; every comparison word (inside or outside the
half-power band, which term sets the amplitude, whether estimates agree) is decided from those numbers.
Symbols are typeset as Markdown maths ($\\omega_\\mathrm{res}$), numbers in powers of ten as × 10ⁿ.

Examples
--------
>>> from vibration.book.chapters.frequency_response.study import frequency_response_study
>>> st = frequency_response_study(n_points=2001, n_omega=20, n_damping=10)
>>> print(band_text(st).splitlines()[2][:60])
- **high damping** (c = 15 N s/m): overdamped (ζ = 1.68 > 1:
"""

from __future__ import annotations

import math

from vibration.book.chapters.frequency_response.keyresults import KEY_RESULTS
from vibration.book.chapters.frequency_response.study import TOL_ESTIMATE, FrequencyStudy
from vibration.book.presentation.narrative import regime_clause
from vibration.book.presentation.numbers import sig as num

#: Residual of the energy balance (relative to the largest work) above which a simulation is unfit for audits.
AUDIT = 1e-4

W_RES = r"$\omega_\mathrm{res}$"
W_REF = r"$\omega_\mathrm{ref}$"
W_N = r"$\omega_n$"


def listing(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``.

    >>> listing(["low damping", "nominal damping"])
    'low damping and nominal damping'
    """
    items = list(items)
    if not items:
        return ""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _names(cases) -> str:
    return listing([f"**{c.name}**" for c in cases])


# -- key results -------------------------------------------------------------------------------


def _band_sentence(study: FrequencyStudy) -> str:
    """Where ω_res lies, per damping: inside, outside, or no band."""
    w = f"The paper's resonant forcing {W_RES} = {num(study.params.omega_res)} rad/s"
    inside = [c for c in study.cases if c.inside is True]
    outside = [c for c in study.cases if c.inside is False]
    none = [c for c in study.cases if c.inside is None]
    parts = []
    if inside:
        parts.append(f"lies inside the half-power band of the {_names(inside)} case{'s' if len(inside) > 1 else ''}")
    if outside:
        parts.append(f"lies outside the half-power band of the {_names(outside)} case{'s' if len(outside) > 1 else ''}")
    text = f"{w} " + "; it ".join(parts) if parts else w
    if none:
        have = "have" if len(none) > 1 else "has"
        text += (
            f"{';' if parts else ':'} the {_names(none)} case{'s' if len(none) > 1 else ''} {have} no half-power band"
        )
    return text + "."


def key_results(study: FrequencyStudy) -> str:
    """The key-results box: the chapter's headline numbers as a Markdown block quote."""
    p = study.params
    ratio = p.omega_res / study.omega_n
    declared = KEY_RESULTS["M_res"].value(study)  # the nominal case's, as declared in keyresults.py
    amps = [
        f"{num(declared if c.case == 'c_nominal' else c.M_res, 3)} times with the {c.name.split()[0]}"
        for c in study.cases
        if c.steady
    ]
    if amps:
        amps[0] = amps[0].replace(" times with", " times the static deflection $F_0/k$ with")
    no_steady = [c.name for c in study.cases if not c.steady]
    bullets = [
        f"At {W_RES} = {num(p.omega_res)} rad/s, {num(ratio, 4)} times the natural frequency, the steady amplitude "
        f"is {listing(amps)} damping" + (f"; the {listing(no_steady)} has no steady state" if no_steady else "") + ".",
        _band_sentence(study),
    ]
    est = [c for c in study.checks if c.check.startswith("ζ from")]
    if est and all(c.ok for c in est):
        bullets.append(
            f"The damping ratio measured from the half-power points and from a free decay matches $c/(2\\sqrt{{km}})$ "
            f"to better than {num(TOL_ESTIMATE)}."
        )
    bullets.append(
        f"The paper's RK45 output leaves {num(100 * study.energy_residual(1), 2)} % of the work unaccounted for in "
        "the energy balance; the exact response closes it to quadrature level."
    )
    w, c, peak = study.design.largest
    bullets.append(
        f"Over the design map the window's largest displacement is {num(peak)} m (ω = {num(w)} rad/s, "
        f"c = {num(c, 3)} N s/m); at the lightest damping it stays above half of that only within a band "
        f"{num(study.design.danger_width, 3)} rad/s wide."
    )
    return "\n".join(["> **Key results**", ">", *(f"> * {b}" for b in bullets)])


# -- the body ----------------------------------------------------------------------------------


def band_text(study: FrequencyStudy) -> str:
    """Per damping: regime, half-power band, and whether ω_res is inside or outside it."""
    lines = []
    w = f"{W_RES} = {num(study.params.omega_res)} rad/s"
    for c in study.cases:
        head = f"**{c.name}** (c = {num(c.c)} N s/m): {regime_clause(c.osc)}"
        if c.c < 0:
            tail = "no steady state and no half-power band: the response at any frequency grows."
        elif c.c == 0:
            tail = f"the peak is infinite at {W_N} = {num(study.omega_n)} rad/s, so there is no half-power band."
        elif c.hi is None:
            tail = (
                f"no resonant peak and so no half-power band; at {w} the steady amplitude is "
                f"{num(c.M_res, 3)} times the static deflection."
            )
        else:
            where = "inside" if c.inside else "outside"
            band = f"from {num(c.lo)} to {num(c.hi)} rad/s" if c.lo is not None else f"up to {num(c.hi)} rad/s"
            tail = (
                f"half-power band {band}; {w} is **{where} the half-power band**, where the steady amplitude is "
                f"{num(c.M_res, 3)} times the static deflection (peak {num(c.M_peak, 3)} at {num(c.omega_peak)} rad/s)."
            )
        lines.append(f"- {head}; {tail}")
    return "\n".join(lines)


def _what_sets(ctl) -> str:
    r, M = ctl.r, ctl.M
    if ctl.setter == "stiffness":
        return (
            f"$\\omega/\\omega_n$ = {num(r, 3)}: M = {num(M, 4)}, within {num(100 * (1 - M / ctl.undamped), 2)} % "
            f"of the undamped $1/|1 - r^2|$ = {num(ctl.undamped, 4)}, so stiffness and mass set the amplitude and "
            "damping hardly matters"
        )
    if ctl.setter == "damping":
        return (
            f"$\\omega/\\omega_n$ = {num(r, 4)}: M = {num(M, 4)}, within {num(100 * (1 - M / ctl.damping_only), 2)} % "
            f"of $1/(2\\zeta r)$ = {num(ctl.damping_only, 4)}, so damping sets the amplitude, "
            r"$X \approx F_0/(c\omega)$"
        )
    return (
        f"$\\omega/\\omega_n$ = {num(r, 3)}: M = {num(M, 4)}, against {num(ctl.undamped, 4)} undamped and "
        f"{num(ctl.damping_only, 4)} from damping alone, so stiffness, mass and damping all matter"
    )


def control_text(study: FrequencyStudy) -> str:
    """What sets the steady amplitude at ω_ref and ω_res, for the nominal damping."""
    nom = study.nominal
    if not study.controls:
        return (
            f"With the nominal damping c = {num(nom.c)} N s/m there is no finite steady amplitude to attribute; "
            "the other dampings are in the tables above."
        )
    ref, res = study.controls
    return (
        f"For the nominal damping (c = {num(nom.c)} N s/m): at {W_REF} = {num(ref.omega)} rad/s, "
        f"{_what_sets(ref)}; at {W_RES} = {num(res.omega)} rad/s, {_what_sets(res)}."
    )


def estimates_text(study: FrequencyStudy) -> str:
    """Whether the three damping-ratio estimates agree (from the checks), and which do not exist."""
    est = [c for c in study.checks if c.check.startswith("ζ from")]
    worst = max((c.value for c in est), default=None)
    if worst is None:
        text = "No damping here has a peak and a decay to estimate from."
    elif worst < TOL_ESTIMATE:
        text = f"Where they exist, the three estimates agree to better than {num(TOL_ESTIMATE)} in relative terms."
    else:
        text = f"The estimates differ by up to {num(worst, 2)} in relative terms."
    missing = [c for c in study.cases if c.zeta_hp is None or c.zeta_ld is None]
    if missing:
        text += (
            f" The {_names(missing)} case{'s lack' if len(missing) > 1 else ' lacks'} a peak or a clean decay for "
            "some estimates (footnotes)."
        )
    return text


def decomposition_text(study: FrequencyStudy) -> str:
    """How the transient starts and ends, from the decomposition."""
    d = study.decomposition
    t_end = study.params.t_end
    if math.isfinite(d.t_s):
        settle = (
            f"falls below 2 % of X after {num(d.t_s, 3)} s, inside the window"
            if d.t_s <= t_end
            else f"needs {num(d.t_s, 3)} s to fall below 2 % of X, longer than the {num(t_end)} s window"
        )
    else:
        settle = "never decays, because the damping is not positive"
    return (
        f"At t = 0 the transient cancels the steady state, $x_h(0)$ = {num(d.x_h0)} m against X = {num(d.X)} m "
        f"at a phase lag of {num(d.phase, 3)} rad, so the motion starts from rest; the transient then {settle}, "
        f"and {num(abs(d.x_h_end), 3)} m of it is left at the end of the window."
    )


def energy_text(study: FrequencyStudy) -> str:
    """What the energy audit shows: the exact response balances, the paper's RK45 output leaks."""
    eb = study.energy[0][1]
    share = float(eb.dissipated[-1] / eb.work[-1]) if eb.work[-1] != 0 else math.nan
    return (
        f"By the end of the window the damper has dissipated {num(100 * share, 3)} % of the work the force did; the "
        f"rest is the stored energy of the motion. On the paper's RK45 output the three terms no longer balance: the "
        f"residual reaches {num(100 * study.energy_residual(1), 2)} % of the largest work, the integrator's energy "
        "error made visible."
    )


def design_text(study: FrequencyStudy) -> str:
    """How narrow the dangerous band is at the lowest damping of the grid, and how flat the highest is."""
    dm = study.design
    w, c, peak = dm.largest
    lo, hi = dm.danger_band
    return (
        f"The largest peak on the grid is {num(peak)} m, at ω = {num(w)} rad/s and c = {num(c, 3)} N s/m. At the "
        f"lowest damping of the grid (c = {num(dm.dampings[0], 3)} N s/m) the peak exceeds half its largest value "
        + (f"only for ω from {num(lo)} to {num(hi)} rad/s" if hi > lo else f"only at ω = {num(lo)} rad/s")
        + f" ({num(100 * dm.danger_width / study.omega_n, 2)} % of {W_N} wide, counting whole grid steps); at the "
        f"highest (c = {num(dm.dampings[-1], 3)} N s/m) the peaks over ω stay within a factor {num(dm.flatness, 3)} "
        "of each other."
    )


def takeaways(study: FrequencyStudy) -> str:
    """What a designer takes away, in new words: conclusions drawn from the numbers, not repeated from above."""
    nom = study.nominal
    bullets = []
    if study.controls:
        ref, res = study.controls
        if res.setter == "damping":
            bullets.append(
                f"At resonance only damping limits the amplitude: doubling the nominal c would bring the steady "
                f"amplitude at {W_RES} down to {num(100 * res.doubled, 3)} % of its value, a cure that costs a damper, "
                "not a redesign."
            )
        elif res.setter == "stiffness":
            bullets.append(
                f"At {W_RES} the forcing is far enough from {W_N} that doubling the damping leaves "
                f"{num(100 * res.doubled, 3)} % of the steady amplitude: retune k or m instead."
            )
        else:
            bullets.append(
                f"At {W_RES} both levers work: doubling the damping leaves {num(100 * res.doubled, 3)} % of the steady "
                f"amplitude, and moving {W_N} further from the forcing with k or m lowers it too."
            )
        if ref.setter == "stiffness":
            bullets.append(
                f"Away from resonance damping buys little: at {W_REF} twice the damping leaves "
                f"{num(100 * ref.doubled, 3)} % of the amplitude; move {W_N} with k or m to change it."
            )
        else:
            bullets.append(
                f"Even at {W_REF} the damping matters: twice the damping leaves {num(100 * ref.doubled, 3)} % of the "
                "amplitude."
            )
    if nom.hi is not None and nom.lo is not None:
        bullets.append(
            f"Keep operating frequencies out of the half-power band: at the nominal damping it spans "
            f"{num(nom.hi - nom.lo, 3)} rad/s, {num(100 * (nom.hi - nom.lo) / study.omega_n, 2)} % of {W_N}, and it "
            "narrows in proportion as the damping falls."
        )
    bullets.append(
        "Audit energy on the closed form or at tight tolerances, never on a simulation at the integrator's default "
        "tolerances: its integration error shows up as energy that comes from nowhere."
        if study.energy_residual(1) >= AUDIT
        else "Even a simulation at the integrator's default tolerances is good enough for an energy audit here."
    )
    return "\n".join("- " + b for b in bullets)
