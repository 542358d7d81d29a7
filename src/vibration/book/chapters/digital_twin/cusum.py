"""The CUSUM's run lengths: measured on seeded records, and from theory (the Markov-chain method).

The detector of :func:`vibration.physics.twin.detect_change` adds ``z = r^2 / sigma^2 - 1 - nu`` per sample
and alarms when the running sum (reset at zero) exceeds ``h``. For a white Gaussian residual of variance
``sigma^2`` plus a known response difference ``d_n``, ``u = r^2 / sigma^2`` is the square of a normal variable of
mean ``mu_n = d_n / sigma`` and unit variance, independent from sample to sample, so the statistic is a Markov
chain. Brook & Evans (1972) discretise its state ``[0, h]`` into ``N`` cells: the average run length (ARL) to an
alarm of a stationary chain is ``(I - Q)^-1 1`` from the zero state, and for a change that varies with time the
distribution over the cells can be pushed forward one sample at a time, which gives the alarm-time distribution,
hence the detection probability and the mean delay on the same record the Monte Carlo uses.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy.special import ndtr

from vibration.physics.model import ParameterError

#: Cells of the Markov chain (the ARL is extrapolated from N and 2N cells).
CELLS = 150
#: The forward propagation stops when the chance of no alarm yet falls below this.
SURVIVAL_TOL = 1e-9


@njit(cache=True)
def _solve(a, b):  # pragma: no cover - compiled
    """Gaussian elimination with partial pivoting, single-threaded (a and b are overwritten; returns x)."""
    n = b.size
    for col in range(n):
        piv = col
        for r in range(col + 1, n):
            if abs(a[r, col]) > abs(a[piv, col]):
                piv = r
        if piv != col:
            for c in range(n):
                a[col, c], a[piv, c] = a[piv, c], a[col, c]
            b[col], b[piv] = b[piv], b[col]
        d = a[col, col]
        for r in range(col + 1, n):
            f = a[r, col] / d
            if f != 0.0:
                for c in range(col, n):
                    a[r, c] -= f * a[col, c]
                b[r] -= f * b[col]
    x = np.empty(n)
    for r in range(n - 1, -1, -1):
        acc = b[r]
        for c in range(r + 1, n):
            acc -= a[r, c] * x[c]
        x[r] = acc / a[r, r]
    return x


def _u_cdf(x, mu):
    """P((Z + mu)^2 <= x) for a standard normal Z, x an array (0 below zero)."""
    s = np.sqrt(np.maximum(x, 0.0))
    return np.where(x > 0.0, ndtr(s - mu) - ndtr(-s - mu), 0.0)


def _z_cdf(s, mu, drift, scale=1.0):
    """P(z <= s) for the increment z = scale * u - 1 - drift."""
    return _u_cdf((np.asarray(s, float) + 1.0 + drift) / scale, mu)


def _grid(h: float, cells: int) -> float:
    return h / (cells - 0.5)


def arl_markov(h: float, drift: float, mu: float = 0.0, *, cells: int = CELLS, scale: float = 1.0) -> float:
    """Average run length (samples) of the zero-start CUSUM for i.i.d. increments, Brook-Evans with ``cells`` cells.

    State j stands for g in [(j - 1/2) D, (j + 1/2) D) (state 0 holds the reset g = 0), D = h / (cells - 1/2).

    Examples
    --------
    >>> round(arl_markov(0.5, 1.0) / arl_markov(0.5, 1.0, cells=600), 2)    # converged in the cell count
    1.0
    """
    if not (h > 0 and math.isfinite(h) and cells >= 10):
        raise ParameterError(f"h = {h!r}, cells = {cells!r}: allowed h > 0 and at least 10 cells")
    d = _grid(h, cells)
    g = np.arange(cells) * d
    edges = (np.arange(cells) + 0.5) * d  # upper edge of each state
    cdf = _z_cdf(edges[None, :] - g[:, None], mu, drift, scale)  # P(g + z < upper edge of j)
    q = np.empty((cells, cells))
    q[:, 0] = cdf[:, 0]
    q[:, 1:] = np.diff(cdf, axis=1)
    arl = _solve(np.eye(cells) - q, np.ones(cells))
    return float(arl[0])


def arl_theory(
    h: float, drift: float, mu: float = 0.0, *, cells: int = CELLS, scale: float = 1.0
) -> tuple[float, float]:
    """ARL (samples) extrapolated from ``cells`` and ``2 cells`` cells (error ~ 1/N^2), and its discretisation error."""
    a, b = arl_markov(h, drift, mu, cells=cells, scale=scale), arl_markov(h, drift, mu, cells=2 * cells, scale=scale)
    arl, err = b + (b - a) / 3.0, abs(b - a) / 3.0
    if not (arl > 0 and err < 0.05 * arl and math.isfinite(arl)):
        return math.nan, math.nan  # beyond the chain's numerical reach (an astronomically long ARL)
    return arl, err


def arl_estimated_sigma(h: float, drift: float, n_cal: int, *, nodes: int = 7) -> tuple[float, float]:
    """ARL (samples) when each record divides by its own noise variance estimated from ``n_cal`` samples.

    The calibration estimate is ``s^2 = sigma^2 chi2_(n_cal - 2) / (n_cal - 5)`` (two initial-state values fitted),
    so each record's increments are ``u sigma^2 / s^2``; alarms over many records come at the mean rate
    ``E[1 / ARL(s)]``, taken by Gauss-Hermite quadrature over the (nearly normal) spread of ``s^2``. Returns the
    ARL and its discretisation error.
    """
    from numpy.polynomial.hermite_e import hermegauss

    if n_cal < 10:
        raise ParameterError(f"n_cal = {n_cal!r}: allowed at least 10 calibration samples")
    x, w = hermegauss(nodes)
    w = w / w.sum()
    mean = (n_cal - 2.0) / (n_cal - 5.0)
    spread = mean * math.sqrt(2.0 / (n_cal - 2.0))
    rates, errs = [], []
    for xi in x:
        arl, err = arl_theory(h, drift, scale=1.0 / (mean + spread * xi))
        if math.isnan(arl):
            return math.nan, math.nan
        rates.append(1.0 / arl)
        errs.append(err / arl**2)
    rate = float(np.dot(w, rates))
    return 1.0 / rate, float(np.dot(w, errs)) / rate**2


def alarm_distribution(mu, h: float, drift: float, *, cells: int = CELLS, scale: float = 1.0) -> np.ndarray:
    """P(first alarm at sample n) of the zero-start CUSUM driven by ``u_n = scale (Z_n + mu_n)^2``.

    ``mu`` (n,) is the response difference over the noise's standard deviation at each monitored sample.
    Returns (n,) probabilities (they sum to the chance of an alarm within the record).
    """
    mu = np.asarray(mu, float)
    d = _grid(h, cells)
    offsets = np.arange(-(cells - 1), cells) * d  # j - i in cells
    i_vals = np.arange(cells) * d
    p = np.zeros(cells)
    p[0] = 1.0
    out = np.zeros(mu.size)
    survival = 1.0
    for n in range(mu.size):
        w_hi = _z_cdf(offsets + 0.5 * d, mu[n], drift, scale)
        w = np.diff(np.concatenate([_z_cdf([offsets[0] - 0.5 * d], mu[n], drift, scale), w_hi]))
        to_zero = _z_cdf(0.5 * d - i_vals, mu[n], drift, scale)
        new = np.empty(cells)
        new[0] = float(p @ to_zero)
        new[1:] = np.convolve(p, w)[cells : 2 * cells - 1]
        total = float(new.sum())
        out[n] = survival - total
        survival = total
        p = new
        if survival < SURVIVAL_TOL:
            break
    return np.maximum(out, 0.0)


@njit(cache=True)
def _restart_alarms(z, thresholds, counts):  # pragma: no cover - compiled
    """Alarms of a CUSUM restarted at zero after each alarm, per threshold (added to ``counts``)."""
    for j in range(thresholds.size):
        h = thresholds[j]
        g = 0.0
        for i in range(z.size):
            g = g + z[i]
            if g < 0.0:
                g = 0.0
            if g > h:
                counts[j] += 1
                g = 0.0


def restart_alarms(z, thresholds) -> np.ndarray:
    """Alarm count of the restarted CUSUM of increments ``z`` at each threshold."""
    counts = np.zeros(len(thresholds), dtype=np.int64)
    _restart_alarms(np.asarray(z, float), np.asarray(thresholds, float), counts)
    return counts


@dataclass(frozen=True, kw_only=True)
class RunLengths:
    """Average run length to a false alarm: measured (restarted CUSUM on healthy records) and Markov-chain theory."""

    thresholds: np.ndarray  # (T,) h, 1
    alarms: np.ndarray  # (T,) false alarms over all healthy records (restarting after each)
    samples: int  # monitored samples over all healthy records
    dt: float  # s
    theory: np.ndarray  # (T,) ARL, samples
    theory_error: np.ndarray  # (T,) discretisation error of the theory, samples

    @property
    def measured(self) -> np.ndarray:
        """(T,) monitored samples per alarm (nan: no alarm), samples."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(self.alarms > 0, self.samples / np.maximum(self.alarms, 1), np.nan)

    @property
    def stderr(self) -> np.ndarray:
        """(T,) standard error of :attr:`measured` (alarm count Poisson: ARL / sqrt(alarms)), samples."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return self.measured / np.sqrt(np.maximum(self.alarms, 1))

    @property
    def lower95(self) -> np.ndarray:
        """(T,) one-sided 95 % lower bound of the ARL from the alarm count (exact Poisson), samples."""
        from scipy.stats import chi2

        return 2.0 * self.samples / chi2.ppf(0.95, 2 * self.alarms + 2)


@dataclass(frozen=True, kw_only=True)
class DelayTheory:
    """Markov-chain prediction for the faulty records of one fault at one threshold."""

    threshold: float  # h, 1
    detection_probability: float  # P(alarm at or after the fault start, within the record), 1
    early_alarm_probability: float  # P(alarm before the fault starts), 1
    mean_delay: float  # E[alarm - fault start | alarm at or after it], s
