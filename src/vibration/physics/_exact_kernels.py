"""Compiled kernels of :mod:`vibration.physics.exact` (numba, cached on disk).

Imported lazily by ``exact._compiled()`` so that ``import vibration`` does not
load numba. The kernels take the parameter vector built by ``exact._pack``
(its docstring gives the layout), so one compiled signature serves every
regime:

* :func:`uniform_step` tells a uniform increasing grid from ``t[0] >= 0``;
* :func:`block` evaluates x and v on such a grid as products of about sqrt(n)
  anchors and sqrt(n) offsets, every factor computed directly;
* :func:`series` gives the forced response from rest near ``t = 0`` from its
  Taylor series.

The formulas are those of the module docstring of ``exact``; the comments say
which identity each line uses.
"""

from __future__ import annotations

import cmath
import math

import numba
import numpy as np

from .exact import CRITICAL, FREE, OSC, SERIES_RHO, STEADY
from .exact import NEAR_FORM as NEAR

_EPS = float(np.finfo(float).eps)


@numba.njit(cache=True)
def uniform_step(t, ramp):  # pragma: no cover - compiled
    """The step h (s) if ``t`` is uniform and increasing from ``t[0] >= 0``, else -1.

    Uniform means ``|t[n] - (t[0] + n h)| <= 4 eps t[-1]`` for every n, which
    ``numpy.linspace`` meets (it deviates by at most an ulp or two). ``ramp``
    is ``0, 1, 2, ...`` as floats, at least as long as ``t``.
    """
    n = t.shape[0]
    t0, t1 = t[0], t[n - 1]
    if n < 2 or not (t0 >= 0.0 and t1 > t0):
        return -1.0
    h = (t1 - t0) / (n - 1)
    tol = 4.0 * _EPS * t1
    ok = True
    for i in range(n):  # no early exit: the loop vectorises
        ok &= abs((ramp[i] * h + t0) - t[i]) <= tol
    return h if ok else -1.0


@numba.njit(cache=True)
def _free_basis(kr, sigma, wd, slow, fast, t):  # pragma: no cover - compiled
    """``(P, Q, g)`` at ``t >= 0``: the free response is ``x = x0 P + bx g``, ``v = v0 Q + bv g``.

    ``OSC``: ``P = Q = Re exp(s1 t)`` and ``g = Im exp(s1 t)`` (not divided by
    wd); ``CRITICAL``: ``P = Q = exp(-sigma t)``, ``g = t P``; ``REAL``:
    ``exp(slow t)``, ``exp(fast t)``, ``g = (exp(fast t) - exp(slow t)) / (fast - slow)``
    formed with ``expm1`` from the larger exponential.
    """
    if kr == OSC:
        env = math.exp(-sigma * t)
        kc = env * math.cos(wd * t)
        return kc, kc, env * math.sin(wd * t)
    if kr == CRITICAL:
        e = math.exp(-sigma * t)
        return e, e, t * e
    es, ef = math.exp(slow * t), math.exp(fast * t)
    span = fast - slow
    hi = ef if span > 0.0 else es
    d = abs(span)
    return es, ef, hi * math.expm1(-d * t) / -d


@numba.njit(cache=True)
def _qn(tiny, dr, di, t):  # pragma: no cover - compiled
    """Real and imaginary parts of ``1 - exp(-d t)``, accurate relative to ``|d t|``."""
    if tiny:
        return t - 0.5 * dr * t * t, -0.5 * di * t * t
    b = di * t
    sh = math.sin(0.5 * b)
    em = math.expm1(-dr * t)
    return 2.0 * sh * sh * (1.0 + em) - em, (1.0 + em) * math.sin(b)


@numba.njit(cache=True)
def _cis(w, t):  # pragma: no cover - compiled
    return complex(math.cos(w * t), math.sin(w * t))


@numba.njit(cache=True)
def series(p, ts):  # pragma: no cover - compiled
    """Forced x, v from rest at the times ``ts`` (``R |t| <= 1``), shape (2, len(ts)).

    ``x = (F0/m) Im E``, ``v = (F0/m) omega Re E`` with ``E = E[i omega, s1, s2](t)
    = t^2 sum_k h_k (t/s)^k / (k+2)!``: ``h_k`` is the complete homogeneous
    symmetric polynomial of degree k in the nodes scaled by ``s = max|t|``,
    from ``p_k = -2 sigma p_(k-1) - wn2 p_(k-2)`` (the two roots) and
    ``h_k = i omega h_(k-1) + p_k``; the sum is taken by Horner's rule.
    ``Re E = t^2/2 + ...`` and ``Im E = omega t^3/6 + ...`` are led by exact
    terms, so x and v are accurate relative to themselves however short the time.
    """
    sigma, wn2, w, scale, radius = p[2], p[4], p[12], p[24], p[25]
    m = ts.shape[0]
    out = np.zeros((2, m))
    s = 0.0
    for i in range(m):
        s = max(s, abs(ts[i]))
    if s == 0.0:
        return out
    rho = max(w, radius) * s
    # term k is at most rho^k / (2 k!) of the leading one: stop once rho^(k-1) / (k-1)! < 1e-18
    n_terms, term = 1, 1.0
    while term > 1e-18 and n_terms < 60:
        term *= rho / n_terms
        n_terms += 1
    n_terms += 2
    s2, wn2s, ws = -2.0 * sigma * s, wn2 * s * s, w * s
    cr, ci = np.empty(n_terms), np.empty(n_terms)  # h_k / (k+2)!
    hr, hi = 1.0, 0.0
    p_prev, p_k = 0.0, 1.0
    fact = 2.0
    cr[0], ci[0] = 0.5, 0.0
    for k in range(1, n_terms):
        p_prev, p_k = p_k, s2 * p_k - wn2s * p_prev
        hr, hi = p_k - ws * hi, ws * hr
        fact *= k + 2.0
        cr[k], ci[k] = hr / fact, hi / fact
    for i in range(m):
        u = ts[i] / s
        er, ei = cr[n_terms - 1], ci[n_terms - 1]
        for k in range(n_terms - 2, -1, -1):
            er, ei = er * u + cr[k], ei * u + ci[k]
        t2 = ts[i] * ts[i]
        out[0, i] = scale * (ei * t2)
        out[1, i] = (scale * w) * (er * t2)
    return out


@numba.njit(cache=True)
def block(t, ramp, forms, bounds, xo, vo):  # pragma: no cover - compiled
    """x, v on a uniform grid into ``xo``, ``vo``; returns 0, 1 (not uniform) or 2 (not finite).

    ``forms[f]`` (a parameter vector) serves the samples with ``bounds[f, 0] <= t <
    bounds[f, 1]`` (the near-resonance form, then the steady-state split).
    """
    n = t.shape[0]
    h = uniform_step(t, ramp)
    if h < 0.0:
        return 1
    for f in range(forms.shape[0]):
        a = np.searchsorted(t, bounds[f, 0])
        b = np.searchsorted(t, bounds[f, 1])
        if b > a:
            _block_form(t[a:b], h, forms[f], xo[a:b], vo[a:b])
    ok = True
    big = np.finfo(np.float64).max
    for i in range(n):  # no early exit: the loop vectorises
        ok &= abs(xo[i]) <= big
        ok &= abs(vo[i]) <= big
    return 0 if ok else 2


@numba.njit(cache=True)
def _block_form(t, h, p, xo, vo):  # pragma: no cover - compiled
    """x, v of one form on the uniform grid ``t`` (step ``h``, s) into ``xo``, ``vo``.

    With ``t = a + d`` (anchors ``a = t[j B]``, offsets ``d = b h``, ``B`` about
    sqrt(n)) every term of x and v is ``Im(C(a) F(d))``: ``exp(s t) = exp(s a)
    exp(s d)`` and, with real roots or a double root, ``g(a + d) = exp(fast a)
    g(d) + g(a) exp(slow d)`` (all terms positive, so nothing cancels). The
    columns ``F`` are computed once per offset, the coefficients ``C`` once per
    anchor, and each sample costs one short sum. Samples with ``R t <= 1`` then
    take the forced part from :func:`series` plus the free response.
    """
    n = t.shape[0]
    kr, kf = int(p[0]), int(p[1])
    sigma, wd, wn2, slow, fast, a = p[2], p[3], p[4], p[5], p[6], p[7]
    x0, v0, gx, gv, w = p[8], p[9], p[10], p[11], p[12]
    H = complex(p[13], p[14])
    s1 = complex(p[15], p[16])
    tiny, dr, di = p[19] != 0.0, p[17], p[18]
    mx, mv = complex(p[20], p[21]), 1j * complex(p[22], p[23])  # v = Re(mv PQ) = Im(i mv PQ)
    bx, bv = v0 + a * x0 + gx, -(a * v0 + wn2 * x0) + gv  # coefficients of g in x and v
    B = int(math.sqrt(n - 1))
    while B * B > n - 1:
        B -= 1
    while (B + 1) * (B + 1) <= n - 1:
        B += 1
    B += 1
    J = (n + B - 1) // B
    nfree = 1 if kr == OSC else 3
    K = nfree + kf  # steady: one column more, near: two
    # columns by offset and coefficients by anchor, complex, stored as separate real planes
    # so that the sum over each block of samples is a vectorisable loop
    FR, FI = np.zeros((K, B)), np.zeros((K, B))
    CX, CV = np.zeros((J, K), dtype=np.complex128), np.zeros((J, K), dtype=np.complex128)
    for b in range(B):
        d = b * h
        P, Q, g = _free_basis(kr, sigma, wd, slow, fast, d)
        if kr == OSC:
            FR[0, b], FI[0, b] = P, g  # exp(s1 d)
        else:
            FR[0, b], FR[1, b], FR[2, b] = P, Q, g
        if kf != FREE:
            pd = _cis(w, d)
            FR[nfree, b], FI[nfree, b] = pd.real, pd.imag
            if kf == NEAR:
                qa, qb = _qn(tiny, dr, di, d)
                pq = pd * complex(qa, qb)
                FR[nfree + 1, b], FI[nfree + 1, b] = pq.real, pq.imag
    for j in range(J):
        ta = t[j * B]
        P, Q, g = _free_basis(kr, sigma, wd, slow, fast, ta)
        if kr == OSC:
            # x0 Re Z + (bx / wd) Im Z = Im((i x0 + bx / wd) Z)
            z = complex(P, g)
            CX[j, 0] = complex(bx / wd, x0) * z
            CV[j, 0] = complex(bv / wd, v0) * z
        else:
            # x0 P(a + d) + bx g(a + d) with P(a + d) = P(a) P(d), g(a + d) = Q(a) g(d) + g(a) P(d)
            CX[j, 0] = complex(0.0, x0 * P + bx * g)
            CV[j, 0] = complex(0.0, bv * g)
            CV[j, 1] = complex(0.0, v0 * Q)
            CX[j, 2] = complex(0.0, bx * Q)
            CV[j, 2] = complex(0.0, bv * Q)
        if kf == STEADY:
            pa = H * _cis(w, ta)
            CX[j, nfree], CV[j, nfree] = pa, (1j * w) * pa
        elif kf == NEAR:
            # exp(i w t) q(t) at t = a + d: P(a) q(a) P(d) + exp(s1 a) P(d) q(d)
            qa, qb = _qn(tiny, dr, di, ta)
            c1 = _cis(w, ta) * complex(qa, qb)
            za = cmath.exp(s1 * ta)
            CX[j, nfree], CV[j, nfree] = mx * c1, mv * c1
            CX[j, nfree + 1], CV[j, nfree + 1] = mx * za, mv * za
    for j in range(J):
        base = j * B
        nb = min(B, n - base)
        xb, vb = xo[base : base + nb], vo[base : base + nb]
        xb[:] = 0.0
        vb[:] = 0.0
        for k in range(K):
            # Im(C F) = Re C Im F + Im C Re F
            cxr, cxi, cvr, cvi = CX[j, k].real, CX[j, k].imag, CV[j, k].real, CV[j, k].imag
            fr, fi = FR[k], FI[k]
            for b in range(nb):
                xb[b] += cxr * fi[b] + cxi * fr[b]
            for b in range(nb):
                vb[b] += cvr * fi[b] + cvi * fr[b]
    if kf != FREE:
        # first samples: forced part from rest by its series, plus the free response from (x0, v0)
        rho_t = SERIES_RHO / max(w, p[25])
        m = 0
        while m < n and t[m] <= rho_t:
            m += 1
        if m > 0:
            xs = series(p, t[:m])
            x0o, v0o = p[26], p[27]
            ax = v0o + a * x0o
            av = -(a * v0o + wn2 * x0o)
            for i in range(m):
                P, Q, g = _free_basis(kr, sigma, wd, slow, fast, t[i])
                if kr == OSC:
                    g /= wd
                xo[i] = xs[0, i] + (x0o * P + ax * g)
                vo[i] = xs[1, i] + (v0o * Q + av * g)
