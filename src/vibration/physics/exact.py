"""Closed-form response of the forced oscillator, exact in every regime.

Write the characteristic roots ``s1, s2`` of ``m s^2 + c s + k`` and let
``E[a, b, ...](t)`` be the divided difference of ``s -> exp(s t)`` over the
nodes. Then, from ``x(0) = x0``, ``v(0) = v0``,

* the impulse kernel is ``g(t) = E[s1, s2](t) = exp(-sigma t) S(t)``,
* the free response is ``x0 g'(t) + (v0 + 2 sigma x0) g(t)``,
* the response to ``F0 sin(omega t)`` from rest is
  ``(F0/m) Im E[i omega, s1, s2](t)`` with
  ``E[i omega, s1, s2] = (E[i omega, s1] - E[s1, s2]) / (i omega - s2)``.

``s1`` is the root nearest ``i omega``; ``|i omega - s2| >= omega_n`` for
``c >= 0``, so the only small divisor is ``i omega - s1``, which vanishes at
undamped resonance. It is removed analytically with
``E[i omega, s1](t) = exp(i omega t) t h(z)``, ``z = (i omega - s1) t``,
``h(z) = (1 - exp(-z)) / z``, and ``1 - exp(-z)`` is evaluated with
``expm1`` and half-angle sines, so there is no catastrophic cancellation near
resonance or near critical damping, and ``t cos`` growth at exact undamped
resonance comes out of the same formula. The kernels are written with
``cos, sin`` (underdamped), ``t exp`` (critical) or ``exp, expm1``
(overdamped), each continuous through ``zeta = 1``.

Away from that singular case (``|i omega - s1| max|t| >= NEAR``) the same
response is formed as steady state ``Im(H exp(i omega t))``, ``H = F0 / (k - m
omega^2 + i c omega)``, plus the free response from the initial conditions the
steady state leaves over: every term is then accurate relative to itself,
which keeps very slow forcing (omega << omega_n) accurate too.

Cost per sample: five transcendental evaluations (``exp``, ``cos``/``sin`` of
``wd t`` and of ``omega t``) for an underdamped oscillator, six near undamped
resonance (``expm1`` and the half-angle ``sin``/``cos`` of the detuning phase
replace ``cos``/``sin(omega t)``), three to five with real roots.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .model import Oscillator, ParameterError, SineForce, check_real, check_records


@dataclass(frozen=True)
class Response:
    """Time response of the oscillator.

    ``t`` (s), ``x`` (m) and ``v`` (m/s) are arrays of one shape. ``nfev`` is
    the number of right-hand-side evaluations (0 for the closed form);
    ``status`` is the solver status (0: reached the end).
    """

    t: np.ndarray  # time, s
    x: np.ndarray  # displacement, m
    v: np.ndarray  # velocity, m/s
    method: str  # "exact" or the solve_ivp method name
    nfev: int = 0  # right-hand-side evaluations
    njev: int = 0  # Jacobian evaluations
    nlu: int = 0  # LU decompositions
    status: int = 0  # solver status, 0 = success
    message: str = "closed form"
    rtol: float | None = None  # relative tolerance asked of the solver
    atol: float | None = None  # absolute tolerance asked of the solver, m and m/s

    @property
    def success(self) -> bool:
        """True when the integration reached ``t_end``."""
        return self.status == 0


@dataclass(frozen=True)
class SteadyState:
    """Steady-state (particular) response ``x_ss(t) = amplitude sin(omega t - phase)``."""

    amplitude: float  # displacement amplitude, m
    phase: float  # lag of x behind F, rad; in [0, pi] for c >= 0
    magnification: float  # amplitude / (F0 / k), dimensionless
    velocity_amplitude: float  # omega * amplitude, m/s
    static_deflection: float  # F0 / k, m


def steady_state(osc: Oscillator, force: SineForce) -> SteadyState:
    """Amplitude, phase lag and magnification of the steady-state response.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    force : SineForce
        F0 (N), omega (rad/s).

    Returns
    -------
    SteadyState
        ``amplitude`` (m) and ``phase`` (rad) such that
        ``x_ss(t) = amplitude * sin(omega t - phase)``; ``magnification`` is
        ``amplitude / (F0/k)``. At undamped resonance the amplitude is ``inf``
        and the phase ``pi/2``. For c < 0 the particular solution is returned
        (phase in ``[-pi, 0]``), although it is never reached.

    Examples
    --------
    >>> ss = steady_state(Oscillator(1.0, 0.5, 20.0), SineForce(5.0, 3.0))
    >>> round(ss.amplitude, 4), round(ss.phase, 4)     # m, rad
    (0.4504, 0.1355)
    >>> round(ss.magnification, 4)
    1.8015
    """
    check_records(osc, force)
    r = force.omega / osc.natural_frequency  # frequency ratio
    two_zeta_r = 2.0 * osc.damping_ratio * r
    one_minus = (1.0 - r) * (1.0 + r)
    den = math.hypot(one_minus, two_zeta_r)
    mag = math.inf if den == 0.0 else 1.0 / den
    phase = math.pi / 2 if den == 0.0 else math.atan2(two_zeta_r, one_minus)
    static = force.F0 / osc.k
    amp = static * mag if force.F0 > 0 else 0.0
    return SteadyState(
        amplitude=amp,
        phase=phase,
        magnification=mag,
        velocity_amplitude=force.omega * amp,
        static_deflection=static,
    )


def _times(t) -> np.ndarray:
    try:
        arr = np.asarray(t, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"t = {t!r} is not an array of numbers: allowed finite times in s") from None
    if arr.ndim > 1:
        raise ParameterError(f"t has shape {arr.shape}: allowed a scalar or a 1-D array of times in s")
    if not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)].ravel()[0]
        raise ParameterError(f"t contains {bad!r}: allowed finite times in s")
    return arr


def _kernels(osc: Oscillator, t: np.ndarray):
    """Return ``(kc, g, s1, s2, cb, sb)`` in a form stable in every regime.

    ``g(t) = E[s1, s2](t)`` is the unit impulse response times m (s) and
    ``kc = g'(t) + sigma g(t)`` (``exp(-sigma t) cos(wd t)`` when underdamped).
    For oscillating roots ``cb, sb = cos, sin(wd t)`` are returned for reuse by
    :func:`_forced_near` (else ``None``).
    """
    sigma = osc.decay_rate
    wn2 = osc.k / osc.m
    q = wn2 - sigma * sigma
    cb = sb = None
    if q > 0.0:  # oscillating roots -sigma +/- i wd
        wd = math.sqrt(q)
        env = np.exp(-sigma * t)
        cb, sb = np.cos(wd * t), np.sin(wd * t)
        kc, ks = env * cb, env * sb / wd
        s1, s2 = complex(-sigma, wd), complex(-sigma, -wd)
    elif q == 0.0:  # double root -sigma
        kc = np.exp(-sigma * t)
        ks = t * kc
        s1 = s2 = complex(-sigma, 0.0)
    else:  # two real roots, s_hi - s_lo = 2 mu
        mu = math.sqrt(-q)
        if sigma > 0.0:
            s_hi, s_lo = -wn2 / (sigma + mu), -(sigma + mu)
        else:
            s_hi, s_lo = -sigma + mu, wn2 / (-sigma + mu)  # both roots positive
        e_hi = np.exp(s_hi * t)
        e2m = np.expm1(-2.0 * mu * t)
        kc, ks = 0.5 * e_hi * (2.0 + e2m), -e_hi * e2m / (2.0 * mu)
        s1, s2 = complex(s_hi, 0.0), complex(s_lo, 0.0)
    return kc, ks, s1, s2, cb, sb


#: Below this value of ``|i omega - s1| max|t|`` the forced response is formed by
#: :func:`_forced_near`; above it the steady-state/transient split loses at most
#: about ``60 eps / 0.1`` relative (measured), below 1e-13.
NEAR = 0.1


def _forced_near(omega: float, g, s1: complex, s2: complex, t, cb, sb, sx: float, sv: float):
    """Forced response from rest near the singular case: ``sx Im E`` (m) and ``sv Re E`` (m/s).

    ``E = E[i omega, s1, s2](t) = (E[i omega, s1] - g) / (i omega - s2)`` with
    ``E[i omega, s1] = exp(i omega t) (1 - exp(-z)) / d``, ``d = i omega - s1``,
    ``z = d t``. ``1 - exp(-z) = A + iB`` is formed from ``expm1`` and half-angle
    sines, accurate relative to ``|z|`` however small, so dividing by a tiny
    ``d`` loses nothing; when ``|z| < 1e-8`` over the whole window the series
    ``t (1 - z/2)`` replaces the quotient (exact resonance, subnormal ``d``).
    For oscillating roots ``cos, sin(omega t)`` come from ``cb, sb = cos, sin(wd t)``
    by the angle-sum formulas. Real arithmetic, complex constants folded in.
    """
    alpha, beta = -s1.real, s1.imag  # decay rate (1/s) and frequency (rad/s) of the paired root
    d = complex(alpha, omega - beta)
    lam = 1.0 / (1j * omega - s2)
    lx, lv = sx * lam, sv * lam
    b = (omega - beta) * t  # detuning phase, rad
    sh, ch = np.sin(0.5 * b), np.cos(0.5 * b)
    cos_b, sin_b = 1.0 - 2.0 * sh * sh, 2.0 * sh * ch
    if cb is not None:  # omega t = wd t + b
        cw, sw = cb * cos_b - sb * sin_b, sb * cos_b + cb * sin_b  # cos, sin(omega t)
    else:  # real roots: beta = 0, so b = omega t
        cw, sw = cos_b, sin_b
    if abs(d) * float(np.max(np.abs(t), initial=0.0)) < 1e-8:
        pa, pb, mx, mv = t - 0.5 * d.real * t * t, -0.5 * d.imag * t * t, lx, lv
    else:
        em = np.expm1(-alpha * t)
        pa = 2.0 * sh * sh * (1.0 + em) - em
        pb = (1.0 + em) * sin_b
        mx, mv = lx / d, lv / d
    qre, qim = cw * pa - sw * pb, cw * pb + sw * pa  # exp(i omega t) (A + iB)
    return qre * mx.imag + qim * mx.real - g * lx.imag, qre * mv.real - qim * mv.imag - g * lv.real


def exact_response(osc: Oscillator, force: SineForce, t, x0: float = 0.0, v0: float = 0.0) -> Response:
    """Exact displacement and velocity at the times ``t``.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).
    force : SineForce
        F0 (N), omega (rad/s).
    t : array_like
        Times, s (any finite values, any order, 1-D or scalar).
    x0 : float
        Displacement at t = 0, m.
    v0 : float
        Velocity at t = 0, m/s.

    Returns
    -------
    Response
        ``t`` (s), ``x`` (m), ``v`` (m/s), ``method="exact"``, ``nfev=0``.

    Examples
    --------
    Undamped, at exact resonance, from rest:
    ``x = F0/(2 m wn^2) (sin wn t - wn t cos wn t)``, so ``x(pi) = -pi/4`` here.

    >>> import numpy as np
    >>> osc = Oscillator(1.0, 0.0, 4.0)
    >>> r = exact_response(osc, SineForce(1.0, 2.0), [0.0, np.pi])
    >>> np.round(r.x, 6)          # m
    array([ 0.      , -0.785398])
    >>> bool(abs(r.x[1] + np.pi / 4) < 1e-15)
    True
    """
    check_records(osc, force)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    tt = _times(t)
    flat = np.atleast_1d(tt)
    kc, g, s1, s2, cb, sb = _kernels(osc, flat)
    sigma, wn2, w = osc.decay_rate, osc.k / osc.m, force.omega
    x = v = 0.0
    if force.F0 != 0.0 and w != 0.0:
        if abs(1j * w - s2) < abs(1j * w - s1):
            s1, s2 = s2, s1  # pair i omega with the nearer root (real roots)
        if abs(1j * w - s1) * float(np.max(np.abs(flat), initial=0.0)) >= NEAR:
            # steady state Im(H exp(i w t)), H = F0 / (k - m w^2 + i c w); the transient
            # is the free response from the initial conditions it leaves over
            wn = math.sqrt(wn2)
            h = force.F0 / complex(osc.m * (wn - w) * (wn + w), osc.c * w)
            wt = w * flat
            sw, cw = np.sin(wt), np.cos(wt)
            x = h.real * sw + h.imag * cw
            v = (w * h.real) * cw - (w * h.imag) * sw
            x0, v0 = x0 - h.imag, v0 - w * h.real
        else:
            scale = force.F0 / osc.m
            x, v = _forced_near(w, g, s1, s2, flat, cb, sb, scale, scale * w)
    if x0 != 0.0 or v0 != 0.0 or np.isscalar(x):
        # free response: x = x0 g' + (v0 + 2 sigma x0) g, v = v0 g' - wn^2 x0 g, g' = kc - sigma g
        x = x + (x0 * kc + (v0 + sigma * x0) * g)
        v = v + (v0 * kc - (sigma * v0 + wn2 * x0) * g)
    shape = tt.shape
    return Response(t=tt, x=x.reshape(shape), v=v.reshape(shape), method="exact")
