"""Chapter 7, control: its parameters, declared once (the PID loop's work checked before a kernel starts)."""

from __future__ import annotations

from vibration.book.presentation.parameters import (
    declared,
    ordered,
    paper_window,
)
from vibration.physics.control import pid_work_check
from vibration.physics.model import Oscillator, ParameterError


def _pid_affordable(p: dict) -> None:
    """The PID loop's work stays within its budget (checked before a kernel starts)."""
    try:
        pid_work_check(Oscillator(m=p["m"], c=p["c_nominal"], k=p["k"]), p["pid_kp"], p["pid_ki"], kd=p["pid_kd"],
                       t_end=p["t_end"], omega=p["omega_res"])  # fmt: skip
    except ParameterError as exc:
        gains = f"pid_kp = {p['pid_kp']!r}, pid_ki = {p['pid_ki']!r}, pid_kd = {p['pid_kd']!r}"
        raise ParameterError(f"{gains} with m = {p['m']!r} kg, k = {p['k']!r} N/m: {exc}") from None


SCHEMA = declared(__package__, together=(paper_window, ordered("c_sa_min", "c_sa_max", "N s/m"), _pid_affordable))

Params = SCHEMA.record_type(module=__name__)
