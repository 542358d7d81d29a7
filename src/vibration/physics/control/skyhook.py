"""The ideal skyhook under base excitation, in closed form: transmissibility and the actuator's mean powers."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, check_real
from ..stability import transmissibility
from ._common import _finite, _omegas

__all__ = ["SkyhookPower", "passive_transmissibility", "skyhook_power", "skyhook_transmissibility"]


def passive_transmissibility(osc: Oscillator, omegas) -> np.ndarray:
    """Base-excitation transmissibility ``|X/Y| = |k + i c w| / |k - m w^2 + i c w|``, 1.

    The absolute displacement of the mass over the base amplitude, in steady state:
    :func:`vibration.physics.stability.transmissibility`, for a scalar or 1-D ``omegas``,
    always as an array.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> float(passive_transmissibility(osc, np.sqrt(40.0)).round(12))   # at sqrt(2) omega_n: 1
    1.0
    """
    check_oscillator(osc)
    return np.asarray(transmissibility(osc, _omegas(omegas)))


def skyhook_transmissibility(osc: Oscillator, c_sky: float, omegas) -> np.ndarray:
    """Ideal-skyhook transmissibility ``|X/Y| = |k + i c w| / |k - m w^2 + i (c + c_sky) w|``, 1.

    The passive spring k and damper c connect the mass to the base ``Y sin(w t)``; the
    skyhook damper ``c_sky`` connects it to the inertial frame (force ``-c_sky v``).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, passive damper to the base), k (N/m).
    c_sky : float
        Skyhook damping, N s/m (>= 0).
    omegas : array_like
        Base frequencies, rad/s (>= 0).

    Returns
    -------
    numpy.ndarray
        Transmissibility, 1, same shape as ``omegas``.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> w = osc.natural_frequency
    >>> round(float(skyhook_transmissibility(osc, 8.0, w)), 4)          # at resonance
    0.5294
    >>> round(float(skyhook_transmissibility(osc, 0.0, w)), 4)          # passive: sqrt(1 + (k/(c w))^2)
    9.0
    """
    check_oscillator(osc)
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    w = _omegas(omegas)
    # divided through by w^2 above 1 rad/s, so that no product overflows
    s = 1.0 / np.maximum(w, 1.0)
    m, c, k, cc = osc.m, osc.c, osc.k, osc.c + c_sky
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        num = np.hypot(k * s * s, c * w * s * s)
        den = np.hypot(k * s * s - m * (w * s) * (w * s), cc * w * s * s)
        out = num / den
    if not np.all(np.isfinite(out)):
        bad = float(np.asarray(w)[~np.isfinite(out)].ravel()[0])
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: the transmissibility is not finite there (undamped resonance or "
            "overflow); allowed frequencies with a finite steady state"
        )
    return out


@dataclass(frozen=True, kw_only=True)
class SkyhookPower:
    """Steady mean powers of the ideal skyhook force ``f = -c_sky v`` under base motion ``Y sin(omega t)``, W."""

    removed: float  # mean c_sky v^2: what the skyhook force takes out of the mass (its work on the mass, negated)
    net: float  # mean f (v - v_b): net power an actuator between body and base delivers (negative: it absorbs)
    supplied: float  # mean of the positive part of f (v - v_b): what the actuator must supply, W
    gross: float  # mean |f (v - v_b)|: the power it exchanges in both directions, W


def skyhook_power(osc: Oscillator, c_sky: float, Y: float, *, omega: float) -> SkyhookPower:
    """Mean steady powers (W) of the ideal skyhook realised by an actuator between the mass and the base.

    With ``x = Im(H Y e^{i omega t})``, ``H = (k + i c omega) / (k - m omega^2 + i (c + c_sky) omega)``,
    the actuator's power ``p = f (v - v_b) = a + b cos(2 omega t + phi)`` has the mean
    ``a = -c_sky (<v^2> - <v v_b>)`` and the swing ``b``; the mean of its positive part is
    ``(a theta + b sin theta) / pi`` with ``cos theta = -a / b`` (``a`` if ``|a| >= b`` and ``a > 0``,
    0 if ``a <= -b``), and the gross exchange ``mean |p| = 2 mean(p+) - a``. The skyhook itself,
    a damper to the inertial frame, removes ``c_sky <v^2>``.

    Examples
    --------
    >>> p = skyhook_power(Oscillator(m=1.0, c=0.5, k=20.0), 8.0, 0.25, omega=20.0**0.5)
    >>> round(p.removed, 4), round(p.net, 4), round(p.supplied, 4), round(p.gross, 4)
    (1.4014, -1.1073, 0.4242, 1.9556)
    """
    check_oscillator(osc)
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    Y = check_real("Y", Y, low=0.0, unit="m")
    w = check_real("omega", omega, low=0.0, unit="rad/s")
    m, c, k = osc.m, osc.c, osc.k
    den = complex(k - m * w * w, (c + c_sky) * w)
    if den == 0:
        raise ParameterError(f"omega = {w!r} rad/s: undamped resonance, no steady state; allowed c + c_sky > 0")
    H = complex(k, c * w) / den
    V = 1j * w * H * Y  # complex velocity amplitude of the mass, m/s
    Vb = 1j * w * Y  # of the base
    F = -c_sky * V  # of the force
    P_rel = F * np.conj(V - Vb)  # p = Re(F e^{iwt}) Re(Vr e^{iwt}) = Re(F conj(Vr))/2 + Re(F Vr e^{2iwt})/2
    a = float(0.5 * P_rel.real)
    b = float(0.5 * abs(F * (V - Vb)))
    if not (math.isfinite(a) and math.isfinite(b)):
        raise ParameterError(
            f"c_sky = {c_sky!r} N s/m, Y = {Y!r} m, omega = {w!r} rad/s overflow the skyhook power: allowed c_sky, Y "
            "and omega whose power c_sky (omega Y)^2 is a finite float"
        )
    if b <= abs(a):
        pos = max(a, 0.0)
    else:
        theta = math.acos(-a / b)
        pos = (a * theta + b * math.sin(theta)) / math.pi
    removed = float(0.5 * c_sky * abs(V) * abs(V))
    out = SkyhookPower(removed=removed, net=a, supplied=pos, gross=2.0 * pos - a)
    _finite("Y, omega", [out.removed, out.net, out.gross], "the skyhook power")
    return out
