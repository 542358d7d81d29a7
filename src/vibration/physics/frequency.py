"""Frequency-domain and window quantities: magnification, phase, bandwidth,
logarithmic decrement, settling time, energy balance and the design map."""

from __future__ import annotations

import functools
import math
import numbers
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.integrate import cumulative_simpson
from scipy.optimize import brentq

from .checks import check_array, check_oscillator, like_input
from .exact import Response, _grid_exp, _kernels, _roots, _uniform, exact_response, steady_state
from .model import (
    N_POINTS_MAX,
    Oscillator,
    ParameterError,
    SineForce,
    check_int,
    check_real,
    check_records,
)

#: Largest number of samples in one precomputed table of the design map (2 tables of 8 bytes each).
MAP_CELLS_MAX = 50_000_000

#: Cells whose forcing lies within ``NEAR / t_end`` (1/s) of a characteristic root take
#: their peak from :func:`exact_response`: there the steady-state split the map's loop
#: uses would cancel (it loses about ``60 eps / NEAR`` of the peak at this distance).
NEAR = 0.1


def _array(values, name: str, unit: str) -> np.ndarray:
    """``values`` as a float array, or :class:`ParameterError` naming ``name``."""
    if values is None or isinstance(values, str | bytes):
        raise ParameterError(f"{name} = {values!r} is not an array of numbers: allowed a 1-D array in {unit}")
    try:
        raw = np.asarray(values)
        if raw.dtype.kind not in "iufO":
            raise TypeError
        if raw.dtype.kind == "O" and not all(isinstance(v, numbers.Real) and not isinstance(v, bool) for v in raw.flat):
            raise TypeError
        return np.asarray(raw, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise ParameterError(f"{name} = {values!r} is not an array of numbers: allowed a 1-D array in {unit}") from None


def _increasing(
    values,
    name: str,
    unit: str,
    size: int | None = None,
    min_size: int = 1,
    low: float | None = None,
    partner: str = "",
) -> np.ndarray:
    """A finite, strictly increasing 1-D array (of ``size`` samples if given, each >= ``low`` if given)."""
    a = _array(values, name, unit)
    if a.ndim != 1 or a.size < min_size:
        raise ParameterError(f"{name} has shape {a.shape}: allowed a 1-D array of at least {min_size} values in {unit}")
    if size is not None and a.size != size:
        raise ParameterError(
            f"{name} has {a.size} values: allowed as many as the {size} samples it goes with"
            + (f" ({partner} has {size})" if partner else "")
        )
    return check_array(name, a, low=low, ndim=(1,), min_size=min_size, increasing=True, unit=unit)


def _damped(m: float, c: float, k: float) -> Oscillator:
    """The oscillator of one entry of ``dampings``, or :class:`ParameterError` naming ``dampings``."""
    try:
        return Oscillator(m=m, c=c, k=k)
    except ParameterError as exc:
        raise ParameterError(f"dampings contains {c!r} N s/m: {exc}") from None


def _omegas(omegas, name: str = "omegas", scalar: bool = False) -> np.ndarray:
    w = _array(omegas, name, "rad/s")
    if w.ndim > 1 or (w.ndim == 0 and not scalar) or w.size == 0:
        allowed = "a scalar or a non-empty 1-D array" if scalar else "a non-empty 1-D array"
        raise ParameterError(f"{name} has shape {w.shape}: allowed {allowed} in rad/s")
    if not np.all(np.isfinite(w)) or np.any(w < 0):
        bad = w[~(np.isfinite(w) & (w >= 0))][0]
        raise ParameterError(f"{name} contains {bad!r}: allowed finite values >= 0 rad/s")
    return w


def magnification(osc: Oscillator, omegas):
    """Steady-state amplitude over static deflection, ``|x| / (F0/k)``, at each omega.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    omegas : float or array_like
        Forcing frequencies, rad/s (>= 0): a scalar or a 1-D array.

    Returns
    -------
    float or numpy.ndarray
        ``1 / sqrt((1 - r^2)^2 + (2 zeta r)^2)``, ``r = omega / omega_n``; dimensionless; a float for a
        scalar omega.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> np.round(magnification(osc, [0.0, osc.natural_frequency]), 4)
    array([1.    , 8.9443])
    """
    check_oscillator(osc)
    w = _omegas(omegas, scalar=True)
    r = w / osc.natural_frequency
    with np.errstate(divide="ignore", over="ignore"):
        return like_input(1.0 / np.hypot((1.0 - r) * (1.0 + r), 2.0 * osc.damping_ratio * r), w)


def phase_lag(osc: Oscillator, omegas):
    """Phase lag of displacement behind force, rad, in ``[0, pi]`` for c >= 0 (a float for a scalar omega).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> np.round(phase_lag(osc, [0.0, osc.natural_frequency, 1e6]), 4)
    array([0.    , 1.5708, 3.1416])
    """
    check_oscillator(osc)
    w = _omegas(omegas, scalar=True)
    r = w / osc.natural_frequency
    with np.errstate(over="ignore", invalid="ignore"):
        im, re = 2.0 * osc.damping_ratio * r, (1.0 - r) * (1.0 + r)
    return like_input(np.where((im == 0.0) & (re == 0.0), 0.5 * np.pi, np.arctan2(im, re)), w)


@dataclass(frozen=True, kw_only=True)
class HalfPower:
    """Half-power points of a sampled magnification curve."""

    peak_omega: float  # frequency of the sampled peak, rad/s
    peak_magnification: float  # peak of the curve, dimensionless
    omega_low: float  # lower half-power frequency, rad/s
    omega_high: float  # upper half-power frequency, rad/s

    @property
    def bandwidth(self) -> float:
        """``omega_high - omega_low``, rad/s."""
        return self.omega_high - self.omega_low

    @property
    def damping_ratio(self) -> float:
        """Damping ratio from the exact half-power points of the displacement curve.

        They sit at ``r^2 = 1 - 2 zeta^2 +/- 2 zeta sqrt(1 - zeta^2)``, so
        ``(w_hi^2 - w_lo^2) / (w_hi^2 + w_lo^2) = 2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2)``,
        solved for zeta (no light-damping approximation, no need for omega_n).
        """
        ratio = (self.omega_high**2 - self.omega_low**2) / (self.omega_high**2 + self.omega_low**2)
        return brentq(lambda z: 2 * z * math.sqrt(1 - z * z) - ratio * (1 - 2 * z * z), 0.0, 0.5)


def half_power_points(omegas, mags) -> HalfPower:
    """Locate the half-power points (``mag = peak / sqrt(2)``) of a sampled curve.

    Linear interpolation between samples; the curve must fall below the
    half-power level on both sides of its peak.

    Parameters
    ----------
    omegas : array_like
        Strictly increasing, finite frequencies, rad/s (at least 3).
    mags : array_like
        Magnification at those frequencies (as many, finite, >= 0), dimensionless.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> w = np.linspace(3.0, 6.0, 30001)
    >>> hp = half_power_points(w, magnification(osc, w))
    >>> round(hp.bandwidth, 3), round(hp.damping_ratio, 4)   # rad/s, 1
    (0.502, 0.0559)
    """
    w = _increasing(omegas, "omegas", "rad/s", min_size=3)
    if w[0] < 0.0:
        raise ParameterError(f"omegas contains {w[0]!r}: allowed finite values >= 0 rad/s")
    g = _array(mags, "mags", "(dimensionless)")
    if g.shape != w.shape:
        raise ParameterError(
            f"mags has shape {g.shape}: allowed the shape of omegas, {w.shape} (one magnification per frequency)"
        )
    if not np.all(np.isfinite(g) & (g >= 0.0)):
        bad = float(g[~(np.isfinite(g) & (g >= 0.0))][0])
        raise ParameterError(f"mags contains {bad!r}: allowed finite values >= 0")
    i = int(np.argmax(g))
    level = g[i] / math.sqrt(2.0)
    below_left = np.nonzero(g[:i] < level)[0]
    below_right = np.nonzero(g[i:] < level)[0]
    if below_left.size == 0 or below_right.size == 0:
        raise ParameterError(
            "omegas does not bracket both half-power points of mags: allowed omegas and mags whose peak has both "
            "half-power crossings (mags falls below peak/sqrt(2) on both sides; widen the frequency range)"
        )
    j = below_left[-1]
    lo = np.interp(level, [g[j], g[j + 1]], [w[j], w[j + 1]])
    j = i + below_right[0]
    hi = np.interp(level, [g[j], g[j - 1]], [w[j], w[j - 1]])
    return HalfPower(peak_omega=float(w[i]), peak_magnification=float(g[i]), omega_low=float(lo), omega_high=float(hi))


def local_maxima(y) -> np.ndarray:
    """Indices of the samples of ``y`` above the one before and not below the one after (a plateau counts
    once, at its first sample); the ends never count.

    >>> local_maxima(np.array([0.0, 2.0, 1.0, 3.0, 3.0, 0.0, 1.0]))
    array([1, 3])
    """
    y = np.asarray(y)
    return np.nonzero((y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:]))[0] + 1


def log_decrement(t, x) -> tuple[float, float]:
    """Logarithmic decrement of a free decay and the damping ratio it implies.

    Uses the successive positive peaks of ``x`` (refined by a parabola through
    each sampled maximum) and a least-squares fit of ``ln(peak)`` against the
    peak index: ``delta = -slope``, ``zeta = delta / sqrt(4 pi^2 + delta^2)``.

    Parameters
    ----------
    t : array_like
        Sample times, s: finite, strictly increasing, one per sample of ``x``
        (any spacing; each peak is refined by the parabola through its three
        samples at their own times).
    x : array_like
        Displacement of a free decay, m (finite, 1-D).

    Returns
    -------
    (delta, zeta)
        Logarithmic decrement and damping ratio, dimensionless. A ``RuntimeWarning`` says when the peaks
        scatter so that delta is not resolved from zero (a record of noise, not of a decay).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> t = np.linspace(0.0, 20.0, 20001)
    >>> r = exact_response(osc, SineForce(F0=0.0, omega=0.0), t, x0=1.0)
    >>> delta, zeta = log_decrement(r.t, r.x)
    >>> round(zeta, 5)
    0.0559
    """
    x = _array(x, "x", "m")
    if x.ndim != 1 or x.size < 3:
        raise ParameterError(f"x has shape {x.shape}: allowed a 1-D array of at least 3 displacements in m")
    if not np.all(np.isfinite(x)):
        raise ParameterError(f"x contains {float(x[~np.isfinite(x)][0])!r}: allowed finite displacements in m")
    t = _increasing(t, "t", "s", size=x.size, low=0.0, partner="x")
    idx = local_maxima(x)
    idx = idx[x[idx] > 0]
    if idx.size < 2:
        raise ParameterError("x has fewer than two positive peaks: allowed an oscillating free decay")
    ym, y0, yp = x[idx - 1], x[idx], x[idx + 1]
    hm, hp = t[idx] - t[idx - 1], t[idx + 1] - t[idx]  # spacings either side, s
    if np.all(hm == hp):
        den = ym - 2 * y0 + yp
        off = np.where(den != 0, 0.5 * (ym - yp) / np.where(den != 0, den, 1.0), 0.0)
        peaks = y0 - 0.25 * (ym - yp) * off
    else:  # vertex of the parabola through (-hm, ym), (0, y0), (hp, yp)
        dm, dp = (y0 - ym) / hm, (yp - y0) / hp  # slopes, m/s
        curv = (dp - dm) / (hm + hp)  # half the second derivative, m/s^2
        slope0 = dm + curv * hm  # slope at the sample, m/s
        peaks = np.where(curv < 0, y0 - slope0 * slope0 / (4.0 * np.where(curv < 0, curv, -1.0)), y0)
    n = np.arange(peaks.size)
    slope, icpt = np.polyfit(n, np.log(peaks), 1)
    delta = -float(slope)
    _warn_unresolved(n, np.log(peaks) - (slope * n + icpt), delta)
    return delta, delta / math.sqrt(4 * math.pi**2 + delta**2)


def _warn_unresolved(n: np.ndarray, resid: np.ndarray, delta: float) -> None:
    """Warn when the peaks scatter about their line and its slope is not resolved from zero (noise, no decay)."""
    if n.size < 3:
        return
    sd = float(np.sqrt(np.sum(resid**2) / (n.size - 2)))
    se = sd / float(np.sqrt(np.sum((n - n.mean()) ** 2)))
    if sd > 1e-6 and abs(delta) < 2.0 * se:
        warnings.warn(
            f"x does not decay like a free oscillation: the logarithmic decrement {delta:.3g} is not resolved from "
            f"zero (standard error {se:.2g} from the scatter of {n.size} peaks about their line); the damping ratio "
            "it gives is not a measurement",
            RuntimeWarning,
            stacklevel=3,
        )


def settling_time(osc: Oscillator, force: SineForce, tol: float = 0.02, *, x0: float = 0.0, v0: float = 0.0) -> float:
    """Time after which the transient stays within ``tol`` of the steady amplitude, s.

    ``tol`` is a fraction, from 1e-12 to 0.999, of the steady amplitude; of a free decay (F0 = 0) from
    ``x0`` (m), ``v0`` (m/s), of its initial amplitude ``sqrt(x0^2 + (v0 / omega_n)^2)``.

    The transient is the exact response from ``(x0, v0)`` (rest by default) minus the steady state. For an
    underdamped oscillator its envelope ``R exp(-sigma t)`` is used (the usual definition); otherwise the
    transient itself, located by bracketing and root finding. ``inf`` when the transient never decays (c <= 0).

    Raises
    ------
    ParameterError
        When nothing moves: no force and the oscillator at rest.

    Examples
    --------
    >>> round(settling_time(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)), 2)   # s
    14.06
    >>> round(settling_time(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=0.0, omega=0.0), x0=0.1), 2)   # s
    15.65
    """
    check_records(osc, force)
    tol = check_real("tol", tol, low=1e-12, high=0.999)  # a fraction: below 1e-12 t_s is rounding noise
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    ss = steady_state(osc, force)
    if ss.amplitude == 0.0 and x0 == 0.0 and v0 == 0.0:
        raise ParameterError(
            f"F0 = {force.F0!r} N with x0 = 0 m and v0 = 0 m/s: nothing moves, so there is nothing to settle: "
            "allowed F0 > 0 N, or a free decay from x0 != 0 or v0 != 0"
        )
    if osc.c <= 0.0:
        return math.inf
    w, sigma = force.omega, osc.decay_rate
    level = tol * (ss.amplitude if ss.amplitude > 0.0 else math.hypot(x0, v0 / osc.natural_frequency))
    x0 = x0 + ss.amplitude * math.sin(ss.phase)  # transient's initial displacement, m
    v0 = v0 - w * ss.amplitude * math.cos(ss.phase)  # and velocity, m/s
    if osc.regime == "underdamped":
        r = math.hypot(x0, (v0 + sigma * x0) / osc.damped_natural_frequency)
        return max(0.0, math.log(r / level) / sigma) if r > 0.0 else 0.0
    tau = osc.time_constant
    bound = abs(x0) + abs(v0 + sigma * x0) * tau + abs(x0) * sigma * tau
    t_hi = tau * (max(0.0, math.log(max(bound, level) / level)) + 3.0)
    free = SineForce(F0=0.0, omega=0.0)
    grid = np.linspace(0.0, t_hi, 4001)
    tr = np.abs(exact_response(osc, free, grid, x0=x0, v0=v0).x)
    above = np.nonzero(tr > level)[0]
    if above.size == 0:
        return 0.0
    j = above[-1]
    if j == grid.size - 1:
        return float(grid[-1])
    f = lambda s: abs(exact_response(osc, free, s, x0=x0, v0=v0).x) - level  # noqa: E731
    return float(brentq(f, grid[j], grid[j + 1], xtol=1e-12))


@dataclass(frozen=True, kw_only=True)
class EnergyBalance:
    """Cumulative energy terms along a response, J (arrays on the response's times)."""

    work: np.ndarray  # work done by the force, J
    dissipated: np.ndarray  # energy dissipated by the damper, J
    stored: np.ndarray  # kinetic + potential energy minus its initial value, J

    @property
    def residual(self) -> np.ndarray:
        """``work - dissipated - stored``, J: zero up to quadrature error."""
        return self.work - self.dissipated - self.stored


def energy_balance(osc: Oscillator, force: SineForce, resp: Response) -> EnergyBalance:
    """Work of the force, damper dissipation and stored energy along ``resp``.

    Integrals by cumulative Simpson's rule on the response's own times, which
    must be finite and strictly increasing (at least 3 samples).

    Examples
    --------
    >>> osc, f = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    >>> r = exact_response(osc, f, np.linspace(0.0, 50.0, 50001))
    >>> eb = energy_balance(osc, f, r)
    >>> bool(np.max(np.abs(eb.residual)) < 1e-9 * np.max(np.abs(eb.work)))
    True
    """
    check_records(osc, force)
    if not isinstance(resp, Response):
        raise ParameterError(f"resp = {resp!r} is not a Response: allowed the result of exact_response or simulate")
    t = _increasing(resp.t, "resp.t", "s", min_size=3)
    x, v = _array(resp.x, "resp.x", "m"), _array(resp.v, "resp.v", "m/s")
    for name, arr in (("resp.x", x), ("resp.v", v)):
        if arr.shape != t.shape or not np.all(np.isfinite(arr)):
            raise ParameterError(f"{name} has shape {arr.shape}: allowed finite values, one per time of resp.t")
    power_in = force(t) * v
    power_out = osc.c * v * v
    work = cumulative_simpson(power_in, x=t, initial=0.0)
    dissipated = cumulative_simpson(power_out, x=t, initial=0.0)
    energy = 0.5 * osc.m * v * v + 0.5 * osc.k * x * x
    return EnergyBalance(work=work, dissipated=dissipated, stored=energy - energy[0])


@functools.cache
def _peak_kernel():
    """Compile (once per process, cached on disk) the fused peak loop; numba is imported lazily."""
    import numba

    @numba.njit(parallel=True, cache=True)
    def kernel(sw, cw, kc, g, p, q, a, b):  # pragma: no cover - compiled
        nc, nw, nt = p.shape[0], p.shape[1], sw.shape[1]
        out = np.empty((nc, nw))
        for i in numba.prange(nc):
            for j in range(nw):
                pij, qij, aij, bij = p[i, j], q[i, j], a[i, j], b[i, j]
                best = 0.0
                for n in range(nt):
                    val = abs(pij * sw[j, n] + qij * cw[j, n] + aij * kc[i, n] + bij * g[i, n])
                    if val > best:
                        best = val
                out[i, j] = best
        return out

    return kernel


def peak_displacement_map(
    m: float,
    k: float,
    F0: float,
    *,
    omegas,
    dampings,
    t_end: float = 50.0,
    n_points: int = 5001,
) -> np.ndarray:
    """Max |x| over ``linspace(0, t_end, n_points)`` from rest, on an (c, omega) grid.

    ``x = Re(H) sin(omega t) + Im(H) cos(omega t) + transient``, with
    ``H = F0 / (k - m omega^2 + i c omega)``; ``sin``/``cos`` depend only on
    omega and the transient kernels only on c, so each is computed once and a
    compiled loop combines them (4 multiply-adds per sample). Cells whose
    forcing lies within ``NEAR / t_end`` of a characteristic root (undamped
    resonance with almost no damping), where that split would cancel, fall back
    to :func:`exact_response`. ``len(omegas) * n_points`` and
    ``len(dampings) * n_points`` are capped at ``MAP_CELLS_MAX``.

    Parameters
    ----------
    m, k, F0 : float
        Mass (kg), stiffness (N/m), force amplitude (N).
    omegas : array_like
        Forcing frequencies, rad/s (1-D).
    dampings : array_like
        Damping coefficients, N s/m (1-D, finite, any sign).
    t_end : float
        End of the window, s.
    n_points : int
        Samples in the window.

    Returns
    -------
    numpy.ndarray
        Shape ``(len(dampings), len(omegas))``, indexed ``[damping, omega]``, m.

    Examples
    --------
    >>> pk = peak_displacement_map(1.0, 20.0, 5.0, omegas=[3.0, 4.47], dampings=[0.5, 15.0])
    >>> np.round(pk, 3)     # m
    array([[0.613, 2.237],
           [0.135, 0.105]])
    """
    m, k, F0, t_end, n_points, w, c = _map_args(m, k, F0, t_end, n_points, omegas, dampings)
    if F0 == 0.0:
        return np.zeros((c.size, w.size))
    t = np.linspace(0.0, t_end, n_points)
    step = _uniform(t)
    with np.errstate(all="ignore"):
        ew = _grid_exp(1j * w, t, step)  # exp(i omega t)
        sw, cw = np.ascontiguousarray(ew.imag), np.ascontiguousarray(ew.real)
    kc, g, coef = _free_kernels(m, k, c, t, step, t_end)
    near, p, q = _forced_amplitudes(m, k, F0, w, c, t_end)
    # transient = free response from x0 = -q, v0 = -omega p, as in exact_response:
    # x0 P + (v0 + a x0) g
    a = -q
    b = -w[None, :] * p - coef[:, None] * q
    out = _peak_kernel()(sw, cw, kc, g, p, q, a, b)
    for i, j in zip(*np.nonzero(near), strict=True):
        try:
            r = exact_response(Oscillator(m=m, c=float(c[i]), k=k), SineForce(F0=F0, omega=float(w[j])), t)
        except ParameterError:
            out[i, j] = math.inf
        else:
            out[i, j] = np.max(np.abs(r.x))
    if not np.all(np.isfinite(out)):
        i, j = (int(v[0]) for v in np.nonzero(~np.isfinite(out)))
        raise ParameterError(
            f"dampings contains {float(c[i])!r}: with omega = {float(w[j])!r} rad/s the displacement overflows "
            f"the float range within t_end = {t_end!r} s: allowed dampings whose response stays finite"
        )
    return out


def _map_args(m, k, F0, t_end, n_points, omegas, dampings):
    """The checked arguments of :func:`peak_displacement_map`, ``(m, k, F0, t_end, n_points, omegas, dampings)``,
    refused when a table of ``len(omegas)`` or ``len(dampings)`` rows of ``n_points`` exceeds ``MAP_CELLS_MAX``."""
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    F0 = check_real("F0", F0, low=0.0, unit="N")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    w = _omegas(omegas)
    c = check_array("dampings", dampings, ndim=(1,), unit="N s/m")
    for name, size in (("omegas", w.size), ("dampings", c.size)):
        if size * n_points > MAP_CELLS_MAX:
            raise ParameterError(
                f"len({name}) * n_points = {size * n_points} is out of range: allowed <= {MAP_CELLS_MAX} "
                f"samples per table (memory)"
            )
    return m, k, F0, t_end, n_points, w, c


def _free_kernels(m: float, k: float, c: np.ndarray, t: np.ndarray, step, t_end: float):
    """Free-response kernels of each damping on the uniform times ``t``: ``(P, g, a)`` with
    ``x = x0 P + (v0 + a x0) g``; refused when one overflows within ``t_end``."""
    with np.errstate(all="ignore"):
        kc = np.empty((c.size, t.size))  # P of the free response x = x0 P + (v0 + a x0) g
        g = np.empty((c.size, t.size))
        coef = np.empty(c.size)  # a, 1/s
        roots = [_roots(_damped(m, float(ci), k)) for ci in c]
        osc_rows = [i for i, ro in enumerate(roots) if ro.kind == "osc"]
        if osc_rows:  # underdamped: exp((-sigma + i wd) t) for all of them at once
            s1 = np.array([complex(-roots[i].sigma, roots[i].wd) for i in osc_rows])
            z = _grid_exp(s1, t, step)
            kc[osc_rows] = z.real
            g[osc_rows] = z.imag / s1.imag[:, None]
        for i, ro in enumerate(roots):
            coef[i] = ro.a
            if ro.kind != "osc":
                kc[i], _, g[i], _ = _kernels(Oscillator(m=m, c=float(c[i]), k=k), t)
    blown = ~(np.isfinite(kc).all(axis=1) & np.isfinite(g).all(axis=1))
    if blown.any():
        i = int(np.nonzero(blown)[0][0])
        raise ParameterError(
            f"dampings contains {float(c[i])!r}: its free response overflows the float range within "
            f"t_end = {t_end!r} s: allowed dampings whose response stays finite"
        )
    return kc, g, coef


def _forced_amplitudes(m: float, k: float, F0: float, w: np.ndarray, c: np.ndarray, t_end: float):
    """``(near, Re H, Im H)`` on the (damping, omega) grid, ``H = F0 / (k - m omega^2 + i c omega)``: ``near``
    where i omega lies within ``NEAR / t_end`` of a characteristic root, and there H is set to 0."""
    # distance from i omega to the nearest characteristic root, 1/s
    sigma = (c / (2.0 * m))[:, None]
    root = np.emath.sqrt(sigma * sigma - k / m)
    dist = np.minimum(np.abs(1j * w[None, :] + sigma - root), np.abs(1j * w[None, :] + sigma + root))
    near = dist * t_end < NEAR
    den = (k - m * w * w)[None, :] + 1j * np.multiply.outer(c, w)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        h = np.where(near, 0.0, F0 / np.where(near, 1.0, den))
    return near, h.real, h.imag
