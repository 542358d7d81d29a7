"""The front page's computation: the paper's headline numbers, exact, and the audit's verdicts.

Every value here is computed from the run's parameters with the exact closed form
(:func:`vibration.steady_state`, :func:`vibration.exact_response`, :func:`vibration.poles`) and
the claims audit of :mod:`vibration.physics.audit`; the paper's own numbers are quoted from its
text (:data:`PAPER_SAYS`). :func:`overview_study` returns one frozen :class:`OverviewStudy`.

Examples
--------
>>> st = overview_study()
>>> round(st.x_res, 4), round(st.ratio, 2), st.verdicts["reproduced"]
(2.2371, 4.97, 12)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.overview.params import Params
from vibration.book.presentation.findings import scenarios_of
from vibration.physics.audit import VERDICTS, audit_claims
from vibration.physics.exact import exact_response, steady_state
from vibration.physics.model import Oscillator, SineForce
from vibration.physics.paper import load_claims
from vibration.physics.stability import poles

#: What the paper says, quoted (section 3 and the abstract), with its number and the number's unit.
PAPER_SAYS = {
    "reference_amplitude": ("approximately ±0.5 meters", 0.5, "m"),
    "resonance_amplitude": ("a level of ±5.0 meters", 5.0, "m"),
    "ratio": ("increased by approximately 10 times", 10.0, ""),
    "resonance_velocity": ("over ±20.0 m/s", 20.0, "m/s"),
    "low_damping": ("the system is unstable", None, ""),
    "high_damping": ("a negligible level, such as ±0.1 meters", 0.1, "m"),
}

#: Samples of the window for the peaks and the figure.
N_POINTS = 5001


@dataclass(frozen=True, kw_only=True)
class OverviewStudy:
    """The run's exact values behind the front page (SI units)."""

    params: Params
    x_ref: float  # steady amplitude at omega_ref, c_nominal, m
    x_res: float  # steady amplitude at omega_res, c_nominal, m (inf undamped at exact resonance)
    v_res: float  # steady velocity amplitude at omega_res, c_nominal, m/s
    peak_low: float  # largest |x| in the window at c_low, m
    growth_low: float  # real part of the least stable pole at c_low, 1/s
    bounded_low: float  # steady amplitude at c_low (inf when there is none), m
    peak_high: float  # largest |x| in the window at c_high, m
    t: np.ndarray  # times of the resonance response, s
    x: np.ndarray  # exact displacement at omega_res, c_nominal, from rest, m
    verdicts: dict  # verdict -> number of claims of the audit, in the order of VERDICTS
    solver_gap: float  # largest |RK45 / exact - 1| over the audit's numerical claims, 1

    @property
    def ratio(self) -> float:
        """Steady amplitude at resonance over the reference one."""
        return self.x_res / self.x_ref if self.x_ref > 0 else math.nan

    @property
    def n_claims(self) -> int:
        """Number of audited claims."""
        return sum(self.verdicts.values())


def _solver_gap(rows: list[dict]) -> float:
    gaps = [
        abs(float(r["paper_method_value"]) / float(r["exact_value"]) - 1)
        for r in rows
        if isinstance(r["paper_method_value"], float | int)
        and not isinstance(r["paper_method_value"], bool)
        and isinstance(r["exact_value"], float | int)
        and r["exact_value"]
    ]
    return max(gaps, default=0.0)


def overview_study(params: Params | None = None, **values) -> OverviewStudy:
    """The front page's whole computation.

    Parameters
    ----------
    params : Params, optional
        The validated parameters; or give them as keyword arguments (checked by the schema).
    """
    p = params if params is not None else Params.from_values(values)
    nominal = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    ref = steady_state(nominal, SineForce(F0=p.F0, omega=p.omega_ref))
    res = steady_state(nominal, SineForce(F0=p.F0, omega=p.omega_res))
    t = np.linspace(0.0, p.t_end, N_POINTS)
    x = exact_response(nominal, SineForce(F0=p.F0, omega=p.omega_res), t).x
    low, high = Oscillator(m=p.m, c=p.c_low, k=p.k), Oscillator(m=p.m, c=p.c_high, k=p.k)
    force = SineForce(F0=p.F0, omega=p.omega_res)
    peak_low = float(np.max(np.abs(exact_response(low, force, t).x)))
    growth_low = float(max(s.real for s in poles(low)))
    bounded_low = steady_state(low, force).amplitude if p.c_low > 0 else math.inf
    peak_high = float(np.max(np.abs(exact_response(high, force, t).x)))
    rows = audit_claims(scenarios_of(p), load_claims())
    verdicts = {v: sum(r["verdict"] == v for r in rows) for v in VERDICTS}
    return OverviewStudy(
        params=p,
        x_ref=ref.amplitude if p.c_nominal >= 0 else math.nan,
        x_res=res.amplitude if p.c_nominal >= 0 else math.nan,
        v_res=p.omega_res * res.amplitude if p.c_nominal >= 0 else math.nan,
        peak_low=peak_low,
        growth_low=growth_low,
        bounded_low=bounded_low,
        peak_high=peak_high,
        t=t,
        x=x,
        verdicts=verdicts,
        solver_gap=_solver_gap(rows),
    )
