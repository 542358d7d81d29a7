"""Chapter 10, a digital twin: its parameters, declared once (a monitored record long enough to judge)."""

from __future__ import annotations

from vibration.book.presentation.parameters import declared, sampling
from vibration.physics.model import ParameterError
from vibration.physics.twin.measurements import MIN_SAMPLES

#: What a monitored record must hold besides its calibration quarter: the Kalman filter's settling time and two
#: of its averaging blocks, s (``KALMAN_SETTLE`` and ``KALMAN_BLOCK`` of the study; a test checks they agree).
MONITOR_SETTLE, MONITOR_BLOCK = 10.0, 20.0


def monitoring_window(p: dict) -> None:
    """A monitored record holds its samples, and after the calibration quarter the filter's settling and two blocks."""
    t, dt = p["t_monitor"], p["dt"]
    if t / dt < MIN_SAMPLES:
        raise ParameterError(
            f"t_monitor = {t!r} s holds {t / dt:.3g} samples of dt = {dt!r} s: allowed t_monitor >= "
            f"{MIN_SAMPLES} dt = {MIN_SAMPLES * dt:.4g} s"
        )
    need = (MONITOR_SETTLE + 2.0 * MONITOR_BLOCK) / 0.75
    if t < need:
        raise ParameterError(
            f"t_monitor = {t!r} s leaves {0.75 * t:.4g} s after the calibration quarter, less than the filter's "
            f"settling ({MONITOR_SETTLE:g} s) and two averaging blocks ({MONITOR_BLOCK:g} s each) before the drop "
            f"at 0.7 t_monitor is judged: allowed t_monitor >= {need:.4g} s"
        )


SCHEMA = declared(__package__, together=(sampling, monitoring_window))

Params = SCHEMA.record_type(module=__name__)
