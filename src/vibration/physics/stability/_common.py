"""Shared input checks of the stability package."""

from __future__ import annotations

import numpy as np

from ..checks import check_array
from ..model import N_POINTS_MAX, Oscillator, ParameterError


def _check_stable(osc: Oscillator, what: str) -> None:
    if not osc.c > 0.0:
        raise ParameterError(
            f"c = {osc.c!r} N s/m is out of range: allowed c > 0 N s/m ({what} exists only for an "
            "asymptotically stable oscillator)"
        )


def _frequencies(omegas, name: str = "omegas") -> np.ndarray:
    return check_array(name, omegas, low=0.0, ndim=(0, 1), unit="rad/s")


def _times(t, name: str = "t", max_size: int = N_POINTS_MAX) -> np.ndarray:
    return check_array(name, t, low=0.0, ndim=(0, 1), max_size=max_size, unit="s")
