"""The Duffing oscillator: harmonic balance, sweeps, jumps and chaos (Part II).

The paper's oscillator with a cubic spring, forced by a cosine,

    m x'' + c x' + k x + k3 x^3 = F0 cos(omega t),

studied two independent ways.

*Harmonic balance (one harmonic).* With ``x = a cos(omega t) + b sin(omega t)`` and
``A^2 = a^2 + b^2`` the balance of the first harmonic gives the amplitude equation

    A^2 [(k - m omega^2 + (3/4) k3 A^2)^2 + (c omega)^2] = F0^2,

a cubic in ``A^2`` solved in closed form at each omega (:func:`hb_amplitudes`). Its fold
(saddle-node) points are the roots of a quintic (:func:`folds`), its backbone is
``omega^2 = k/m + (3/4)(k3/m) A^2`` (:func:`backbone`) and, parametrised by the amplitude,
the whole response curve is explicit (:func:`response_curve`): for each ``A`` the curve's
frequencies solve a quadratic in ``omega^2``. References: A. H. Nayfeh and D. T. Mook,
*Nonlinear Oscillations* (Wiley, 1979), section 4.1 (primary resonance of the Duffing
equation); I. Kovacic and M. J. Brennan (eds), *The Duffing Equation* (Wiley, 2011).

*Stability of the harmonic-balance branches* comes from the slow flow: letting ``a, b``
vary slowly (van der Pol / averaging) gives ``a' = Q/(2 m omega)``, ``b' = -P/(2 m omega)``
with ``P, Q`` the cosine and sine residuals. Its Jacobian has trace ``-c/m`` and
determinant ``p'(A^2) / (2 m omega)^2``, where ``p(z) = z[(k - m omega^2 + 3 k3 z/4)^2 +
(c omega)^2] - F0^2``; with ``c > 0`` a branch is stable exactly when ``p'(A^2) > 0`` (no Hopf
bifurcation is possible, the trace being negative). :func:`periodic_orbit` checks this
independently: it finds the periodic orbit of the full equation by Newton shooting and its
Floquet multipliers from the variational equations.

*Time integration.* :func:`sweep` and :func:`frequency_sweep` step the forcing frequency up
or down, start each step from the previous steady state and integrate whole forcing periods
(a compiled Dormand-Prince 5(4) pair with SciPy's RK45 error control) until the
stroboscopic state is steady. :func:`poincare_section`, :func:`lyapunov_qr` and
:func:`lyapunov_benettin` integrate with a compiled fixed-step RK4 for the chaotic regime.

The package is split by concept: :mod:`.model` (the record, budgets, time response),
:mod:`.harmonic_balance`, :mod:`.sweeps`, :mod:`.orbits` and :mod:`.chaos`.
"""

from __future__ import annotations

from .chaos import (
    LyapunovEstimate,
    LyapunovResult,
    lyapunov_benettin,
    lyapunov_estimate,
    lyapunov_qr,
    poincare_section,
    pooled_exponent,
)
from .harmonic_balance import Folds, backbone, folds, hb_amplitudes, linear_trust_amplitude, response_curve

# work budgets, and the input helpers that other physics modules import from here
from .model import (
    MAX_RHS_EVALUATIONS,  # noqa: F401
    MAX_RK4_STEPS,  # noqa: F401
    MAX_SCIPY_SWEEP_STEPS,  # noqa: F401
    MAX_SWEEP_STEPS,  # noqa: F401
    NEWTON_STEPS,  # noqa: F401
    RK4_STABILITY,  # noqa: F401
    Duffing,
    _Counted,  # noqa: F401
    _real_array,  # noqa: F401
    duffing_response,
)
from .orbits import OrbitBranch, OrbitFold, PeriodicOrbit, continue_orbits, periodic_orbit
from .sweeps import SweepResult, frequency_sweep, locate_jump, sweep

__all__ = [
    "Duffing",
    "Folds",
    "LyapunovEstimate",
    "LyapunovResult",
    "OrbitBranch",
    "OrbitFold",
    "PeriodicOrbit",
    "SweepResult",
    "backbone",
    "continue_orbits",
    "duffing_response",
    "folds",
    "frequency_sweep",
    "hb_amplitudes",
    "linear_trust_amplitude",
    "lyapunov_benettin",
    "lyapunov_estimate",
    "locate_jump",
    "lyapunov_qr",
    "periodic_orbit",
    "poincare_section",
    "pooled_exponent",
    "response_curve",
    "sweep",
]
