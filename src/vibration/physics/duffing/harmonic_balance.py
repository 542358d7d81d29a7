"""Harmonic balance of the Duffing oscillator (one harmonic): amplitude equation, backbone, folds, curve.

See :mod:`vibration.physics.duffing` for the equations and references.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model import ParameterError, check_int, check_real
from .model import NEWTON_STEPS, Duffing, _check_damped, _check_duffing, _overflow_is_error, _real_array


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
    >>> [(round(a, 4), s) for a, s in hb_amplitudes(Duffing(m=1.0, c=0.5, k=20.0, k3=0.0), 5.0, 3.0)]
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
    >>> round(float(backbone(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0), 2.0)), 4)     # rad/s
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
    >>> round(linear_trust_amplitude(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)), 4)    # m
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


@dataclass(frozen=True, kw_only=True)
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
    kap = d.kappa
    a_peak, w_peak = _peak(d, F0)
    if kap == 0.0:
        return _folds_record([], kap, a_peak, w_peak)
    found = _fold_points(d, F0)
    if math.isfinite(a_peak):  # folds of the resonance curve, not of a softening curve's outer branch
        found = [(w, a) for w, a in found if a <= a_peak * (1 + 1e-9)]
    found.sort()
    return _folds_record(found, kap, a_peak, w_peak)


def _fold_points(d: Duffing, F0: float) -> list[tuple[float, float]]:
    """Every admissible root of the fold quintic as ``(omega, A)`` (rad/s, m), in the companion matrix's order."""
    m, c, k, kap = d.m, d.c, d.k, d.kappa
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
    return found


def _folds_record(found: list[tuple[float, float]], kap: float, a_peak: float, w_peak: float) -> Folds:
    """The :class:`Folds` of the sorted fold points ``found`` and the peak: both folds, the one jump of an open
    softening curve, or none."""
    nan = math.nan
    if len(found) == 1 and kap < 0:  # an open softening curve: only the sweep-up jump exists
        (wh, ah) = found[0]
        return Folds(
            omega_low=nan, omega_high=wh, amplitude_low=nan, amplitude_high=ah, peak_amplitude=a_peak, peak_omega=w_peak
        )
    if len(found) < 2:
        return Folds(
            omega_low=nan, omega_high=nan, amplitude_low=nan, amplitude_high=nan, peak_amplitude=a_peak,
            peak_omega=w_peak,
        )  # fmt: skip
    (wl, al), (wh, ah) = found[0], found[-1]
    return Folds(
        omega_low=wl, omega_high=wh, amplitude_low=al, amplitude_high=ah, peak_amplitude=a_peak, peak_omega=w_peak
    )


@_overflow_is_error
def response_curve(duffing: Duffing, F0: float, omega_max: float, *, n: int = 801, amplitude_max: float | None = None):
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
    >>> w, a, st = response_curve(Duffing(m=1.0, c=0.5, k=20.0, k3=2.0), 5.0, 8.0)
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
    try:
        a_low = min(hb_amplitudes(d, F0, omega_max))[0]
    except ParameterError:
        raise ParameterError(
            f"omega_max = {omega_max!r} rad/s overflows the amplitude equation there (m omega_max^2 = "
            f"{m * omega_max * omega_max:.3g} N/m): allowed omega_max whose (k - m omega_max^2)^2 is a finite float"
        ) from None
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
    if omega.size < 2:
        with np.errstate(all="ignore"):
            w_all = _curve_points(m, c, k, kap, F0, math.inf, a_low + (a_top - a_low) * s)[0]
        lowest = float(np.sort(w_all)[1]) if w_all.size >= 2 else math.nan
        raise ParameterError(
            f"omega_max = {omega_max!r} rad/s leaves {omega.size} point(s) of the response curve: allowed omega_max "
            f"above its lowest frequencies (omega_max > {lowest:.6g} rad/s)"
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
