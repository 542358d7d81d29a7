"""Semi-active control under base excitation: on-off and clipped skyhook and the MR damper, run and swept
with a compiled RK4, and the memoryless laws as callables.

The closed-form ideal skyhook is in :mod:`.skyhook`, the MR damper's model in :mod:`.mr_damper`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..checks import check_choice, check_oscillator
from ..model import N_POINTS_MAX, Oscillator, ParameterError, check_int, check_real
from ._common import _omegas
from ._kernels import RK4_STEPS_MAX, SWEEP_STEPS_MAX, _sa_kernel
from .mr_damper import SPENCER_1997, MRDamper

__all__ = [
    "SEMI_ACTIVE_LAWS",
    "SemiActiveResponse",
    "SemiActiveSweep",
    "semi_active_controller",
    "semi_active_response",
    "semi_active_sweep",
]

SEMI_ACTIVE_LAWS = ("passive", "skyhook", "on-off", "clipped", "mr")


def _check_dampings(c_sky, c_min, c_max) -> tuple[float, float, float]:
    """The skyhook gain and the device's damping bounds, N s/m, checked (0 <= c_min <= c_max)."""
    c_sky = check_real("c_sky", c_sky, low=0.0, unit="N s/m")
    c_min = check_real("c_min", c_min, low=0.0, unit="N s/m")
    c_max = check_real("c_max", c_max, low=0.0, unit="N s/m")
    if c_max < c_min:
        raise ParameterError(
            f"c_max = {c_max!r} N s/m is below c_min = {c_min!r} N s/m: allowed c_max >= {c_min:g} N s/m "
            "(0 <= c_min <= c_max, finite)"
        )
    return c_sky, c_min, c_max


def _sa_params(osc, law, c_sky, c_min, c_max, damper):
    if law not in SEMI_ACTIVE_LAWS:
        raise ParameterError(f"law = {law!r} is not supported: allowed one of {', '.join(SEMI_ACTIVE_LAWS)}")
    c_sky, c_min, c_max = _check_dampings(c_sky, c_min, c_max)
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
    *,
    Y: float,
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
    >>> r = semi_active_response(osc, "clipped", 4.47, Y=0.25, c_sky=8.0, c_min=0.5, c_max=15.0,
    ...                          t_end=10.0, n_points=11)
    >>> r.t.shape, r.law
    ((11,), 'clipped')
    """
    check_oscillator(osc)
    law_i, p = _sa_params(osc, law, c_sky, c_min, c_max, damper)
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    Y = check_real("Y", Y, low=0.0, unit="m")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
    spp, dt_max = _check_steps(steps_per_period, dt_max)
    n_steps, stride, dt = _response_steps(law_i, p, w, t_end, n_points, spp, dt_max)
    rec, dt = _response_run(law_i, p, Y, w, n_steps, stride, dt, spp, dt_max)
    return _response_record(rec, Y, w, law, dt)


def _check_steps(steps_per_period, dt_max) -> tuple[int, float]:
    """The checked RK4 step settings ``(steps_per_period, dt_max)`` of the semi-active runs and sweeps."""
    spp = check_int("steps_per_period", steps_per_period, low=100, high=100_000)
    dt_max = check_real("dt_max", dt_max, low=0.0, low_open=True, unit="s")
    return spp, dt_max


def _response_steps(law_i: int, p: np.ndarray, w: float, t_end: float, n_points: int, spp: int, dt_max: float):
    """RK4 steps in all, steps per output sample and the step (s) of :func:`semi_active_response` (checked budget)."""
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
    return n_steps, stride, dt


def _response_run(law_i, p, Y, w, n_steps, stride, dt, spp, dt_max) -> tuple[np.ndarray, float]:
    """The compiled run's samples and its step (s), a quarter as long while the run overflows (REFINE times)."""
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
    return rec, dt


def _response_record(rec: np.ndarray, Y: float, w: float, law: str, dt: float) -> SemiActiveResponse:
    """The :class:`SemiActiveResponse` of the compiled run's samples ``rec`` (t, x, v, f, command)."""
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


def _sweep_plan(osc, law_i, p, ws, Y, *, c_sky, c_min, settle, periods, spp, dt_max):
    """Each frequency's RK4 step (s), steps in all and while settling, and its starting state (checked budgets).

    The start is the steady state of the linear loop: the ideal skyhook, or the passive damper ``c + c_min``
    for ``law="passive"``; it settles for ``settle`` time constants of the slowest decay any law allows.
    """
    sigma = (osc.c + c_min) / (2.0 * osc.m)
    if sigma <= 0.0:
        raise ParameterError(
            f"c + c_min = {osc.c + c_min!r} N s/m: allowed > 0 (a steady state needs some damping in every state)"
        )
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
    return dts, n_steps, n_settle, s0s


def _sweep_runs(law_i, p, Y, ws, s0s, dts, n_steps, n_settle) -> np.ndarray:
    """The compiled sweep's per-frequency sums; a frequency whose run overflowed runs again with a shorter step.

    ``dts``, ``n_steps`` and ``n_settle`` are updated in place for the frequencies run again.
    """
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
    return st


def semi_active_sweep(
    osc: Oscillator,
    law: str,
    omegas,
    *,
    Y: float,
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
    >>> from vibration.physics.control.skyhook import skyhook_transmissibility
    >>> osc = Oscillator(m=1.0, c=0.5, k=20.0)
    >>> s = semi_active_sweep(osc, "skyhook", [4.4721], Y=0.25, c_sky=8.0, periods=2)
    >>> bool(abs(s.fundamental[0] - skyhook_transmissibility(osc, 8.0, 4.4721)) < 1e-6)
    True
    """
    check_oscillator(osc)
    law_i, p = _sa_params(osc, law, c_sky, c_min, c_max, damper)
    w_arr = _omegas(omegas)
    if np.any(w_arr <= 0):
        raise ParameterError(f"omegas contains {float(w_arr[w_arr <= 0][0])!r}: allowed frequencies > 0 rad/s")
    Y = check_real("Y", Y, low=0.0, low_open=True, unit="m")
    settle = check_real("settle", settle, low=1.0, high=50.0)
    periods = check_int("periods", periods, low=1, high=1000)
    spp, dt_max = _check_steps(steps_per_period, dt_max)
    ws = w_arr.ravel()
    dts, n_steps, n_settle, s0s = _sweep_plan(
        osc, law_i, p, ws, Y, c_sky=c_sky, c_min=c_min, settle=settle, periods=periods, spp=spp, dt_max=dt_max
    )
    st = _sweep_runs(law_i, p, Y, ws, s0s, dts, n_steps, n_settle)
    if not np.all(np.isfinite(st)):
        bad = ws[~np.all(np.isfinite(st), axis=1)][0]
        raise ParameterError(
            f"omegas contains {bad!r} rad/s: the RK4 run overflowed even at a step of {dts[ws == bad][0]:.3g} s "
            f"with Y = {Y!r} m (too long for the device; allowed a smaller dt_max = {dt_max!r} s or more "
            f"steps_per_period = {spp}, or a smaller Y)"
        )
    return _sweep_record(st, w_arr, Y, periods, law)


def _sweep_record(st: np.ndarray, w_arr: np.ndarray, Y: float, periods: int, law: str) -> SemiActiveSweep:
    """The :class:`SemiActiveSweep` of the compiled sweep's per-frequency sums ``st``, shaped as ``w_arr``."""
    ws = w_arr.ravel()
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
    law: str, c_sky: float, c_min: float, *, c_max: float, Y: float, omega: float
) -> Callable[[float, float, float], float]:
    """The skyhook laws as a plain callable ``controller(t, x, v) -> f`` (s, m, m/s -> N).

    For :func:`simulate_controlled` with ``base=(Y, omega)``; ``law`` is one of
    ``"passive"``, ``"skyhook"``, ``"on-off"``, ``"clipped"`` (the MR damper has an
    internal state, so it is not memoryless). Same laws as :func:`semi_active_response`.

    Examples
    --------
    >>> f = semi_active_controller("on-off", 8.0, 0.5, c_max=15.0, Y=0.25, omega=4.47)
    >>> round(f(0.0, 0.0, 1.0), 12)     # N: v (v - v_b) = 1 (1 - 1.1175) < 0, so c_min
    0.05875
    """
    law = check_choice("law", law, SEMI_ACTIVE_LAWS[:4])
    c_sky, c_min, c_max = _check_dampings(c_sky, c_min, c_max)
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
