"""Semi-active control under base excitation: passive and ideal-skyhook transmissibility, the MR damper
(modified Bouc-Wen), on-off and clipped skyhook runs and sweeps (compiled RK4), and the laws as callables."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from ..checks import check_choice
from ..model import N_POINTS_MAX, Oscillator, ParameterError, check_int, check_real
from ..stability import _check_osc, transmissibility
from ._common import _finite, _omegas
from ._kernels import RK4_STEPS_MAX, SWEEP_STEPS_MAX, _sa_kernel

SEMI_ACTIVE_LAWS = ("passive", "skyhook", "on-off", "clipped", "mr")


# ----------------------------------------------------------------------------- semi-active


def passive_transmissibility(osc: Oscillator, omegas) -> np.ndarray:
    """Base-excitation transmissibility ``|X/Y| = |k + i c w| / |k - m w^2 + i c w|``, 1.

    The absolute displacement of the mass over the base amplitude, in steady state:
    :func:`vibration.physics.stability.transmissibility`, for a scalar or 1-D ``omegas``,
    always as an array.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> float(passive_transmissibility(osc, np.sqrt(40.0)).round(12))   # at sqrt(2) omega_n: 1
    1.0
    """
    _check_osc(osc)
    return np.asarray(transmissibility(osc, _omegas(omegas)))


def skyhook_transmissibility(osc: Oscillator, c_sky: float, omegas) -> np.ndarray:
    """Ideal-skyhook transmissibility ``|X/Y| = |k + i c w| / |k - m w^2 + i (c + c_sky) w|``, 1.

    The passive spring k and damper c connect the mass to the base ``Y sin(w t)``; the
    skyhook damper ``c_sky`` connects it to the inertial frame (force ``-c_sky v``).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m, passive damper to the base), k (N/m).
    c_sky : float
        Skyhook damping, N s/m (>= 0).
    omegas : array_like
        Base frequencies, rad/s (>= 0).

    Returns
    -------
    numpy.ndarray
        Transmissibility, 1, same shape as ``omegas``.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> w = osc.natural_frequency
    >>> round(float(skyhook_transmissibility(osc, 8.0, w)), 4)          # at resonance
    0.5294
    >>> round(float(skyhook_transmissibility(osc, 0.0, w)), 4)          # passive: sqrt(1 + (k/(c w))^2)
    9.0
    """
    _check_osc(osc)
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    w = _omegas(omegas)
    # divided through by w^2 above 1 rad/s, so that no product overflows
    s = 1.0 / np.maximum(w, 1.0)
    m, c, k, cc = osc.m, osc.c, osc.k, osc.c + c_sky
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        num = np.hypot(k * s * s, c * w * s * s)
        den = np.hypot(k * s * s - m * (w * s) * (w * s), cc * w * s * s)
        out = num / den
    if not np.all(np.isfinite(out)):
        bad = float(np.asarray(w)[~np.isfinite(out)].ravel()[0])
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: the transmissibility is not finite there (undamped resonance or "
            "overflow); allowed frequencies with a finite steady state"
        )
    return out


@dataclass(frozen=True, kw_only=True)
class MRDamper:
    """Modified Bouc-Wen model of an MR damper (Spencer, Dyke, Sain and Carlson 1997), SI units.

    ``F = c1 y' + k1 x``, ``y' = (alpha z + c0 x' + k0 (x - y)) / (c0 + c1)``,
    ``z' = -gamma |x' - y'| z |z|^(n-1) - beta (x' - y') |z|^n + A (x' - y')``, with
    ``alpha = alpha_a + alpha_b u``, ``c0 = c0a + c0b u``, ``c1 = c1a + c1b u`` and the
    coil filter ``u' = -eta (u - V)`` on the commanded voltage ``V`` in ``[0, v_max]``.
    ``x`` is the piston displacement (relative to the base), ``F`` the force it resists with.
    The accumulator preload ``k1 x0`` of the original is left out: a constant force only
    shifts the static equilibrium.
    """

    c0a: float  # viscous damping at large velocity, 0 V, N s/m
    c0b: float  # its voltage slope, N s/(m V)
    k0: float  # stiffness at large velocity, N/m
    c1a: float  # viscous damping at low velocity (roll-off), 0 V, N s/m
    c1b: float  # its voltage slope, N s/(m V)
    k1: float  # accumulator stiffness, N/m
    alpha_a: float  # evolutionary coefficient, 0 V, N/m
    alpha_b: float  # its voltage slope, N/(m V)
    gamma: float  # Bouc-Wen shape, 1/m^2 (for n = 2)
    beta: float  # Bouc-Wen shape, 1/m^2 (for n = 2)
    A: float  # Bouc-Wen scale, 1
    n: float  # Bouc-Wen exponent, 1
    eta: float  # coil (first-order filter) rate, 1/s
    v_max: float  # largest command voltage, V

    def __post_init__(self) -> None:
        for name in ("c0a", "c0b", "k0", "c1a", "c1b", "k1", "alpha_a", "alpha_b", "gamma", "beta", "A"):
            object.__setattr__(self, name, check_real(name, getattr(self, name), low=0.0))
        object.__setattr__(self, "c1a", check_real("c1a", self.c1a, low=0.0, low_open=True, unit="N s/m"))
        object.__setattr__(self, "n", check_real("n", self.n, low=1.0, high=4.0))
        object.__setattr__(self, "eta", check_real("eta", self.eta, low=0.0, low_open=True, unit="1/s"))
        object.__setattr__(self, "v_max", check_real("v_max", self.v_max, low=0.0, unit="V"))

    @property
    def z_max(self) -> float:
        """Largest evolutionary displacement ``(A / (gamma + beta))^(1/n)``, m."""
        return (self.A / (self.gamma + self.beta)) ** (1.0 / self.n)

    @property
    def yield_force(self) -> float:
        """Hysteretic force ``alpha z_max`` at full voltage, N."""
        return (self.alpha_a + self.alpha_b * self.v_max) * self.z_max

    def scaled(self, length: float, force: float) -> MRDamper:
        """Similitude copy: displacements times ``length``, forces times ``force``, time unchanged.

        Stiffnesses and damping coefficients scale by ``force / length``, ``gamma`` and
        ``beta`` (for n = 2) by ``1 / length^n``, ``A``, ``n``, ``eta`` and the voltage are unchanged, so
        the scaled device run at ``length`` times the stroke gives exactly ``force`` times
        the force history.

        Examples
        --------
        >>> d = SPENCER_1997.scaled(length=2.0, force=0.5)
        >>> round(d.yield_force / SPENCER_1997.yield_force, 12), round(d.z_max / SPENCER_1997.z_max, 12)
        (0.5, 2.0)
        """
        length = check_real("length", length, low=0.0, low_open=True)
        force = check_real("force", force, low=0.0, low_open=True)
        s, g = force / length, length ** (-self.n)
        return replace(
            self,
            c0a=self.c0a * s,
            c0b=self.c0b * s,
            k0=self.k0 * s,
            c1a=self.c1a * s,
            c1b=self.c1b * s,
            k1=self.k1 * s,
            alpha_a=self.alpha_a * s,
            alpha_b=self.alpha_b * s,
            gamma=self.gamma * g,
            beta=self.beta * g,
        )


#: Spencer, Dyke, Sain and Carlson (1997), "Phenomenological model for magnetorheological
#: dampers", J. Eng. Mech. 123(3):230-238, parameters of the modified Bouc-Wen model
#: identified for their prototype damper (about 3000 N capacity, tested at 1.5 cm and
#: 2.5 Hz, 0-2.25 V): c0a 21.0 N s/cm, c0b 3.50 N s/(cm V), k0 46.9 N/cm, c1a 283 N s/cm,
#: c1b 2.95 N s/(cm V), k1 5.00 N/cm, x0 14.3 cm (preload, not used), alpha_a 140 N/cm,
#: alpha_b 695 N/(cm V), gamma = beta = 363 cm^-2, A 301, n 2, eta 190 1/s; here in SI.
SPENCER_1997 = MRDamper(
    c0a=21.0e2,
    c0b=3.50e2,
    k0=46.9e2,
    c1a=283.0e2,
    c1b=2.95e2,
    k1=5.00e2,
    alpha_a=140.0e2,
    alpha_b=695.0e2,
    gamma=363.0e4,
    beta=363.0e4,
    A=301.0,
    n=2.0,
    eta=190.0,
    v_max=2.25,
)

#: Displacement amplitude of the tests the parameters were identified on, m (1.5 cm).
SPENCER_1997_STROKE = 0.015


def _sa_params(osc, law, c_sky, c_min, c_max, damper):
    if law not in SEMI_ACTIVE_LAWS:
        raise ParameterError(f"law = {law!r} is not supported: allowed one of {', '.join(SEMI_ACTIVE_LAWS)}")
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    c_min = check_real("c_min", c_min, low=0.0, unit="N s/m")
    c_max = check_real("c_max", c_max, low=0.0, unit="N s/m")
    if c_max < c_min:
        raise ParameterError(
            f"c_max = {c_max!r} N s/m is below c_min = {c_min!r} N s/m: allowed c_max >= {c_min:g} N s/m "
            "(0 <= c_min <= c_max, finite)"
        )
    d = damper if damper is not None else SPENCER_1997
    if not isinstance(d, MRDamper):
        raise ParameterError(f"damper = {damper!r} is not an MRDamper: allowed None or MRDamper(...)")
    p = np.array(
        [
            osc.m, osc.c, osc.k, c_sky, c_min, c_max,
            d.c0a, d.c0b, d.k0, d.c1a, d.c1b, d.k1, d.alpha_a, d.alpha_b, d.gamma, d.beta, d.A, d.n, d.eta, d.v_max,
        ]
    )  # fmt: skip
    return SEMI_ACTIVE_LAWS.index(law), p


@dataclass(frozen=True, kw_only=True)
class SemiActiveResponse:
    """Time response of the base-excited oscillator with a controllable device."""

    t: np.ndarray  # time, s
    x: np.ndarray  # absolute displacement of the mass, m
    v: np.ndarray  # absolute velocity of the mass, m/s
    x_base: np.ndarray  # base displacement, m
    v_base: np.ndarray  # base velocity, m/s
    f: np.ndarray  # force of the device on the mass, N
    command: np.ndarray  # 1 when the law asks for more than c_min (MR: coil voltage, V)
    law: str  # the control law
    dt: float  # RK4 step, s


#: Times a sweep frequency whose RK4 run overflowed is run again with a quarter of the step.
REFINE = 2


def _sa_rate_check(p: np.ndarray, dt: float, w: float, spp: int) -> None:
    """Refuse an RK4 step longer than the plant's fastest time scale (RK4 would be inaccurate or diverge)."""
    m, c, k, c_sky, c_max = p[0], p[1], p[2], p[3], p[5]
    rate = math.sqrt(k / m) + (abs(c) + max(c_sky, c_max)) / m
    if not dt * rate <= 1.0:
        raise ParameterError(
            f"omega = {w!r} rad/s with steps_per_period = {spp}: the RK4 step {dt:.3g} s is {dt * rate:.3g} times the "
            f"plant's fastest time scale 1/{rate:.3g} s (sqrt(k/m) + (|c| + max(c_sky = {c_sky!r}, c_max = {c_max!r}))"
            "/m); allowed at most 1 (raise the frequency or steps_per_period, or lower c_sky and c_max)"
        )


def _sa_step(law_i: int, w: float, steps_per_period: int, dt_max: float) -> tuple[float, int]:
    """RK4 step (s) and steps per forcing period: ``steps_per_period`` or more, below ``dt_max``."""
    period = 2.0 * math.pi / w
    if law_i == 4 and not period / dt_max <= RK4_STEPS_MAX:
        raise ParameterError(
            f"omega = {w!r} rad/s with dt_max = {dt_max!r} s: {period / dt_max:.3g} RK4 steps per period, "
            f"allowed at most {RK4_STEPS_MAX}"
        )
    n = max(steps_per_period, math.ceil(period / dt_max)) if law_i == 4 else steps_per_period
    return period / n, n


def semi_active_response(
    osc: Oscillator,
    law: str,
    omega: float,
    Y: float,
    *,
    c_sky: float = 0.0,
    c_min: float = 0.0,
    c_max: float = 0.0,
    damper: MRDamper | None = None,
    t_end: float = 50.0,
    n_points: int = 5001,
    steps_per_period: int = 2000,
    dt_max: float = 2e-4,
) -> SemiActiveResponse:
    """Base-excited response from rest with a controllable device, fixed-step RK4 (numba).

    ``m x'' + c (x' - x_b') + k (x - x_b) = f``, ``x_b = Y sin(omega t)``, with the device force
    ``f`` on the mass given by ``law``:

    * ``"passive"``: a damper at ``c_min``, ``f = -c_min (v - v_b)``;
    * ``"skyhook"``: ideal, ``f = -c_sky v`` (needs an active actuator);
    * ``"on-off"``: damper at ``c_max`` when ``v (v - v_b) > 0`` (the skyhook force is
      dissipative), else ``c_min``;
    * ``"clipped"``: damper coefficient ``c_sky v / (v - v_b)`` clipped to ``[c_min, c_max]``
      when ``v (v - v_b) > 0``, else ``c_min`` (continuous clipped skyhook);
    * ``"mr"``: the MR damper ``damper`` (modified Bouc-Wen) switched by the on-off
      skyhook condition: full voltage ``v_max`` when ``v (v - v_b) > 0``, else 0 V (the
      coil filter smooths the step). Dyke et al.'s clipped-optimal rule
      ``(f_sky - f) f > 0`` chatters at the integration step here, so it is not used.

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (passive damper to the base, N s/m), k (N/m).
    law : str
        One of ``"passive"``, ``"skyhook"``, ``"on-off"``, ``"clipped"``, ``"mr"``.
    omega : float
        Base frequency, rad/s (> 0).
    Y : float
        Base amplitude, m (>= 0).
    c_sky : float
        Skyhook gain, N s/m (>= 0).
    c_min, c_max : float
        Bounds of the device damping, N s/m (0 <= c_min <= c_max).
    damper : MRDamper, optional
        For ``law="mr"``; :data:`SPENCER_1997` unscaled by default.
    t_end : float
        End of the window, s (> 0).
    n_points : int
        Output samples (nearest RK4 steps; the grid is uniform).
    steps_per_period : int
        RK4 steps per forcing period (100 to 100000).
    dt_max : float
        Largest RK4 step for the stiff MR model, s.

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> r = semi_active_response(osc, "clipped", 4.47, 0.25, c_sky=8.0, c_min=0.5, c_max=15.0, t_end=10.0, n_points=11)
    >>> r.t.shape, r.law
    ((11,), 'clipped')
    """
    _check_osc(osc)
    law_i, p = _sa_params(osc, law, c_sky, c_min, c_max, damper)
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    Y = check_real("Y", Y, low=0.0, unit="m")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    spp = check_int("steps_per_period", steps_per_period, low=100, high=100_000)
    dt_max = check_real("dt_max", dt_max, low=0.0, low_open=True, unit="s")
    dt, _ = _sa_step(law_i, w, spp, dt_max)
    _sa_rate_check(p, dt, w, spp)
    if not t_end / dt <= RK4_STEPS_MAX:
        raise ParameterError(
            f"t_end = {t_end!r} s at omega = {w!r} rad/s needs {t_end / dt:.3g} RK4 steps of {dt:.3g} s: allowed at "
            f"most {RK4_STEPS_MAX} (shorten t_end, lower omega or steps_per_period)"
        )
    n_steps = max(1, math.ceil(t_end / dt))
    stride = max(1, n_steps // (n_points - 1))
    n_steps = stride * (n_points - 1)
    dt = t_end / n_steps
    if n_steps > RK4_STEPS_MAX:
        raise ParameterError(
            f"t_end = {t_end!r} s needs {n_steps} RK4 steps of {dt:.3g} s: allowed at most {RK4_STEPS_MAX} "
            "(shorten t_end or lower steps_per_period)"
        )
    rec, _ = _sa_kernel()[0](law_i, p, Y, w, np.zeros(5), dt, n_steps, stride, n_steps + 1)
    for _ in range(REFINE):  # the MR damper's state may need a shorter step (see semi_active_sweep)
        if np.all(np.isfinite(rec)) or 4 * n_steps > RK4_STEPS_MAX:
            break
        n_steps, stride, dt = 4 * n_steps, 4 * stride, dt / 4.0
        rec, _ = _sa_kernel()[0](law_i, p, Y, w, np.zeros(5), dt, n_steps, stride, n_steps + 1)
    if not np.all(np.isfinite(rec)):
        raise ParameterError(
            f"dt_max = {dt_max!r} s, steps_per_period = {spp}: the RK4 run overflowed (step {dt:.3g} s too long "
            "for the device or the plant); allowed a smaller step"
        )
    t = rec[:, 0]
    return SemiActiveResponse(
        t=t,
        x=rec[:, 1],
        v=rec[:, 2],
        x_base=Y * np.sin(w * t),
        v_base=Y * w * np.cos(w * t),
        f=rec[:, 3],
        command=rec[:, 4],
        law=law,
        dt=dt,
    )


@dataclass(frozen=True, kw_only=True)
class SemiActiveSweep:
    """Steady-state measures of a semi-active law across base frequencies."""

    omegas: np.ndarray  # base frequencies, rad/s
    peak: np.ndarray  # max |x| / Y over the measured periods, 1
    fundamental: np.ndarray  # amplitude of the fundamental harmonic of x over Y, 1
    force_rms: np.ndarray  # RMS device force, N
    force_peak: np.ndarray  # peak device force, N
    switches: np.ndarray  # command changes per period, 1
    power: np.ndarray  # mean |f (v - v_b)|, W (mechanical power handled by the device)
    law: str  # the control law


def semi_active_sweep(
    osc: Oscillator,
    law: str,
    omegas,
    Y: float,
    *,
    c_sky: float = 0.0,
    c_min: float = 0.0,
    c_max: float = 0.0,
    damper: MRDamper | None = None,
    settle: float = 12.0,
    periods: int = 8,
    steps_per_period: int = 1000,
    dt_max: float = 2e-4,
) -> SemiActiveSweep:
    """Steady-state transmissibility of a semi-active law at each base frequency (numba RK4).

    Each frequency starts in the steady state of the ideal skyhook (or of the passive
    damper ``c + c_min`` for ``law="passive"``), runs ``settle / sigma`` seconds with
    ``sigma = (c + c_min) / (2 m)`` the slowest decay any law allows (so the start is
    forgotten by a factor ``exp(-settle)``), rounded up to whole periods, then measures
    over ``periods`` whole periods: peak ``|x| / Y``, the fundamental harmonic of ``x``
    over ``Y`` (left-point sums over whole periods, exact for trigonometric polynomials
    of low degree), RMS and peak device force, command switches per period and mean
    mechanical power.

    Parameters are those of :func:`semi_active_response`; ``omegas`` in rad/s (> 0),
    ``settle`` (1 to 50) in decay time constants, ``periods`` (1 to 1000).

    Examples
    --------
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> s = semi_active_sweep(osc, "skyhook", [4.4721], 0.25, c_sky=8.0, periods=2)
    >>> bool(abs(s.fundamental[0] - skyhook_transmissibility(osc, 8.0, 4.4721)) < 1e-6)
    True
    """
    _check_osc(osc)
    law_i, p = _sa_params(osc, law, c_sky, c_min, c_max, damper)
    w_arr = _omegas(omegas)
    if np.any(w_arr <= 0):
        raise ParameterError(f"omegas contains {float(w_arr[w_arr <= 0][0])!r}: allowed frequencies > 0 rad/s")
    Y = check_real("Y", Y, low=0.0, low_open=True, unit="m")
    settle = check_real("settle", settle, low=1.0, high=50.0)
    periods = check_int("periods", periods, low=1, high=1000)
    spp = check_int("steps_per_period", steps_per_period, low=100, high=100_000)
    dt_max = check_real("dt_max", dt_max, low=0.0, low_open=True, unit="s")
    sigma = (osc.c + c_min) / (2.0 * osc.m)
    if sigma <= 0.0:
        raise ParameterError(
            f"c + c_min = {osc.c + c_min!r} N s/m: allowed > 0 (a steady state needs some damping in every state)"
        )
    ws = w_arr.ravel()
    c_start = osc.c + (c_min if law_i == 0 else 0.0)
    sky = c_sky if law_i != 0 else 0.0
    dts, n_steps, n_settle = np.empty(ws.size), np.empty(ws.size, np.int64), np.empty(ws.size, np.int64)
    s0s = np.zeros((ws.size, 5))
    for j, w in enumerate(ws.tolist()):  # Python floats: an overflow gives inf (checked below), not a warning
        if not math.isfinite(2.0 * math.pi / w):
            raise ParameterError(f"omegas contains {w!r} rad/s: its period overflows; allowed a finite period")
        dts[j], n_per = _sa_step(law_i, w, spp, dt_max)
        _sa_rate_check(p, dts[j], w, spp)
        settle_periods = settle / sigma / (2.0 * math.pi / w)
        if not (settle_periods + periods) * n_per <= RK4_STEPS_MAX:
            raise ParameterError(
                f"omegas contains {w!r} rad/s: settling {settle!r} time constants of {1.0 / sigma:.3g} s "
                f"(c + c_min = {osc.c + c_min!r} N s/m) takes {settle_periods:.3g} periods of {n_per} RK4 steps: "
                f"allowed at most {RK4_STEPS_MAX} steps"
            )
        n_settle[j] = math.ceil(settle_periods) * n_per
        n_steps[j] = n_settle[j] + periods * n_per
        if n_steps[j] > RK4_STEPS_MAX:
            raise ParameterError(
                f"omegas contains {w!r} rad/s: it needs {n_steps[j]} RK4 steps (settle = {settle!r} time constants "
                f"of {1.0 / sigma:.3g} s plus {periods} periods), allowed at most {RK4_STEPS_MAX}"
            )
        # start in the steady state of the linear loop (c_start to the base, sky to the frame)
        h = (osc.k + 1j * osc.c * w) / (osc.k - osc.m * w * w + 1j * (c_start + sky) * w) * Y
        s0s[j, :2] = h.imag, w * h.real
    if n_steps.sum() > SWEEP_STEPS_MAX:
        raise ParameterError(
            f"omegas has {ws.size} frequencies needing {int(n_steps.sum())} RK4 steps in all: "
            f"allowed at most {SWEEP_STEPS_MAX} (fewer frequencies, periods or steps_per_period)"
        )
    st = _sa_kernel()[1](law_i, p, Y, ws, s0s, dts, n_steps, n_settle)
    # The MR damper's internal (Bouc-Wen) state stiffens with the stroke velocity, so a fast or stiff plant
    # can need a shorter step than dt_max: the frequencies whose run overflowed are run again with a quarter
    # of the step, at most REFINE times, inside the same budget of RK4 steps.
    spent = int(n_steps.sum())
    for _ in range(REFINE):
        bad = ~np.all(np.isfinite(st), axis=1)
        if not bad.any():
            break
        more = 4 * int(n_steps[bad].sum())
        if spent + more > SWEEP_STEPS_MAX:
            break
        spent += more
        dts[bad], n_steps[bad], n_settle[bad] = dts[bad] / 4.0, 4 * n_steps[bad], 4 * n_settle[bad]
        st[bad] = _sa_kernel()[1](law_i, p, Y, ws[bad], s0s[bad], dts[bad], n_steps[bad], n_settle[bad])
    if not np.all(np.isfinite(st)):
        bad = ws[~np.all(np.isfinite(st), axis=1)][0]
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: the RK4 run overflowed even at a step of {dts[ws == bad][0]:.3g} s "
            f"with Y = {Y!r} m (too long for the device; allowed a smaller dt_max = {dt_max!r} s or more "
            f"steps_per_period = {spp}, or a smaller Y)"
        )
    n, span = st[:, 6], periods * 2.0 * np.pi / ws
    out = np.stack(
        [
            st[:, 2] / Y,
            2.0 * np.hypot(st[:, 0], st[:, 1]) / n / Y,
            np.sqrt(st[:, 3] / n),
            st[:, 4],
            st[:, 5] / periods,
            st[:, 7] / span,
        ]
    )
    shape = w_arr.shape
    return SemiActiveSweep(
        omegas=w_arr,
        peak=out[0].reshape(shape),
        fundamental=out[1].reshape(shape),
        force_rms=out[2].reshape(shape),
        force_peak=out[3].reshape(shape),
        switches=out[4].reshape(shape),
        power=out[5].reshape(shape),
        law=law,
    )


def semi_active_controller(
    law: str, c_sky: float, c_min: float, c_max: float, Y: float, omega: float
) -> Callable[[float, float, float], float]:
    """The skyhook laws as a plain callable ``controller(t, x, v) -> f`` (s, m, m/s -> N).

    For :func:`simulate_controlled` with ``base=(Y, omega)``; ``law`` is one of
    ``"passive"``, ``"skyhook"``, ``"on-off"``, ``"clipped"`` (the MR damper has an
    internal state, so it is not memoryless). Same laws as :func:`semi_active_response`.

    Examples
    --------
    >>> f = semi_active_controller("on-off", 8.0, 0.5, 15.0, 0.25, 4.47)
    >>> round(f(0.0, 0.0, 1.0), 12)     # N: v (v - v_b) = 1 (1 - 1.1175) < 0, so c_min
    0.05875
    """
    law = check_choice("law", law, SEMI_ACTIVE_LAWS[:4])
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    c_min = check_real("c_min", c_min, low=0.0, unit="N s/m")
    c_max = check_real("c_max", c_max, low=0.0, unit="N s/m")
    if c_max < c_min:
        raise ParameterError(
            f"c_max = {c_max!r} N s/m is below c_min = {c_min!r} N s/m: allowed c_max >= {c_min:g} N s/m "
            "(0 <= c_min <= c_max, finite)"
        )
    Y = check_real("Y", Y, low=0.0, unit="m")
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")  # the base moves: omega > 0
    if not math.isfinite(max(c_max, c_sky, 1.0) * Y * max(w, 1.0)):
        raise ParameterError(
            f"Y = {Y!r} m, omega = {w!r} rad/s: the base velocity times the damping overflows; allowed a finite force"
        )

    def controller(t: float, x: float, v: float) -> float:
        vr = v - Y * w * math.cos(w * t)
        if law == "passive":
            return -c_min * vr
        if law == "skyhook":
            return -c_sky * v
        if v * vr > 0.0:
            if law == "on-off":
                return -c_max * vr
            a = min(max(c_sky * abs(v), c_min * abs(vr)), c_max * abs(vr))
            return -a if vr > 0.0 else a
        return -c_min * vr

    return controller


@dataclass(frozen=True, kw_only=True)
class SkyhookPower:
    """Steady mean powers of the ideal skyhook force ``f = -c_sky v`` under base motion ``Y sin(omega t)``, W."""

    removed: float  # mean c_sky v^2: what the skyhook force takes out of the mass (its work on the mass, negated)
    net: float  # mean f (v - v_b): net power an actuator between body and base delivers (negative: it absorbs)
    supplied: float  # mean of the positive part of f (v - v_b): what the actuator must supply, W
    gross: float  # mean |f (v - v_b)|: the power it exchanges in both directions, W


def skyhook_power(osc: Oscillator, c_sky: float, Y: float, omega: float) -> SkyhookPower:
    """Mean steady powers (W) of the ideal skyhook realised by an actuator between the mass and the base.

    With ``x = Im(H Y e^{i omega t})``, ``H = (k + i c omega) / (k - m omega^2 + i (c + c_sky) omega)``,
    the actuator's power ``p = f (v - v_b) = a + b cos(2 omega t + phi)`` has the mean
    ``a = -c_sky (<v^2> - <v v_b>)`` and the swing ``b``; the mean of its positive part is
    ``(a theta + b sin theta) / pi`` with ``cos theta = -a / b`` (``a`` if ``|a| >= b`` and ``a > 0``,
    0 if ``a <= -b``), and the gross exchange ``mean |p| = 2 mean(p+) - a``. The skyhook itself,
    a damper to the inertial frame, removes ``c_sky <v^2>``.

    Examples
    --------
    >>> p = skyhook_power(Oscillator(m=1.0, c=0.5, k=20.0), 8.0, 0.25, 20.0**0.5)
    >>> round(p.removed, 4), round(p.net, 4), round(p.supplied, 4), round(p.gross, 4)
    (1.4014, -1.1073, 0.4242, 1.9556)
    """
    _check_osc(osc)
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    Y = check_real("Y", Y, low=0.0, unit="m")
    w = check_real("omega", omega, low=0.0, unit="rad/s")
    m, c, k = osc.m, osc.c, osc.k
    den = complex(k - m * w * w, (c + c_sky) * w)
    if den == 0:
        raise ParameterError(f"omega = {w!r} rad/s: undamped resonance, no steady state; allowed c + c_sky > 0")
    H = complex(k, c * w) / den
    V = 1j * w * H * Y  # complex velocity amplitude of the mass, m/s
    Vb = 1j * w * Y  # of the base
    F = -c_sky * V  # of the force
    P_rel = F * np.conj(V - Vb)  # p = Re(F e^{iwt}) Re(Vr e^{iwt}) = Re(F conj(Vr))/2 + Re(F Vr e^{2iwt})/2
    a = float(0.5 * P_rel.real)
    b = float(0.5 * abs(F * (V - Vb)))
    if not (math.isfinite(a) and math.isfinite(b)):
        raise ParameterError(
            f"c_sky = {c_sky!r} N s/m, Y = {Y!r} m, omega = {w!r} rad/s overflow the skyhook power: allowed c_sky, Y "
            "and omega whose power c_sky (omega Y)^2 is a finite float"
        )
    if b <= abs(a):
        pos = max(a, 0.0)
    else:
        theta = math.acos(-a / b)
        pos = (a * theta + b * math.sin(theta)) / math.pi
    removed = float(0.5 * c_sky * abs(V) * abs(V))
    out = SkyhookPower(removed=removed, net=a, supplied=pos, gross=2.0 * pos - a)
    _finite("Y, omega", [out.removed, out.net, out.gross], "the skyhook power")
    return out
