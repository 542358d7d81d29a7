"""Lab oscillator: reader and analyses of a real driven, damped torsional oscillator.

Modules: :mod:`~vibration.physics.lab.logger` (the logger's CSV exports),
:mod:`~vibration.physics.lab.decay` (exact free decay with viscous and Coulomb friction, and its
whole-trace least-squares fit), :mod:`~vibration.physics.lab.peaks` (extrema and the classical
peak analysis, an independent estimator), :mod:`~vibration.physics.lab.harmonic` (one-harmonic
least squares), :mod:`~vibration.physics.lab.friction` (steady forced response with Coulomb +
viscous friction, Den Hartog's exact solution and harmonic balance, and a stick-slip simulator),
:mod:`~vibration.physics.lab.amplitude` (damping against amplitude, the brake at matched amplitude),
:mod:`~vibration.physics.lab.pooled` (a law fitted to many runs), :mod:`~vibration.physics.lab.steady`
(steadiness of driven runs by late drift), :mod:`~vibration.physics.lab.cassy` (CASSY Lab 2 exports) and
:mod:`~vibration.physics.lab.manifest` (a laboratory's folder described by ``runs.csv``).
"""

from vibration.physics.lab.amplitude import (
    DampingCurve,
    DampingDifference,
    JointBrakeFit,
    compare_damping,
    damping_vs_amplitude,
    joint_brake_fit,
)
from vibration.physics.lab.cassy import load_cassy_runs
from vibration.physics.lab.decay import (
    FreeDecayFit,
    damping_ode,
    equivalent_zeta,
    fit_free_decay,
    free_decay_response,
    parse_law,
)
from vibration.physics.lab.forced import law_forced_amplitude, simulate_driven
from vibration.physics.lab.friction import (
    friction_forced_amplitude,
    friction_forced_amplitude_hb,
    simulate_friction_oscillator,
)
from vibration.physics.lab.harmonic import HarmonicFit, harmonic_fit
from vibration.physics.lab.logger import LoggerRun, load_logger_runs
from vibration.physics.lab.manifest import LabCheck, LabData, LabRun, Rig, check_lab_data, load_lab_data
from vibration.physics.lab.peaks import DecayPeaks, PeakDecayFit, free_decay_peaks, half_period_losses, peak_decay_fit
from vibration.physics.lab.pooled import PooledDecayFit, fit_free_decays
from vibration.physics.lab.steady import Steadiness, steadiness

__all__ = [
    "DampingCurve",
    "DampingDifference",
    "DecayPeaks",
    "FreeDecayFit",
    "HarmonicFit",
    "JointBrakeFit",
    "LabCheck",
    "LabData",
    "LabRun",
    "LoggerRun",
    "PeakDecayFit",
    "PooledDecayFit",
    "Rig",
    "Steadiness",
    "check_lab_data",
    "compare_damping",
    "damping_ode",
    "damping_vs_amplitude",
    "equivalent_zeta",
    "fit_free_decay",
    "fit_free_decays",
    "free_decay_peaks",
    "free_decay_response",
    "friction_forced_amplitude",
    "friction_forced_amplitude_hb",
    "half_period_losses",
    "harmonic_fit",
    "joint_brake_fit",
    "law_forced_amplitude",
    "load_cassy_runs",
    "load_lab_data",
    "load_logger_runs",
    "parse_law",
    "peak_decay_fit",
    "simulate_driven",
    "simulate_friction_oscillator",
    "steadiness",
]
