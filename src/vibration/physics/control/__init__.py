"""Control: active (PD, PID, LQR), semi-active (skyhook, MR damper) and input shaping (Part II).

The plant is the paper's oscillator ``m x'' + c x' + k x = F(t) + u`` (SI units: kg, N s/m,
N/m; x in m, v in m/s, forces in N, t in s).

Active control (the force ``u`` is applied to the mass by an actuator)

* :func:`pd_oscillator`: ``u = -kp x - kd v`` is the oscillator ``(m, c + kd, k + kp)``;
  :func:`stabilising_velocity_gain` is the exact boundary ``kd* = -c`` of the flutter model.
* :func:`lqr`: gains of ``u = -K [x, v]`` minimising ``J = int (q_x x^2 + q_v v^2 + r u^2) dt``
  (python-control's ``lqr``); the closed loop is again an oscillator. For this plant the
  Riccati equation has the closed form ``k + K_0 = sqrt(k^2 + q_x/r)``,
  ``c + K_1 = sqrt(c^2 + q_v/r + 2 m K_0)`` (:func:`lqr_closed_form`).
* :func:`pid_response`: PID with an actuator force limit and one of three integrator
  treatments ("none", "clamping", "back-calculation").
* :func:`simulate_controlled`: any memoryless controller given as a plain callable
  ``controller(t, x, v) -> u`` (s, m, m/s -> N), with optional force limit and optional
  harmonic base motion.

Semi-active control under base excitation ``x_b = Y sin(omega t)`` (the suspension case):
the mass hangs on the spring k and passive damper c from the base, and a controllable
device adds a force ``f`` on the mass.

* :func:`skyhook_transmissibility`: the ideal skyhook, ``f = -c_sky v`` (a damper to the
  inertial frame), exact.
* :func:`semi_active_response` and :func:`semi_active_sweep`: on-off and continuous
  clipped skyhook with the device damping bounded to ``[c_min, c_max]``, and an MR damper
  (modified Bouc-Wen model, :data:`SPENCER_1997`, scaled with :meth:`MRDamper.scaled`) switched
  by the on-off skyhook condition. Integrated with fixed-step RK4 compiled by numba.

Input shaping: :func:`zv_shaper`, :func:`zvd_shaper` (impulse times in s and amplitudes
summing to 1), :func:`shaper_residual` (residual vibration ratio, closed form) and
:func:`shaped_move` (exact response to a shaped step command).

Metrics: :func:`response_metrics` (peak and RMS displacement in the window and in steady
state, peak and RMS force, energy exchanged by the actuator).

Modules by concept: :mod:`.active` (PD, LQR, controlled simulation, metrics), :mod:`.pid` (PID with
an actuator limit), :mod:`.skyhook` (the ideal skyhook in closed form), :mod:`.mr_damper` (the MR
damper's model), :mod:`.semi_active` (on-off, clipped and MR runs and sweeps; compiled kernels in
:mod:`._kernels`), :mod:`.shaping` (ZV, ZVD, shaped moves). This package re-exports their
public names.
"""

from __future__ import annotations

from ._common import EXPM_SAMPLES_MAX, MAX_NFEV, MAX_SEGMENTS, RTOL_MAX, RTOL_MIN
from ._kernels import RK4_STEPS_MAX, SWEEP_STEPS_MAX
from .active import (
    ControlledResponse,
    LQRResult,
    Metrics,
    lqr,
    lqr_closed_form,
    pd_oscillator,
    response_metrics,
    simulate_controlled,
    stabilising_velocity_gain,
)
from .loops import (
    LoopCosts,
    PIDPoles,
    force_floor,
    hold_force,
    largest_holdable_reference,
    loop_costs,
    pid_poles,
)
from .mr_damper import SPENCER_1997, SPENCER_1997_STROKE, MRDamper
from .pid import ANTI_WINDUP, PIDResponse, pid_linear_response, pid_response, pid_work_check
from .semi_active import (
    SEMI_ACTIVE_LAWS,
    SemiActiveResponse,
    SemiActiveSweep,
    semi_active_controller,
    semi_active_response,
    semi_active_sweep,
)
from .shaping import Shaper, insensitivity_band, residual_amplitude, shaped_move, shaper_residual, zv_shaper, zvd_shaper
from .skyhook import SkyhookPower, passive_transmissibility, skyhook_power, skyhook_transmissibility

__all__ = [
    "LoopCosts",
    "PIDPoles",
    "SkyhookPower",
    "force_floor",
    "hold_force",
    "insensitivity_band",
    "largest_holdable_reference",
    "loop_costs",
    "pid_poles",
    "skyhook_power",
    "SPENCER_1997",
    "SPENCER_1997_STROKE",
    "ControlledResponse",
    "LQRResult",
    "MRDamper",
    "Metrics",
    "PIDResponse",
    "SemiActiveResponse",
    "SemiActiveSweep",
    "Shaper",
    "lqr",
    "lqr_closed_form",
    "passive_transmissibility",
    "pd_oscillator",
    "pid_linear_response",
    "pid_response",
    "pid_work_check",
    "residual_amplitude",
    "response_metrics",
    "semi_active_controller",
    "semi_active_response",
    "semi_active_sweep",
    "shaped_move",
    "shaper_residual",
    "simulate_controlled",
    "skyhook_transmissibility",
    "stabilising_velocity_gain",
    "zv_shaper",
    "zvd_shaper",
]

# constants and names the tests and benches reach through the package
_INTERNAL = (ANTI_WINDUP, SEMI_ACTIVE_LAWS, EXPM_SAMPLES_MAX, MAX_NFEV, MAX_SEGMENTS, RTOL_MAX, RTOL_MIN)
_INTERNAL += (RK4_STEPS_MAX, SWEEP_STEPS_MAX)
del _INTERNAL
