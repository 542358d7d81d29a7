"""Exact landmarks of the magnification curve: the half-power band and the resonant peak."""

from __future__ import annotations

import math

from ..model import Oscillator

__all__ = ["half_power_band", "resonant_peak"]


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
