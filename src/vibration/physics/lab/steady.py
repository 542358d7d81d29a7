"""Steadiness of a driven run by its late drift, and the time it takes to reach 90 % of its final amplitude."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.physics.lab._checks import time_and_signal
from vibration.physics.model import ParameterError, check_real

#: Steps per drive period of the sliding one-period window used for t90.
T90_STEPS = 8


@dataclass(frozen=True, kw_only=True)
class Steadiness:
    """Late drift of a driven run.

    Attributes
    ----------
    steady : bool
        ``|drift| <= tolerance`` or ``|drift| <= 2 drift_stderr``.
    drift : float
        Relative change of the one-harmonic amplitude from the first to the last of the final
        ``periods`` drive periods.
    drift_stderr : float
        Its standard error (least squares of the two one-period fits).
    t90 : float
        Time (s, from the start of the record) at the centre of the first one-period window whose
        amplitude reaches 90 % of the final one.
    amplitude : float
        One-harmonic amplitude over the final ``periods`` periods (rad).
    amplitude_stderr : float
        Its standard error (rad).
    periods : int
        Periods of the late window; ``tolerance`` the relative tolerance used.
    """

    steady: bool
    drift: float
    drift_stderr: float
    t90: float
    amplitude: float
    amplitude_stderr: float
    periods: int
    tolerance: float


def _harmonic(t, y, omega):
    X = np.column_stack([np.sin(omega * t), np.cos(omega * t), np.ones_like(t), t - t.mean()])
    coef, *_ = np.linalg.lstsq(X, y, rcond=None)
    r = y - X @ coef
    dof = max(1, t.size - X.shape[1])
    cov = float(r @ r) / dof * np.linalg.pinv(X.T @ X)
    a = math.hypot(coef[0], coef[1])
    if a > 0:
        g = np.array([coef[0] / a, coef[1] / a, 0.0, 0.0])
        se = math.sqrt(max(float(g @ cov @ g), 0.0))
    else:
        se = math.sqrt(max(cov[0, 0], 0.0))
    return a, se


def steadiness(t, theta, omega, *, periods: int = 3, tolerance: float = 0.02) -> Steadiness:
    """Whether a driven run is steady by its drift over its last drive periods.

    One harmonic at the drive frequency (with an offset and a linear trend of the centre) is fitted by
    least squares to the first and to the last of the final ``periods`` whole drive periods; the drift
    is the relative change of its amplitude. ``t90`` comes from one-period windows slid over the
    record in steps of an eighth of a period.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing.
    theta : array_like
        Wheel angle (rad).
    omega : float
        Drive angular frequency (rad/s), > 0.
    periods : int
        Final drive periods considered, 2 to 100 (the record must hold at least that many).
    tolerance : float
        Largest relative drift of a steady run, in (0, 1).

    Returns
    -------
    Steadiness

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0.0, 30.0, 0.05)
    >>> s = steadiness(t, (1.0 - np.exp(-t / 2.0)) * np.sin(4.0 * t), 4.0)
    >>> s.steady, round(s.t90, 1)
    (True, 4.7)
    """
    ta, ya = time_and_signal(t, theta, t_name="t", y_name="theta", y_unit="rad")
    omega, periods, tolerance, period = _checked_drive(ta, omega, periods, tolerance)
    t_end = float(ta[-1])
    (a1, s1), (a2, s2) = _end_periods(ta, ya, omega, periods, period)
    if a1 <= 0:
        raise ParameterError("theta has no oscillation at the drive frequency: allowed a driven run")
    drift = (a2 - a1) / a1
    drift_se = math.hypot(s2 / a1, a2 * s1 / a1**2)
    late = ta >= t_end - periods * period - 1e-9
    amp, amp_se = _harmonic(ta[late], ya[late], omega)
    t90 = _t90(ta, ya, omega, period, a2)
    steady = bool(abs(drift) <= tolerance or abs(drift) <= 2.0 * drift_se)
    return Steadiness(
        steady=steady,
        drift=float(drift),
        drift_stderr=float(drift_se),
        t90=float(t90),
        amplitude=float(amp),
        amplitude_stderr=float(amp_se),
        periods=int(periods),
        tolerance=float(tolerance),
    )


def _checked_drive(ta, omega, periods, tolerance):
    """The options of :func:`steadiness`, checked in order: ``(omega, periods, tolerance, drive period in s)``."""
    omega = check_real("omega", omega, low=0.0, low_open=True, high=1e4, unit="rad/s")
    if isinstance(periods, bool) or not isinstance(periods, (int, np.integer)) or not 2 <= periods <= 100:
        raise ParameterError(f"periods = {periods!r} is out of range: allowed an integer 2 <= periods <= 100")
    tolerance = check_real("tolerance", tolerance, low=0.0, low_open=True, high=0.999)
    period = 2.0 * math.pi / omega
    if ta[-1] - ta[0] < periods * period:
        raise ParameterError(
            f"t spans {ta[-1] - ta[0]:g} s, fewer than periods = {periods} drive periods of omega = {omega!r} rad/s "
            f"({periods * period:g} s): allowed omega >= {2.0 * math.pi * periods / (ta[-1] - ta[0]):.6g} rad/s "
            "for this record, or a longer record"
        )
    return omega, periods, tolerance, period


def _end_periods(ta, ya, omega, periods, period):
    """``[(amplitude, stderr)]`` of the first and of the last of the final ``periods`` drive periods."""
    t_end = float(ta[-1])
    windows = []
    for start in (t_end - periods * period, t_end - period):
        m = (ta >= start - 1e-9) & (ta <= start + period + 1e-9)
        if np.count_nonzero(m) < 6:
            raise ParameterError(
                f"omega = {omega!r} rad/s is out of range: a drive period holds fewer than 6 samples of t"
            )
        windows.append(_harmonic(ta[m], ya[m], omega))
    return windows


def _t90(ta, ya, omega, period, final):
    """Centre (s, from the record's start) of the first one-period window whose amplitude reaches 0.9 ``final``.

    The windows slide in steps of ``period / T90_STEPS``; the last time ``ta[-1]`` (s) when none does.
    """
    t_end = float(ta[-1])
    step = period / T90_STEPS
    n_steps = int((t_end - period - ta[0]) / step) + 1
    for i in range(max(n_steps, 0)):
        s0 = float(ta[0]) + i * step
        m = (ta >= s0) & (ta <= s0 + period)
        if np.count_nonzero(m) < 6:
            continue
        if _harmonic(ta[m], ya[m], omega)[0] >= 0.9 * final:
            return s0 + 0.5 * period - float(ta[0])
    return t_end
