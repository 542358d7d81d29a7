"""Monte Carlo experiments on identification: coverage of the intervals and the scaling of the errors.

The records that break the model's assumptions are in :mod:`.assumptions`, the detection trade-offs and
the chapter's fault scenarios in :mod:`.detection`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

import numpy as np

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, check_int, check_real
from .identification import identify
from .measurements import MIN_SAMPLES, _check_seed, _check_sensor, _grid_size, _signal, _work
from .synthetic import random_force, synthetic_measurements
from .validation import WHITENESS_LAGS, _ar1, binomial_halfwidth, input_correlation, ljung_box

__all__ = [
    "MAX_EXPERIMENT_SAMPLES",
    "CoverageExperiment",
    "EstimateGrid",
    "RunResults",
    "estimate_grid",
    "identification_experiment",
    "identification_sweep",
]

#: Work budget: samples simulated and identified (or monitored) by one Monte Carlo experiment, all its
#: records together.
MAX_EXPERIMENT_SAMPLES = 20_000_000


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


@dataclass(frozen=True, kw_only=True, eq=False)
class RunResults:
    """Per-run results of a coverage experiment, filled in place run by run (or batch by batch)."""

    estimates: np.ndarray  # (R, 3) m (kg), c (N s/m), k (N/m)
    stderr: np.ndarray  # (R, 3) their standard errors
    ci95: np.ndarray  # (R, 3, 2) their 95 % intervals
    whiteness_p: np.ndarray  # (R,) Ljung-Box p-value of each residual
    input_p: np.ndarray  # (R,) p-value of each residual's correlation with the force

    @classmethod
    def empty(cls, runs: int) -> RunResults:
        """Unfilled arrays for ``runs`` runs."""
        return cls(
            estimates=np.empty((runs, 3)),
            stderr=np.empty((runs, 3)),
            ci95=np.empty((runs, 3, 2)),
            whiteness_p=np.empty(runs),
            input_p=np.empty(runs),
        )

    def experiment(
        self, truth, *, noise: float, duration: float, dt: float, sensor: str, case=None
    ) -> CoverageExperiment:
        """The :class:`CoverageExperiment` of these runs (``case`` None: as assumed); the fields keep their names."""
        per_run = {f.name: getattr(self, f.name) for f in fields(self)}
        return CoverageExperiment(
            truth=truth,
            noise=noise,
            duration=duration,
            dt=dt,
            sensor=sensor,
            **per_run,
            **({} if case is None else {"case": case}),
        )


def _noise_rng(seed: int, stream: int, run: int) -> np.random.Generator:
    """Independent generator per (experiment seed, stream, run): a SeedSequence of the three integers."""
    return np.random.default_rng([seed, stream, run])


def _monte_carlo(
    truth, t, force, clean, sd, runs, seed, stream, sensor, *, noise, dt, lags, force_sd=0.0, colour=0.0, case=None
) -> CoverageExperiment:
    """Identify ``runs`` noisy copies of one record; each run draws its own noise (see :func:`_noise_rng`).

    Returns the experiment's record; ``noise`` (1) and ``dt`` (s) are the level and step it reports, ``case``
    the assumption the records break (None: as assumed).
    """
    out = RunResults.empty(runs)
    for i in range(runs):
        rng = _noise_rng(seed, stream, i)
        y = clean + sd * _ar1(t.size, colour, rng)
        f = force + force_sd * rng.standard_normal(t.size) if force_sd > 0.0 else force
        fit = identify(t, f, **{sensor: y}, search="local")
        out.estimates[i] = (fit.m, fit.c, fit.k)
        out.stderr[i] = fit.stderr
        out.ci95[i] = fit.ci95
        out.whiteness_p[i] = ljung_box(fit.residual, lags)[1]
        out.input_p[i] = input_correlation(fit.residual, f, lags)[1]
    return out.experiment(truth, noise=noise, duration=float(t[-1]), dt=dt, sensor=sensor, case=case)


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
    check_oscillator(osc)
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
    truth = np.array([osc.m, osc.c, osc.k])
    return _monte_carlo(truth, t, force, clean, sd, runs, seed, stream, sensor, noise=noise, dt=dt, lags=lags)


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
    check_oscillator(osc)
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
