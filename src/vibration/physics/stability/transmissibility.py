"""Base excitation: transmissibility, the isolation frequency and the resonance peaks."""

from __future__ import annotations

import math

import numpy as np

from ..checks import check_oscillator
from ..checks import like_input as _out
from ..model import Oscillator
from ._common import _frequencies

# ----------------------------------------------------------------------------- base excitation


def transmissibility(osc: Oscillator, omegas):
    """Displacement transmissibility ``|X/Y|`` under base motion ``y = Y sin(omega t)``.

    ``T = sqrt((1 + (2 zeta r)^2) / ((1 - r^2)^2 + (2 zeta r)^2))``, ``r = omega/omega_n``;
    the same ratio is the force transmissibility ``|F_T / F0|`` of a force on the mass
    to the ground. ``T = 1`` at ``r = sqrt(2)`` for every damping; below it damping lowers
    T, above it damping raises T. Evaluated in scaled form for ``r > 1`` (no overflow);
    ``inf`` at exact undamped resonance. For ``c < 0`` the ratio of the particular
    solution is returned (never reached: the free response grows).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    omegas : float or array_like
        Excitation frequencies, rad/s (finite, >= 0), a scalar or a 1-D array.

    Returns
    -------
    float or numpy.ndarray
        T, dimensionless, same shape as ``omegas``.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> wn = osc.natural_frequency
    >>> np.round(transmissibility(osc, [0.0, wn, np.sqrt(2) * wn, 3 * wn]), 4)
    array([1.    , 9.    , 1.    , 0.1317])
    >>> round(transmissibility(Oscillator(m=1.0, c=15.0, k=20.0), 3 * wn), 4)
    0.7866
    """
    check_oscillator(osc)
    w = _frequencies(omegas)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        r = w / osc.natural_frequency
        b = 2.0 * osc.damping_ratio * r  # 2 zeta r
        low = np.hypot(1.0, b) / np.hypot((1.0 - r) * (1.0 + r), b)
        inv = 1.0 / np.where(r > 1.0, r, 1.0)
        bz = 2.0 * osc.damping_ratio * inv  # (2 zeta r) / r^2
        high = np.hypot(inv * inv, bz) / np.hypot((inv - 1.0) * (inv + 1.0), bz)
        out = np.where(r > 1.0, high, low)
        out = np.where(np.isinf(b) & (r <= 1.0), 1.0, out)  # zeta -> inf below omega_n: T -> 1
    return _out(out, w)


def isolation_frequency(osc: Oscillator) -> float:
    """Frequency above which base motion is attenuated (T < 1) at any damping: ``sqrt(2) omega_n``, rad/s.

    Examples
    --------
    >>> round(isolation_frequency(Oscillator(m=1.0, c=0.5, k=20.0)), 4)     # rad/s
    6.3246
    """
    return math.sqrt(2.0) * check_oscillator(osc).natural_frequency


def _zeta_and_omega_n(osc) -> tuple[float, float]:
    """``(|zeta|, omega_n rad/s)`` of a checked oscillator."""
    check_oscillator(osc)
    return abs(osc.damping_ratio), osc.natural_frequency


def peak_transmissibility(osc: Oscillator) -> tuple[float, float]:
    """Largest transmissibility over frequency and where it occurs: ``(omega_peak rad/s, T_max)``.

    The maximum sits at ``r^2 = 2 / (1 + sqrt(1 + 8 zeta^2))`` (below 1 for every
    ``zeta > 0``, written without cancellation); ``(omega_n, inf)`` when undamped.

    Examples
    --------
    >>> w, t = peak_transmissibility(Oscillator(m=1.0, c=0.5, k=20.0))
    >>> round(w, 4), round(t, 4)          # rad/s, 1
    (4.4583, 9.0137)
    """
    zeta, wn = _zeta_and_omega_n(osc)
    if zeta == 0.0:
        return wn, math.inf
    r = math.sqrt(2.0 / (1.0 + math.sqrt(1.0 + 8.0 * zeta * zeta)))
    return r * wn, float(transmissibility(Oscillator(m=osc.m, c=abs(osc.c), k=osc.k), r * wn))


def peak_magnification(osc: Oscillator) -> tuple[float, float]:
    """Largest force-excited magnification ``|X|/(F0/k)`` and where: ``(omega_peak rad/s, value)``.

    ``1 / (2 zeta sqrt(1 - zeta^2))`` at ``omega_n sqrt(1 - 2 zeta^2)`` when
    ``zeta < 1/sqrt(2)``; otherwise the curve falls from 1 at ``omega = 0``.
    ``(omega_n, inf)`` when undamped; ``|zeta|`` is used when ``c < 0``.

    Examples
    --------
    >>> w, g = peak_magnification(Oscillator(m=1.0, c=0.5, k=20.0))
    >>> round(w, 4), round(g, 4)          # rad/s, 1
    (4.4581, 8.9583)
    >>> peak_magnification(Oscillator(m=1.0, c=15.0, k=20.0))
    (0.0, 1.0)
    """
    zeta, wn = _zeta_and_omega_n(osc)
    if zeta == 0.0:
        return wn, math.inf
    if zeta >= 1.0 / math.sqrt(2.0):
        return 0.0, 1.0
    return wn * math.sqrt((1.0 - zeta * math.sqrt(2.0)) * (1.0 + zeta * math.sqrt(2.0))), 1.0 / (
        2.0 * zeta * math.sqrt((1.0 - zeta) * (1.0 + zeta))
    )
