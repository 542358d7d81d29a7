"""vibration: the forced mass-spring-damper, exactly and numerically.

Public API
----------
Oscillator, SineForce
    Frozen parameter records in SI units (kg, N s/m, N/m; N, rad/s).
simulate
    ``scipy.integrate.solve_ivp`` on the state-space form (the paper's method).
exact_response, steady_state
    Closed-form response in every regime, and the steady-state amplitude/phase.
magnification, phase_lag, half_power_points, log_decrement, settling_time,
energy_balance, peak_displacement_map
    Frequency-domain and window quantities.
load_scenarios, load_claims, paper_defaults
    The paper's inputs from ``data/``.
load_logger_runs, fit_free_decay, harmonic_fit, friction_forced_amplitude, ...
    Part III: a real oscillator's logger files, its free decays (viscous, Coulomb, both) and
    driven runs, and the steady response with dry friction (``vibration.physics.lab``).

Examples
--------
>>> from vibration import Oscillator, SineForce, exact_response, steady_state
>>> osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)
>>> round(steady_state(osc, force).amplitude, 3)     # m
2.237
"""

# Part II: each chapter's physics module lists its public names in __all__.
from .physics import control, duffing, lab, learning, stability, tmd, twin  # noqa: E402
from .physics.control import *  # noqa: F403
from .physics.duffing import *  # noqa: F403
from .physics.exact import Response, SteadyState, exact_response, steady_state
from .physics.frequency import (
    EnergyBalance,
    HalfPower,
    energy_balance,
    half_power_points,
    log_decrement,
    magnification,
    peak_displacement_map,
    phase_lag,
    settling_time,
)
from .physics.lab import *  # noqa: F403
from .physics.learning import *  # noqa: F403
from .physics.model import N_POINTS_MAX, REGIMES, Oscillator, ParameterError, SineForce
from .physics.numerics import METHODS, simulate
from .physics.paper import Scenario, load_claims, load_scenarios, paper_defaults
from .physics.stability import *  # noqa: F403
from .physics.tmd import *  # noqa: F403
from .physics.twin import *  # noqa: F403

__all__ = [
    "METHODS",
    "N_POINTS_MAX",
    "REGIMES",
    "EnergyBalance",
    "HalfPower",
    "Oscillator",
    "ParameterError",
    "Response",
    "Scenario",
    "SineForce",
    "SteadyState",
    "energy_balance",
    "exact_response",
    "half_power_points",
    "load_claims",
    "load_scenarios",
    "log_decrement",
    "magnification",
    "paper_defaults",
    "peak_displacement_map",
    "phase_lag",
    "settling_time",
    "simulate",
    "steady_state",
]
for _chapter in (stability, control, tmd, duffing, twin, learning, lab):
    __all__ += _chapter.__all__
del _chapter

__version__ = "0.1.0"
