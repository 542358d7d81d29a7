"""Least-squares fit of one harmonic, ``offset + amplitude sin(omega t + phase)``, to a sampled signal."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from vibration.physics.lab._checks import time_and_signal
from vibration.physics.model import check_real

#: Largest number of trial frequencies of the periodogram when omega is estimated (4 per
#: resolution width 2 pi / duration, at least 200).
MAX_TRIAL = 20_000
#: Largest number of samples the periodogram uses (an even subset; the refinement uses all).
MAX_GRID_SAMPLES = 5_000


@dataclass(frozen=True, kw_only=True)
class HarmonicFit:
    """``offset + amplitude sin(omega t + phase)`` fitted by least squares.

    Attributes
    ----------
    omega : float
        Angular frequency (rad/s), given or estimated.
    amplitude : float
        Amplitude (units of y), >= 0.
    phase : float
        Phase (rad) in (-pi, pi].
    offset : float
        Mean level (units of y).
    stderr : dict
        Standard errors keyed "omega" (0 when omega was given), "amplitude", "phase", "offset",
        from ``s^2 (J^T J)^-1``.
    residual_rms : float
        Root mean square of the residuals (units of y).
    n : int
        Number of samples.
    """

    omega: float
    amplitude: float
    phase: float
    offset: float
    stderr: dict = field(repr=False)
    residual_rms: float
    n: int

    def predict(self, t) -> np.ndarray:
        """The fitted harmonic at the times ``t`` (s)."""
        return self.offset + self.amplitude * np.sin(self.omega * np.asarray(t, dtype=float) + self.phase)


def _linear(t, y, omega):
    X = np.column_stack([np.sin(omega * t), np.cos(omega * t), np.ones_like(t)])
    coef, *_ = np.linalg.lstsq(X, y, rcond=None)
    r = y - X @ coef
    return coef, float(r @ r)


def _rss_grid(x, y, grid, chunk=256):
    """Residual sum of squares of the linear harmonic fit at every trial frequency (vectorised)."""
    yc = y - y.mean()
    out = np.empty(grid.size)
    for i in range(0, grid.size, chunk):
        w = grid[i : i + chunk, None]
        S, C = np.sin(w * x), np.cos(w * x)
        S = S - S.mean(axis=1, keepdims=True)  # the offset column, projected out
        C = C - C.mean(axis=1, keepdims=True)
        ss, cc, sc = (S * S).sum(1), (C * C).sum(1), (S * C).sum(1)
        sy, cy = S @ yc, C @ yc
        det = ss * cc - sc * sc
        det = np.where(det > 0, det, np.inf)
        explained = (cc * sy * sy - 2 * sc * sy * cy + ss * cy * cy) / det
        out[i : i + chunk] = float(yc @ yc) - explained
    return out


def _wrap(phase: float) -> float:
    p = math.remainder(phase, 2.0 * math.pi)
    return math.pi if p == -math.pi else p


def harmonic_fit(t, y, omega=None) -> HarmonicFit:
    """Fit ``offset + amplitude sin(omega t + phase)`` to samples at any strictly increasing times.

    With ``omega`` given the problem is linear (sine, cosine and constant columns). Without it,
    omega is first located on a least-squares periodogram (the residual sum of squares of the
    linear fit, which works on non-uniform grids) at 4 trial frequencies per resolution width
    2 pi / duration from 2 pi / duration to pi / (median time step) (at most 20 000, on at
    most 5 000 evenly chosen samples), then refined together with the
    other three by nonlinear least squares (:func:`scipy.optimize.least_squares`). Standard
    errors from ``s^2 (J^T J)^-1`` with ``s^2 = RSS / (n - p)``: valid for independent residuals.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing, 20 to 1 000 000 samples.
    y : array_like
        Signal (any unit), same length, finite, not constant.
    omega : float, optional
        Angular frequency (rad/s), > 0; estimated from ``y`` when ``None``.

    Returns
    -------
    HarmonicFit
        omega in rad/s, phase in rad, amplitude and offset in the units of y.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0.0, 10.0, 201)
    >>> f = harmonic_fit(t, 0.5 + 2.0 * np.sin(3.0 * t - 1.0))
    >>> round(f.omega, 9), round(f.amplitude, 9), round(f.phase, 9), round(f.offset, 9)
    (3.0, 2.0, -1.0, 0.5)
    """
    ta, ya = time_and_signal(t, y, t_name="t", y_name="y")
    n = ta.size
    tc = 0.5 * (ta[0] + ta[-1])  # centre the time for conditioning; the phase is converted back
    x = ta - tc
    if omega is not None:
        w = check_real("omega", omega, low=0.0, low_open=True, high=1e9, unit="rad/s")
        a, b, c, rss, cov = _fit_at(x, ya, w)
        var_w = 0.0
    else:
        a, b, c, w, rss, cov = _fit_with_frequency(ta, x, ya)
        var_w = cov[3, 3]
    amp, phase_c, var_amp, var_phc, g_ph = _polar(a, b, cov[:2, :2])
    # phase at t = 0: phase_c - w tc
    if omega is None:
        var_ph = var_phc + tc * tc * var_w - 2.0 * tc * float(g_ph @ cov[:2, 3])
    else:
        var_ph = var_phc
    phase = _wrap(phase_c - w * tc)
    return HarmonicFit(
        omega=float(w),
        amplitude=float(amp),
        phase=float(phase),
        offset=float(c),
        stderr={
            "omega": float(math.sqrt(max(var_w, 0.0))),
            "amplitude": float(math.sqrt(max(var_amp, 0.0))),
            "phase": float(math.sqrt(max(var_ph, 0.0))),
            "offset": float(math.sqrt(max(cov[2, 2], 0.0))),
        },
        residual_rms=float(math.sqrt(rss / n)),
        n=int(n),
    )


def _fit_at(x, y, w):
    """``(a, b, c, rss, cov)`` of ``a sin(w x) + b cos(w x) + c`` at the given w (covariance ``s^2 (J^T J)^-1``)."""
    coef, rss = _linear(x, y, w)
    J = np.column_stack([np.sin(w * x), np.cos(w * x), np.ones_like(x)])
    cov = rss / max(1, x.size - 3) * np.linalg.pinv(J.T @ J)
    a, b, c = coef
    return a, b, c, rss, cov


def _fit_with_frequency(ta, x, y):
    """``(a, b, c, w, rss, cov)`` with w estimated too: periodogram start, then nonlinear least squares.

    ``x`` is the centred time ``ta - tc``; ``cov`` is 4 x 4, in the order a, b, c, w.
    """
    n = ta.size
    w0 = _periodogram_peak(ta, x, y)
    coef0, _ = _linear(x, y, w0)

    def resid(p):
        return p[0] * np.sin(p[3] * x) + p[1] * np.cos(p[3] * x) + p[2] - y

    sol = optimize.least_squares(resid, np.r_[coef0, w0], x_scale="jac", method="lm", max_nfev=2000)
    a, b, c, w = sol.x
    w = abs(w)
    if sol.x[3] < 0:
        a = -a
    r = resid(np.array([a, b, c, w]))
    rss = float(r @ r)
    J = np.column_stack([np.sin(w * x), np.cos(w * x), np.ones_like(x), a * x * np.cos(w * x) - b * x * np.sin(w * x)])
    cov = rss / max(1, n - 4) * np.linalg.pinv(J.T @ J)
    return a, b, c, w, rss, cov


def _periodogram_peak(ta, x, y) -> float:
    """The trial frequency (rad/s) of least residual on the least-squares periodogram (see :func:`harmonic_fit`)."""
    n = ta.size
    duration = float(ta[-1] - ta[0])
    w_lo = 2.0 * math.pi / duration
    w_hi = math.pi / float(np.median(np.diff(ta)))
    n_trial = int(min(MAX_TRIAL, max(200, 4.0 * (w_hi - w_lo) / w_lo)))
    grid = np.linspace(w_lo, w_hi, n_trial)
    sub = np.unique(np.linspace(0, n - 1, min(n, MAX_GRID_SAMPLES)).astype(np.int64))
    return float(grid[int(np.argmin(_rss_grid(x[sub], y[sub], grid)))])


def _polar(a, b, cov_ab):
    """Amplitude and phase of ``a sin + b cos``, their variances, and the phase's gradient in (a, b)."""
    amp = math.hypot(a, b)
    phase_c = math.atan2(b, a)  # at centred time
    # d(amp) = (a da + b db)/amp ; d(phase_c) = (a db - b da)/amp^2
    g_amp = np.array([a, b]) / amp if amp > 0 else np.zeros(2)
    g_ph = np.array([-b, a]) / amp**2 if amp > 0 else np.zeros(2)
    var_amp = float(g_amp @ cov_ab @ g_amp)
    var_phc = float(g_ph @ cov_ab @ g_ph)
    return amp, phase_c, var_amp, var_phc, g_ph
