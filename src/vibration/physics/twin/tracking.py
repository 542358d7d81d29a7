"""Tracking the stiffness (extended Kalman filter) and detecting a change (CUSUM on the reference residual)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..model import Oscillator, ParameterError, check_real
from .identification import Identification, identify
from .measurements import MIN_SAMPLES, _record, _work
from .sampled import _foh, _run

__all__ = [
    "ChangeDetection",
    "cusum_variance_ratio",
    "StiffnessTrack",
    "detect_change",
    "track_stiffness",
]

#: Largest CUSUM drift accepted, in units of the noise variance (a detector that can never alarm beyond it).
DRIFT_MAX = 100.0
#: Default CUSUM drift (in units of the noise variance) and threshold of :func:`detect_change`.
CUSUM_DRIFT = 1.0
CUSUM_THRESHOLD = 40.0

#: Resolution of the stiffness at which the Kalman filter recomputes its exact step, fraction of the reference k.
K_QUANTUM = 1e-5

#: Fraction of a record used to calibrate the detector (and to identify it when no reference is given).
CALIBRATION = 0.25

#: Work budget: samples of one :func:`track_stiffness` (a Python loop).
MAX_TRACK_SAMPLES = 1_000_000


# --------------------------------------------------------------------------- tracking and detection


def _reference(reference, t, force, y, sensor, n_cal, name="reference"):
    """(Oscillator, Identification or None) of the healthy asset."""
    if reference is None:
        fit = identify(t[:n_cal], force[:n_cal], **{sensor: y[:n_cal]})
        return fit.oscillator, fit
    if isinstance(reference, Identification):
        return reference.oscillator, None
    if isinstance(reference, Oscillator):
        return reference, None
    try:
        m, c, k = (float(v) for v in reference)
    except (TypeError, ValueError):
        raise ParameterError(
            f"{name} = {reference!r:.60}: allowed None, an Identification, an Oscillator or (m kg, c N s/m, k N/m)"
        ) from None
    return Oscillator(m=m, c=c, k=k), None


def _calibration(calibration, n):
    calibration = check_real("calibration", calibration, low=0.0, high=0.9, low_open=True)
    n_cal = int(round(calibration * n))
    if n_cal < MIN_SAMPLES or n - n_cal < 2:
        raise ParameterError(
            f"calibration = {calibration!r} leaves {n_cal} calibration samples of {n}: allowed at least "
            f"{MIN_SAMPLES} calibration samples and some to monitor"
        )
    return n_cal


def _reference_output(osc, force, y, h, sensor, n_cal):
    """Output of the reference model with its initial state fitted on the first n_cal samples; and sigma^2."""
    phi, g0, g1 = (v[0] for v in _foh(osc.m, osc.c, osc.k, h))
    row = np.array([1.0, 0.0]) if sensor == "x" else np.array([-osc.k, -osc.c]) / osc.m
    feed = 0.0 if sensor == "x" else 1.0 / osc.m
    forced = _run(phi, g0, g1, row, feed, force, (0.0, 0.0))
    b1 = _run(phi, g0, g1, row, 0.0, np.zeros_like(force), (1.0, 0.0))
    b2 = _run(phi, g0, g1, row, 0.0, np.zeros_like(force), (0.0, 1.0))
    basis = np.column_stack([b1, b2])
    scale = np.sqrt(np.sum(basis[:n_cal] ** 2, axis=0))
    scale[scale == 0.0] = 1.0
    z0, *_ = np.linalg.lstsq(basis[:n_cal] / scale, (y - forced)[:n_cal], rcond=None)
    z0 = z0 / scale
    model = forced + basis @ z0
    r = y - model
    s2 = float(r[:n_cal] @ r[:n_cal]) / max(n_cal - 5, 1)
    return model, s2, z0


def _calibrated_reference(reference, calibration, t, h, force, y, sensor):
    """``(n_cal, osc, model, s2, z0)``: the calibration window's length, the reference and its fitted output."""
    n_cal = _calibration(calibration, t.size)
    osc, _ = _reference(reference, t, force, y, sensor, n_cal)
    return (n_cal, osc, *_reference_output(osc, force, y, h, sensor, n_cal))


@dataclass(frozen=True, kw_only=True)
class StiffnessTrack:
    """Online stiffness estimate: ``t`` (s), ``k`` (N/m) and its standard deviation ``k_std`` (N/m)."""

    t: np.ndarray
    k: np.ndarray
    k_std: np.ndarray
    reference: Oscillator  # m and c held at these values, k started here
    walk: float  # random-walk intensity of k, fraction of k per sqrt(s)
    sigma: float  # sensor noise standard deviation used, m or m/s^2


def track_stiffness(
    t, force, x=None, *, a=None, reference=None, walk: float = 0.02, calibration: float = CALIBRATION
) -> StiffnessTrack:
    """Track the stiffness online with an extended Kalman filter on the augmented state ``(x, v, k)``.

    Why a Kalman filter rather than recursive least squares with forgetting: the
    noise is on the measured response, not on a regressor, so an equation-error
    regression (``m x'' + c x' + k x = F``) would need derivatives (or integrals)
    of the noisy signal and be biased; the filter uses the exact model, works
    the same for displacement and acceleration, and gives a standard deviation
    of ``k`` at every sample. The random walk ``walk`` plays the role of the
    forgetting factor: larger follows faster and is noisier.

    Parameters
    ----------
    t, force, x, a : array_like
        As :func:`identify` (s, N, m or m/s^2).
    reference : Identification, Oscillator, (m, c, k) or None
        Healthy model; m (kg) and c (N s/m) are held, k (N/m) is tracked. None:
        identified on the first ``calibration`` fraction of the record.
    walk : float
        Random-walk intensity of k, fraction of the reference k per sqrt(s) (> 0).
    calibration : float
        Fraction of the record that estimates the noise (and the reference), 1.

    Examples
    --------
    >>> from vibration.physics.twin import random_force, stiffness_profile, synthetic_measurements
    >>> t = np.arange(0.0, 120.0, 0.02)
    >>> ks = stiffness_profile(t, 20.0, 1e9, decline_rate=0.0, drop_time=60.0, drop=0.2)
    >>> meas = synthetic_measurements(Oscillator(m=1.0, c=0.5, k=20.0), t, random_force(t), noise=2e-3, stiffness=ks)
    >>> tr = track_stiffness(**meas, reference=(1.0, 0.5, 20.0))
    >>> round(float(tr.k[t < 60][-1])), round(float(tr.k[-1]))          # N/m
    (20, 16)
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    _work("t", f"{t.size} samples", t.size, MAX_TRACK_SAMPLES, "filter steps (one per sample)")
    walk = check_real("walk", walk, low=0.0, low_open=True, high=1e6, unit="1/sqrt(s)")
    _, osc, _, s2, z0 = _calibrated_reference(reference, calibration, t, h, force, y, sensor)
    r_var = max(s2, 1e-30)
    ks, kstd = _kalman_track(osc, h, force, y, sensor, z0, q=(walk * osc.k) ** 2 * h, r_var=r_var)
    return StiffnessTrack(t=t, k=ks, k_std=kstd, reference=osc, walk=walk, sigma=math.sqrt(r_var))


def _kalman_track(osc, h, force, y, sensor, z0, *, q, r_var):
    """Filtered k (N/m) and its standard deviation (N/m) at every sample, from the state ``z0`` at the first.

    The state ``(x, v, k)`` and its symmetric covariance ``(p00, p01, p02, p11, p12, p22)`` are plain floats
    (the 3 x 3 algebra written out); ``q`` is the random-walk variance of k per step, ``r_var`` the sensor's.
    """
    m, c, k_ref = osc.m, osc.c, osc.k
    n = force.size
    x0, v0 = float(z0[0]), float(z0[1])
    state = (x0, v0, k_ref)
    p = (1e-6 * max(abs(x0), 1e-9) ** 2, 0.0, 0.0, 1e-6 * max(abs(v0), 1e-9) ** 2, 0.0, (0.02 * k_ref) ** 2)
    ks = np.empty(n)
    kstd = np.empty(n)
    fl, yl = force.tolist(), y.tolist()
    quantum = K_QUANTUM * k_ref
    cache: dict[int, tuple] = {}
    for i in range(n):
        state, p = _kalman_update(state, p, m, c, sensor, fl[i], yl[i], r_var, 1e-6 * k_ref)
        ks[i], kstd[i] = state[2], math.sqrt(max(p[5], 0.0))
        if i == n - 1:
            break
        # predict to sample i + 1 with the exact FOH step at the current k (quantised to K_QUANTUM k_ref)
        key = int(round(state[2] / quantum))
        if key not in cache:
            cache[key] = _foh_step(m, c, key * quantum, h)
        state, p = _kalman_predict(state, p, cache[key], fl[i], fl[i + 1], q)
    return ks, kstd


def _foh_step(m, c, k, h):
    """The exact FOH step at stiffness k as plain floats: phi (row by row), then gamma0, then gamma1."""
    phi, g0, g1 = (v[0] for v in _foh(m, c, k, h))
    return (*phi.ravel().tolist(), *g0.tolist(), *g1.tolist())


def _kalman_update(state, p, m, c, sensor, f, y, r_var, k_min):
    """Measurement update of the state and covariance with one sample (force ``f``, measured ``y``); k >= k_min."""
    x_, v_, k_ = state
    p00, p01, p02, p11, p12, p22 = p
    if sensor == "x":
        h0, h1, h2, pred = 1.0, 0.0, 0.0, x_
    else:
        h0, h1, h2 = -k_ / m, -c / m, -x_ / m
        pred = (f - c * v_ - k_ * x_) / m
    ph0 = p00 * h0 + p01 * h1 + p02 * h2
    ph1 = p01 * h0 + p11 * h1 + p12 * h2
    ph2 = p02 * h0 + p12 * h1 + p22 * h2
    sv = h0 * ph0 + h1 * ph1 + h2 * ph2 + r_var
    innov = (y - pred) / sv
    state = (x_ + ph0 * innov, v_ + ph1 * innov, max(k_ + ph2 * innov, k_min))
    p00, p01, p02 = p00 - ph0 * ph0 / sv, p01 - ph0 * ph1 / sv, p02 - ph0 * ph2 / sv
    p11, p12, p22 = p11 - ph1 * ph1 / sv, p12 - ph1 * ph2 / sv, p22 - ph2 * ph2 / sv
    return state, (p00, p01, p02, p11, p12, p22)


def _kalman_predict(state, p, mats, f0, f1, q):
    """Prediction of the state and covariance over one step (``mats`` of :func:`_foh_step`, forces f0 then f1)."""
    x_, v_, k_ = state
    p00, p01, p02, p11, p12, p22 = p
    f00, f01, f10, f11, a0, a1, b0, b1 = mats
    xn = f00 * x_ + f01 * v_ + a0 * f0 + b0 * f1
    vn = f10 * x_ + f11 * v_ + a1 * f0 + b1 * f1
    s0, s1 = -(a0 * x_ + b0 * xn), -(a1 * x_ + b1 * xn)  # d(x, v)[i+1] / dk, the -k x term held linear
    q00 = f00 * p00 + f01 * p01 + s0 * p02
    q01 = f00 * p01 + f01 * p11 + s0 * p12
    q02 = f00 * p02 + f01 * p12 + s0 * p22
    q10 = f10 * p00 + f11 * p01 + s1 * p02
    q11 = f10 * p01 + f11 * p11 + s1 * p12
    q12 = f10 * p02 + f11 * p12 + s1 * p22
    p00 = q00 * f00 + q01 * f01 + q02 * s0
    p01 = q00 * f10 + q01 * f11 + q02 * s1
    p11 = q10 * f10 + q11 * f11 + q12 * s1
    return (xn, vn, k_), (p00, p01, q02, p11, q12, p22 + q)


@dataclass(frozen=True, kw_only=True)
class ChangeDetection:
    """CUSUM on the normalised squared residual of the reference model.

    ``alarm_time`` (s) is None when the statistic never crosses the threshold.
    """

    alarm_time: float | None  # first time the CUSUM exceeds the threshold, s
    alarm_index: int | None  # its sample index
    change_time: float | None  # estimated onset: the last restart of the CUSUM before the alarm, s
    t: np.ndarray = field(repr=False)  # time, s
    statistic: np.ndarray = field(repr=False)  # CUSUM g_n, 1 (0 on the calibration window)
    residual: np.ndarray = field(repr=False)  # measured minus reference model, m or m/s^2
    threshold: float = CUSUM_THRESHOLD  # alarm level of g, 1
    drift: float = CUSUM_DRIFT  # allowance subtracted from r^2/sigma^2 - 1, 1
    sigma: float = math.nan  # noise standard deviation from the calibration window, m or m/s^2
    reference: Oscillator | None = None  # healthy model
    calibration_end: float = math.nan  # end of the calibration window, s


def cusum_variance_ratio(drift: float) -> float:
    """The residual-variance ratio rho the CUSUM of :func:`detect_change` is the optimal (likelihood-ratio) test for.

    For Gaussian residuals whose variance goes from sigma^2 to rho sigma^2, the log-likelihood ratio of
    one sample is ``((1 - 1/rho) u - ln rho) / 2`` with ``u = r^2 / sigma^2``: proportional to
    ``u - ln rho / (1 - 1/rho)``. The detector's increment ``u - 1 - drift`` is that with
    ``ln rho / (1 - 1/rho) = 1 + drift``; this solves it for rho (> 1).

    Examples
    --------
    >>> round(cusum_variance_ratio(1.0), 3), round(cusum_variance_ratio(2 * math.log(2) - 1), 6)
    (4.922, 2.0)
    """
    from scipy.optimize import brentq

    drift = check_real("drift", drift, low=0.0, low_open=True, high=DRIFT_MAX)

    def f(rho):
        return math.log(rho) / (1.0 - 1.0 / rho) - 1.0 - drift

    return float(brentq(f, 1.0 + 1e-12, 1e60, xtol=1e-14, rtol=1e-14))


def _cusum(z):
    s = np.cumsum(z)
    return s - np.minimum(np.minimum.accumulate(s), 0.0)


def detect_change(
    t,
    force,
    x=None,
    *,
    a=None,
    reference=None,
    threshold: float = CUSUM_THRESHOLD,
    drift: float = CUSUM_DRIFT,
    calibration: float = CALIBRATION,
) -> ChangeDetection:
    """Raise an alarm when the asset stops behaving like its reference model.

    Statistic: the output-error residual ``r = y - y_ref`` of the reference model
    driven by the measured force (its initial state and the noise variance
    ``sigma^2`` fitted on the first ``calibration`` fraction of the record, taken
    as healthy). Under no change ``r`` is white with variance ``sigma^2``; a change
    of m, c or k adds the response difference to it. The one-sided CUSUM
    ``g[n] = max(0, g[n-1] + r[n]^2 / sigma^2 - 1 - drift)`` starts at the end of
    the calibration window; the alarm is the first ``g > threshold``. The drift
    tunes it to a residual-variance ratio rho with ``ln rho / (1 - 1/rho) = 1 + drift``
    (:func:`cusum_variance_ratio`; ``drift = 1``: rho = 4.92, not a doubling); the
    threshold sets the false alarm rate (measured in the chapter).

    Parameters
    ----------
    t, force, x, a : array_like
        As :func:`identify` (s, N, m or m/s^2).
    reference : Identification, Oscillator, (m, c, k) or None
        Healthy model (kg, N s/m, N/m). None: identified on the calibration window.
    threshold : float
        Alarm level of the CUSUM, 1 (> 0).
    drift : float
        Allowance per sample, in units of the noise variance, 1 (> 0).
    calibration : float
        Fraction of the record taken as healthy, 1 (0 to 0.9).

    Returns
    -------
    ChangeDetection
        ``alarm_time`` (s, or None), the estimated onset ``change_time`` (s), the
        statistic, the residual and the settings.

    Examples
    --------
    >>> from vibration.physics.twin import random_force, stiffness_profile, synthetic_measurements
    >>> t = np.arange(0.0, 200.0, 0.02)
    >>> osc, f = Oscillator(m=1.0, c=0.5, k=20.0), random_force(t, seed=4)
    >>> ks = stiffness_profile(t, 20.0, 1e9, decline_rate=0.0, drop_time=120.0, drop=0.05)
    >>> healthy = detect_change(**synthetic_measurements(osc, t, f, noise=2e-3, seed=5))
    >>> faulty = detect_change(**synthetic_measurements(osc, t, f, noise=2e-3, seed=5, stiffness=ks))
    >>> healthy.alarm_time is None, 120.0 < faulty.alarm_time < 125.0         # s
    (True, True)
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    threshold = check_real("threshold", threshold, low=0.0, low_open=True)
    drift = check_real("drift", drift, low=0.0, low_open=True, high=DRIFT_MAX)
    n_cal, osc, model, s2, _ = _calibrated_reference(reference, calibration, t, h, force, y, sensor)
    r = y - model
    s2 = max(s2, 1e-300)
    g = np.zeros(t.size)
    g[n_cal:] = _cusum(r[n_cal:] ** 2 / s2 - 1.0 - drift)
    alarm, onset = _first_alarm(t, g, threshold, n_cal)
    return ChangeDetection(
        alarm_time=float(t[alarm]) if alarm is not None else None,
        alarm_index=alarm,
        change_time=onset,
        t=t,
        statistic=g,
        residual=r,
        threshold=threshold,
        drift=drift,
        sigma=math.sqrt(s2),
        reference=osc,
        calibration_end=float(t[n_cal]),
    )


def _first_alarm(t, g, threshold, n_cal):
    """Index of the first ``g > threshold`` and the estimated onset (s): the CUSUM's last restart before it."""
    over = np.nonzero(g > threshold)[0]
    if not over.size:
        return None, None
    alarm = int(over[0])
    zeros = np.nonzero(g[n_cal:alarm] == 0.0)[0]
    return alarm, float(t[n_cal + zeros[-1] + 1]) if zeros.size else float(t[n_cal])
