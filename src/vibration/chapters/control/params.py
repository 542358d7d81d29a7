"""Chapter 7, control: its parameters, declared once (the PID loop's work checked before a kernel starts)."""

from __future__ import annotations

from vibration.physics.control import pid_work_check
from vibration.physics.model import Oscillator, ParameterError
from vibration.presentation.parameters import (
    count,
    damping,
    ordered,
    paper_window,
    positive,
    quantity,
    ratio,
    shared,
    shared_params,
)
from vibration.presentation.schema import Schema


def _pid_affordable(p: dict) -> None:
    """The PID loop's work stays within its budget (checked before a kernel starts)."""
    try:
        pid_work_check(Oscillator(m=p["m"], c=p["c_nominal"], k=p["k"]), p["pid_kp"], p["pid_ki"], p["pid_kd"],
                       p["t_end"], p["omega_res"])  # fmt: skip
    except ParameterError as exc:
        gains = f"pid_kp = {p['pid_kp']!r}, pid_ki = {p['pid_ki']!r}, pid_kd = {p['pid_kd']!r}"
        raise ParameterError(f"{gains} with m = {p['m']!r} kg, k = {p['k']!r} N/m: {exc}") from None


SCHEMA = Schema(
    notebook="07_control",
    params=(
        *shared_params("m", "k"),
        shared("F0", meaning="force amplitude (and k times the base amplitude of the suspension)"),
        shared("c_nominal", meaning="passive damping of the plant"),
        *shared_params("omega_res", "t_end", "n_points"),
        quantity("kp", "K_p", 16.0, unit="N/m", low=0.0, high=1e4, meaning="PD position gain"),
        damping("kd", "K_d", 5.5, low=0.0, high=1e3, meaning="PD velocity gain"),
        positive("pid_kp", "K_P", 133.6, unit="N/m", high=1e4, meaning="PID proportional gain"),
        positive("pid_ki", "K_I", 512.0, unit="N/(m s)", high=1e5, meaning="PID integral gain"),
        damping("pid_kd", "K_D", 18.7, low=0.0, high=1e3, meaning="PID derivative gain (on the measurement)"),
        positive("u_max", "u_max", 12.0, unit="N", high=1e4, meaning="actuator force limit of the PID"),
        quantity("x_ref", "x_ref", 0.5, unit="m", low=-10.0, high=10.0, meaning="set point of the PID move"),
        quantity("q_x", "q_x", 1.0, unit="1/m²", low=0.0, high=1e8, meaning="LQR weight of the displacement"),
        quantity("q_v", "q_v", 0.0, unit="s²/m²", low=0.0, high=1e8, meaning="LQR weight of the velocity"),
        quantity("r_lqr", "r", 0.001, unit="1/N²", low=1e-09, high=1e4, meaning="LQR weight of the control force"),
        damping("c_flutter", "c_f", -0.5, low=-1e3, high=0.0, meaning="negative damping of the flutter model"),
        damping("c_sky", "c_sky", 8.0, low=0.0, high=1e3, meaning="skyhook damping"),
        damping("c_sa_min", "c_min", 0.5, low=0.0, high=1e3, meaning="lowest damping of the semi-active damper"),
        damping("c_sa_max", "c_max", 15.0, low=0.0, high=1e4, meaning="highest damping of the semi-active damper"),
        positive("f_mr", "f_MR", 10.0, unit="N", high=1e3, meaning="full-voltage yield force of the scaled MR damper"),
        count("n_sweep", "N_sweep", 41, low=10, high=400, meaning="frequencies of the semi-active sweeps"),
        quantity("move", "D", 0.1, unit="m", low=-10.0, high=10.0, meaning="distance of the point-to-point move"),
        ratio(
            "freq_error",
            "ε_ω",
            0.1,
            low=-0.9,
            high=2.0,
            meaning="relative error of the model natural frequency the shapers are designed on",
        ),
    ),
    together=(paper_window, ordered("c_sa_min", "c_sa_max", "N s/m"), _pid_affordable),
)

Params = SCHEMA.record_type(module=__name__)
