"""Cost and design: the damper's load under harmonic force and one point of the design trade-off."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, check_real
from ._common import _frequencies
from .poles import stability_class
from .random_load import white_noise_variance
from .step import step_metrics
from .transmissibility import peak_magnification, transmissibility

# ----------------------------------------------------------------------------- cost and design


@dataclass(frozen=True, kw_only=True)
class DamperLoad:
    """Steady-state load on the damper under ``F0 sin(omega t)`` on the mass."""

    omega: np.ndarray  # forcing frequencies, rad/s
    amplitude: np.ndarray  # displacement amplitude |X|, m
    force_amplitude: np.ndarray  # damper force amplitude c omega |X|, N
    mean_power: np.ndarray  # mean power the damper dissipates, c omega^2 |X|^2 / 2, W


def damper_load(osc: Oscillator, F0: float, omegas) -> DamperLoad:
    """Damper force amplitude and mean dissipated power in the steady state, at each omega.

    ``|X| = F0 / sqrt((k - m omega^2)^2 + (c omega)^2)``, damper force ``c omega |X|``
    (N), mean power ``c omega^2 |X|^2 / 2`` (W), equal to the mean power the force
    delivers. At ``omega = omega_n`` the damper force equals F0 for every c (it balances
    the applied force) and the power is ``F0^2 / (2 c)``: at resonance less damping
    dissipates more power, through a larger velocity.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, >= 0), k (N/m).
    F0 : float
        Force amplitude, N (>= 0).
    omegas : float or array_like
        Forcing frequencies, rad/s (>= 0).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> d = damper_load(osc, 5.0, [3.0, osc.natural_frequency])
    >>> np.round(d.force_amplitude, 4), np.round(d.mean_power, 4)     # N, W
    (array([0.6756, 5.    ]), array([ 0.4564, 25.    ]))
    """
    check_oscillator(osc)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    if osc.c < 0.0:
        raise ParameterError(f"c = {osc.c!r} N s/m is out of range: allowed c >= 0 N s/m (a damper dissipates)")
    w = _frequencies(omegas)
    wn = osc.natural_frequency
    with np.errstate(all="ignore"):  # a non-finite result is refused below
        amp = F0 / np.hypot(osc.m * (wn - w) * (wn + w), osc.c * w)
        force = osc.c * w * amp
        if osc.c == 0.0:
            force = np.zeros_like(w)
        power = 0.5 * force * w * amp
        power = np.where(force == 0.0, 0.0, power)
    if not (np.all(np.isfinite(amp)) and np.all(np.isfinite(power))):
        bad = float(w[~(np.isfinite(amp) & np.isfinite(power))].ravel()[0])
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: with c = {osc.c!r} N s/m and F0 = {F0!r} N the steady amplitude there "
            "is not finite (undamped resonance or overflow); allowed frequencies and F0 with a finite steady state"
        )
    return DamperLoad(omega=w, amplitude=amp, force_amplitude=force, mean_power=power)


@dataclass(frozen=True, kw_only=True)
class DesignMetrics:
    """One damping on the three axes of the trade-off, plus its random response.

    A field is ``None`` where the quantity does not exist for this damping (see
    :func:`design_metrics`).
    """

    c: float  # damping coefficient, N s/m
    zeta: float  # damping ratio, 1
    peak_magnification: float | None  # largest |X|/(F0/k) under force on the mass, 1; None if c <= 0
    isolation_ratio: float  # r = omega / omega_n where isolation is judged, 1
    transmissibility: float | None  # steady |X/Y| under base motion at that r, 1; None if c < 0
    overshoot: float | None  # step overshoot, fraction; 1 if c = 0, None if c < 0
    settling_time: float | None  # step 2 % settling time, s; None if c <= 0
    rms_per_sqrt_S0: float | None  # sqrt(pi / (k c)), m / sqrt(N^2 s/rad); None if c <= 0
    stability: str  # verdict of stability_class


def design_metrics(osc: Oscillator, isolation_ratio: float = 3.0, band: float = 0.02) -> DesignMetrics:
    """The damping's place on the trade-off: resonant peak, isolation at ``r``, step settling.

    Any sign of c. Where a quantity does not exist the field is ``None``:

    * ``c = 0``: no finite resonant peak (a force at ``omega_n`` grows the response like
      t), no settling (the step response ``1 - cos omega_n t`` oscillates for ever, its
      overshoot is exactly 1) and no stationary random response (the variance grows
      like t); the steady transmissibility ``1/|1 - r^2|`` exists away from ``r = 1``.
    * ``c < 0``: no steady state at all (every free motion grows), so none of the
      quantities exists.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).
    isolation_ratio : float
        Frequency ratio ``omega / omega_n`` at which the transmissibility is taken (> 0).
    band : float
        Settling band of the step response (fraction).

    Examples
    --------
    >>> d = design_metrics(Oscillator(m=1.0, c=15.0, k=20.0))
    >>> round(d.peak_magnification, 3), round(d.transmissibility, 4), round(d.settling_time, 3)
    (1.0, 0.7866, 2.723)
    >>> d = design_metrics(Oscillator(m=1.0, c=0.0, k=20.0))
    >>> d.peak_magnification, round(d.transmissibility, 12), d.overshoot, d.settling_time, d.stability
    (None, 0.125, 1.0, None, 'marginally stable')
    """
    check_oscillator(osc)
    isolation_ratio = check_real("isolation_ratio", isolation_ratio, low=0.0, low_open=True)
    verdict = stability_class(osc).verdict
    t_r = float(transmissibility(osc, isolation_ratio * osc.natural_frequency))
    if osc.c > 0.0:
        step = step_metrics(osc, band)
        return DesignMetrics(
            c=osc.c,
            zeta=osc.damping_ratio,
            peak_magnification=peak_magnification(osc)[1],
            isolation_ratio=isolation_ratio,
            transmissibility=t_r,
            overshoot=step.overshoot,
            settling_time=step.settling_time,
            rms_per_sqrt_S0=math.sqrt(white_noise_variance(osc, 1.0)),
            stability=verdict,
        )
    undamped = osc.c == 0.0
    return DesignMetrics(
        c=osc.c,
        zeta=osc.damping_ratio,
        peak_magnification=None,
        isolation_ratio=isolation_ratio,
        transmissibility=t_r if undamped and math.isfinite(t_r) else None,
        overshoot=1.0 if undamped else None,
        settling_time=None,
        rms_per_sqrt_S0=None,
        stability=verdict,
    )
