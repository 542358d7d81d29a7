"""The audit's evaluators: one function per quantity, giving the paper's method's value, the exact value and why."""

from __future__ import annotations

import math

import numpy as np

from .resonance import half_power_band
from .rk45 import rk45_pair, scipy_rk45_nodes
from .runs import ALSO_USES, _g, _growing, _no_steady_text, _Run, _stability

__all__: list[str] = []


def _context(run: _Run):
    """What most evaluators read off a run: oscillator, force, window, ω_n, ζ, steady state, and the
    sentence for a run without a steady state."""
    osc, force, t_end = run.sc.oscillator, run.sc.force, run.sc.t_end
    no_steady = _no_steady_text(osc)
    return osc, force, t_end, osc.natural_frequency, osc.damping_ratio, run.ss, no_steady


def _eval_rk45_pair(q: str, run: _Run | None, runs: dict[str, _Run]):
    name = rk45_pair()
    nodes = ", ".join(str(c) for c in scipy_rk45_nodes())
    return (
        "",
        name,
        (
            f"The paper's RK45 has nodes c = ({nodes}), the Dormand-Prince pair "
            "(Fehlberg's are 0, 1/4, 3/8, 12/13, 1, 1/2), and advances with its 5th-order solution."
        ),
    )


def _eval_natural_frequency(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    return "", wn, f"ω_n = √(k/m) = √({_g(osc.k)}/{_g(osc.m)}) = {wn:.4f} rad/s."


def _eval_frequency_ratio(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    r = force.omega / wn
    lo, hi = half_power_band(osc)
    if hi is None:
        band = f"there is no half-power band at ζ = {_g(zeta, 3)}"
    else:
        inside = (lo is None or lo <= force.omega) and force.omega <= hi
        band = (
            f"{'inside' if inside else 'outside'} the half-power band "
            f"({_g(lo) if lo is not None else '0'} to {_g(hi)} rad/s at ζ = {_g(zeta, 3)})"
        )
    return "", r, f"ω/ω_n = {_g(force.omega)}/{wn:.4f} = {r:.5f}, a detuning of {abs(1 - r) * 100:.3g} %; {band}."


def _eval_regime(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    return "", osc.regime, f"ζ = c/(2√(km)) = {_g(osc.c)}/{osc.critical_damping:.4f} = {zeta:.4f}."


def _steady_amplitude(run: _Run, sym: str, exact: float, why: str):
    """The late peak of ``x`` or ``v`` by RK45, and the steady amplitude with why (none without a steady state)."""
    late = run.late(getattr(run.paper, sym))
    return (late, exact, why) if run.has_steady else (late, None, _no_steady_text(run.sc.oscillator))


def _eval_steady_amplitude_x(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    why = (
        f"x_ss = F0/√((k − mω²)² + (cω)²) = {_g(ss.amplitude)} m, {_g(ss.magnification, 3)} times the "
        f"static deflection F0/k = {_g(ss.static_deflection)} m."
    )
    return _steady_amplitude(run, "x", ss.amplitude, why)


def _eval_steady_amplitude_v(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    why = f"v_ss = ω x_ss = {_g(force.omega)} × {_g(ss.amplitude)} m = {_g(ss.velocity_amplitude)} m/s."
    return _steady_amplitude(run, "v", ss.velocity_amplitude, why)


def _window_peaks(run: _Run, sym: str, unit: str, tail: str):
    """Peak of |x| (``sym`` "x", m) or |v| ("v", m/s) over the window by RK45 and exactly, and the sentence."""
    pk_p = float(np.max(np.abs(getattr(run.paper, sym))))
    pk_e = float(np.max(np.abs(getattr(run.exact, sym))))
    return (
        pk_p,
        pk_e,
        f"Over [0, {_g(run.sc.t_end)}] s the peak |{sym}| is {_g(pk_e)} {unit} exactly ({_g(pk_p)} {unit} by RK45)"
        + tail,
    )


def _eval_peak_x(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    tail = (
        f"the steady amplitude is {_g(ss.amplitude)} m (magnification {_g(ss.magnification, 3)}, ζ = {_g(zeta, 3)})."
        if run.has_steady
        else no_steady
    )
    return _window_peaks(run, "x", "m", "; " + tail)


def _eval_peak_v(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    bound = f"; near resonance it is bounded by F0/c = {_g(force.F0 / osc.c)} m/s" if osc.c > 0 else ""
    return _window_peaks(run, "v", "m/s", bound + ".")


def _eval_amplitude_ratio(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    other = runs[ALSO_USES[q][0]]
    if not (run.has_steady and other.has_steady) or other.ss.amplitude == 0:
        unsteady = run if not run.has_steady else other  # name the run without a steady state
        return "", None, _no_steady_text(unsteady.sc.oscillator)
    r_e = ss.amplitude / other.ss.amplitude
    r_p = run.late(run.paper.x) / other.late(other.paper.x)
    if q == "amplitude_ratio_resonance_reference":
        text = (
            f"The steady amplitudes are {_g(ss.amplitude)} m and {_g(other.ss.amplitude)} m, "
            f"a ratio of {_g(r_e, 3)}, set by the magnifications {_g(ss.magnification, 3)} "
            f"and {_g(other.ss.magnification, 3)}."
        )
    else:
        text = (
            f"x_ss falls from {_g(other.ss.amplitude)} m to {_g(ss.amplitude)} m (ratio {_g(r_e, 3)}), still "
            f"{_g(ss.magnification, 2)} times the static deflection F0/k = {_g(ss.static_deflection)} m."
        )
    return r_p, r_e, text


def _eval_stability(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    late = _growing(run.paper.t[run.late_mask], run.paper.x[run.late_mask])
    paper = "growing at t_end" if late == "yes" else "steady at t_end"
    st = _stability(osc, force.omega)
    if osc.c < 0:
        why = f"c = {_g(osc.c)} N s/m puts the roots at Re s = {_g(-osc.decay_rate)} 1/s > 0: unbounded growth."
    elif osc.c == 0:
        why = (
            "c = 0 forced exactly at ω_n: the response grows as t cos(ω_n t), without bound."
            if st == "unstable"
            else (
                "c = 0: the free vibration never decays, but forced off ω_n the response stays bounded "
                f"(beats with period {_g(2 * math.pi / abs(wn - force.omega), 3)} s)."
            )
        )
    else:
        settle = (
            f"the window ends before the transient has settled (2 % settling time {_g(run.settle, 3)} s)"
            if run.settle > t_end
            else f"it settles within {_g(run.settle, 3)} s"
        )
        why = (
            f"c = {_g(osc.c)} N s/m puts both roots in the left half-plane (slowest decay rate "
            f"{_g(1 / osc.time_constant)} 1/s), so the response is bounded by x_ss = {_g(ss.amplitude)} m "
            f"plus a decaying transient; {settle}."
        )
    return paper, st, why


def _eval_growing_throughout(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    grows = _growing(run.exact.t, run.exact.x)
    if osc.c <= 0:
        why = "c ≤ 0: nothing removes energy, so the cycle peaks of this forced response keep rising."
        if grows == "no":
            why = "c ≤ 0, yet the cycle peaks do not rise throughout: the response beats against the forcing."
    elif grows == "yes":
        why = (
            f"The envelope rises as x_ss (1 − exp(−t/τ)) with τ = {_g(osc.time_constant, 3)} s toward "
            f"x_ss = {_g(ss.amplitude)} m, reached (2 %) only after {_g(run.settle, 3)} s."
        )
    else:
        why = (
            f"The cycle peaks do not rise throughout: the transient (τ = {_g(osc.time_constant, 3)} s) beats "
            f"against the forcing or has died out, around x_ss = {_g(ss.amplitude)} m."
        )
    return _growing(run.paper.t, run.paper.x), grows, why


def _eval_steady_in_window(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    inside = run.settle <= t_end
    if not math.isfinite(run.settle):
        why = "c ≤ 0: the transient never decays, so the response never settles."
    else:
        why = (
            f"The 2 % settling time is {_g(run.settle, 3)} s ({_g(run.settle / osc.time_constant, 2)} time "
            f"constants), {'inside' if inside else 'beyond'} the {_g(t_end)} s window."
        )
    return "", "yes" if inside else "no", why


#: quantity -> its evaluator ``(q, run, runs) -> (paper_method_value, exact_value, reason)``; the
#: amplitude ratios share one (their partner run is ``ALSO_USES[q][0]``).
_EVALUATORS = {
    "rk45_pair": _eval_rk45_pair,
    "natural_frequency": _eval_natural_frequency,
    "frequency_ratio": _eval_frequency_ratio,
    "regime": _eval_regime,
    "steady_amplitude_x": _eval_steady_amplitude_x,
    "steady_amplitude_v": _eval_steady_amplitude_v,
    "peak_x": _eval_peak_x,
    "peak_v": _eval_peak_v,
    "stability": _eval_stability,
    "growing_throughout": _eval_growing_throughout,
    "steady_in_window": _eval_steady_in_window,
}


def _evaluate(q: str, sid: str, runs: dict[str, _Run]):
    """(paper_method_value, exact_value, reason) of quantity ``q`` for scenario ``sid``.

    ``exact_value`` None: the quantity does not exist in this run.
    """
    evaluator = _eval_amplitude_ratio if q.startswith("amplitude_ratio_") else _EVALUATORS.get(q)
    if evaluator is None:
        raise ValueError(f"quantity = {q!r} is not known to the audit")
    return evaluator(q, None if q == "rk45_pair" else runs[sid], runs)
