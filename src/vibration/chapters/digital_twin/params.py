"""Chapter 10, a digital twin: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.physics.model import ParameterError
from vibration.physics.twin.measurements import MIN_SAMPLES
from vibration.presentation.parameters import sampling, shared
from vibration.presentation.schema import Param, Schema

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


SCHEMA = Schema(
    "10_digital_twin",
    (
        shared("m", meaning="mass of the simulated asset"),
        shared("k", meaning="healthy spring stiffness"),
        shared("c_nominal", meaning="damping coefficient of the asset"),
        Param("F_rms", "F_rms", 2.0, "N", 0.0, 10000.0, "rms of the random test force", low_open=True),
        Param("f_max", "f_max", 2.0, "Hz", 0.2, 1000.0, "upper edge of the test force band"),
        Param("dt", "Δt", 0.02, "s", 0.0, 1.0, "sampling step of the sensors", low_open=True),
        Param("t_record", "T_rec", 60.0, "s", 0.0, 10000.0, "length of one identification test", low_open=True),
        Param("noise", "ε_x", 0.05, "", 0.0, 10.0, "sensor noise standard deviation over rms response", low_open=True),
        Param("runs", "N_MC", 500, "", 10, 2000, "Monte Carlo realisations for the interval coverage"),
        Param("sweep_runs", "N_sw", 30, "", 5, 100, "realisations per point of the error-scaling sweeps"),
        Param("assumption_runs", "N_as", 1200, "", 10, 5000, "realisations per case with a broken assumption"),
        Param("force_noise", "ε_F", 0.05, "", 0.0, 1.0, "force-noise standard deviation over rms force", low_open=True),
        Param("colour", "ρ", 0.9, "", 0.0, 0.99, "lag-one correlation of the coloured sensor noise", low_open=True),
        Param(
            "cubic",
            "κ",
            0.05,
            "",
            0.0,
            1.0,
            "unmodelled cubic spring force over kx at the rms displacement",
            low_open=True,
        ),
        Param("t_monitor", "T_mon", 240.0, "s", 0.0, 10000.0, "length of a monitored record", low_open=True),
        Param(
            "decline_rate", "r_k", 0.0005, "1/s", 0.0, 1.0, "fatigue-like stiffness loss per second as a fraction of k"
        ),
        Param("drop", "Δk/k", 0.1, "", 0.0, 0.9, "sudden stiffness loss as a fraction of k"),
        Param("detect_runs", "N_det", 100, "", 5, 300, "healthy and faulty records per detection experiment"),
        Param("threshold", "h", 40.0, "", 0.0, 1000000.0, "CUSUM alarm threshold", low_open=True),
        Param("seed", "s", 13, "", 0, 2147483647, "seed of the forces and of the noise"),
    ),
    together=(sampling, monitoring_window),
)

Params = SCHEMA.record_type()
