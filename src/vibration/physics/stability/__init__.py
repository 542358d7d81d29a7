"""Stability and damping as a design choice: poles, growth, isolation, shock and random loads.

Everything here is a closed form for the oscillator ``m x'' + c x' + k x = F(t)``
(:class:`~vibration.Oscillator`, SI units), with one seeded simulation for the
random-load check.

* **Stability.** :func:`poles` are the roots of ``m s^2 + c s + k``;
  :func:`stability_class` says which of the three usual notions hold (asymptotic:
  every free response decays, ``c > 0``; Lyapunov/marginal: every free response
  stays bounded, ``c >= 0``; bounded-input bounded-output: every bounded force
  gives a bounded displacement, ``c > 0``). :func:`growth_envelope` is the closed-form
  envelope of a response from rest under ``F0 sin(omega t)``: it approaches the
  steady amplitude when ``c > 0``, grows like ``F0 t / (2 m omega_n)`` at exact
  undamped resonance and like ``exp(-c t / (2 m))`` when ``c < 0``.
* **Base excitation.** :func:`transmissibility` is ``|X/Y|`` for a base motion
  ``y = Y sin(omega t)`` (equal to the force transmissibility ``|F_T/F0|``):
  ``sqrt((1 + (2 zeta r)^2) / ((1 - r^2)^2 + (2 zeta r)^2))``, ``r = omega/omega_n``.
  Every damping gives 1 at ``r = sqrt(2)`` (:func:`isolation_frequency`); above it
  more damping transmits more.
* **Shock.** :func:`step_metrics` gives overshoot, peak, rise and settling times
  of the step response; :func:`settling_optimal_zeta` the damping ratio with the
  shortest settling time.
* **Random load.** :func:`white_noise_variance` is the stationary displacement
  variance ``pi S0 / (k c)`` under a white force of two-sided spectral density
  ``S0`` (N^2 s/rad); :func:`white_noise_monte_carlo` estimates it by simulation.
* **Cost.** :func:`damper_load` gives the damper's force amplitude and mean power
  under harmonic force; :func:`design_metrics` collects one point of the design
  trade-off.

Modules by concept: :mod:`.poles` (poles, stability notions, growth), :mod:`.transmissibility`
(base excitation, isolation), :mod:`.step` (shock), :mod:`.random_load` (white noise, Monte Carlo),
:mod:`.design` (damper load, design metrics). This package re-exports their public names.
"""

from __future__ import annotations

from ._common import _check_stable
from .design import DamperLoad, DesignMetrics, damper_load, design_metrics
from .poles import Stability, growth_envelope, poles, stability_class
from .random_load import (
    MC_CHUNK,
    MC_SAMPLES,
    MC_TOTAL_MAX,
    SAMPLES_MAX,
    MonteCarlo,
    _transition,
    simulate_white_noise,
    white_noise_force_optimum,
    white_noise_force_variance,
    white_noise_monte_carlo,
    white_noise_variance,
    white_noise_velocity_variance,
)
from .step import BAND_MIN, STEP_SAMPLES_MAX, StepMetrics, settling_optimal_zeta, step_metrics, step_response
from .transmissibility import isolation_frequency, peak_magnification, peak_transmissibility, transmissibility

__all__ = [
    "DamperLoad",
    "DesignMetrics",
    "MonteCarlo",
    "Stability",
    "StepMetrics",
    "damper_load",
    "design_metrics",
    "growth_envelope",
    "isolation_frequency",
    "peak_magnification",
    "peak_transmissibility",
    "poles",
    "settling_optimal_zeta",
    "simulate_white_noise",
    "stability_class",
    "step_metrics",
    "step_response",
    "transmissibility",
    "white_noise_force_optimum",
    "white_noise_force_variance",
    "white_noise_monte_carlo",
    "white_noise_variance",
    "white_noise_velocity_variance",
]

# names reached through the package by the control package, the tests and the benches
_INTERNAL = (_check_stable, _transition, MC_CHUNK, MC_SAMPLES, MC_TOTAL_MAX, SAMPLES_MAX)
_INTERNAL += (BAND_MIN, STEP_SAMPLES_MAX)
del _INTERNAL
