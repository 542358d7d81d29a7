"""Input shaping: ZV and ZVD shapers, their residual vibration, shaped moves and the ringing amplitude."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_array, check_choice, check_oscillator
from ..exact import exact_response
from ..model import Oscillator, ParameterError, SineForce, check_real
from ._common import _finite, _grid

#: Most impulses a :class:`Shaper` may have.
SHAPER_IMPULSES_MAX = 64


@dataclass(frozen=True, kw_only=True)
class Shaper:
    """Input shaper: impulses of ``amplitudes`` (summing to 1) at ``times`` (s)."""

    times: np.ndarray  # impulse times, s (first 0)
    amplitudes: np.ndarray  # impulse amplitudes, 1 (sum 1)
    omega_n: float  # design natural frequency, rad/s
    zeta: float  # design damping ratio, 1
    kind: str  # "ZV" or "ZVD"

    def __post_init__(self) -> None:
        t = check_array(
            "times", self.times, low=0.0, ndim=(1,), max_size=SHAPER_IMPULSES_MAX, increasing=True, unit="s"
        )
        if t[0] != 0.0:
            raise ParameterError(f"times = {t.tolist()!r} s starts at {t[0]!r} s: allowed a first impulse at 0 s")
        a = check_array("amplitudes", self.amplitudes, ndim=(1,), max_size=SHAPER_IMPULSES_MAX)
        if a.size != t.size:
            raise ParameterError(
                f"amplitudes has {a.size} values and times {t.size}: allowed one amplitude per impulse time"
            )
        if abs(float(a.sum()) - 1.0) > 1e-9:
            raise ParameterError(
                f"amplitudes = {a.tolist()!r} sum to {float(a.sum())!r}: allowed amplitudes summing to 1 (within 1e-9)"
            )
        t.setflags(write=False)
        a.setflags(write=False)
        object.__setattr__(self, "times", t)
        object.__setattr__(self, "amplitudes", a)
        object.__setattr__(self, "omega_n", check_real("omega_n", self.omega_n, low=0.0, low_open=True, unit="rad/s"))
        object.__setattr__(self, "zeta", check_real("zeta", self.zeta, low=0.0, high=1.0, unit=""))
        object.__setattr__(self, "kind", check_choice("kind", self.kind, ("ZV", "ZVD")))

    @property
    def duration(self) -> float:
        """Time of the last impulse (the delay the shaper adds to a move), s."""
        return float(self.times[-1])


def _underdamped(osc) -> tuple[float, float, float]:
    check_oscillator(osc)
    zeta = osc.damping_ratio
    if not 0.0 <= zeta < 1.0:
        raise ParameterError(
            f"osc.c = {osc.c!r} N s/m gives zeta = {zeta!r}: allowed an underdamped oscillator, 0 <= zeta < 1"
        )
    return zeta, osc.natural_frequency, osc.damped_natural_frequency


def zv_shaper(osc: Oscillator) -> Shaper:
    """Zero-vibration shaper: ``[1, K] / (1 + K)`` at ``[0, T_d / 2]``, ``K = exp(-zeta pi / sqrt(1 - zeta^2))``.

    Singer and Seering (1990), J. Dyn. Syst. Meas. Control 112:76-82. ``T_d = 2 pi / omega_d`` (s).

    Examples
    --------
    >>> s = zv_shaper(Oscillator(m=1.0, c=0.0, k=4.0 * np.pi**2))       # 1 Hz, undamped
    >>> s.times, s.amplitudes
    (array([0. , 0.5]), array([0.5, 0.5]))
    """
    zeta, wn, wd = _underdamped(osc)
    K = math.exp(-zeta * math.pi / math.sqrt(1.0 - zeta * zeta))
    return Shaper(
        times=np.array([0.0, math.pi / wd]), amplitudes=np.array([1.0, K]) / (1.0 + K), omega_n=wn, zeta=zeta, kind="ZV"
    )


def zvd_shaper(osc: Oscillator) -> Shaper:
    """Zero-vibration-derivative shaper: ``[1, 2K, K^2] / (1 + K)^2`` at ``[0, T_d/2, T_d]``.

    Singer and Seering (1990). Zero residual vibration and zero slope against frequency
    error at the design point, at the cost of twice the ZV delay.

    Examples
    --------
    >>> s = zvd_shaper(Oscillator(m=1.0, c=0.0, k=4.0 * np.pi**2))
    >>> s.times, s.amplitudes
    (array([0. , 0.5, 1. ]), array([0.25, 0.5 , 0.25]))
    """
    zeta, wn, wd = _underdamped(osc)
    K = math.exp(-zeta * math.pi / math.sqrt(1.0 - zeta * zeta))
    amps = np.array([1.0, 2.0 * K, K * K]) / (1.0 + K) ** 2
    return Shaper(
        times=np.array([0.0, math.pi / wd, 2.0 * math.pi / wd]), amplitudes=amps, omega_n=wn, zeta=zeta, kind="ZVD"
    )


def _check_shaper(shaper) -> Shaper:
    if shaper is not None and not isinstance(shaper, Shaper):
        raise ParameterError(f"shaper = {shaper!r} is not a Shaper: allowed None, zv_shaper(osc) or zvd_shaper(osc)")
    if shaper is not None:
        times = check_array("shaper.times", shaper.times, low=0.0, ndim=(1,), max_size=100, unit="s")
        amps = check_array("shaper.amplitudes", shaper.amplitudes, ndim=(1,), max_size=100)
        if times.shape != amps.shape:
            raise ParameterError(f"shaper has {times.size} times and {amps.size} amplitudes: allowed as many of each")
    return shaper


def shaper_residual(shaper: Shaper | None, osc: Oscillator) -> float:
    """Residual vibration of a shaped step over that of the unshaped step, on the oscillator ``osc``, 1.

    ``V = exp(-sigma t_N) sqrt(C^2 + S^2)`` with ``C = sum A_i exp(sigma t_i) cos(omega_d t_i)``,
    ``S`` the same with ``sin`` (Singer and Seering 1990): the ringing just after the last
    impulse over the ringing of the plain step just after its impulse. 1 without shaper, 0 when the
    shaper was designed for ``osc``. ``osc`` may differ from the design oscillator
    (sensitivity to modelling error); it must be underdamped.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> shaper_residual(zv_shaper(osc), osc) < 1e-15
    True
    >>> round(shaper_residual(zv_shaper(osc), Oscillator(m=1.0, c=0.5, k=20.0 * 1.1**2)), 4)    # 10 % frequency error
    0.1431
    """
    _check_shaper(shaper)
    zeta, wn, wd = _underdamped(osc)
    if shaper is None:
        return 1.0
    sigma = zeta * wn
    tn = shaper.times[-1]
    e = shaper.amplitudes * np.exp(-sigma * (tn - shaper.times))
    return float(math.hypot(np.sum(e * np.cos(wd * shaper.times)), np.sum(e * np.sin(wd * shaper.times))))


def _step_response(osc: Oscillator, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Response (m, m/s) to a unit-displacement step command ``F = k H(t)`` from rest: ``1 + free(-1, 0)``."""
    free = exact_response(osc, SineForce(F0=0.0, omega=0.0), t, x0=-1.0, v0=0.0)
    return 1.0 + free.x, free.v


def shaped_move(
    osc: Oscillator, shaper: Shaper | None, distance: float, *, t_end: float = 10.0, n_points: int = 2001
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Exact point-to-point move: force command ``k D sum A_i H(t - t_i)`` from rest.

    The command moves the static equilibrium from 0 to ``D``; unshaped it is one step. The
    response is the superposition of exact step responses (``exact_response`` free
    response), so it is exact to rounding for every regime.

    Parameters
    ----------
    osc : Oscillator
        The real oscillator, m (kg), c (N s/m), k (N/m).
    shaper : Shaper or None
        Shaper (designed on any model) or None for the plain step.
    distance : float
        Move distance D, m.
    t_end, n_points : float, int
        Window (s) and samples.

    Returns
    -------
    (t, x, v, command)
        s, m, m/s and the command force, N.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> t, x, v, u = shaped_move(osc, zv_shaper(osc), 0.1, t_end=20.0, n_points=3)
    >>> np.round(x, 6)                                     # m
    array([0. , 0.1, 0.1])
    """
    check_oscillator(osc)
    _check_shaper(shaper)
    D = check_real("distance", distance, unit="m")
    t = _grid(t_end, n_points)
    times, amps = (np.array([0.0]), np.array([1.0])) if shaper is None else (shaper.times, shaper.amplitudes)
    x = np.zeros_like(t)
    v = np.zeros_like(t)
    u = np.zeros_like(t)
    for ti, ai in zip(times, amps, strict=True):
        on = t >= ti
        xs, vs = _step_response(osc, t[on] - ti)
        x[on] += ai * D * xs
        v[on] += ai * D * vs
        u[on] += ai * D * osc.k
    for name, a in (("x", x), ("v", v), ("command", u)):
        if not np.all(np.isfinite(a)):
            raise ParameterError(f"distance = {D!r} m: the move's {name} overflows; allowed a smaller distance")
    return t, x, v, u


def residual_amplitude(osc: Oscillator, t, x, *, v, target: float) -> np.ndarray:
    """Amplitude of the ringing about ``target`` (m) at each sample, m: ``|(x - D) + i (v + sigma (x - D)) / omega_d|``.

    For a free underdamped oscillation this is its envelope ``a exp(-sigma t)``.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.0, k=4.0)
    >>> float(residual_amplitude(osc, 0.0, 1.0, v=2.0, target=0.0)[0])     # sqrt(1 + (2/2)^2)
    1.4142135623730951
    """
    zeta, wn, wd = _underdamped(osc)
    sigma = zeta * wn
    target = check_real("target", target, unit="m")
    tt = np.atleast_1d(check_array("t", t, unit="s"))
    xx = np.atleast_1d(check_array("x", x, unit="m"))
    vv = np.atleast_1d(check_array("v", v, unit="m/s"))
    if not tt.shape == xx.shape == vv.shape:
        raise ParameterError(f"t, x, v have shapes {tt.shape}, {xx.shape}, {vv.shape}: allowed one and the same shape")
    d = xx - target
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.hypot(d, (vv + sigma * d) / wd)
    return _finite("x, v", out, "the ringing amplitude")


def insensitivity_band(shaper: Shaper, osc: Oscillator, level: float = 0.05) -> tuple[float, float]:
    """Band of natural-frequency ratios ``q = omega_real / omega_model`` around 1 where ``V <= level``, 1.

    The real oscillator is ``osc`` with ``k`` scaled by ``q^2`` (same m and c). The edges are the
    roots of ``V(q) = level`` nearest to 1 on each side, bracketed on a grid of step 0.001 in q
    that walks out from 1 and solved by Brent's method to 1e-12 in q (not read off the grid).

    Parameters
    ----------
    shaper : Shaper
        ZV or ZVD shaper (designed on ``osc`` or not).
    osc : Oscillator
        The model; the real oscillators scale its k.
    level : float
        Largest tolerated residual vibration ratio, 1 (0 < level < 1).

    Returns
    -------
    (float, float)
        Lower and upper edge, 1 (nan where V stays below ``level`` down to q = 0.05 or up to q = 20).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.0, k=20.0)                       # undamped: V = |cos(pi q / 2)| for ZV
    >>> lo, hi = insensitivity_band(zv_shaper(osc), osc)
    >>> round(lo, 6), round(float(2 * np.arccos(0.05) / np.pi), 6)
    (0.968156, 0.968156)
    """
    from scipy.optimize import brentq

    if not isinstance(shaper, Shaper):
        raise ParameterError(f"shaper = {shaper!r} is not a Shaper: allowed zv_shaper(osc) or zvd_shaper(osc)")
    _underdamped(osc)
    level = check_real("level", level, low=0.0, high=1.0, low_open=True)
    m, c, k = osc.m, osc.c, osc.k

    def g(q: float) -> float:
        return shaper_residual(shaper, Oscillator(m=m, c=c, k=k * q * q)) - level

    if not g(1.0) < 0.0:
        raise ParameterError(
            f"level = {level!r}: the shaper's residual at the model frequency is {g(1.0) + level:.3g}; "
            "allowed a level above it"
        )
    edges = []
    for stop, step in ((0.05, -1e-3), (20.0, 1e-3)):
        q0, q1, out = 1.0, 1.0 + step, math.nan
        while (q1 - stop) * step <= 0.0:
            try:
                g1 = g(q1)
            except ParameterError:  # the real oscillator stops being underdamped: V undefined beyond
                break
            if g1 >= 0.0:
                out = brentq(g, q0, q1, xtol=1e-12, rtol=1e-14)
                break
            q0, q1 = q1, q1 + step
        edges.append(out)
    return edges[0], edges[1]
