"""Model records and input validation.

The two records of the model are frozen dataclasses in SI units:
:class:`Oscillator` (mass, damping, stiffness) and :class:`SineForce`
(amplitude, angular frequency). Every derived quantity is a property, computed
from the three or two fields, never stored twice. Validation happens once, in
``__post_init__``, and every violation raises :class:`ParameterError` whose
message names the parameter, its value and the allowed range.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

#: Largest number of output samples :func:`vibration.simulate` will allocate.
N_POINTS_MAX = 2_000_000

#: |zeta - 1| at or below which the oscillator counts as critically damped.
CRITICAL_TOL = 1e-12

#: Range of the rates sqrt(k/m) and |c|/m (1/s) an Oscillator may have: their squares
#: and products with times stay finite, normal floats (1e150 squared is 1e300).
RATE_MIN, RATE_MAX = 1e-150, 1e150

REGIMES = ("undamped", "underdamped", "critically damped", "overdamped", "unstable")


class ParameterError(ValueError, TypeError):
    """A parameter is out of its allowed range or of the wrong type.

    Subclasses both :class:`ValueError` and :class:`TypeError` so that callers
    may catch either; the message always names the parameter, its value and
    what is allowed.
    """


def check_real(
    name: str,
    value,
    *,
    low: float | None = None,
    high: float | None = None,
    low_open: bool = False,
    unit: str = "",
) -> float:
    """Return ``value`` as a finite float, or raise :class:`ParameterError`.

    Parameters
    ----------
    name : str
        Parameter name used in the error message.
    value : real number
        The value to check (bools are refused).
    low, high : float, optional
        Inclusive bounds; ``low`` is exclusive when ``low_open`` is true.
    unit : str
        Unit shown in the message.

    Examples
    --------
    >>> check_real("m", 2, low=0.0, low_open=True, unit="kg")
    2.0
    >>> check_real("m", 0.0, low=0.0, low_open=True, unit="kg")
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: m = 0.0 kg is out of range: allowed m > 0 kg, finite
    """
    allowed = _describe(name, low, high, low_open, unit)
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ParameterError(f"{name} = {value!r} is not a real number: allowed {allowed}")
    v = float(value) + 0.0  # + 0.0 turns -0.0 into 0.0
    ok = math.isfinite(v)
    if ok and low is not None:
        ok = v > low if low_open else v >= low
    if ok and high is not None:
        ok = v <= high
    if not ok:
        raise ParameterError(f"{name} = {v!r}{_u(unit)} is out of range: allowed {allowed}")
    return v


def check_int(name: str, value, *, low: int, high: int) -> int:
    """Return ``value`` as an int in ``[low, high]``, or raise :class:`ParameterError`.

    Examples
    --------
    >>> check_int("n_points", 11, low=2, high=100)
    11
    """
    allowed = f"integer {low} <= {name} <= {high}"
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ParameterError(f"{name} = {value!r} is not an integer: allowed {allowed}")
    v = int(value)
    if not low <= v <= high:
        raise ParameterError(f"{name} = {v} is out of range: allowed {allowed}")
    return v


def check_records(osc, force) -> None:
    """Raise :class:`ParameterError` unless ``osc`` is an :class:`Oscillator` and ``force`` a :class:`SineForce`."""
    if not isinstance(osc, Oscillator):
        raise ParameterError(f"osc = {osc!r} is not an Oscillator: allowed Oscillator(m, c, k)")
    if not isinstance(force, SineForce):
        raise ParameterError(f"force = {force!r} is not a SineForce: allowed SineForce(F0, omega)")


def _u(unit: str) -> str:
    return f" {unit}" if unit else ""


def _describe(name, low, high, low_open, unit) -> str:
    parts = []
    if low is not None:
        parts.append(f"{name} {'>' if low_open else '>='} {low:g}{_u(unit)}")
    if high is not None:
        parts.append(f"{name} <= {high:g}{_u(unit)}")
    parts.append("finite")
    return ", ".join(parts)


@dataclass(frozen=True, kw_only=True)
class Oscillator:
    """Linear single-degree-of-freedom oscillator ``m x'' + c x' + k x = F(t)``.

    Negative damping is allowed: it is the honest linear model of a
    self-excited instability such as flutter, and its regime is ``"unstable"``.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> round(osc.natural_frequency, 4)       # rad/s
    4.4721
    >>> round(osc.damping_ratio, 5)
    0.0559
    >>> osc.regime
    'underdamped'
    >>> Oscillator(m=1.0, c=15.0, k=20.0).regime
    'overdamped'
    """

    m: float  # mass, kg; > 0
    c: float  # viscous damping coefficient, N s/m; any finite value
    k: float  # stiffness, N/m; > 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "m", check_real("m", self.m, low=0.0, low_open=True, unit="kg"))
        object.__setattr__(self, "c", check_real("c", self.c, unit="N s/m"))
        object.__setattr__(self, "k", check_real("k", self.k, low=0.0, low_open=True, unit="N/m"))
        # the rates the solution is made of must be representable: omega_n^2 = k/m and |c|/m
        wn2, cm = self.k / self.m, abs(self.c) / self.m
        ok_k = RATE_MIN**2 <= wn2 <= RATE_MAX**2  # False for inf and for underflow to 0
        if not (ok_k and cm <= RATE_MAX):
            name, unit, rate, value = ("k", "N/m", "k/m", wn2) if not ok_k else ("c", "N s/m", "|c|/m", cm)
            raise ParameterError(
                f"{name} = {getattr(self, name)!r} {unit} with m = {self.m!r} kg gives {rate} = {value!r}: "
                f"allowed {RATE_MIN**2:g} 1/s^2 <= k/m <= {RATE_MAX**2:g} 1/s^2 and |c|/m <= {RATE_MAX:g} 1/s "
                "(omega_n and the decay rate must be finite, normal floats)"
            )

    @classmethod
    def from_modal(cls, *, m: float, omega_n: float, zeta: float) -> Oscillator:
        """The oscillator of mass ``m`` (kg), natural frequency ``omega_n`` (rad/s) and damping ratio ``zeta``.

        ``k = m omega_n^2``, ``c = 2 zeta m omega_n``.

        >>> osc = Oscillator.from_modal(m=2.0, omega_n=3.0, zeta=0.1)
        >>> osc
        Oscillator(m=2.0 kg, c=1.2000000000000002 N s/m, k=18.0 N/m)
        >>> round(osc.damping_ratio, 12), round(osc.natural_frequency, 12)
        (0.1, 3.0)
        """
        m = check_real("m", m, low=0.0, low_open=True, unit="kg")
        omega_n = check_real("omega_n", omega_n, low=0.0, low_open=True, unit="rad/s")
        zeta = check_real("zeta", zeta)
        return cls(m=m, c=2.0 * zeta * m * omega_n, k=m * omega_n**2)

    def __repr__(self) -> str:
        return f"Oscillator(m={self.m!r} kg, c={self.c!r} N s/m, k={self.k!r} N/m)"

    @property
    def natural_frequency(self) -> float:
        """Undamped natural frequency ``sqrt(k/m)``, rad/s."""
        return math.sqrt(self.k / self.m)

    @property
    def critical_damping(self) -> float:
        """Critical damping coefficient ``2 sqrt(k m)``, N s/m."""
        return 2.0 * math.sqrt(self.k) * math.sqrt(self.m)  # no overflow of k m at extreme scales

    @property
    def damping_ratio(self) -> float:
        """Damping ratio ``zeta = c / (2 sqrt(k m))``, dimensionless."""
        return self.c / self.critical_damping

    @property
    def decay_rate(self) -> float:
        """Envelope decay rate ``sigma = c / (2 m)``, 1/s (negative when unstable)."""
        return self.c / (2.0 * self.m)

    @property
    def damped_natural_frequency(self) -> float:
        """Damped natural frequency ``omega_n sqrt(1 - zeta^2)``, rad/s.

        Zero when the oscillator does not oscillate (|zeta| >= 1).
        """
        q = self.k / self.m - self.decay_rate**2
        return math.sqrt(q) if q > 0.0 else 0.0

    @property
    def regime(self) -> str:
        """One of ``"undamped"``, ``"underdamped"``, ``"critically damped"``,
        ``"overdamped"`` or ``"unstable"`` (c < 0).

        ``|zeta - 1| <= CRITICAL_TOL`` counts as critically damped, so that
        ``c = 2 sqrt(k m)`` evaluated in floating point is recognised.
        """
        if self.c < 0.0:
            return "unstable"
        if self.c == 0.0:
            return "undamped"
        zeta = self.damping_ratio
        if abs(zeta - 1.0) <= CRITICAL_TOL:
            return "critically damped"
        return "underdamped" if zeta < 1.0 else "overdamped"

    @property
    def quality_factor(self) -> float:
        """Quality factor ``Q = 1 / (2 zeta) = sqrt(k m) / c``, dimensionless.

        ``inf`` when undamped; ``nan`` (not defined) when c < 0.
        """
        if self.c < 0.0:
            return math.nan
        if self.c == 0.0:
            return math.inf
        return math.sqrt(self.k) * math.sqrt(self.m) / self.c

    @property
    def half_power_bandwidth(self) -> float:
        """Half-power bandwidth ``2 zeta omega_n = c / m``, rad/s.

        Exact for the velocity (power) response at every damping; the
        displacement response's half-power points are that far apart only in
        the light-damping limit. ``nan`` when c < 0.
        """
        return self.c / self.m if self.c >= 0.0 else math.nan

    @property
    def time_constant(self) -> float:
        """Decay time constant of the slowest free mode, s.

        ``2 m / c`` when underdamped, ``1 / omega_n`` when critically damped,
        ``1 / (sigma - sqrt(sigma^2 - omega_n^2))`` when overdamped; ``inf``
        when undamped; ``nan`` (not defined) when c < 0.
        """
        if self.c < 0.0:
            return math.nan
        if self.c == 0.0:
            return math.inf
        sigma, wn2 = self.decay_rate, self.k / self.m
        if self.regime == "overdamped":
            mu = math.sqrt(sigma * sigma - wn2)
            return (sigma + mu) / wn2  # = 1 / (sigma - mu), without cancellation
        return 1.0 / sigma


@dataclass(frozen=True, kw_only=True)
class SineForce:
    """Harmonic force ``F(t) = F0 sin(omega t)``.

    Examples
    --------
    >>> f = SineForce(F0=5.0, omega=3.0)
    >>> round(f.frequency_hz, 4)
    0.4775
    >>> float(f(0.0))
    0.0
    """

    F0: float  # force amplitude, N; >= 0
    omega: float  # angular frequency, rad/s; >= 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "F0", check_real("F0", self.F0, low=0.0, unit="N"))
        object.__setattr__(self, "omega", check_real("omega", self.omega, low=0.0, unit="rad/s"))

    def __repr__(self) -> str:
        return f"SineForce(F0={self.F0!r} N, omega={self.omega!r} rad/s)"

    @property
    def frequency_hz(self) -> float:
        """Forcing frequency ``omega / (2 pi)``, Hz."""
        return self.omega / (2.0 * math.pi)

    def __call__(self, t):
        """Force at time(s) ``t`` (s), N."""
        import numpy as np

        return self.F0 * np.sin(self.omega * np.asarray(t, dtype=float))
