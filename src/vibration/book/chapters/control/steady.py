"""The steady-state tail of chapter 7's runs: the last forcing periods of the window, where amplitudes,
RMS forces and powers are measured."""

from __future__ import annotations

import math

#: Forcing periods at the end of the window that count as steady state.
STEADY_PERIODS = 10


def t_steady(t_end: float, omega: float) -> float:
    """Start of the steady-state tail (the last :data:`STEADY_PERIODS` forcing periods), s."""
    return max(0.0, t_end - STEADY_PERIODS * 2.0 * math.pi / omega) if omega > 0 else 0.5 * t_end
