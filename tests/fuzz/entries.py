"""One fuzz entry per public callable of ``vibration.__all__``: a valid baseline call, from which the bad-input
battery is derived by parameter kind (the kind is read from the baseline value's type).

Adding an entry is one line: ``fuzz(vibration.name, arg=value, ...)`` with a cheap valid call (keyword arguments
by parameter name). Options: ``check=`` (what a valid result is; default every number finite), ``skip=`` (the
parameters the battery leaves alone, each with its reason in ``why``) and ``record=`` for the result records the
library builds (no battery: they are outputs, not inputs).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from fuzzing import finite

import vibration as v
import vibration.book as book
from vibration.physics import twin

ROOT = Path(__file__).resolve().parents[2]


@dataclass(frozen=True, kw_only=True)
class Entry:
    """A public callable, a valid call of it, and what the battery may do with it."""

    fn: Callable
    args: dict
    check: Callable | None = None  # result -> bool; None: every number in it finite
    skip: tuple[str, ...] = ()  # parameters left out of the battery
    why: str = ""  # why they are left out (or, for a record, why it has no battery)
    record: bool = False  # a result record the library builds: baseline only
    kinds: dict = field(default_factory=dict)  # parameter -> kind, when the baseline's type does not say it

    @property
    def name(self) -> str:
        return self.fn.__name__


ENTRIES: dict[str, Entry] = {}


def fuzz(fn, /, *, check=None, skip=(), why="", record=False, kinds=None, **args) -> Entry:
    """Declare the fuzz entry of ``fn`` (a public callable) with the valid call ``fn(**args)``."""
    if not record:
        inspect.signature(fn).bind(**args)  # the baseline names real parameters
    entry = Entry(fn=fn, args=args, check=check, skip=tuple(skip), why=why, record=record, kinds=kinds or {})
    assert entry.name not in ENTRIES, f"two fuzz entries for {entry.name}"
    ENTRIES[entry.name] = entry
    return entry


def _no_nan(out) -> bool:
    """Finite, or ``inf`` where a function documents it (an undamped resonance): never nan."""
    return not np.any(np.isnan(np.asarray(out, dtype=float)))


def finite_except(*documented: str):
    """Every number finite but in the fields whose docstring documents nan (no alarm, an escaped mass, ...)."""

    def check(out) -> bool:
        fields = getattr(out, "__dataclass_fields__", {})
        return all(finite(getattr(out, f)) for f in fields if f not in documented)

    return check


# --------------------------------------------------------------------------------------------- baselines
OSC = v.Oscillator(m=1.0, c=0.5, k=20.0)
FORCE = v.SineForce(F0=5.0, omega=4.47)
D = v.Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
T = np.linspace(0.0, 5.0, 101)
W = np.linspace(1.0, 8.0, 15)
RESP = v.exact_response(OSC, FORCE, T)
DECAY_T = np.linspace(0.0, 20.0, 2001)
DECAY_X = np.exp(-0.25 * DECAY_T) * np.cos(4.466 * DECAY_T)
TWIN_T = np.arange(0.0, 40.0, 0.02)
TWIN_F = v.random_force(TWIN_T, seed=1)
TWIN = twin.synthetic_measurements(OSC, TWIN_T, TWIN_F, noise=1e-3, seed=2)
TUNING = v.hinf_tuning(0.05)
BUILDING = v.shear_building([1.0, 1.0], [100.0, 100.0])
LAB_T = np.linspace(0.0, 30.0, 3001)
LAB_THETA = 1.2 * np.exp(-0.05 * LAB_T) * np.cos(3.0 * LAB_T)
PEAKS = v.free_decay_peaks(LAB_T, LAB_THETA)


def _cassy_file() -> Path:
    """A small CASSY Lab 2 export (German headers, ``;``, decimal comma, BOM) of a free decay at 10 Hz."""
    import tempfile

    t = np.arange(0.0, 60.0, 0.1)
    theta = 2.0 * np.exp(-0.03 * t) * np.cos(3.0 * t)
    header = "Zeit t / s;Weg &b_A1 / rad;Spannung U_B1 / V"
    rows = [";".join(f"{x:.4f}".replace(".", ",") for x in (a, b, 0.002)) for a, b in zip(t, theta, strict=True)]
    path = Path(tempfile.mkdtemp(prefix="fuzz-cassy-")) / "frei.csv"
    path.write_bytes(("\ufeff" + "\r\n".join([header, *rows]) + "\r\n").encode("utf-8"))
    return path


CASSY_FILE = _cassy_file()
TASK = v.OscillatorTask(n_steps=50)

# the core
fuzz(v.Oscillator, m=1.0, c=0.5, k=20.0)
fuzz(v.SineForce, F0=5.0, omega=4.47)
fuzz(v.exact_response, osc=OSC, force=FORCE, t=T, x0=0.1, v0=0.0)
fuzz(v.steady_state, osc=OSC, force=FORCE)
# loads as records, and the frequency domain of any harmonic one
fuzz(v.Harmonic, F0=5.0, omega=4.47, phase=0.3)
fuzz(v.Unbalance, m_e=0.1, e=0.05, omega=4.0)
fuzz(v.BaseMotion, Y=0.01, omega=4.0, phase=0.2)
fuzz(v.Step, F0=2.0, t0=0.5)
fuzz(v.Sampled, t=T, F=np.sin(T))
fuzz(v.frequency_response, osc=OSC, load=v.Unbalance(m_e=0.1, e=0.05, omega=4.0), omegas=W)
fuzz(v.peak_response, osc=OSC, load=v.BaseMotion(Y=0.01, omega=4.0))
fuzz(v.state_space, osc=OSC)
for _rec in (v.FrequencyResponse, v.Peak, v.StateSpace):
    fuzz(_rec, record=True, why="a result record the library builds and returns")
fuzz(v.simulate, osc=OSC, force=FORCE, t_end=2.0, n_points=21, x0=0.0, v0=0.0, method="RK45", rtol=1e-3, atol=1e-6)
fuzz(v.magnification, osc=OSC, omegas=W, check=_no_nan)
fuzz(v.phase_lag, osc=OSC, omegas=W)
fuzz(v.half_power_points, omegas=W, mags=v.magnification(OSC, W))
fuzz(v.log_decrement, t=DECAY_T, x=DECAY_X)
fuzz(v.settling_time, osc=OSC, force=FORCE, tol=0.02)
fuzz(v.energy_balance, osc=OSC, force=FORCE, resp=RESP)
fuzz(v.peak_displacement_map, m=1.0, k=20.0, F0=5.0, omegas=W[:3], dampings=[0.5, 1.0], t_end=5.0, n_points=51)
fuzz(v.load_claims)
fuzz(v.load_scenarios)
fuzz(v.paper_defaults)
for _rec in (v.Response, v.SteadyState, v.EnergyBalance, v.HalfPower, v.Scenario):
    fuzz(_rec, record=True, why="a result record the library builds and returns")

# chapter 6: stability
fuzz(v.poles, osc=OSC)
fuzz(v.stability_class, osc=OSC)
fuzz(v.transmissibility, osc=OSC, omegas=W, check=_no_nan)
fuzz(v.step_metrics, osc=OSC, band=0.02, F0=5.0)
fuzz(v.step_response, osc=OSC, t=T)
fuzz(v.growth_envelope, osc=OSC, force=FORCE, t=T)
fuzz(v.damper_load, osc=OSC, F0=5.0, omegas=W)
fuzz(v.white_noise_variance, osc=OSC, S0=1.0)
fuzz(v.simulate_white_noise, osc=OSC, S0=1.0, t_end=2.0, dt=0.01, n_paths=2, seed=1)

# chapter 7: control
fuzz(v.lqr, osc=OSC, q_x=1.0, q_v=1.0, r=0.01)
fuzz(v.pd_oscillator, osc=OSC, kp=10.0, kd=2.0)
fuzz(v.zv_shaper, osc=OSC)
fuzz(v.zvd_shaper, osc=OSC)
fuzz(v.Shaper, times=np.array([0.0, 0.7]), amplitudes=np.array([0.6, 0.4]), omega_n=4.47, zeta=0.05, kind="ZV")
fuzz(v.skyhook_transmissibility, osc=OSC, c_sky=5.0, omegas=W, check=_no_nan)
fuzz(v.skyhook_power, osc=OSC, c_sky=5.0, Y=0.01, omega=4.47)
fuzz(v.semi_active_controller, law="on-off", c_sky=8.0, c_min=0.5, c_max=15.0, Y=0.25, omega=4.47)
fuzz(
    v.semi_active_response, osc=OSC, law="on-off", omega=4.47, Y=0.01, c_sky=8.0, c_min=0.5, c_max=15.0,
    t_end=4.0, n_points=41,
)  # fmt: skip
fuzz(v.semi_active_sweep, osc=OSC, law="on-off", omegas=[4.0, 4.5, 5.0], Y=0.01, c_sky=8.0, c_min=0.5, c_max=15.0,
     settle=2.0, periods=2, steps_per_period=100)  # fmt: skip
fuzz(
    v.simulate_controlled, osc=OSC, controller=lambda t, x, vv: -5.0 * vv, force=FORCE, t_end=2.0, n_points=21,
    x0=0.0, v0=0.0,
)  # fmt: skip

# chapter 8: tuned mass dampers and structures
fuzz(v.den_hartog, mu=0.05, zeta_p=0.0)
fuzz(v.hinf_tuning, mu=0.05, zeta_p=0.0)
fuzz(v.h2_tuning, mu=0.05, zeta_p=0.0)
fuzz(v.robust_tuning, mu=0.05, zeta_p=0.0, band=0.05)
fuzz(
    v.TMDTuning,
    rule="x",
    mu=0.05,
    f=0.95,
    zeta_a=0.13,
    zeta_p=0.0,
    peak=6.4,
    r_peak=0.9,
    converged=True,
    check=lambda t: finite_except("peak")(t) and not np.isnan(t.peak),
)  # peak = inf documented (undamped absorber)
fuzz(v.tmd_magnification, mu=0.05, f=0.95, zeta_a=0.13, r=np.linspace(0.5, 1.5, 11), zeta_p=0.0, check=_no_nan)
fuzz(v.tmd_peak, mu=0.05, f=0.95, zeta_a=0.13, zeta_p=0.0, check=_no_nan)
fuzz(v.tmd_fixed_points, mu=0.05, f=0.95)
fuzz(v.mistuned_peak, tuning=TUNING, stiffness_error=[-0.05, 0.0, 0.05], zeta_p=0.0)
fuzz(v.MDOF, M=np.eye(2), C=np.zeros((2, 2)), K=np.array([[200.0, -100.0], [-100.0, 100.0]]),
     kinds={"M": "matrix", "C": "matrix", "K": "matrix"})  # fmt: skip
fuzz(v.shear_building, masses=[1.0, 1.0], stiffnesses=[100.0, 100.0], zeta=0.05)
fuzz(v.add_absorber, model=BUILDING, dof=1, m_a=0.05, k_a=4.0, c_a=0.1)
fuzz(v.tmd_system, m=1.0, c=0.5, k=20.0, tuning=TUNING)
fuzz(v.first_mode_absorber, model=BUILDING, mu=0.05, dof=-1, rule="H∞")

# chapter 9: the Duffing oscillator
fuzz(v.Duffing, m=1.0, c=0.5, k=20.0, k3=2.0)
fuzz(v.hb_amplitudes, duffing=D, F0=5.0, omega=5.0)
fuzz(v.folds, duffing=D, F0=5.0)
fuzz(v.response_curve, duffing=D, F0=5.0, omega_max=8.0, n=50)
fuzz(v.duffing_response, duffing=D, F0=5.0, omega=4.47, t=T, sine=True, x0=0.0, v0=0.0)
fuzz(v.frequency_sweep, duffing=D, F0=5.0, omegas=W[:3], direction="up", x0=0.0, v0=0.0, max_periods=200)
_CHAOS = {"duffing": D, "F0": 5.0, "omega": 4.47, "x0": 0.0, "v0": 0.0, "steps_per_period": 100}
fuzz(v.poincare_section, **_CHAOS, n_periods=20, n_transient=5)
fuzz(v.lyapunov_qr, **_CHAOS, n_periods=20, n_transient=5)
fuzz(v.lyapunov_benettin, **_CHAOS, n_periods=20, n_transient=5)
fuzz(v.lyapunov_estimate, **_CHAOS, n_periods=50, n_blocks=5, n_transient=5)

# chapter 10: the digital twin
fuzz(v.random_force, t=TWIN_T, band=(0.1, 2.0), rms=2.0, seed=0)
fuzz(v.identify, t=TWIN.t, force=TWIN.force, x=TWIN.x, search="local")
fuzz(v.detect_change, t=TWIN.t, force=TWIN.force, x=TWIN.x, threshold=40.0, drift=1.0, calibration=0.25)
fuzz(v.ljung_box, residual=np.random.default_rng(0).standard_normal(200), lags=10)
fuzz(v.load_measurements, path=ROOT / "data" / "twin_example.csv", kinds={"path": "path"})
fuzz(
    v.detection_experiment, osc=OSC, t=TWIN_T, force=TWIN_F, stiffness=np.full(TWIN_T.size, 20.0), change_time=20.0,
    noise=1e-3, runs=2, thresholds=[10.0, 40.0], check=finite_except("first_crossing"),
)  # fmt: skip
fuzz(v.detection_study, osc=OSC, reference=None, t_monitor=40.0, dt=0.02, noise=1e-3, decline_rate=0.0, drop=0.05,
     runs=2, thresholds=[10.0, 40.0], skip=("reference",),
     check=lambda out: all(finite_except("first_crossing")(e) for e in out.values()),
     why="reference: None or an Oscillator, tried by osc")  # fmt: skip

# chapter 11: learning
fuzz(v.OscillatorTask, m=1.0, c=0.5, k=20.0, dt=0.01, n_steps=50)
fuzz(v.lqr_reference, task=TASK)
fuzz(v.best_passive_damping, task=TASK)
fuzz(v.exosystem_optimum, task=TASK)
fuzz(v.OscillatorEnv, task=TASK)

# Part III: the real oscillator
fuzz(v.load_logger_runs, path=ROOT / "data" / "lab_oscillator" / "free_decay_no_magnet.csv", kinds={"path": "path"})
fuzz(v.fit_free_decay, t=LAB_T, theta=LAB_THETA, law="combined")
fuzz(v.peak_decay_fit, t=LAB_T, theta=LAB_THETA, law="combined")
fuzz(v.free_decay_peaks, t=LAB_T, theta=LAB_THETA)
fuzz(v.half_period_losses, peaks=PEAKS, offset=0.0)
fuzz(v.free_decay_response, t=LAB_T, omega_n=3.0, zeta=0.02, friction=0.01, offset=0.0, theta0=1.0, t0=0.0)
fuzz(v.harmonic_fit, t=LAB_T, y=LAB_THETA, omega=3.0)
fuzz(v.friction_forced_amplitude, r=np.linspace(0.5, 1.5, 11), zeta=0.05, friction_ratio=0.1, check=_no_nan)
fuzz(v.friction_forced_amplitude_hb, r=np.linspace(0.5, 1.5, 11), zeta=0.05, friction_ratio=0.1, check=_no_nan)
fuzz(v.simulate_friction_oscillator, t=LAB_T[:301], drive=0.1 * np.sin(3.0 * LAB_T[:301]), omega_n=3.0, zeta=0.05,
     friction=0.01, gain=1.0, substeps=5)  # fmt: skip
LAB_RUNS = [(LAB_T, LAB_THETA), (LAB_T, 1.1 * LAB_THETA), (LAB_T, 0.9 * LAB_THETA)]
LAB_DRIVEN = 0.5 * np.sin(3.0 * LAB_T) * (1.0 - np.exp(-0.5 * LAB_T))
fuzz(v.damping_vs_amplitude, t=LAB_T, theta=LAB_THETA)
fuzz(v.fit_free_decays, runs=LAB_RUNS, law="coulomb+viscous")
fuzz(v.compare_damping, runs_a=LAB_RUNS, runs_b=LAB_RUNS[:2], band=(0.2, 1.0))
fuzz(v.joint_brake_fit, runs_a=LAB_RUNS, runs_b=LAB_RUNS[:2])
fuzz(v.steadiness, t=LAB_T, theta=LAB_DRIVEN, omega=3.0, periods=3, tolerance=0.02)
fuzz(v.parse_law, law="coulomb+quadratic", check=lambda out: isinstance(out, tuple))
fuzz(v.equivalent_zeta, amplitude=np.linspace(0.5, 3.0, 6), omega_n=3.0, zeta=0.01, quadratic=0.01)
fuzz(
    v.law_forced_amplitude,
    omega=np.linspace(2.5, 3.5, 5),
    omega_n=3.0,
    force=0.1,
    zeta=0.02,
    friction=0.005,
    check=_no_nan,
)
fuzz(v.damping_ode, t_eval=LAB_T[:301], omega_n=3.0, zeta=0.02, friction=0.01, theta0=1.0)
fuzz(v.simulate_driven, duration=10.0, sample_interval=0.1, omega_n=3.0, force=0.1, omega=3.0, zeta=0.02,
     friction=0.005)  # fmt: skip
LAB_FOLDER = ROOT / "data" / "lab_oscillator"
fuzz(v.load_lab_data, folder=LAB_FOLDER, kinds={"folder": "path"}, check=lambda out: out is not None)
fuzz(v.check_lab_data, folder=LAB_FOLDER, kinds={"folder": "path"}, check=lambda out: out is not None)
fuzz(v.load_cassy_runs, path=CASSY_FILE, kinds={"path": "path"})
for _rec in (v.DampingCurve, v.DampingDifference, v.JointBrakeFit, v.LabCheck, v.LabData, v.LabRun):
    fuzz(_rec, record=True, why="a result record the library builds and returns")
for _rec in (v.PooledDecayFit, v.Rig, v.Steadiness):
    fuzz(_rec, record=True, why="a result record the library builds and returns")

# runs at scale: a chapter's study over a grid (the chapter and grid battery is in tests/publishing/test_sweep.py)
fuzz(book.sweep, chapter="04_frequency_response", grid={"c_nominal": [0.5, 1.0]}, params=None, client=None,
     serial=True, skip=("chapter", "grid", "params", "client", "serial"), check=lambda out: out is not None,
     why="chapter, grid, params: validated against the chapter's schema, refused naming the parameter in "
     "tests/publishing/test_sweep.py; client: a dask Client or None; serial: computes in this process, "
     "not on a cluster")  # fmt: skip
# teaching: exercises and their check (chapter names and parameters are validated against the schemas)
fuzz(book.exercises, chapter="04_frequency_response", params={"c_nominal": 0.8},
     check=lambda out: len(out) >= 4)  # fmt: skip
fuzz(book.check, exercise_id="01.1", answer=1.0, params=None, quantity="omega_n",
     skip=("answer", "quantity"), check=lambda out: isinstance(out.correct, bool),
     why="answer: any number, mapping or option letter is judged, not refused; quantity: None or a name")  # fmt: skip
fuzz(book.objectives, chapter="04_frequency_response", check=lambda out: out is not None)
fuzz(book.exercise_section, chapter="04_frequency_response", params=None,
     check=lambda out: out is not None)  # fmt: skip
for _rec in (v.DecayPeaks, v.FreeDecayFit, v.HarmonicFit, v.LoggerRun, v.PeakDecayFit):
    fuzz(_rec, record=True, why="a result record the library builds and returns")
fuzz(v.ParameterError, record=True, why="the exception the battery expects")
