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
    notebook="10_digital_twin",
    params=(
        shared("m", meaning="mass of the simulated asset"),
        shared("k", meaning="healthy spring stiffness"),
        shared("c_nominal", meaning="damping coefficient of the asset"),
        Param(
            name="F_rms",
            symbol="F_rms",
            default=2.0,
            unit="N",
            low=0.0,
            high=10000.0,
            meaning="rms of the random test force",
            low_open=True,
        ),
        Param(
            name="f_max",
            symbol="f_max",
            default=2.0,
            unit="Hz",
            low=0.2,
            high=1000.0,
            meaning="upper edge of the test force band",
        ),
        Param(
            name="dt",
            symbol="Δt",
            default=0.02,
            unit="s",
            low=0.0,
            high=1.0,
            meaning="sampling step of the sensors",
            low_open=True,
        ),
        Param(
            name="t_record",
            symbol="T_rec",
            default=60.0,
            unit="s",
            low=0.0,
            high=10000.0,
            meaning="length of one identification test",
            low_open=True,
        ),
        Param(
            name="noise",
            symbol="ε_x",
            default=0.05,
            unit="",
            low=0.0,
            high=10.0,
            meaning="sensor noise standard deviation over rms response",
            low_open=True,
        ),
        Param(
            name="runs",
            symbol="N_MC",
            default=500,
            unit="",
            low=10,
            high=2000,
            meaning="Monte Carlo realisations for the interval coverage",
        ),
        Param(
            name="sweep_runs",
            symbol="N_sw",
            default=30,
            unit="",
            low=5,
            high=100,
            meaning="realisations per point of the error-scaling sweeps",
        ),
        Param(
            name="assumption_runs",
            symbol="N_as",
            default=1200,
            unit="",
            low=10,
            high=5000,
            meaning="realisations per case with a broken assumption",
        ),
        Param(
            name="force_noise",
            symbol="ε_F",
            default=0.05,
            unit="",
            low=0.0,
            high=1.0,
            meaning="force-noise standard deviation over rms force",
            low_open=True,
        ),
        Param(
            name="colour",
            symbol="ρ",
            default=0.9,
            unit="",
            low=0.0,
            high=0.99,
            meaning="lag-one correlation of the coloured sensor noise",
            low_open=True,
        ),
        Param(
            name="cubic",
            symbol="κ",
            default=0.05,
            unit="",
            low=0.0,
            high=1.0,
            meaning="unmodelled cubic spring force over kx at the rms displacement",
            low_open=True,
        ),
        Param(
            name="t_monitor",
            symbol="T_mon",
            default=240.0,
            unit="s",
            low=0.0,
            high=10000.0,
            meaning="length of a monitored record",
            low_open=True,
        ),
        Param(
            name="decline_rate",
            symbol="r_k",
            default=0.0005,
            unit="1/s",
            low=0.0,
            high=1.0,
            meaning="fatigue-like stiffness loss per second as a fraction of k",
        ),
        Param(
            name="drop",
            symbol="Δk/k",
            default=0.1,
            unit="",
            low=0.0,
            high=0.9,
            meaning="sudden stiffness loss as a fraction of k",
        ),
        Param(
            name="detect_runs",
            symbol="N_det",
            default=100,
            unit="",
            low=5,
            high=300,
            meaning="healthy and faulty records per detection experiment",
        ),
        Param(
            name="threshold",
            symbol="h",
            default=40.0,
            unit="",
            low=0.0,
            high=1000000.0,
            meaning="CUSUM alarm threshold",
            low_open=True,
        ),
        Param(
            name="seed",
            symbol="s",
            default=13,
            unit="",
            low=0,
            high=2147483647,
            meaning="seed of the forces and of the noise",
        ),
    ),
    together=(sampling, monitoring_window),
)

Params = SCHEMA.record_type()
