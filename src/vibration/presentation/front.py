"""The front page: the paper's headline numbers beside the exact ones, computed by the run.

Every value here is computed from the run's parameters with the exact closed form
(:func:`vibration.steady_state`, :func:`vibration.exact_response`, :func:`vibration.poles`
where it exists); the paper's numbers are quoted from its text (:data:`PAPER_SAYS`).
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass

import numpy as np

from ..physics.exact import exact_response, steady_state
from ..physics.model import Oscillator, SineForce
from ..physics.stability import poles
from .style import figure, place_legend
from .tables import Column, Table

#: What the paper says, quoted (section 3 and the abstract), with the unit of the number.
PAPER_SAYS = {
    "reference_amplitude": ("approximately ±0.5 meters", 0.5, "m"),
    "resonance_amplitude": ("a level of ±5.0 meters", 5.0, "m"),
    "ratio": ("increased by approximately 10 times", 10.0, ""),
    "resonance_velocity": ("over ±20.0 m/s", 20.0, "m/s"),
    "low_damping": ("the system is unstable", None, ""),
    "high_damping": ("a negligible level, such as ±0.1 meters", 0.1, "m"),
}


@dataclass(frozen=True)
class Headline:
    """The run's exact values behind the front page."""

    m: float  # kg
    k: float  # N/m
    F0: float  # N
    t_end: float  # s
    omega_ref: float  # rad/s
    omega_res: float  # rad/s
    c_low: float  # N s/m
    c_nominal: float  # N s/m
    c_high: float  # N s/m
    x_ref: float  # steady amplitude at omega_ref, c_nominal, m
    x_res: float  # steady amplitude at omega_res, c_nominal, m
    v_res: float  # steady velocity amplitude at omega_res, c_nominal, m/s
    peak_low: float  # largest |x| in the window at c_low, m
    growth_low: float  # real part of the least stable pole at c_low, 1/s
    bounded_low: float  # steady amplitude at c_low (inf when undamped at resonance), m
    peak_high: float  # largest |x| in the window at c_high, m

    @property
    def ratio(self) -> float:
        return self.x_res / self.x_ref


def headline(m, k, F0, t_end, omega_ref, omega_res, c_low, c_nominal, c_high, n_points: int = 5001) -> Headline:
    """Compute the front page's numbers for these parameters (SI units)."""
    nominal = Oscillator(m, c_nominal, k)
    ref = steady_state(nominal, SineForce(F0, omega_ref))
    res = steady_state(nominal, SineForce(F0, omega_res))
    t = np.linspace(0.0, t_end, n_points)
    low = Oscillator(m, c_low, k)
    peak_low = float(np.max(np.abs(exact_response(low, SineForce(F0, omega_res), t).x)))
    # with c <= 0 the response has no bounded steady state
    bounded_low = steady_state(low, SineForce(F0, omega_res)).amplitude if c_low > 0 else math.inf
    high = Oscillator(m, c_high, k)
    peak_high = float(np.max(np.abs(exact_response(high, SineForce(F0, omega_res), t).x)))
    return Headline(
        m, k, F0, t_end, omega_ref, omega_res, c_low, c_nominal, c_high,
        x_ref=ref.amplitude, x_res=res.amplitude, v_res=omega_res * res.amplitude,
        peak_low=peak_low, growth_low=max(s.real for s in poles(low)), bounded_low=bounded_low,
        peak_high=peak_high,
    )  # fmt: skip


def _stability_word(h: Headline) -> str:
    if h.growth_low < 0:
        return f"stable (poles at Re s = {h.growth_low:.3g} 1/s)"
    if h.growth_low == 0:
        return "marginally stable (poles on the imaginary axis)"
    return f"unstable (a pole at Re s = +{h.growth_low:.3g} 1/s)"


def headline_table(h: Headline) -> Table:
    """The paper's headline numbers beside the exact values of this run."""
    say = PAPER_SAYS
    rows = [
        {
            "q": f"steady amplitude, ω = {h.omega_ref:g} rad/s, c = {h.c_nominal:g} N s/m",
            "paper": say["reference_amplitude"][0],
            "exact": f"{h.x_ref:.4g} m",
        },
        {
            "q": f"steady amplitude, ω = {h.omega_res:g} rad/s, c = {h.c_nominal:g} N s/m",
            "paper": say["resonance_amplitude"][0],
            "exact": f"{h.x_res:.4g} m",
        },
        {"q": "ratio of the two amplitudes", "paper": say["ratio"][0], "exact": f"{h.ratio:.3g}"},
        {
            "q": f"steady velocity amplitude, ω = {h.omega_res:g} rad/s",
            "paper": say["resonance_velocity"][0],
            "exact": f"{h.v_res:.4g} m/s",
        },
        {
            "q": f"c = {h.c_low:g} N s/m at ω = {h.omega_res:g} rad/s",
            "paper": say["low_damping"][0],
            "exact": _stability_word(h) + f"; largest |x| in {h.t_end:g} s: {h.peak_low:.4g} m",
        },
        {
            "q": f"c = {h.c_high:g} N s/m at ω = {h.omega_res:g} rad/s",
            "paper": say["high_damping"][0],
            "exact": f"largest |x| in {h.t_end:g} s: {h.peak_high:.4g} m",
        },
    ]
    return Table(
        rows,
        [Column("q", "quantity"), Column("paper", "the paper says"), Column("exact", "exact, this run")],
        caption="The paper's headline numbers beside the exact solution of its own equation.",
        name="tab-front-headline",
        notes=("The paper's words are quoted from its Findings; they refer to its parameters (m = 1 kg, k = 20 N/m, "
               "F0 = 5 N, c = 0.1, 0.5, 15 N s/m).",),
    )  # fmt: skip


def headline_sentence(h: Headline) -> str:
    """One paragraph stating what the run found, from the numbers."""
    paper_x = PAPER_SAYS["resonance_amplitude"][1]
    rel = "below" if h.x_res < paper_x else "above"
    stab = "stable" if h.growth_low < 0 else ("marginally stable" if h.growth_low == 0 else "unstable")
    return (
        f"At the paper's resonance (ω = {h.omega_res:g} rad/s, c = {h.c_nominal:g} N s/m) the exact steady amplitude "
        f"is {h.x_res:.4g} m, {rel} the paper's 5 m, and {h.ratio:.3g} times the amplitude at ω = {h.omega_ref:g} "
        f"rad/s (the paper: about 10 times). With c = {h.c_low:g} N s/m the oscillator is {stab}: its largest "
        f"displacement in the {h.t_end:g} s window is {h.peak_low:.4g} m"
        + (f", on the way to a bounded steady amplitude of {h.bounded_low:.4g} m." if math.isfinite(h.bounded_low)
           and h.growth_low < 0 else ".")
    )  # fmt: skip


def verdict_table(claims: list[dict]) -> Table:
    """How many of the audited claims got each verdict (rows of the claims audit)."""
    counts = Counter(str(row["verdict"]) for row in claims)
    rows = [{"verdict": v, "n": n} for v, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))]
    rows.append({"verdict": "total", "n": sum(counts.values())})
    return Table(
        rows,
        [Column("verdict", "verdict"), Column("n", "claims")],
        caption="Verdicts of the claims audit (chapter 2) for this run.",
        name="tab-front-verdicts",
    )


def headline_figure(h: Headline, n_points: int = 5001):
    """x(t) at the paper's resonance, exact, with the paper's ±5 m and the exact steady amplitude."""
    t = np.linspace(0.0, h.t_end, n_points)
    x = exact_response(Oscillator(h.m, h.c_nominal, h.k), SineForce(h.F0, h.omega_res), t).x
    fig, ax = figure(height=3.2)
    ax.plot(t, x, color="C0", lw=0.9, label=rf"exact $x(t)$, $c$ = {h.c_nominal:g} N s/m")
    ax.axhline(h.x_res, color="C2", ls="--", lw=1.2, label=rf"exact steady amplitude $\pm${h.x_res:.3g} m")
    ax.axhline(-h.x_res, color="C2", ls="--", lw=1.2)
    paper_x = PAPER_SAYS["resonance_amplitude"][1]
    ax.axhline(paper_x, color="C1", ls=":", lw=1.5, label=rf"the paper's $\pm${paper_x:g} m")
    ax.axhline(-paper_x, color="C1", ls=":", lw=1.5)
    ax.set_xlabel("$t$ (s)")
    ax.set_ylabel("$x$ (m)")
    ax.set_title(rf"Resonance, $\omega$ = {h.omega_res:g} rad/s: exact response against the paper's amplitude")
    top = max(paper_x, float(np.max(np.abs(x)))) * 1.6
    ax.set_ylim(-top, top)
    place_legend(ax, ncols=3)
    return fig
