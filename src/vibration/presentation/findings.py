"""Chapter 1: the paper's scenarios run once, their findings, and the tables built from them.

:func:`reproduce` runs the paper's method (RK45 at SciPy's defaults) and the exact closed
form on every scenario once; the figures (:mod:`.plotting`), the tables below and the
sentences (:mod:`.narrative`) all read that one :class:`Reproduction`, so a run with other
parameters never contradicts itself.

Examples
--------
>>> rep = reproduce(scenarios_from(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0), n_points=1001)
>>> [f["regime"] for f in rep.findings]
['underdamped', 'underdamped', 'underdamped', 'underdamped', 'overdamped']
>>> rep.by_id["damping_low"]["steady_in_window"]
False
"""

from __future__ import annotations

import csv
import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..physics.exact import Response, exact_response, steady_state
from ..physics.frequency import settling_time
from ..physics.model import N_POINTS_MAX, Oscillator, SineForce, check_int, check_real
from ..physics.numerics import DEFAULT_N_POINTS, simulate
from ..physics.paper import Scenario
from .tables import TABLES_ENV, Column, Missing, Table, fmt

#: Short names of the paper's scenarios, as the tables and sentences call them.
CASE_NAMES = {
    "reference": "reference",
    "resonance": "resonance",
    "damping_low": "low damping",
    "damping_nominal": "nominal damping",
    "damping_high": "high damping",
}

#: Why a quantity does not exist when the damping is not positive.
NO_STEADY = "no steady state is reached when c ≤ 0"


def case_name(sid: str) -> str:
    """Short name of scenario ``sid`` (the id itself when it is not one of the paper's)."""
    return CASE_NAMES.get(sid, sid)


def scenarios_from(
    m: float,
    k: float,
    F0: float,
    t_end: float,
    omega_ref: float,
    omega_res: float,
    c_low: float,
    c_nominal: float,
    c_high: float,
) -> dict[str, Scenario]:
    """The paper's five scenarios built from (possibly overridden) chapter parameters.

    Parameters
    ----------
    m, k, F0 : float
        Mass (kg), stiffness (N/m), force amplitude (N).
    t_end : float
        End of the window, s (> 0).
    omega_ref, omega_res : float
        Reference and "resonant" forcing frequencies, rad/s.
    c_low, c_nominal, c_high : float
        Dampings, N s/m (any sign: 0 is undamped, negative is self-excited).

    Examples
    --------
    >>> sc = scenarios_from(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0)
    >>> [s.oscillator.c for s in sc.values()]
    [0.5, 0.5, 0.1, 0.5, 15.0]
    """
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    rows = [
        ("reference", "Reference case (far from resonance)", "", c_nominal, omega_ref),
        ("resonance", "Resonance case", "Figure 1", c_nominal, omega_res),
        ("damping_low", "Low damping at resonance", "Figure 2", c_low, omega_res),
        ("damping_nominal", "Nominal damping at resonance", "Figure 2", c_nominal, omega_res),
        ("damping_high", "High damping at resonance", "Figure 2", c_high, omega_res),
    ]
    return {
        sid: Scenario(sid, label, fig, Oscillator(m, c, k), SineForce(F0, w), t_end, 0.0, 0.0)
        for sid, label, fig, c, w in rows
    }


def _findings(sc: Scenario, paper: Response, exact: Response) -> dict[str, object]:
    """The findings of one scenario: exact quantities and the paper's method side by side.

    Returns a dict with ``scenario``, ``omega_rad_s``, ``c_Ns_m``, ``omega_n_rad_s``,
    ``zeta``, ``regime``, ``x_ss_m``, ``v_ss_m_s``, ``peak_x_rk45_m``, ``peak_x_exact_m``,
    ``peak_v_rk45_m_s``, ``peak_v_exact_m_s``, ``max_err_x_rk45_m``, ``tau_s``,
    ``t_settle_2pct_s`` (``inf`` when c <= 0) and ``steady_in_window`` (bool).
    """
    osc, force = sc.oscillator, sc.force
    ss = steady_state(osc, force)
    ts = settling_time(osc, force)
    return {
        "scenario": sc.scenario_id,
        "omega_rad_s": force.omega,
        "c_Ns_m": osc.c,
        "omega_n_rad_s": osc.natural_frequency,
        "zeta": osc.damping_ratio,
        "regime": osc.regime,
        "x_ss_m": ss.amplitude,
        "v_ss_m_s": ss.velocity_amplitude,
        "peak_x_rk45_m": float(np.max(np.abs(paper.x))),
        "peak_x_exact_m": float(np.max(np.abs(exact.x))),
        "peak_v_rk45_m_s": float(np.max(np.abs(paper.v))),
        "peak_v_exact_m_s": float(np.max(np.abs(exact.v))),
        "max_err_x_rk45_m": float(np.max(np.abs(paper.x - exact.x))),
        "tau_s": osc.time_constant,
        "t_settle_2pct_s": ts,
        "steady_in_window": bool(ts <= sc.t_end),
    }


@dataclass(frozen=True)
class Reproduction:
    """Every scenario run once by the paper's method and exactly, with its findings."""

    scenarios: dict  # scenario_id -> Scenario
    paper: dict  # scenario_id -> Response of RK45 at SciPy's defaults (s, m, m/s)
    exact: dict  # scenario_id -> Response of the closed form on the same times
    findings: list  # one dict per scenario (see _findings), in scenario order

    @property
    def by_id(self) -> dict:
        """Findings keyed by scenario id."""
        return {f["scenario"]: f for f in self.findings}


def reproduce(scenarios: dict[str, Scenario], n_points: int = DEFAULT_N_POINTS) -> Reproduction:
    """Run the paper's method and the closed form once per scenario (``n_points`` samples each).

    Identical scenarios (the paper's resonance and nominal-damping cases) are run once.
    """
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    paper, exact, done = {}, {}, {}
    for sid, sc in scenarios.items():
        key = (sc.oscillator, sc.force, sc.t_end, sc.x0, sc.v0)
        if key not in done:
            p = simulate(sc.oscillator, sc.force, sc.t_end, n_points, sc.x0, sc.v0)
            done[key] = (p, exact_response(sc.oscillator, sc.force, p.t, sc.x0, sc.v0))
        paper[sid], exact[sid] = done[key]
    findings = [_findings(sc, paper[sid], exact[sid]) for sid, sc in scenarios.items()]
    return Reproduction(dict(scenarios), paper, exact, findings)


def _settle_cell(f: dict):
    return f["t_settle_2pct_s"] if math.isfinite(f["t_settle_2pct_s"]) else Missing(NO_STEADY)


def _tau_cell(f: dict):
    tau = f["tau_s"]
    if f["c_Ns_m"] < 0:
        return Missing("the free vibration grows when c < 0: no decay time")
    return tau if math.isfinite(tau) else Missing("the free vibration never decays when c = 0")


def _xss_cell(f: dict, key: str):
    if f["c_Ns_m"] < 0:
        return Missing(NO_STEADY)
    v = f[key]
    return v if math.isfinite(v) else Missing("infinite at undamped exact resonance")


def findings_table(rep: Reproduction) -> Table:
    """The per-scenario findings for people: regime, steady amplitude, window peak, settling.

    Examples
    --------
    >>> rep = reproduce(scenarios_from(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0), n_points=1001)
    >>> print(repr(findings_table(rep)).splitlines()[1])
    case             c (N s/m)  ω (rad/s)  ζ       regime       x_ss (m)  peak |x| (m)  t_s (s)  settles by t_end
    """
    rows = [
        {
            "case": case_name(f["scenario"]),
            "c": f["c_Ns_m"],
            "omega": f["omega_rad_s"],
            "zeta": f["zeta"],
            "regime": f["regime"],
            "xss": _xss_cell(f, "x_ss_m"),
            "peak": f["peak_x_exact_m"],
            "ts": _settle_cell(f),
            "settled": f["steady_in_window"],
        }
        for f in rep.findings
    ]
    t_end = next(iter(rep.scenarios.values())).t_end
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("c", "c (N s/m)", 3),
            Column("omega", "ω (rad/s)", 4),
            Column("zeta", "ζ", 3),
            Column("regime", "regime"),
            Column("xss", "x_ss (m)", 4),
            Column("peak", "peak |x| (m)", 4),
            Column("ts", "t_s (s)", 3),
            Column("settled", "settles by t_end"),
        ],
        caption=(
            f"Findings per scenario, exact: steady amplitude x_ss, largest |x| in the window [0, {t_end:g}] s "
            "from rest, and the 2 % settling time t_s (the transient stays below 2 % of x_ss after it)."
        ),
        name="tab-reproduction-findings",
    )


def methods_table(rep: Reproduction) -> Table:
    """The paper's method beside the exact solution: peaks of x and v, time constant, worst error.

    Examples
    --------
    >>> rep = reproduce(scenarios_from(1.0, 20.0, 5.0, 50.0, 3.0, 4.47, 0.1, 0.5, 15.0), n_points=1001)
    >>> methods_table(rep).name
    'tab-reproduction-methods'
    """
    rows = [
        {
            "case": case_name(f["scenario"]),
            "vss": _xss_cell(f, "v_ss_m_s"),
            "pv": f["peak_v_exact_m_s"],
            "pv45": f["peak_v_rk45_m_s"],
            "px45": f["peak_x_rk45_m"],
            "err": f["max_err_x_rk45_m"],
            "tau": _tau_cell(f),
        }
        for f in rep.findings
    ]
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("vss", "v_ss (m/s)", 4),
            Column("pv", "peak |v| (m/s)", 4),
            Column("pv45", "peak |v| RK45 (m/s)", 4),
            Column("px45", "peak |x| RK45 (m)", 4),
            Column("err", "max |x_RK45 − x| (m)", 3),
            Column("tau", "τ (s)", 3),
        ],
        caption=(
            "The paper's method (RK45 at SciPy's default tolerances) beside the exact solution: velocity "
            "amplitude v_ss = ω x_ss, peaks in the window, RK45's worst displacement error, and the time "
            "constant τ of the slowest free mode."
        ),
        name="tab-reproduction-methods",
    )


def write_findings_csv(rep: Reproduction, folder=None) -> Path | None:
    """Write ``findings.csv`` (one row per scenario, every finding at 10 significant figures).

    Into ``folder`` or ``$VIBRATION_TABLES_DIR``; nothing when neither is set.
    """
    return write_rows_csv("findings", rep.findings, folder)


def write_rows_csv(name: str, rows: list[dict], folder=None) -> Path | None:
    """Write ``rows`` (dicts with the same keys) to ``<name>.csv`` at 10 significant figures."""
    folder = folder or os.environ.get(TABLES_ENV)
    if not (folder and rows):
        return None
    path = Path(folder) / f"{name}.csv"
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(list(rows[0]))
        writer.writerows([fmt(r[c], 10) for c in rows[0]] for r in rows)
    return path


def at_least(value: float, floor: float):
    """``value``, or the text ``"< floor"`` when it is below ``floor``.

    For cells at rounding level, whose last digits depend on the CPU's
    floating-point paths: strict nbval then compares the bound, not the noise.

    Examples
    --------
    >>> at_least(3.2e-3, 1e-12), at_least(4.4e-16, 1e-12)
    (0.0032, '< 1e-12')
    """
    return value if value >= floor else f"< {fmt(floor)}"
