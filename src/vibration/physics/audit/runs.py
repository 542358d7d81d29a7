"""One scenario's responses on the paper's grid, computed once, and what the audit reads off them."""

from __future__ import annotations

import math

import numpy as np

from ..exact import exact_response, steady_state
from ..frequency import local_maxima, settling_time
from ..model import Oscillator
from ..numerics import simulate
from ..paper import Scenario

__all__ = ["ALSO_USES"]

#: Scenarios a claim about quantity q also depends on (besides its own).
ALSO_USES = {
    "amplitude_ratio_resonance_reference": ("reference",),
    "amplitude_ratio_high_nominal": ("damping_nominal",),
}


def _cycle_peaks(t, x) -> np.ndarray:
    """Local maxima of |x| (one or two per forcing cycle), m."""
    a = np.abs(x)
    return a[local_maxima(a)]


class _Run:
    """Both responses of one scenario on the paper's grid, computed once."""

    def __init__(self, sc: Scenario, n_points: int, cache: dict):
        self.sc = sc
        key = (sc.oscillator, sc.force, sc.t_end, sc.x0, sc.v0)
        if key not in cache:
            paper = simulate(sc.oscillator, sc.force, sc.t_end, n_points=n_points, x0=sc.x0, v0=sc.v0)
            cache[key] = (paper, exact_response(sc.oscillator, sc.force, paper.t, x0=sc.x0, v0=sc.v0))
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


def _no_steady_text(osc: Oscillator) -> str:
    """The sentence for a run without a steady state (c < 0)."""
    return (
        f"c = {_g(osc.c)} N s/m < 0: the free vibration grows as exp({_g(-osc.decay_rate, 3)} t/s), "
        "so no steady state exists."
    )
