"""The claims audit: each checkable claim of the paper against its own method and exact theory.

Verdict rule (:func:`verdict`), decided from the exact value:

* ``approx`` claims ("about X"): **reproduced** when the exact value rounds to
  the claim at the claim's own precision (within half a unit of its last
  stated digit, so "0.5" covers 0.45 to 0.55); **partly reproduced** when it is
  within a factor :data:`PARTLY_FACTOR` of the claim; else **not reproduced**.
* ``greater`` / ``less`` claims ("over X", "below X"): **reproduced** when the
  inequality holds, **partly reproduced** when it holds after relaxing X by
  the factor :data:`PARTLY_FACTOR`, else **not reproduced**.
* ``category`` claims (a regime, a method): **reproduced** when equal, else
  **not reproduced**.
"""

from __future__ import annotations

import math
from decimal import Decimal
from fractions import Fraction

import numpy as np
from scipy.integrate import RK45

from .exact import exact_response, steady_state
from .frequency import settling_time
from .numerics import DEFAULT_N_POINTS, simulate
from .paper import Scenario

#: A claim within this factor of the exact value (either way) is "partly reproduced".
PARTLY_FACTOR = 1.5

#: Nodes c_i of the two 5(4)/4(5) pairs the paper's "RK45" could mean
#: (Dormand & Prince 1980; Fehlberg 1969), to identify SciPy's tableau.
RK_PAIRS = {
    "Dormand-Prince 5(4)": (0, Fraction(1, 5), Fraction(3, 10), Fraction(4, 5), Fraction(8, 9), 1),
    "Runge-Kutta-Fehlberg 4(5)": (0, Fraction(1, 4), Fraction(3, 8), Fraction(12, 13), 1, Fraction(1, 2)),
}

COLUMNS = (
    "claim_id",
    "claim",
    "quantity",
    "unit",
    "paper_value",
    "paper_method_value",
    "exact_value",
    "verdict",
    "reason",
)


def half_unit(text: str) -> float:
    """Half a unit in the last stated digit of a number as written.

    Examples
    --------
    >>> half_unit("0.5"), half_unit("5.0"), half_unit("4.47"), half_unit("10")
    (0.05, 0.05, 0.005, 0.5)
    """
    exponent = Decimal(text.strip()).as_tuple().exponent
    return 0.5 * 10.0**exponent


def verdict(kind: str, paper_value: str, exact_value) -> str:
    """``reproduced``, ``partly reproduced`` or ``not reproduced`` by the module's rule.

    Examples
    --------
    >>> verdict("approx", "0.5", 0.4504), verdict("approx", "1.5", 1.351), verdict("approx", "5.0", 2.237)
    ('reproduced', 'partly reproduced', 'not reproduced')
    >>> verdict("greater", "10.0", 10.26), verdict("category", "unstable", "stable")
    ('reproduced', 'not reproduced')
    """
    if kind == "category":
        return "reproduced" if str(exact_value) == paper_value else "not reproduced"
    claim, value = float(paper_value), float(exact_value)
    if kind == "approx":
        if abs(value - claim) <= half_unit(paper_value) * (1 + 1e-12):
            return "reproduced"
        lo, hi = sorted((abs(value), abs(claim)))
        return "partly reproduced" if lo > 0 and hi / lo <= PARTLY_FACTOR else "not reproduced"
    if kind == "greater":
        if value > claim:
            return "reproduced"
        return "partly reproduced" if value * PARTLY_FACTOR > claim else "not reproduced"
    if kind == "less":
        if value < claim:
            return "reproduced"
        return "partly reproduced" if value < claim * PARTLY_FACTOR else "not reproduced"
    raise ValueError(f"kind = {kind!r} is not known: allowed approx, greater, less, category")


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

    def __init__(self, sc: Scenario, n_points: int):
        self.sc = sc
        self.paper = simulate(sc.oscillator, sc.force, sc.t_end, n_points, sc.x0, sc.v0)
        self.exact = exact_response(sc.oscillator, sc.force, self.paper.t, sc.x0, sc.v0)
        self.ss = steady_state(sc.oscillator, sc.force)
        self.settle = settling_time(sc.oscillator, sc.force)

    def late(self, arr) -> float:
        """max |arr| over the last fifth of the window (steady part)."""
        return float(np.max(np.abs(arr[self.paper.t >= 0.8 * self.sc.t_end])))


def _stability(c: float) -> str:
    return "stable" if c > 0 else ("marginal" if c == 0 else "unstable")


def _growing(t, x) -> str:
    peaks = _cycle_peaks(t, x)
    return "yes" if peaks.size > 2 and np.all(np.diff(peaks) >= -1e-9 * peaks.max()) else "no"


def _evaluate(q: str, sid: str, runs: dict[str, _Run]):
    """(paper_method_value, exact_value, reason) of quantity ``q`` for scenario ``sid``."""
    if q == "rk45_pair":
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
    run = runs[sid]
    osc, force, t_end = run.sc.oscillator, run.sc.force, run.sc.t_end
    wn, zeta, ss = osc.natural_frequency, osc.damping_ratio, run.ss
    if q == "natural_frequency":
        return "", wn, f"omega_n = sqrt(k/m) = sqrt({osc.k:g}/{osc.m:g}) = {wn:.4f} rad/s."
    if q == "frequency_ratio":
        r = force.omega / wn
        inside = abs(1 - r) < zeta
        return (
            "",
            r,
            (
                f"omega/omega_n = {force.omega:g}/{wn:.4f} = {r:.5f}, a detuning of {abs(1 - r) * 100:.3f} %, "
                f"{'inside' if inside else 'outside'} the half-power band (half-width zeta = {zeta:.3g})."
            ),
        )
    if q == "regime":
        return "", osc.regime, f"zeta = c/(2 sqrt(k m)) = {osc.c:g}/{osc.critical_damping:.4f} = {zeta:.4f}."
    if q == "steady_amplitude_x":
        return (
            run.late(run.paper.x),
            ss.amplitude,
            (
                f"x_ss = F0/sqrt((k - m omega^2)^2 + (c omega)^2) = {ss.amplitude:.4g} m, i.e. "
                f"{ss.magnification:.3g} times the static deflection F0/k = {ss.static_deflection:.4g} m."
            ),
        )
    if q == "steady_amplitude_v":
        return (
            run.late(run.paper.v),
            ss.velocity_amplitude,
            (f"v_ss = omega x_ss = {force.omega:g} x {ss.amplitude:.4g} = {ss.velocity_amplitude:.4g} m/s."),
        )
    if q == "peak_x":
        pk_p, pk_e = float(np.max(np.abs(run.paper.x))), float(np.max(np.abs(run.exact.x)))
        return (
            pk_p,
            pk_e,
            (
                f"Over [0, {t_end:g}] s the peak is {pk_e:.4g} m exact and {pk_p:.4g} m with the paper's RK45; "
                f"the steady amplitude is {ss.amplitude:.4g} m "
                f"(magnification {ss.magnification:.3g}, zeta = {zeta:.3g})."
            ),
        )
    if q == "peak_v":
        pk_p, pk_e = float(np.max(np.abs(run.paper.v))), float(np.max(np.abs(run.exact.v)))
        return (
            pk_p,
            pk_e,
            (
                f"Over [0, {t_end:g}] s the peak velocity is {pk_e:.4g} m/s exact and {pk_p:.4g} m/s with RK45; "
                f"near resonance it is bounded by F0/c = {force.F0 / osc.c if osc.c > 0 else math.inf:.4g} m/s."
            ),
        )
    if q == "amplitude_ratio_resonance_reference":
        ref = runs["reference"]
        r_e = ss.amplitude / ref.ss.amplitude
        r_p = run.late(run.paper.x) / ref.late(ref.paper.x)
        return (
            r_p,
            r_e,
            (
                f"The steady amplitudes are {ss.amplitude:.4g} m and {ref.ss.amplitude:.4g} m, a ratio of {r_e:.3g} "
                f"set by the magnifications {ss.magnification:.3g} and {ref.ss.magnification:.3g} (zeta = {zeta:.3g})."
            ),
        )
    if q == "amplitude_ratio_high_nominal":
        nom = runs["damping_nominal"]
        r_e = ss.amplitude / nom.ss.amplitude
        r_p = run.late(run.paper.x) / nom.late(nom.paper.x)
        return (
            r_p,
            r_e,
            (
                f"x_ss falls from {nom.ss.amplitude:.4g} m to {ss.amplitude:.4g} m (ratio {r_e:.3g}), yet stays "
                f"{ss.magnification:.2g} times the static deflection F0/k = {ss.static_deflection:.4g} m."
            ),
        )
    if q == "stability":
        late = _growing(run.paper.t[run.paper.t >= 0.8 * t_end], run.paper.x[run.paper.t >= 0.8 * t_end])
        paper = "growing at t_end" if late == "yes" else "steady at t_end"
        sigma = osc.decay_rate
        if osc.c <= 0:
            why = f"c = {osc.c:g} N s/m leaves a root at Re s = {-sigma:.4g} 1/s >= 0: the response is not bounded."
        else:
            settle = (
                f"the window ends before the transient has settled (2 % settling time {run.settle:.3g} s)"
                if run.settle > t_end
                else f"it settles within {run.settle:.3g} s"
            )
            why = (
                f"c = {osc.c:g} N s/m puts both roots in the left half-plane (slowest decay rate "
                f"{1 / osc.time_constant:.4g} 1/s), so the response is bounded by "
                f"x_ss = {ss.amplitude:.4g} m plus a decaying transient; {settle}."
            )
        return paper, _stability(osc.c), why
    if q == "growing_throughout":
        grows = _growing(run.exact.t, run.exact.x)
        if grows == "yes":
            why = (
                f"The envelope rises as x_ss (1 - exp(-t/tau)) with tau = {osc.time_constant:.3g} s toward "
                f"x_ss = {ss.amplitude:.4g} m, reached (2 %) only after {run.settle:.3g} s."
            )
        else:
            why = (
                f"The cycle peaks do not rise throughout: the transient (tau = {osc.time_constant:.3g} s) beats "
                f"against the forcing or has died out, around x_ss = {ss.amplitude:.4g} m."
            )
        return _growing(run.paper.t, run.paper.x), grows, why
    if q == "steady_in_window":
        inside = run.settle <= t_end
        return (
            "",
            "yes" if inside else "no",
            (
                f"The 2 % settling time is {run.settle:.3g} s ({run.settle / osc.time_constant:.2g} time constants), "
                f"{'inside' if inside else 'beyond'} the {t_end:g} s window."
            ),
        )
    raise ValueError(f"quantity = {q!r} is not known to the audit")


def audit_claims(
    scenarios: dict[str, Scenario], claims: list[dict[str, str]], n_points: int = DEFAULT_N_POINTS
) -> list[dict[str, object]]:
    """The claims table: one row per claim, columns :data:`COLUMNS`.

    ``paper_method_value`` comes from RK45 at SciPy's default tolerances on
    ``n_points`` samples, ``exact_value`` from the closed form; the verdict
    follows :func:`verdict`; ``""`` marks a value the method does not affect.
    """
    runs = {sid: _Run(sc, n_points) for sid, sc in scenarios.items()}
    rows = []
    for cl in claims:
        pm, ex, reason = _evaluate(cl["quantity"], cl["scenario_id"], runs)
        rows.append(
            {
                "claim_id": cl["claim_id"],
                "claim": cl["claim"],
                "quantity": cl["quantity"] + (f" [{cl['scenario_id']}]" if cl["scenario_id"] else ""),
                "unit": cl["unit"],
                "paper_value": cl["paper_value"],
                "paper_method_value": pm,
                "exact_value": ex,
                "verdict": verdict(cl["kind"], cl["paper_value"], ex),
                "reason": reason,
            }
        )
    return rows
