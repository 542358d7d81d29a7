"""Extrema of a free decay and the classical peak analysis (log decrement, linear envelope).

An estimator independent of the whole-trace fit :func:`vibration.physics.lab.decay.fit_free_decay`:
it uses only the times and angles of the extrema. The model and its half-period recursion are
described in :mod:`vibration.physics.lab.decay`.
"""

from __future__ import annotations

import hashlib
import math
from collections import OrderedDict
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize, signal

from vibration.physics.lab._checks import time_and_signal
from vibration.physics.model import ParameterError, check_real

LAWS = ("viscous", "coulomb", "combined")
#: Fewest half periods (intervals between consecutive extrema) an analysis needs.
MIN_HALF_PERIODS = 4
#: Extrema whose swing to the next one is below this fraction of the first swing are not used
#: by :func:`peak_decay_fit` (near the stop real wheels leave the model: the half period shortens).
MIN_SWING_FRACTION = 0.2


# ----------------------------------------------------------------------------- peaks


@dataclass(frozen=True, eq=False, kw_only=True)
class DecayPeaks:
    """Extrema of a free decay, refined by a local parabola.

    Attributes
    ----------
    t : numpy.ndarray
        Times of the extrema (s).
    theta : numpy.ndarray
        Angles at the extrema (rad).
    sign : numpy.ndarray
        +1 for a maximum, -1 for a minimum; maxima and minima alternate.
    index : numpy.ndarray
        Index of the sample nearest each extremum.
    """

    t: np.ndarray
    theta: np.ndarray
    sign: np.ndarray
    index: np.ndarray

    @property
    def n(self) -> int:
        """Number of extrema."""
        return int(self.t.size)


def _resolution(y: np.ndarray) -> float:
    """Smallest step between distinct values (the quantisation step of encoder data)."""
    u = np.unique(y)
    d = np.diff(u)
    d = d[d > 1e-12 * max(1.0, float(np.max(np.abs(u))))]
    return float(d.min()) if d.size else 0.0


def free_decay_peaks(t, theta) -> DecayPeaks:
    """Alternating maxima and minima of a decaying oscillation, refined by a local least-squares parabola.

    Extrema are found with a prominence of at least three resolution steps of the signal (the
    smallest step between distinct values, i.e. the encoder's quantum) and at least 2 % of its
    range, so that quantisation flicker at rest is not counted; plateaus count once. Each extremum
    is then refined by a two-sided parabola (one curvature on each side of the vertex, because
    Coulomb friction makes the acceleration jump there) fitted to the samples within 0.2 of a half
    period of it (at least 3 samples).

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing (uniform spacing not needed).
    theta : array_like
        Angles (rad).

    Returns
    -------
    DecayPeaks
        Times (s), angles (rad), signs and sample indices of the extrema.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0.0, 10.0, 0.05)
    >>> p = free_decay_peaks(t, np.exp(-0.1 * t) * np.cos(3.0 * t))
    >>> p.n, p.sign[:3].tolist(), round(float(p.t[1]), 2)
    (9, [-1, 1, -1], 2.08)
    """
    ta, ya = time_and_signal(t, theta, t_name="t", y_name="theta", y_unit="rad")
    return _peaks(ta, ya)


#: The peaks of the last few records (their bytes' digest -> DecayPeaks, read-only): a study fits each decay with
#: every candidate law, and every fit starts from the same peaks.
_PEAKS_SEEN: OrderedDict = OrderedDict()
_PEAKS_KEPT = 64


def _peaks(ta: np.ndarray, ya: np.ndarray) -> DecayPeaks:
    """:func:`free_decay_peaks` of checked arrays, computed once per record (a pure function of their values)."""
    key = (ta.shape, ta.dtype.str, ya.dtype.str, hashlib.blake2b(ta.tobytes() + ya.tobytes(), digest_size=20).digest())
    found = _PEAKS_SEEN.get(key)
    if found is None:
        found = _PEAKS_SEEN[key] = _find_peaks(ta, ya)
        if len(_PEAKS_SEEN) > _PEAKS_KEPT:
            _PEAKS_SEEN.popitem(last=False)
    return found


def _find_peaks(ta: np.ndarray, ya: np.ndarray) -> DecayPeaks:
    thr = max(3.0 * _resolution(ya), 0.02 * float(np.ptp(ya)))
    hi, _ = signal.find_peaks(ya, prominence=thr)
    lo, _ = signal.find_peaks(-ya, prominence=thr)
    idx = np.concatenate([hi, lo])
    sgn = np.concatenate([np.ones(hi.size, int), -np.ones(lo.size, int)])
    order = np.argsort(idx)
    idx, sgn = idx[order], sgn[order]
    keep_i: list[int] = []
    keep_s: list[int] = []
    for i, s in zip(idx.tolist(), sgn.tolist(), strict=True):
        if keep_s and keep_s[-1] == s:  # two maxima (or minima) in a row: keep the more extreme
            if s * ya[i] > s * ya[keep_i[-1]]:
                keep_i[-1] = i
            continue
        keep_i.append(i)
        keep_s.append(s)
    idx = np.asarray(keep_i, dtype=np.int64)
    sgn = np.asarray(keep_s, dtype=np.int64)
    tp = ta[idx].astype(float)
    yp = ya[idx].astype(float)
    if idx.size >= 2:
        half = float(np.median(np.diff(ta[idx])))
        for m, i in enumerate(idx.tolist()):
            w = np.abs(ta - ta[i]) <= 0.2 * half
            if np.count_nonzero(w) < 3:
                continue
            ref = _refine(ta[w] - ta[i], ya[w], sgn[m], 0.2 * half)
            if ref is not None:
                tp[m] = ta[i] + ref[0]
                yp[m] = ref[1]
    for arr in (tp, yp, sgn, idx):
        arr.flags.writeable = False
    return DecayPeaks(t=tp, theta=yp, sign=sgn, index=idx)


def _refine(x: np.ndarray, y: np.ndarray, sgn: int, reach: float):
    """Vertex (x, y) of a two-sided parabola y = a + b_L (x - x_p)^2 (left), a + b_R (x - x_p)^2 (right).

    Two curvatures because with Coulomb friction the acceleration jumps at the extremum (the
    centre of the motion moves by 2 Delta): one parabola would be biased towards the flatter side.
    """

    def sse(xp):
        left = x < xp
        X = np.column_stack([np.ones_like(x), np.where(left, (x - xp) ** 2, 0.0), np.where(left, 0.0, (x - xp) ** 2)])
        coef, *_ = np.linalg.lstsq(X, y, rcond=None)
        r = y - X @ coef
        return float(r @ r), coef

    dx = float(np.min(np.diff(x))) if x.size > 1 else reach
    lo_x, hi_x = max(float(x.min()), -2.0 * dx), min(float(x.max()), 2.0 * dx)
    if not lo_x < hi_x:
        return None
    res = optimize.minimize_scalar(lambda v: sse(v)[0], bounds=(lo_x, hi_x), method="bounded", options={"xatol": 1e-9})
    xp = float(res.x)
    _, coef = sse(xp)
    if coef[1] * sgn > 0 or coef[2] * sgn > 0:  # not curved the right way: keep the sample
        return None
    return xp, float(coef[0])


def _start(ta, ya, peaks: DecayPeaks) -> int:
    """Index (into the peaks) of the first extremum after the sample of largest |theta - median|."""
    i_max = int(np.argmax(np.abs(ya - np.median(ya))))
    after = np.nonzero(peaks.index > i_max)[0]
    return int(after[0]) if after.size else peaks.n


# ----------------------------------------------------------------------------- peak-based estimator


@dataclass(frozen=True, kw_only=True)
class PeakDecayFit:
    """Free-decay parameters estimated from the extrema alone (independent of :func:`fit_free_decay`).

    Attributes
    ----------
    law : str
        "viscous", "coulomb" or "combined".
    omega_n : float
        Natural angular frequency (rad/s).
    zeta : float
        Damping ratio (0 for "coulomb").
    friction : float
        Coulomb friction angle Delta (rad; 0 for "viscous").
    offset : float
        Resting angle c (rad).
    stderr : dict
        Standard errors of the four, keyed "omega_n", "zeta", "friction", "offset" (0 when fixed).
    n_peaks : int
        Number of extrema used.
    """

    law: str
    omega_n: float
    zeta: float
    friction: float
    offset: float
    stderr: dict = field(repr=False)
    n_peaks: int


def _ols(X, y):
    beta, *_ = np.linalg.lstsq(X, y, rcond=None)
    r = y - X @ beta
    dof = max(1, y.size - X.shape[1])
    s2 = float(r @ r) / dof
    cov = s2 * np.linalg.pinv(X.T @ X)
    return beta, cov


def peak_decay_fit(t, theta, law: str = "combined") -> PeakDecayFit:
    r"""Estimate omega_n, zeta, Delta and the offset from the extrema only (log decrement and peak line).

    The extrema after the largest excursion (see
    :func:`~vibration.physics.lab.decay.fit_free_decay`) are located with
    :func:`free_decay_peaks`, and used until the swing to the next extremum falls below
    :data:`MIN_SWING_FRACTION` (0.2) of the first swing: near the stop a real wheel's half period
    shortens and the last few extrema do not follow the model. Their times give the half period
    :math:`\pi/\omega_d` by a straight-line fit against their count; their angles obey the
    recursion of :mod:`vibration.physics.lab.decay`, written
    linearly as :math:`\theta_{k+1} = -q\theta_k + (1+q)\theta_0 + \sigma_k(1+q)\theta_f` with
    :math:`\sigma_k = \mathrm{sgn}(\theta_k - c)` the known alternating sign, which is solved by
    ordinary least squares (``q = 1`` for "coulomb", no :math:`\sigma` term for "viscous"). Standard
    errors by the delta method from the two regressions. The regression is not constrained: with
    little viscous damping ``q`` may come out above 1, i.e. a slightly negative zeta, which then
    means "zero within its error". This is the classical peak analysis (log
    decrement for viscous, linear envelope for Coulomb friction), used to cross-check the
    whole-trace fit.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing.
    theta : array_like
        Angles (rad).
    law : {"viscous", "coulomb", "combined"}
        Friction law.

    Returns
    -------
    PeakDecayFit
        omega_n in rad/s, friction and offset in rad.

    Examples
    --------
    >>> import numpy as np
    >>> from vibration.physics.lab.decay import free_decay_response
    >>> t = np.arange(0.0, 12.0, 0.01)
    >>> y = free_decay_response(t, 4.5, 0.02, friction=0.03, offset=0.1, theta0=1.0)
    >>> f = peak_decay_fit(t, y)
    >>> round(f.omega_n, 3), round(f.zeta, 4), round(f.friction, 4), round(f.offset, 4)
    (4.5, 0.02, 0.03, 0.1)
    """
    if law not in LAWS:
        raise ParameterError(f"law = {law!r} is out of range: allowed one of {LAWS}")
    ta, ya = time_and_signal(t, theta, t_name="t", y_name="theta", y_unit="rad")
    tp, yp, sp = _used_extrema(ta, ya)
    wd, s_wd = _damped_frequency(tp)
    x, y1, sig = yp[:-1], yp[1:], sp[:-1].astype(float)
    if law == "coulomb":
        zeta, s_z, c, s_c, d, s_d = _coulomb_recursion(x, y1, sig)
    else:
        zeta, s_z, c, s_c, d, s_d = _decay_ratio_recursion(x, y1, sig, law)
    root = math.sqrt(1.0 - zeta * zeta)
    omega_n = wd / root
    s_w = math.hypot(s_wd / root, wd * zeta / root**3 * s_z)
    return PeakDecayFit(
        law=law,
        omega_n=float(omega_n),
        zeta=float(zeta),
        friction=float(d),
        offset=float(c),
        stderr={"omega_n": s_w, "zeta": float(s_z), "friction": float(s_d), "offset": float(s_c)},
        n_peaks=int(tp.size),
    )


def _used_extrema(ta, ya):
    """Times, angles and signs of the extrema :func:`peak_decay_fit` uses (at least ``MIN_HALF_PERIODS + 1``)."""
    peaks = _peaks(ta, ya)
    k0 = _start(ta, ya, peaks)
    tp, yp, sp = peaks.t[k0:], peaks.theta[k0:], peaks.sign[k0:]
    if tp.size >= 2:
        swing = np.abs(np.diff(yp))
        small = np.nonzero(swing < MIN_SWING_FRACTION * swing[0])[0]
        if small.size:
            m = int(small[0]) + 1
            tp, yp, sp = tp[:m], yp[:m], sp[:m]
    need = MIN_HALF_PERIODS + 1
    if tp.size < need:
        raise ParameterError(
            f"theta has {max(0, tp.size - 1)} half periods after its largest excursion which is out of range: "
            f"allowed at least {MIN_HALF_PERIODS} (the fit needs {need} extrema)"
        )
    return tp, yp, sp


def _damped_frequency(tp):
    """omega_d (rad/s) and its standard error from the line through the extrema's times against their count."""
    kk = np.arange(tp.size, dtype=float)
    (_, half), cov_t = _ols(np.column_stack([np.ones_like(kk), kk]), tp)
    wd = math.pi / half
    return wd, wd / half * math.sqrt(cov_t[1, 1])


def _coulomb_recursion(x, y1, sig):
    """``(zeta, s_zeta, c, s_c, Delta, s_Delta)`` of the Coulomb recursion (q = 1): ``x + y1 = 2 c + 2 Delta sig``."""
    beta, cov = _ols(np.column_stack([np.ones_like(x), sig]), x + y1)
    c, d = beta / 2.0
    s_c, s_d = math.sqrt(cov[0, 0]) / 2.0, math.sqrt(cov[1, 1]) / 2.0
    zeta = s_z = 0.0
    return zeta, s_z, c, s_c, d, s_d


def _decay_ratio_recursion(x, y1, sig, law):
    """``(zeta, s_zeta, c, s_c, Delta, s_Delta)`` of the recursion ``y1 = -q x + (1 + q) c [+ (1 + q) Delta sig]``."""
    cols = [-x, np.ones_like(x)] + ([sig] if law == "combined" else [])
    beta, cov = _ols(np.column_stack(cols), y1)
    qv = float(beta[0])
    if not 0.0 < qv < 2.0:
        raise ParameterError(
            f"theta: the extrema give a decay ratio q = {qv!r} which is out of range: allowed 0 < q < 2 (not a "
            "free decay)"
        )
    lq = math.log(qv)
    zeta = -lq / math.hypot(math.pi, lq)
    dz_dq = (math.pi**2 / math.hypot(math.pi, lq) ** 3) * (-1.0 / qv)
    s_z = abs(dz_dq) * math.sqrt(cov[0, 0])
    c, s_c = _over_one_plus_q(beta, cov, qv, 1)
    d, s_d = _over_one_plus_q(beta, cov, qv, 2) if law == "combined" else (0.0, 0.0)
    return zeta, s_z, c, s_c, d, s_d


def _over_one_plus_q(beta, cov, qv, j):
    """``beta[j] / (1 + q)`` and its standard error (delta method with the full covariance)."""
    b = float(beta[j])
    g = np.zeros(len(beta))
    g[0], g[j] = -b / (1 + qv) ** 2, 1.0 / (1 + qv)
    return b / (1 + qv), math.sqrt(float(g @ cov @ g))


def half_period_losses(peaks: DecayPeaks, offset: float) -> tuple[np.ndarray, np.ndarray]:
    """Amplitude and amplitude loss per half period, from consecutive extrema.

    Parameters
    ----------
    peaks : DecayPeaks
        Extrema from :func:`free_decay_peaks`.
    offset : float
        Resting angle c (rad) the amplitudes are measured from.

    Returns
    -------
    amplitude, loss : numpy.ndarray
        ``|theta_k - c|`` and ``|theta_k - c| - |theta_{k+1} - c|`` (rad), one per half period.
        For the model of the module the loss is ``(1 - q) amplitude + (1 + q) Delta``: a line through
        the origin for viscous damping, the constant ``2 Delta`` for Coulomb friction.

    Examples
    --------
    >>> import numpy as np
    >>> from vibration.physics.lab.decay import free_decay_response
    >>> t = np.arange(0.0, 6.0, 0.01)
    >>> p = free_decay_peaks(t, free_decay_response(t, 4.5, 0.0, friction=0.05, theta0=1.0))
    >>> a, loss = half_period_losses(p, 0.0)
    >>> bool(np.allclose(loss, 0.1, atol=2e-3))
    True
    """
    if not isinstance(peaks, DecayPeaks):
        raise ParameterError(f"peaks = {peaks!r} is not a DecayPeaks: allowed the result of free_decay_peaks")
    c = check_real("offset", offset, low=-1e6, high=1e6, unit="rad")
    a = np.abs(peaks.theta - c)
    return a[:-1].copy(), a[:-1] - a[1:]
