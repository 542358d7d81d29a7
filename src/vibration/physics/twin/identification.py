"""Identification of m, c, k with intervals (output error on the exact model) and frequency-domain estimates."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import signal
from scipy.optimize import least_squares
from scipy.stats import t as student_t

from ..model import Oscillator, ParameterError, check_int
from .measurements import _record
from .sampled import _filters, _foh

__all__ = [
    "FrequencyEstimate",
    "FrequencyResponse",
    "Identification",
    "frequency_estimates",
    "frf_estimate",
    "identify",
]

#: Relative spacing of the natural-frequency grid of the global search, and its damping ratios.
GRID_STEP = 0.05
GRID_ZETAS = (0.05, 0.3)


# --------------------------------------------------------------------------- identification


@dataclass(frozen=True, kw_only=True)
class Identification:
    """Least-squares estimate of the oscillator from one record, with its uncertainty."""

    m: float  # mass, kg
    c: float  # damping, N s/m
    k: float  # stiffness, N/m
    stderr: np.ndarray  # (3,) standard errors of m, c, k (kg, N s/m, N/m)
    ci95: np.ndarray  # (3, 2) 95 % confidence intervals of m, c, k
    cov: np.ndarray  # (3, 3) covariance of (m, c, k)
    x0: float  # initial displacement, m
    v0: float  # initial velocity, m/s
    sigma: float  # noise standard deviation estimated from the residual (m or m/s^2)
    n: int  # samples
    dt: float  # sampling step, s
    sensor: str  # "x" or "a"
    force_hold_error: float  # estimate of max |F - FOH(F)| / rms F, 1 (should be far below the noise)
    residual: np.ndarray = field(repr=False)  # measured minus model, m or m/s^2

    @property
    def oscillator(self) -> Oscillator:
        """The identified oscillator."""
        return Oscillator(m=self.m, c=self.c, k=self.k)

    @property
    def natural_frequency(self) -> float:
        """sqrt(k / m), rad/s."""
        return math.sqrt(self.k / self.m)

    @property
    def damping_ratio(self) -> float:
        """c / (2 sqrt(k m)), 1."""
        return self.c / (2.0 * math.sqrt(self.k * self.m))

    @property
    def dof(self) -> int:
        """Residual degrees of freedom, N - 5 (m, c, k and the initial state)."""
        return self.n - 5


def _varpro(force, y, h, sensor):
    """Variable projection on (ln omega_n, ln zeta): columns, linear solve, residual and batched grid cost."""
    n = force.size
    delta = np.zeros(n)
    delta[0] = 1.0
    yy = float(y @ y)
    lo_psi = (math.log(2.0 * np.pi / (h * n) / 100.0), math.log(1e-6))
    hi_psi = (math.log(4.0 * np.pi / h), math.log(100.0))

    def _columns(phi, g0, g1, wn, zeta):
        cc, kk = 2.0 * zeta * wn, wn * wn
        r = np.array([1.0, 0.0]) if sensor == "x" else np.array([-kk, -cc])
        feed = 0.0 if sensor == "x" else 1.0
        b, a, free_b = _filters(phi, g0, g1, r, feed)
        yi = signal.lfilter([1.0], a, delta)
        yi1 = np.concatenate([[0.0], yi[:-1]])
        basis = [free_b[j][0] * yi + free_b[j][1] * yi1 for j in range(2)]
        w0 = -g1 * force[0]
        forced = signal.lfilter(b, a, force) + w0[0] * basis[0] + w0[1] * basis[1]
        return np.column_stack([forced, basis[0], basis[1]])

    def columns(theta):
        wn, zeta = np.exp(theta)
        phi, g0, g1 = (v[0] for v in _foh(1.0, 2.0 * zeta * wn, wn * wn, h))
        return _columns(phi, g0, g1, wn, zeta)

    def solve(theta):
        g = columns(theta)
        scale = np.sqrt(np.sum(g * g, axis=0))
        scale[scale == 0.0] = 1.0
        gs = g / scale
        if not np.all(np.isfinite(gs)):
            return None, None
        coef, *_ = np.linalg.lstsq(gs, y, rcond=None)
        return coef / scale, g

    def residual(theta):
        if not (lo_psi[0] <= theta[0] <= hi_psi[0] and lo_psi[1] <= theta[1] <= hi_psi[1]):
            return np.full(n, 1e3 * math.sqrt(yy / n) + 1e-300)  # outside the physical box: a flat wall
        coef, g = solve(theta)
        if coef is None:
            return np.full(n, 1e10)
        return g @ coef - y

    def grid_cost(wns, zetas):
        """Residual sum of squares at each (omega_n, zeta) pair (normal equations, scaled columns)."""
        wns, zetas = np.asarray(wns, float), np.asarray(zetas, float)
        phi, g0, g1 = _foh(np.ones(wns.size), 2.0 * zetas * wns, wns * wns, h)
        out = np.empty(wns.size)
        for i in range(wns.size):
            g = _columns(phi[i], g0[i], g1[i], wns[i], zetas[i])
            scale = np.sqrt(np.sum(g * g, axis=0))
            if not np.all(np.isfinite(scale)) or np.any(scale == 0.0):
                out[i] = np.inf
                continue
            gs = g / scale
            gram, rhs = gs.T @ gs, gs.T @ y
            try:
                coef = np.linalg.solve(gram, rhs)
            except np.linalg.LinAlgError:
                out[i] = np.inf
                continue
            out[i] = yy - float(coef @ rhs)
        return out

    return columns, solve, residual, grid_cost


def _levy_start(force, y, h, sensor):
    """(omega_n, zeta) from a linear fit of 1/H on the Welch H1 estimate, or None."""
    try:
        frf = _frf(force, y, h, sensor)
    except (ValueError, ParameterError):
        return None
    w, hh, coh, pff = frf
    sel = (coh > 0.5) & (w > 0) & (pff >= 1e-2 * np.max(pff))
    if np.count_nonzero(sel) < 4:
        return None
    w, hh = w[sel], hh[sel]
    # minimise |H (k - m w^2 + i c w) - 1|^2: linear in (k, m, c)
    rows = np.concatenate(
        [
            np.column_stack([hh.real, -(w**2) * hh.real, -w * hh.imag]),
            np.column_stack([hh.imag, -(w**2) * hh.imag, w * hh.real]),
        ]
    )
    rhs = np.concatenate([np.ones(w.size), np.zeros(w.size)])
    try:
        (k, m, c), *_ = np.linalg.lstsq(rows, rhs, rcond=None)
    except np.linalg.LinAlgError:
        return None
    if not (k > 0 and m > 0 and c > 0):
        return None
    return math.sqrt(k / m), c / (2.0 * math.sqrt(k * m))


def _frf(force, y, h, sensor, nperseg=None):
    """Welch H1 receptance estimate: (omega rad/s, H m/N, coherence)."""
    n = force.size
    if nperseg is None:
        nperseg = int(min(n, max(64, n // 4)))
    f, pff = signal.welch(force, fs=1.0 / h, nperseg=nperseg, detrend="constant")
    _, pfy = signal.csd(force, y, fs=1.0 / h, nperseg=nperseg, detrend="constant")
    _, pyy = signal.welch(y, fs=1.0 / h, nperseg=nperseg, detrend="constant")
    w = 2.0 * np.pi * f
    with np.errstate(divide="ignore", invalid="ignore"):
        coh = np.abs(pfy) ** 2 / (pff * pyy)
        hh = pfy / pff
        if sensor == "a":
            hh = -hh / w**2
    ok = np.isfinite(hh) & (w > 0) & (pff > 1e-9 * np.max(pff))
    return w[ok], hh[ok], coh[ok], pff[ok]


def identify(t, force, x=None, *, a=None, search: str = "global") -> Identification:
    """Estimate m, c, k from a broadband test, with standard errors and 95 % confidence intervals.

    Output-error nonlinear least squares on the exact first-order-hold model
    (see the module docstring for the method and its assumptions: force
    measured without noise and band-limited below the Nyquist frequency, white
    Gaussian noise on the response, unknown initial state estimated too).

    Parameters
    ----------
    t : array_like
        Uniform, increasing sample times, s (at least ``MIN_SAMPLES``).
    force : array_like
        Measured force, N; it must vary (chirp, random or impulse test).
    x : array_like, optional
        Measured displacement, m.
    a : array_like, optional
        Measured acceleration, m/s^2 (give exactly one of ``x`` and ``a``).
    search : {"global", "local"}
        ``"global"``: a grid over the natural frequency (5 % steps from one
        period per record to 0.9 of the Nyquist frequency, two damping ratios)
        plus the frequency-domain (Levy) start, the best few polished.
        ``"local"``: the Levy start only (falls back to global if it fails);
        used by the Monte Carlo experiments for speed.

    Returns
    -------
    Identification
        ``m`` (kg), ``c`` (N s/m), ``k`` (N/m), ``stderr`` (3,), ``ci95`` (3, 2),
        the covariance, the initial state, the noise estimate and the residual.

    Raises
    ------
    ParameterError
        Bad input (as :func:`load_measurements`), or a record the method cannot
        use: natural frequency not resolved by the sampling or the record, or a
        force that does not separate m, c and k.

    Examples
    --------
    >>> from vibration.physics.twin import random_force, synthetic_measurements
    >>> t = np.arange(0.0, 40.0, 0.01)
    >>> meas = synthetic_measurements(Oscillator(m=2.0, c=1.0, k=50.0), t, random_force(t, (0.2, 3.0)),
    ...                               sensor="a", noise=0.05, seed=3)
    >>> fit = identify(meas.t, meas.force, a=meas.a)
    >>> [round(v, 1) for v in (fit.m, fit.c, fit.k)], fit.ci95.shape        # kg, N s/m, N/m
    ([2.0, 1.0, 50.0], (3, 2))
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    if not isinstance(search, str) or search not in ("global", "local"):
        raise ParameterError(f"search = {search!r}: allowed 'global' or 'local'")
    if search == "local":
        try:
            fit = _identify(t, h, force, y, sensor, local=True)
            if np.all(np.isfinite(fit.stderr)):
                return fit
        except ParameterError:
            pass
    return _identify(t, h, force, y, sensor, local=False)


def _search_starts(force, y, h, sensor, local: bool, band) -> list:
    """Starting points (cost, (omega_n, zeta)) of the polish, best first: the grid's best and the Levy start.

    The grid runs over the natural frequencies in ``band`` (rad/s) on at most 20000 samples; ``local`` keeps the
    Levy start only (refused if it fails).
    """
    w_lo, w_hi = band
    n = force.size
    m_search = min(n, 20000)
    *_, grid_cost = _varpro(force[:m_search], y[:m_search], h, sensor)
    lo_s = max(w_lo, 2.0 * np.pi / (h * (m_search - 1)))
    grid_w = np.geomspace(lo_s, w_hi, int(np.ceil(np.log(w_hi / lo_s) / GRID_STEP)) + 1)
    starts = []
    levy = _levy_start(force, y, h, sensor)
    if local:
        if levy is None or not w_lo <= levy[0] <= w_hi:
            raise ParameterError("no frequency-domain start: allowed a global search")
        grid_w = grid_w[:0]
    for zeta in GRID_ZETAS if grid_w.size else ():
        costs = grid_cost(grid_w, np.full(grid_w.size, zeta))
        for i in np.argsort(costs)[:2]:
            starts.append((costs[i], (grid_w[i], zeta)))
    if levy is not None and w_lo <= levy[0] <= w_hi:
        levy = (levy[0], min(max(levy[1], 1e-4), 5.0))
        starts.append((float(grid_cost([levy[0]], [levy[1]])[0]), levy))
    starts.sort(key=lambda s: s[0])
    return starts


def _polish(residual, starts):
    """The best Levenberg-Marquardt solution from the first three distinct starts (None without starts)."""
    best = None
    seen = []
    for _, (wv, zeta) in starts:
        th0 = np.log([wv, min(max(zeta, 1e-4), 5.0)])
        if any(np.all(np.abs(th0 - s) < [0.02, 0.3]) for s in seen):
            continue
        seen.append(th0)
        sol = least_squares(residual, th0, method="lm", x_scale=[0.01, 0.1], xtol=1e-10, ftol=1e-12, gtol=1e-12)
        if best is None or sol.cost < best.cost:
            best = sol
        if len(seen) >= 3:
            break
    return best


def _check_estimate(coef, wn, h, span) -> None:
    """Refuse a fit with 1/m <= 0, or a natural frequency that the step ``h`` or the span (s) does not resolve."""
    if coef is None or not coef[0] > 0.0:
        raise ParameterError(
            "x or a does not fit the oscillator model (best fit has 1/m <= 0): allowed a response measured "
            "along the force (check sign and units) of an oscillator the sampling resolves"
        )
    if wn > 0.8 * np.pi / h:
        raise ParameterError(
            f"t: step {h:g} s does not resolve the estimated natural frequency {wn:.4g} rad/s: allowed "
            f"sampling at least 2.5 samples per period (step <= {0.8 * np.pi / wn:.3g} s)"
        )
    if wn < 2.0 * np.pi / span:
        raise ParameterError(
            f"t spans {span:g} s, less than one period of the estimated natural frequency {wn:.4g} rad/s: "
            f"allowed a record of several periods (> {2 * np.pi / wn:.3g} s)"
        )


def _mck_covariance(columns, psi, coef, g, res, mck) -> tuple[np.ndarray, float]:
    """Covariance of (m, c, k) and the noise variance s^2 at the solution ``psi``, ``coef`` with residual ``res``.

    Gauss-Newton covariance of (ln omega_n, ln zeta, 1/m, x0, v0), mapped to ``mck`` = (m, c, k) by the delta
    method.
    """
    m, c, k = mck
    n = res.size
    jac = np.empty((n, 5))
    for j in range(2):
        step = 1e-6
        dp = np.zeros(2)
        dp[j] = step
        jac[:, j] = (columns(psi + dp) @ coef - columns(psi - dp) @ coef) / (2.0 * step)
    jac[:, 2:] = g
    dof = n - 5
    s2 = float(res @ res) / dof
    scale = np.sqrt(np.sum(jac * jac, axis=0))
    scale[scale == 0.0] = 1.0
    js = jac / scale
    _, sv, vt = np.linalg.svd(js, full_matrices=False)
    if sv[-1] <= 1e-10 * sv[0]:
        raise ParameterError(
            "force does not separate m, c and k (information matrix singular): allowed a broadband force "
            "exciting below, at and above the natural frequency (chirp or random)"
        )
    cov_full = (vt.T / sv**2) @ vt / np.outer(scale, scale) * s2
    d = np.array([[0.0, 0.0, -m * m, 0, 0], [c, c, -c * m, 0, 0], [2.0 * k, 0.0, -k * m, 0, 0]])
    return d @ cov_full @ d.T, s2


def _identify(t, h, force, y, sensor, local: bool) -> Identification:
    """Identify the oscillator from a checked record: start search, polish on the whole record, uncertainty."""
    n = t.size
    span = float(t[-1] - t[0])
    w_lo, w_hi = 2.0 * np.pi / span, 0.9 * np.pi / h
    if w_lo >= w_hi / 2:
        raise ParameterError(f"t spans {span:g} s with step {h:g} s: allowed a record of many samples")
    starts = _search_starts(force, y, h, sensor, local, (w_lo, w_hi))
    columns, solve, residual, _ = _varpro(force, y, h, sensor)
    psi = _polish(residual, starts).x
    wn, zeta = np.exp(psi)
    coef, g = solve(psi)
    _check_estimate(coef, wn, h, span)
    m = 1.0 / coef[0]
    c, k = 2.0 * zeta * wn * m, wn * wn * m
    # the forced column already holds the -gamma1 F[0] part of w[0], so the free coefficients are z[0]
    z0 = coef[1:]
    res = g @ coef - y
    cov, s2 = _mck_covariance(columns, psi, coef, g, res, (m, c, k))
    stderr = np.sqrt(np.diag(cov))
    q = float(student_t.ppf(0.975, n - 5))
    est = np.array([m, c, k])
    ci = np.column_stack([est - q * stderr, est + q * stderr])
    hold = float(np.max(np.abs(np.diff(force, 2))) / 8.0 / max(np.sqrt(np.mean(force**2)), 1e-300))
    return Identification(
        m=float(m),
        c=float(c),
        k=float(k),
        stderr=stderr,
        ci95=ci,
        cov=cov,
        x0=float(z0[0]),
        v0=float(z0[1]),
        sigma=math.sqrt(s2),
        n=int(n),
        dt=h,
        sensor=sensor,
        force_hold_error=hold,
        residual=-res,
    )


# --------------------------------------------------------------------------- frequency domain


@dataclass(frozen=True, kw_only=True)
class FrequencyResponse:
    """Measured receptance (Welch H1 estimate): ``omega`` (rad/s), ``H`` (m/N, complex), ``coherence`` (1)."""

    omega: np.ndarray
    H: np.ndarray
    coherence: np.ndarray
    force_psd: np.ndarray  # one-sided PSD of the force, N^2/Hz


@dataclass(frozen=True, kw_only=True)
class FrequencyEstimate:
    """m (kg), c (N s/m), k (N/m), omega_n (rad/s), zeta (1) from the measured FRF; nan and a reason if none."""

    method: str
    m: float
    c: float
    k: float
    omega_n: float
    zeta: float
    reason: str = ""


def frf_estimate(t, force, x=None, *, a=None, nperseg: int | None = None) -> FrequencyResponse:
    """Receptance estimate ``H1 = S_Fy / S_FF`` (Welch, Hann window, 50 % overlap).

    Parameters
    ----------
    t : array_like
        Uniform sample times, s.
    force : array_like
        Force, N.
    x, a : array_like, optional
        Displacement (m) or acceleration (m/s^2); acceleration is turned into
        receptance by dividing by ``-omega^2``.
    nperseg : int, optional
        Samples per segment (default a quarter of the record: seven averages).

    Examples
    --------
    >>> from vibration.physics.twin import random_force, synthetic_measurements
    >>> t = np.arange(0.0, 200.0, 0.02)
    >>> meas = synthetic_measurements(Oscillator(m=1.0, c=0.5, k=20.0), t, random_force(t))
    >>> frf = frf_estimate(**meas)
    >>> i = int(np.argmin(np.abs(frf.omega - 2.0)))
    >>> bool(abs(abs(frf.H[i]) * abs(20 - frf.omega[i] ** 2 + 0.5j * frf.omega[i]) - 1) < 0.02)
    True
    """
    t, h, force, y, sensor = _record(t, force, x, a)
    if nperseg is not None:
        nperseg = check_int("nperseg", nperseg, low=16, high=t.size)
    omega, H, coherence, force_psd = _frf(force, y, h, sensor, nperseg)
    return FrequencyResponse(omega=omega, H=H, coherence=coherence, force_psd=force_psd)


def _nan_estimate(method: str, reason: str) -> FrequencyEstimate:
    return FrequencyEstimate(
        method=method, m=math.nan, c=math.nan, k=math.nan, omega_n=math.nan, zeta=math.nan, reason=reason
    )


def _resonance_bins(frf: FrequencyResponse):
    """The contiguous bins with force and coherence, their magnitudes and the peak's bin, or None and the reason.

    Returns ((omega, H, |H|, peak index), "") or (None, reason).
    """
    if frf.omega.size == 0:
        return None, "no frequency bins"
    keep = (frf.force_psd >= 1e-2 * np.max(frf.force_psd)) & (frf.coherence > 0.5)
    first, last = np.nonzero(keep)[0][[0, -1]] if np.any(keep) else (0, -1)
    w, hh = frf.omega[first : last + 1], frf.H[first : last + 1]
    if w.size < 5:
        return None, "fewer than 5 frequency bins with force and coherence"
    mag = np.abs(hh)
    i = int(np.argmax(mag))
    if i == 0 or i == w.size - 1:
        return None, "no resonance peak inside the measured band"
    return (w, hh, mag, i), ""


def _parabolic_peak(w, mag, i: int) -> tuple[float, float]:
    """Frequency and magnitude of the peak at bin ``i`` by parabolic interpolation of its bins."""
    y0, y1, y2 = mag[i - 1], mag[i], mag[i + 1]
    den = y0 - 2 * y1 + y2
    d = 0.5 * (y0 - y2) / den if den < 0 else 0.0
    w_pk = w[i] + d * (w[i + 1] - w[i - 1]) / 2.0
    h_pk = y1 - 0.25 * (y0 - y2) * d
    return w_pk, h_pk


def _half_power_estimate(w, mag, i: int, w_pk, h_pk) -> FrequencyEstimate:
    """The half-power estimate from the peak (frequency ``w_pk``, magnitude ``h_pk``, bin ``i``)."""
    level = h_pk / math.sqrt(2.0)
    left = np.nonzero(mag[:i] < level)[0]
    right = np.nonzero(mag[i:] < level)[0]
    if left.size == 0 or right.size == 0 or (right[0] + (i - left[-1]) - 1) < 5:
        return _nan_estimate("half-power", "half-power band not resolved by the frequency bins")
    j = left[-1]
    lo = float(np.interp(level, [mag[j], mag[j + 1]], [w[j], w[j + 1]]))
    j = i + right[0]
    hi = float(np.interp(level, [mag[j], mag[j - 1]], [w[j], w[j - 1]]))
    ratio = (hi**2 - lo**2) / (hi**2 + lo**2)
    if ratio >= 1.0:
        return _nan_estimate("half-power", "damping too high for a half-power estimate")
    # 2 z sqrt(1 - z^2) / (1 - 2 z^2) = ratio  ->  z^2 = (1 - 1/sqrt(1 + ratio^2)) / 2
    zeta = math.sqrt(0.5 * (1.0 - 1.0 / math.sqrt(1.0 + ratio * ratio)))
    wn = w_pk / math.sqrt(1.0 - 2.0 * zeta**2)
    k = 1.0 / (2.0 * zeta * math.sqrt(1.0 - zeta**2) * h_pk)
    m = k / wn**2
    return FrequencyEstimate(
        method="half-power",
        m=float(m),
        c=2.0 * zeta * math.sqrt(k * m),
        k=float(k),
        omega_n=float(wn),
        zeta=float(zeta),
    )


def _circle_fit_estimate(w, hh, mag, i: int, h_pk) -> FrequencyEstimate:
    """The circle-fit estimate on the bins around the peak (bin ``i``, magnitude ``h_pk``) above half of it."""
    lo_i, hi_i = i, i
    while lo_i - 1 >= 0 and mag[lo_i - 1] >= 0.5 * h_pk:
        lo_i -= 1
    while hi_i + 1 < w.size and mag[hi_i + 1] >= 0.5 * h_pk:
        hi_i += 1
    sel = slice(lo_i, hi_i + 1)
    if hi_i - lo_i + 1 < 5:
        return _nan_estimate("circle fit", "fewer than 5 frequency bins near the resonance")
    yv = 1j * w[sel] * hh[sel]
    u, v = yv.real, yv.imag
    g = np.column_stack([u, v, np.ones_like(u)])
    (dd, ee, ff), *_ = np.linalg.lstsq(g, -(u * u + v * v), rcond=None)
    centre = complex(-dd / 2.0, -ee / 2.0)
    radius = math.sqrt(max(abs(centre) ** 2 - ff, 0.0))
    if radius == 0.0 or abs(centre) == 0.0:
        return _nan_estimate("circle fit", "degenerate circle")
    c = 1.0 / (2.0 * radius)
    theta = np.angle((yv - centre) / centre)
    ws = w[sel]
    (m, k), *_ = np.linalg.lstsq(np.column_stack([ws**2, -np.ones_like(ws)]), -c * ws * np.tan(theta / 2.0), rcond=None)
    if not (m > 0 and k > 0):
        return _nan_estimate("circle fit", "circle fit gave m or k <= 0")
    return FrequencyEstimate(
        method="circle fit",
        m=float(m),
        c=float(c),
        k=float(k),
        omega_n=math.sqrt(k / m),
        zeta=c / (2 * math.sqrt(k * m)),
    )


def frequency_estimates(frf: FrequencyResponse) -> tuple[FrequencyEstimate, FrequencyEstimate]:
    """Half-power and circle-fit estimates of m, c, k from a measured receptance.

    * **Half-power**: peak of ``|H|`` (parabolic interpolation of the bins), the
      exact half-power relation for zeta (as :func:`vibration.half_power_points`),
      ``k = 1 / (2 zeta sqrt(1 - zeta^2) |H|max)``, ``m = k / omega_n^2``.
    * **Circle fit**: the mobility ``i omega H = 1 / (c + i (m omega - k / omega))``
      of a viscous oscillator is a circle of diameter ``1/c`` through the origin;
      an algebraic circle fit on the bins above half the peak gives ``c``, and
      the angle ``theta`` of each point seen from the centre gives
      ``m omega^2 - k = -c omega tan(theta / 2)``, linear in ``m, k``.

    Only bins where the force is strong (PSD above 1 % of its peak) and the
    coherence above 0.5 are used. Both need a resolved resonance peak (zeta
    below about 0.3 and several bins inside the half-power band); otherwise the
    estimate is nan with a reason.

    Examples
    --------
    >>> from vibration.physics.twin import random_force, synthetic_measurements
    >>> t = np.arange(0.0, 400.0, 0.02)
    >>> meas = synthetic_measurements(Oscillator(m=1.0, c=0.5, k=20.0), t, random_force(t))
    >>> hp, cf = frequency_estimates(frf_estimate(**meas, nperseg=10000))
    >>> float(round(hp.k, 0)), float(round(cf.m, 1))                                  # N/m, kg
    (20.0, 1.0)
    """
    if not isinstance(frf, FrequencyResponse):
        raise ParameterError(f"frf = {frf!r:.60} is not a FrequencyResponse: allowed the output of frf_estimate")
    bins, r = _resonance_bins(frf)
    if bins is None:
        return _nan_estimate("half-power", r), _nan_estimate("circle fit", r)
    w, hh, mag, i = bins
    w_pk, h_pk = _parabolic_peak(w, mag, i)
    return _half_power_estimate(w, mag, i, w_pk, h_pk), _circle_fit_estimate(w, hh, mag, i, h_pk)
