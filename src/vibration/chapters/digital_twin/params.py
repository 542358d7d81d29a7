"""Chapter 10, a digital twin: its parameters, declared once (a monitored record long enough to judge)."""

from __future__ import annotations

from vibration.physics.model import ParameterError
from vibration.physics.twin.measurements import MIN_SAMPLES
from vibration.presentation.parameters import count, positive, quantity, ratio, sampling, seed, shared
from vibration.presentation.schema import Schema

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
    notebook="10_digital_twin",
    params=(
        shared("m", meaning="mass of the simulated asset"),
        shared("k", meaning="healthy spring stiffness"),
        shared("c_nominal", meaning="damping coefficient of the asset"),
        positive("F_rms", "F_rms", 2.0, unit="N", high=1e4, meaning="rms of the random test force"),
        quantity("f_max", "f_max", 2.0, unit="Hz", low=0.2, high=1e3, meaning="upper edge of the test force band"),
        positive("dt", "Δt", 0.02, unit="s", high=1.0, meaning="sampling step of the sensors"),
        positive("t_record", "T_rec", 60.0, unit="s", high=1e4, meaning="length of one identification test"),
        positive("noise", "ε_x", 0.05, unit="", high=10.0, meaning="sensor noise standard deviation over rms response"),
        count("runs", "N_MC", 500, low=10, high=2000, meaning="Monte Carlo realisations for the interval coverage"),
        count("sweep_runs", "N_sw", 30, low=5, high=100, meaning="realisations per point of the error-scaling sweeps"),
        count(
            "assumption_runs", "N_as", 1200, low=10, high=5000, meaning="realisations per case with a broken assumption"
        ),
        positive(
            "force_noise", "ε_F", 0.05, unit="", high=1.0, meaning="force-noise standard deviation over rms force"
        ),
        positive("colour", "ρ", 0.9, unit="", high=0.99, meaning="lag-one correlation of the coloured sensor noise"),
        positive(
            "cubic",
            "κ",
            0.05,
            unit="",
            high=1.0,
            meaning="unmodelled cubic spring force over kx at the rms displacement",
        ),
        positive("t_monitor", "T_mon", 240.0, unit="s", high=1e4, meaning="length of a monitored record"),
        quantity(
            "decline_rate",
            "r_k",
            0.0005,
            unit="1/s",
            low=0.0,
            high=1.0,
            meaning="fatigue-like stiffness loss per second as a fraction of k",
        ),
        ratio("drop", "Δk/k", 0.1, low=0.0, high=0.9, meaning="sudden stiffness loss as a fraction of k"),
        count(
            "detect_runs", "N_det", 100, low=5, high=300, meaning="healthy and faulty records per detection experiment"
        ),
        positive("threshold", "h", 40.0, unit="", high=1e6, meaning="CUSUM alarm threshold"),
        seed(13, meaning="seed of the forces and of the noise"),
    ),
    together=(sampling, monitoring_window),
)

Params = SCHEMA.record_type(module=__name__)
