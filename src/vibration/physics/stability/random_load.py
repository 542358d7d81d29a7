"""Random load: white-noise variances in closed form, exact discrete simulation and Monte Carlo."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import expm
from scipy.signal import lfilter

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, check_int, check_real
from ._common import _check_stable
from .poles import poles

#: Largest number of samples :func:`simulate_white_noise` and :func:`white_noise_monte_carlo` draw.
SAMPLES_MAX = 50_000_000
#: Recorded steps per path of :func:`white_noise_monte_carlo` by default.
MC_SAMPLES = 2000
#: Samples simulated at once by :func:`white_noise_monte_carlo` (memory of one chunk ~ 50 bytes each).
MC_CHUNK = 1_000_000

#: Largest total number of samples (paths times samples per path) of one Monte Carlo estimate (about 5 s).
MC_TOTAL_MAX = 100_000_000


# ----------------------------------------------------------------------------- random load


def _check_S0(S0) -> float:
    return check_real("S0", S0, low=0.0, unit="N^2 s/rad")


def _check_stationary(osc: Oscillator, S0, what: str = "a stationary random response") -> float:
    """Check the oscillator and the force density ``S0`` (N^2 s/rad) and that ``what`` exists (c > 0)."""
    check_oscillator(osc)
    S0 = _check_S0(S0)
    _check_stable(osc, what)
    return S0


def white_noise_variance(osc: Oscillator, S0: float) -> float:
    """Stationary displacement variance under a white-noise force, m^2.

    With the force's two-sided power spectral density ``S0`` (N^2 s/rad, over
    ``-inf < omega < inf``, so its autocorrelation is ``2 pi S0 delta(tau)``),
    ``var x = S0 integral |H(omega)|^2 d omega = pi S0 / (k c)``,
    ``H = 1 / (k - m omega^2 + i c omega)``. The mass drops out.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, > 0), k (N/m).
    S0 : float
        Two-sided force spectral density, N^2 s/rad (>= 0).

    Raises
    ------
    ParameterError
        When ``c <= 0``: there is no stationary response (the variance grows without bound).

    Examples
    --------
    >>> round(white_noise_variance(Oscillator(m=1.0, c=0.5, k=20.0), 1.0), 6)      # m^2
    0.314159
    """
    S0 = _check_stationary(osc, S0)
    return _finite_variance(math.pi * S0 / osc.k / osc.c, S0, "displacement")


def white_noise_velocity_variance(osc: Oscillator, S0: float) -> float:
    """Stationary velocity variance under a white-noise force, ``pi S0 / (m c)``, m^2/s^2.

    Same conventions as :func:`white_noise_variance`.

    Examples
    --------
    >>> round(white_noise_velocity_variance(Oscillator(m=1.0, c=0.5, k=20.0), 1.0), 6)     # m^2/s^2
    6.283185
    """
    S0 = _check_stationary(osc, S0)
    return _finite_variance(math.pi * S0 / osc.m / osc.c, S0, "velocity")


def _finite_variance(value: float, S0: float, what: str) -> float:
    if not math.isfinite(value):
        raise ParameterError(
            f"S0 = {S0!r} N^2 s/rad: the {what} variance overflows the float range; allowed a smaller S0"
        )
    return value


#: Largest dt over the oscillator's own time step that the exact doublings of _transition cover (2^60).
MAX_DOUBLING_RATIO = 2.0**60


def _transition(osc: Oscillator, S0: float, dt: float):
    """Exact one-step transition of the state (x, v) over dt: ``Phi`` and the noise covariance ``Q``.

    Van Loan's method on a short step ``h = dt / 2^j`` (no longer than :func:`_default_dt`,
    so ``expm`` of the block ``[[-A, B q B^T], [0, A^T]] h`` never meets a large growth
    ``exp(|s| h)``): it gives ``Phi(h) = exp(A h)`` and
    ``Q(h) = integral_0^h exp(A s) B q B^T exp(A^T s) ds``, ``q = 2 pi S0`` (N^2 s). Then
    ``j`` exact doublings ``Q(2h) = Q(h) + Phi(h) Q(h) Phi(h)^T``, ``Phi(2h) = Phi(h)^2``
    reach any dt, however stiff or lightly damped the oscillator. Independent of the
    closed-form variance.
    """
    a = np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]])
    bqb = np.array([[0.0, 0.0], [0.0, 2.0 * math.pi * S0 / osc.m**2]])
    base = float(_default_dt(osc))
    ratio = dt / base  # Python floats: an overflow gives inf, caught here
    if not ratio <= MAX_DOUBLING_RATIO:
        raise ParameterError(
            f"dt = {dt!r} s is {ratio:.3g} times the oscillator's time step {base:.3g} s: allowed at most "
            f"{MAX_DOUBLING_RATIO:.3g} times (dt <= {MAX_DOUBLING_RATIO * base:.3g} s)"
        )
    j = max(0, math.ceil(math.log2(ratio))) if osc.c > 0.0 else 0
    h = math.ldexp(dt, -j)
    big = np.zeros((4, 4))
    big[:2, :2] = -a
    big[:2, 2:] = bqb
    big[2:, 2:] = a.T
    e = expm(big * h)
    phi = e[2:, 2:].T
    qd = phi @ e[:2, 2:]
    qd = 0.5 * (qd + qd.T)
    for _ in range(j):
        qd = qd + phi @ qd @ phi.T
        qd = 0.5 * (qd + qd.T)
        phi = phi @ phi
    return phi, qd


def _default_dt(osc: Oscillator) -> float:
    """Sample spacing: a tenth of the shorter of the natural period and the slow time constant, s."""
    period = 2.0 * math.pi / osc.natural_frequency
    tau = osc.time_constant
    fast = 1.0 / abs(poles(osc)[1].real) if osc.regime == "overdamped" else tau
    return min(period, tau, 10 * fast) / 10.0


def simulate_white_noise(
    osc: Oscillator,
    S0: float,
    t_end: float,
    *,
    dt: float | None = None,
    n_paths: int = 1,
    seed: int = 0,
):
    """Sample paths of the response from rest to a white-noise force, on ``0, dt, 2 dt, ...``.

    The state (x, v) is advanced by its exact Gaussian transition over each step
    (:func:`scipy.linalg.expm`, Van Loan's covariance integral), so the samples have
    exactly the distribution of the continuous process at the sample times, whatever
    dt: ``X_{n+1} = Phi X_n + w_n``, ``w_n ~ N(0, Q)``; the recursion runs as a linear
    filter (:func:`scipy.signal.lfilter`). Seeded (``numpy.random.default_rng(seed)``).

    Parameters
    ----------
    osc, S0
        As in :func:`white_noise_variance`: the damped oscillator and the two-sided force spectral
        density, N^2 s/rad (>= 0).
    t_end : float
        End of the window, s (> 0).
    dt : float, optional
        Sample spacing, s (> 0); default a tenth of the shorter of the natural period
        and the decay time constant.
    n_paths : int
        Independent paths (1 to 100000).
    seed : int
        Seed of the generator (>= 0).

    Returns
    -------
    (t, x, v)
        Times (s, shape ``(n,)``), displacement (m) and velocity (m/s), shape ``(n_paths, n)``.

    Examples
    --------
    >>> t, x, v = simulate_white_noise(Oscillator(m=1.0, c=0.5, k=20.0), 1.0, 10.0, dt=0.01, n_paths=2)
    >>> x.shape, float(x[0, 0]), float(v[1, 0])
    ((2, 1001), 0.0, 0.0)
    """
    S0, dt, n, n_paths, seed = _simulation_inputs(osc, S0, t_end, dt, n_paths, seed)
    x, v = _filtered_paths(osc, S0, dt, n, n_paths, seed)
    t = np.arange(n) * dt
    return t, x, v


def _simulation_inputs(osc: Oscillator, S0, t_end, dt, n_paths, seed) -> tuple[float, float, int, int, int]:
    """:func:`simulate_white_noise`'s arguments checked in its order: ``(S0, dt, n, n_paths, seed)``, n samples."""
    S0 = _check_stationary(osc, S0)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    dt = _default_dt(osc) if dt is None else check_real("dt", dt, low=0.0, low_open=True, unit="s")
    n_paths = check_int("n_paths", n_paths, low=1, high=100_000)
    seed = check_int("seed", seed, low=0, high=2**63 - 1)
    if not n_paths * (t_end / dt + 1.0) <= SAMPLES_MAX:
        raise ParameterError(
            f"n_paths * (t_end/dt + 1) = {n_paths * (t_end / dt + 1.0):.6g} (n_paths = {n_paths}, t_end = {t_end!r} s, "
            f"dt = {dt!r} s) is out of range: allowed <= {SAMPLES_MAX} samples (memory)"
        )
    n = int(math.floor(t_end / dt + 1e-9)) + 1
    if n < 2:
        raise ParameterError(f"dt = {dt!r} s is out of range: allowed dt <= t_end = {t_end!r} s")
    if n * n_paths > SAMPLES_MAX:
        raise ParameterError(
            f"n_paths * (t_end/dt + 1) = {n * n_paths} is out of range: allowed <= {SAMPLES_MAX} samples (memory)"
        )
    return S0, dt, n, n_paths, seed


def _filtered_paths(osc: Oscillator, S0: float, dt: float, n: int, n_paths: int, seed: int):
    """``n_paths`` seeded paths ``(x, v)`` of ``n`` samples from rest: the exact transition run as a linear filter."""
    phi, qd = _transition(osc, S0, dt)
    lower = _covariance_factor(qd) if S0 > 0.0 else np.zeros((2, 2))
    rng = np.random.default_rng(seed)
    xi = rng.standard_normal((2, n_paths, n))  # the last draw is not used
    w1 = lower[0, 0] * xi[0]
    if lower[0, 1] != 0.0:  # only the eigenvalue factor of a rounding-level singular covariance has this term
        w1 = w1 + lower[0, 1] * xi[1]
    w2 = lower[1, 0] * xi[0] + lower[1, 1] * xi[1]
    # X_j = Phi X_{j-1} + w_{j-1}, X_0 = 0, as a filter (the leading 0 of b is the delay);
    # (zI - Phi)^-1 = adj / det: x = ((z - Phi22) W1 + Phi12 W2) / det, v = (Phi21 W1 + (z - Phi11) W2) / det
    den = [1.0, -(phi[0, 0] + phi[1, 1]), phi[0, 0] * phi[1, 1] - phi[0, 1] * phi[1, 0]]
    x = lfilter([0.0, 1.0, -phi[1, 1]], den, w1, axis=-1) + lfilter([0.0, 0.0, phi[0, 1]], den, w2, axis=-1)
    v = lfilter([0.0, 0.0, phi[1, 0]], den, w1, axis=-1) + lfilter([0.0, 1.0, -phi[0, 0]], den, w2, axis=-1)
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        raise ParameterError(
            f"S0 = {S0!r} N^2 s/rad on the oscillator (m = {osc.m!r} kg, c = {osc.c!r} N s/m, k = {osc.k!r} N/m) "
            f"overflows the sampled response (stationary variance pi S0/(k c) = {math.pi * S0 / (osc.k * osc.c):.3g}"
            " m^2): allowed S0 and m, c, k whose noise covariance and its square root are finite floats"
        )
    return x, v


@dataclass(frozen=True, kw_only=True)
class MonteCarlo:
    """A seeded Monte Carlo estimate of the stationary displacement and velocity variances."""

    variance: float  # mean of x^2 over paths and samples after the burn-in, m^2
    standard_error: float  # of ``variance``, from the spread of the per-path means, m^2
    velocity_variance: float  # mean of v^2, m^2/s^2
    velocity_standard_error: float  # m^2/s^2
    n_paths: int  # independent paths, 1
    n_samples: int  # samples per path after the burn-in, 1
    dt: float  # sample spacing, s
    burn_in: float  # discarded start of each path (from rest), s
    seed: int  # generator seed


def white_noise_monte_carlo(
    osc: Oscillator,
    S0: float,
    n_paths: int = 200,
    *,
    duration: float | None = None,
    dt: float | None = None,
    seed: int = 0,
) -> MonteCarlo:
    """Estimate the stationary variances by simulation (:func:`simulate_white_noise`).

    Each path starts from rest; the first 12 decay time constants are discarded (the
    variance's start-up transient is then below ``exp(-24)`` of its value), and
    ``x^2``, ``v^2`` are averaged over the rest and over paths. The standard error
    comes from the spread of the per-path means (paths are independent, samples
    within a path are not).

    The transition over each step is exact (:func:`simulate_white_noise`), so the step
    only sets how many samples are averaged, not an error: by default a path records
    :data:`MC_SAMPLES` steps over 100 decay time constants (``dt = tau / 20``, about the
    samples that are not strongly correlated), so the cost is the same for every damping,
    however light (``tau = 2m/c`` long) or heavy (a stiff fast mode).

    Parameters
    ----------
    osc, S0
        As in :func:`white_noise_variance`: m (kg), c (N s/m, > 0), k (N/m); two-sided force spectral
        density, N^2 s/rad (>= 0).
    n_paths : int
        Independent paths (2 to 100000).
    duration : float, optional
        Recorded time per path after the burn-in, s; default 100 time constants.
    dt : float, optional
        Sample spacing, s (> 0); default ``duration / MC_SAMPLES``.
    seed : int
        Seed (>= 0).

    Returns
    -------
    MonteCarlo

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> mc = white_noise_monte_carlo(osc, 1.0, n_paths=50)
    >>> bool(abs(mc.variance - white_noise_variance(osc, 1.0)) < 4 * mc.standard_error)
    True
    """
    n_paths, burn, duration, dt = _monte_carlo_window(osc, n_paths, duration, dt)
    px, pv, keep = _path_means(osc, S0, n_paths, burn + duration, dt, burn, seed)
    return _monte_carlo_record(px, pv, keep, S0=S0, n_paths=n_paths, duration=duration, dt=dt, burn=burn, seed=seed)


def _monte_carlo_window(osc: Oscillator, n_paths, duration, dt) -> tuple[int, float, float, float]:
    """:func:`white_noise_monte_carlo`'s oscillator, paths and window checked: ``(n_paths, burn-in, duration, dt)``."""
    check_oscillator(osc)
    _check_stable(osc, "a stationary random response")
    n_paths = check_int("n_paths", n_paths, low=2, high=100_000)
    tau = osc.time_constant
    burn = 12.0 * tau
    duration = 100.0 * tau if duration is None else check_real("duration", duration, low=0.0, low_open=True, unit="s")
    dt = duration / MC_SAMPLES if dt is None else check_real("dt", dt, low=0.0, low_open=True, unit="s")
    total = n_paths * ((burn + duration) / dt + 1.0)
    if not total <= MC_TOTAL_MAX:
        raise ParameterError(
            f"n_paths * (burn-in + duration) / dt = {total:.3g} samples (n_paths = {n_paths}, "
            f"duration = {duration!r} s, dt = {dt!r} s, burn-in {burn:.3g} s): "
            f"allowed at most {MC_TOTAL_MAX:g} samples in all (run time)"
        )
    return n_paths, burn, duration, dt


def _path_means(osc: Oscillator, S0, n_paths: int, t_end: float, dt: float, burn: float, seed):
    """Per-path means of ``x^2`` and ``v^2`` after the burn-in, simulated in chunks of paths (one seed each from
    ``SeedSequence(seed)``); with the last chunk's mask of the samples kept."""
    chunk = max(1, min(n_paths, MC_CHUNK // max(1, int(t_end / dt) + 1)))
    ss = np.random.SeedSequence(check_int("seed", seed, low=0, high=2**63 - 1))
    mx, mv = [], []
    done = 0
    for child in ss.spawn(math.ceil(n_paths / chunk)):
        size = min(chunk, n_paths - done)
        t, x, v = simulate_white_noise(osc, S0, t_end, dt=dt, n_paths=size, seed=int(child.generate_state(1)[0]))
        keep = t >= burn
        mx.append(np.mean(x[:, keep] ** 2, axis=1))
        mv.append(np.mean(v[:, keep] ** 2, axis=1))
        done += size
    return np.concatenate(mx), np.concatenate(mv), keep


def _monte_carlo_record(px, pv, keep, *, S0, n_paths, duration, dt, burn, seed) -> MonteCarlo:
    """The estimate from the per-path means ``px``, ``pv`` (refused when their statistics overflow)."""
    with np.errstate(over="ignore", invalid="ignore"):
        stats = [float(px.mean()), float(px.std(ddof=1)), float(pv.mean()), float(pv.std(ddof=1))]
    if not all(math.isfinite(x) for x in stats):
        raise ParameterError(
            f"duration = {duration!r} s, dt = {dt!r} s, S0 = {S0!r}: the sample variances overflow the float range; "
            "allowed a shorter step or a smaller load"
        )
    return MonteCarlo(
        variance=stats[0],
        standard_error=stats[1] / math.sqrt(px.size),
        velocity_variance=stats[2],
        velocity_standard_error=stats[3] / math.sqrt(pv.size),
        n_paths=n_paths,
        n_samples=int(np.count_nonzero(keep)),
        dt=dt,
        burn_in=burn,
        seed=seed,
    )


def white_noise_force_variance(osc: Oscillator, S0: float) -> float:
    """Stationary variance of the force ``k x + c v`` passed to the support under a white force, N^2.

    ``x`` and ``v`` are uncorrelated in the stationary state, so the variance is
    ``k^2 var x + c^2 var v = pi S0 (k / c + c / m)``: it grows without bound as ``c -> 0`` and
    as ``c -> inf``, and is least at ``c = sqrt(k m)`` (:func:`white_noise_force_optimum`).

    Examples
    --------
    >>> round(white_noise_force_variance(Oscillator(m=1.0, c=0.5, k=20.0), 0.1), 4)     # N^2
    12.7235
    """
    S0 = _check_stationary(osc, S0, "a stationary force variance")
    return math.pi * S0 * (osc.k / osc.c + osc.c / osc.m)


def white_noise_force_optimum(m: float, k: float, S0: float) -> tuple[float, float]:
    """Damping (N s/m) that minimises the transmitted-force variance, ``sqrt(k m)``, and that variance, N^2.

    Examples
    --------
    >>> c, var = white_noise_force_optimum(1.0, 20.0, 0.1)
    >>> round(c, 4), round(var, 4)
    (4.4721, 2.8099)
    """
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    S0 = _check_S0(S0)
    c = math.sqrt(k * m)
    return c, 2.0 * math.pi * S0 * math.sqrt(k / m)


def _covariance_factor(qd: np.ndarray) -> np.ndarray:
    """L with L L^T = qd: Cholesky, or for a covariance that rounding left singular or slightly indefinite
    (a very stiff or very damped step), the symmetric square root with its negative eigenvalues set to 0."""
    try:
        return np.linalg.cholesky(qd)
    except np.linalg.LinAlgError:
        w, v = np.linalg.eigh(0.5 * (qd + qd.T))
        if not np.all(np.isfinite(w)) or w.max() <= 0.0:
            raise ParameterError(
                f"the step covariance of the white-noise load is not a covariance (eigenvalues {w.tolist()}): "
                "allowed a dt or an oscillator for which it is positive semi-definite"
            ) from None
        return v * np.sqrt(np.clip(w, 0.0, None))
