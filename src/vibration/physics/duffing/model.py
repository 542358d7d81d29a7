"""The Duffing oscillator's model and its time response.

The record :class:`Duffing` (``m x'' + c x' + k x + k3 x^3 = F(t)``), the work budgets and input
checks shared by the package's other modules, and :func:`duffing_response` (``solve_ivp``,
DOP853) for a response in time. See :mod:`vibration.physics.duffing` for the chapter's overview.
"""

from __future__ import annotations

import functools
import inspect
import math
import numbers
from dataclasses import dataclass

import numpy as np

from ..checks import OverBudget, check_array, check_derived
from ..model import N_POINTS_MAX, ParameterError, check_real

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
    """``value`` as a finite float array of any shape, or :class:`ParameterError` (see :func:`check_array`).

    An object array whose elements are all real numbers (not bools) is accepted as floats, as read
    from a CSV file or built from a list of Python numbers mixed with numpy scalars.
    """
    if not isinstance(value, (str, bytes, np.ndarray)):
        try:
            arr = np.asarray(value)
        except (TypeError, ValueError):
            arr = None
        if (
            arr is not None
            and arr.dtype.kind == "O"
            and all(isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_)) for v in arr.reshape(-1))
        ):
            value = arr.astype(float)
    elif isinstance(value, np.ndarray) and value.dtype.kind == "O":
        if all(isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_)) for v in value.reshape(-1)):
            value = value.astype(float)
    return check_array(name, value, ndim=tuple(range(33)), min_size=min_size, max_size=max_size, unit=unit)


class _Counted:
    """A right-hand side that counts its evaluations and stops the integrator past ``limit``."""

    def __init__(self, fun, limit: int) -> None:
        self.fun, self.limit, self.calls = fun, limit, 0

    def __call__(self, t, y):
        self.calls += 1
        if self.calls > self.limit:
            raise OverBudget
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
            try:
                bound = inspect.signature(fun).bind(*args, **kwargs).arguments
                shown = ", ".join(f"{k} = {v!r}" for k, v in bound.items())
            except TypeError:
                shown = ", ".join([repr(a) for a in args] + [f"{k}={v!r}" for k, v in kwargs.items()])
            raise ParameterError(
                f"{fun.__name__}({shown:.200}) overflows a float ({exc}): allowed parameters whose amplitudes, "
                "frequencies and their powers are finite floats"
            ) from None

    return wrapper


#: Smallest static deflection F0/k (m) integrated: below it the tolerances (relative to it) underflow.
XREF_MIN = 1e-150


def _check_scales(d: Duffing, F0: float, x0: float, v0: float, xr: float) -> None:
    """Refuse, naming the arguments, a force or initial state beyond floating point for a time integration."""
    if F0 > 0 and not xr >= XREF_MIN:
        raise ParameterError(
            f"F0 = {F0!r} N gives a static deflection F0/k = {xr:.3g} m, below {XREF_MIN:g} m where the tolerances "
            f"underflow: allowed F0 = 0 or F0 >= {XREF_MIN:g} k (N)"
        )
    check_derived(
        "the linearised rate (1/s) at the amplitude max(|x0|, F0/k)",
        _linear_rate(d, max(abs(x0), xr)),
        inputs={"F0": F0, "x0": x0},
        allowed="F0 and |x0| whose cubic stiffness k3 x^2 stays finite (|x0|, F0/k below about 1e100)",
    )
    x2 = x0 * x0
    check_derived(
        "the initial energy (m v0^2 + k x0^2 + k3 x0^4 / 2) / 2 (J)",
        0.5 * (d.m * v0 * v0 + d.k * x2 + 0.5 * d.k3 * x2 * x2),
        inputs={"x0": x0, "v0": v0},
        allowed="x0 and v0 whose energy is a finite float (|x0|, |v0| below about 1e75)",
    )


def _rates(d: Duffing) -> str:
    return f"c/m = {d.c / d.m:.3g} 1/s, sqrt(|k|/m) = {math.sqrt(d.k / d.m):.3g} rad/s"


# --------------------------------------------------------------------------------------- model


@dataclass(frozen=True, kw_only=True)
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
    >>> Duffing(m=1.0, c=0.05, k=0.0, k3=1.0).natural_frequency      # Ueda's oscillator
    0.0
    >>> Duffing(m=1.0, c=0.5, k=0.0, k3=-1.0)
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


# ----------------------------------------------------------------------------------- time response


def duffing_response(
    duffing: Duffing,
    F0: float,
    omega: float,
    *,
    t,
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
    >>> x, v = duffing_response(Duffing(m=1.0, c=0.5, k=20.0, k3=0.0), 5.0, 4.47, t=[0.0, 50.0], sine=True)
    >>> round(float(x[-1]), 4)          # m, as the linear closed form of Part I
    2.009
    """
    d, F0, w, x0, v0, rtol, tt = _response_args(duffing, F0, omega, x0, v0, rtol, sine, t)
    t_end = float(tt[-1])
    if t_end == 0.0:  # t = [0]: the initial state
        return np.array([x0]), np.array([v0])
    xr = _x_ref(d, F0) if F0 > 0 else max(abs(x0), 1.0)
    _check_scales(d, F0, x0, v0, xr)
    _check_response_work(d, w, x0, xr, t_end)
    blow_up = 1e3 * max(xr, abs(x0), d.barrier) if d.k3 < 0 else math.inf
    sol = _integrate_response(d, F0, w, sine, x0, v0, tt, t_end, rtol, xr, blow_up)
    _check_response_solution(sol, d, blow_up, tt)
    return sol.y[0], sol.y[1]


def _response_args(duffing, F0, omega, x0, v0, rtol, sine, t):
    """The checked arguments of :func:`duffing_response`: ``(d, F0, omega, x0, v0, rtol, t)``, ``t`` flattened."""
    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = check_real("omega", omega, low=0.0, unit="rad/s")
    x0 = check_real("x0", x0, unit="m")
    v0 = check_real("v0", v0, unit="m/s")
    rtol = check_real("rtol", rtol, low=1e-13, high=1e-3)
    if not isinstance(sine, (bool, np.bool_)):
        raise ParameterError(f"sine = {sine!r:.60} is not a bool: allowed True or False")
    tt = check_array("t", t, low=0.0, ndim=(0, 1), increasing=True, unit="s").reshape(-1)
    return d, F0, w, x0, v0, rtol, tt


def _check_response_work(d: Duffing, w: float, x0: float, xr: float, t_end: float) -> None:
    """Refuse up front a window of :func:`duffing_response` that needs more than ``MAX_RHS_EVALUATIONS``."""
    # DOP853 needs h lambda within its stability interval (about 6) and takes 12 evaluations a step
    lam = _linear_rate(d, max(abs(x0), xr))
    need = 12.0 * t_end * max(lam, w) / 6.0
    if not need <= MAX_RHS_EVALUATIONS:
        raise ParameterError(
            f"t up to {t_end:.6g} s needs at least {need:.3g} right-hand-side evaluations (step <= 6/lambda, "
            f"lambda = {max(lam, w):.3g} 1/s from {_rates(d)}, omega = {w:.3g} rad/s), more than "
            f"{MAX_RHS_EVALUATIONS}: allowed a shorter window or a less stiff oscillator (smaller c/m, k/m)"
        )


def _integrate_response(d: Duffing, F0, w, sine, x0, v0, tt, t_end, rtol, xr, blow_up):
    """``solve_ivp`` (DOP853) of :func:`duffing_response` at the times ``tt``, stopped at ``|x| = blow_up``."""
    from scipy.integrate import solve_ivp

    m, c, k, k3 = d.m, d.c, d.k, d.k3
    trig = math.sin if sine else math.cos

    def rhs(time, y):
        return (y[1], (F0 * trig(w * time) - c * y[1] - k * y[0] - k3 * y[0] ** 3) / m)

    def escape(time, y):
        return blow_up - abs(y[0])

    escape.terminal = True
    counted = _Counted(rhs, MAX_RHS_EVALUATIONS)
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            return solve_ivp(
                counted,
                (0.0, t_end),
                (x0, v0),
                method="DOP853",
                t_eval=tt,
                rtol=rtol,
                atol=rtol * xr,
                events=escape if d.k3 < 0 else None,
            )
    except OverBudget:
        raise ParameterError(
            f"duffing_response spent its budget of {MAX_RHS_EVALUATIONS} right-hand-side evaluations before "
            f"t = {t_end:.6g} s ({_rates(d)}, k3 = {k3!r} N/m^3, x0 = {x0!r} m, v0 = {v0!r} m/s): allowed a shorter "
            "window, a looser rtol or a less stiff oscillator"
        ) from None


def _check_response_solution(sol, d: Duffing, blow_up: float, tt: np.ndarray) -> None:
    """Refuse a run of :func:`duffing_response` in which the mass escaped or the integration failed."""
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
