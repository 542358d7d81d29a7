"""Per-scenario findings and fixed-precision tables (printed for nbval, saved as CSV)."""

from __future__ import annotations

import csv
import math
import os
from pathlib import Path

import numpy as np

from ..physics.exact import exact_response, steady_state
from ..physics.frequency import settling_time
from ..physics.model import Oscillator, SineForce, check_real
from ..physics.numerics import DEFAULT_N_POINTS, simulate
from ..physics.paper import Scenario

#: Environment variable naming the folder where :func:`show_table` also writes CSV files.
TABLES_ENV = "VIBRATION_TABLES_DIR"


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

    Units: m kg, k N/m, F0 N, t_end s, omegas rad/s, dampings N s/m. Every
    value is validated by the records it builds.

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


def scenario_findings(sc: Scenario, n_points: int = DEFAULT_N_POINTS, paper=None) -> dict[str, object]:
    """The findings row of one scenario: exact quantities and the paper's method side by side.

    ``paper`` is the scenario's :func:`simulate` result if the caller already has
    it (for the figures, say); otherwise it is computed here.

    Returns a dict with ``scenario``, ``omega_n`` (rad/s), ``zeta``, ``regime``,
    ``x_ss`` (m), ``v_ss`` (m/s), ``peak_x_rk45``, ``peak_x_exact`` (m),
    ``peak_v_rk45``, ``peak_v_exact`` (m/s), ``max_err_x_rk45`` (m),
    ``tau`` (s), ``t_settle`` (s) and ``steady_in_window`` (bool).
    """
    osc, force = sc.oscillator, sc.force
    if paper is None:
        paper = simulate(osc, force, sc.t_end, n_points, sc.x0, sc.v0)
    exact = exact_response(osc, force, paper.t, sc.x0, sc.v0)
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


def fmt(value, digits: int = 4) -> str:
    """Fixed-precision text of a table cell: floats to ``digits`` significant figures.

    Examples
    --------
    >>> fmt(2.23703819), fmt(0.000123456), fmt(True), fmt(math.inf), fmt("overdamped")
    ('2.237', '0.0001235', 'yes', 'inf', 'overdamped')
    """
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    if isinstance(value, int | np.integer):
        return str(int(value))
    if isinstance(value, float | np.floating):
        v = float(value)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return f"{v:.{digits}g}"
    return str(value)


def at_least(value: float, floor: float):
    """``value``, or the text ``"< floor"`` when it is below ``floor``.

    For table cells at rounding level, whose last digits depend on the CPU's
    floating-point paths: strict nbval then compares the bound, not the noise.

    Examples
    --------
    >>> at_least(3.2e-3, 1e-12), at_least(4.4e-16, 1e-12)
    (0.0032, '< 1e-12')
    """
    return value if value >= floor else f"< {floor:g}"


def format_table(rows: list[dict[str, object]], digits: int = 4, columns=None) -> str:
    """Rows of dicts as an aligned fixed-precision text table.

    ``columns`` selects and orders the columns (default: the first row's keys).

    Examples
    --------
    >>> print(format_table([{"c_Ns_m": 0.5, "regime": "underdamped"}, {"c_Ns_m": 15.0, "regime": "overdamped"}]))
    c_Ns_m  regime
    ------  -----------
    0.5     underdamped
    15      overdamped
    """
    if not rows:
        return "(no rows)"
    cols = list(columns or rows[0])
    cells = [[fmt(r[c], digits) for c in cols] for r in rows]
    widths = [max(len(c), *(len(row[i]) for row in cells)) for i, c in enumerate(cols)]
    lines = ["  ".join(c.ljust(w) for c, w in zip(cols, widths, strict=True))]
    lines.append("  ".join("-" * w for w in widths))
    lines += ["  ".join(v.ljust(w) for v, w in zip(row, widths, strict=True)) for row in cells]
    return "\n".join(line.rstrip() for line in lines)


def transpose(rows: list[dict[str, object]], key: str) -> list[dict[str, object]]:
    """Turn rows keyed by ``key`` into one row per field (for wide tables)."""
    fields = [f for f in rows[0] if f != key]
    return [{"quantity": f, **{str(r[key]): r[f] for r in rows}} for f in fields]


def show_table(name: str, rows: list[dict[str, object]], digits: int = 4, columns=None) -> None:
    """Print ``rows`` as a fixed-precision table; also write ``name.csv`` when
    ``$VIBRATION_TABLES_DIR`` is set (the report runner sets it).

    ``columns`` limits the printed columns; the CSV always has all of them.
    CSV cells use 10 significant figures, so two runs write identical bytes.
    """
    print(format_table(rows, digits, columns))
    folder = os.environ.get(TABLES_ENV)
    if folder and rows:
        path = Path(folder) / f"{name}.csv"
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("w", newline="", encoding="utf-8") as fh:
            writer = csv.writer(fh, lineterminator="\n")
            writer.writerow(list(rows[0]))
            writer.writerows([fmt(r[c], 10) for c in rows[0]] for r in rows)
