"""Chapter 10, a digital twin: the whole computation, one frozen record.

:func:`digital_twin_study` takes the chapter's validated :class:`~vibration.book.chapters.digital_twin.params.Params`
and returns a :class:`DigitalTwinStudy`; the figures, tables and sentences are functions of that record.
Every record here is synthetic (made by the package from seeded draws, and stated as such in the chapter).
Every parameter reaches every computation that uses it: the force band's upper edge ``f_max`` (Hz), its rms
``F_rms`` (N) and the sampling step ``dt`` (s) drive the test records, the Monte Carlo experiments, the monitored
records, the Kalman check, the discretisation check and the slider grid alike.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.digital_twin import cusum, montecarlo
from vibration.book.chapters.digital_twin.params import Params
from vibration.physics.model import Oscillator
from vibration.physics.twin import (
    THRESHOLDS,
    WHITENESS_LAGS,
    AssumptionStudy,
    ChangeDetection,
    CoverageExperiment,
    DetectionExperiment,
    EstimateGrid,
    FaultScenario,
    FrequencyEstimate,
    FrequencyResponse,
    Identification,
    Measurements,
    StiffnessTrack,
    detect_change,
    detection_study,
    discretisation_checks,
    estimate_grid,
    fault_scenario,
    frequency_estimates,
    frf_estimate,
    identify,
    predicted_coverage,
    random_force,
    simulated_test,
    stiffness_profile,
    synthetic_measurements,
    track_stiffness,
)
from vibration.physics.twin.assumptions import assumption_records

#: Length of the sine record of the discretisation check, s.
CHECK_WINDOW = 50.0
#: A check difference below this is at rounding level (its digits differ between machines).
ROUNDING = 1e-11
#: Lower edge of the test force band, Hz.
F_LOW = 0.1
#: Noise levels of the error-scaling sweep (over the rms response), and record lengths over ``t_record``.
SWEEP_NOISES = (0.01, 0.03, 0.1, 0.3)
SWEEP_LENGTHS = (0.25, 0.5, 1.0, 2.0)
#: The frequency-domain estimates read a record this many times longer than the test.
FRF_FACTOR = 8
#: The coverage target: every share's 95 % half-width at most this.
HALFWIDTH_TARGET = 0.03
#: Random-walk intensity of the Kalman filter, fraction of k per sqrt(s) (track_stiffness's default).
WALK = 0.02
#: Records per truth in the Kalman check, and the length of its averaging blocks, s.
KALMAN_RECORDS = 2
KALMAN_BLOCK = 20.0
#: Seconds after the calibration window that the filter is given to converge before errors count.
KALMAN_SETTLE = 10.0
#: Runs per case that the batch fit is compared with identify() on.
AGREEMENT_RUNS = 2
#: Alarms needed before a measured run length is compared with theory.
MIN_ALARMS = 20


@dataclass(frozen=True, kw_only=True)
class KalmanCheck:
    """The Kalman filter's stated standard deviation of k against its actual error, over many samples."""

    truth: str  # "constant" or "random walk"
    records: int
    samples: int  # samples counted over all records
    stated: float  # rms of the stated standard deviation of k, N/m
    actual: float  # rms of the actual error of k, N/m
    ratio: float  # actual / stated, 1
    halfwidth: float  # 95 % half-width of the ratio (batch means over blocks), 1


@dataclass(frozen=True, kw_only=True)
class DigitalTwinStudy:
    """Every number the chapter shows, at one set of parameters."""

    params: Params
    asset: Oscillator  # the truth: m (kg), c (N s/m), k (N/m)
    band: tuple[float, float]  # force band, Hz
    checks: dict  # name -> (measured difference, bound, rounding level?)
    batch_agreement: float  # largest relative difference of the batch fit from identify(), 1
    test: Measurements
    fit: Identification
    frf: FrequencyResponse
    half_power: FrequencyEstimate
    circle: FrequencyEstimate
    frf_record: float  # length of the record the FRF estimates read, s
    coverage: CoverageExperiment
    by_noise: tuple[CoverageExperiment, ...]
    by_length: tuple[CoverageExperiment, ...]
    assumptions: AssumptionStudy
    scenario: FaultScenario
    monitored: Measurements
    track: StiffnessTrack
    alarm: ChangeDetection
    kalman: tuple[KalmanCheck, ...]
    detection: dict  # fault -> DetectionExperiment
    run_lengths: cusum.RunLengths
    delay_theory: dict  # fault -> DelayTheory at the chosen threshold
    grid: EstimateGrid

    @property
    def threshold_index(self) -> int:
        """Index of the chosen threshold in the detection experiments' threshold grid."""
        ex = next(iter(self.detection.values()))
        return int(np.argmin(np.abs(ex.thresholds - self.params.threshold)))

    @property
    def drift(self) -> float:
        """The CUSUM drift nu, 1."""
        return next(iter(self.detection.values())).drift


def _noise_sd(clean: np.ndarray, level: float) -> float:
    return level * float(np.sqrt(np.mean(clean**2)))


def _coverage(asset, p: Params, band, duration, noise, runs, stream) -> CoverageExperiment:
    t, force, clean = montecarlo.design(asset, duration, p.dt, seed=p.seed, band=band, rms=p.F_rms)
    return montecarlo.experiment(
        asset,
        t,
        force,
        clean=clean,
        noise_sd=_noise_sd(clean, noise),
        runs=runs,
        seed=p.seed,
        stream=stream,
        noise=noise,
    )


def _assumptions(asset, p: Params, band, reference: CoverageExperiment) -> tuple[AssumptionStudy, float]:
    """The as-assumed experiment and one per broken assumption (own noise stream each); and the batch agreement."""
    t, force, linear = montecarlo.design(asset, p.t_record, p.dt, seed=p.seed, band=band, rms=p.F_rms)
    x_rms = float(np.sqrt(np.mean(linear**2)))
    k3 = p.cubic * asset.k / x_rms**2
    f_rms = float(np.sqrt(np.mean(force**2)))
    experiments = {"as assumed": reference}
    predicted = {"as assumed": predicted_coverage(asset, t, force, colour=0.0)}
    for j, label, (uf, uy, uc, _uk), clean in assumption_records(asset, k3, t, force=force, linear=linear):
        experiments[label] = montecarlo.experiment(
            asset,
            t,
            force,
            clean=clean,
            noise_sd=uy * _noise_sd(clean, p.noise),
            runs=p.assumption_runs,
            seed=p.seed,
            stream=1000 + j,
            force_sd=uf * p.force_noise * f_rms,
            colour=uc * p.colour,
            noise=uy * p.noise,
            case=label,
        )
        predicted[label] = predicted_coverage(asset, t, force, colour=p.colour) if uc else None
    agree = montecarlo.agreement(
        asset, t, force, clean=linear, noise_sd=_noise_sd(linear, p.noise), seed=p.seed, stream=0, runs=AGREEMENT_RUNS
    )
    study = AssumptionStudy(
        experiments=experiments,
        predicted=predicted,
        force_noise=p.force_noise,
        noise=p.noise,
        colour=p.colour,
        cubic=p.cubic,
        k3=k3,
        lags=WHITENESS_LAGS,
    )
    return study, agree


def _block_ratio(errors: list[np.ndarray], stated: list[np.ndarray], block: int) -> tuple[float, float, float, float]:
    """rms error, rms stated sd, their ratio and its 95 % half-width from batch means over blocks."""
    e2 = np.concatenate([(e[: e.size // block * block] ** 2).reshape(-1, block).mean(axis=1) for e in errors])
    s2 = np.concatenate([(s[: s.size // block * block] ** 2).reshape(-1, block).mean(axis=1) for s in stated])
    ratio2 = float(e2.mean() / s2.mean())
    b = e2.size
    var_r2 = float(np.var(e2 - ratio2 * s2, ddof=1)) / b / float(s2.mean()) ** 2
    ratio = math.sqrt(ratio2)
    return math.sqrt(float(e2.mean())), math.sqrt(float(s2.mean())), ratio, 1.96 * math.sqrt(var_r2) / (2 * ratio)


def _kalman(asset, p: Params, band, fit: Identification, noise_sd: float) -> tuple[KalmanCheck, ...]:
    """Stated sd of k against the actual error: constant stiffness, and a random walk (the filter's own model)."""
    t = np.arange(int(round(p.t_monitor / p.dt)) + 1) * p.dt
    count = t > (0.25 * p.t_monitor + KALMAN_SETTLE)
    block = max(int(round(KALMAN_BLOCK / p.dt)), 2)
    out = []
    for truth in ("constant", "random walk"):
        errors, stated = [], []
        for r in range(KALMAN_RECORDS):
            seed = p.seed + 100 + 10 * r + (5 if truth == "random walk" else 0)
            force = random_force(t, band=band, rms=p.F_rms, seed=seed)
            ks = np.full(t.size, asset.k)
            if truth == "random walk":
                rng = np.random.default_rng([p.seed, 7, r])
                steps = WALK * asset.k * math.sqrt(p.dt) * rng.standard_normal(t.size)
                steps[: int(np.argmax(count))] = 0.0  # healthy until the filter has settled
                ks = asset.k + np.cumsum(steps)
                ks = np.maximum(ks, 0.05 * asset.k)
            rec = synthetic_measurements(asset, t, force, noise=noise_sd, seed=seed + 1, stiffness=ks)
            tr = track_stiffness(rec.t, rec.force, x=rec.x, reference=fit, walk=WALK)
            errors.append((tr.k - ks)[count])
            stated.append(tr.k_std[count])
        actual, sd, ratio, half = _block_ratio(errors, stated, block)
        out.append(
            KalmanCheck(
                truth=truth,
                records=KALMAN_RECORDS,
                samples=int(sum(e.size for e in errors)),
                stated=sd,
                actual=actual,
                ratio=ratio,
                halfwidth=half,
            )
        )
    return tuple(out)


def _healthy_increments(asset, p: Params, band, fit, sd_rel: float):
    """The detection experiments' healthy records again: each one's CUSUM increments after calibration."""
    t = np.arange(int(round(p.t_monitor / p.dt)) + 1) * p.dt
    force = random_force(t, band=band, rms=p.F_rms, seed=p.seed + 4)
    clean = synthetic_measurements(asset, t, force).x
    sd = _noise_sd(clean, sd_rel)
    out = []
    for j in range(2):  # the two experiments of detection_study, seeds seed + 1 + 7919 j, healthy seed + i
        first = p.seed + 4 + 1 + 7919 * j
        for i in range(p.detect_runs):
            y = clean + sd * np.random.default_rng(first + i).standard_normal(t.size)
            det = detect_change(t, force, x=y, reference=fit, threshold=p.threshold)
            n_cal = int(np.searchsorted(t, det.calibration_end))
            out.append(det.residual[n_cal:] ** 2 / det.sigma**2 - 1.0 - det.drift)
    return t, force, clean, sd, out, n_cal


def _run_lengths(p: Params, increments, drift: float, n_cal: int) -> cusum.RunLengths:
    thresholds = np.array(sorted(set(THRESHOLDS) | {float(p.threshold)}))
    counts = sum(cusum.restart_alarms(z, thresholds) for z in increments)
    samples = int(sum(z.size for z in increments))
    theory = np.array([cusum.arl_estimated_sigma(h, drift, n_cal) for h in thresholds])
    return cusum.RunLengths(
        thresholds=thresholds, alarms=counts, samples=samples, dt=p.dt, theory=theory[:, 0], theory_error=theory[:, 1]
    )


def _delay_theory(asset, p, fit, t, force, sd, threshold, drift) -> dict:
    """Markov-chain alarm-time distribution on each fault's noise-free residual (the faulty records' mean)."""
    start = 0.4 * p.t_monitor
    profiles = {
        "sudden drop": stiffness_profile(t, asset.k, start, decline_rate=0.0, drop_time=start, drop=p.drop),
        "slow decline": stiffness_profile(t, asset.k, start, decline_rate=p.decline_rate),
    }
    out = {}
    for label, ks in profiles.items():
        clean = synthetic_measurements(asset, t, force, stiffness=ks).x
        det = detect_change(t, force, x=clean, reference=fit, threshold=threshold)
        n_cal = int(np.searchsorted(t, det.calibration_end))
        mu = det.residual[n_cal:] / sd
        prob = cusum.alarm_distribution(mu, threshold, drift)
        tm = t[n_cal:]
        late = tm >= start - 1e-9
        p_late = float(prob[late].sum())
        delay = float(np.sum(prob[late] * (tm[late] - start)) / p_late) if p_late > 0 else math.nan
        out[label] = cusum.DelayTheory(
            threshold=threshold,
            detection_probability=p_late,
            early_alarm_probability=float(prob[~late].sum()),
            mean_delay=delay,
        )
    return out


def _checks(asset: Oscillator, p: Params) -> dict:
    """The discretisation check: a sine of rms F_rms at the band's upper edge, sampled at dt over 50 s."""
    n_check = int(round(CHECK_WINDOW / p.dt)) + 1
    checks_raw = discretisation_checks(
        asset, math.sqrt(2.0) * p.F_rms, 2.0 * math.pi * p.f_max, t_end=CHECK_WINDOW, n=n_check
    )
    return {name: (value, bound, value < ROUNDING) for name, (value, bound) in checks_raw.items()}


def _identification(
    asset: Oscillator, p: Params, band
) -> tuple[Measurements, Identification, FrequencyResponse, FrequencyEstimate, FrequencyEstimate]:
    """The test record, its fit and FRF; the half-power and circle-fit estimates from a longer record."""
    test = simulated_test(asset, p.t_record, p.dt, noise=p.noise, seed=p.seed, band=band, rms=p.F_rms)
    fit = identify(test.t, test.force, x=test.x)
    frf = frf_estimate(test.t, test.force, x=test.x)
    long_test = simulated_test(
        asset, FRF_FACTOR * p.t_record, p.dt, noise=p.noise, seed=p.seed + 5, band=band, rms=p.F_rms
    )
    half_power, circle = frequency_estimates(frf_estimate(long_test.t, long_test.force, x=long_test.x))
    return test, fit, frf, half_power, circle


def _coverages(
    asset: Oscillator, p: Params, band
) -> tuple[CoverageExperiment, tuple[CoverageExperiment, ...], tuple[CoverageExperiment, ...]]:
    """The coverage experiment at the parameters, and the sweeps over the noise level and the record length."""
    coverage = _coverage(asset, p, band, p.t_record, p.noise, p.runs, 0)
    by_noise = tuple(_coverage(asset, p, band, p.t_record, s, p.sweep_runs, 1 + i) for i, s in enumerate(SWEEP_NOISES))
    by_length = tuple(
        _coverage(asset, p, band, f * p.t_record, p.noise, p.sweep_runs, 1 + len(SWEEP_NOISES) + j)
        for j, f in enumerate(SWEEP_LENGTHS)
    )
    return coverage, by_noise, by_length


def _monitoring(
    asset: Oscillator, p: Params, band, fit: Identification
) -> tuple[FaultScenario, Measurements, StiffnessTrack, ChangeDetection]:
    """The fault scenario, its monitored record, the Kalman stiffness track and the CUSUM alarm on it."""
    scenario = fault_scenario(p.k, p.t_monitor, p.dt, decline_rate=p.decline_rate, drop=p.drop)
    monitored = synthetic_measurements(
        asset,
        scenario.t,
        random_force(scenario.t, band=band, rms=p.F_rms, seed=p.seed + 2),
        noise=fit.sigma,
        seed=p.seed + 3,
        stiffness=scenario.k,
    )
    track = track_stiffness(monitored.t, monitored.force, x=monitored.x, reference=fit, walk=WALK)
    alarm = detect_change(monitored.t, monitored.force, x=monitored.x, reference=fit, threshold=p.threshold)
    return scenario, monitored, track, alarm


def _detection(asset: Oscillator, p: Params, band, fit: Identification) -> tuple[dict, cusum.RunLengths, dict]:
    """The detection experiments, the healthy records' run lengths and each fault's alarm-time theory."""
    detection: dict[str, DetectionExperiment] = detection_study(
        asset,
        fit,
        p.t_monitor,
        dt=p.dt,
        noise=p.noise,
        decline_rate=p.decline_rate,
        drop=p.drop,
        runs=p.detect_runs,
        seed=p.seed + 4,
        band=band,
        rms=p.F_rms,
        thresholds=tuple(sorted(set(THRESHOLDS) | {float(p.threshold)})),
    )
    drift = next(iter(detection.values())).drift
    t_mon, force_mon, _, sd_mon, increments, n_cal = _healthy_increments(asset, p, band, fit, p.noise)
    run_lengths = _run_lengths(p, increments, drift, n_cal)
    delay_theory = _delay_theory(asset, p, fit, t_mon, force_mon, sd_mon, float(p.threshold), drift)
    return detection, run_lengths, delay_theory


def digital_twin_study(params: Params | None = None, **values) -> DigitalTwinStudy:
    """Chapter 10 on one parameter record: identification, its coverage, the monitored asset and its alarms.

    ``params`` is the chapter's validated record (the force band and its rms, the sampling step, the record
    lengths, the noise, the faults, the seed), or the values are given as keyword arguments and checked by
    the schema. Every record the study reads is synthetic, drawn from that seed. Returns the frozen
    :class:`DigitalTwinStudy`.
    """
    p = params if params is not None else Params.from_values(values)
    asset = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    band = (F_LOW, p.f_max)
    checks = _checks(asset, p)
    test, fit, frf, half_power, circle = _identification(asset, p, band)
    coverage, by_noise, by_length = _coverages(asset, p, band)
    assumptions, agree = _assumptions(asset, p, band, coverage)
    scenario, monitored, track, alarm = _monitoring(asset, p, band, fit)
    kalman = _kalman(asset, p, band, fit, fit.sigma)
    detection, run_lengths, delay_theory = _detection(asset, p, band, fit)
    grid = estimate_grid(asset, dt=p.dt, seed=p.seed, band=band, rms=p.F_rms)
    return DigitalTwinStudy(
        params=p,
        asset=asset,
        band=band,
        checks=checks,
        batch_agreement=agree,
        test=test,
        fit=fit,
        frf=frf,
        half_power=half_power,
        circle=circle,
        frf_record=FRF_FACTOR * p.t_record,
        coverage=coverage,
        by_noise=by_noise,
        by_length=by_length,
        assumptions=assumptions,
        scenario=scenario,
        monitored=monitored,
        track=track,
        alarm=alarm,
        kalman=kalman,
        detection=detection,
        run_lengths=run_lengths,
        delay_theory=delay_theory,
        grid=grid,
    )
