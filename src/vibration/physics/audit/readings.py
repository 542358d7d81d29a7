"""Alternative readings of a claim: the same quantity read another way, each with the number it gives."""

from __future__ import annotations

import numpy as np

from ..frequency import settling_time
from .rk45 import rk45_pair
from .runs import ALSO_USES, _g, _growing, _Run, _stability

__all__ = ["readings"]


def readings(q: str, sid: str, runs: dict[str, _Run]) -> list[tuple[str, object, str]]:
    """Alternative readings of quantity ``q``: ``(description, value, unit)`` each, computed.

    ``value`` is a float (in ``unit``), a word, or None when it does not exist in this run.
    """
    if q == "rk45_pair":
        return [("the pair whose nodes equal those of the paper's RK45", rk45_pair(), "")]
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
