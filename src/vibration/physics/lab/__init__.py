"""Lab oscillator: reader and analyses of a real driven, damped torsional oscillator.

Modules: :mod:`~vibration.physics.lab.logger` (the logger's CSV exports),
:mod:`~vibration.physics.lab.decay` (exact free decay with viscous and Coulomb friction, and its
whole-trace least-squares fit), :mod:`~vibration.physics.lab.peaks` (extrema and the classical
peak analysis, an independent estimator), :mod:`~vibration.physics.lab.harmonic` (one-harmonic
least squares), :mod:`~vibration.physics.lab.friction` (steady forced response with Coulomb +
viscous friction, Den Hartog's exact solution and harmonic balance, and a stick-slip simulator).
"""

from vibration.physics.lab.decay import FreeDecayFit, fit_free_decay, free_decay_response
from vibration.physics.lab.friction import (
    friction_forced_amplitude,
    friction_forced_amplitude_hb,
    simulate_friction_oscillator,
)
from vibration.physics.lab.harmonic import HarmonicFit, harmonic_fit
from vibration.physics.lab.logger import LoggerRun, load_logger_runs
from vibration.physics.lab.peaks import DecayPeaks, PeakDecayFit, free_decay_peaks, half_period_losses, peak_decay_fit

__all__ = [
    "DecayPeaks",
    "FreeDecayFit",
    "HarmonicFit",
    "LoggerRun",
    "PeakDecayFit",
    "fit_free_decay",
    "free_decay_peaks",
    "free_decay_response",
    "friction_forced_amplitude",
    "friction_forced_amplitude_hb",
    "half_period_losses",
    "harmonic_fit",
    "load_logger_runs",
    "peak_decay_fit",
    "simulate_friction_oscillator",
]
