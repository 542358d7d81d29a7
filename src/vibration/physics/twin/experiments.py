"""Monte Carlo experiments: coverage of the intervals, error scaling, detection trade-offs, fault scenarios."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..checks import check_array
from ..model import RATE_MAX, RATE_MIN, Oscillator, ParameterError, check_int, check_real
from .identification import identify
from .measurements import MAX_ABS, MIN_SAMPLES, _check_osc, _check_seed, _check_sensor, _grid_size, _signal, _work
from .sampled import random_force, stiffness_profile, synthetic_measurements
from .tracking import CALIBRATION, CUSUM_DRIFT, DRIFT_MAX, detect_change
from .validation import (
    WHITENESS_LAGS,
    _ar1,
    binomial_halfwidth,
    cubic_response,
    input_correlation,
    ljung_box,
    predicted_coverage,
)

__all__ = [
    "ASSUMPTION_CASES",
    "AssumptionStudy",
    "CoverageExperiment",
    "DetectionExperiment",
    "EstimateGrid",
    "FaultScenario",
    "THRESHOLDS",
    "assumption_study",
    "detection_experiment",
    "detection_study",
    "estimate_grid",
    "fault_scenario",
    "identification_experiment",
    "identification_sweep",
]

#: Work budget: samples simulated and identified (or monitored) by one Monte Carlo experiment, all its
#: records together.
MAX_EXPERIMENT_SAMPLES = 20_000_000


# --------------------------------------------------------------------------- Monte Carlo experiments


@dataclass(frozen=True, kw_only=True)
class CoverageExperiment:
    """Repeated identification of one oscillator from noisy records (seeded), with the residual tests of each run."""

    truth: np.ndarray  # (3,) m (kg), c (N s/m), k (N/m)
    estimates: np.ndarray  # (R, 3)
    stderr: np.ndarray  # (R, 3)
    ci95: np.ndarray  # (R, 3, 2)
    noise: float  # noise standard deviation / rms of the noise-free response, 1
    duration: float  # record length, s
    dt: float  # sampling step, s
    sensor: str  # "x" or "a"
    whiteness_p: np.ndarray | None = field(default=None, repr=False)  # (R,) Ljung-Box p-value of each residual
    input_p: np.ndarray | None = field(default=None, repr=False)  # (R,) p-value of the residual-force correlation
    case: str = "as assumed"  # which assumption the records break
    alpha: float = 0.05  # level of the residual tests, 1

    @property
    def runs(self) -> int:
        return int(self.estimates.shape[0])

    @property
    def covered(self) -> np.ndarray:
        """(R, 3) whether each 95 % interval contains the truth."""
        return (self.ci95[:, :, 0] <= self.truth) & (self.truth <= self.ci95[:, :, 1])

    @property
    def coverage(self) -> np.ndarray:
        """(3,) fraction of the 95 % intervals that contain the truth."""
        return self.covered.mean(axis=0)

    @property
    def coverage_halfwidth(self) -> np.ndarray:
        """(3,) 95 % binomial half-width of the coverage for R runs at 0.95 (1.96 sqrt(0.95 * 0.05 / R))."""
        return np.full(3, 1.96 * math.sqrt(0.95 * 0.05 / self.runs))

    @property
    def coverage_uncertainty(self) -> np.ndarray:
        """(3,) half-width of the Wilson 95 % interval of each measured coverage, 1."""
        return binomial_halfwidth(self.covered.sum(axis=0), self.runs)

    def flagged(self, which: str = "whiteness") -> float:
        """Share of runs whose residual test (``"whiteness"`` or ``"input"``) rejects at ``alpha``, 1 (nan: not run)."""
        p = self.whiteness_p if which == "whiteness" else self.input_p
        return math.nan if p is None else float(np.mean(p < self.alpha))

    def flagged_uncertainty(self, which: str = "whiteness") -> float:
        """Wilson 95 % half-width of :meth:`flagged`, 1."""
        share = self.flagged(which)
        return math.nan if math.isnan(share) else float(binomial_halfwidth(round(share * self.runs), self.runs))

    @property
    def rel_rmse(self) -> np.ndarray:
        """(3,) root-mean-square relative error of m, c, k, 1."""
        return np.sqrt(np.mean(((self.estimates - self.truth) / self.truth) ** 2, axis=0))

    @property
    def rel_bias(self) -> np.ndarray:
        """(3,) mean relative error of m, c, k, 1."""
        return np.mean((self.estimates - self.truth) / self.truth, axis=0)

    @property
    def rel_stderr(self) -> np.ndarray:
        """(3,) root-mean-square of the reported relative standard errors, 1."""
        return np.sqrt(np.mean((self.stderr / self.truth) ** 2, axis=0))


def _noise_rng(seed: int, stream: int, run: int) -> np.random.Generator:
    """Independent generator per (experiment seed, stream, run): a SeedSequence of the three integers."""
    return np.random.default_rng([seed, stream, run])


def _monte_carlo(truth, t, force, clean, sd, runs, seed, stream, sensor, *, force_sd=0.0, colour=0.0, lags):
    """Identify ``runs`` noisy copies of one record; each run draws its own noise (see :func:`_noise_rng`)."""
    est = np.empty((runs, 3))
    se = np.empty((runs, 3))
    ci = np.empty((runs, 3, 2))
    white = np.empty(runs)
    inp = np.empty(runs)
    for i in range(runs):
        rng = _noise_rng(seed, stream, i)
        y = clean + sd * _ar1(t.size, colour, rng)
        f = force + force_sd * rng.standard_normal(t.size) if force_sd > 0.0 else force
        fit = identify(t, f, **{sensor: y}, search="local")
        est[i] = (fit.m, fit.c, fit.k)
        se[i] = fit.stderr
        ci[i] = fit.ci95
        white[i] = ljung_box(fit.residual, lags)[1]
        inp[i] = input_correlation(fit.residual, f, lags)[1]
    return est, se, ci, white, inp


def identification_experiment(
    osc: Oscillator,
    *,
    duration: float = 60.0,
    dt: float = 0.02,
    noise: float = 0.05,
    runs: int = 200,
    seed: int = 0,
    sensor: str = "x",
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
    stream: int = 0,
    lags: int = WHITENESS_LAGS,
) -> CoverageExperiment:
    """Identify ``osc`` from ``runs`` records that differ only in their noise (seeded).

    One band-limited random force (seed ``seed``) drives the oscillator from
    rest; every run adds fresh white Gaussian noise of standard deviation ``noise`` times the rms
    of the noise-free response, drawn from its own generator (seeded by ``(seed, stream, run)``,
    so experiments with different ``stream`` share no draws), and :func:`identify`
    (``search="local"``) estimates m, c, k and their intervals; the residual of each fit goes
    through the Ljung-Box and input-correlation tests.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    duration : float
        Record length, s.
    dt : float
        Sampling step, s.
    noise : float
        Noise standard deviation relative to the rms response, 1 (> 0).
    runs : int
        Realisations (2 to 10000).
    seed : int
        Seed of the force and of the noise.
    sensor : {"x", "a"}
        Displacement or acceleration.
    band : (float, float)
        Force band, Hz.
    rms : float
        Force rms, N.
    stream : int
        Noise stream, 1 (>= 0): experiments sharing ``seed`` draw independent noise when it differs.
    lags : int
        Lags of the residual tests, samples.

    Examples
    --------
    >>> ex = identification_experiment(Oscillator(m=1.0, c=0.5, k=20.0), duration=20.0, runs=20)
    >>> ex.estimates.shape, bool(np.all(ex.coverage >= 0.8))
    ((20, 3), True)
    """
    _check_osc(osc)
    duration = check_real("duration", duration, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, high=duration / MIN_SAMPLES, unit="s")
    noise = check_real("noise", noise, low=0.0, low_open=True, high=10.0)
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    stream = check_int("stream", stream, low=0, high=2**31)
    sensor = _check_sensor(sensor)
    n = _grid_size(duration, dt)
    lags = check_int("lags", lags, low=1, high=n // 4)
    _work("runs", runs, runs * n, MAX_EXPERIMENT_SAMPLES, f"samples to identify ({runs} runs x {n} samples)")
    t = np.arange(n) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    clean = synthetic_measurements(osc, t, force, sensor=sensor).response
    sd = noise * float(np.sqrt(np.mean(clean**2)))
    est, se, ci, white, inp = _monte_carlo(
        np.array([osc.m, osc.c, osc.k]), t, force, clean, sd, runs, seed, stream, sensor, lags=lags
    )
    truth = np.array([osc.m, osc.c, osc.k])
    return CoverageExperiment(
        truth=truth,
        estimates=est,
        stderr=se,
        ci95=ci,
        noise=noise,
        duration=float(t[-1]),
        dt=dt,
        sensor=sensor,
        whiteness_p=white,
        input_p=inp,
    )


# --------------------------------------------------------------------------- violated assumptions

#: The records of :func:`assumption_study`: label -> (force noise, response noise, colour, cubic), each a
#: multiplier of the study's arguments of the same name (1: use it, 0: leave it out).
ASSUMPTION_CASES = {
    "noise on the force": (1.0, 0.0, 0.0, 0.0),
    "noise on both channels": (1.0, 1.0, 0.0, 0.0),
    "coloured sensor noise": (0.0, 1.0, 1.0, 0.0),
    "unmodelled cubic spring": (0.0, 1.0, 0.0, 1.0),
}


@dataclass(frozen=True, kw_only=True)
class AssumptionStudy:
    """Coverage and residual tests when the records break one assumption at a time (one experiment per case)."""

    experiments: dict  # label -> CoverageExperiment (the as-assumed case first)
    predicted: dict  # label -> (3,) first-order coverage of m, c, k, or None where no prediction applies
    force_noise: float  # force-noise standard deviation / rms force, 1
    noise: float  # response-noise standard deviation / rms response, 1
    colour: float  # lag-one correlation of the coloured sensor noise, 1
    cubic: float  # k3 x_rms^2 / k of the cubic spring, 1
    k3: float  # the cubic coefficient that gives it, N/m^3
    lags: int  # lags of the residual tests, samples


def assumption_study(
    osc: Oscillator,
    reference: CoverageExperiment,
    *,
    force_noise: float = 0.05,
    colour: float = 0.9,
    cubic: float = 0.05,
    runs: int = 60,
    seed: int = 0,
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
) -> AssumptionStudy:
    """Coverage of the intervals, and how often the residual tests flag the record, under violated assumptions.

    Each case of :data:`ASSUMPTION_CASES` uses the design of ``reference`` (its record length,
    step, noise level and sensor; the force of seed ``seed``) and breaks one assumption: white
    noise of ``force_noise`` times the rms force on the measured force (alone, then with the
    response noise), AR(1) sensor noise of lag-one correlation ``colour`` (same marginal standard
    deviation), or a cubic spring ``k3 x^3`` with ``k3 x_rms^2 = cubic k`` (x_rms of the linear
    response). Every case draws its own noise (stream 1000 + case). The as-assumed case is
    ``reference`` itself; the white and coloured cases also get the first-order coverage of
    :func:`predicted_coverage`.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    reference : CoverageExperiment
        The as-assumed experiment (:func:`identification_experiment`, displacement sensor).
    force_noise : float
        Force-noise standard deviation over the rms force, 1 (0 < value <= 1).
    colour : float
        Lag-one correlation of the coloured noise, 1 (0 < value <= 0.99).
    cubic : float
        Cubic force over linear force at the rms displacement, 1 (0 < value <= 1).
    runs : int
        Realisations per violated case (2 to 10000).
    seed : int
        Seed of the force (as the reference's) and of the noise.
    band, rms
        Force band (Hz) and rms (N), as the reference's.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> ref = identification_experiment(osc, duration=20.0, runs=4)
    >>> st = assumption_study(osc, ref, runs=3)
    >>> list(st.experiments)[:2], st.experiments["coloured sensor noise"].flagged()
    (['as assumed', 'noise on the force'], 1.0)
    """
    _check_osc(osc)
    if not isinstance(reference, CoverageExperiment) or reference.sensor != "x":
        raise ParameterError(f"reference = {reference!r:.60}: allowed a displacement CoverageExperiment")
    force_noise = check_real("force_noise", force_noise, low=0.0, low_open=True, high=1.0)
    colour = check_real("colour", colour, low=0.0, low_open=True, high=0.99)
    cubic = check_real("cubic", cubic, low=0.0, low_open=True, high=1.0)
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    dt = reference.dt
    n = _grid_size(reference.duration, dt)
    _work("runs", runs, len(ASSUMPTION_CASES) * runs * n, MAX_EXPERIMENT_SAMPLES, "samples to identify")
    t = np.arange(n) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    linear = synthetic_measurements(osc, t, force).x
    x_rms = float(np.sqrt(np.mean(linear**2)))
    k3 = cubic * osc.k / x_rms**2
    f_rms = float(np.sqrt(np.mean(force**2)))
    truth = np.array([osc.m, osc.c, osc.k])
    lags = WHITENESS_LAGS
    experiments = {"as assumed": reference}
    predicted = {"as assumed": predicted_coverage(osc, t, force, 0.0)}
    clean_cubic = None
    for j, (label, (uf, uy, uc, uk)) in enumerate(ASSUMPTION_CASES.items()):
        if uk:
            clean_cubic = cubic_response(osc, k3, t, force) if clean_cubic is None else clean_cubic
            clean = clean_cubic
        else:
            clean = linear
        sd = uy * reference.noise * float(np.sqrt(np.mean(clean**2)))
        est, se, ci, white, inp = _monte_carlo(
            truth,
            t,
            force,
            clean,
            sd,
            runs,
            seed,
            1000 + j,
            "x",
            force_sd=uf * force_noise * f_rms,
            colour=uc * colour,
            lags=lags,
        )
        experiments[label] = CoverageExperiment(
            truth=truth,
            estimates=est,
            stderr=se,
            ci95=ci,
            noise=reference.noise * uy,
            duration=float(t[-1]),
            dt=dt,
            sensor="x",
            whiteness_p=white,
            input_p=inp,
            case=label,
        )
        predicted[label] = predicted_coverage(osc, t, force, colour) if uc else None
    return AssumptionStudy(
        experiments=experiments,
        predicted=predicted,
        force_noise=force_noise,
        noise=reference.noise,
        colour=colour,
        cubic=cubic,
        k3=k3,
        lags=lags,
    )


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
    stiffness,
    change_time: float,
    *,
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
    >>> ks = stiffness_profile(t, 20.0, 1e9, 0.0, drop_time=60.0, drop=0.05)
    >>> ex = detection_experiment(osc, t, f, ks, 60.0, noise=2e-3, runs=5, reference=osc, thresholds=[40, 80])
    >>> ex.detection_probability.tolist(), ex.false_alarm_probability.tolist()
    ([1.0, 1.0], [0.0, 0.0])
    """
    _check_osc(osc)
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
    healthy = synthetic_measurements(osc, t, force, sensor=sensor)
    faulty = synthetic_measurements(osc, t, force, sensor=sensor, stiffness=stiffness)
    peaks = np.empty(runs)
    first = np.full((runs, thr.size), np.nan)
    monitored = math.nan
    for i in range(runs):
        for kind, clean, sd in ((0, healthy, seed + i), (1, faulty, seed + runs + i)):
            y = clean.response + noise * np.random.default_rng(sd).standard_normal(t.size)
            det = detect_change(
                t,
                force,
                **{sensor: y},
                reference=reference,
                threshold=float(np.max(thr)),
                drift=drift,
                calibration=calibration,
            )
            monitored = float(t[-1] - det.calibration_end)
            g = det.statistic
            if kind == 0:
                peaks[i] = float(np.max(g))
            else:
                run_max = np.maximum.accumulate(g)
                idx = np.searchsorted(run_max, thr, side="right")
                ok = idx < t.size
                first[i, ok] = t[idx[ok]]
    return DetectionExperiment(
        thresholds=thr,
        change_time=change_time,
        monitored=monitored,
        healthy_peak=peaks,
        first_crossing=first,
        drift=drift,
    )


def identification_sweep(
    osc: Oscillator,
    *,
    noises=(0.01, 0.03, 0.1, 0.3),
    durations=(15.0, 30.0, 60.0, 120.0),
    noise: float = 0.05,
    duration: float = 60.0,
    runs: int = 40,
    seed: int = 0,
    **kwargs,
) -> tuple[list[CoverageExperiment], list[CoverageExperiment]]:
    """Error scaling: :func:`identification_experiment` over noise levels (at ``duration``) and record lengths
    (at ``noise``).

    Every point draws its own noise (stream ``1 + index`` of the point), so the fitted scaling exponents are
    measured, not fixed by rescaling one draw.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    noises : sequence of float
        Noise standard deviations relative to the rms response, 1.
    durations : sequence of float
        Record lengths, s.
    noise, duration : float
        The value held fixed in the other sweep (1, s).
    runs, seed : int
        Realisations per point and the first seed.
    **kwargs
        Passed to :func:`identification_experiment` (``dt``, ``sensor``, ``band``, ``rms``).

    Examples
    --------
    >>> by_noise, by_length = identification_sweep(Oscillator(m=1.0, c=0.5, k=20.0), noises=(0.01, 0.3),
    ...                                            durations=(20.0, 40.0), runs=5)
    >>> float(by_noise[1].rel_rmse[2] / by_noise[0].rel_rmse[2]) > 10     # error grows with the noise (30x)
    True
    """
    noises, durations = _signal("noises", noises), _signal("durations", durations)
    runs = check_int("runs", runs, low=2, high=10_000)
    dt = check_real("dt", kwargs.get("dt", 0.02), low=0.0, low_open=True, unit="s")
    total = runs * (noises.size * (duration / dt + 1) + float(np.sum(durations / dt + 1)))
    _work("runs", runs, total, MAX_EXPERIMENT_SAMPLES, "samples to identify over both sweeps")
    by_noise = [
        identification_experiment(osc, duration=duration, noise=s, runs=runs, seed=seed, stream=1 + i, **kwargs)
        for i, s in enumerate(noises)
    ]
    by_length = [
        identification_experiment(
            osc, duration=d, noise=noise, runs=runs, seed=seed, stream=1 + noises.size + j, **kwargs
        )
        for j, d in enumerate(durations)
    ]
    return by_noise, by_length


@dataclass(frozen=True, kw_only=True)
class EstimateGrid:
    """One seeded identification per (noise, record length): what the slider panels show."""

    truth: np.ndarray  # (3,) m (kg), c (N s/m), k (N/m)
    noises: np.ndarray  # (I,) noise / rms response, 1
    durations: np.ndarray  # (J,) record lengths, s
    estimates: np.ndarray  # (I, J, 3)
    ci95: np.ndarray  # (I, J, 3, 2)


def estimate_grid(
    osc: Oscillator,
    noises=(0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5),
    durations=(10.0, 20.0, 40.0, 80.0, 160.0),
    *,
    dt: float = 0.02,
    seed: int = 0,
    sensor: str = "x",
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
) -> EstimateGrid:
    """Identify one record per (noise, record length); the records share the force and the noise draw.

    The longest record is simulated once (force seed ``seed``, standard normal
    noise draw seed ``seed + 1``); shorter records are its first samples and each
    noise level scales the same draw, so moving one slider changes one thing.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    noises : sequence of float
        Noise standard deviation / rms of the noise-free response, 1.
    durations : sequence of float
        Record lengths, s.
    dt : float
        Sampling step, s.
    seed : int
        Seed of the force; the noise draw uses ``seed + 1``.
    sensor, band, rms
        As :func:`identification_experiment`.

    Examples
    --------
    >>> g = estimate_grid(Oscillator(m=1.0, c=0.5, k=20.0), noises=(0.01, 0.1), durations=(20.0, 40.0))
    >>> g.estimates.shape, g.ci95.shape
    ((2, 2, 3), (2, 2, 3, 2))
    """
    _check_osc(osc)
    noises = _signal("noises", noises)
    durations = _signal("durations", durations)
    if np.any(noises <= 0) or np.any(durations <= 0) or np.any(noises > 10.0):
        raise ParameterError(
            f"noises = {noises!r:.60} and durations = {durations!r:.60}: allowed 0 < noise <= 10 and durations > 0 s"
        )
    dt = check_real("dt", dt, low=0.0, low_open=True, unit="s")
    seed = _check_seed(seed)
    sensor = _check_sensor(sensor)
    n_max = _grid_size(float(np.max(durations)), dt, "durations")
    total = noises.size * float(np.sum(np.round(durations / dt) + 1))
    _work("noises x durations", (noises.size, durations.size), total, MAX_EXPERIMENT_SAMPLES, "samples to identify")
    t = np.arange(n_max) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    clean = synthetic_measurements(osc, t, force, sensor=sensor).response
    draw = np.random.default_rng(seed + 1).standard_normal(t.size)
    est = np.empty((noises.size, durations.size, 3))
    ci = np.empty((noises.size, durations.size, 3, 2))
    for j, d in enumerate(durations):
        n = int(round(d / dt)) + 1
        rms_y = float(np.sqrt(np.mean(clean[:n] ** 2)))
        for i, s in enumerate(noises):
            fit = identify(t[:n], force[:n], **{sensor: clean[:n] + s * rms_y * draw[:n]}, search="local")
            est[i, j] = (fit.m, fit.c, fit.k)
            ci[i, j] = fit.ci95
    return EstimateGrid(
        truth=np.array([osc.m, osc.c, osc.k]), noises=noises, durations=durations, estimates=est, ci95=ci
    )


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


def fault_scenario(k: float, t_monitor: float, dt: float, decline_rate: float, drop: float) -> FaultScenario:
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
    >>> sc = fault_scenario(20.0, 100.0, 0.5, 0.001, 0.1)
    >>> sc.decline_start, sc.drop_time, round(float(sc.k[-1]), 3)
    (40.0, 70.0, 16.92)
    """
    t_monitor = check_real("t_monitor", t_monitor, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, unit="s")
    if dt > t_monitor / MIN_SAMPLES:
        raise ParameterError(
            f"dt = {dt!r} s with t_monitor = {t_monitor!r} s gives fewer than {MIN_SAMPLES} samples: allowed dt <= "
            f"t_monitor / {MIN_SAMPLES} (t_monitor >= {MIN_SAMPLES} dt)"
        )
    t = np.arange(_grid_size(t_monitor, dt, "t_monitor")) * dt
    start, when = 0.4 * t_monitor, 0.7 * t_monitor
    return FaultScenario(
        t=t,
        k=stiffness_profile(t, k, start, decline_rate, drop_time=when, drop=drop),
        decline_start=start,
        drop_time=when,
    )


def detection_study(
    osc: Oscillator,
    reference,
    t_monitor: float,
    dt: float,
    noise: float,
    decline_rate: float,
    drop: float,
    *,
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
    >>> st = detection_study(osc, osc, 100.0, 0.02, 0.01, 0.001, 0.05, runs=3, thresholds=(40.0,))
    >>> sorted(st), [float(e.detection_probability[0]) for e in st.values()]
    (['slow decline', 'sudden drop'], [1.0, 1.0])
    """
    _check_osc(osc)
    t_monitor = check_real("t_monitor", t_monitor, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, unit="s")
    if dt > t_monitor / MIN_SAMPLES:
        raise ParameterError(
            f"dt = {dt!r} s with t_monitor = {t_monitor!r} s gives fewer than {MIN_SAMPLES} samples: allowed dt <= "
            f"t_monitor / {MIN_SAMPLES} (t_monitor >= {MIN_SAMPLES} dt)"
        )
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
        "sudden drop": stiffness_profile(t, osc.k, start, 0.0, drop_time=start, drop=drop),
        "slow decline": stiffness_profile(t, osc.k, start, decline_rate),
    }
    return {
        label: detection_experiment(
            osc,
            t,
            force,
            ks,
            start,
            noise=sd,
            runs=runs,
            seed=seed + 1 + 7919 * j,
            thresholds=thresholds,
            reference=reference,
        )
        for j, (label, ks) in enumerate(profiles.items())
    }
