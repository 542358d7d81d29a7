"""Change detection under Monte Carlo: detection and false-alarm trade-offs, and the chapter's fault scenarios."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..checks import check_array, check_oscillator
from ..model import RATE_MAX, RATE_MIN, Oscillator, ParameterError, check_int, check_real
from .experiments import MAX_EXPERIMENT_SAMPLES
from .measurements import MAX_ABS, MIN_SAMPLES, _check_seed, _check_sensor, _grid_size, _signal, _work
from .synthetic import random_force, stiffness_profile, synthetic_measurements
from .tracking import CALIBRATION, CUSUM_DRIFT, DRIFT_MAX, detect_change

__all__ = [
    "THRESHOLDS",
    "DetectionExperiment",
    "FaultScenario",
    "detection_experiment",
    "detection_study",
    "fault_scenario",
]


@dataclass(frozen=True, kw_only=True)
class DetectionExperiment:
    """Seeded healthy and faulty records run through :func:`detect_change`, for many thresholds."""

    thresholds: np.ndarray  # (T,) CUSUM thresholds, 1
    change_time: float  # time the fault starts, s
    monitored: float  # monitored time per record (after calibration), s
    healthy_peak: np.ndarray = field(repr=False)  # (R,) max of the CUSUM over each healthy record
    first_crossing: np.ndarray = field(repr=False)  # (R, T) alarm time of each faulty record (nan: none), s
    drift: float = CUSUM_DRIFT

    @property
    def runs(self) -> int:
        return int(self.healthy_peak.size)

    @property
    def false_alarm_probability(self) -> np.ndarray:
        """(T,) fraction of healthy records that raise an alarm, plus faulty records alarmed before the fault."""
        early = np.nan_to_num(self.first_crossing, nan=np.inf) < self.change_time
        healthy = self.healthy_peak[:, None] > self.thresholds[None, :]
        return (healthy.sum(axis=0) + early.sum(axis=0)) / (2.0 * self.runs)

    @property
    def false_alarm_rate(self) -> np.ndarray:
        """(T,) alarms per hour of healthy monitoring (healthy records only), 1/h."""
        alarms = (self.healthy_peak[:, None] > self.thresholds[None, :]).sum(axis=0)
        return alarms / (self.runs * self.monitored / 3600.0)

    @property
    def false_alarm_rate_upper(self) -> np.ndarray:
        """(T,) one-sided 95 % upper confidence bound of :attr:`false_alarm_rate` (Poisson, exact), 1/h.

        With k alarms in H hours of healthy monitoring: ``chi2.ppf(0.95, 2 k + 2) / (2 H)``; 0 alarms give
        ``-ln(0.05) / H``, about 3 / H.
        """
        from scipy.stats import chi2

        alarms = (self.healthy_peak[:, None] > self.thresholds[None, :]).sum(axis=0)
        hours = self.runs * self.monitored / 3600.0
        return chi2.ppf(0.95, 2 * alarms + 2) / (2.0 * hours)

    @property
    def monitored_hours(self) -> float:
        """Healthy monitoring over all healthy records, h."""
        return self.runs * self.monitored / 3600.0

    @property
    def healthy_max(self) -> float:
        """Largest CUSUM value reached on any healthy record, 1 (the threshold's margin is threshold / this)."""
        return float(np.max(self.healthy_peak))

    @property
    def detection_probability(self) -> np.ndarray:
        """(T,) fraction of faulty records alarmed at or after the fault start."""
        late = np.nan_to_num(self.first_crossing, nan=-np.inf) >= self.change_time
        return late.mean(axis=0)

    @property
    def mean_delay(self) -> np.ndarray:
        """(T,) mean of alarm time minus fault start over the detected faulty records, s (nan: none)."""
        d = self.first_crossing - self.change_time
        d = np.where(d >= 0.0, d, np.nan)
        with np.errstate(invalid="ignore"):
            cnt = np.sum(np.isfinite(d), axis=0)
            return np.where(cnt > 0, np.nansum(d, axis=0) / np.maximum(cnt, 1), np.nan)


def detection_experiment(
    osc: Oscillator,
    t,
    force,
    *,
    stiffness,
    change_time: float,
    noise: float,
    runs: int = 200,
    seed: int = 0,
    thresholds=(10.0, 20.0, 40.0, 80.0),
    drift: float = CUSUM_DRIFT,
    calibration: float = CALIBRATION,
    sensor: str = "x",
    reference=None,
) -> DetectionExperiment:
    """Run :func:`detect_change` on ``runs`` healthy and ``runs`` faulty records (same force, fresh noise).

    Parameters
    ----------
    osc : Oscillator
        Healthy oscillator: m (kg), c (N s/m), k (N/m).
    t, force : array_like
        Sample times (s) and force (N) shared by every record.
    stiffness : array_like
        Stiffness history of the faulty records, N/m (see :func:`stiffness_profile`).
    change_time : float
        When the fault starts, s (after the calibration window).
    noise : float
        Sensor noise standard deviation, m or m/s^2.
    runs : int
        Records of each kind (2 to 10000).
    seed : int
        First noise seed (healthy ``seed + i``, faulty ``seed + runs + i``).
    thresholds : array_like
        CUSUM thresholds to evaluate, 1.
    drift, calibration : float
        As :func:`detect_change`.
    sensor : {"x", "a"}
        Displacement or acceleration.
    reference : optional
        As :func:`detect_change` (None: identified on each record's calibration window).

    Examples
    --------
    >>> t = np.arange(0.0, 120.0, 0.02)
    >>> osc, f = Oscillator(m=1.0, c=0.5, k=20.0), random_force(t)
    >>> ks = stiffness_profile(t, 20.0, 1e9, decline_rate=0.0, drop_time=60.0, drop=0.05)
    >>> ex = detection_experiment(osc, t, f, stiffness=ks, change_time=60.0, noise=2e-3, runs=5, reference=osc,
    ...                           thresholds=[40, 80])
    >>> ex.detection_probability.tolist(), ex.false_alarm_probability.tolist()
    ([1.0, 1.0], [0.0, 0.0])
    """
    t, runs, seed, sensor, change_time, thr, noise, drift, stiffness = _checked_experiment(
        osc, t, runs, seed, sensor, change_time, thresholds, noise, drift, stiffness
    )
    records = (
        synthetic_measurements(osc, t, force, sensor=sensor),
        synthetic_measurements(osc, t, force, sensor=sensor, stiffness=stiffness),
    )
    settings = {"reference": reference, "threshold": float(np.max(thr)), "drift": drift, "calibration": calibration}
    peaks, first, monitored = _monitor_records(t, force, records, noise, runs, seed, thr, sensor, settings)
    return DetectionExperiment(
        thresholds=thr,
        change_time=change_time,
        monitored=monitored,
        healthy_peak=peaks,
        first_crossing=first,
        drift=drift,
    )


def _checked_experiment(osc, t, runs, seed, sensor, change_time, thresholds, noise, drift, stiffness):
    """The arguments of :func:`detection_experiment`, checked in order (ParameterError at the first bad one).

    Returns ``(t, runs, seed, sensor, change_time, thresholds, noise, drift, stiffness)``.
    """
    check_oscillator(osc)
    t = check_array("t", _signal("t", t), low=0.0, ndim=(1,), min_size=MIN_SAMPLES, increasing=True, unit="s")
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    sensor = _check_sensor(sensor)
    _work(
        "runs",
        runs,
        2 * runs * t.size,
        MAX_EXPERIMENT_SAMPLES,
        f"samples to monitor (2 x {runs} runs x {t.size} samples)",
    )
    change_time = check_real("change_time", change_time, low=float(t[0]), high=float(t[-1]), unit="s")
    thr = _signal("thresholds", thresholds) if np.ndim(thresholds) == 1 else None
    if thr is None or np.any(thr <= 0.0):
        raise ParameterError(f"thresholds = {thresholds!r}: allowed a 1-D array of positive numbers")
    noise = check_real("noise", noise, low=0.0, low_open=True, high=MAX_ABS, unit="(sensor units)")
    drift = check_real("drift", drift, low=0.0, low_open=True, high=DRIFT_MAX)
    stiffness = check_array(
        "stiffness", _signal("stiffness", stiffness, t.size), low=osc.m * RATE_MIN**2, high=osc.m * RATE_MAX**2,
        ndim=(1,), unit="N/m",
    )  # fmt: skip
    return t, runs, seed, sensor, change_time, thr, noise, drift, stiffness


def _noisy_statistic(t, force, clean, noise, seed, sensor, settings):
    """CUSUM statistic of :func:`detect_change` on ``clean`` plus seeded noise, and the monitored time (s)."""
    y = clean.response + noise * np.random.default_rng(seed).standard_normal(t.size)
    det = detect_change(t, force, **{sensor: y}, **settings)
    return det.statistic, float(t[-1] - det.calibration_end)


def _first_crossing(t, g, thresholds):
    """(T,) first time the statistic ``g`` exceeds each threshold, s (nan: never)."""
    run_max = np.maximum.accumulate(g)
    idx = np.searchsorted(run_max, thresholds, side="right")
    ok = idx < t.size
    out = np.full(thresholds.size, np.nan)
    out[ok] = t[idx[ok]]
    return out


def _monitor_records(t, force, records, noise, runs, seed, thresholds, sensor, settings):
    """Each healthy record's peak statistic, each faulty record's first crossings, and the monitored time (s).

    Record i draws its noise from seed ``seed + i`` (healthy) and ``seed + runs + i`` (faulty), in that order.
    """
    healthy, faulty = records
    peaks = np.empty(runs)
    first = np.full((runs, thresholds.size), np.nan)
    monitored = math.nan
    for i in range(runs):
        g, monitored = _noisy_statistic(t, force, healthy, noise, seed + i, sensor, settings)
        peaks[i] = float(np.max(g))
        g, monitored = _noisy_statistic(t, force, faulty, noise, seed + runs + i, sensor, settings)
        first[i] = _first_crossing(t, g, thresholds)
    return peaks, first, monitored


# --------------------------------------------------------------------------- chapter scenarios

#: CUSUM thresholds the chapter's trade-off curves run through, 1.
THRESHOLDS = tuple(float(v) for v in np.geomspace(4.0, 400.0, 15))


@dataclass(frozen=True, kw_only=True)
class FaultScenario:
    """The monitored record's stiffness history: decline from ``decline_start``, drop at ``drop_time``."""

    t: np.ndarray  # s
    k: np.ndarray  # true stiffness, N/m
    decline_start: float  # s
    drop_time: float  # s


def _check_window(t_monitor, dt) -> tuple[float, float]:
    """The monitored window (s) and sampling step (s), checked: at least ``MIN_SAMPLES`` samples."""
    t_monitor = check_real("t_monitor", t_monitor, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, unit="s")
    if dt > t_monitor / MIN_SAMPLES:
        raise ParameterError(
            f"dt = {dt!r} s with t_monitor = {t_monitor!r} s gives fewer than {MIN_SAMPLES} samples: allowed dt <= "
            f"t_monitor / {MIN_SAMPLES} (t_monitor >= {MIN_SAMPLES} dt)"
        )
    return t_monitor, dt


def fault_scenario(k: float, t_monitor: float, dt: float, *, decline_rate: float, drop: float) -> FaultScenario:
    """Healthy for the first 40 % of the window, then a slow decline, and a sudden drop at 70 %.

    Parameters
    ----------
    k : float
        Healthy stiffness, N/m.
    t_monitor, dt : float
        Window length and sampling step, s.
    decline_rate : float
        Fraction of k lost per second during the decline, 1/s.
    drop : float
        Fraction of k lost at the drop, 1.

    Examples
    --------
    >>> sc = fault_scenario(20.0, 100.0, 0.5, decline_rate=0.001, drop=0.1)
    >>> sc.decline_start, sc.drop_time, round(float(sc.k[-1]), 3)
    (40.0, 70.0, 16.92)
    """
    t_monitor, dt = _check_window(t_monitor, dt)
    t = np.arange(_grid_size(t_monitor, dt, "t_monitor")) * dt
    start, when = 0.4 * t_monitor, 0.7 * t_monitor
    return FaultScenario(
        t=t,
        k=stiffness_profile(t, k, start, decline_rate=decline_rate, drop_time=when, drop=drop),
        decline_start=start,
        drop_time=when,
    )


def detection_study(
    osc: Oscillator,
    reference,
    t_monitor: float,
    *,
    dt: float,
    noise: float,
    decline_rate: float,
    drop: float,
    runs: int = 100,
    seed: int = 0,
    thresholds=THRESHOLDS,
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
) -> dict[str, DetectionExperiment]:
    """Two seeded detection experiments on ``t_monitor``-long records: a sudden drop alone and a slow decline alone.

    Both faults start at 40 % of the window (after the 25 % calibration). The noise is
    ``noise`` times the rms of the healthy noise-free response (1); the force is a fresh
    band-limited random force (seed ``seed``, band ``band`` in Hz, rms ``rms`` in N).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> st = detection_study(osc, osc, 100.0, dt=0.02, noise=0.01, decline_rate=0.001, drop=0.05, runs=3,
    ...                      thresholds=(40.0,))
    >>> sorted(st), [float(e.detection_probability[0]) for e in st.values()]
    (['slow decline', 'sudden drop'], [1.0, 1.0])
    """
    check_oscillator(osc)
    t_monitor, dt = _check_window(t_monitor, dt)
    noise = check_real("noise", noise, low=0.0, low_open=True, high=10.0)
    decline_rate = check_real("decline_rate", decline_rate, low=0.0, unit="1/s")
    drop = check_real("drop", drop, low=0.0, high=0.9)
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    n = _grid_size(t_monitor, dt, "t_monitor")
    _work("runs", runs, 4 * runs * n, MAX_EXPERIMENT_SAMPLES, f"samples to monitor (2 faults x 2 x {runs} runs x {n})")
    t = np.arange(n) * dt
    start = 0.4 * t_monitor
    force = random_force(t, band=band, rms=rms, seed=seed)
    clean = synthetic_measurements(osc, t, force).x
    sd = noise * float(np.sqrt(np.mean(clean**2)))
    profiles = {
        "sudden drop": stiffness_profile(t, osc.k, start, decline_rate=0.0, drop_time=start, drop=drop),
        "slow decline": stiffness_profile(t, osc.k, start, decline_rate=decline_rate),
    }
    return {
        label: detection_experiment(
            osc,
            t,
            force,
            stiffness=ks,
            change_time=start,
            noise=sd,
            runs=runs,
            seed=seed + 1 + 7919 * j,
            thresholds=thresholds,
            reference=reference,
        )
        for j, (label, ks) in enumerate(profiles.items())
    }
