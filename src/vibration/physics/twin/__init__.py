"""A digital twin: measurements, identification, tracking and change detection (Part II).

Modules, by concept: :mod:`.measurements` (the record, its file format and input checks),
:mod:`.sampled` (exact discretisation, sampled response), :mod:`.synthetic` (synthetic records),
:mod:`.identification` (least squares with intervals, frequency-domain estimates),
:mod:`.tracking` (Kalman tracking of k, CUSUM change detection), :mod:`.validation` (residual
tests, records that break the assumptions, first-order coverage), :mod:`.experiments` (Monte Carlo
identification: coverage, error scaling), :mod:`.assumptions` (violated assumptions) and
:mod:`.detection` (detection trade-offs, fault scenarios). Their public names are re-exported here.

The twin is the linear oscillator ``m x'' + c x' + k x = F(t)`` fed with a measured
force and compared with a measured displacement ``x`` or acceleration ``a``.

Model of the data (the assumptions every function here relies on)
-----------------------------------------------------------------
* The force is measured without noise and sampled uniformly (step ``h``); between
  samples it is taken as linear (first-order hold). That is exact for a
  piecewise-linear force and accurate to ``h^2 |F''| / 8`` otherwise, so the force
  should be band-limited well below the Nyquist frequency ``pi / h``.
* The response is sampled at the same instants and carries additive white
  Gaussian noise of constant standard deviation (m for ``x``, m/s^2 for ``a``);
  no offset, no drift, no noise on the force.
* The initial state ``x(t0), v(t0)`` is unknown and estimated with the parameters.
* Over the analysed window the parameters are constant (identification) or
  constant until a change (detection), and the first part of a monitored record
  is healthy when no reference is given.

Exact discretisation
--------------------
With ``z = (x, v)``, ``z' = A z + B F``, ``A = [[0, 1], [-k/m, -c/m]]``,
``B = (0, 1/m)`` and ``F`` linear on ``[t_n, t_n + h]``, the state advances
exactly as ``z[n+1] = Phi z[n] + (P0 - P1) F[n] + P1 F[n+1]`` where
``expm(h [[A, B, 0], [0, 0, 1/h], [0, 0, 0]]) = [[Phi, P0, P1], ...]``
(one 4 x 4 matrix exponential per step size and parameter set). The recursion is
run as a second-order IIR filter (``scipy.signal.lfilter``), so a response costs
one matrix exponential and one pass over the samples.

Identification
--------------
Nonlinear least squares on that exact discrete model (output error). The
output is linear in ``1/m`` and in the initial state once ``omega_n`` and
``zeta`` are fixed, so those three are projected out (variable projection) and a
global grid over ``(omega_n, zeta)``, a frequency-domain (Levy) start and a
local ``least_squares`` polish find the minimum. Standard errors come from the
Jacobian of the full model in ``(m, c, k, x0, v0)`` at the optimum,
``cov = s^2 (J^T J)^-1`` with ``s^2 = RSS / (N - 5)``, and the 95 % intervals
use Student's t with ``N - 5`` degrees of freedom.

Tracking and detection
----------------------
:func:`track_stiffness` is an extended Kalman filter on ``(x, v, k)`` with a
random walk on ``k``; :func:`detect_change` runs a one-sided CUSUM on the
normalised squared output-error residual of the reference model.

Examples
--------
>>> from vibration import Oscillator
>>> t = np.arange(0.0, 60.0, 0.02)
>>> meas = synthetic_measurements(Oscillator(m=1.0, c=0.5, k=20.0), t, random_force(t, seed=1), noise=1e-3, seed=2)
>>> fit = identify(meas.t, meas.force, x=meas.x)
>>> [round(v, 2) for v in (fit.m, fit.c, fit.k)]      # kg, N s/m, N/m
[1.0, 0.5, 20.0]
"""

from __future__ import annotations

import numpy as np  # noqa: F401 - the examples above use np

from .assumptions import ASSUMPTION_CASES, AssumptionStudy, assumption_study  # noqa: F401 - as twin.NAME
from .detection import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    THRESHOLDS,
    DetectionExperiment,
    FaultScenario,
    detection_experiment,
    detection_study,
    fault_scenario,
)
from .experiments import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    MAX_EXPERIMENT_SAMPLES,
    CoverageExperiment,
    EstimateGrid,
    RunResults,
    estimate_grid,
    identification_experiment,
    identification_sweep,
)
from .identification import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    GRID_STEP,
    GRID_ZETAS,
    FrequencyEstimate,
    FrequencyResponse,
    Identification,
    frequency_estimates,
    frf_estimate,
    identify,
)
from .measurements import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    ACCELERATION,
    COLUMNS,
    DISPLACEMENT,
    FORCE,
    MAX_ABS,
    MAX_BYTES,
    MIN_SAMPLES,
    SEED_MAX,
    TIME,
    UNIFORM_TOL,
    Measurements,
    load_measurements,
    measurements_csv,
    save_measurements,
)
from .sampled import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    MAX_RHS_EVALUATIONS,
    Discretization,
    SampledResponse,
    discretisation_checks,
    discretize,
    expm_batch,
    sampled_response,
)
from .synthetic import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    MAX_MULTISINE_TERMS,
    example_measurements,
    random_force,
    simulated_test,
    stiffness_profile,
    synthetic_measurements,
)
from .tracking import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    CALIBRATION,
    CUSUM_DRIFT,
    CUSUM_THRESHOLD,
    K_QUANTUM,
    MAX_TRACK_SAMPLES,
    ChangeDetection,
    StiffnessTrack,
    _cusum,
    cusum_variance_ratio,
    detect_change,
    track_stiffness,
)
from .validation import (  # noqa: F401 - constants and helpers kept reachable as twin.NAME
    WHITENESS_LAGS,
    binomial_halfwidth,
    cubic_response,
    input_correlation,
    ljung_box,
    predicted_coverage,
)

__all__ = [
    "AssumptionStudy",
    "ChangeDetection",
    "Discretization",
    "EstimateGrid",
    "FaultScenario",
    "THRESHOLDS",
    "FrequencyEstimate",
    "FrequencyResponse",
    "Identification",
    "Measurements",
    "SampledResponse",
    "StiffnessTrack",
    "detect_change",
    "cusum_variance_ratio",
    "assumption_study",
    "binomial_halfwidth",
    "cubic_response",
    "input_correlation",
    "ljung_box",
    "predicted_coverage",
    "CoverageExperiment",
    "RunResults",
    "DetectionExperiment",
    "detection_experiment",
    "detection_study",
    "discretisation_checks",
    "fault_scenario",
    "estimate_grid",
    "identification_experiment",
    "identification_sweep",
    "discretize",
    "expm_batch",
    "example_measurements",
    "frequency_estimates",
    "frf_estimate",
    "identify",
    "load_measurements",
    "measurements_csv",
    "random_force",
    "sampled_response",
    "save_measurements",
    "simulated_test",
    "stiffness_profile",
    "synthetic_measurements",
    "track_stiffness",
]
