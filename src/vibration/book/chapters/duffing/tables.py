"""Chapter 9's tables, each a :class:`~vibration.book.presentation.tables.Table` built from a :class:`DuffingStudy`.

Every column keeps one number of significant figures (trailing zeros shown,
:func:`vibration.book.presentation.numbers.column`); the chaotic runs' digits depend on the machine's rounding (a
chaotic trajectory amplifies the last bit), so they are :class:`~vibration.book.presentation.numbers.Approx` cells
with the tolerances of :mod:`.notation`.
"""

from __future__ import annotations

import math

from vibration.book.chapters.duffing.notation import ERROR_FACTOR, Z_ATOL, exponent_approx, forcing_term, k3_text
from vibration.book.chapters.duffing.study import DuffingStudy, SpringCase
from vibration.book.presentation.numbers import Approx, bound, column, integer, minus
from vibration.book.presentation.tables import Missing, Table, columns, self_checks

NO_ORBIT = "shooting did not converge"


def _cell(value: float, digits: int, reason: str) -> str | Missing:
    return column(value, digits) if math.isfinite(value) else Missing(reason=reason)


def _exponent(value: float, n_periods: float) -> Approx:
    """A chaotic exponent from ``n_periods`` periods (its column prints 4 figures)."""
    return exponent_approx(value, n_periods)


def _error(value: float) -> Approx:
    """A standard error by batch means (its column prints 1 figure)."""
    return Approx(value=value, factor=ERROR_FACTOR)


def _k3(case: SpringCase) -> str:
    return k3_text(case.duffing.k3)


def _spring(case: SpringCase) -> str:
    return f"{case.label}, {_k3(case)}"


def hb_table(study: DuffingStudy) -> Table:
    """Folds, peak and its textbook estimate for each spring, and the linear spring's peak."""
    rows = []
    for case in study.cases:
        f = case.folds
        no, open_ = "single-valued response: no fold", "the curve does not close"
        rows.append(
            {
                "case": _spring(case),
                "wl": _cell(f.omega_low, 5, no),
                "wh": _cell(f.omega_high, 5, no),
                "wp": _cell(f.peak_omega, 5, open_),
                "ap": _cell(f.peak_amplitude, 4, open_),
                "abb": _cell(case.backbone_peak, 4, open_),
                "lin": _cell(case.linear_peak, 4, "overdamped: no resonance peak"),
            }
        )
    p = study.params
    return Table(
        rows=rows,
        columns=columns(
            """
            case  spring
            wl    ω_low (rad/s)
            wh    ω_high (rad/s)
            wp    ω_peak (rad/s)
            ap    A_peak (m)
            abb   F₀/(c ω_bb) (m)
            lin   linear peak (m)
            """
        ),
        caption=f"One-harmonic frequency response at m = {p.m:g} kg, k = {p.k:g} N/m, c = {p.c_nominal:g} N s/m, "
        f"F₀ = {p.F0:g} N: the folds ω_low and ω_high bounding the band of three amplitudes, the peak, its "
        "textbook estimate F₀/(c ω) on the backbone ω_bb, and the peak of the same oscillator with a linear spring.",
        name="tab-duffing-folds",
    )


def stability_table(study: DuffingStudy) -> Table:
    """Slow-flow stability of every root inside the band against the Floquet multipliers of the shooting orbit."""
    rows = []
    for case in study.cases:
        for ch in case.checks:
            rows.append(
                {
                    "case": case.label,
                    "w": column(ch.omega, 5),
                    "a": column(ch.amplitude, 4),
                    "st": "stable" if ch.stable else "unstable",
                    "ao": _cell(ch.orbit_amplitude, 4, NO_ORBIT),
                    "mu": _cell(ch.max_multiplier, 4, NO_ORBIT),
                    "stf": Missing(reason=NO_ORBIT)
                    if ch.floquet_stable is None
                    else ("stable" if ch.floquet_stable else "unstable"),  # fmt: skip
                    "agree": Missing(reason=NO_ORBIT) if ch.agree is None else ch.agree,
                }
            )
    if not rows:
        none = Missing(reason="no band of three amplitudes in either spring")
        rows = [{"case": "—", "w": none, "a": none, "st": none, "ao": none, "mu": none, "stf": none, "agree": none}]
    return Table(
        rows=rows,
        columns=columns(
            """
            case   spring
            w      ω (rad/s)
            a      A, one harmonic (m)
            st     slow flow
            ao     A, shooting (m)
            mu     max |μ|
            stf    Floquet
            agree  agree
            """
        ),
        caption="Stability of each one-harmonic amplitude at two frequencies inside the band: the slow flow's "
        "verdict against the Floquet multipliers μ of the periodic orbit of the full equation found from it by "
        "Newton shooting with an eighth-order Runge–Kutta integrator.",
        name="tab-duffing-stability",
    )


def fold_table(study: DuffingStudy) -> Table:
    """Folds of the periodic orbit, one-harmonic folds and the sweeps' refined jumps (rad/s)."""
    rows = []
    for r in study.folds_compared:
        case = next(c for c in study.cases if c.label == r.case)
        no_orbit = (
            "the continued branch did not reach both folds"
            if case.folds.bistable
            else "no fold of the periodic orbit (single-valued response)"
        )
        no_jump = "no jump off a branch in the sweep" if case.folds.bistable else "no fold, so no jump"
        rows.append(
            {
                "case": r.case,
                "dir": r.direction,
                "orbit": _cell(r.orbit, 6, no_orbit),
                "hb": _cell(r.hb, 6, "no fold"),
                "jump": _cell(r.jump, 6, no_jump),
                "bracket": _cell(r.bracket, 2, no_jump),
                "hb_err": _cell(r.hb_error, 2, no_orbit if case.folds.bistable else "no fold"),
                "jump_err": _cell(r.jump_error, 2, no_orbit if math.isfinite(r.jump) else no_jump),
            }
        )
    steps = study.params.n_sweep
    return Table(
        rows=rows,
        columns=columns(
            """
            case      spring
            dir       sweep
            orbit     fold, periodic orbit (rad/s)
            hb        fold, one harmonic (rad/s)
            jump      jump, time integration (rad/s)
            bracket   jump bracket (rad/s)
            hb_err    one harmonic − orbit (rad/s)
            jump_err  jump − orbit (rad/s)
            """
        ),
        caption="Where each sweep leaves its branch: the fold of the periodic orbit of the full equation "
        "(pseudo-arclength continuation by shooting; the branch turns where a Floquet multiplier passes +1), the "
        f"one-harmonic fold, and the sweep's jump ({integer(steps)} frequencies per sweep, the bracket refined by "
        "sweeping it again at 1/100 of the step).",
        name="tab-duffing-jumps",
    )


def history_table(study: DuffingStudy) -> Table:
    """Steady amplitude of the hardening spring at the paper's frequency (and mid-band) by where the motion
    comes from."""
    rows = [
        {
            "where": h.where,
            "omega": column(h.omega, 4),
            "linear": column(h.linear, 4),
            "hb_low": column(h.hb_low, 4),
            "hb_high": _cell(h.hb_high, 4, "one stable amplitude at this frequency"),
            "rest": column(h.rest, 4),
            "up": column(h.up, 4),
            "down": column(h.down, 4),
        }
        for h in study.history
    ]
    depends = [h.where for h in study.history if h.depends_on_history]
    fixed = [h.where for h in study.history if not h.depends_on_history]
    verdict = (
        f"the steady amplitude depends on where the motion comes from at {' and at '.join(depends)}"
        + (f", not at {' or at '.join(fixed)}" if fixed else "")
        if depends
        else "the steady amplitude is the same whichever way the motion comes"
    )
    return Table(
        rows=rows,
        columns=columns(
            """
            where    frequency
            omega    ω (rad/s)
            linear   linear (m)
            hb_low   lower stable A (m)
            hb_high  upper stable A (m)
            rest     from rest (m)
            up       sweep up (m)
            down     sweep down (m)
            """
        ),
        caption=f"Hardening spring, {_k3(study.hardening)}: steady amplitudes by one harmonic and "
        f"by time integration from rest and after sweeps from either side; {verdict}.",
        name="tab-duffing-history",
    )


def _start(x0: float, v0: float) -> str:
    return minus(f"x₀ = {x0:g} m, v₀ = {v0:g} m/s")


def lyapunov_table(study: DuffingStudy) -> Table:
    """Lyapunov exponents of the chaotic main run and of the periodic case, by both methods."""
    p = study.params
    rows = []
    for e in (study.main_run, study.lyap_benettin):
        rows.append(
            {
                "case": f"F = {p.F0_ueda:g} N",
                "method": "variational + QR" if e.method == "qr" else "two trajectories",
                "n": e.n_periods,
                "l1": _exponent(e.exponent, e.n_periods),
                "se": _error(e.standard_error),
                "l2": _exponent(e.second, e.n_periods)
                if e.method == "qr"
                else Missing(reason="the two-trajectory method gives λ₁ only"),
            }
        )
    for r in (study.periodic_qr, study.periodic_benettin):
        rows.append(
            {
                "case": f"F = {p.F0_ueda_periodic:g} N",
                "method": "variational + QR" if r.method == "qr" else "two trajectories",
                "n": r.running.size,
                "l1": column(r.exponents[0], 4),
                "se": Missing(reason="a periodic orbit: the estimate converges instead of scattering"),
                "l2": column(r.exponents[1], 4)
                if len(r.exponents) > 1
                else Missing(reason="the two-trajectory method gives λ₁ only"),  # fmt: skip
            }
        )
    main = study.main_run
    return Table(
        rows=rows,
        columns=columns(
            """
            case    forcing
            method  method
            n       periods
            l1      λ_1 (1/s)
            se      standard error (1/s)  1
            l2      λ_2 (1/s)
            """
        ),
        caption=f"Lyapunov exponents of Ueda's oscillator ẍ + {p.c_ueda:g} ẋ + x³ = {forcing_term(p)} from "
        f"{_start(*study_start(study))} (per unit time, natural logarithm); standard errors by batch means over "
        f"{integer(main.block_means.size)} blocks of {integer(main.block_periods)} periods.",
        name="tab-duffing-lyapunov",
    )


def study_start(study: DuffingStudy) -> tuple[float, float]:
    """Initial state of the main run, m and m/s."""
    return study.main_run.x0, study.main_run.v0


def lyapunov_runs_table(study: DuffingStudy) -> Table:
    """Runs that share no trajectory: other initial states and step sizes, each with its standard error."""
    pooled = study.pooled
    rows = [
        {
            "start": _start(e.x0, e.v0),
            "spp": e.steps_per_period,
            "h": column(e.period / e.steps_per_period, 3),
            "n": e.n_periods,
            "l1": _exponent(e.exponent, e.n_periods),
            "se": _error(e.standard_error),
            "z": Approx(value=(e.exponent - pooled.mean) / e.standard_error, atol=Z_ATOL),
        }
        for e in study.lyap_runs
    ]
    total = sum(e.n_periods for e in study.lyap_runs)
    rows.append({"start": "pooled (inverse-variance weights)", "spp": None, "h": None,
                 "n": total, "l1": _exponent(pooled.mean, total),
                 "se": _error(pooled.standard_error), "z": None})  # fmt: skip
    return Table(
        rows=rows,
        columns=columns(
            """
            start  initial state
            spp    RK4 steps per period
            h      step h (s)
            n      periods
            l1     λ_1 (1/s)
            se     standard error (1/s)    1
            z      (λ_1 − pooled) / error  2
            """
        ),
        caption=f"Largest exponent at F = {study.params.F0_ueda:g} N from runs that share no trajectory (other "
        "initial states, other RK4 steps; variational equations with QR), the first being the main run.",
        name="tab-duffing-lyapunov-runs",
    )


def lyapunov_convergence_table(study: DuffingStudy) -> Table:
    """Convergence of the main run: the estimate and its standard error against the averaging length."""
    rows = [
        {
            "n": r.n,
            "time": column(r.time, 3),
            "l1": _exponent(r.exponent, r.n),
            "se": _error(r.standard_error),
        }
        for r in study.convergence
    ]
    return Table(
        rows=rows,
        columns=columns(
            """
            n     periods N
            time  averaging time (s)
            l1    λ_1 (1/s)
            se    standard error (1/s)  1
            """
        ),
        caption="The main run's largest exponent from its first N periods; its standard error falls as 1/√N.",
        name="tab-duffing-lyapunov-convergence",
    )


def checks_table(study: DuffingStudy) -> Table:
    """Rounding-level self-checks, printed as bounds (the bound, not the value, reproduces on every machine)."""
    checks = (
        ("amplitude equation on the drawn curves, relative residual", bound(study.amp_residual, 1e-12)),
        ("Floquet: |μ₁ μ₂| against exp(−cT/m), relative error", bound(study.liouville, 1e-9)),
        ("QR exponents: |λ₁ + λ₂ + c/m| (RK4 step error), 1/s", bound(study.qr_sum_error, 1e-6)),
        ("continued folds: |μ − 1| of the multiplier closest to +1", bound(study.fold_multiplier_error, 1e-8)),
    )
    caption = "Self-checks: identities the computation must meet to rounding, with the bound each meets."
    return self_checks(checks, caption=caption, name="tab-duffing-checks")
