"""vibration: the forced mass-spring-damper, exactly and numerically.

Public API (``vibration.__all__``: the physics only)
-----------------------------------------------------
Oscillator (also ``Oscillator.from_modal(m=, omega_n=, zeta=)``), ParameterError
    The oscillator, a frozen record in SI units (kg, N s/m, N/m), and the error every bad input raises.
SineForce, Harmonic, Unbalance, BaseMotion, Step, Sampled
    Loads as records: the paper's ``F0 sin(omega t)``, a phase, a rotating unbalance (``m_e e omega^2``),
    support motion (displacement or acceleration), a step, an arbitrary sampled force.
exact_response, simulate, steady_state
    The closed-form response in every regime, ``scipy.integrate.solve_ivp`` on the state space (the paper's
    method), and the steady state; every load record is accepted.
frequency_response, peak_response, magnification, phase_lag, half_power_points, log_decrement,
settling_time, energy_balance, peak_displacement_map
    Frequency-domain and window quantities (a scalar frequency gives a float, an array an array).
state_space
    The matrices ``A, B, C, D`` and, with python-control installed, ``.to_control()``.

Response and FrequencyResponse records draw themselves (``.plot()``, matplotlib imported only then).

Namespaces, loaded on first use and importable as modules (``from vibration.control import pid_response``):
``vibration.stability``, ``vibration.control``, ``vibration.tmd``, ``vibration.duffing``, ``vibration.twin``,
``vibration.learning``, ``vibration.lab`` (Part III's readers and fitters) and ``vibration.paper`` (the paper's
scenarios and claims). ``vibration.learn`` is the gymnasium environment (extra ``learn``). The book that uses
the library (chapters, figures, the exercise sheets and ``check``, the report runner) is ``vibration.book``.

``import vibration`` needs only numpy, scipy and numba and imports no plotting or publishing package.

Examples
--------
>>> from vibration import Oscillator, SineForce, exact_response, steady_state
>>> osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)
>>> round(steady_state(osc, force).amplitude, 3)     # m
2.237
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

from .physics.exact import Response, SteadyState, exact_response, steady_state
from .physics.forcing import (
    BaseMotion,
    FrequencyResponse,
    Harmonic,
    Peak,
    Sampled,
    Step,
    Unbalance,
    frequency_response,
    peak_response,
)
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
from .physics.model import N_POINTS_MAX, REGIMES, Oscillator, ParameterError, SineForce
from .physics.numerics import METHODS, simulate
from .physics.state_space import StateSpace, state_space

if TYPE_CHECKING:  # never run: it shows the lazy modules to static import graphs (the report's cache, linters)
    from . import control, duffing, lab, learning, paper, stability, tmd, twin
    from .physics.learning import disturbance, env

__version__ = "0.1.0"

#: The names of the core, imported above.
_CORE = [
    "METHODS",
    "N_POINTS_MAX",
    "REGIMES",
    "BaseMotion",
    "EnergyBalance",
    "FrequencyResponse",
    "HalfPower",
    "Harmonic",
    "Oscillator",
    "ParameterError",
    "Peak",
    "Response",
    "Sampled",
    "SineForce",
    "StateSpace",
    "SteadyState",
    "Step",
    "Unbalance",
    "energy_balance",
    "exact_response",
    "frequency_response",
    "half_power_points",
    "log_decrement",
    "magnification",
    "peak_displacement_map",
    "peak_response",
    "phase_lag",
    "settling_time",
    "simulate",
    "state_space",
    "steady_state",
]

#: Names that earlier versions kept at the top level: they still load on first use (module -> (extra or None,
#: names)) but are not in ``__all__``; their home is the namespace of their module.
_LAZY: dict[str, tuple[str | None, list[str]]] = {
    "vibration.physics.stability": (
        None,
        ["damper_load", "growth_envelope", "poles", "simulate_white_noise", "stability_class", "step_metrics"]
        + ["step_response", "transmissibility", "white_noise_variance"],
    ),
    "vibration.physics.control": (
        None,
        ["SPENCER_1997", "SPENCER_1997_STROKE", "Shaper", "lqr", "pd_oscillator", "semi_active_controller"]
        + ["semi_active_response", "semi_active_sweep", "simulate_controlled", "skyhook_power"]
        + ["skyhook_transmissibility", "zv_shaper", "zvd_shaper"],
    ),
    "vibration.physics.tmd": (
        None,
        ["MDOF", "TMDTuning", "add_absorber", "den_hartog", "first_mode_absorber", "h2_tuning", "hinf_tuning"]
        + ["mistuned_peak", "robust_tuning", "shear_building", "tmd_fixed_points", "tmd_magnification"]
        + ["tmd_peak", "tmd_system"],
    ),
    "vibration.physics.duffing": (
        None,
        ["Duffing", "duffing_response", "folds", "frequency_sweep", "hb_amplitudes", "lyapunov_benettin"]
        + ["lyapunov_estimate", "lyapunov_qr", "poincare_section", "response_curve"],
    ),
    "vibration.physics.twin": (
        None,
        ["detect_change", "detection_experiment", "detection_study", "identify", "ljung_box"]
        + ["load_measurements", "random_force"],
    ),
    "vibration.physics.learning": (None, ["OscillatorTask", "best_passive_damping", "lqr_reference"]),
    "vibration.physics.learning.disturbance": (None, ["exosystem_optimum"]),
    "vibration.physics.learning.env": ("learn", ["OscillatorEnv"]),
    # Part III: every name of vibration.physics.lab.__all__, listed explicitly
    "vibration.physics.lab": (
        None,
        ["DecayPeaks", "FreeDecayFit", "HarmonicFit", "LoggerRun", "PeakDecayFit", "fit_free_decay"]
        + ["free_decay_peaks", "free_decay_response", "friction_forced_amplitude", "friction_forced_amplitude_hb"]
        + ["half_period_losses", "harmonic_fit", "load_logger_runs", "peak_decay_fit"]
        + ["simulate_friction_oscillator"]
        + ["DampingCurve", "DampingDifference", "JointBrakeFit", "LabCheck", "LabData", "LabRun", "PooledDecayFit"]
        + ["Rig", "Steadiness", "check_lab_data", "compare_damping", "damping_ode", "damping_vs_amplitude"]
        + ["equivalent_zeta", "fit_free_decays", "joint_brake_fit", "law_forced_amplitude", "load_cassy_runs"]
        + ["load_lab_data", "parse_law", "simulate_driven", "steadiness"],
    ),
    "vibration.physics.paper": (None, ["Scenario", "load_claims", "load_scenarios", "paper_defaults"]),
}

#: Book helpers that left the library's namespace: name -> its home now.
_MOVED = {name: f"vibration.book.{name}" for name in ("check", "exercise_section", "exercises", "objectives", "sweep")}

#: Namespaces reachable as ``vibration.<name>`` and importable as modules: the extra each needs.
_NAMESPACES: dict[str, str | None] = {
    "stability": None,
    "control": None,
    "tmd": None,
    "duffing": None,
    "twin": None,
    "learning": None,
    "lab": None,
    "paper": None,
    "learn": "learn",
}

#: Third-party packages of each extra (the message of a missing one names the extra and them).
EXTRAS = {
    "scale": ("dask", "distributed", "xarray", "h5netcdf"),
    "learn": ("gymnasium", "cma"),
    "control": ("control",),
    "book": ("matplotlib", "ipywidgets", "papermill"),
}

_WHERE = {name: module for module, (_, names) in _LAZY.items() for name in names}

__all__ = list(_CORE)


def _load(module: str, extra: str | None, what: str):
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        if extra is None or exc.name not in EXTRAS.get(extra, ()):
            raise
        raise ImportError(
            f"vibration.{what} needs the optional extra {extra!r} ({', '.join(EXTRAS[extra])}): "
            f"pip install 'vibration[{extra}]'",
            name=exc.name,
        ) from exc


def __getattr__(name: str):
    if name in _WHERE:
        module = _WHERE[name]
        value = getattr(_load(module, _LAZY[module][0], name), name)
    elif name in _NAMESPACES:
        value = _load(f"vibration.{name}", _NAMESPACES[name], name)
    elif name in _MOVED:
        raise AttributeError(
            f"module 'vibration' has no attribute {name!r}: it is a helper of the book, now {_MOVED[name]} "
            "(pip install 'vibration[book]')",
            name=name,
        )
    else:
        for space, extra in _NAMESPACES.items():
            if (
                extra is None
                and not name.startswith("_")
                and name in getattr(_load(f"vibration.{space}", None, space), "__all__", ())
            ):
                raise AttributeError(
                    f"module 'vibration' has no attribute {name!r}: it is vibration.{space}.{name}", name=name
                )
        raise AttributeError(f"module 'vibration' has no attribute {name!r}", name=name)
    globals()[name] = value  # later look-ups skip __getattr__
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__) | set(_NAMESPACES))
