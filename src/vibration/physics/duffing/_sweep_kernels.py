"""The compiled Dormand-Prince 5(4) kernel of a stepped Duffing sweep (numba), in four parts.

Imported lazily by :func:`vibration.physics.duffing.sweep_integrators._sweep_kernel`, so that ``import
vibration`` does not import numba. :func:`sweep_kernel` walks the frequencies and periods and controls the
step; :func:`_dp54_step` takes one step with its error estimate (SciPy's RK45 tableau), :func:`_step_extremum`
finds an extremum of x inside a step and :func:`_steady_test` judges one period's stroboscopic change. Every
function is compiled once and cached on disk.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["sweep_kernel"]

# Dormand-Prince 5(4), the tableau and error estimate of SciPy's RK45
a21 = 1 / 5
a31, a32 = 3 / 40, 9 / 40
a41, a42, a43 = 44 / 45, -56 / 15, 32 / 9
a51, a52, a53, a54 = 19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729
a61, a62, a63, a64, a65 = 9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656
b1, b3, b4, b5, b6 = 35 / 384, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84
e1, e3, e4, e5, e6, e7 = -71 / 57600, 71 / 16695, -71 / 1920, 17253 / 339200, -22 / 525, 1 / 40
c2, c3, c4, c5 = 1 / 5, 3 / 10, 4 / 5, 8 / 9


@numba.njit(cache=True)
def _accel(x, v, t, m, c, k, k3, F0, w):  # pragma: no cover
    """The Duffing acceleration at the state (x, v) and time t within the period."""
    return (F0 * np.cos(w * t) - c * v - k * x - k3 * x * x * x) / m


@numba.njit(cache=True)
def _dp54_step(x, v, a0, tau, h, t_new, m, c, k, k3, F0, w, rtol, atol):  # pragma: no cover
    """One Dormand-Prince 5(4) step of length h from tau (FSAL: k1 = (v, a0)).

    Returns the new state and acceleration ``(xn, vn, an)`` at ``t_new`` and the scaled error norm.
    """
    k1x, k1v = v, a0
    xx, vv = x + h * a21 * k1x, v + h * a21 * k1v
    k2x, k2v = vv, _accel(xx, vv, tau + c2 * h, m, c, k, k3, F0, w)
    xx = x + h * (a31 * k1x + a32 * k2x)
    vv = v + h * (a31 * k1v + a32 * k2v)
    k3x, k3v = vv, _accel(xx, vv, tau + c3 * h, m, c, k, k3, F0, w)
    xx = x + h * (a41 * k1x + a42 * k2x + a43 * k3x)
    vv = v + h * (a41 * k1v + a42 * k2v + a43 * k3v)
    k4x, k4v = vv, _accel(xx, vv, tau + c4 * h, m, c, k, k3, F0, w)
    xx = x + h * (a51 * k1x + a52 * k2x + a53 * k3x + a54 * k4x)
    vv = v + h * (a51 * k1v + a52 * k2v + a53 * k3v + a54 * k4v)
    k5x, k5v = vv, _accel(xx, vv, tau + c5 * h, m, c, k, k3, F0, w)
    xx = x + h * (a61 * k1x + a62 * k2x + a63 * k3x + a64 * k4x + a65 * k5x)
    vv = v + h * (a61 * k1v + a62 * k2v + a63 * k3v + a64 * k4v + a65 * k5v)
    k6x, k6v = vv, _accel(xx, vv, tau + h, m, c, k, k3, F0, w)
    xn = x + h * (b1 * k1x + b3 * k3x + b4 * k4x + b5 * k5x + b6 * k6x)
    vn = v + h * (b1 * k1v + b3 * k3v + b4 * k4v + b5 * k5v + b6 * k6v)
    an = _accel(xn, vn, t_new, m, c, k, k3, F0, w)
    ex = h * (e1 * k1x + e3 * k3x + e4 * k4x + e5 * k5x + e6 * k6x + e7 * vn)
    ev = h * (e1 * k1v + e3 * k3v + e4 * k4v + e5 * k5v + e6 * k6v + e7 * an)
    sx = atol + rtol * max(abs(x), abs(xn))
    sv = atol + rtol * max(abs(v), abs(vn))
    return xn, vn, an, np.sqrt(0.5 * ((ex / sx) ** 2 + (ev / sv) ** 2))


@numba.njit(cache=True)
def _step_extremum(x, v, a0, xn, vn, an, h):  # pragma: no cover
    """The extremum of x inside a step whose velocity changes sign: quintic Hermite, bisection on its slope."""
    lo, hi = 0.0, 1.0
    for _ in range(48):
        s = 0.5 * (lo + hi)
        d1 = (
            x * (-30 * s**2 + 60 * s**3 - 30 * s**4)
            + h * v * (1 - 18 * s**2 + 32 * s**3 - 15 * s**4)
            + h * h * a0 * (2 * s - 9 * s**2 + 12 * s**3 - 5 * s**4) / 2
            + xn * (30 * s**2 - 60 * s**3 + 30 * s**4)
            + h * vn * (-12 * s**2 + 28 * s**3 - 15 * s**4)
            + h * h * an * (3 * s**2 - 8 * s**3 + 5 * s**4) / 2
        )
        if (d1 > 0.0) == (v > 0.0):
            lo = s
        else:
            hi = s
    s = 0.5 * (lo + hi)
    return (
        x * (1 - 10 * s**3 + 15 * s**4 - 6 * s**5)
        + h * v * (s - 6 * s**3 + 8 * s**4 - 3 * s**5)
        + h * h * a0 * (s**2 - 3 * s**3 + 3 * s**4 - s**5) / 2
        + xn * (10 * s**3 - 15 * s**4 + 6 * s**5)
        + h * vn * (-4 * s**3 + 7 * s**4 - 3 * s**5)
        + h * h * an * (s**3 - 2 * s**4 + s**5) / 2
    )


@numba.njit(cache=True)
def _steady_test(dd, d_prev, rho_prev, scale, steady_tol):  # pragma: no cover
    """Whether one period's stroboscopic change ``dd`` says steady, with the contraction ratio it implies.

    The change, extrapolated over the remaining geometric tail ``r / (1 - r)`` (``r`` the larger of the
    last two ratios of consecutive changes), must stay within ``steady_tol`` of the half swing ``scale``.
    Returns ``(ok, rho)``.
    """
    if d_prev > 0.0:
        rho = dd / d_prev
    else:
        rho = 0.0 if dd == 0.0 else 1.0
    r = max(rho, rho_prev)
    ok = False
    if dd == 0.0:
        ok = True
    elif r < 1.0:
        ok = dd * max(1.0, r / (1.0 - r)) <= steady_tol * scale
    return ok, rho


@numba.njit(cache=True)
def sweep_kernel(
    m,
    c,
    k,
    k3,
    F0,
    omegas,
    x0,
    v0,
    rtol,
    atol,
    steady_tol,
    min_periods,
    max_periods,
    blow_up,
    amp,
    xmax_out,
    xmin_out,
    steady,
    periods,
    xs,
    vs,
    nsteps,
    max_steps,
):  # pragma: no cover
    """Returns ``(status, j)``: status 0 done, 1 ``max_steps`` attempted steps spent (at frequency j)."""
    x, v = x0, v0
    attempted = 0
    for j in range(omegas.shape[0]):
        w = omegas[j]
        T = 2.0 * np.pi / w
        h = T / 40.0
        hmax = T / 16.0
        px, pv = x, v
        d_prev, ok_prev, rho_prev = -1.0, False, 1.0
        done, escaped = False, False
        xmax, xmin = -np.inf, np.inf
        n = 0
        steps = 0
        while n < max_periods and not done:
            tau = 0.0
            xmax, xmin = x, x
            a0 = _accel(x, v, tau, m, c, k, k3, F0, w)
            rejected = False
            while tau < T:
                attempted += 1
                if attempted > max_steps:
                    nsteps[j] = steps
                    periods[j] = n
                    return 1, j
                if h > hmax:
                    h = hmax
                last = tau + h >= T
                if last:
                    h = T - tau
                t_new = T if last else tau + h
                xn, vn, an, err = _dp54_step(x, v, a0, tau, h, t_new, m, c, k, k3, F0, w, rtol, atol)
                if not np.isfinite(err):
                    escaped = True
                    break
                if err < 1.0:
                    steps += 1
                    if (v > 0.0) != (vn > 0.0):
                        xe = _step_extremum(x, v, a0, xn, vn, an, h)
                        xmax = max(xmax, xe)
                        xmin = min(xmin, xe)
                    x, v, a0 = xn, vn, an
                    xmax = max(xmax, x)
                    xmin = min(xmin, x)
                    tau = t_new
                    if err == 0.0:
                        fac = 10.0
                    else:
                        fac = min(10.0, 0.9 * err ** (-0.2))
                    if rejected:
                        fac = min(1.0, fac)
                    if not last:
                        h *= fac
                    rejected = False
                    if abs(x) > blow_up:
                        escaped = True
                        break
                else:
                    h *= max(0.2, 0.9 * err ** (-0.2))
                    rejected = True
            if escaped:
                break
            n += 1
            # steady criterion on the stroboscopic state (x, v/omega)
            dd = np.sqrt((x - px) ** 2 + ((v - pv) / w) ** 2)
            px, pv = x, v
            ok, rho = _steady_test(dd, d_prev, rho_prev, max(0.5 * (xmax - xmin), atol), steady_tol)
            if ok and ok_prev and n >= min_periods:
                done = True
            d_prev, ok_prev, rho_prev = dd, ok, rho
        nsteps[j] = steps
        periods[j] = n
        if escaped:
            amp[j] = np.nan
            xmax_out[j] = np.nan
            xmin_out[j] = np.nan
            steady[j] = False
            xs[j] = np.nan
            vs[j] = np.nan
            x, v = 0.0, 0.0  # the next frequency starts from rest
        else:
            amp[j] = 0.5 * (xmax - xmin)
            xmax_out[j] = xmax
            xmin_out[j] = xmin
            steady[j] = done
            xs[j] = x
            vs[j] = v
    return 0, omegas.shape[0]
