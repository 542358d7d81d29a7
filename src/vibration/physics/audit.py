"""The claims audit: each checkable claim of the paper against its own method and exact theory.

Verdict rule (:func:`verdict`), decided from the exact value:

* ``approx`` claims ("about X"): **reproduced** when the exact value rounds to
  the claim at the claim's own precision (within half a unit of its last
  stated digit, so "0.5" covers 0.45 to 0.55); **partly reproduced** when it is
  within a factor :data:`PARTLY_FACTOR` of the claim; else **number differs**.
* ``greater`` / ``less`` claims ("over X", "below X"): **reproduced** when the
  inequality holds, **partly reproduced** when it holds after relaxing X by
  the factor :data:`PARTLY_FACTOR`, else **number differs**.
* ``category`` claims (a word: a regime, stability, a method's name): **reproduced**
  when equal; otherwise **physics contradicts** when the word is about the motion
  (regime, stability, growth, settling) and **name differs** for the method's name.
* A quantity that does not exist in the run (a steady amplitude when c < 0) makes a
  numerical claim **physics contradicts**.

Beside each discrepancy the audit computes the *readings* that could explain it
(:func:`readings`): the same claim read as a peak-to-peak value, as a magnification
factor, as a transient still growing at the end of the window, and so on, each with the
number it gives and whether it matches the paper by the same rule. It says which
reading fits best, never which one the authors meant.

Examples
--------
>>> from vibration.physics.paper import load_claims, load_scenarios
>>> rows = {r["claim_id"]: r for r in audit_claims(load_scenarios(), load_claims(), n_points=2001)}
>>> rows["C09"]["verdict"], rows["C14"]["verdict"], rows["C20"]["verdict"]
('number differs', 'physics contradicts', 'name differs')
>>> rows["C09"]["best_reading"]
'2 x_ss at resonance / x_ss of reference'
"""

from __future__ import annotations

import math
from decimal import Decimal
from fractions import Fraction

import numpy as np
from scipy.integrate import RK45

from .exact import exact_response, steady_state
from .frequency import settling_time
from .model import Oscillator
from .numerics import DEFAULT_N_POINTS, simulate
from .paper import Scenario, load_scenarios

__all__ = [
    "PARTLY_FACTOR",
    "RK_PAIRS",
    "VERDICTS",
    "audit_claims",
    "claim_kind_text",
    "half_power_band",
    "half_unit",
    "readings",
    "resonant_peak",
    "rk45_pair",
    "scipy_rk45_nodes",
    "verdict",
]

#: A claim within this factor of the exact value (either way) is "partly reproduced".
PARTLY_FACTOR = 1.5

#: Every verdict, best first.
VERDICTS = ("reproduced", "partly reproduced", "number differs", "name differs", "physics contradicts")

#: Quantities whose words are about the motion (a mismatch is "physics contradicts").
PHYSICAL_WORDS = ("regime", "stability", "growing_throughout", "steady_in_window")

#: Nodes c_i of the two 5(4)/4(5) pairs the paper's "RK45" could mean
#: (Dormand & Prince 1980; Fehlberg 1969), to identify SciPy's tableau.
RK_PAIRS = {
    "Dormand-Prince 5(4)": (0, Fraction(1, 5), Fraction(3, 10), Fraction(4, 5), Fraction(8, 9), 1),
    "Runge-Kutta-Fehlberg 4(5)": (0, Fraction(1, 4), Fraction(3, 8), Fraction(12, 13), 1, Fraction(1, 2)),
}

#: Columns of :func:`audit_claims` rows (and of the report's ``claims.csv``).
COLUMNS = (
    "claim_id",
    "claim",
    "quantity",
    "unit",
    "kind",
    "claim_kind",
    "paper_value",
    "paper_method_value",
    "exact_value",
    "verdict",
    "reason",
    "best_reading",
    "best_reading_value",
    "best_reading_matches",
    "changed",
)

#: Scenarios a claim about quantity q also depends on (besides its own).
ALSO_USES = {
    "amplitude_ratio_resonance_reference": ("reference",),
    "amplitude_ratio_high_nominal": ("damping_nominal",),
}


def changed_text(sc: Scenario, paper: Scenario | None) -> str:
    """What differs between a run's scenario and the paper's (empty when nothing does).

    Examples
    --------
    >>> sc = load_scenarios()
    >>> changed_text(sc["damping_low"], sc["damping_low"])
    ''
    >>> from dataclasses import replace
    >>> changed_text(replace(sc["damping_low"], oscillator=Oscillator(m=1.0, c=0.05, k=20.0)), sc["damping_low"])
    "c = 0.05 N s/m (the paper's: 0.1)"
    """
    if paper is None:
        return ""
    pairs = [
        ("m", sc.oscillator.m, paper.oscillator.m, "kg"),
        ("c", sc.oscillator.c, paper.oscillator.c, "N s/m"),
        ("k", sc.oscillator.k, paper.oscillator.k, "N/m"),
        ("F0", sc.force.F0, paper.force.F0, "N"),
        ("ω", sc.force.omega, paper.force.omega, "rad/s"),
        ("t_end", sc.t_end, paper.t_end, "s"),
    ]
    return "; ".join(f"{n} = {_g(a, 6)} {u} (the paper's: {_g(b, 6)})" for n, a, b, u in pairs if a != b)


def half_unit(text: str) -> float:
    """Half a unit in the last stated digit of a number as written.

    Examples
    --------
    >>> half_unit("0.5"), half_unit("5.0"), half_unit("4.47"), half_unit("10")
    (0.05, 0.05, 0.005, 0.5)
    """
    exponent = Decimal(text.strip()).as_tuple().exponent
    return 0.5 * 10.0**exponent


def verdict(kind: str, paper_value: str, exact_value, quantity: str = "") -> str:
    """The verdict of one claim by the module's rule (one of :data:`VERDICTS`).

    ``exact_value`` None means the quantity does not exist in this run.

    Examples
    --------
    >>> verdict("approx", "0.5", 0.4504), verdict("approx", "1.5", 1.351), verdict("approx", "5.0", 2.237)
    ('reproduced', 'partly reproduced', 'number differs')
    >>> verdict("greater", "10.0", 10.26), verdict("category", "unstable", "stable", "stability")
    ('reproduced', 'physics contradicts')
    >>> verdict("category", "Runge-Kutta-Fehlberg 4(5)", "Dormand-Prince 5(4)", "rk45_pair")
    'name differs'
    """
    if exact_value is None:
        return "physics contradicts"
    if kind == "category":
        if str(exact_value) == paper_value:
            return "reproduced"
        return "physics contradicts" if quantity in PHYSICAL_WORDS else "name differs"
    claim, value = float(paper_value), float(exact_value)
    if kind == "approx":
        if abs(value - claim) <= half_unit(paper_value) * (1 + 1e-12):
            return "reproduced"
        lo, hi = sorted((abs(value), abs(claim)))
        return "partly reproduced" if lo > 0 and hi / lo <= PARTLY_FACTOR else "number differs"
    if kind == "greater":
        if value > claim:
            return "reproduced"
        return "partly reproduced" if value * PARTLY_FACTOR > claim else "number differs"
    if kind == "less":
        if value < claim:
            return "reproduced"
        return "partly reproduced" if value < claim * PARTLY_FACTOR else "number differs"
    raise ValueError(f"kind = {kind!r} is not known: allowed approx, greater, less, category")


def claim_kind_text(kind: str, paper_value: str, unit: str, quantity: str = "") -> str:
    """The claim's kind beside its value, in words.

    Examples
    --------
    >>> claim_kind_text("approx", "0.5", "m"), claim_kind_text("greater", "10.0", "m")
    ('about 0.5 m', 'over 10.0 m')
    >>> claim_kind_text("less", "0.1", "1", "amplitude_ratio_high_nominal")
    'below 0.1 of nominal'
    >>> claim_kind_text("category", "unstable", "")
    'a word: unstable'
    """
    u = "" if unit in ("", "1") else f" {unit}"
    if kind == "category":
        return f"a word: {paper_value}"
    of = {"amplitude_ratio_high_nominal": " of nominal", "amplitude_ratio_resonance_reference": "-fold"}.get(
        quantity, u
    )
    word = {"approx": "about", "greater": "over", "less": "below"}[kind]
    return f"{word} {paper_value}{of}"


def half_power_band(osc: Oscillator) -> tuple[float | None, float | None]:
    """Exact half-power frequencies of the displacement response, rad/s.

    The magnification falls to its peak over sqrt(2) at
    ``r^2 = 1 - 2 zeta^2 -/+ 2 zeta sqrt(1 - zeta^2)``. ``None`` for a point
    that does not exist: both when there is no finite peak (zeta <= 0 or
    zeta >= 1/sqrt(2)), the lower one when ``r^2`` would be negative.

    Examples
    --------
    >>> lo, hi = half_power_band(Oscillator(m=1.0, c=0.5, k=20.0))
    >>> round(lo, 4), round(hi, 4), round(hi - lo, 4)      # rad/s
    (4.2003, 4.7019, 0.5016)
    >>> half_power_band(Oscillator(m=1.0, c=15.0, k=20.0))
    (None, None)
    """
    z, wn = osc.damping_ratio, osc.natural_frequency
    if not 0.0 < z < 1.0 / math.sqrt(2.0):
        return None, None
    mid, half = 1.0 - 2.0 * z * z, 2.0 * z * math.sqrt(1.0 - z * z)
    lo2 = mid - half
    return (wn * math.sqrt(lo2) if lo2 > 0.0 else None), wn * math.sqrt(mid + half)


def resonant_peak(osc: Oscillator) -> tuple[float | None, float | None]:
    """Frequency (rad/s) and height (dimensionless) of the magnification's peak.

    The peak sits at ``r = sqrt(1 - 2 zeta^2)`` with height ``1 / (2 zeta sqrt(1 - zeta^2))``
    for ``0 < zeta < 1/sqrt(2)``; at ``omega_n`` with infinite height when undamped. ``None``
    for both when there is no peak (``zeta >= 1/sqrt(2)``: the curve falls from 1 at
    omega = 0) or no steady state (c < 0).

    Examples
    --------
    >>> w, mag = resonant_peak(Oscillator(m=1.0, c=0.5, k=20.0))
    >>> round(w, 4), round(mag, 4)      # rad/s, 1
    (4.4581, 8.9583)
    >>> resonant_peak(Oscillator(m=1.0, c=0.0, k=20.0))[1], resonant_peak(Oscillator(m=1.0, c=15.0, k=20.0))
    (inf, (None, None))
    """
    z, wn = osc.damping_ratio, osc.natural_frequency
    if z == 0.0:
        return wn, math.inf
    if not 0.0 < z < 1.0 / math.sqrt(2.0):
        return None, None
    return wn * math.sqrt(1.0 - 2.0 * z * z), 1.0 / (2.0 * z * math.sqrt(1.0 - z * z))


def scipy_rk45_nodes() -> tuple[Fraction, ...]:
    """Nodes ``c_i`` of SciPy's ``RK45`` tableau as exact fractions.

    Examples
    --------
    >>> ", ".join(str(c) for c in scipy_rk45_nodes())
    '0, 1/5, 3/10, 4/5, 8/9, 1'
    """
    return tuple(Fraction(float(c)).limit_denominator(1000) for c in RK45.C)


def rk45_pair() -> str:
    """Name of the Runge-Kutta pair whose nodes equal SciPy's ``RK45.C``.

    Examples
    --------
    >>> rk45_pair()
    'Dormand-Prince 5(4)'
    """
    nodes = scipy_rk45_nodes()
    for name, ref in RK_PAIRS.items():
        if nodes == tuple(Fraction(x) for x in ref):
            return name
    return "unknown: nodes " + ", ".join(str(c) for c in nodes)


def _cycle_peaks(t, x) -> np.ndarray:
    """Local maxima of |x| (one or two per forcing cycle), m."""
    a = np.abs(x)
    idx = np.nonzero((a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:]))[0] + 1
    return a[idx]


class _Run:
    """Both responses of one scenario on the paper's grid, computed once."""

    def __init__(self, sc: Scenario, n_points: int, cache: dict):
        self.sc = sc
        key = (sc.oscillator, sc.force, sc.t_end, sc.x0, sc.v0)
        if key not in cache:
            paper = simulate(sc.oscillator, sc.force, sc.t_end, n_points, sc.x0, sc.v0)
            cache[key] = (paper, exact_response(sc.oscillator, sc.force, paper.t, sc.x0, sc.v0))
        self.paper, self.exact = cache[key]
        self.ss = steady_state(sc.oscillator, sc.force)
        self.settle = settling_time(sc.oscillator, sc.force)
        self.late_mask = self.paper.t >= 0.8 * sc.t_end

    @property
    def has_steady(self) -> bool:
        """Whether a steady state exists and is finite (c > 0, or c = 0 off resonance)."""
        return self.sc.oscillator.c >= 0.0 and math.isfinite(self.ss.amplitude)

    def late(self, arr) -> float:
        """max |arr| over the last fifth of the window (the steady part when it has settled)."""
        return float(np.max(np.abs(arr[self.late_mask])))


def _stability(osc: Oscillator, omega: float) -> str:
    """'stable' (c > 0), 'unstable' (c < 0, or c = 0 forced exactly at omega_n) or 'marginal'."""
    if osc.c > 0:
        return "stable"
    if osc.c < 0 or omega == osc.natural_frequency:
        return "unstable"
    return "marginal"


def _growing(t, x) -> str:
    peaks = _cycle_peaks(t, x)
    return "yes" if peaks.size > 2 and np.all(np.diff(peaks) >= -1e-9 * peaks.max()) else "no"


def _g(v, d=4) -> str:
    if v is None:
        return "—"
    v = float(v)
    if math.isinf(v):
        return "∞"
    text = f"{v:.{d}g}"
    if "e" in text:
        mant, exp = text.split("e")
        text = f"{mant}e{int(exp)}"
    return text


def _context(run: _Run):
    """What most evaluators read off a run: oscillator, force, window, ω_n, ζ, steady state, and the
    sentence for a run without a steady state."""
    osc, force, t_end = run.sc.oscillator, run.sc.force, run.sc.t_end
    no_steady = (
        f"c = {_g(osc.c)} N s/m < 0: the free vibration grows as exp({_g(-osc.decay_rate, 3)} t/s), "
        "so no steady state exists."
    )
    return osc, force, t_end, osc.natural_frequency, osc.damping_ratio, run.ss, no_steady


def _eval_rk45_pair(q: str, run: _Run | None, runs: dict[str, _Run]):
    name = rk45_pair()
    nodes = ", ".join(str(c) for c in scipy_rk45_nodes())
    return (
        "",
        name,
        (
            f"SciPy's RK45 has nodes c = ({nodes}), the Dormand-Prince pair "
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


def _eval_steady_amplitude_x(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    if not run.has_steady:
        return run.late(run.paper.x), None, no_steady
    return (
        run.late(run.paper.x),
        ss.amplitude,
        (
            f"x_ss = F0/√((k − mω²)² + (cω)²) = {_g(ss.amplitude)} m, {_g(ss.magnification, 3)} times the "
            f"static deflection F0/k = {_g(ss.static_deflection)} m."
        ),
    )


def _eval_steady_amplitude_v(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    if not run.has_steady:
        return run.late(run.paper.v), None, no_steady
    return (
        run.late(run.paper.v),
        ss.velocity_amplitude,
        f"v_ss = ω x_ss = {_g(force.omega)} × {_g(ss.amplitude)} m = {_g(ss.velocity_amplitude)} m/s.",
    )


def _eval_peak_x(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    pk_p, pk_e = float(np.max(np.abs(run.paper.x))), float(np.max(np.abs(run.exact.x)))
    tail = (
        f"the steady amplitude is {_g(ss.amplitude)} m (magnification {_g(ss.magnification, 3)}, ζ = {_g(zeta, 3)})."
        if run.has_steady
        else no_steady
    )
    return (
        pk_p,
        pk_e,
        f"Over [0, {_g(t_end)}] s the peak |x| is {_g(pk_e)} m exactly ({_g(pk_p)} m by RK45); {tail}",
    )


def _eval_peak_v(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    pk_p, pk_e = float(np.max(np.abs(run.paper.v))), float(np.max(np.abs(run.exact.v)))
    bound = f"; near resonance it is bounded by F0/c = {_g(force.F0 / osc.c)} m/s" if osc.c > 0 else ""
    return (
        pk_p,
        pk_e,
        f"Over [0, {_g(t_end)}] s the peak |v| is {_g(pk_e)} m/s exactly ({_g(pk_p)} m/s by RK45){bound}.",
    )


def _eval_amplitude_ratio(q: str, run: _Run, runs: dict[str, _Run]):
    osc, force, t_end, wn, zeta, ss, no_steady = _context(run)
    other = runs[ALSO_USES[q][0]]
    if not (run.has_steady and other.has_steady) or other.ss.amplitude == 0:
        unsteady = run if not run.has_steady else other  # name the run without a steady state
        o = unsteady.sc.oscillator
        return (
            "",
            None,
            (
                f"c = {_g(o.c)} N s/m < 0: the free vibration grows as exp({_g(-o.decay_rate, 3)} t/s), "
                "so no steady state exists."
            ),
        )
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


def readings(q: str, sid: str, runs: dict[str, _Run]) -> list[tuple[str, object, str]]:
    """Alternative readings of quantity ``q``: ``(description, value, unit)`` each, computed.

    ``value`` is a float (in ``unit``), a word, or None when it does not exist in this run.
    """
    if q == "rk45_pair":
        return [("the pair whose nodes equal SciPy's RK45 nodes", rk45_pair(), "")]
    run = runs[sid]
    osc, force, ss, t_end = run.sc.oscillator, run.sc.force, run.ss, run.sc.t_end
    amp = ss.amplitude if run.has_steady else None
    if q in ("steady_amplitude_x", "peak_x", "steady_amplitude_v", "peak_v"):
        arr, unit, sym = (run.exact.x, "m", "x") if q.endswith("_x") else (run.exact.v, "m/s", "v")
        a = amp if q.endswith("_x") or amp is None else force.omega * amp
        return [
            ("steady amplitude", a, unit),
            (f"largest |{sym}| in the window", float(np.max(np.abs(arr))), unit),
            ("2 × steady amplitude (peak-to-peak)", None if a is None else 2.0 * a, unit),
            ("peak-to-peak in the window", float(np.max(arr) - np.min(arr)), unit),
        ]
    if q.startswith("amplitude_ratio_"):
        other = runs[ALSO_USES[q][0]]
        ok = run.has_steady and other.has_steady and other.ss.amplitude > 0
        r = ss.amplitude / other.ss.amplitude if ok else None
        readings = [
            ("ratio of steady amplitudes", r, "1"),
            (
                "ratio of window peaks of |x|",
                float(np.max(np.abs(run.exact.x)) / np.max(np.abs(other.exact.x))),
                "1",
            ),
        ]
        if q == "amplitude_ratio_resonance_reference":
            readings += [
                ("magnification x_ss/(F0/k) at resonance", ss.magnification if ok else None, "1"),
                ("2 x_ss at resonance / x_ss of reference", None if r is None else 2 * r, "1"),
            ]
        return readings
    if q == "stability":
        late = _growing(run.exact.t[run.late_mask], run.exact.x[run.late_mask])
        return [
            ("bounded? (roots of m s² + c s + k)", _stability(osc, force.omega), ""),
            (
                f"still growing at t = {_g(t_end)} s, read as instability",
                "unstable" if late == "yes" else "stable",
                "",
            ),
        ]
    if q == "growing_throughout":
        late = _growing(run.exact.t[run.late_mask], run.exact.x[run.late_mask])
        return [
            ("cycle peaks never decrease over the window", _growing(run.exact.t, run.exact.x), ""),
            ("peaks still rising in the last fifth", late, ""),
        ]
    if q == "steady_in_window":
        s5 = settling_time(osc, force, tol=0.05)
        return [
            ("2 % settling time inside the window", "yes" if run.settle <= t_end else "no", ""),
            ("5 % settling time inside the window", "yes" if s5 <= t_end else "no", ""),
        ]
    if q == "regime":
        return [("ζ = c/(2√(km))", osc.regime, "")]
    if q == "natural_frequency":
        return [("√(k/m)", osc.natural_frequency, "rad/s")]
    if q == "frequency_ratio":
        return [("ω/ω_n", force.omega / osc.natural_frequency, "1")]
    raise ValueError(f"quantity = {q!r} is not known to the audit")


def _closeness(kind: str, paper_value: str, value) -> tuple:
    """Sort key of a reading: verdict rank, then |log(value / claim)| (numbers only)."""
    if value is None:
        return (len(VERDICTS), math.inf)
    rank = VERDICTS.index(verdict(kind, paper_value, value))
    if kind == "category":
        return (rank, 0.0)
    v, c = abs(float(value)), abs(float(paper_value))
    return (rank, abs(math.log(v / c)) if v > 0 and c > 0 else math.inf)


def audit_claims(
    scenarios: dict[str, Scenario], claims: list[dict[str, str]], n_points: int = DEFAULT_N_POINTS
) -> list[dict[str, object]]:
    """The claims table: one row per claim, columns :data:`COLUMNS`.

    ``paper_method_value`` comes from RK45 at SciPy's default tolerances on
    ``n_points`` samples, ``exact_value`` from the closed form (None when the
    quantity does not exist in the run); the verdict follows :func:`verdict`;
    ``""`` marks a value the method does not affect. ``readings`` holds
    ``(description, value, unit, verdict)`` for every reading of the claim and
    ``best_reading`` the description of the one that fits best (by verdict, then
    by closeness to the paper's number).
    """
    cache: dict = {}
    runs = {sid: _Run(sc, n_points, cache) for sid, sc in scenarios.items()}
    try:
        paper_sc = load_scenarios()
    except OSError:  # pragma: no cover - data/ moved away: nothing to compare with
        paper_sc = {}
    rows = []
    for cl in claims:
        q, sid, kind = cl["quantity"], cl["scenario_id"], cl["kind"]
        pm, ex, reason = _evaluate(q, sid, runs)
        reads = [(d, v, u, verdict(kind, cl["paper_value"], v, q)) for d, v, u in readings(q, sid, runs)]
        best = min(reads, key=lambda r: _closeness(kind, cl["paper_value"], r[1]))
        rows.append(
            {
                "claim_id": cl["claim_id"],
                "claim": cl["claim"],
                "quantity": q + (f" [{sid}]" if sid else ""),
                "unit": cl["unit"],
                "kind": kind,
                "claim_kind": claim_kind_text(kind, cl["paper_value"], cl["unit"], q),
                "paper_value": cl["paper_value"],
                "paper_method_value": pm,
                "exact_value": ex,
                "verdict": verdict(kind, cl["paper_value"], ex, q),
                "reason": reason,
                "best_reading": best[0],
                "best_reading_value": best[1],
                "best_reading_matches": best[3] == "reproduced",
                "readings": reads,
                "scenario_id": sid,
                "changed": "; ".join(
                    t
                    for t in dict.fromkeys(
                        (f"{s}: " if s != sid else "") + changed_text(scenarios[s], paper_sc.get(s))
                        for s in ((sid, *ALSO_USES.get(q, ())) if sid else ())
                        if changed_text(scenarios[s], paper_sc.get(s))
                    )
                ),
            }
        )
    return rows
