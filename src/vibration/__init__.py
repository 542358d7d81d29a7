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
poles, transmissibility, step_metrics, ... (Part II, chapter 6)
    Stability, isolation, shock and random load (:mod:`vibration.stability`).
lqr, simulate_controlled, skyhook_transmissibility, zv_shaper, ... (chapter 7)
    Active, semi-active and shaped control (:mod:`vibration.control`).
den_hartog, hinf_tuning, h2_tuning, tmd_peak, MDOF, shear_building, ... (chapter 8)
    Tuned mass dampers and multi-storey structures (:mod:`vibration.tmd`).
Duffing, hb_amplitudes, folds, sweep, lyapunov_qr, ... (chapter 9)
    The cubic spring (:mod:`vibration.duffing`).
load_measurements, identify, detect_change, ... (chapter 10)
    The digital twin (:mod:`vibration.twin`).
lqr_reference, OscillatorTask, OscillatorEnv, ... (chapter 11)
    The learning task; ``OscillatorEnv`` needs the ``learn`` extra (:mod:`vibration.learn`).
load_logger_runs, fit_free_decay, harmonic_fit, friction_forced_amplitude, ... (Part III)
    A real oscillator's logger files, its free decays and driven runs (:mod:`vibration.lab`).

Every other public name lives in its namespace: ``vibration.stability``, ``vibration.control``,
``vibration.tmd``, ``vibration.duffing``, ``vibration.twin``, ``vibration.learning``,
``vibration.lab`` (each the physics package of that name, with its own ``__all__``).

``import vibration`` needs only the core dependencies (numpy, scipy, numba); the chapter names load
on first use, and a name that needs an optional extra says which one when it is missing.

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
from .physics.paper import Scenario, load_claims, load_scenarios, paper_defaults

if TYPE_CHECKING:  # never run: it shows the lazy modules to static import graphs (the report's cache, linters)
    from .physics import control, duffing, lab, learning, stability, tmd, twin
    from .physics.learning import disturbance, env

__version__ = "0.1.0"

#: The names of the core, imported above.
_CORE = [
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

#: Top-level names that load on first use: module -> (extra it needs or None, names). Adding a name from a
#: subpackage is one entry in its list; the module must export it (it is checked by tests/test_package_api.py).
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
    # runs at scale: a chapter's study over a grid of parameters, gathered into an xarray Dataset
    "vibration.publishing.sweep": ("scale", ["sweep"]),
    # teaching: every chapter's exercises with answers computed from a run's parameters, and their check
    "vibration.publishing.sheets": ("book", ["check", "exercise_section", "exercises", "objectives"]),
}

#: Namespaces reachable as ``vibration.<name>``: module and the extra it needs.
_NAMESPACES: dict[str, tuple[str, str | None]] = {
    "stability": ("vibration.physics.stability", None),
    "control": ("vibration.physics.control", None),
    "tmd": ("vibration.physics.tmd", None),
    "duffing": ("vibration.physics.duffing", None),
    "twin": ("vibration.physics.twin", None),
    "learning": ("vibration.physics.learning", None),
    "lab": ("vibration.physics.lab", None),
    "learn": ("vibration.physics.learning.env", "learn"),
}

#: Third-party packages of each extra (the message of a missing one names the extra and them).
EXTRAS = {
    "scale": ("dask", "distributed", "xarray", "h5netcdf"),
    "learn": ("gymnasium", "cma"),
    "control": ("control",),
    "book": ("matplotlib", "ipywidgets", "papermill"),
}

_WHERE = {name: module for module, (_, names) in _LAZY.items() for name in names}

__all__ = _CORE + [name for _, names in _LAZY.values() for name in names]


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
        module, extra = _NAMESPACES[name]
        value = _load(module, extra, name)
    else:
        for space, (module, extra) in _NAMESPACES.items():
            if extra is None and name in getattr(importlib.import_module(module), "__all__", ()):
                raise AttributeError(
                    f"module 'vibration' has no attribute {name!r}: it is vibration.{space}.{name}", name=name
                )
        raise AttributeError(f"module 'vibration' has no attribute {name!r}", name=name)
    globals()[name] = value  # later look-ups skip __getattr__
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__) | set(_NAMESPACES))
