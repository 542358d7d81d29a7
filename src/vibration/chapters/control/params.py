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
        pid_work_check(Oscillator(m=p["m"], c=p["c_nominal"], k=p["k"]), p["pid_kp"], p["pid_ki"], p["pid_kd"],
                       p["t_end"], p["omega_res"])  # fmt: skip
    except ParameterError as exc:
        gains = f"pid_kp = {p['pid_kp']!r}, pid_ki = {p['pid_ki']!r}, pid_kd = {p['pid_kd']!r}"
        raise ParameterError(f"{gains} with m = {p['m']!r} kg, k = {p['k']!r} N/m: {exc}") from None


SCHEMA = Schema(
    notebook="07_control",
    params=(
        shared("m"),
        shared("k"),
        shared("F0", meaning="force amplitude (and k times the base amplitude of the suspension)"),
        shared("c_nominal", meaning="passive damping of the plant"),
        shared("omega_res", meaning='the paper\'s "resonant" forcing frequency'),
        shared("t_end"),
        shared("n_points"),
        Param(name="kp", symbol="K_p", default=16.0, unit="N/m", low=0.0, high=10000.0, meaning="PD position gain"),
        Param(name="kd", symbol="K_d", default=5.5, unit="N s/m", low=0.0, high=1000.0, meaning="PD velocity gain"),
        Param(
            name="pid_kp",
            symbol="K_P",
            default=133.6,
            unit="N/m",
            low=0.0,
            high=10000.0,
            meaning="PID proportional gain",
            low_open=True,
        ),
        Param(
            name="pid_ki",
            symbol="K_I",
            default=512.0,
            unit="N/(m s)",
            low=0.0,
            high=100000.0,
            meaning="PID integral gain",
            low_open=True,
        ),
        Param(
            name="pid_kd",
            symbol="K_D",
            default=18.7,
            unit="N s/m",
            low=0.0,
            high=1000.0,
            meaning="PID derivative gain (on the measurement)",
        ),
        Param(
            name="u_max",
            symbol="u_max",
            default=12.0,
            unit="N",
            low=0.0,
            high=10000.0,
            meaning="actuator force limit of the PID",
            low_open=True,
        ),
        Param(
            name="x_ref",
            symbol="x_ref",
            default=0.5,
            unit="m",
            low=-10.0,
            high=10.0,
            meaning="set point of the PID move",
        ),
        Param(
            name="q_x",
            symbol="q_x",
            default=1.0,
            unit="1/m²",
            low=0.0,
            high=100000000.0,
            meaning="LQR weight of the displacement",
        ),
        Param(
            name="q_v",
            symbol="q_v",
            default=0.0,
            unit="s²/m²",
            low=0.0,
            high=100000000.0,
            meaning="LQR weight of the velocity",
        ),
        Param(
            name="r_lqr",
            symbol="r",
            default=0.001,
            unit="1/N²",
            low=1e-09,
            high=10000.0,
            meaning="LQR weight of the control force",
        ),
        Param(
            name="c_flutter",
            symbol="c_f",
            default=-0.5,
            unit="N s/m",
            low=-1000.0,
            high=0.0,
            meaning="negative damping of the flutter model",
        ),
        Param(name="c_sky", symbol="c_sky", default=8.0, unit="N s/m", low=0.0, high=1000.0, meaning="skyhook damping"),
        Param(
            name="c_sa_min",
            symbol="c_min",
            default=0.5,
            unit="N s/m",
            low=0.0,
            high=1000.0,
            meaning="lowest damping of the semi-active damper",
        ),
        Param(
            name="c_sa_max",
            symbol="c_max",
            default=15.0,
            unit="N s/m",
            low=0.0,
            high=10000.0,
            meaning="highest damping of the semi-active damper",
        ),
        Param(
            name="f_mr",
            symbol="f_MR",
            default=10.0,
            unit="N",
            low=0.0,
            high=1000.0,
            meaning="full-voltage yield force of the scaled MR damper",
            low_open=True,
        ),
        Param(
            name="n_sweep",
            symbol="N_sweep",
            default=41,
            unit="",
            low=10,
            high=400,
            meaning="frequencies of the semi-active sweeps",
        ),
        Param(
            name="move",
            symbol="D",
            default=0.1,
            unit="m",
            low=-10.0,
            high=10.0,
            meaning="distance of the point-to-point move",
        ),
        Param(
            name="freq_error",
            symbol="ε_ω",
            default=0.1,
            unit="",
            low=-0.9,
            high=2.0,
            meaning="relative error of the model natural frequency the shapers are designed on",
        ),
    ),
    together=(
        paper_window,
        ordered("c_sa_min", "c_sa_max", "N s/m"),
        _pid_affordable,
    ),
)

Params = SCHEMA.record_type()
