"""Loads as records: harmonic with a phase, rotating unbalance, base motion, a step and a sampled input.

Each record says what drives the oscillator ``m x'' + c x' + k x = F(t)``; :func:`vibration.exact_response`,
:func:`vibration.simulate`, :func:`vibration.steady_state` and :func:`frequency_response` take any of them
(and the paper's :class:`~vibration.SineForce`, which is ``Harmonic`` with zero phase).

* :class:`Harmonic` ``F(t) = F0 sin(omega t + phase)``.
* :class:`Unbalance` a rotating unbalance ``m_e`` at eccentricity ``e``: ``F(t) = m_e e omega^2 sin(omega t)``.
* :class:`BaseMotion` the support moves as ``y(t) = Y sin(omega t + phase)``; the spring and damper connect the
  mass to the support, so ``m x'' + c (x' - y') + k (x - y) = 0`` with ``x`` the mass's absolute displacement,
  that is the force ``k y + c y'`` on a fixed-support oscillator. ``BaseMotion.from_acceleration(A=, omega=)``
  takes the support's acceleration amplitude instead (``Y = A / omega^2``).
* :class:`Step` ``F(t) = F0`` for ``t >= t0``, 0 before.
* :class:`Sampled` an arbitrary force given at sample times, linear between them (a first-order hold, as
  ``scipy.signal.lsim`` and python-control's ``forced_response`` take it).

The exact responses are closed forms: the harmonic loads from the paper's sine response and its derivative
(``x_cos = v_sin / omega`` is the response to ``cos omega t`` from rest), the step from the free response, the
sampled input from the matrix exponential of the state space over each interval (exact for a force linear
between samples).

Examples
--------
A washing-machine drum of 40 kg on its suspension, 0.05 kg m of unbalance: the amplitude peaks above omega_n,
at ``omega_n / sqrt(1 - 2 zeta^2)``.

>>> from vibration import Oscillator
>>> drum = Oscillator.from_modal(m=40.0, omega_n=2 * math.pi * 6.0, zeta=0.1)
>>> p = peak_response(drum, Unbalance(m_e=0.05, e=1.0, omega=1.0))
>>> round(p.omega / drum.natural_frequency, 4), round(1 / math.sqrt(1 - 2 * 0.1**2), 4)
(1.0102, 1.0102)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .checks import like_input
from .model import N_POINTS_MAX, Oscillator, ParameterError, SineForce, check_real

#: Most distinct interval lengths a :class:`Sampled` response takes a matrix exponential for.
MAX_STEP_LENGTHS = 100_000


@dataclass(frozen=True, kw_only=True)
class Harmonic:
    """Harmonic force ``F(t) = F0 sin(omega t + phase)``.

    >>> Harmonic(F0=2.0, omega=3.0, phase=math.pi / 2)(0.0)       # N
    2.0
    """

    F0: float  # force amplitude, N; >= 0
    omega: float  # angular frequency, rad/s; >= 0
    phase: float = 0.0  # phase of the force at t = 0, rad

    def __post_init__(self) -> None:
        object.__setattr__(self, "F0", check_real("F0", self.F0, low=0.0, unit="N"))
        object.__setattr__(self, "omega", check_real("omega", self.omega, low=0.0, unit="rad/s"))
        object.__setattr__(self, "phase", check_real("phase", self.phase, unit="rad"))

    def __call__(self, t):
        """Force at time(s) ``t`` (s), N."""
        return like_input(self.F0 * np.sin(self.omega * np.asarray(t, dtype=float) + self.phase), t)

    def __repr__(self) -> str:
        return f"Harmonic(F0={self.F0!r} N, omega={self.omega!r} rad/s, phase={self.phase!r} rad)"


@dataclass(frozen=True, kw_only=True)
class Unbalance:
    """Rotating unbalance: mass ``m_e`` at radius ``e`` turning at ``omega``, ``F(t) = m_e e omega^2 sin(omega t)``.

    >>> round(Unbalance(m_e=0.1, e=0.2, omega=10.0).F0, 12)         # N
    2.0
    """

    m_e: float  # unbalanced mass, kg; >= 0
    e: float  # its eccentricity (radius), m; >= 0
    omega: float  # rotation speed, rad/s; >= 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "m_e", check_real("m_e", self.m_e, low=0.0, unit="kg"))
        object.__setattr__(self, "e", check_real("e", self.e, low=0.0, unit="m"))
        object.__setattr__(self, "omega", check_real("omega", self.omega, low=0.0, unit="rad/s"))

    @property
    def F0(self) -> float:
        """Force amplitude at this speed, ``m_e e omega^2``, N."""
        return self.m_e * self.e * self.omega**2

    def __call__(self, t):
        """Force at time(s) ``t`` (s), N."""
        return like_input(self.F0 * np.sin(self.omega * np.asarray(t, dtype=float)), t)

    def __repr__(self) -> str:
        return f"Unbalance(m_e={self.m_e!r} kg, e={self.e!r} m, omega={self.omega!r} rad/s)"


@dataclass(frozen=True, kw_only=True)
class BaseMotion:
    """The support moves as ``y(t) = Y sin(omega t + phase)``; x is the mass's absolute displacement.

    >>> BaseMotion.from_acceleration(A=9.0, omega=3.0).Y      # m
    1.0
    """

    Y: float  # support displacement amplitude, m; >= 0
    omega: float  # angular frequency, rad/s; >= 0
    phase: float = 0.0  # phase of the support's motion at t = 0, rad

    def __post_init__(self) -> None:
        object.__setattr__(self, "Y", check_real("Y", self.Y, low=0.0, unit="m"))
        object.__setattr__(self, "omega", check_real("omega", self.omega, low=0.0, unit="rad/s"))
        object.__setattr__(self, "phase", check_real("phase", self.phase, unit="rad"))

    @classmethod
    def from_acceleration(cls, *, A: float, omega: float, phase: float = 0.0) -> BaseMotion:
        """The support's motion from its acceleration amplitude ``A`` (m/s^2): ``Y = A / omega^2``."""
        A = check_real("A", A, low=0.0, unit="m/s^2")
        omega = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
        return cls(Y=A / omega**2, omega=omega, phase=phase)

    @property
    def A(self) -> float:
        """Acceleration amplitude of the support, ``Y omega^2``, m/s^2."""
        return self.Y * self.omega**2

    def __call__(self, t):
        """Support displacement y at time(s) ``t`` (s), m."""
        return like_input(self.Y * np.sin(self.omega * np.asarray(t, dtype=float) + self.phase), t)

    def __repr__(self) -> str:
        return f"BaseMotion(Y={self.Y!r} m, omega={self.omega!r} rad/s, phase={self.phase!r} rad)"


@dataclass(frozen=True, kw_only=True)
class Step:
    """Step force ``F(t) = F0`` for ``t >= t0`` and 0 before.

    >>> Step(F0=3.0, t0=1.0)([0.5, 1.0])      # N
    array([0., 3.])
    """

    F0: float  # step height, N; any sign
    t0: float = 0.0  # time of the step, s; >= 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "F0", check_real("F0", self.F0, unit="N"))
        object.__setattr__(self, "t0", check_real("t0", self.t0, low=0.0, unit="s"))

    def __call__(self, t):
        """Force at time(s) ``t`` (s), N."""
        tt = np.asarray(t, dtype=float)
        return like_input(np.where(tt >= self.t0, self.F0, 0.0), t)

    def __repr__(self) -> str:
        return f"Step(F0={self.F0!r} N, t0={self.t0!r} s)"


@dataclass(frozen=True, kw_only=True, eq=False)
class Sampled:
    """A force sampled at times ``t`` (s, from 0, strictly increasing), linear between samples, N.

    >>> f = Sampled(t=[0.0, 1.0, 2.0], F=[0.0, 2.0, 0.0])
    >>> float(f(0.5)), f.t_end                # N, s
    (1.0, 2.0)
    """

    t: np.ndarray = field(repr=False)  # sample times, s; t[0] = 0, strictly increasing
    F: np.ndarray = field(repr=False)  # force at each sample, N; finite

    def __post_init__(self) -> None:
        t = _float_array("t", self.t, "s")
        F = _float_array("F", self.F, "N")
        if t.ndim != 1 or t.size < 2 or t.size > N_POINTS_MAX:
            raise ParameterError(f"t has shape {t.shape}: allowed 2 to {N_POINTS_MAX} sample times in s")
        if F.shape != t.shape:
            raise ParameterError(
                f"t has shape {t.shape} and F has shape {F.shape}: allowed one force F in N per sample time t in s"
            )
        if t[0] != 0.0:
            raise ParameterError(f"t[0] = {float(t[0])!r} s: allowed t[0] = 0 s (the response starts at t = 0)")
        steps = np.diff(t)
        if not np.all(steps > 0):
            i = int(np.argmin(steps > 0))
            raise ParameterError(
                f"t[{i + 1}] = {float(t[i + 1])!r} s is not after t[{i}] = {float(t[i])!r} s: allowed increasing times"
            )
        for name, a in (("t", t), ("F", F)):
            a.setflags(write=False)
            object.__setattr__(self, name, a)

    @property
    def t_end(self) -> float:
        """Last sample time, s: the input is not defined beyond it."""
        return float(self.t[-1])

    def __call__(self, t):
        """Force at time(s) ``t`` (s), N (linear between samples)."""
        return like_input(np.interp(np.asarray(t, dtype=float), self.t, self.F), t)

    def __repr__(self) -> str:
        return f"Sampled({self.t.size} samples over 0-{self.t_end:g} s, |F| <= {float(np.max(np.abs(self.F))):g} N)"


#: Every load record :func:`vibration.exact_response` and :func:`vibration.simulate` take.
LOADS = (SineForce, Harmonic, Unbalance, BaseMotion, Step, Sampled)
HARMONIC_LOADS = (SineForce, Harmonic, Unbalance, BaseMotion)


def check_load(load, name: str = "force"):
    """Return ``load`` when it is one of :data:`LOADS`, or raise :class:`ParameterError`."""
    if not isinstance(load, LOADS):
        allowed = ", ".join(c.__name__ for c in LOADS)
        raise ParameterError(f"{name} = {load!r:.80} is not a load record: allowed one of {allowed}")
    return load


def _float_array(name: str, values, unit: str) -> np.ndarray:
    try:
        raw = np.asarray(values)
        if raw.dtype.kind not in "iuf":
            raise TypeError
        a = np.array(raw, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(
            f"{name} = {values!r:.60} is not an array of numbers: allowed finite values in {unit}"
        ) from None
    if not np.all(np.isfinite(a)):
        raise ParameterError(f"{name} contains {float(a[~np.isfinite(a)][0])!r}: allowed finite values in {unit}")
    return a


def equivalent_harmonic(osc: Oscillator, load) -> tuple[float, float, float]:
    """The force on the mass of a harmonic load as ``(amplitude N, omega rad/s, phase rad)``.

    ``F(t) = amplitude sin(omega t + phase)``: for base motion the force ``k y + c y'`` the support passes
    through spring and damper, ``Y |k + i c omega|`` at the phase lead ``atan2(c omega, k)``.
    """
    if isinstance(load, SineForce):
        return load.F0, load.omega, 0.0
    if isinstance(load, Harmonic):
        return load.F0, load.omega, load.phase
    if isinstance(load, Unbalance):
        return load.F0, load.omega, 0.0
    if isinstance(load, BaseMotion):
        w = load.omega
        return load.Y * math.hypot(osc.k, osc.c * w), w, load.phase + math.atan2(osc.c * w, osc.k)
    raise ParameterError(
        f"force = {load!r:.80} is not a harmonic load: allowed SineForce, Harmonic, Unbalance, BaseMotion"
    )


def load_function(osc: Oscillator, load):
    """The force on the mass as a function of one time (s), N, for the numerical integrators."""
    if isinstance(load, HARMONIC_LOADS):
        amp, w, ph = equivalent_harmonic(osc, load)
        sin = math.sin
        return lambda t: amp * sin(w * t + ph)
    if isinstance(load, Step):
        F0, t0 = load.F0, load.t0
        return lambda t: F0 if t >= t0 else 0.0
    ts, Fs = load.t, load.F
    return lambda t: float(np.interp(t, ts, Fs))


def fastest_rate(load) -> float:
    """The fastest angular rate of a load, rad/s: its frequency, or pi over the shortest sample spacing."""
    if isinstance(load, Sampled):
        return math.pi / float(np.min(np.diff(load.t)))
    return getattr(load, "omega", 0.0)


# --- exact responses -------------------------------------------------------------------------------------------


def exact_load_response(osc: Oscillator, load, t: np.ndarray, *, x0: float, v0: float):
    """The exact ``(x, v)`` arrays of :func:`vibration.exact_response` for any load of :data:`LOADS`."""
    from .exact import exact_response

    rest = SineForce(F0=0.0, omega=0.0)
    free = exact_response(osc, rest, t, x0=x0, v0=v0)
    if isinstance(load, HARMONIC_LOADS):
        fx, fv = _harmonic_from_rest(osc, *equivalent_harmonic(osc, load), t)
    elif isinstance(load, Step):
        fx, fv = _step_from_rest(osc, load.F0, load.t0, t)
    else:
        return _sampled(osc, load, t, x0, v0)
    return free.x + fx, free.v + fv


def _harmonic_from_rest(osc: Oscillator, amp: float, w: float, phase: float, t: np.ndarray):
    """Response from rest to ``amp sin(w t + phase)``: sine and cosine parts from the exact sine response."""
    from .exact import exact_response

    if amp == 0.0:
        return np.zeros_like(t), np.zeros_like(t)
    if w == 0.0:  # a constant force amp sin(phase) from t = 0
        return _step_from_rest(osc, amp * math.sin(phase), 0.0, t)
    unit = exact_response(osc, SineForce(F0=1.0, omega=w), t)
    a = (np.sin(w * t) - osc.c * unit.v - osc.k * unit.x) / osc.m  # acceleration of the unit sine response
    cs, sn = math.cos(phase), math.sin(phase)
    # x_cos = v_sin / w: differentiating the sine response from rest gives the response to w cos(w t) from rest
    return amp * (cs * unit.x + sn * unit.v / w), amp * (cs * unit.v + sn * a / w)


def _step_from_rest(osc: Oscillator, F0: float, t0: float, t: np.ndarray):
    """Response from rest to a step ``F0`` at ``t0``: ``(F0/k)(1 - phi(t - t0))``, phi the free decay from x = 1."""
    from .exact import exact_response

    x, v = np.zeros_like(t), np.zeros_like(t)
    on = t >= t0
    if F0 == 0.0 or not np.any(on):
        return x, v
    phi = exact_response(osc, SineForce(F0=0.0, omega=0.0), t[on] - t0, x0=1.0)
    x[on] = F0 / osc.k * (1.0 - phi.x)
    v[on] = -F0 / osc.k * phi.v
    return x, v


def _sampled(osc: Oscillator, load: Sampled, t: np.ndarray, x0: float, v0: float):
    """Exact response to a force linear between samples: the state space stepped by its matrix exponential."""
    from scipy.linalg import expm

    flat = np.atleast_1d(t)
    if flat.min() < 0.0 or flat.max() > load.t_end:
        bad = float(flat[(flat < 0.0) | (flat > load.t_end)][0])
        raise ParameterError(f"t contains {bad!r} s: allowed 0 <= t <= {load.t_end!r} s, the sampled input's span")
    grid = np.union1d(load.t, flat)
    if grid.size > N_POINTS_MAX:
        raise ParameterError(
            f"t has {flat.size} times: with the input's samples more than {N_POINTS_MAX}: allowed fewer"
        )
    F = np.interp(grid, load.t, load.F)
    h = np.diff(grid)
    lengths, which = np.unique(h, return_inverse=True)
    if lengths.size > MAX_STEP_LENGTHS:
        raise ParameterError(
            f"t and the input's sample times make {lengths.size} distinct intervals: allowed at most "
            f"{MAX_STEP_LENGTHS} (a uniform grid makes one)"
        )
    # [[A h, B h, 0], [0, 0, 1], [0, 0, 0]] -> Phi, Gamma1, Gamma2 (first-order hold; scipy.signal.lsim's form)
    M = np.zeros((lengths.size, 4, 4))
    M[:, 0, 1] = lengths
    M[:, 1, 0] = -osc.k / osc.m * lengths
    M[:, 1, 1] = -osc.c / osc.m * lengths
    M[:, 1, 2] = lengths / osc.m
    M[:, 2, 3] = 1.0
    E = expm(M)
    phi, g1, g2 = E[:, :2, :2], E[:, :2, 2], E[:, :2, 3]
    xs, vs = _march(phi[which], (g1 - g2)[which], g2[which], F, x0, v0)
    if not (np.all(np.isfinite(xs)) and np.all(np.isfinite(vs))):
        raise ParameterError("the response to the sampled input overflows the float range: allowed a shorter input")
    pos = np.searchsorted(grid, t)
    return xs[pos], vs[pos]


def _march(phi, g0, g1, F, x0, v0):
    """``y[j+1] = phi[j] y[j] + g0[j] F[j] + g1[j] F[j+1]`` from ``y[0] = (x0, v0)``."""
    n = F.size
    xs, vs = np.empty(n), np.empty(n)
    x, v = x0, v0
    xs[0], vs[0] = x, v
    p, a, b = phi.tolist(), g0.tolist(), g1.tolist()
    f = F.tolist()
    for j in range(n - 1):
        (p00, p01), (p10, p11) = p[j]
        x, v = (
            p00 * x + p01 * v + a[j][0] * f[j] + b[j][0] * f[j + 1],
            p10 * x + p11 * v + a[j][1] * f[j] + b[j][1] * f[j + 1],
        )
        xs[j + 1], vs[j + 1] = x, v
    return xs, vs


# --- the frequency domain --------------------------------------------------------------------------------------


@dataclass(frozen=True, kw_only=True, eq=False)
class FrequencyResponse:
    """Steady amplitude, phase and transmitted force of a harmonic load over a range of frequencies."""

    omega: np.ndarray = field(repr=False)  # forcing frequency, rad/s
    amplitude: np.ndarray = field(repr=False)  # steady displacement amplitude of the mass, m
    phase: np.ndarray = field(repr=False)  # lag of x behind the load (force, or the support's motion), rad
    transmitted: np.ndarray = field(repr=False)  # amplitude of the force passed to the support, N
    load: str  # "force", "unbalance" or "base motion"

    def __repr__(self) -> str:
        i = int(np.argmax(self.amplitude))
        return (
            f"FrequencyResponse({self.load}, {self.omega.size} frequencies over {self.omega[0]:g}-{self.omega[-1]:g} "
            f"rad/s, largest amplitude {self.amplitude[i]:.4g} m at {self.omega[i]:.4g} rad/s)"
        )

    def plot(self, ax=None):
        """A Bode plot: amplitude (m, logarithmic) and phase lag (degrees) against omega (rad/s); the two axes."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(2, 1, sharex=True, figsize=(6.0, 4.5), layout="constrained")
        top, bottom = ax
        top.loglog(self.omega, self.amplitude)
        top.set_ylabel("amplitude $X$ (m)")
        bottom.semilogx(self.omega, np.degrees(self.phase))
        bottom.set_ylabel(r"phase lag $\varphi$ (°)")
        bottom.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
        return ax


def _load_kind(load) -> str:
    return {Unbalance: "unbalance", BaseMotion: "base motion"}.get(type(load), "force")


def frequency_response(osc: Oscillator, load, omegas) -> FrequencyResponse:
    """Steady response to ``load`` with its frequency replaced by each of ``omegas`` (rad/s).

    The load's other fields stay: a force's F0, an unbalance's ``m_e e`` (so its force grows as omega^2), a base
    motion's Y. The transmitted force is ``|k + i c omega| X`` for a force or an unbalance on a fixed support, and
    ``m omega^2 X`` (the support's reaction, spring and damper together) for base motion.

    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> fr = frequency_response(osc, Harmonic(F0=5.0, omega=1.0), [3.0])
    >>> round(float(fr.amplitude[0]), 4)           # m, the paper's reference case
    0.4504
    """
    from .checks import check_oscillator
    from .frequency import _omegas

    check_oscillator(osc)
    if not isinstance(load, HARMONIC_LOADS):
        raise ParameterError(
            f"force = {load!r:.80} is not a harmonic load: allowed SineForce, Harmonic, Unbalance, BaseMotion"
        )
    w = np.atleast_1d(_omegas(omegas, scalar=True))
    kind = _load_kind(load)
    X, g = _phasors(osc, load, w)
    amplitude = np.abs(X)
    r = w / osc.natural_frequency
    with np.errstate(over="ignore", invalid="ignore"):
        stiff = osc.k * (r * r if kind == "base motion" else np.hypot(1.0, 2.0 * osc.damping_ratio * r))
        transmitted = stiff * amplitude
    _refuse_overflow(np.isfinite(g), amplitude, transmitted, w=w)
    lag = np.where(np.isfinite(g), -np.angle(np.where(np.isfinite(g), g, 1.0)), 0.5 * np.pi) + 0.0
    return FrequencyResponse(omega=w, amplitude=amplitude, phase=lag, transmitted=transmitted, load=kind)


def _refuse_overflow(resolvable: np.ndarray, *arrays: np.ndarray, w: np.ndarray) -> None:
    for a in arrays:
        bad = resolvable & ~np.isfinite(a)
        if np.any(bad):
            raise ParameterError(
                f"omegas contains {float(w[bad][0])!r} rad/s: the response there overflows the float range; "
                "allowed frequencies at which it stays finite"
            )


def _phasors(osc: Oscillator, load, w: np.ndarray):
    """``(X, g)``: the complex displacement amplitude X (m) and ``g``, x over the load's own phasor.

    ``g = 1 / D`` for a force or an unbalance (x over F/k), ``(1 + 2 i zeta r) / D`` for base motion (x over y),
    with ``D = 1 - r^2 + 2 i zeta r``; above resonance numerator and D are divided by r^2 so nothing overflows.
    ``g`` is infinite at undamped resonance.
    """
    kind = _load_kind(load)
    r = w / osc.natural_frequency
    z = osc.damping_ratio
    big = r > 1.0
    q = np.where(big, r, 1.0)  # the scale: r above resonance, 1 below
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        inv = 1.0 / (q * q)
        D = np.where(big, (inv - 1.0) + 2j * z / q, (1.0 - r) * (1.0 + r) + 2j * z * r)  # D / q^2
        if kind == "base motion":
            N = np.where(big, inv + 2j * z / q, 1.0 + 2j * z * r)  # (1 + 2 i zeta r) / q^2
            ref = load.Y
        elif kind == "unbalance":
            N = np.where(big, 1.0, r * r) + 0j  # r^2 / q^2
            ref = load.m_e * load.e / osc.m
        else:
            N = inv + 0j  # 1 / q^2
            ref = load.F0 / osc.k
        zero = D == 0
        safe = np.where(zero, 1.0, D)
        ratio = np.where(zero, complex(0.0, -math.inf), N / safe)  # x over ref
        # g: x over the load's own phasor (F/k for a force or an unbalance, y for base motion)
        g = np.where(zero, complex(0.0, -math.inf), inv / safe) if kind == "unbalance" else ratio
        X = ref * ratio if ref > 0 else np.zeros_like(ratio)
    return X, g


def steady_load(osc: Oscillator, load):
    """:func:`vibration.steady_state` of a harmonic load: ``x_ss = amplitude sin(omega t + load phase - phase)``.

    ``magnification`` is the amplitude over the reference: over ``F/k`` for a force or an unbalance, over the
    support's Y (the displacement transmissibility) for base motion; ``static_deflection`` is that reference, m.
    """
    from .exact import SteadyState

    if not isinstance(load, HARMONIC_LOADS):
        raise ParameterError(
            f"force = {load!r:.80} is not a harmonic load: allowed SineForce, Harmonic, Unbalance, BaseMotion"
        )
    w = np.array([load.omega])
    X, g = _phasors(osc, load, w)
    kind = _load_kind(load)
    ref = (
        load.Y
        if kind == "base motion"
        else (load.m_e * load.e * load.omega**2 if kind == "unbalance" else load.F0) / osc.k
    )
    mag = float(np.abs(g[0]))
    amp = float(np.abs(X[0]))
    if not (math.isfinite(ref) and (math.isfinite(amp) or math.isinf(mag))):
        raise ParameterError(
            f"omega = {load.omega!r} rad/s: the steady state overflows the float range; allowed a lower omega"
        )
    lag = 0.5 * math.pi if math.isinf(mag) else float(-np.angle(g[0]))
    return SteadyState(amplitude=amp, phase=lag, magnification=mag, velocity_amplitude=load.omega * amp,
                       static_deflection=ref)  # fmt: skip


@dataclass(frozen=True, kw_only=True)
class Peak:
    """The largest steady amplitude over all frequencies, and where it is."""

    omega: float  # frequency of the peak, rad/s (0: largest at rest; inf: approached as omega grows)
    amplitude: float  # its displacement amplitude, m (inf: undamped)

    def __repr__(self) -> str:
        return f"Peak(omega={self.omega:.6g} rad/s, amplitude={self.amplitude:.6g} m)"


def peak_response(osc: Oscillator, load) -> Peak:
    """Closed-form peak of :func:`frequency_response` for ``c >= 0``.

    * force: ``omega_n sqrt(1 - 2 zeta^2)`` for ``zeta < 1/sqrt 2`` (else at rest), ``X = (F0/k) / (2 zeta
      sqrt(1 - zeta^2))``;
    * unbalance: ``omega_n / sqrt(1 - 2 zeta^2)``, ``X = (m_e e / m) / (2 zeta sqrt(1 - zeta^2))``; for
      ``zeta >= 1/sqrt 2`` the amplitude rises to ``m_e e / m`` as omega grows (``omega = inf``);
    * base motion: ``omega_n sqrt(sqrt(1 + 8 zeta^2) - 1) / (2 zeta)``, ``X = Y T`` at that ratio.

    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> p = peak_response(osc, SineForce(F0=5.0, omega=1.0))
    >>> round(p.omega, 3), round(p.amplitude, 4)     # rad/s, m
    (4.458, 2.2396)
    """
    from .checks import check_oscillator

    check_oscillator(osc)
    if osc.c < 0.0:
        raise ParameterError(f"c = {osc.c!r} N s/m: allowed c >= 0 (an unstable oscillator has no steady state)")
    wn, z = osc.natural_frequency, osc.damping_ratio
    kind = _load_kind(load) if isinstance(load, HARMONIC_LOADS) else None
    if kind is None:
        raise ParameterError(
            f"force = {load!r:.80} is not a harmonic load: allowed SineForce, Harmonic, Unbalance, BaseMotion"
        )
    if z == 0.0:
        return Peak(omega=wn, amplitude=math.inf)
    q = 1.0 - 2.0 * z * z
    if kind == "base motion":
        w = wn * math.sqrt(math.sqrt(1.0 + 8.0 * z * z) - 1.0) / (2.0 * z)
    elif q <= 0.0:
        w = 0.0 if kind == "force" else math.inf
    else:
        w = wn * math.sqrt(q) if kind == "force" else wn / math.sqrt(q)
    if math.isinf(w):
        return Peak(omega=w, amplitude=load.m_e * load.e / osc.m)
    return Peak(omega=w, amplitude=float(frequency_response(osc, load, [w]).amplitude[0]))
