"""Uncertainty of a whole-trace free-decay fit: Jacobian, naive and Newey-West standard errors, residual whiteness.

Encoder rounding errors are correlated where the wheel moves slowly, so besides the naive
``s^2 (J^T J)^-1`` the fit reports a Newey-West sandwich (Bartlett kernel) and the larger of the two;
the Durbin-Watson statistic and the Ljung-Box p-value say how far the residuals are from white.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import stats

__all__ = ["central_jacobian", "hac_cov", "standard_errors", "whiteness"]


def whiteness(r: np.ndarray) -> tuple[float, float]:
    """Durbin-Watson statistic and Ljung-Box p-value (20 lags or n/5) of the residuals ``r``."""
    dw = float(np.sum(np.diff(r) ** 2) / np.sum(r * r))
    n = r.size
    h = int(min(20, max(1, n // 5)))
    rc = r - r.mean()
    den = float(rc @ rc)
    acf = np.array([float(rc[k:] @ rc[:-k]) / den for k in range(1, h + 1)])
    q = n * (n + 2) * float(np.sum(acf**2 / (n - np.arange(1, h + 1))))
    return dw, float(stats.chi2.sf(q, h))


def hac_cov(J: np.ndarray, r: np.ndarray, lags: int, *, bread: np.ndarray) -> np.ndarray:
    """Newey-West sandwich covariance (Bartlett kernel, ``lags`` lags) of the parameters, ``bread = (J^T J)^-1``."""
    g = J * r[:, None]
    meat = g.T @ g
    for k in range(1, lags + 1):
        w = 1.0 - k / (lags + 1.0)
        gk = g[k:].T @ g[:-k]
        meat += w * (gk + gk.T)
    return bread @ meat @ bread


def central_jacobian(resid, x0: np.ndarray, n_rows: int, *, nonnegative) -> np.ndarray:
    """Central-difference Jacobian of ``resid`` at ``x0`` (``n_rows`` residuals).

    A parameter flagged in ``nonnegative`` steps down no further than 0.
    """
    J = np.empty((n_rows, x0.size))
    scale = np.array([max(abs(v), 1e-3) for v in x0])
    for j in range(x0.size):
        h = 1e-6 * scale[j]
        xp, xm = x0.copy(), x0.copy()
        xp[j] += h
        xm[j] = max(xm[j] - h, 0.0) if nonnegative[j] else xm[j] - h
        J[:, j] = (resid(xp) - resid(xm)) / (xp[j] - xm[j])
    return J


def standard_errors(J: np.ndarray, r: np.ndarray, lags: int) -> tuple[list[float], list[float]]:
    """Naive and Newey-West standard errors of the parameters (the columns of ``J``) from the residuals ``r``."""
    n, p_free = r.size, J.shape[1]
    rss = float(r @ r)
    s2 = rss / max(1, n - p_free)
    bread = np.linalg.pinv(J.T @ J)
    cov_naive = s2 * bread
    cov_hac = hac_cov(J, r, lags, bread=bread) * n / max(1, n - p_free)
    naive = [float(math.sqrt(max(cov_naive[j, j], 0.0))) for j in range(p_free)]
    hac = [float(math.sqrt(max(cov_hac[j, j], 0.0))) for j in range(p_free)]
    return naive, hac
