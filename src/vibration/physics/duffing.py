"""The Duffing oscillator: harmonic balance, sweeps, jumps and chaos (Part II).

The paper's oscillator with a cubic spring, forced by a cosine,

    m x'' + c x' + k x + k3 x^3 = F0 cos(omega t),

studied two independent ways.

*Harmonic balance (one harmonic).* With ``x = a cos(omega t) + b sin(omega t)`` and
``A^2 = a^2 + b^2`` the balance of the first harmonic gives the amplitude equation

    A^2 [(k - m omega^2 + (3/4) k3 A^2)^2 + (c omega)^2] = F0^2,

a cubic in ``A^2`` solved in closed form at each omega (:func:`hb_amplitudes`). Its fold
(saddle-node) points are the roots of a quintic (:func:`folds`), its backbone is
``omega^2 = k/m + (3/4)(k3/m) A^2`` (:func:`backbone`) and, parametrised by the amplitude,
the whole response curve is explicit (:func:`response_curve`): for each ``A`` the curve's
frequencies solve a quadratic in ``omega^2``. References: A. H. Nayfeh and D. T. Mook,
*Nonlinear Oscillations* (Wiley, 1979), section 4.1 (primary resonance of the Duffing
equation); I. Kovacic and M. J. Brennan (eds), *The Duffing Equation* (Wiley, 2011).

*Stability of the harmonic-balance branches* comes from the slow flow: letting ``a, b``
vary slowly (van der Pol / averaging) gives ``a' = Q/(2 m omega)``, ``b' = -P/(2 m omega)``
with ``P, Q`` the cosine and sine residuals. Its Jacobian has trace ``-c/m`` and
determinant ``p'(A^2) / (2 m omega)^2``, where ``p(z) = z[(k - m omega^2 + 3 k3 z/4)^2 +
(c omega)^2] - F0^2``; with ``c > 0`` a branch is stable exactly when ``p'(A^2) > 0`` (no Hopf
bifurcation is possible, the trace being negative). :func:`periodic_orbit` checks this
independently: it finds the periodic orbit of the full equation by Newton shooting and its
Floquet multipliers from the variational equations.

*Time integration.* :func:`sweep` and :func:`frequency_sweep` step the forcing frequency up
or down, start each step from the previous steady state and integrate whole forcing periods
(a compiled Dormand-Prince 5(4) pair with SciPy's RK45 error control) until the
stroboscopic state is steady. :func:`poincare_section`, :func:`lyapunov_qr` and
:func:`lyapunov_benettin` integrate with a compiled fixed-step RK4 for the chaotic regime.
"""

from __future__ import annotations

import functools
import math
import numbers
from dataclasses import dataclass

import numpy as np

from .model import N_POINTS_MAX, ParameterError, check_int, check_real

__all__ = [
    "Duffing",
    "Folds",
    "LyapunovResult",
    "PeriodicOrbit",
    "SweepResult",
    "backbone",
    "duffing_response",
    "folds",
    "frequency_sweep",
    "hb_amplitudes",
    "linear_trust_amplitude",
    "lyapunov_benettin",
    "locate_jump",
    "lyapunov_qr",
    "periodic_orbit",
    "poincare_section",
    "response_curve",
    "sweep",
]

#: Newton polishing steps applied to every closed-form root of the amplitude cubic.
NEWTON_STEPS = 3

#: Work budgets (each a few seconds at most): integrator steps of one :func:`frequency_sweep` (or of all
#: the sweeps of one :func:`locate_jump`) with the compiled integrator and with SciPy's; right-hand-side
#: evaluations of one :func:`duffing_response` or :func:`periodic_orbit`; fixed RK4 steps of one
#: :func:`poincare_section`, :func:`lyapunov_qr` or :func:`lyapunov_benettin`.
MAX_SWEEP_STEPS = 20_000_000
MAX_SCIPY_SWEEP_STEPS = 100_000
MAX_RHS_EVALUATIONS = 600_000
MAX_RK4_STEPS = 50_000_000

#: Largest ``h lambda`` of the fixed-step RK4 (its stability interval on the negative real axis is 2.785).
RK4_STABILITY = 2.78


# --------------------------------------------------------------------------------------- inputs


def _real_array(name: str, value, *, unit: str = "", min_size: int = 1, max_size: int = N_POINTS_MAX) -> np.ndarray:
    """``value`` as a finite float array, or :class:`ParameterError`.

    Refuses strings, bools, complex numbers, objects that are not real numbers, ragged
    sequences, non-finite values and sizes outside ``[min_size, max_size]``; the message names
    the parameter, its value and what is allowed.
    """
    allowed = f"an array of finite real numbers{f' ({unit})' if unit else ''}, {min_size} to {max_size} values"
    if isinstance(value, (str, bytes)):
        raise ParameterError(f"{name} = {value!r:.60} is a string: allowed {allowed}")
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} = {value!r:.60} is not an array of numbers: allowed {allowed}") from None
    if arr.dtype.kind == "O" and all(
        isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_)) for v in arr.reshape(-1)
    ):
        arr = arr.astype(float)
    if arr.dtype.kind not in "iuf":
        raise ParameterError(
            f"{name} = {value!r:.60} has values of type {arr.dtype} (not real numbers: bool, complex, string "
            f"or object): allowed {allowed}"
        )
    if not min_size <= arr.size <= max_size:
        raise ParameterError(f"{name} has {arr.size} values: allowed {allowed}")
    arr = arr.astype(float)
    bad = np.flatnonzero(~np.isfinite(arr))
    if bad.size:
        i = int(bad[0])
        raise ParameterError(f"{name}[{i}] = {arr.reshape(-1)[i]!r} is not finite: allowed {allowed}")
    return arr


class _OverBudget(Exception):
    """Raised inside a right-hand side when its evaluation budget is spent."""


class _Counted:
    """A right-hand side that counts its evaluations and stops the integrator past ``limit``."""

    def __init__(self, fun, limit: int) -> None:
        self.fun, self.limit, self.calls = fun, limit, 0

    def __call__(self, t, y):
        self.calls += 1
        if self.calls > self.limit:
            raise _OverBudget
        return self.fun(t, y)


def _linear_rate(d: Duffing, amplitude: float = 0.0) -> float:
    """Fastest rate of the linearised oscillator about ``|x| = amplitude``, 1/s (largest |eigenvalue|)."""
    k_eff = abs(d.k + 3.0 * d.k3 * amplitude * amplitude)
    sig = d.c / (2.0 * d.m)
    wn2 = k_eff / d.m
    if sig * sig > wn2:
        return sig + math.sqrt(sig * sig - wn2)
    return math.sqrt(wn2)


def _overflow_is_error(fun):
    """Turn a float overflow (``OverflowError``, ``ZeroDivisionError``) inside ``fun`` into :class:`ParameterError`."""

    @functools.wraps(fun)
    def wrapper(*args, **kwargs):
        try:
            return fun(*args, **kwargs)
        except (OverflowError, ZeroDivisionError) as exc:
            shown = ", ".join([repr(a) for a in args] + [f"{k}={v!r}" for k, v in kwargs.items()])
            raise ParameterError(
                f"{fun.__name__}({shown:.200}) overflows a float ({exc}): allowed parameters whose amplitudes, "
                "frequencies and their powers are finite floats"
            ) from None

    return wrapper


def _rates(d: Duffing) -> str:
    return f"c/m = {d.c / d.m:.3g} 1/s, sqrt(|k|/m) = {math.sqrt(d.k / d.m):.3g} rad/s"


# --------------------------------------------------------------------------------------- model


@dataclass(frozen=True)
class Duffing:
    """Duffing oscillator ``m x'' + c x' + k x + k3 x^3 = F(t)``.

    ``k3 > 0`` is a hardening spring, ``k3 < 0`` a softening one (its potential has a
    barrier at ``|x| = sqrt(-k/k3)``, beyond which the mass escapes), ``k3 = 0`` the linear
    oscillator. ``k = 0`` (a pure cubic spring, as in Ueda's oscillator) needs ``k3 > 0``.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> round(d.natural_frequency, 4), d.character          # rad/s
    (4.4721, 'hardening')
    >>> Duffing(1.0, 0.05, 0.0, 1.0).natural_frequency      # Ueda's oscillator
    0.0
    >>> Duffing(1.0, 0.5, 0.0, -1.0)
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: k3 = -1.0 N/m^3 is out of range: allowed k3 > 0 N/m^3, finite
    """

    m: float  # mass, kg; > 0
    c: float  # viscous damping coefficient, N s/m; >= 0
    k: float  # linear stiffness, N/m; >= 0
    k3: float  # cubic stiffness, N/m^3; finite (> 0 hardening, < 0 softening), > 0 when k = 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "m", check_real("m", self.m, low=0.0, low_open=True, unit="kg"))
        object.__setattr__(self, "c", check_real("c", self.c, low=0.0, unit="N s/m"))
        object.__setattr__(self, "k", check_real("k", self.k, low=0.0, unit="N/m"))
        if self.k == 0.0:
            object.__setattr__(self, "k3", check_real("k3", self.k3, low=0.0, low_open=True, unit="N/m^3"))
        else:
            object.__setattr__(self, "k3", check_real("k3", self.k3, unit="N/m^3"))

    @property
    def natural_frequency(self) -> float:
        """Small-amplitude natural frequency ``sqrt(k/m)``, rad/s."""
        return math.sqrt(self.k / self.m)

    @property
    def kappa(self) -> float:
        """Effective cubic coefficient of the first harmonic, ``(3/4) k3``, N/m^3."""
        return 0.75 * self.k3

    @property
    def character(self) -> str:
        """``"hardening"`` (k3 > 0), ``"softening"`` (k3 < 0) or ``"linear"`` (k3 = 0)."""
        return "hardening" if self.k3 > 0 else "softening" if self.k3 < 0 else "linear"

    @property
    def half_power_bandwidth(self) -> float:
        """Half-power bandwidth of the linear oscillator, ``c/m``, rad/s."""
        return self.c / self.m

    @property
    def barrier(self) -> float:
        """Displacement of the softening spring's potential barrier ``sqrt(-k/k3)``, m (inf otherwise)."""
        return math.sqrt(-self.k / self.k3) if self.k3 < 0 else math.inf


def _check_duffing(duffing) -> Duffing:
    if not isinstance(duffing, Duffing):
        raise ParameterError(f"duffing = {duffing!r} is not a Duffing: allowed Duffing(m, c, k, k3)")
    return duffing


def _check_damped(duffing: Duffing) -> None:
    if duffing.c <= 0.0:
        raise ParameterError(
            f"c = {duffing.c!r} N s/m is out of range: allowed c > 0 N s/m (a steady state needs damping)"
        )


def _x_ref(duffing: Duffing, F0: float) -> float:
    """A displacement scale, m: the static deflection under F0 (or 1 m when F0 = 0)."""
    if F0 == 0.0:
        return 1.0
    if duffing.k > 0.0:
        return F0 / duffing.k
    return (F0 / duffing.k3) ** (1.0 / 3.0)


# ------------------------------------------------------------------------- harmonic balance


def _cubic_real_roots(b: float, c1: float, d: float) -> list[float]:
    """Real roots of the monic cubic ``y^3 + b y^2 + c1 y + d``, closed form then Newton-polished."""
    p = c1 - b * b / 3.0
    q = 2.0 * b**3 / 27.0 - b * c1 / 3.0 + d
    disc = (q / 2.0) ** 2 + (p / 3.0) ** 3
    shift = -b / 3.0
    if disc < 0.0 and p < 0.0:  # three real roots (trigonometric form)
        r = 2.0 * math.sqrt(-p / 3.0)
        arg = max(-1.0, min(1.0, 3.0 * q / (p * r)))
        phi = math.acos(arg) / 3.0
        roots = [r * math.cos(phi - 2.0 * math.pi * j / 3.0) + shift for j in range(3)]
    else:  # one real root (Cardano, without cancellation)
        s = math.sqrt(max(disc, 0.0))
        u = -math.copysign(abs(q) / 2.0 + s, q)
        a_ = math.copysign(abs(u) ** (1.0 / 3.0), u)
        roots = [(a_ - p / (3.0 * a_) if a_ != 0.0 else 0.0) + shift]
    out = []
    for y in roots:
        for _ in range(NEWTON_STEPS):
            f = ((y + b) * y + c1) * y + d
            fp = (3.0 * y + 2.0 * b) * y + c1
            if fp == 0.0 or not math.isfinite(f):
                break
            step = f / fp
            if not math.isfinite(step):
                break
            y -= step
        out.append(y)
    return out


@_overflow_is_error
def hb_amplitudes(duffing: Duffing, F0: float, omega: float) -> list[tuple[float, bool]]:
    """Every one-harmonic steady amplitude at one forcing frequency, with its stability.

    Solves ``A^2 [(k - m omega^2 + (3/4) k3 A^2)^2 + (c omega)^2] = F0^2`` exactly: with
    ``y = (3/4) k3 A^2`` it is the monic cubic ``y^3 + 2 s y^2 + (s^2 + c^2 omega^2) y -
    (3/4) k3 F0^2 = 0``, ``s = k - m omega^2``, solved in closed form (trigonometric or
    Cardano) and polished by Newton's method; every real root with ``A^2 > 0`` is an
    amplitude. A root is stable when the slow-flow Jacobian (trace ``-c/m``) has a positive
    determinant, i.e. ``dp/dA^2 = (s + y)(s + 3 y) + (c omega)^2 > 0``; with ``c = 0`` that
    means a centre (neutrally stable). Roots too close to a fold to be told apart in floating
    point may be returned once.

    Parameters
    ----------
    duffing : Duffing
        The oscillator (kg, N s/m, N/m, N/m^3).
    F0 : float
        Force amplitude of ``F0 cos(omega t)``, N (>= 0).
    omega : float
        Forcing frequency, rad/s (> 0).

    Returns
    -------
    list of (float, bool)
        ``(A, stable)`` pairs in ascending ``A``, amplitudes in m. One pair outside the
        bistable band, three inside it (stable, unstable, stable). For a softening spring
        the largest roots may lie beyond the potential barrier, where one harmonic is no
        longer a faithful answer. Empty only for the undamped linear oscillator at resonance.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> [(round(a, 4), s) for a, s in hb_amplitudes(d, 5.0, 5.07)]       # m
    [(1.0411, True), (1.625, False), (1.9703, True)]
    >>> [(round(a, 4), s) for a, s in hb_amplitudes(Duffing(1.0, 0.5, 20.0, 0.0), 5.0, 3.0)]
    [(0.4504, True)]
    """
    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    omega = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    s = d.k - d.m * omega * omega
    cw2 = (d.c * omega) ** 2
    if F0 == 0.0:
        return [(0.0, d.c > 0.0 or s != 0.0)]
    kap = d.kappa
    if kap == 0.0:
        den = s * s + cw2
        return [(F0 / math.sqrt(den), True)] if den > 0.0 else []
    roots = _cubic_real_roots(2.0 * s, s * s + cw2, -kap * F0 * F0)
    pairs = []
    for y in roots:
        z = y / kap
        if not (z > 0.0 and math.isfinite(z)):
            continue
        stable = (s + y) * (s + 3.0 * y) + cw2 > 0.0
        pairs.append((math.sqrt(z), bool(stable)))
    if not pairs:  # the cubic always has a root z > 0 (p(0) = -F0^2 < 0): only an overflow loses it
        raise ParameterError(
            f"F0 = {F0!r} N with k3 = {d.k3!r} N/m^3 and omega = {omega!r} rad/s overflows the amplitude cubic "
            "((3/4) k3 F0^2 or (k - m omega^2)^2 is not a finite float): allowed smaller F0, |k3| or omega"
        )
    pairs.sort()
    unique: list[tuple[float, bool]] = []
    for a, st in pairs:  # a double root split by rounding, polished onto the same value
        if unique and abs(a - unique[-1][0]) <= 1e-12 * a:
            continue
        unique.append((a, st))
    return unique


@_overflow_is_error
def backbone(duffing: Duffing, amplitude):
    """Backbone (free-vibration frequency of one harmonic) ``sqrt(k/m + (3/4)(k3/m) A^2)``, rad/s.

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    amplitude : float or array_like
        Amplitude ``A``, m (>= 0).

    Returns
    -------
    float or numpy.ndarray
        Frequency, rad/s; ``nan`` where ``omega^2 < 0`` (a softening spring past its barrier).

    Examples
    --------
    >>> round(float(backbone(Duffing(1.0, 0.5, 20.0, 2.0), 2.0)), 4)     # rad/s
    5.099
    """
    d = _check_duffing(duffing)
    a = _real_array("amplitude", amplitude, unit="m")
    if np.any(a < 0):
        raise ParameterError(f"amplitude = {amplitude!r:.60} is out of range: allowed amplitude >= 0 m, finite")
    with np.errstate(over="ignore"):
        w2 = (d.k + d.kappa * a * a) / d.m
    if not np.all(np.isfinite(w2)):
        raise ParameterError(
            f"amplitude = {amplitude!r:.60} overflows (3/4) k3 A^2 with k3 = {d.k3!r} N/m^3: allowed amplitudes "
            "whose backbone frequency is a finite float"
        )
    with np.errstate(invalid="ignore"):
        out = np.where(w2 >= 0, np.sqrt(np.maximum(w2, 0.0)), np.nan)
    return float(out) if out.ndim == 0 else out


@_overflow_is_error
def linear_trust_amplitude(duffing: Duffing) -> float:
    """Amplitude at which the backbone has moved one half-power bandwidth ``c/m`` from ``omega_n``, m.

    Below it the linear answer's resonance peak sits within its own half-power band of the
    nonlinear one; above it the linear frequency response is no longer trustworthy. Solves
    ``|backbone(A) - omega_n| = c/m``; ``inf`` when ``k3 = 0``, ``nan`` when the softening
    backbone reaches zero frequency first.

    Parameters
    ----------
    duffing : Duffing
        The oscillator (needs k > 0).

    Returns
    -------
    float
        Amplitude, m.

    Examples
    --------
    >>> round(linear_trust_amplitude(Duffing(1.0, 0.5, 20.0, 2.0)), 4)    # m
    1.7743
    """
    d = _check_duffing(duffing)
    if d.k == 0.0:
        raise ParameterError(f"k = {d.k!r} N/m is out of range: allowed k > 0 N/m (a linear answer needs one)")
    if d.k3 == 0.0:
        return math.inf
    wn, bw = d.natural_frequency, d.half_power_bandwidth
    target = wn + bw if d.k3 > 0 else wn - bw
    if target < 0.0:
        return math.nan
    z = d.m * (target * target - wn * wn) / d.kappa
    return math.sqrt(z)


@dataclass(frozen=True)
class Folds:
    """Fold (saddle-node) points and peak of the one-harmonic response curve.

    ``omega_low < omega_high`` bound the band where three amplitudes coexist (``nan`` when
    the response is single-valued at every frequency). A softening spring forced so hard that
    its curve never closes (it runs to ``omega -> 0`` beyond the potential barrier) has only
    ``omega_high``; ``omega_low`` and the peak are then ``nan``. For a hardening spring a sweep up
    jumps down at ``omega_high`` and a sweep down jumps up at ``omega_low``; for a softening
    one a sweep up jumps up at ``omega_high`` and a sweep down jumps down at ``omega_low``.
    """

    omega_low: float  # lower fold frequency, rad/s
    omega_high: float  # upper fold frequency, rad/s
    amplitude_low: float  # amplitude of the double root at omega_low, m
    amplitude_high: float  # amplitude of the double root at omega_high, m
    peak_amplitude: float  # largest amplitude of the response curve, m
    peak_omega: float  # frequency of the peak, rad/s

    @property
    def bistable(self) -> bool:
        """Whether two stable amplitudes coexist somewhere (the folds exist)."""
        return math.isfinite(self.omega_low) and math.isfinite(self.omega_high)


def _peak(d: Duffing, F0: float) -> tuple[float, float]:
    """Largest amplitude of the response curve and its frequency (where its two branches meet)."""
    m, c, k, kap = d.m, d.c, d.k, d.kappa
    # dA/domega = 0  <=>  k - m w^2 + kap z = c^2/(2m); with p = 0:
    # (c^2 kap/m) z^2 + (c^2 k/m - c^4/(4 m^2)) z - F0^2 = 0
    qa, qb, qc = c * c * kap / m, c * c * k / m - c**4 / (4 * m * m), -F0 * F0
    if qa == 0.0:
        zs = [-qc / qb] if qb > 0 else []
    else:
        disc = qb * qb - 4 * qa * qc
        if disc < 0:
            zs = []
        else:
            sq = math.sqrt(disc)
            r1 = (-qb - math.copysign(sq, qb)) / (2 * qa) if qb != 0 else sq / (2 * abs(qa))
            r2 = qc / (qa * r1) if r1 != 0 else math.nan
            zs = sorted(z for z in (r1, r2) if z > 0 and math.isfinite(z))
    for z in zs:
        w2 = (k + kap * z - c * c / (2 * m)) / m
        if w2 > 0:
            return math.sqrt(z), math.sqrt(w2)
    if zs or d.k3 >= 0:  # peak at omega -> 0: the static deflection k A + k3 A^3 = F0
        ys = [y for y in _cubic_real_roots(2 * k, k * k, -kap * F0 * F0) if kap != 0 and y / kap > 0]
        if kap == 0:
            return F0 / k, 0.0
        if ys:
            return math.sqrt(min(ys) / kap), 0.0
    return math.nan, math.nan


@_overflow_is_error
def folds(duffing: Duffing, F0: float) -> Folds:
    """Fold frequencies, their amplitudes and the peak of the one-harmonic response curve.

    At a fold the amplitude cubic has a double root, ``p = dp/dA^2 = 0``; eliminating
    omega leaves, for ``y = (3/4) k3 A^2``, the quintic

        4 c^2 y^5 + 4 c^2 k y^4 - 4 m (3/4) k3 F0^2 y^3 + 2 c^2 (3/4) k3 F0^2 y^2 + m ((3/4) k3)^2 F0^4 = 0,

    whose admissible roots (``A^2 > 0``, ``omega^2 = (k + y + (3/4) k3 F0^2 / (2 y^2)) / m > 0``)
    are the folds (eigenvalues of the companion matrix, Newton-polished). The peak is where
    the curve's two branches meet, ``dA/domega = 0``: ``k - m omega^2 + (3/4) k3 A^2 =
    c^2/(2m)``, a quadratic in ``A^2``; to leading order in the damping it lies on the
    backbone with ``A = F0 / (c omega)``.

    Parameters
    ----------
    duffing : Duffing
        The oscillator, with c > 0.
    F0 : float
        Force amplitude, N (> 0).

    Returns
    -------
    Folds
        ``omega_low``, ``omega_high`` (rad/s), ``amplitude_low``, ``amplitude_high`` (m),
        ``peak_amplitude`` (m), ``peak_omega`` (rad/s); fold fields are ``nan`` when the
        response is single-valued, peak fields ``nan`` when a softening curve never closes.

    Examples
    --------
    >>> f = folds(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0), 5.0)
    >>> round(f.omega_low, 4), round(f.omega_high, 4), round(f.peak_amplitude, 4)   # rad/s, rad/s, m
    (5.0437, 5.1045, 1.9703)
    """
    d = _check_duffing(duffing)
    _check_damped(d)
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    m, c, k, kap = d.m, d.c, d.k, d.kappa
    a_peak, w_peak = _peak(d, F0)
    nan = math.nan
    if kap == 0.0:
        return Folds(nan, nan, nan, nan, a_peak, w_peak)
    g = kap * F0 * F0
    # scale y by y0 so that the coefficients are O(1)
    y0 = abs(g) ** (1.0 / 3.0)
    coeffs = np.array(
        [4 * c * c * y0**5, 4 * c * c * k * y0**4, -4 * m * g * y0**3, 2 * c * c * g * y0**2, 0.0, m * g * g]
    )
    if not (np.all(np.isfinite(coeffs)) and math.isfinite(g * g) and np.max(np.abs(coeffs)) > 0):
        raise ParameterError(
            f"F0 = {F0!r} N with k3 = {d.k3!r} N/m^3, c = {c!r} N s/m overflows the fold quintic (its "
            "coefficients are not finite floats): allowed smaller F0 or |k3|"
        )
    coeffs = coeffs / np.max(np.abs(coeffs))
    found = []
    for r in np.roots(coeffs):
        if abs(r.imag) > 1e-6 * max(1.0, abs(r)):
            continue
        y = float(r.real) * y0
        for _ in range(8):  # Newton on the unscaled quintic
            f = (((4 * c * c * y + 4 * c * c * k) * y - 4 * m * g) * y + 2 * c * c * g) * y * y + m * g * g
            fp = (((20 * c * c * y + 16 * c * c * k) * y - 12 * m * g) * y + 4 * c * c * g) * y
            if fp == 0 or not math.isfinite(fp):
                break
            y -= f / fp
        z = y / kap
        w2 = (k + y + g / (2 * y * y)) / m if y != 0 else -1.0
        if z > 0 and w2 > 0 and math.isfinite(w2):
            found.append((math.sqrt(w2), math.sqrt(z)))
    if math.isfinite(a_peak):  # folds of the resonance curve, not of a softening curve's outer branch
        found = [(w, a) for w, a in found if a <= a_peak * (1 + 1e-9)]
    found.sort()
    if len(found) == 1 and kap < 0:  # an open softening curve: only the sweep-up jump exists
        (wh, ah) = found[0]
        return Folds(nan, wh, nan, ah, a_peak, w_peak)
    if len(found) < 2:
        return Folds(nan, nan, nan, nan, a_peak, w_peak)
    (wl, al), (wh, ah) = found[0], found[-1]
    return Folds(wl, wh, al, ah, a_peak, w_peak)


@_overflow_is_error
def response_curve(duffing: Duffing, F0: float, omega_max: float, n: int = 801, amplitude_max: float | None = None):
    """The whole one-harmonic response curve, parametrised by the amplitude.

    For each ``A`` the frequencies of the curve solve ``m^2 W^2 - (2 m (k + (3/4) k3 A^2) -
    c^2) W + (k + (3/4) k3 A^2)^2 - F0^2/A^2 = 0`` with ``W = omega^2``, so the curve,
    including its unstable middle branch and its folds, is drawn without root tracking.
    The points run along the curve: the low-frequency branch with ``A`` rising to the peak,
    then the high-frequency branch with ``A`` falling.

    Parameters
    ----------
    duffing : Duffing
        The oscillator (c > 0).
    F0 : float
        Force amplitude, N (> 0).
    omega_max : float
        Highest frequency kept, rad/s (> 0); the lowest amplitude sampled is the one there.
    n : int
        Amplitudes per branch (10 to 100000).
    amplitude_max : float, optional
        Largest amplitude sampled, m, when the curve does not close (softening spring
        forced beyond its barrier); default 1.5 times the barrier.

    Returns
    -------
    tuple of numpy.ndarray
        ``(omega, A, stable)``: rad/s, m and the slow-flow stability of each point, in
        order along the curve (points with ``omega^2 <= 0`` or above ``omega_max`` dropped).

    Examples
    --------
    >>> w, a, st = response_curve(Duffing(1.0, 0.5, 20.0, 2.0), 5.0, 8.0)
    >>> round(float(a.max()), 3), bool(st.all())     # m
    (1.97, False)
    """
    d = _check_duffing(duffing)
    _check_damped(d)
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    omega_max = check_real("omega_max", omega_max, low=0.0, low_open=True, unit="rad/s")
    n = check_int("n", n, low=10, high=100_000)
    if amplitude_max is not None:
        amplitude_max = check_real("amplitude_max", amplitude_max, low=0.0, low_open=True, unit="m")
    m, c, k, kap = d.m, d.c, d.k, d.kappa
    a_peak, w_peak = _peak(d, F0)
    if math.isfinite(a_peak) and w_peak > 0:
        a_top = a_peak
    else:
        a_top = amplitude_max
        a_top = a_top or 1.5 * (d.barrier if math.isfinite(d.barrier) else max(hb_amplitudes(d, F0, omega_max))[0])
    a_low = min(hb_amplitudes(d, F0, omega_max))[0]
    a_low = min(a_low, 0.999 * a_top)
    # denser near the peak, where the two branches turn: cosine spacing in A
    s = 0.5 * (1 - np.cos(np.linspace(0.0, np.pi, n)))
    with np.errstate(all="ignore"):
        omega, A, stable = _curve_points(m, c, k, kap, F0, omega_max, a_low + (a_top - a_low) * s)
    if not (np.all(np.isfinite(omega)) and np.all(np.isfinite(A))):
        raise ParameterError(
            f"F0 = {F0!r} N with k3 = {d.k3!r} N/m^3 overflows the response curve (A up to {a_top:.3g} m): "
            "allowed smaller F0 or |k3|"
        )
    return omega, A, stable


def _curve_points(m, c, k, kap, F0, omega_max, a):
    """Points ``(omega, A, stable)`` of the response curve at the amplitudes ``a``, in order along it."""
    z = a * a
    kz = k + kap * z
    B = 2 * m * kz - c * c
    D = c**4 - 4 * m * c * c * kz + 4 * m * m * F0 * F0 / z
    sq = np.sqrt(np.maximum(D, 0.0))
    w_lo2, w_hi2 = (B - sq) / (2 * m * m), (B + sq) / (2 * m * m)
    W = np.concatenate([w_lo2, w_hi2[::-1]])
    A = np.concatenate([a, a[::-1]])
    keep = (W > 0) & (np.concatenate([D, D[::-1]]) >= 0)
    W, A = W[keep], A[keep]
    omega = np.sqrt(W)
    keep = omega <= omega_max
    omega, A, W = omega[keep], A[keep], W[keep]
    sig = k - m * W
    y = kap * A * A
    stable = (sig + y) * (sig + 3 * y) + c * c * W > 0
    return omega, A, stable


# ----------------------------------------------------------------------------- compiled kernels


@functools.cache
def _kernels():
    """Compile (once per process, cached on disk) the integrators; numba is imported lazily."""
    import numba

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
                a0 = (F0 * np.cos(w * tau) - c * v - k * x - k3 * x * x * x) / m
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
                    # stages (FSAL: k1 = (v, a0))
                    k1x, k1v = v, a0
                    xx, vv = x + h * a21 * k1x, v + h * a21 * k1v
                    k2x, k2v = vv, (F0 * np.cos(w * (tau + c2 * h)) - c * vv - k * xx - k3 * xx * xx * xx) / m
                    xx = x + h * (a31 * k1x + a32 * k2x)
                    vv = v + h * (a31 * k1v + a32 * k2v)
                    k3x, k3v = vv, (F0 * np.cos(w * (tau + c3 * h)) - c * vv - k * xx - k3 * xx * xx * xx) / m
                    xx = x + h * (a41 * k1x + a42 * k2x + a43 * k3x)
                    vv = v + h * (a41 * k1v + a42 * k2v + a43 * k3v)
                    k4x, k4v = vv, (F0 * np.cos(w * (tau + c4 * h)) - c * vv - k * xx - k3 * xx * xx * xx) / m
                    xx = x + h * (a51 * k1x + a52 * k2x + a53 * k3x + a54 * k4x)
                    vv = v + h * (a51 * k1v + a52 * k2v + a53 * k3v + a54 * k4v)
                    k5x, k5v = vv, (F0 * np.cos(w * (tau + c5 * h)) - c * vv - k * xx - k3 * xx * xx * xx) / m
                    xx = x + h * (a61 * k1x + a62 * k2x + a63 * k3x + a64 * k4x + a65 * k5x)
                    vv = v + h * (a61 * k1v + a62 * k2v + a63 * k3v + a64 * k4v + a65 * k5v)
                    k6x, k6v = vv, (F0 * np.cos(w * (tau + h)) - c * vv - k * xx - k3 * xx * xx * xx) / m
                    xn = x + h * (b1 * k1x + b3 * k3x + b4 * k4x + b5 * k5x + b6 * k6x)
                    vn = v + h * (b1 * k1v + b3 * k3v + b4 * k4v + b5 * k5v + b6 * k6v)
                    t_new = T if last else tau + h
                    an = (F0 * np.cos(w * t_new) - c * vn - k * xn - k3 * xn * xn * xn) / m
                    ex = h * (e1 * k1x + e3 * k3x + e4 * k4x + e5 * k5x + e6 * k6x + e7 * vn)
                    ev = h * (e1 * k1v + e3 * k3v + e4 * k4v + e5 * k5v + e6 * k6v + e7 * an)
                    sx = atol + rtol * max(abs(x), abs(xn))
                    sv = atol + rtol * max(abs(v), abs(vn))
                    err = np.sqrt(0.5 * ((ex / sx) ** 2 + (ev / sv) ** 2))
                    if not np.isfinite(err):
                        escaped = True
                        break
                    if err < 1.0:
                        steps += 1
                        # extremum of x inside the step: quintic Hermite, bisection on its derivative
                        if (v > 0.0) != (vn > 0.0):
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
                            xe = (
                                x * (1 - 10 * s**3 + 15 * s**4 - 6 * s**5)
                                + h * v * (s - 6 * s**3 + 8 * s**4 - 3 * s**5)
                                + h * h * a0 * (s**2 - 3 * s**3 + 3 * s**4 - s**5) / 2
                                + xn * (10 * s**3 - 15 * s**4 + 6 * s**5)
                                + h * vn * (-4 * s**3 + 7 * s**4 - 3 * s**5)
                                + h * h * an * (s**3 - 2 * s**4 + s**5) / 2
                            )
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
                scale = max(0.5 * (xmax - xmin), atol)
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

    @numba.njit(cache=True)
    def rk4_kernel(
        m, c, k, k3, F0, w, x0, v0, n_periods, steps_per_period, mode, d0, record, gs_every, blow_up
    ):  # pragma: no cover
        """mode 0: Poincare points; 1: QR on the variational equations; 2: two-trajectory renormalisation.

        The tangent vectors (mode 1) or the separation (mode 2) are renormalised at the end of
        every period and, when the damping contracts them strongly, also every ``gs_every`` steps.
        Returns (points (n_periods, 2), running largest exponent per period, tail): tail holds the
        sums of logs (2), the final state and tangent vectors (6), a status (0 done, 1 the state
        left ``|x| <= blow_up`` or stopped being finite, 2 a tangent vector or the separation
        underflowed to 0 or overflowed) and the period at which it stopped.
        """
        T = 2.0 * np.pi / w
        h = T / steps_per_period
        x, v = x0, v0
        # tangent vectors (mode 1) or the partner trajectory (mode 2)
        q11, q21, q12, q22 = 1.0, 0.0, 0.0, 1.0
        px, pv = x0 + d0, v0
        pts = np.empty((n_periods, 2))
        running = np.empty(n_periods)
        s1, s2 = 0.0, 0.0
        for n in range(n_periods):
            for i in range(steps_per_period):
                tau = i * h
                f0 = F0 * np.cos(w * tau)
                fh = F0 * np.cos(w * (tau + 0.5 * h))
                f1 = F0 * np.cos(w * (tau + h))
                # main trajectory with (optionally) the two tangent vectors
                j1 = -(k + 3.0 * k3 * x * x) / m
                k1x, k1v = v, (f0 - c * v - k * x - k3 * x**3) / m
                l1a, l1b = q21, j1 * q11 - c / m * q21
                l1c, l1d = q22, j1 * q12 - c / m * q22
                xa, va = x + 0.5 * h * k1x, v + 0.5 * h * k1v
                ja = -(k + 3.0 * k3 * xa * xa) / m
                qa11, qa21 = q11 + 0.5 * h * l1a, q21 + 0.5 * h * l1b
                qa12, qa22 = q12 + 0.5 * h * l1c, q22 + 0.5 * h * l1d
                k2x, k2v = va, (fh - c * va - k * xa - k3 * xa**3) / m
                l2a, l2b = qa21, ja * qa11 - c / m * qa21
                l2c, l2d = qa22, ja * qa12 - c / m * qa22
                xb, vb = x + 0.5 * h * k2x, v + 0.5 * h * k2v
                jb = -(k + 3.0 * k3 * xb * xb) / m
                qb11, qb21 = q11 + 0.5 * h * l2a, q21 + 0.5 * h * l2b
                qb12, qb22 = q12 + 0.5 * h * l2c, q22 + 0.5 * h * l2d
                k3x, k3v = vb, (fh - c * vb - k * xb - k3 * xb**3) / m
                l3a, l3b = qb21, jb * qb11 - c / m * qb21
                l3c, l3d = qb22, jb * qb12 - c / m * qb22
                xc, vc = x + h * k3x, v + h * k3v
                jc = -(k + 3.0 * k3 * xc * xc) / m
                qc11, qc21 = q11 + h * l3a, q21 + h * l3b
                qc12, qc22 = q12 + h * l3c, q22 + h * l3d
                k4x, k4v = vc, (f1 - c * vc - k * xc - k3 * xc**3) / m
                l4a, l4b = qc21, jc * qc11 - c / m * qc21
                l4c, l4d = qc22, jc * qc12 - c / m * qc22
                x += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x)
                v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
                if mode == 1:
                    q11 += h / 6.0 * (l1a + 2 * l2a + 2 * l3a + l4a)
                    q21 += h / 6.0 * (l1b + 2 * l2b + 2 * l3b + l4b)
                    q12 += h / 6.0 * (l1c + 2 * l2c + 2 * l3c + l4c)
                    q22 += h / 6.0 * (l1d + 2 * l2d + 2 * l3d + l4d)
                if mode == 2:  # partner trajectory, the same RK4 steps
                    m1x, m1v = pv, (f0 - c * pv - k * px - k3 * px**3) / m
                    ya, wa = px + 0.5 * h * m1x, pv + 0.5 * h * m1v
                    m2x, m2v = wa, (fh - c * wa - k * ya - k3 * ya**3) / m
                    yb, wb = px + 0.5 * h * m2x, pv + 0.5 * h * m2v
                    m3x, m3v = wb, (fh - c * wb - k * yb - k3 * yb**3) / m
                    yc, wc = px + h * m3x, pv + h * m3v
                    m4x, m4v = wc, (f1 - c * wc - k * yc - k3 * yc**3) / m
                    px += h / 6.0 * (m1x + 2 * m2x + 2 * m3x + m4x)
                    pv += h / 6.0 * (m1v + 2 * m2v + 2 * m3v + m4v)
                renorm = i == steps_per_period - 1 or (i + 1) % gs_every == 0
                if mode == 1 and renorm:  # Gram-Schmidt (QR) once per period (or every gs_every steps)
                    r11 = np.sqrt(q11 * q11 + q21 * q21)
                    if not (r11 > 0.0 and r11 < np.inf):
                        return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 2.0, n])
                    q11, q21 = q11 / r11, q21 / r11
                    dot = q11 * q12 + q21 * q22
                    q12, q22 = q12 - dot * q11, q22 - dot * q21
                    r22 = np.sqrt(q12 * q12 + q22 * q22)
                    if not (r22 > 0.0 and r22 < np.inf):
                        return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 2.0, n])
                    q12, q22 = q12 / r22, q22 / r22
                    if record:
                        s1 += np.log(r11)
                        s2 += np.log(r22)
                if mode == 2 and renorm:  # renormalise the separation to d0 along its current direction
                    dx, dv = px - x, pv - v
                    dist = np.sqrt(dx * dx + dv * dv)
                    if not (dist > 0.0 and dist < np.inf):
                        return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 2.0, n])
                    if record:
                        s1 += np.log(dist / d0)
                    px, pv = x + dx * d0 / dist, v + dv * d0 / dist
            if not (abs(x) <= blow_up and abs(v) < np.inf):
                return pts[:n], running[:n], np.array([s1, s2, x, v, q11, q21, q12, q22, 1.0, n])
            pts[n, 0] = x
            pts[n, 1] = v
            running[n] = s1 / ((n + 1) * T)
        return pts, running, np.array([s1, s2, x, v, q11, q21, q12, q22, 0.0, n_periods])

    return sweep_kernel, rk4_kernel


# ------------------------------------------------------------------------------- frequency sweeps


@dataclass(frozen=True)
class SweepResult:
    """Steady responses of a stepped frequency sweep, aligned with the frequencies given."""

    omega: np.ndarray  # forcing frequencies, rad/s (in the order given)
    amplitude: np.ndarray  # half the peak-to-peak x over the last period, m (nan if the mass escaped)
    x_max: np.ndarray  # largest x over the last period, m
    x_min: np.ndarray  # smallest x over the last period, m
    steady: np.ndarray  # whether the steady criterion was met before max_periods
    periods: np.ndarray  # forcing periods integrated at each frequency
    x_end: np.ndarray  # stroboscopic state at the end (phase 0 of the forcing), m
    v_end: np.ndarray  # ..., m/s
    direction: str  # "up" or "down"
    n_steps: np.ndarray  # accepted integrator steps at each frequency

    def jumps(self, threshold: float = 0.25) -> list[tuple[float, float, float, float]]:
        """Jumps between consecutive steps of the sweep (in sweep order).

        A jump is a change of amplitude larger than ``threshold`` times the larger of the
        two. Returns ``(omega_before, omega_after, A_before, A_after)`` tuples, rad/s and m.
        """
        order = np.argsort(self.omega, kind="stable")
        if self.direction == "down":
            order = order[::-1]
        out = []
        for i, j in zip(order[:-1], order[1:], strict=True):
            a, b = self.amplitude[i], self.amplitude[j]
            if np.isfinite(a) and np.isfinite(b) and abs(b - a) > threshold * max(a, b):
                out.append((float(self.omega[i]), float(self.omega[j]), float(a), float(b)))
        return out

    @property
    def escaped(self) -> np.ndarray:
        """Whether the mass escaped (softening spring past its barrier) at each frequency: amplitude ``nan`` there."""
        return ~np.isfinite(self.amplitude)


def _check_omegas(omegas) -> np.ndarray:
    w = _real_array("omegas", omegas, unit="rad/s", max_size=1_000_000).reshape(-1)
    if np.any(w <= 0):
        raise ParameterError(
            f"omegas = {omegas!r:.60} is out of range: allowed non-empty, every omega > 0 rad/s, finite"
        )
    return w


def _sweep_work(d: Duffing, F0: float, ws: np.ndarray, x0: float, min_periods: int, max_steps: int, name: str) -> None:
    """Refuse up front a sweep whose first ``min_periods`` periods alone need more than ``max_steps`` steps.

    An explicit Runge-Kutta pair needs ``h lambda`` within its stability interval (about 3.3
    for Dormand-Prince 5(4)), ``lambda`` the fastest rate of the linearised oscillator, and at
    least 16 steps per period (its largest step).
    """
    lam = _linear_rate(d, max(abs(x0), _x_ref(d, F0) if F0 > 0 else 0.0))
    periods = 2.0 * np.pi / ws
    with np.errstate(over="ignore"):
        need = float(np.sum(min_periods * np.maximum(16.0, periods * lam / 3.3)))
    if not need <= max_steps:
        w_min = float(np.min(ws))
        raise ParameterError(
            f"{name} needs at least {need:.3g} integrator steps ({min_periods} forcing periods at each of "
            f"{ws.size} frequencies, the lowest omega = {w_min:.3g} rad/s with period {2 * np.pi / w_min:.3g} s, "
            f"step <= 3.3/lambda for the fastest rate lambda = {lam:.3g} 1/s: {_rates(d)}), more than "
            f"max_steps = {max_steps}: allowed fewer frequencies, higher omega or a less stiff oscillator "
            "(smaller c/m, k/m)"
        )


def frequency_sweep(
    duffing: Duffing,
    F0: float,
    omegas,
    direction: str,
    *,
    x0: float = 0.0,
    v0: float = 0.0,
    rtol: float = 1e-8,
    atol: float | None = None,
    steady_tol: float = 1e-6,
    max_periods: int = 5000,
    integrator: str = "compiled",
    max_steps: int | None = None,
) -> SweepResult:
    """Stepped frequency sweep by time integration, each step from the previous steady state.

    The frequencies are visited in ascending order (``"up"``) or descending (``"down"``);
    the first starts from ``(x0, v0)`` and each next one from the state the previous one
    ended in, at phase 0 of ``F0 cos(omega t)``. Whole forcing periods are integrated
    until the stroboscopic state ``P_n = (x, v/omega)`` is steady: with ``d_n = |P_n -
    P_{n-1}|`` and ``r`` the larger of the last two ratios ``d_n/d_{n-1}``, the geometric
    estimate of the remaining drift ``d_n max(1, r/(1-r))`` must stay below ``steady_tol``
    times the amplitude for two consecutive periods (``r < 1``). The amplitude is half the
    peak-to-peak displacement over the last period, its extrema located inside the steps
    by quintic Hermite interpolation. A frequency that does not settle within
    ``max_periods`` (near a fold, subharmonic or chaotic motion) is flagged ``steady =
    False``; a mass that escapes (softening spring past its barrier) gives ``nan`` and the
    next frequency starts from rest.

    Parameters
    ----------
    duffing : Duffing
        The oscillator (c > 0).
    F0 : float
        Force amplitude, N (>= 0).
    omegas : array_like
        Forcing frequencies, rad/s (> 0), in any order; results are aligned with them.
    direction : {"up", "down"}
        Sweep direction.
    x0, v0 : float
        Initial displacement (m) and velocity (m/s) at the first frequency.
    rtol : float
        Relative tolerance of the integrator (1e-13 to 1e-2).
    atol : float, optional
        Absolute tolerance, m and m/s; default ``rtol`` times the static deflection ``F0/k``.
    steady_tol : float
        Steady criterion, relative to the amplitude (1e-12 to 1e-1).
    max_periods : int
        Most periods integrated per frequency (3 to 10^6).
    integrator : {"compiled", "scipy"}
        The compiled Dormand-Prince 5(4) (numba) or ``scipy.integrate.solve_ivp`` with
        RK45 one period at a time (extrema from its events): the same method and error
        control, for checking and timing.
    max_steps : int, optional
        Work budget: most integrator steps (accepted and rejected, all frequencies together);
        default ``MAX_SWEEP_STEPS`` (compiled, a few seconds) or ``MAX_SCIPY_SWEEP_STEPS``
        (scipy). A sweep that clearly needs more (a stiff oscillator, c/m or k/m large
        against omega, or a very low omega) is refused before it starts; one that spends the
        budget stops with a :class:`ParameterError` naming the frequency it reached.

    Returns
    -------
    SweepResult
        ``escaped`` flags the frequencies where the mass escaped (amplitude ``nan``).

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> w = np.linspace(4.6, 5.4, 9)
    >>> up, down = frequency_sweep(d, 5.0, w, "up"), frequency_sweep(d, 5.0, w, "down")
    >>> np.round(up.amplitude, 2)       # m
    array([1.53, 1.65, 1.76, 1.86, 1.95, 1.97, 0.74, 0.63, 0.55])
    >>> np.round(down.amplitude, 2)     # m
    array([1.53, 1.65, 1.76, 1.86, 1.95, 0.94, 0.74, 0.63, 0.55])
    >>> bool(up.steady.all() and down.steady.all())
    True
    """
    d = _check_duffing(duffing)
    _check_damped(d)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = _check_omegas(omegas)
    if not isinstance(direction, str) or direction not in ("up", "down"):
        raise ParameterError(f"direction = {direction!r:.60} is not valid: allowed 'up' or 'down'")
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    rtol = check_real("rtol", rtol, low=1e-13, high=1e-2)
    xr = _x_ref(d, F0) if F0 > 0 else max(abs(x0), 1.0)
    atol = rtol * xr if atol is None else check_real("atol", atol, low=0.0, low_open=True, unit="m")
    steady_tol = check_real("steady_tol", steady_tol, low=1e-12, high=0.1)
    max_periods = check_int("max_periods", max_periods, low=3, high=1_000_000)
    if not isinstance(integrator, str) or integrator not in ("compiled", "scipy"):
        raise ParameterError(f"integrator = {integrator!r:.60} is not valid: allowed 'compiled' or 'scipy'")
    limit = MAX_SWEEP_STEPS if integrator == "compiled" else MAX_SCIPY_SWEEP_STEPS
    max_steps = limit if max_steps is None else check_int("max_steps", max_steps, low=1, high=limit)
    _sweep_work(d, F0, w, x0, 3, max_steps, "frequency_sweep")
    order = np.argsort(w, kind="stable")
    if direction == "down":
        order = order[::-1]
    ws = np.ascontiguousarray(w[order])
    nw = ws.size
    amp, xmax, xmin = np.empty(nw), np.empty(nw), np.empty(nw)
    steady, periods, nsteps = np.zeros(nw, dtype=np.bool_), np.zeros(nw, dtype=np.int64), np.zeros(nw, np.int64)
    xs, vs = np.empty(nw), np.empty(nw)
    blow_up = 1e3 * max(xr, abs(x0), d.barrier if math.isfinite(d.barrier) else 0.0)
    args = (d.m, d.c, d.k, d.k3, F0, ws, x0, v0, rtol, atol, steady_tol, 3, max_periods, blow_up)
    outs = (amp, xmax, xmin, steady, periods, xs, vs, nsteps)
    if integrator == "compiled":
        status, j = _kernels()[0](*args, *outs, max_steps)
    else:
        status, j = _sweep_scipy(*args, *outs, max_steps)
    if status != 0:
        raise ParameterError(
            f"frequency_sweep spent its budget of max_steps = {max_steps} integrator steps at omega = {ws[j]:.6g} "
            f"rad/s (frequency {j + 1} of {nw} in sweep order, {periods[j]} periods there; {_rates(d)}): allowed "
            "fewer frequencies, a smaller max_periods, a looser steady_tol or rtol, or a less stiff oscillator"
        )
    inv = np.empty_like(order)
    inv[order] = np.arange(nw)
    return SweepResult(
        omega=w.copy(),
        amplitude=amp[inv],
        x_max=xmax[inv],
        x_min=xmin[inv],
        steady=steady[inv],
        periods=periods[inv],
        x_end=xs[inv],
        v_end=vs[inv],
        direction=direction,
        n_steps=nsteps[inv],
    )


def sweep(duffing: Duffing, F0: float, omegas, direction: str) -> np.ndarray:
    """Steady amplitudes of a stepped frequency sweep by time integration, m.

    :func:`frequency_sweep` with its defaults (see there for the steady criterion);
    ``amplitude[i]`` belongs to ``omegas[i]`` whatever the direction.

    Parameters
    ----------
    duffing : Duffing
        The oscillator (c > 0).
    F0 : float
        Force amplitude of ``F0 cos(omega t)``, N (>= 0).
    omegas : array_like
        Forcing frequencies, rad/s (> 0).
    direction : {"up", "down"}
        Visit the frequencies in ascending or descending order.

    Returns
    -------
    numpy.ndarray
        Half the peak-to-peak displacement over the last period at each frequency, m.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> np.round(sweep(d, 5.0, [5.0, 5.1], "up"), 3)      # m: on the upper branch at 5.1 rad/s
    array([1.951, 1.968])
    >>> np.round(sweep(d, 5.0, [5.0, 5.1], "down"), 3)    # m: from rest onto the lower one, then up at 5.0
    array([1.951, 0.938])
    """
    return frequency_sweep(duffing, F0, omegas, direction).amplitude


def locate_jump(
    duffing: Duffing,
    F0: float,
    result: SweepResult,
    which: int = 0,
    levels: int = 2,
    n: int = 10,
    max_periods: int = 5000,
):
    """Narrow a jump of a sweep down by re-sweeping its bracket on finer and finer grids.

    Starting from the steady state just before the jump, the bracket ``(omega_before,
    omega_after)`` is swept again in the same direction with ``n`` steps, the new bracket
    is the step where the amplitude jumps, and so on ``levels`` times: the bracket shrinks
    by ``n^levels``. Near a fold the response settles slowly (critical slowing down), so
    ``max_periods`` is raised to 20000 here.

    Parameters
    ----------
    duffing : Duffing
        The oscillator of the sweep.
    F0 : float
        Force amplitude of the sweep, N.
    result : SweepResult
        A sweep with at least one jump.
    which : int
        Which jump, in sweep order (0 first).
    levels : int
        Refinements (0 to 8).
    n : int
        Steps per refinement (2 to 1000).

    Returns
    -------
    tuple of float
        ``(omega_before, omega_after)``, rad/s: the last frequency on the old branch and the
        first on the new one; the jump lies between them.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> up = frequency_sweep(d, 5.0, np.linspace(4.6, 5.4, 9), "up")
    >>> lo, hi = locate_jump(d, 5.0, up)
    >>> round(lo, 3), round(hi - lo, 6)       # rad/s, rad/s
    (5.107, 0.001)
    """
    d = _check_duffing(duffing)
    _check_damped(d)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    if not isinstance(result, SweepResult):
        raise ParameterError(f"result = {result!r:.60} is not a SweepResult: allowed the output of frequency_sweep")
    max_periods = check_int("max_periods", max_periods, low=3, high=1_000_000)
    jumps = result.jumps()
    which = check_int("which", which, low=0, high=max(len(jumps) - 1, 0))
    if not jumps:
        raise ParameterError("result has no jump: allowed a sweep whose amplitude jumps")
    levels = check_int("levels", levels, low=0, high=8)
    n = check_int("n", n, low=2, high=1000)
    w_before, w_after, *_ = jumps[which]
    i = int(np.flatnonzero(result.omega == w_before)[0])
    x, v = float(result.x_end[i]), float(result.v_end[i])
    budget = MAX_SWEEP_STEPS  # shared by every level
    for _ in range(levels):
        ws = np.linspace(w_before, w_after, n + 1)
        if budget < 1:
            raise ParameterError(
                f"locate_jump spent its budget of {MAX_SWEEP_STEPS} integrator steps with levels = {levels}, "
                f"n = {n}: allowed fewer levels or steps per level"
            )
        res = frequency_sweep(d, F0, ws, result.direction, x0=x, v0=v, max_periods=max_periods, max_steps=budget)
        budget -= int(res.n_steps.sum())
        order = np.argsort(ws) if result.direction == "up" else np.argsort(ws)[::-1]
        amps = res.amplitude[order]
        a0 = amps[0]
        found = False
        for j in range(1, n + 1):
            if abs(amps[j] - a0) > 0.25 * max(amps[j], a0) or not np.isfinite(amps[j]):
                k_prev = order[j - 1]
                w_before, w_after = float(ws[k_prev]), float(ws[order[j]])
                x, v = float(res.x_end[k_prev]), float(res.v_end[k_prev])
                found = True
                break
            a0 = amps[j]
        if not found:  # the finer sweep crossed without jumping: keep the last bracket
            break
    return w_before, w_after


def duffing_response(
    duffing: Duffing,
    F0: float,
    omega: float,
    t,
    *,
    sine: bool = False,
    x0: float = 0.0,
    v0: float = 0.0,
    rtol: float = 1e-10,
):
    """Response ``x(t)`` to ``F0 cos(omega t)`` (or ``F0 sin(omega t)``, the paper's forcing) from ``(x0, v0)``.

    ``solve_ivp`` with DOP853 at ``rtol`` (absolute tolerance ``rtol`` times the static
    deflection), sampled at ``t``.

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    F0 : float
        Force amplitude, N (>= 0).
    omega : float
        Forcing frequency, rad/s (>= 0).
    t : array_like
        Sample times, s (increasing, starting at the initial time 0 or later).
    sine : bool
        Force with ``sin`` (the paper) instead of ``cos``.
    x0, v0 : float
        State at t = 0, m and m/s.
    rtol : float
        Relative tolerance (1e-13 to 1e-3).

    Returns
    -------
    tuple of numpy.ndarray
        ``(x, v)``, m and m/s at ``t``.

    Examples
    --------
    >>> x, v = duffing_response(Duffing(1.0, 0.5, 20.0, 0.0), 5.0, 4.47, [0.0, 50.0], sine=True)
    >>> round(float(x[-1]), 4)          # m, as the linear closed form of Part I
    2.009
    """
    from scipy.integrate import solve_ivp

    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = check_real("omega", omega, low=0.0, unit="rad/s")
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    rtol = check_real("rtol", rtol, low=1e-13, high=1e-3)
    if not isinstance(sine, (bool, np.bool_)):
        raise ParameterError(f"sine = {sine!r:.60} is not a bool: allowed True or False")
    tt = _real_array("t", t, unit="s").reshape(-1)
    if np.any(np.diff(tt) < 0) or tt[0] < 0:
        raise ParameterError(f"t = {t!r:.60} is out of range: allowed non-empty, increasing, t >= 0 s, finite")
    m, c, k, k3 = d.m, d.c, d.k, d.k3
    trig = math.sin if sine else math.cos
    t_end = float(tt[-1])
    xr = _x_ref(d, F0) if F0 > 0 else max(abs(x0), 1.0)
    # DOP853 needs h lambda within its stability interval (about 6) and takes 12 evaluations a step
    lam = _linear_rate(d, max(abs(x0), xr))
    need = 12.0 * t_end * max(lam, w) / 6.0
    if not need <= MAX_RHS_EVALUATIONS:
        raise ParameterError(
            f"t up to {t_end:.6g} s needs at least {need:.3g} right-hand-side evaluations (step <= 6/lambda, "
            f"lambda = {max(lam, w):.3g} 1/s from {_rates(d)}, omega = {w:.3g} rad/s), more than "
            f"{MAX_RHS_EVALUATIONS}: allowed a shorter window or a less stiff oscillator (smaller c/m, k/m)"
        )
    blow_up = 1e3 * max(xr, abs(x0), d.barrier) if d.k3 < 0 else math.inf

    def rhs(time, y):
        return (y[1], (F0 * trig(w * time) - c * y[1] - k * y[0] - k3 * y[0] ** 3) / m)

    def escape(time, y):
        return blow_up - abs(y[0])

    escape.terminal = True
    counted = _Counted(rhs, MAX_RHS_EVALUATIONS)
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            sol = solve_ivp(
                counted,
                (0.0, t_end),
                (x0, v0),
                method="DOP853",
                t_eval=tt,
                rtol=rtol,
                atol=rtol * xr,
                events=escape if d.k3 < 0 else None,
            )
    except _OverBudget:
        raise ParameterError(
            f"duffing_response spent its budget of {MAX_RHS_EVALUATIONS} right-hand-side evaluations before "
            f"t = {t_end:.6g} s ({_rates(d)}, k3 = {k3!r} N/m^3, x0 = {x0!r} m, v0 = {v0!r} m/s): allowed a shorter "
            "window, a looser rtol or a less stiff oscillator"
        ) from None
    if sol.status == 1:
        raise ParameterError(
            f"the mass escaped over the softening spring's barrier ({d.barrier:.3g} m): |x| passed {blow_up:.3g} m "
            f"at t = {float(sol.t_events[0][0]):.6g} s: allowed parameters whose motion stays bounded "
            "(smaller F0, x0, v0 or |k3|)"
        )
    if sol.status != 0 or not (np.all(np.isfinite(sol.y)) and sol.y.shape[1] == tt.size):
        raise ParameterError(
            f"the integration failed ({sol.message}): allowed parameters whose motion stays bounded and finite"
        )
    return sol.y[0], sol.y[1]


def _sweep_scipy(
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
):
    """The sweep of the compiled kernel with ``solve_ivp(method="RK45")``, one period per call.

    Returns ``(status, j)`` as the kernel: status 1 when about ``max_steps`` steps (counted as
    right-hand-side evaluations / 6) are spent, at frequency j.
    """
    from scipy.integrate import solve_ivp

    x, v = x0, v0
    budget = _Counted(None, 6 * max_steps)
    for j, w in enumerate(omegas):
        T = 2.0 * math.pi / w

        def rhs(t, y, w=w):
            budget.calls += 1
            if budget.calls > budget.limit:
                raise _OverBudget
            return (y[1], (F0 * math.cos(w * t) - c * y[1] - k * y[0] - k3 * y[0] ** 3) / m)

        def turning(t, y):
            return y[1]

        d_prev, ok_prev, rho_prev, done, escaped, n, steps = -1.0, False, 1.0, False, False, 0, 0
        xmax = xmin = x
        while n < max_periods and not done:
            try:
                with np.errstate(over="ignore", invalid="ignore"):
                    sol = solve_ivp(
                        rhs, (0.0, T), (x, v), method="RK45", rtol=rtol, atol=atol, events=turning, max_step=T / 16
                    )
            except _OverBudget:
                nsteps[j], periods[j] = steps, n
                return 1, j
            steps += sol.t.size - 1
            if sol.status != 0 or not np.all(np.isfinite(sol.y[:, -1])) or np.max(np.abs(sol.y[0])) > blow_up:
                escaped = True
                break
            xe = sol.y_events[0][:, 0] if sol.y_events[0].size else np.empty(0)
            allx = np.concatenate([sol.y[0], xe])
            xmax, xmin = float(allx.max()), float(allx.min())
            px, pv = x, v
            x, v = float(sol.y[0, -1]), float(sol.y[1, -1])
            n += 1
            dd = math.hypot(x - px, (v - pv) / w)
            scale = max(0.5 * (xmax - xmin), atol)
            rho = dd / d_prev if d_prev > 0 else (0.0 if dd == 0 else 1.0)
            r = max(rho, rho_prev)
            ok = dd == 0.0 or (r < 1.0 and dd * max(1.0, r / (1.0 - r)) <= steady_tol * scale)
            done = ok and ok_prev and n >= min_periods
            d_prev, ok_prev, rho_prev = dd, ok, rho
        nsteps[j], periods[j] = steps, n
        if escaped:
            amp[j] = xmax_out[j] = xmin_out[j] = xs[j] = vs[j] = math.nan
            steady[j] = False
            x, v = 0.0, 0.0
        else:
            amp[j], xmax_out[j], xmin_out[j], steady[j], xs[j], vs[j] = 0.5 * (xmax - xmin), xmax, xmin, done, x, v
    return 0, len(omegas)


# ------------------------------------------------------------------- periodic orbits and Floquet


@dataclass(frozen=True)
class PeriodicOrbit:
    """A periodic orbit of the forcing period, found by shooting, with its Floquet multipliers."""

    omega: float  # forcing frequency, rad/s
    x0: float  # displacement at phase 0 of the forcing, m
    v0: float  # velocity at phase 0, m/s
    amplitude: float  # half the peak-to-peak displacement, m
    multipliers: tuple[complex, complex]  # eigenvalues of the monodromy matrix
    residual: float  # |P(x0, v0) - (x0, v0)| of the converged orbit, m (velocity / omega)
    iterations: int  # Newton iterations

    @property
    def stable(self) -> bool:
        """Both multipliers inside the unit circle."""
        return max(abs(mu) for mu in self.multipliers) < 1.0


def _flow_period(d: Duffing, F0: float, w: float, x0: float, v0: float, rtol: float, events=False, budget=None):
    """One forcing period of the state and its variational equations (DOP853); ``budget`` a :class:`_Counted`."""
    from scipy.integrate import solve_ivp

    m, c, k, k3 = d.m, d.c, d.k, d.k3

    def rhs(t, y):
        if budget is not None:
            budget.calls += 1
            if budget.calls > budget.limit:
                raise _OverBudget
        x, v = y[0], y[1]
        jx = -(k + 3.0 * k3 * x * x) / m
        return (
            v,
            (F0 * math.cos(w * t) - c * v - k * x - k3 * x**3) / m,
            y[3],
            jx * y[2] - c / m * y[3],
            y[5],
            jx * y[4] - c / m * y[5],
        )

    def turning(t, y):
        return y[1]

    T = 2.0 * math.pi / w
    xr = max(abs(x0), abs(v0) / w, 1e-300)
    with np.errstate(over="ignore", invalid="ignore"):
        sol = solve_ivp(
            rhs,
            (0.0, T),
            (x0, v0, 1.0, 0.0, 0.0, 1.0),
            method="DOP853",
            rtol=rtol,
            atol=rtol * xr * 1e-3,
            events=turning if events else None,
        )
    return sol


def periodic_orbit(
    duffing: Duffing,
    F0: float,
    omega: float,
    amplitude_guess: float | None = None,
    *,
    x0: float | None = None,
    v0: float | None = None,
    rtol: float = 1e-11,
    max_iterations: int = 40,
) -> PeriodicOrbit:
    """Periodic orbit of the full equation by Newton shooting, with its Floquet multipliers.

    Newton's method on ``P(x0, v0) - (x0, v0) = 0``, ``P`` the flow over one forcing period
    (``solve_ivp``, DOP853, with the variational equations giving the monodromy matrix
    ``M = dP/d(x0, v0)``). The orbit is stable when both eigenvalues of ``M`` (the Floquet
    multipliers) lie inside the unit circle; their product is ``exp(-c T / m)`` (Liouville),
    a check of the integration. Works on unstable orbits too (the middle harmonic-balance
    branch), which time integration alone cannot reach.

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    F0 : float
        Force amplitude, N (>= 0).
    omega : float
        Forcing frequency, rad/s (> 0).
    amplitude_guess : float, optional
        Start from the one-harmonic solution with this amplitude (m); its phase is taken
        from the amplitude equation. Default: the largest harmonic-balance amplitude.
    x0, v0 : float, optional
        Start from this state at phase 0 instead (m, m/s).
    rtol : float
        Relative tolerance of DOP853 (1e-13 to 1e-6).
    max_iterations : int
        Newton iterations allowed (1 to 200).

    Returns
    -------
    PeriodicOrbit

    Raises
    ------
    ParameterError
        When Newton's method does not converge from the guess.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> hb = hb_amplitudes(d, 5.0, 5.07)
    >>> [(round(a, 3), s) for a, s in hb]          # m, slow-flow stability
    [(1.041, True), (1.625, False), (1.97, True)]
    >>> [(round(o.amplitude, 3), o.stable) for o in (periodic_orbit(d, 5.0, 5.07, a) for a, _ in hb)]
    [(1.046, True), (1.62, False), (1.986, True)]
    """
    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    rtol = check_real("rtol", rtol, low=1e-13, high=1e-6)
    max_iterations = check_int("max_iterations", max_iterations, low=1, high=200)
    if (x0 is None) != (v0 is None):
        raise ParameterError(f"x0 = {x0!r:.30} and v0 = {v0!r:.30}: allowed both given (m, m/s) or both None")
    if x0 is None:
        if amplitude_guess is None:
            hb = hb_amplitudes(d, F0, w)
            if not hb:
                raise ParameterError(
                    f"omega = {w!r} rad/s is the undamped linear oscillator's resonance (no steady amplitude): "
                    "allowed c > 0, k3 != 0 or another omega"
                )
            amplitude_guess = max(hb)[0]
        A = check_real("amplitude_guess", amplitude_guess, low=0.0, unit="m")
        # a cos(wt) + b sin(wt): from the cosine/sine balance, a = (s + y) A^2 / F0, b = c w A^2 / F0
        s, y = d.k - d.m * w * w, d.kappa * A * A
        if F0 > 0:
            a, b = (s + y) * A * A / F0, d.c * w * A * A / F0
        else:
            a, b = A, 0.0
        x, v = a, b * w
    else:
        x = check_real("x0", x0, unit="m")
        v = check_real("v0", v0, unit="m/s")
    if not (math.isfinite(x) and math.isfinite(v)):
        raise ParameterError(
            f"amplitude_guess = {amplitude_guess!r} m gives a non-finite starting state: allowed a smaller guess"
        )
    # each period needs h lambda within DOP853's stability interval (about 6), 12 evaluations a step
    T = 2.0 * math.pi / w
    lam = _linear_rate(d, max(abs(x), _x_ref(d, F0) if F0 > 0 else 0.0))
    need = 2.0 * 12.0 * max(T * lam / 6.0, 1.0)
    if not need <= MAX_RHS_EVALUATIONS:
        raise ParameterError(
            f"omega = {w!r} rad/s (period {T:.3g} s) needs at least {need:.3g} right-hand-side evaluations for two "
            f"periods (step <= 6/lambda, lambda = {lam:.3g} 1/s: {_rates(d)}), more than {MAX_RHS_EVALUATIONS}: "
            "allowed a higher omega or a less stiff oscillator (smaller c/m, k/m)"
        )
    budget = _Counted(None, MAX_RHS_EVALUATIONS)
    try:
        return _shoot(d, F0, w, x, v, rtol, max_iterations, budget)
    except _OverBudget:
        raise ParameterError(
            f"periodic_orbit spent its budget of {MAX_RHS_EVALUATIONS} right-hand-side evaluations at omega = "
            f"{w!r} rad/s ({_rates(d)}): allowed fewer max_iterations, a looser rtol, a higher omega or a less "
            "stiff oscillator"
        ) from None


def _shoot(d: Duffing, F0: float, w: float, x: float, v: float, rtol: float, max_iterations: int, budget):
    """Damped Newton shooting from ``(x, v)``, then the orbit's multipliers (see :func:`periodic_orbit`)."""
    res = math.inf
    it = 0
    for it in range(1, max_iterations + 1):  # noqa: B007
        sol = _flow_period(d, F0, w, x, v, rtol, budget=budget)
        yT = sol.y[:, -1]
        g = np.array([yT[0] - x, yT[1] - v])
        M = np.array([[yT[2], yT[4]], [yT[3], yT[5]]])
        res = math.hypot(g[0], g[1] / w)
        scale = max(abs(x), abs(v) / w, _x_ref(d, F0) if F0 > 0 else 1.0)
        if res <= 1e-9 * scale:
            break
        try:
            dx = np.linalg.solve(M - np.eye(2), -g)
        except np.linalg.LinAlgError:
            break
        if not np.all(np.isfinite(dx)):
            break
        lam = 1.0  # damped Newton: halve the step until the residual decreases
        while lam > 1e-3:
            xt, vt = x + lam * dx[0], v + lam * dx[1]
            yt = _flow_period(d, F0, w, xt, vt, rtol, budget=budget).y[:, -1]
            if math.isfinite(yt[0]) and math.hypot(yt[0] - xt, (yt[1] - vt) / w) < res:
                break
            lam *= 0.5
        x, v = xt, vt
        if not (math.isfinite(x) and math.isfinite(v)):
            break
    else:
        it = max_iterations
    if not res <= 1e-7 * max(abs(x), abs(v) / w, 1e-300):
        raise ParameterError(
            f"periodic_orbit did not converge at omega = {w!r} rad/s (residual {res:.3g} m): allowed a guess "
            "closer to a periodic orbit (amplitude_guess or x0, v0)"
        )
    sol = _flow_period(d, F0, w, x, v, rtol, events=True, budget=budget)
    yT = sol.y[:, -1]
    M = np.array([[yT[2], yT[4]], [yT[3], yT[5]]])
    if not np.all(np.isfinite(M)):
        raise ParameterError(
            f"periodic_orbit: the monodromy matrix at omega = {w!r} rad/s is not finite (overflow): allowed "
            "parameters whose orbit and its variations stay finite over one period"
        )
    mu = np.linalg.eigvals(M)
    xe = sol.y_events[0][:, 0] if sol.y_events[0].size else sol.y[0]
    xa = np.concatenate([xe, sol.y[0]])
    return PeriodicOrbit(
        omega=w,
        x0=x,
        v0=v,
        amplitude=0.5 * float(xa.max() - xa.min()),
        multipliers=(complex(mu[0]), complex(mu[1])),
        residual=res,
        iterations=it,
    )


# ------------------------------------------------------------------------------------- chaos


@dataclass(frozen=True)
class LyapunovResult:
    """Lyapunov exponents of the forced oscillator (per unit time, 1/s)."""

    exponents: tuple[float, ...]  # largest first, 1/s (QR gives two, two-trajectory one)
    running: np.ndarray  # running estimate of the largest exponent after each period, 1/s
    method: str  # "qr" (variational equations) or "benettin" (two trajectories)
    time: float  # averaging time, s
    x_end: float  # final state, m
    v_end: float  # m/s


def _rk4_run(duffing, F0, omega, x0, v0, n_periods, n_transient, steps_per_period, mode=0, d0=1.0):
    """Check the arguments, discard ``n_transient`` periods, then run the compiled RK4 in ``mode``.

    Returns the averaging time ``n_periods T`` (s) and the kernel's ``(points, running, tail)``.
    """
    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    n_periods = check_int("n_periods", n_periods, low=1, high=2_000_000)
    n_transient = check_int("n_transient", n_transient, low=0, high=10_000_000)
    spp = check_int("steps_per_period", steps_per_period, low=8, high=100_000)
    total = (n_periods + n_transient) * spp
    if total > MAX_RK4_STEPS:
        raise ParameterError(
            f"n_periods = {n_periods}, n_transient = {n_transient} and steps_per_period = {spp} make {total} RK4 "
            f"steps: allowed at most {MAX_RK4_STEPS} "
            "((n_periods + n_transient) steps_per_period)"
        )
    T = 2.0 * math.pi / w
    h = T / spp
    lam = _linear_rate(d, max(abs(x0), _x_ref(d, F0) if F0 > 0 else 0.0))
    if h * lam > RK4_STABILITY:
        need = math.ceil(T * lam / RK4_STABILITY)
        raise ParameterError(
            f"steps_per_period = {spp} at omega = {w!r} rad/s gives a step of {h:.3g} s, and the fixed-step RK4 is "
            f"unstable for h lambda > {RK4_STABILITY} with lambda = {lam:.3g} 1/s ({_rates(d)}): allowed "
            f"steps_per_period >= {need:.3g}"
            + (" (above its limit 100000: a higher omega or a less stiff oscillator)" if need > 100_000 else "")
        )
    blow_up = 1e3 * max(_x_ref(d, F0), abs(x0), d.barrier) if d.k3 < 0 else math.inf
    # renormalise at least every time the damping alone contracts by exp(-5): the second tangent vector
    # (QR) and the separation (two trajectories) must stay well above the rounding of the leading one
    contraction = d.c / d.m * T
    gs_every = spp if contraction <= 5.0 else max(1, int(spp * 5.0 / contraction))
    kern = _kernels()[1]
    if n_transient:
        *_, tail = kern(d.m, d.c, d.k, d.k3, F0, w, x0, v0, n_transient, spp, 0, 1.0, False, spp, blow_up)
        _rk4_status(d, F0, w, x0, v0, tail, 0)
        x0, v0 = float(tail[2]), float(tail[3])
    out = kern(d.m, d.c, d.k, d.k3, F0, w, x0, v0, n_periods, spp, mode, d0, mode != 0, gs_every, blow_up)
    _rk4_status(d, F0, w, x0, v0, out[2], n_transient)
    time = n_periods * T
    return (time, *out)


def _rk4_status(d: Duffing, F0: float, w: float, x0: float, v0: float, tail: np.ndarray, offset: int) -> None:
    """Raise :class:`ParameterError` when the compiled RK4 stopped early (see its status codes)."""
    status, n = int(tail[8]), int(tail[9]) + offset
    if status == 1:
        what = (
            f"the mass escaped over the softening spring's barrier ({d.barrier:.3g} m; |x| passed "
            f"{1e3 * max(_x_ref(d, F0), abs(x0), d.barrier):.3g} m or overflowed)"
            if d.k3 < 0
            else "the fixed-step RK4 overflowed (the state is not finite: the step is too large for the cubic "
            "stiffness at this amplitude, or the motion is unbounded)"
        )
        raise ParameterError(
            f"{what} in forcing period {n + 1} (F0 = {F0!r} N, omega = {w!r} rad/s, x0 = {x0!r} m, v0 = {v0!r} "
            "m/s): allowed parameters whose motion stays bounded, or more steps_per_period"
        )
    if status == 2:
        raise ParameterError(
            f"the tangent vectors or the trajectories' separation underflowed or overflowed in forcing period "
            f"{n + 1} ({_rates(d)}, omega = {w!r} rad/s): allowed a less extreme damping or forcing period"
        )
    exps = tail[:2]
    if not np.all(np.isfinite(exps)):  # pragma: no cover - the kernel stops before
        raise ParameterError("the Lyapunov sums are not finite: allowed parameters whose motion stays bounded")


def _lyapunov_result(time, running, tail, method, n_exponents) -> LyapunovResult:
    return LyapunovResult(
        exponents=tuple(float(s / time) for s in tail[:n_exponents]),
        running=running,
        method=method,
        time=time,
        x_end=float(tail[2]),
        v_end=float(tail[3]),
    )


def poincare_section(
    duffing: Duffing,
    F0: float,
    omega: float,
    x0: float = 0.0,
    v0: float = 0.0,
    n_periods: int = 2000,
    n_transient: int = 200,
    steps_per_period: int = 400,
):
    """Stroboscopic Poincaré section: the state at phase 0 of the forcing, once per period.

    Integrated with a compiled fixed-step RK4 (``steps_per_period`` steps per period).

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    F0 : float
        Force amplitude, N.
    omega : float
        Forcing frequency, rad/s.
    x0, v0 : float
        Initial state at t = 0, m and m/s.
    n_periods : int
        Points returned (after the transient).
    n_transient : int
        Periods discarded first.
    steps_per_period : int
        RK4 steps per forcing period (8 to 100000).

    Returns
    -------
    numpy.ndarray
        Shape ``(n_periods, 2)``: x (m) and v (m/s) at ``t = (n_transient + i + 1) T``.

    Examples
    --------
    >>> pts = poincare_section(Duffing(1.0, 0.5, 20.0, 2.0), 5.0, 3.0, n_periods=3)
    >>> bool(np.ptp(pts[:, 0]) < 1e-9)           # a period-1 orbit: one point
    True
    """
    _, pts, _, _ = _rk4_run(duffing, F0, omega, x0, v0, n_periods, n_transient, steps_per_period)
    return pts


def lyapunov_qr(
    duffing: Duffing,
    F0: float,
    omega: float,
    x0: float = 0.0,
    v0: float = 0.0,
    n_periods: int = 2000,
    n_transient: int = 100,
    steps_per_period: int = 400,
) -> LyapunovResult:
    """Both Lyapunov exponents from the variational equations with QR (Gram-Schmidt) re-orthonormalisation.

    The state and two tangent vectors are integrated together (compiled RK4); once per
    forcing period the tangent vectors are orthonormalised and the logarithms of the
    diagonal of R accumulated (Benettin et al. 1980; Wolf et al. 1985). The two exponents
    sum to ``-c/m`` (the trace of the Jacobian), whatever the motion.

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    F0 : float
        Force amplitude, N.
    omega : float
        Forcing frequency, rad/s.
    x0, v0 : float
        Initial state, m and m/s.
    n_periods : int
        Periods averaged over (after the transient).
    n_transient : int
        Periods discarded first (the tangent vectors align meanwhile).
    steps_per_period : int
        RK4 steps per forcing period.

    Returns
    -------
    LyapunovResult
        ``exponents = (lambda_1, lambda_2)``, 1/s.

    Examples
    --------
    >>> r = lyapunov_qr(Duffing(1.0, 0.5, 20.0, 2.0), 5.0, 3.0, n_periods=200)
    >>> round(sum(r.exponents), 6)        # = -c/m, 1/s
    -0.5
    """
    time, _, running, tail = _rk4_run(duffing, F0, omega, x0, v0, n_periods, n_transient, steps_per_period, 1)
    return _lyapunov_result(time, running, tail, "qr", 2)


def lyapunov_benettin(
    duffing: Duffing,
    F0: float,
    omega: float,
    x0: float = 0.0,
    v0: float = 0.0,
    n_periods: int = 2000,
    n_transient: int = 100,
    steps_per_period: int = 400,
    d0: float = 1e-8,
) -> LyapunovResult:
    """Largest Lyapunov exponent from two nearby trajectories, renormalised once per period.

    A partner trajectory starts ``d0`` away; both are integrated with the same compiled RK4
    steps (no variational equations), and once per forcing period the logarithm of their
    separation over ``d0`` is accumulated and the partner pulled back to distance ``d0``
    along the separation (Benettin et al. 1976). Independent of :func:`lyapunov_qr` except
    for the stepper.

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    F0 : float
        Force amplitude, N.
    omega : float
        Forcing frequency, rad/s.
    x0, v0 : float
        Initial state, m and m/s.
    n_periods, n_transient, steps_per_period : int
        As in :func:`lyapunov_qr`.
    d0 : float
        Separation kept between the trajectories, in (x m, v m/s) (1e-12 to 1e-4).

    Returns
    -------
    LyapunovResult
        ``exponents = (lambda_1,)``, 1/s.

    Examples
    --------
    >>> r = lyapunov_benettin(Duffing(1.0, 0.5, 20.0, 2.0), 5.0, 3.0, n_periods=200)
    >>> r.exponents[0] < 0                # a stable periodic orbit
    True
    """
    d0 = check_real("d0", d0, low=1e-12, high=1e-4)
    time, _, running, tail = _rk4_run(duffing, F0, omega, x0, v0, n_periods, n_transient, steps_per_period, 2, d0)
    return _lyapunov_result(time, running, tail, "benettin", 1)
