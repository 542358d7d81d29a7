"""Tables of the stability chapter, each a function of a :class:`StabilityStudy`.

Numbers are written by :func:`~vibration.book.chapters.stability.words.sig`: one number of significant
figures per column, trailing zeros kept, powers of ten as ``× 10ⁿ``. A quantity that does not exist
for a damping (no steady state for c < 0, no settling for c = 0, ...) is a
:class:`~vibration.book.presentation.tables.Missing` with its reason as a footnote.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.book.chapters.stability.study import BAND, LABELS, StabilityStudy, StepMetrics
from vibration.book.chapters.stability.words import WN_CELL, pole_text, sig
from vibration.book.presentation.tables import Missing, Table, bound, columns, self_checks
from vibration.physics.exact import steady_state
from vibration.physics.model import Oscillator
from vibration.physics.stability import (
    damper_load,
    peak_transmissibility,
    poles,
    stability_class,
    step_response,
    transmissibility,
    white_noise_force_variance,
    white_noise_variance,
    white_noise_velocity_variance,
)

#: Reasons shown in tables (as "—" with a footnote).
WHY_UNDAMPED_PEAK = Missing(reason=f"unbounded: with c = 0 a force at {WN_CELL} grows the response like t")
WHY_NO_STEADY = Missing(reason="no steady state: with c < 0 every free motion grows")
WHY_NO_SETTLING_0 = Missing(reason="never settles: with c = 0 the step response oscillates for ever")
WHY_NO_VARIANCE = Missing(reason="no stationary variance: with c ≤ 0 it grows without bound")
NO_PEAK = Missing(reason="no peak: the response rises monotonically")


def _s(value, digits: int):
    """A cell: the number at ``digits`` significant figures, or the Missing reason as it is."""
    return value if isinstance(value, Missing) else sig(value, digits)


#: The first columns of each table by damping: the case, as the paper names it, and its damping.
_BY_DAMPING = columns(
    """
    case  damping
    c     c (N s/m)
    """
)

# ----------------------------------------------------------------------------- poles


def case_label(key: str) -> str:
    """How a row of the pole table names its case."""
    if key == "undamped":
        return "undamped"
    if key == "unstable":
        return "flutter model"
    return f"{key} damping, “{LABELS[key]}”"


def poles_table(st: StabilityStudy) -> Table:
    """Poles and stability of the paper's dampings (sorted by value), c = 0 and the flutter model."""
    rows = []
    for key, c in st.pole_cases():
        osc = st.osc(c)
        s = stability_class(osc)
        rows.append(
            {
                "case": case_label(key),
                "c": sig(c, 3),
                "zeta": sig(osc.damping_ratio, 3),
                "poles": pole_text(poles(osc)),
                "abscissa": sig(s.spectral_abscissa, 3),
                "asym": s.asymptotic,
                "lyap": s.lyapunov,
                "bibo": s.bibo,
                "verdict": s.verdict,
            }
        )
    return Table(
        rows=rows,
        columns=columns(
            """
            case      case
            c         c (N s/m)
            zeta      ζ
            poles     poles s (1/s)
            abscissa  max Re s (1/s)
            asym      free motion decays
            lyap      free motion bounded
            bibo      bounded force, bounded x
            verdict   verdict
            """
        ),
        caption="Poles of m s² + c s + k and the three notions of stability.",
        name="tab-stability-poles",
    )


# ----------------------------------------------------------------------------- growth


def growth_table(st: StabilityStudy) -> Table:
    """Growth law, rate and the size reached at the end of the window, per case."""
    rows = []
    none = Missing(reason="not this growth law")
    for case, g in st.growth.items():
        osc, force = g.osc, g.force
        row = {
            "case": case if not (case == "exponential" and osc.c == 0.0) else "none (flutter model at c = 0)",
            "c": sig(osc.c, 3),
            "omega": sig(force.omega, 4),
            "t_end": sig(g.t_end, 4),
            "steady": none,
            "slope": none,
            "rate": none,
            "peak": sig(g.peak, 4),
            "env_end": sig(float(g.env[-1]), 4),
        }
        if case == "bounded":
            row["steady"] = sig(steady_state(osc, force).amplitude, 4)
        elif case == "linear":
            row["slope"] = sig(st.F0 / (2.0 * st.m * st.omega_n), 4)
        elif osc.c < 0.0:
            row["rate"] = sig(stability_class(osc).spectral_abscissa, 3)
        rows.append(row)
    return Table(
        rows=rows,
        columns=columns(
            """
            case     growth
            c        c (N s/m)
            omega    ω (rad/s)
            t_end    window (s)
            steady   steady amplitude (m)
            slope    F_0/(2mω_n) (m/s)
            rate     max Re s (1/s)
            peak     max |x| in window (m)
            env_end  envelope at window end (m)
            """
        ),
        caption=f"Three ways a response from rest grows over up to {st.t_growth:g} s (exact closed forms).",
        name="tab-stability-growth",
    )


# ----------------------------------------------------------------------------- transmissibility


def _family_rows(st: StabilityStudy) -> list[tuple[str, float]]:
    """(label, c) of the transmissibility table: the run's dampings, ζ = 0.2, ζ*, ζ = 1; by value."""
    out = [(f"{name}: c = {sig(c, 3)} N s/m", c) for name, c in st.by_value()]
    out += [("ζ = 0.2", 0.2 * st.c_crit), (f"ζ* = {st.zeta_star:.3f}", st.c_star), ("ζ = 1", st.c_crit)]
    return sorted(out, key=lambda p: p[1])


def transmissibility_table(st: StabilityStudy) -> Table:
    """Transmissibility at resonance, at sqrt(2) omega_n and at the isolation ratio; its peak (c <= 0 included)."""
    wn = st.omega_n
    rows = []
    for label, c in _family_rows(st):
        osc = st.osc(c)
        row = {"case": label, "zeta": sig(osc.damping_ratio, 3)}
        if c < 0.0:
            row.update({key: WHY_NO_STEADY for key in ("t_res", "t_iso", "t_r", "wp", "tp")})
        else:
            wp, tp = peak_transmissibility(osc)
            t_res = float(transmissibility(osc, wn))
            row.update(
                {
                    "t_res": sig(t_res, 4) if math.isfinite(t_res) else WHY_UNDAMPED_PEAK,
                    "t_iso": sig(float(transmissibility(osc, math.sqrt(2.0) * wn)), 4),
                    "t_r": sig(float(transmissibility(osc, st.isolation_ratio * wn)), 4),
                    "wp": sig(wp, 4),
                    "tp": sig(tp, 4) if math.isfinite(tp) else WHY_UNDAMPED_PEAK,
                }
            )
        rows.append(row)
    r = st.isolation_ratio
    return Table(
        rows=rows,
        columns=columns(
            f"""
            case   damping
            zeta   ζ
            t_res  T at ω_n
            t_iso  T at √2 ω_n
            t_r    T at {r:g} ω_n
            wp     ω_peak (rad/s)
            tp     T_max
            """
        ),
        caption="Base-excitation transmissibility |X/Y| (steady state) of the run's dampings and of the damping "
        "ratios 0.2, ζ* and 1, by damping.",
        name="tab-stability-transmissibility",
    )


# ----------------------------------------------------------------------------- step response


def _step_row(st: StabilityStudy, label: str, c: float, s: StepMetrics | None) -> dict:
    row = {"case": label, "c": sig(c, 4), "zeta": sig(st.osc(c).damping_ratio, 4)}
    if s is not None:
        row.update(
            {
                "os": sig(100.0 * s.overshoot, 4),
                "tp": sig(s.peak_time, 4) if math.isfinite(s.peak_time) else NO_PEAK,
                "tr": sig(s.rise_time, 4),
                "ts": sig(s.settling_time, 4),
                "wts": sig(st.omega_n * s.settling_time, 4),
            }
        )
    elif c == 0.0:  # y = 1 - cos(omega_n t): peak 2 at pi/omega_n, crossings of 0.1 and 0.9 in closed form
        wn = st.omega_n
        row.update(
            {
                "os": sig(100.0, 4),
                "tp": sig(math.pi / wn, 4),
                "tr": sig((math.acos(0.1) - math.acos(0.9)) / wn, 4),
                "ts": WHY_NO_SETTLING_0,
                "wts": WHY_NO_SETTLING_0,
            }
        )
    else:
        why = Missing(reason="grows without bound: c < 0")
        row.update({key: why for key in ("os", "tp", "tr", "ts", "wts")})
    return row


def step_table(st: StabilityStudy) -> Table:
    """Step metrics of the run's three dampings (by value) and of the settling-optimal one."""
    rows = [_step_row(st, f"{n} (“{LABELS[n]}”)", c, st.steps.get(n)) for n, c in st.by_value()]
    rows.append(_step_row(st, "settling-optimal ζ*", st.c_star, st.star_step))
    return Table(
        rows=rows,
        columns=_BY_DAMPING
        + columns(
            """
            zeta  ζ
            os    overshoot (%)
            tp    t_peak (s)
            tr    t_rise (s)
            ts    t_s, 2 % (s)
            wts   ω_n t_s
            """
        ),
        caption="Response to a step force, normalised by its final value F/k (exact; settling is the last exit "
        "from the 2 % band).",
        name="tab-stability-step",
    )


# ----------------------------------------------------------------------------- random load


def random_table(st: StabilityStudy) -> Table:
    """Stationary variance under white-noise force: closed form against Monte Carlo (c > 0), by damping."""
    rows = []
    keys = ("exact", "mc", "se", "z", "rms", "vexact", "vmc", "vz")
    for n, c in st.by_value():
        row = {"case": n, "c": sig(c, 3)}
        if n in st.monte_carlo:
            osc, mc = st.osc(c), st.monte_carlo[n]
            exact = white_noise_variance(osc, st.S0)
            exact_v = white_noise_velocity_variance(osc, st.S0)
            row.update(
                {
                    "exact": sig(exact, 4),
                    "mc": sig(mc.variance, 4),
                    "se": sig(mc.standard_error, 2),
                    "z": sig((mc.variance - exact) / mc.standard_error, 2),
                    "rms": sig(math.sqrt(exact), 3),
                    "vexact": sig(exact_v, 4),
                    "vmc": sig(mc.velocity_variance, 4),
                    "vz": sig((mc.velocity_variance - exact_v) / mc.velocity_standard_error, 2),
                }
            )
        else:
            row.update({key: WHY_NO_VARIANCE for key in keys})
        rows.append(row)
    return Table(
        rows=rows,
        columns=_BY_DAMPING
        + columns(
            """
            exact   πS_0/(kc) (m²)
            mc      Monte Carlo (m²)
            se      std. error (m²)
            z       deviation (std. errors)
            rms     σ_x (m)
            vexact  πS_0/(mc) (m²/s²)
            vmc     Monte Carlo (m²/s²)
            vz      deviation (std. errors)
            """
        ),
        caption=f"Displacement and velocity variance under a white-noise force, S_0 = {st.S0:g} N² s/rad "
        f"(two-sided); Monte Carlo with {st.n_paths} paths per damping, independent draws for each damping "
        f"(seeds {st.seed}, {st.seed} + 1, ... in the order of the table), so the deviations are independent.",
        name="tab-stability-random",
    )


def random_force_table(st: StabilityStudy) -> Table:
    """Variance of the force passed to the support under white noise, by damping, and its optimum."""
    c_opt, v_opt = st.support_optimum
    rows = []
    for n, c in st.by_value():
        if c > 0.0:
            v = white_noise_force_variance(st.osc(c), st.S0)
            rows.append({"case": n, "c": sig(c, 3), "var": sig(v, 3), "ratio": sig(v / v_opt, 3)})
        else:
            rows.append({"case": n, "c": sig(c, 3), "var": WHY_NO_VARIANCE, "ratio": WHY_NO_VARIANCE})
    rows.append({"case": "least force variance, c = √(km)", "c": sig(c_opt, 3), "var": sig(v_opt, 3),
                 "ratio": sig(1.0, 3)})  # fmt: skip
    return Table(
        rows=rows,
        columns=_BY_DAMPING
        + columns(
            """
            var    var F_T (N²)
            ratio  over the least
            """
        ),
        caption=(
            f"Force passed to the support, F_T = k x + c v, under a white-noise force of S_0 = {st.S0:g} N² s/rad: "
            "its stationary variance πS_0(k/c + c/m) (x and v are uncorrelated in the stationary state), and the "
            "least over all dampings, 2πS_0√(k/m) at c = √(km)."
        ),
        name="tab-stability-random-force",
    )


# ----------------------------------------------------------------------------- cost


def cost_table(st: StabilityStudy) -> Table:
    """Damper force amplitude and mean power at the paper's forcing frequency and at omega_n, by damping."""
    rows = []
    for n, c in st.by_value():
        osc = st.osc(c)
        for label, w in ((f"{st.omega_res:g} rad/s (paper)", st.omega_res), (WN_CELL, st.omega_n)):
            row = {"case": n, "c": sig(c, 3), "w": label}
            if c < 0.0:
                row.update({"x": WHY_NO_STEADY, "f": WHY_NO_STEADY, "p": WHY_NO_STEADY})
            elif c == 0.0 and w == st.omega_n:  # undamped resonance: no damper, no steady amplitude
                row.update({"x": WHY_UNDAMPED_PEAK, "f": sig(0.0, 4), "p": sig(0.0, 4)})
            else:
                d = damper_load(osc, st.F0, w)
                x = float(d.amplitude)
                row.update(
                    {
                        "x": sig(x, 4) if math.isfinite(x) else WHY_UNDAMPED_PEAK,
                        "f": sig(float(d.force_amplitude), 4),
                        "p": sig(float(d.mean_power), 4),
                    }
                )
            rows.append(row)
    return Table(
        rows=rows,
        columns=_BY_DAMPING
        + columns(
            """
            w     ω
            x     |X| (m)
            f     damper force (N)
            p     mean power (W)
            """
        ),
        caption=f"Cost of damping under F_0 = {st.F0:g} N on the mass, in the steady state.",
        name="tab-stability-cost",
    )


# ----------------------------------------------------------------------------- self-checks


def checks_table(st: StabilityStudy) -> Table:
    """Rounding-level self-checks, printed as bounds."""
    zetas = np.geomspace(1e-4, 1e2, 200)
    cross = max(
        abs(float(transmissibility(Oscillator(m=st.m, c=z * st.c_crit, k=st.k), math.sqrt(2) * st.omega_n)) - 1.0)
        for z in zetas
    )
    roots = 0.0
    for _k, c in st.pole_cases():
        p, ref = poles(st.osc(c)), np.roots([st.m, c, st.k])
        scale = max(st.omega_n, abs(c) / st.m)
        roots = max(roots, float(np.max(np.abs(np.sort_complex(p) - np.sort_complex(ref)))) / scale)
    env = 0.0
    for g in st.growth.values():
        env = max(env, float(np.max((np.abs(g.x) - g.env) / np.maximum(g.env, 1e-300))))
    band = 0.0
    for n, s in st.steps.items():
        band = max(band, abs(abs(float(step_response(st.osc(st.dampings[n]), s.settling_time)) - 1.0) - BAND))
    band = max(band, abs(abs(float(step_response(st.osc(st.c_star), st.star_step.settling_time)) - 1.0) - BAND))
    checks = (
        (f"|T(√2 {WN_CELL}) − 1| over 200 ζ from 10⁻⁴ to 100", bound(cross, 1e-13)),
        (f"poles against a polynomial root finder, relative to max({WN_CELL}, |c|/m)", bound(roots, 1e-12)),
        ("|x| above its closed-form envelope, relative", bound(max(env, 0.0), 1e-9)),
        ("| |y(tₛ) − 1| − 0.02 | at the settling times", bound(band, 1e-12)),
    )
    caption = "Self-checks at rounding level (printed as bounds)."
    return self_checks(checks, caption=caption, name="tab-stability-checks", headers=("self-check", "value"))
