"""Identification when the records break one assumption at a time: force noise, coloured noise, a cubic spring."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, check_int, check_real
from .experiments import MAX_EXPERIMENT_SAMPLES, CoverageExperiment, _monte_carlo
from .measurements import _check_seed, _grid_size, _work
from .synthetic import random_force, synthetic_measurements
from .validation import WHITENESS_LAGS, cubic_response, predicted_coverage

__all__ = ["ASSUMPTION_CASES", "AssumptionStudy", "assumption_study"]

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


def assumption_records(osc: Oscillator, k3: float, t, *, force, linear):
    """Each case of :data:`ASSUMPTION_CASES` with the noise-free displacement its records are made from.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    k3 : float
        Cubic coefficient of the unmodelled spring, N/m^3.
    t, force, linear : numpy.ndarray
        Sample times (s), the force (N) and the oscillator's response to it (m).

    Yields
    ------
    tuple
        ``(j, label, multipliers, clean)``: the case's index (its noise stream is ``1000 + j``), its label, its
        multipliers (force noise, response noise, colour, cubic) and ``linear`` or, for a cubic case, the
        response with the spring ``k3 x^3`` (computed once).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> t = np.arange(0.0, 2.0, 0.01)
    >>> f = np.sin(3.0 * t)
    >>> x = synthetic_measurements(osc, t, f).x
    >>> [(j, uk, clean is x) for j, _, (_, _, _, uk), clean in assumption_records(osc, 5.0, t, force=f, linear=x)]
    [(0, 0.0, True), (1, 0.0, True), (2, 0.0, True), (3, 1.0, False)]
    """
    cubic = None
    for j, (label, multipliers) in enumerate(ASSUMPTION_CASES.items()):
        if multipliers[3] and cubic is None:
            cubic = cubic_response(osc, k3, t, force=force)
        yield j, label, multipliers, cubic if multipliers[3] else linear


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
    >>> from vibration.physics.twin.experiments import identification_experiment
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> ref = identification_experiment(osc, duration=20.0, runs=4)
    >>> st = assumption_study(osc, ref, runs=3)
    >>> list(st.experiments)[:2], st.experiments["coloured sensor noise"].flagged()
    (['as assumed', 'noise on the force'], 1.0)
    """
    force_noise, colour, cubic, runs, seed = _checked_study(osc, reference, force_noise, colour, cubic, runs, seed)
    t, force, linear = _study_record(osc, reference, runs, seed, band, rms)
    x_rms = float(np.sqrt(np.mean(linear**2)))
    k3 = cubic * osc.k / x_rms**2
    experiments, predicted = _case_experiments(
        osc, reference, t, force, linear, k3=k3, runs=runs, seed=seed, force_noise=force_noise, colour=colour
    )
    return AssumptionStudy(
        experiments=experiments,
        predicted=predicted,
        force_noise=force_noise,
        noise=reference.noise,
        colour=colour,
        cubic=cubic,
        k3=k3,
        lags=WHITENESS_LAGS,
    )


def _checked_study(osc, reference, force_noise, colour, cubic, runs, seed):
    """The arguments of :func:`assumption_study`, checked in order: ``(force_noise, colour, cubic, runs, seed)``."""
    check_oscillator(osc)
    if not isinstance(reference, CoverageExperiment) or reference.sensor != "x":
        raise ParameterError(f"reference = {reference!r:.60}: allowed a displacement CoverageExperiment")
    force_noise = check_real("force_noise", force_noise, low=0.0, low_open=True, high=1.0)
    colour = check_real("colour", colour, low=0.0, low_open=True, high=0.99)
    cubic = check_real("cubic", cubic, low=0.0, low_open=True, high=1.0)
    runs = check_int("runs", runs, low=2, high=10_000)
    seed = _check_seed(seed)
    return force_noise, colour, cubic, runs, seed


def _study_record(osc, reference, runs, seed, band, rms):
    """Sample times (s), force (N) and linear noise-free response (m) of the study, on the reference's design."""
    dt = reference.dt
    n = _grid_size(reference.duration, dt)
    _work("runs", runs, len(ASSUMPTION_CASES) * runs * n, MAX_EXPERIMENT_SAMPLES, "samples to identify")
    t = np.arange(n) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    return t, force, synthetic_measurements(osc, t, force).x


def _case_experiments(osc, reference, t, force, linear, *, k3, runs, seed, force_noise, colour):
    """The experiment and predicted coverage of every case, keyed by label (``reference`` as assumed, first)."""
    f_rms = float(np.sqrt(np.mean(force**2)))
    truth = np.array([osc.m, osc.c, osc.k])
    experiments = {"as assumed": reference}
    predicted = {"as assumed": predicted_coverage(osc, t, force, colour=0.0)}
    for j, label, (uf, uy, uc, _uk), clean in assumption_records(osc, k3, t, force=force, linear=linear):
        sd = uy * reference.noise * float(np.sqrt(np.mean(clean**2)))
        experiments[label] = _monte_carlo(
            truth,
            t,
            force,
            clean,
            sd,
            runs,
            seed,
            1000 + j,
            "x",
            noise=reference.noise * uy,
            dt=reference.dt,
            lags=WHITENESS_LAGS,
            force_sd=uf * force_noise * f_rms,
            colour=uc * colour,
            case=label,
        )
        predicted[label] = predicted_coverage(osc, t, force, colour=colour) if uc else None
    return experiments, predicted
