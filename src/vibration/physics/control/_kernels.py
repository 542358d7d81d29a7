"""Compiled fixed-step RK4 of the semi-active loop (numba, cached on disk; imported lazily)."""

from __future__ import annotations

import functools
import math

import numpy as np

# The kernels are plain module-level functions compiled on first use by _sa_kernel (numba is imported
# lazily). They refer to each other through the module globals below, not through closures: numba's
# on-disk cache keys a closure by its pickled free variables, which differ in every process, so nested
# kernels were recompiled (several seconds) by every new process.
#: Largest number of fixed RK4 steps of one semi-active run (about 8 s at 400 ns a step).
RK4_STEPS_MAX = 20_000_000

#: Largest total number of RK4 steps of one sweep (parallel over the frequencies: about 20 s on two cores).
SWEEP_STEPS_MAX = 100_000_000

_nb_device = _nb_rhs = _nb_run = None
_prange = range


def _sa_device(law, p, xb, vb, s):  # pragma: no cover - compiled
    """Force of the device on the mass (N), state derivatives of the MR internals, command."""
    c_sky, c_min, c_max = p[3], p[4], p[5]
    x, v = s[0], s[1]
    vr = v - vb
    dz = dy = du = 0.0
    cmd = 0.0
    if law == 0:  # passive at c_min
        f = -c_min * vr
    elif law == 1:  # ideal skyhook
        f = -c_sky * v
    elif law == 2:  # on-off skyhook
        if v * vr > 0.0:
            f = -c_max * vr
            cmd = 1.0
        else:
            f = -c_min * vr
    elif law == 3:  # continuous clipped skyhook
        if v * vr > 0.0:
            a = min(max(c_sky * abs(v), c_min * abs(vr)), c_max * abs(vr))
            f = -a if vr > 0.0 else a
            cmd = 1.0
        else:
            f = -c_min * vr
    else:  # MR damper, modified Bouc-Wen, clipped-optimal voltage
        xr = x - xb
        z, y, u = s[2], s[3], s[4]
        c0 = p[6] + p[7] * u
        k0 = p[8]
        c1 = p[9] + p[10] * u
        k1 = p[11]
        alpha = p[12] + p[13] * u
        gam, bet, A, n, eta, vmax = p[14], p[15], p[16], p[17], p[18], p[19]
        dy = (alpha * z + c0 * vr + k0 * (xr - y)) / (c0 + c1)
        d = vr - dy
        az = abs(z)
        if n == 2.0:
            dz = -gam * abs(d) * z * az - bet * d * az * az + A * d
        else:
            dz = -gam * abs(d) * z * az ** (n - 1.0) - bet * d * az**n + A * d
        f = -(c1 * dy + k1 * xr)
        if v * vr > 0.0:
            cmd = 1.0
        du = -eta * (u - cmd * vmax)
    return f, dz, dy, du, cmd


def _sa_rhs(law, p, xb, vb, s, out):  # pragma: no cover - compiled
    m, c, k = p[0], p[1], p[2]
    f, dz, dy, du, cmd = _nb_device(law, p, xb, vb, s)
    out[0] = s[1]
    out[1] = (-k * (s[0] - xb) - c * (s[1] - vb) + f) / m
    out[2] = dz
    out[3] = dy
    out[4] = du
    return f, cmd


def _sa_run(law, p, Y, w, s0, dt, n_steps, stride, m_start):  # pragma: no cover - compiled
    """RK4 from state s0 for n_steps of dt; record every stride steps; measure from step m_start.

    Returns (record (n_rec, 5): t, x, v, f, cmd; stats: sum x cos, sum x sin, max|x|,
    sum f^2, max|f|, switches, samples, sum |f vr| dt).
    """
    s = s0.copy()
    k1 = np.empty(5)
    k2 = np.empty(5)
    k3 = np.empty(5)
    k4 = np.empty(5)
    tmp = np.empty(5)
    n_rec = n_steps // stride + 1
    rec = np.empty((n_rec, 5))
    stats = np.zeros(8)
    prev = -1.0
    yw = Y * w
    for i in range(n_steps + 1):
        t = i * dt
        sn, cs = math.sin(w * t), math.cos(w * t)
        f, cmd = _nb_rhs(law, p, Y * sn, yw * cs, s, k1)
        if i % stride == 0:
            j = i // stride
            rec[j, 0] = t
            rec[j, 1] = s[0]
            rec[j, 2] = s[1]
            rec[j, 3] = f
            rec[j, 4] = s[4] if law == 4 else cmd
        if i >= m_start and i < n_steps:  # left-point sums over whole periods (exact for trig polynomials)
            x = s[0]
            stats[0] += x * cs
            stats[1] += x * sn
            stats[2] = max(stats[2], abs(x))
            stats[3] += f * f
            stats[4] = max(stats[4], abs(f))
            if prev >= 0.0 and cmd != prev:
                stats[5] += 1.0
            prev = cmd
            stats[6] += 1.0
            stats[7] += abs(f * (s[1] - yw * cs)) * dt
        if i == n_steps:
            break
        for q in range(5):
            tmp[q] = s[q] + 0.5 * dt * k1[q]
        sh, ch = math.sin(w * (t + 0.5 * dt)), math.cos(w * (t + 0.5 * dt))
        _nb_rhs(law, p, Y * sh, yw * ch, tmp, k2)
        for q in range(5):
            tmp[q] = s[q] + 0.5 * dt * k2[q]
        _nb_rhs(law, p, Y * sh, yw * ch, tmp, k3)
        for q in range(5):
            tmp[q] = s[q] + dt * k3[q]
        t1 = (i + 1) * dt
        _nb_rhs(law, p, Y * math.sin(w * t1), yw * math.cos(w * t1), tmp, k4)
        for q in range(5):
            s[q] += dt / 6.0 * (k1[q] + 2.0 * k2[q] + 2.0 * k3[q] + k4[q])
    return rec, stats


def _sa_sweep(law, p, Y, ws, s0s, dts, n_steps, n_settle):  # pragma: no cover - compiled
    out = np.empty((ws.size, 8))
    for j in _prange(ws.size):
        _, st = _nb_run(law, p, Y, ws[j], s0s[j], dts[j], n_steps[j], n_steps[j], n_settle[j])
        out[j] = st
    return out


@functools.cache
def _sa_kernel():
    """Compile (once per process, cached on disk) the fixed-step RK4 of the semi-active loop; numba is imported
    lazily. The compiled functions are bound to module globals, where numba resolves the calls between them."""
    global _nb_device, _nb_rhs, _nb_run, _prange
    import numba

    _prange = numba.prange
    _nb_device = numba.njit(cache=True)(_sa_device)
    _nb_rhs = numba.njit(cache=True)(_sa_rhs)
    _nb_run = numba.njit(cache=True)(_sa_run)
    return _nb_run, numba.njit(cache=True, parallel=True)(_sa_sweep)
