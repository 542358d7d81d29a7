"""Synthetic test records: a band-limited random force, a fatigue-like stiffness history, simulated records."""

from __future__ import annotations

import math

import numpy as np

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, check_real
from .measurements import (
    MAX_ABS,
    MIN_SAMPLES,
    Measurements,
    _check_band,
    _check_seed,
    _check_sensor,
    _finite_output,
    _grid_size,
    _sampling,
    _signal,
    _work,
)
from .sampled import _foh, sampled_response

__all__ = [
    "example_measurements",
    "random_force",
    "simulated_test",
    "stiffness_profile",
    "synthetic_measurements",
]

#: Work budget: samples times frequencies of one :func:`random_force` (cosines evaluated).
MAX_MULTISINE_TERMS = 100_000_000


def random_force(t, band: tuple[float, float] = (0.1, 2.0), rms: float = 2.0, *, seed: int = 0) -> np.ndarray:
    """Band-limited random force: a multisine with a flat spectrum in ``band`` and random phases.

    Parameters
    ----------
    t : array_like
        Uniform sample times, s.
    band : (float, float)
        Lowest and highest frequency, Hz (0 < low < high).
    rms : float
        Root-mean-square force, N (> 0).
    seed : int
        Seed of the phases.

    Returns
    -------
    numpy.ndarray
        Force at ``t``, N.

    Examples
    --------
    >>> t = np.arange(0.0, 100.0, 0.01)
    >>> round(float(np.sqrt(np.mean(random_force(t, rms=3.0) ** 2))), 6)   # N
    3.0
    """
    t = _signal("t", t)
    if t.size < 2 or not t[-1] > t[0]:
        raise ParameterError(f"t = {t!r:.60} spans no time: allowed at least 2 samples, t[-1] > t[0]")
    lo, hi = _check_band(band)
    nyquist = 0.5 / float(np.median(np.diff(t)))
    if not hi < nyquist:
        raise ParameterError(
            f"band = {band!r} Hz reaches the Nyquist frequency {nyquist:.4g} Hz of t's sampling: allowed an upper "
            f"edge below {nyquist:.4g} Hz (above it the samples alias the band onto lower frequencies)"
        )
    rms = check_real("rms", rms, low=0.0, low_open=True, unit="N")
    seed = _check_seed(seed)
    span = float(t[-1] - t[0])
    df = 1.0 / span
    n_freqs = max(math.floor(hi / df) - math.ceil(lo / df) + 1, 1)
    _work(
        "band",
        (lo, hi),
        float(n_freqs) * t.size,
        MAX_MULTISINE_TERMS,
        f"cosine evaluations ({n_freqs} lines x {t.size} samples)",
    )
    freqs = np.arange(math.ceil(lo / df), math.floor(hi / df) + 1) * df
    if freqs.size == 0:
        freqs = np.array([0.5 * (lo + hi)])
    rng = np.random.default_rng(seed)
    phases = rng.uniform(0.0, 2.0 * np.pi, freqs.size)
    f = np.zeros_like(t)
    tt = t - t[0]
    for k0 in range(0, freqs.size, 256):  # bounded memory
        sl = slice(k0, k0 + 256)
        f += np.cos(2.0 * np.pi * np.outer(tt, freqs[sl]) + phases[sl]).sum(axis=1)
    power = float(np.mean(f**2))
    if not power > 0.0:  # pragma: no cover - a sum of cosines with random phases vanishing at every sample
        raise ParameterError(f"t = {t!r:.60} samples the multisine only at its zeros: allowed more samples")
    return f * (rms / math.sqrt(power))


def stiffness_profile(
    t, k0: float, decline_start: float, *, decline_rate: float, drop_time: float | None = None, drop: float = 0.0
) -> np.ndarray:
    """A fatigue-like stiffness history: constant, then a linear decline, optionally a sudden drop.

    Parameters
    ----------
    t : array_like
        Times, s.
    k0 : float
        Healthy stiffness, N/m (> 0).
    decline_start : float
        Time the slow decline starts, s.
    decline_rate : float
        Relative decline rate, 1/s (fraction of ``k0`` lost per second, >= 0).
    drop_time : float, optional
        Time of the sudden drop, s (None: no drop).
    drop : float
        Fraction of the stiffness lost at ``drop_time``, 1 (0 to 0.9).

    Examples
    --------
    >>> stiffness_profile([0.0, 10.0, 20.0, 30.0], 20.0, 10.0, decline_rate=0.001, drop_time=25.0, drop=0.1)
    array([20.  , 20.  , 19.8 , 17.64])
    """
    t = _signal("t", t)
    k0 = check_real("k0", k0, low=0.0, low_open=True, unit="N/m")
    decline_start = check_real("decline_start", decline_start, unit="s")
    decline_rate = check_real("decline_rate", decline_rate, low=0.0, unit="1/s")
    drop = check_real("drop", drop, low=0.0, high=0.9)
    k = k0 * (1.0 - decline_rate * np.clip(t - decline_start, 0.0, None))
    if drop_time is not None:
        drop_time = check_real("drop_time", drop_time, unit="s")
        k = np.where(t >= drop_time, k * (1.0 - drop), k)
    if np.any(k <= 0.0):
        raise ParameterError(f"decline_rate = {decline_rate!r} 1/s makes k <= 0 inside t: allowed k(t) > 0")
    return k


def synthetic_measurements(
    osc: Oscillator,
    t,
    force,
    *,
    sensor: str = "x",
    noise: float = 0.0,
    seed: int | None = 0,
    stiffness=None,
    x0: float = 0.0,
    v0: float = 0.0,
) -> Measurements:
    """A simulated record: exact FOH response plus white Gaussian noise on the sensor.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    t : array_like
        Uniform sample times, s.
    force : array_like
        Force at ``t``, N.
    sensor : {"x", "a"}
        Displacement (m) or acceleration (m/s^2).
    noise : float
        Standard deviation of the sensor noise, m or m/s^2 (>= 0).
    seed : int or None
        Seed of the noise.
    stiffness : array_like, optional
        Stiffness at each sample, N/m, held over the step that follows (a fault);
        ``osc.k`` is ignored then.
    x0, v0 : float
        Initial displacement (m) and velocity (m/s).

    Examples
    --------
    >>> t = np.arange(0.0, 10.0, 0.01)
    >>> a = synthetic_measurements(Oscillator(m=1.0, c=0.5, k=20.0), t, np.ones_like(t))
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> b = synthetic_measurements(osc, t, np.ones_like(t), stiffness=np.full(t.size, 20.0))
    >>> bool(np.allclose(a.x, b.x, rtol=0, atol=1e-12))
    True
    """
    check_oscillator(osc)
    sensor = _check_sensor(sensor)
    noise = check_real("noise", noise, low=0.0, high=MAX_ABS, unit="m" if sensor == "x" else "m/s^2")
    seed = _check_seed(seed, none=True)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    t = _signal("t", t)
    if t.size < 2:
        raise ParameterError(f"t has {t.size} samples: allowed at least 2")
    force = _signal("force", force, t.size)
    if stiffness is None:
        r = sampled_response(osc, t, force, x0=x0, v0=v0)
        y = r.x if sensor == "x" else r.a
    else:
        ks = _signal("stiffness", stiffness, t.size)
        if np.any(ks <= 0.0):
            raise ParameterError("stiffness has values <= 0: allowed k(t) > 0 N/m")
        h = _sampling(t, lambda i: f"t[{i}]")
        uniq, inv = np.unique(ks[:-1], return_inverse=True)
        phi, g0, g1 = _foh(np.full(uniq.size, osc.m), np.full(uniq.size, osc.c), uniq, h)
        z = np.empty((t.size, 2))
        z[0] = (x0, v0)
        with np.errstate(over="ignore", invalid="ignore"):
            for n in range(t.size - 1):
                j = inv[n]
                z[n + 1] = phi[j] @ z[n] + g0[j] * force[n] + g1[j] * force[n + 1]
            y = z[:, 0] if sensor == "x" else (force - osc.c * z[:, 1] - ks * z[:, 0]) / osc.m
    if noise > 0.0:
        y = y + noise * np.random.default_rng(seed).standard_normal(t.size)
    _finite_output(
        y,
        "the simulated record",
        f"the oscillator {osc} grows without bound, or the force, initial state or noise is too large: allowed a "
        "record that stays a finite float",
    )
    return Measurements(t=t, force=force, x=y) if sensor == "x" else Measurements(t=t, force=force, a=y)


def example_measurements() -> Measurements:
    """The synthetic record shipped as ``data/twin_example.csv`` (made here, not measured).

    The paper's oscillator (m = 1 kg, c = 0.5 N s/m, k = 20 N/m) driven by a
    band-limited random force (0.1 to 2 Hz, 2 N rms, seed 13) for 60 s at 50 Hz
    from rest, displacement with white Gaussian noise of 2 mm (seed 14); values
    rounded to 7 significant figures.

    Examples
    --------
    >>> meas = example_measurements()
    >>> len(meas), meas.sensor
    (3001, 'x')
    """
    t = np.round(np.arange(3001) * 0.02, 10)
    force = random_force(t, band=(0.1, 2.0), rms=2.0, seed=13)
    meas = synthetic_measurements(Oscillator(m=1.0, c=0.5, k=20.0), t, force, noise=2e-3, seed=14)
    r = np.vectorize(lambda v: float(f"{v:.7g}"))
    return Measurements(t=t, force=r(meas.force), x=r(meas.x))


def simulated_test(
    osc: Oscillator,
    duration: float,
    dt: float,
    *,
    noise: float,
    seed: int = 0,
    band: tuple[float, float] = (0.1, 2.0),
    rms: float = 2.0,
    sensor: str = "x",
    stiffness=None,
) -> Measurements:
    """A broadband test record from rest with noise given relative to the rms noise-free response.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    duration, dt : float
        Record length and sampling step, s.
    noise : float
        Noise standard deviation / rms of the noise-free response, 1 (>= 0).
    seed : int
        Force seed; the noise uses ``seed + 1``.
    band, rms, sensor, stiffness
        As :func:`random_force` and :func:`synthetic_measurements` (Hz, N, -, N/m).

    Examples
    --------
    >>> rec = simulated_test(Oscillator(m=1.0, c=0.5, k=20.0), 10.0, 0.02, noise=0.1)
    >>> len(rec), rec.sensor
    (501, 'x')
    """
    check_oscillator(osc)
    duration = check_real("duration", duration, low=0.0, low_open=True, unit="s")
    dt = check_real("dt", dt, low=0.0, low_open=True, high=duration / MIN_SAMPLES, unit="s")
    noise = check_real("noise", noise, low=0.0, high=10.0)
    seed = _check_seed(seed)
    sensor = _check_sensor(sensor)
    t = np.arange(_grid_size(duration, dt)) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    clean = synthetic_measurements(osc, t, force, sensor=sensor, stiffness=stiffness).response
    y = clean + noise * float(np.sqrt(np.mean(clean**2))) * np.random.default_rng(seed + 1).standard_normal(t.size)
    return Measurements(t=t, force=force, x=y) if sensor == "x" else Measurements(t=t, force=force, a=y)
