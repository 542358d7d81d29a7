"""Model validation: residual tests, records that break the assumptions, and first-order coverage predictions.

The identification's intervals (:func:`.identify`) are honest only under its model of the data:
force measured without noise, white Gaussian noise on the response, a linear spring. This
module makes records that break one assumption at a time (:func:`violated_record`: noise on the
force, noise on both channels, coloured (AR(1)) sensor noise, an unmodelled cubic spring) and the
tests that reveal the break from the residual alone, without the truth:

* :func:`ljung_box` -- whiteness of the output-error residual, ``Q = N (N + 2) sum_l rho_l^2 / (N - l)``
  over lags 1..L, chi-square with L degrees of freedom under white residuals;
* :func:`input_correlation` -- correlation of the residual with the measured force at lags 0..L-1,
  ``N r^T R^-1 r / lambda`` (Ljung, *System Identification*, 16.6), chi-square with the rank of R.

:func:`predicted_coverage` gives the coverage the Student-t intervals should have to first order
when the noise is Gaussian with a known covariance (white or AR(1)): the sandwich
``(J^T J)^-1 J^T Sigma J (J^T J)^-1`` against the ``sigma^2 (J^T J)^-1`` the intervals assume, with
J the Jacobian of the exact sampled response at the truth. It is independent of the Monte Carlo
and of the fitting code.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import signal
from scipy.stats import chi2, norm
from scipy.stats import t as student_t

from ..checks import check_oscillator
from ..model import Oscillator, ParameterError, check_int, check_real
from .measurements import _signal
from .sampled import sampled_response

__all__ = [
    "WHITENESS_LAGS",
    "binomial_halfwidth",
    "cubic_response",
    "input_correlation",
    "ljung_box",
    "predicted_coverage",
]

#: Lags of the residual tests (Ljung-Box and input correlation), samples.
WHITENESS_LAGS = 20


def binomial_halfwidth(successes, runs: int, z: float = 1.959963984540054) -> np.ndarray:
    """Half-width of the Wilson 95 % score interval of a proportion ``successes / runs``.

    Unlike the normal approximation it does not vanish at 0 or ``runs`` successes.

    Examples
    --------
    >>> [round(float(v), 4) for v in binomial_halfwidth([190, 0], 200)]
    [0.0311, 0.0094]
    """
    runs = check_int("runs", runs, low=1, high=10**9)
    s = np.asarray(successes, dtype=float)
    if np.any(s < 0) or np.any(s > runs):
        raise ParameterError(f"successes = {successes!r:.60}: allowed 0 to runs = {runs}")
    p = s / runs
    return z * np.sqrt(p * (1.0 - p) / runs + z * z / (4.0 * runs * runs)) / (1.0 + z * z / runs)


def _lags(lags, n: int) -> int:
    return check_int("lags", lags, low=1, high=max(1, n // 4))


def ljung_box(residual, lags: int = WHITENESS_LAGS) -> tuple[float, float]:
    """Ljung-Box portmanteau statistic of a residual and its p-value (chi-square, ``lags`` degrees of freedom).

    Parameters
    ----------
    residual : array_like
        Output-error residual, m or m/s^2 (at least 4 ``lags`` samples).
    lags : int
        Autocorrelation lags 1..``lags`` summed, samples.

    Returns
    -------
    (float, float)
        Q (1) and the probability of a Q at least as large for white noise (1).

    Examples
    --------
    >>> q, p = ljung_box(np.random.default_rng(0).standard_normal(2000))
    >>> bool(p > 0.01)
    True
    >>> q, p = ljung_box(np.cumsum(np.random.default_rng(0).standard_normal(2000)))
    >>> bool(p < 1e-6)
    True
    """
    r = _signal("residual", residual)
    n = r.size
    lags = _lags(lags, n)
    r = r - r.mean()
    c0 = float(r @ r)
    if not c0 > 0.0:
        raise ParameterError("residual is constant: allowed a residual that varies")
    rho = np.array([float(r[lag:] @ r[:-lag]) for lag in range(1, lags + 1)]) / c0
    q = n * (n + 2.0) * float(np.sum(rho**2 / (n - np.arange(1, lags + 1))))
    return q, float(chi2.sf(q, lags))


def input_correlation(residual, force, lags: int = WHITENESS_LAGS) -> tuple[float, float, int]:
    """Test that the residual is uncorrelated with the measured force at lags 0..``lags`` - 1.

    ``zeta = N r^T R^+ r / lambda`` with ``r = Phi^T e / N``, ``R = Phi^T Phi / N`` (rows of
    ``Phi``: the force at lags 0..L-1), ``lambda`` the residual's mean square; ``R^+`` keeps the
    eigenvalues above 1e-9 of the largest (a band-limited force makes R nearly singular), and the
    degrees of freedom are their number.

    Returns
    -------
    (float, float, int)
        zeta (1), its p-value (1) and the degrees of freedom.

    Examples
    --------
    >>> rng = np.random.default_rng(1)
    >>> u = rng.standard_normal(3000)
    >>> bool(input_correlation(rng.standard_normal(3000), u)[1] > 0.01)
    True
    >>> bool(input_correlation(np.convolve(u, [0.0, 0.3, 0.2])[:3000] + rng.standard_normal(3000), u)[1] < 1e-6)
    True
    """
    e = _signal("residual", residual)
    u = _signal("force", force, e.size)
    lags = _lags(lags, e.size)
    u = u - u.mean()
    scale = float(np.sqrt(np.mean(u * u)))
    if not scale > 0.0:
        raise ParameterError("force is constant: allowed a force that varies")
    u = u / scale
    phi = np.column_stack([u[lags - 1 - j : e.size - j] for j in range(lags)])
    ee = e[lags - 1 :]
    n = ee.size
    r = phi.T @ ee / n
    big_r = phi.T @ phi / n
    lam = float(ee @ ee) / n
    w, v = np.linalg.eigh(big_r)
    keep = w > 1e-9 * w[-1]
    proj = v[:, keep].T @ r
    zeta = n * float(np.sum(proj**2 / w[keep])) / lam
    dof = int(np.count_nonzero(keep))
    return zeta, float(chi2.sf(zeta, dof)), dof


def cubic_response(osc: Oscillator, k3: float, t, *, force, substeps: int = 8) -> np.ndarray:
    """Displacement (m) of ``m x'' + c x' + k x + k3 x^3 = F`` from rest, F linear between samples.

    Classical Runge-Kutta with ``substeps`` steps per sampling interval (the force is linear inside each
    interval, so no step straddles a kink). With ``k3 = 0`` it matches the exact sampled response to about
    1e-8 of its amplitude, and with ``k3 > 0`` a tight ``solve_ivp`` (both checked by the tests).

    Examples
    --------
    >>> from vibration.physics.twin import random_force
    >>> t = np.arange(0.0, 10.0, 0.02)
    >>> f = random_force(t, seed=1)
    >>> bool(np.max(np.abs(cubic_response(Oscillator(m=1, c=0.5, k=20), 0.0, t, force=f) - sampled_response(
    ...     Oscillator(m=1, c=0.5, k=20), t, f).x)) < 1e-8)
    True
    """
    check_oscillator(osc)
    k3 = check_real("k3", k3, unit="N/m^3")
    substeps = check_int("substeps", substeps, low=1, high=1000)
    t = _signal("t", t)
    force = _signal("force", force, t.size)
    h = float(t[1] - t[0]) / substeps
    m, c, k = osc.m, osc.c, osc.k
    fl = force.tolist()
    out = [0.0] * t.size
    x = v = 0.0

    def acc(x, v, f):
        return (f - c * v - k * x - k3 * x * x * x) / m

    for i in range(t.size - 1):
        f0, df = fl[i], (fl[i + 1] - fl[i]) / substeps
        for j in range(substeps):
            fa = f0 + j * df
            fm, fb = fa + 0.5 * df, fa + df
            a1 = acc(x, v, fa)
            x2, v2 = x + 0.5 * h * v, v + 0.5 * h * a1
            a2 = acc(x2, v2, fm)
            x3, v3 = x + 0.5 * h * v2, v + 0.5 * h * a2
            a3 = acc(x3, v3, fm)
            x4, v4 = x + h * v3, v + h * a3
            a4 = acc(x4, v4, fb)
            x, v = x + h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4), v + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
        if not abs(x) < 1e12:
            raise ParameterError(f"k3 = {k3!r} N/m^3: the cubic oscillator's response diverged; allowed a bounded one")
        out[i + 1] = x
    return np.array(out)


def _ar1(n: int, colour: float, rng) -> np.ndarray:
    """Stationary AR(1) noise of unit variance and lag-one correlation ``colour``."""
    w = rng.standard_normal(n + 1)
    if colour == 0.0:
        return w[1:]
    y, _ = signal.lfilter([math.sqrt(1.0 - colour * colour)], [1.0, -colour], w[1:], zi=[colour * w[0]])
    return y


def _response_jacobian(osc: Oscillator, t, force) -> np.ndarray:
    """(N, 5) derivative of the exact sampled displacement with respect to m, c, k, x0, v0 at ``osc``."""
    base = (osc.m, osc.c, osc.k)
    cols = []
    for j in range(3):
        step = 1e-5 * base[j]
        hi, lo = list(base), list(base)
        hi[j] += step
        lo[j] -= step
        cols.append(
            (
                sampled_response(Oscillator(m=hi[0], c=hi[1], k=hi[2]), t, force).x
                - sampled_response(Oscillator(m=lo[0], c=lo[1], k=lo[2]), t, force).x
            )
            / (2.0 * step)
        )
    zero = np.zeros_like(force)
    cols.append(sampled_response(osc, t, zero, x0=1.0, v0=0.0).x)
    cols.append(sampled_response(osc, t, zero, x0=0.0, v0=1.0).x)
    return np.column_stack(cols)


def predicted_coverage(osc: Oscillator, t, force, *, colour: float = 0.0) -> np.ndarray:
    """First-order coverage of the Student-t 95 % intervals of m, c, k under Gaussian AR(1) sensor noise.

    The intervals use ``s^2 (J^T J)^-1`` with ``s^2`` the residual variance (to first order the noise's
    marginal variance ``sigma^2``); the estimate's covariance is the sandwich
    ``(J^T J)^-1 J^T Sigma J (J^T J)^-1`` with ``Sigma_ij = sigma^2 colour^|i - j|``. The coverage is
    ``2 Phi(q sd_assumed / sd_true) - 1`` (q the Student-t quantile); it does not depend on sigma, and is
    0.95 (to the t/normal difference) for white noise.

    Parameters
    ----------
    osc : Oscillator
        The truth: m (kg), c (N s/m), k (N/m).
    t, force : array_like
        Sample times (s) and the force (N) of the design.
    colour : float
        Lag-one correlation of the noise, 1 (0 to 0.99).

    Examples
    --------
    >>> from vibration.physics.twin import random_force
    >>> t = np.arange(0.0, 30.0, 0.02)
    >>> p = predicted_coverage(Oscillator(m=1.0, c=0.5, k=20.0), t, random_force(t), colour=0.0)
    >>> [round(float(v), 3) for v in p]
    [0.95, 0.95, 0.95]
    """
    check_oscillator(osc)
    colour = check_real("colour", colour, low=0.0, high=0.99)
    t = _signal("t", t)
    force = _signal("force", force, t.size)
    jac = _response_jacobian(osc, t, force)
    fwd = signal.lfilter([1.0], [1.0, -colour], jac, axis=0)
    bwd = signal.lfilter([1.0], [1.0, -colour], jac[::-1], axis=0)[::-1]
    sj = fwd + bwd - jac  # Sigma J / sigma^2
    inv = np.linalg.inv(jac.T @ jac)
    assumed = np.diag(inv)[:3]
    true = np.diag(inv @ (jac.T @ sj) @ inv)[:3]
    q = float(student_t.ppf(0.975, t.size - 5))
    return 2.0 * norm.cdf(q * np.sqrt(assumed / true)) - 1.0
