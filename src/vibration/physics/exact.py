"""Closed-form response of the forced oscillator, exact in every regime.

Write the characteristic roots ``s1, s2`` of ``m s^2 + c s + k`` and let
``E[a, b, ...](t)`` be the divided difference of ``s -> exp(s t)`` over the
nodes. Then, from ``x(0) = x0``, ``v(0) = v0``,

* the impulse kernel is ``g(t) = E[s1, s2](t) = exp(-sigma t) S(t)``,
* the free response is ``x0 g'(t) + (v0 + 2 sigma x0) g(t)``, written
  ``x0 P + (v0 + a x0) g`` with ``P = g' + sigma g``, ``a = sigma`` for
  oscillating roots and ``P = exp(slow t)``, ``a = -slow`` for real roots, so
  that no term is much larger than x however large |zeta| (also for
  ``c < -2 sqrt(km)``, where the growing root dominates),
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

This form serves the samples with ``|i omega - s1| |t| < NEAR_SPLIT``. At
the later ones (``|i omega - s1| |t| >= NEAR_SPLIT``) the same response is
formed as steady state ``Im(H exp(i omega t))``, ``H = F0 / (k - m omega^2 +
i c omega)``, plus the free response from the initial conditions the steady
state leaves over: every term is then accurate relative to itself, which keeps
very slow forcing (omega << omega_n) accurate too. Before that time the split
would cancel: x is still much smaller than |H| (a window shorter than the
slow time scale, from rest, with a stiff or strongly damped oscillator).

Near ``t = 0`` (``R |t| <= SERIES_RHO``, R the largest rate) the forced part
from rest, ``x ~ F0 omega t^3 / 6m``, comes from the Taylor series of
``E[i omega, s1, s2]``, whose leading terms are exact: no cancellation
however short the time.

Cost per sample. On a uniform increasing grid (``numpy.linspace``, what every
chapter and slider uses) every exponential ``exp(s t)`` is a product
``exp(s a) exp(s d)`` of about sqrt(n) anchors and sqrt(n) offsets, each
computed directly (no recurrence, so no error growth). A compiled kernel
(numba, :mod:`._exact_kernels`) checks that the grid is uniform, evaluates the
2 sqrt(n) anchors and offsets, and forms x and v with a few multiply-adds per
sample: about 1.5 times the cost of one ``np.exp`` over the grid on the
development machine, Python's per-call overhead included (see ``make bench``).
On arbitrary times the pointwise path evaluates five transcendental functions
per sample (``exp``, ``cos``/``sin`` of ``wd t`` and of ``omega t``) for an
underdamped oscillator, three more near undamped resonance, four to six with
real roots.
"""

from __future__ import annotations

import functools
import math
import numbers
from dataclasses import dataclass

import numpy as np

from .model import Oscillator, ParameterError, SineForce, check_real, check_records


@dataclass(frozen=True, kw_only=True)
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

    def __repr__(self) -> str:
        t, x = np.atleast_1d(self.t), np.atleast_1d(self.x)
        span = f"{t.min():g}-{t.max():g} s" if t.size else "no times"
        peak = f"{float(np.max(np.abs(x))):.4g} m" if x.size else "-"
        return f"Response({self.method}, {t.size} samples over {span}, max |x| = {peak}, status {self.status})"

    def plot(self, ax=None):
        """Displacement (m) and velocity (m/s) against time (s) on two stacked axes; returns the axes.

        matplotlib is imported only here (``pip install 'vibration[book]'``).
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(2, 1, sharex=True, figsize=(6.0, 4.0), layout="constrained")
        top, bottom = ax
        top.plot(self.t, self.x)
        top.set_ylabel("$x$ (m)")
        bottom.plot(self.t, self.v)
        bottom.set_ylabel("$v$ (m/s)")
        bottom.set_xlabel("$t$ (s)")
        return ax


@dataclass(frozen=True, kw_only=True)
class SteadyState:
    """Steady-state (particular) response ``x_ss(t) = amplitude sin(omega t - phase)``."""

    amplitude: float  # displacement amplitude, m
    phase: float  # lag of x behind F, rad; in [0, pi] for c >= 0
    magnification: float  # amplitude / (F0 / k), dimensionless
    velocity_amplitude: float  # omega * amplitude, m/s
    static_deflection: float  # F0 / k, m

    def __repr__(self) -> str:
        return (
            f"SteadyState(amplitude={self.amplitude:.6g} m, phase={self.phase:.6g} rad, "
            f"magnification={self.magnification:.6g}, velocity_amplitude={self.velocity_amplitude:.6g} m/s, "
            f"static_deflection={self.static_deflection:.6g} m)"
        )


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
    >>> ss = steady_state(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0))
    >>> round(ss.amplitude, 4), round(ss.phase, 4)     # m, rad
    (0.4504, 0.1355)
    >>> round(ss.magnification, 4)
    1.8015

    Any harmonic load record of :mod:`vibration.forcing` too (unbalance, base motion, a phase): the phase is
    then the lag behind the load, the magnification the amplitude over the load's reference (``F/k``, or the
    support's amplitude for base motion).
    """
    if not isinstance(force, SineForce):
        from .checks import check_oscillator
        from .forcing import steady_load

        return steady_load(check_oscillator(osc), force)
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
    """``t`` as a float array (scalar or 1-D, non-empty, finite), else :class:`ParameterError`."""
    if t is None:
        raise ParameterError("t = None is not an array of numbers: allowed finite times in s")
    try:
        raw = np.asarray(t)
        kind = raw.dtype.kind
        if kind not in "iufO":
            raise TypeError
        if kind == "O" and not all(isinstance(v, numbers.Real) and not isinstance(v, bool) for v in raw.flat):
            raise TypeError
        arr = np.asarray(raw, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise ParameterError(f"t = {t!r} is not an array of numbers: allowed finite times in s") from None
    if arr.ndim > 1:
        raise ParameterError(f"t has shape {arr.shape}: allowed a scalar or a 1-D array of times in s")
    if arr.size == 0:
        raise ParameterError("t = [] is empty: allowed a scalar or a non-empty 1-D array of finite times in s")
    if not math.isfinite(arr.sum()) and not np.all(np.isfinite(arr)):  # the sum: one cheap pass
        bad = float(arr[~np.isfinite(arr)].ravel()[0])
        raise ParameterError(f"t contains {bad!r}: allowed finite times in s")
    return arr


@dataclass(frozen=True, kw_only=True)
class _Roots:
    """Characteristic roots of ``m s^2 + c s + k`` in the form each regime needs.

    ``kind`` is ``"osc"`` (``-sigma +/- i wd``), ``"critical"`` (double root
    ``-sigma``) or ``"real"`` (``slow``, ``fast``: the roots of smaller and
    larger modulus). With ``P, Q, g`` from :func:`_basis` the free response is
    ``x = x0 P + (v0 + a x0) g``, ``v = v0 Q - (a v0 + wn2 x0) g``.
    """

    kind: str
    sigma: float  # decay rate c / 2m, 1/s
    wn2: float  # k / m, 1/s^2
    wd: float = 0.0  # damped frequency, rad/s ("osc")
    slow: float = 0.0  # root of smaller modulus, 1/s ("real")
    fast: float = 0.0  # root of larger modulus, 1/s ("real")

    @property
    def a(self) -> float:
        """The free-response coefficient ``a`` (1/s): ``sigma``, or ``-slow`` with real roots."""
        return -self.slow if self.kind == "real" else self.sigma

    @property
    def pair(self) -> tuple[complex, complex]:
        """The two roots as complex numbers (upper half plane first)."""
        if self.kind == "osc":
            return complex(-self.sigma, self.wd), complex(-self.sigma, -self.wd)
        if self.kind == "critical":
            return complex(-self.sigma, 0.0), complex(-self.sigma, 0.0)
        return complex(self.slow, 0.0), complex(self.fast, 0.0)

    @property
    def radius(self) -> float:
        """Largest root modulus, 1/s."""
        if self.kind == "real":
            return abs(self.fast)
        return math.sqrt(self.wn2) if self.kind == "osc" else abs(self.sigma)


def _roots(osc: Oscillator) -> _Roots:
    sigma, wn2 = osc.decay_rate, osc.k / osc.m
    q = wn2 - sigma * sigma
    if q > 0.0:
        return _Roots(kind="osc", sigma=sigma, wn2=wn2, wd=math.sqrt(q))
    if q == 0.0:
        return _Roots(kind="critical", sigma=sigma, wn2=wn2)
    r = wn2 / sigma / sigma  # < 1; no overflow of sigma^2 at extreme scales
    mu = abs(sigma) * math.sqrt(1.0 - r) if math.isinf(q) else math.sqrt(-q)
    big = abs(sigma) + mu  # modulus of the fast root; the slow one is wn2 / big (no cancellation)
    if sigma > 0.0:
        return _Roots(kind="real", sigma=sigma, wn2=wn2, slow=-wn2 / big, fast=-big)
    return _Roots(kind="real", sigma=sigma, wn2=wn2, slow=wn2 / big, fast=big)


def _basis(ro: _Roots, t: np.ndarray) -> dict[str, np.ndarray]:
    """Exponential kernels at the times ``t`` (s).

    ``"osc"``: ``zr, zi = Re, Im exp((-sigma + i wd) t)``; ``"critical"``:
    ``e = exp(-sigma t)``, ``g = t e``; ``"real"``: ``es, ef = exp(slow t),
    exp(fast t)`` and ``g = (ef - es) / (fast - slow)``, formed with ``expm1``
    from the larger exponential so that it is accurate near critical damping.
    """
    if ro.kind == "osc":
        env = np.exp(-ro.sigma * t)
        wt = ro.wd * t
        return {"zr": env * np.cos(wt), "zi": env * np.sin(wt)}
    if ro.kind == "critical":
        e = np.exp(-ro.sigma * t)
        return {"e": e, "g": t * e}
    es, ef = np.exp(ro.slow * t), np.exp(ro.fast * t)
    span = ro.fast - ro.slow  # 1/s, nonzero
    hi, lo = (ef, es) if span > 0.0 else (es, ef)  # hi = exp(s_hi t): the larger one for t >= 0
    d = abs(span)
    if np.min(t) >= 0.0:
        g = hi * np.expm1(-d * t) / -d
    else:  # factor out whichever exponential is larger at each sample
        at = np.abs(t)
        g = np.sign(t) * np.where(t >= 0.0, hi, lo) * np.expm1(-d * at) / -d
    return {"es": es, "ef": ef, "g": g}


def _kernels(osc: Oscillator, t: np.ndarray):
    """Return ``(P, Q, g, a)``: the free response is ``x = x0 P + (v0 + a x0) g``, ``v = v0 Q - (a v0 + wn2 x0) g``.

    ``g(t) = E[s1, s2](t)`` is the unit impulse response times m (s). With
    oscillating roots or a double root ``P = Q = g' + sigma g`` (``exp(-sigma t)
    cos(wd t)`` when underdamped) and ``a = sigma``; with real roots ``P, Q =
    exp(slow t), exp(fast t)`` and ``a = -slow``, a form in which no term is
    much larger than the response however large |zeta| (``c < -2 sqrt(km)``
    included).
    """
    ro = _roots(osc)
    with np.errstate(all="ignore"):
        b = _basis(ro, np.asarray(t, dtype=float))
    if ro.kind == "osc":
        return b["zr"], b["zr"], b["zi"] / ro.wd, ro.a
    if ro.kind == "critical":
        return b["e"], b["e"], b["g"], ro.a
    return b["es"], b["ef"], b["g"], ro.a


#: Samples with ``|i omega - s1| |t| < NEAR_SPLIT`` take the forced response from the
#: near-resonance form; the later ones from the steady-state/transient split, which
#: before that time loses up to |H| / |x| relative to x (measured against 50 digits:
#: 1e4 eps for a window of 0.05 s of Oscillator(1, 200, 20) at 3 rad/s from rest,
#: 7 eps with the split).
NEAR_SPLIT = 1.0

#: Samples with ``R |t| <= SERIES_RHO`` (R: largest of omega and the root moduli,
#: 1/s) take the forced response from rest from its Taylor series, accurate
#: relative to itself however short the time (x ~ F0 omega t^3 / 6m).
SERIES_RHO = 1.0

#: Smallest number of samples for which a uniform grid takes the block path.
UNIFORM_MIN = 64


@functools.cache
def _compiled():
    """The compiled kernels (:mod:`vibration.physics._exact_kernels`); numba is imported on first use."""
    from . import _exact_kernels

    return _exact_kernels


def _uniform(t: np.ndarray) -> float | None:
    """The step h (s) if ``t`` is a uniform increasing grid from ``t[0] >= 0``, else None.

    Uniform means ``|t[n] - (t[0] + n h)| <= 4 eps t[-1]`` for every n, which
    ``numpy.linspace`` meets (it deviates by at most an ulp or two).
    """
    if t.ndim != 1 or t.size < UNIFORM_MIN:
        return None
    h = _compiled().uniform_step(t, _arange(t.size))
    return h if h > 0.0 else None


@functools.lru_cache(maxsize=8)
def _arange(n: int) -> np.ndarray:
    r = np.arange(n, dtype=float)
    r.flags.writeable = False
    return r


def _grid_exp(s, t: np.ndarray, step: float | None) -> np.ndarray:
    """``exp(s_i t_n)`` for complex rates ``s`` (1/s) and times ``t`` (s), shape ``(len(s), len(t))``.

    On a uniform grid (``step`` from :func:`_uniform`) each row is formed from
    about sqrt(n) anchors times sqrt(n) offsets, every factor computed directly
    (no recurrence, so no error growth); otherwise pointwise.
    """
    s = np.asarray(s, dtype=complex).reshape(-1)
    if step is None:
        return np.exp(np.multiply.outer(s, t))
    n = t.size
    B = math.isqrt(n - 1) + 1
    anchors = np.exp(np.multiply.outer(s, t[::B]))
    offsets = np.exp(np.multiply.outer(s, _arange(B) * step))
    return (anchors[:, :, None] * offsets[:, None, :]).reshape(s.size, -1)[:, :n]


def _forced_and_free(ro: _Roots, osc: Oscillator, force: SineForce, x0: float, v0: float, tmax: float):
    """The forms of the response, ``[(kind, consts, t_lo, t_hi), ...]``: each serves ``t_lo <= |t| < t_hi``.

    ``kind`` is ``"free"`` (no forcing), ``"near"`` (``|t| < NEAR_SPLIT / |i omega - s1|``)
    or ``"steady"`` (later); ``consts`` go to :func:`_pack` and :func:`_pointwise`;
    ``tmax`` is the largest |t| (s).
    """
    w, F0 = force.omega, force.F0
    if F0 == 0.0 or w == 0.0:
        return [("free", {"x0": x0, "v0": v0}, 0.0, math.inf)]
    s1, s2 = ro.pair
    if abs(1j * w - s2) < abs(1j * w - s1):
        s1, s2 = s2, s1  # pair i omega with the nearer root (real roots)
    dist = abs(1j * w - s1)  # 1/s
    split = NEAR_SPLIT / dist if dist > 0.0 else math.inf  # s (inf at exact resonance)
    scale = F0 / osc.m
    alpha, beta = -s1.real, s1.imag  # decay rate (1/s) and frequency (rad/s) of the paired root
    d = complex(alpha, w - beta)
    lam = 1.0 / (1j * w - s2)
    tiny = abs(d) * min(tmax, split) < 1e-8  # exact resonance or subnormal detuning: series of 1 - exp(-z)
    mu = lam if tiny else lam / d
    near = {
        "x0": x0,
        "v0": v0,
        "s1": s1,
        "d": d,
        "tiny": tiny,
        "mx": scale * mu,
        "mv": scale * w * mu,
        "gx": -scale * lam.imag,
        "gv": -scale * w * lam.real,
    }
    forms = [("near", near, 0.0, split)]
    if split <= tmax:
        # steady state Im(H exp(i w t)), H = F0 / (k - m w^2 + i c w); the transient
        # is the free response from the initial conditions it leaves over
        wn = math.sqrt(ro.wn2)
        h = F0 / complex(osc.m * (wn - w) * (wn + w), osc.c * w)
        forms.append(("steady", {"H": h, "x0": x0 - h.imag, "v0": v0 - w * h.real}, split, math.inf))
    return forms


def _qn(c: dict, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real and imaginary parts of ``1 - exp(-d t)`` (or ``t - d t^2/2`` when ``tiny``).

    Accurate relative to ``|d t|``: formed from ``expm1`` and half-angle sines,
    so that dividing by a tiny ``d`` loses nothing.
    """
    d = c["d"]
    if c["tiny"]:
        return t - 0.5 * d.real * t * t, -0.5 * d.imag * t * t
    b = d.imag * t  # detuning phase, rad
    sh = np.sin(0.5 * b)
    em = np.expm1(-d.real * t)
    return 2.0 * sh * sh * (1.0 + em) - em, (1.0 + em) * np.sin(b)


def _pointwise(ro: _Roots, w: float, kind: str, c: dict, t: np.ndarray) -> np.ndarray:
    """``x, v`` at arbitrary times ``t`` (s) as a (2, n) array, in real arithmetic.

    Five transcendental evaluations per sample when underdamped (``exp``,
    ``cos``/``sin`` of ``wd t`` and of ``omega t``), three more in the
    near-resonance form.
    """
    b = _basis(ro, t)
    if ro.kind == "osc":
        P = Q = b["zr"]
        g = b["zi"] / ro.wd
    elif ro.kind == "critical":
        P = Q = b["e"]
        g = b["g"]
    else:
        P, Q, g = b["es"], b["ef"], b["g"]
    x0, v0, a = c["x0"], c["v0"], ro.a
    out = np.empty((2, t.size))
    out[0] = x0 * P + (v0 + a * x0 + c.get("gx", 0.0)) * g
    out[1] = v0 * Q - (a * v0 + ro.wn2 * x0 - c.get("gv", 0.0)) * g
    if kind == "free":
        return out
    wt = w * t
    sw, cw = np.sin(wt), np.cos(wt)
    if kind == "steady":
        h = c["H"]
        out[0] += h.real * sw + h.imag * cw
        out[1] += (w * h.real) * cw - (w * h.imag) * sw
    else:
        qa, qb = _qn(c, t)
        qre, qim = cw * qa - sw * qb, cw * qb + sw * qa  # exp(i omega t) (1 - exp(-d t))
        mx, mv = c["mx"], c["mv"]
        out[0] += qre * mx.imag + qim * mx.real
        out[1] += qre * mv.real - qim * mv.imag
    return out


def exact_response(osc: Oscillator, force: SineForce, t, *, x0: float = 0.0, v0: float = 0.0) -> Response:
    """Exact displacement and velocity at the times ``t``.

    On a uniform increasing grid from ``t >= 0`` (``numpy.linspace``, detected
    to within 4 ulps) ``exp(i omega t)`` and the decaying kernels are formed as
    products of their values at about sqrt(n) exact anchors and sqrt(n) exact
    offsets (a compiled kernel), at rounding level; any other ``t`` is
    evaluated pointwise. The first samples (``R |t| <= SERIES_RHO``) take the
    forced part from its Taylor series, so that x stays accurate relative to
    itself however short the time.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, any sign), k (N/m).
    force : SineForce or a load record
        F0 (N), omega (rad/s); or any record of :mod:`vibration.forcing` (harmonic with a phase, rotating
        unbalance, base motion, step, sampled input), each in closed form.
    t : array_like
        Times, s (any finite values, any order, 1-D or scalar, not empty; a sampled input's response
        only within its span).
    x0 : float
        Displacement at t = 0, m.
    v0 : float
        Velocity at t = 0, m/s.

    Returns
    -------
    Response
        ``t`` (s), ``x`` (m), ``v`` (m/s), ``method="exact"``, ``nfev=0``.

    Raises
    ------
    ParameterError
        On a bad argument, or when x or v overflows the float range inside the
        window (the message gives the first such time).

    Examples
    --------
    Undamped, at exact resonance, from rest:
    ``x = F0/(2 m wn^2) (sin wn t - wn t cos wn t)``, so ``x(pi) = -pi/4`` here.

    >>> import numpy as np
    >>> osc = Oscillator(m=1.0, c=0.0, k=4.0)
    >>> r = exact_response(osc, SineForce(F0=1.0, omega=2.0), [0.0, np.pi])
    >>> np.round(r.x, 6)          # m
    array([ 0.      , -0.785398])
    >>> bool(abs(r.x[1] + np.pi / 4) < 1e-15)
    True
    """
    if not isinstance(force, SineForce):
        return _load_response(osc, force, t, x0, v0)
    check_records(osc, force)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    return _response(osc, force, _times(t), x0, v0)


def _load_response(osc: Oscillator, load, t, x0: float, v0: float) -> Response:
    """:func:`exact_response` of a load record other than :class:`SineForce` (:mod:`.forcing`)."""
    from .checks import check_oscillator
    from .forcing import check_load, exact_load_response

    check_oscillator(osc)
    check_load(load)
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    tt = _times(t)
    x, v = exact_load_response(osc, load, tt, x0=x0, v0=v0)
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        raise ParameterError("the response overflows the float range inside the window: allowed a shorter window")
    return Response(t=tt, x=np.asarray(x, dtype=float), v=np.asarray(v, dtype=float), method="exact")


# codes of the regimes in the compiled kernels' parameter vector
OSC, CRITICAL, REAL = 0, 1, 2  # roots: -sigma +/- i wd, double root -sigma, two real roots
FREE, STEADY, NEAR_FORM = 0, 1, 2  # forced part: none, steady state + transient, near-resonance form
_ROOT_CODES = {"osc": OSC, "critical": CRITICAL, "real": REAL}
_FORCED_CODES = {"free": FREE, "steady": STEADY, "near": NEAR_FORM}


def _pack(ro: _Roots, osc: Oscillator, force: SineForce, kind: str, c: dict, x0: float, v0: float) -> list:
    """The parameter vector of the compiled kernels in :mod:`._exact_kernels`.

    ``[roots code, forced code, sigma, wd, wn2, slow, fast, a, x0', v0', gx, gv, omega,
    Re H, Im H, Re s1, Im s1, Re d, Im d, tiny, Re mx, Im mx, Re mv, Im mv, F0/m,
    radius, x0, v0]``: ``x0', v0'`` and the rest are the constants of
    :func:`_forced_and_free` (0 where a form has none), ``x0, v0`` the initial
    state the series samples add their free response from.
    """
    get = c.get
    h, s1, d, mx, mv = get("H", 0j), get("s1", 0j), get("d", 0j), get("mx", 0j), get("mv", 0j)
    return [
        _ROOT_CODES[ro.kind], _FORCED_CODES[kind], ro.sigma, ro.wd, ro.wn2, ro.slow, ro.fast, ro.a,
        c["x0"], c["v0"], get("gx", 0.0), get("gv", 0.0), force.omega,
        h.real, h.imag, s1.real, s1.imag, d.real, d.imag, float(get("tiny", False)),
        mx.real, mx.imag, mv.real, mv.imag, force.F0 / osc.m, ro.radius, x0, v0,
    ]  # fmt: skip


def _response(osc: Oscillator, force: SineForce, tt: np.ndarray, x0: float, v0: float, blocks: bool = True):
    """:func:`exact_response` after validation; ``blocks=False`` forces the pointwise path."""
    flat = tt.reshape(-1)
    n = flat.size
    ro = _roots(osc)
    if blocks and n >= UNIFORM_MIN and 0.0 <= flat[0] < flat[-1]:
        # a uniform grid (the kernel checks, and returns 1 if it is not one): t[-1] is the largest |t|
        forms = _forced_and_free(ro, osc, force, x0, v0, float(flat[-1]))
        if forms[0][0] == "free" and x0 == 0.0 and v0 == 0.0:
            return Response(t=tt, x=np.zeros(tt.shape), v=np.zeros(tt.shape), method="exact")
        xv = np.empty((2, n))
        p = np.array([_pack(ro, osc, force, kind, consts, x0, v0) for kind, consts, _, _ in forms])
        bounds = np.array([(lo, hi) for _, _, lo, hi in forms])
        if _compiled().block(flat, _arange(n), p, bounds, xv[0], xv[1]) == 0:
            return Response(t=tt, x=xv[0], v=xv[1], method="exact")
        # 1: not a uniform grid; 2: a value beyond the float range, which the pointwise path judges
    forms = _forced_and_free(ro, osc, force, x0, v0, float(np.abs(flat).max()))
    if forms[0][0] == "free" and x0 == 0.0 and v0 == 0.0:
        return Response(t=tt, x=np.zeros(tt.shape), v=np.zeros(tt.shape), method="exact")
    xv = _pointwise_forms(ro, osc, force, forms, flat, x0, v0)
    ok = np.isfinite(xv)
    if not ok.all():
        bad = int(np.nonzero(~(ok[0] & ok[1]))[0][0])
        raise ParameterError(
            f"t = {float(flat[bad])!r} s gives a response beyond the float range (x = {float(xv[0, bad])!r} m, "
            f"v = {float(xv[1, bad])!r} m/s) for {osc}: allowed times at which |x| and |v| stay below "
            f"{np.finfo(float).max:.3g}"
        )
    return Response(t=tt, x=xv[0].reshape(tt.shape), v=xv[1].reshape(tt.shape), method="exact")


def _pointwise_forms(ro: _Roots, osc: Oscillator, force: SineForce, forms: list, t: np.ndarray, x0: float, v0: float):
    """``x, v`` at arbitrary times ``t`` as a (2, n) array: each form on its samples, then the series near 0."""
    w = force.omega
    at = np.abs(t)
    with np.errstate(all="ignore"):
        if len(forms) == 1:
            xv = _pointwise(ro, w, forms[0][0], forms[0][1], t)
        else:
            xv = np.empty((2, t.size))
            for kind, consts, lo, hi in forms:
                idx = np.flatnonzero((at >= lo) & (at < hi))
                if idx.size:
                    xv[:, idx] = _pointwise(ro, w, kind, consts, t[idx])
        if forms[0][0] != "free":
            # first samples: forced part from rest by its series, plus the free response
            idx = np.flatnonzero(at <= SERIES_RHO / max(w, ro.radius))
            if idx.size:
                ts = t[idx]
                kind, consts = forms[0][:2]
                xs = _compiled().series(np.array(_pack(ro, osc, force, kind, consts, x0, v0)), ts)
                if x0 != 0.0 or v0 != 0.0:
                    xs += _pointwise(ro, w, "free", {"x0": x0, "v0": v0}, ts)
                xv[:, idx] = xs
    return xv
