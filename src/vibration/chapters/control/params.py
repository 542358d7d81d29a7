"""Chapter 7, control: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.physics.control import pid_work_check
from vibration.physics.model import Oscillator, ParameterError
from vibration.presentation.parameters import ordered, paper_window, shared
from vibration.presentation.schema import Param, Schema


def _pid_affordable(p: dict) -> None:
    """The PID loop's work stays within its budget (checked before a kernel starts)."""
    try:
        pid_work_check(Oscillator(p["m"], p["c_nominal"], p["k"]), p["pid_kp"], p["pid_ki"], p["pid_kd"],
                       p["t_end"], p["omega_res"])  # fmt: skip
    except ParameterError as exc:
        gains = f"pid_kp = {p['pid_kp']!r}, pid_ki = {p['pid_ki']!r}, pid_kd = {p['pid_kd']!r}"
        raise ParameterError(f"{gains} with m = {p['m']!r} kg, k = {p['k']!r} N/m: {exc}") from None


SCHEMA = Schema(
    "07_control",
    (
        shared("m"),
        shared("k"),
        shared("F0", meaning="force amplitude (and k times the base amplitude of the suspension)"),
        shared("c_nominal", meaning="passive damping of the plant"),
        shared("omega_res", meaning='the paper\'s "resonant" forcing frequency'),
        shared("t_end"),
        shared("n_points"),
        Param("kp", "K_p", 16.0, "N/m", 0.0, 10000.0, "PD position gain"),
        Param("kd", "K_d", 5.5, "N s/m", 0.0, 1000.0, "PD velocity gain"),
        Param("pid_kp", "K_P", 133.6, "N/m", 0.0, 10000.0, "PID proportional gain", low_open=True),
        Param("pid_ki", "K_I", 512.0, "N/(m s)", 0.0, 100000.0, "PID integral gain", low_open=True),
        Param("pid_kd", "K_D", 18.7, "N s/m", 0.0, 1000.0, "PID derivative gain (on the measurement)"),
        Param("u_max", "u_max", 12.0, "N", 0.0, 10000.0, "actuator force limit of the PID", low_open=True),
        Param("x_ref", "x_ref", 0.5, "m", -10.0, 10.0, "set point of the PID move"),
        Param("q_x", "q_x", 1.0, "1/m²", 0.0, 100000000.0, "LQR weight of the displacement"),
        Param("q_v", "q_v", 0.0, "s²/m²", 0.0, 100000000.0, "LQR weight of the velocity"),
        Param("r_lqr", "r", 0.001, "1/N²", 1e-09, 10000.0, "LQR weight of the control force"),
        Param("c_flutter", "c_f", -0.5, "N s/m", -1000.0, 0.0, "negative damping of the flutter model"),
        Param("c_sky", "c_sky", 8.0, "N s/m", 0.0, 1000.0, "skyhook damping"),
        Param("c_sa_min", "c_min", 0.5, "N s/m", 0.0, 1000.0, "lowest damping of the semi-active damper"),
        Param("c_sa_max", "c_max", 15.0, "N s/m", 0.0, 10000.0, "highest damping of the semi-active damper"),
        Param(
            "f_mr", "f_MR", 10.0, "N", 0.0, 1000.0, "full-voltage yield force of the scaled MR damper", low_open=True
        ),
        Param("n_sweep", "N_sweep", 41, "", 10, 400, "frequencies of the semi-active sweeps"),
        Param("move", "D", 0.1, "m", -10.0, 10.0, "distance of the point-to-point move"),
        Param(
            "freq_error",
            "ε_ω",
            0.1,
            "",
            -0.9,
            2.0,
            "relative error of the model natural frequency the shapers are designed on",
        ),
    ),
    together=(
        paper_window,
        ordered("c_sa_min", "c_sa_max", "N s/m"),
        _pid_affordable,
    ),
)

Params = SCHEMA.record_type()
