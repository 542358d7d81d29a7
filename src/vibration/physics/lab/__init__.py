"""Lab oscillator: reader and analyses of a real driven, damped torsional oscillator."""

from vibration.physics.lab.logger import LoggerRun, load_logger_runs

__all__ = ["LoggerRun", "load_logger_runs"]
