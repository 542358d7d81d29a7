"""Free decays with viscous and Coulomb (dry) friction: exact response, damping laws, least-squares fit.

The model and its piecewise closed form are stated in :mod:`~vibration.physics.lab.coulomb_decay` (the
exact response); :mod:`~vibration.physics.lab.damping_laws` adds amplitude-dependent laws (their
equivalent viscous ratio, the energy-balance model and its numerical check),
:mod:`~vibration.physics.lab.decay_fit` the whole-trace fit, :mod:`~vibration.physics.lab.decay_record`
its result and :mod:`~vibration.physics.lab.decay_uncertainty` its standard errors. This module gathers
their names.
"""

from __future__ import annotations

from vibration.physics.lab.coulomb_decay import MAX_HALF_CYCLES, MIN_OMEGA_N, free_decay_response
from vibration.physics.lab.damping_laws import (
    ALIASES,
    POWER_EXPONENT_RANGE,
    TERMS,
    damping_ode,
    equivalent_zeta,
    law_name,
    parse_law,
)
from vibration.physics.lab.damping_laws import _sine_power_integral as _sine_power_integral  # used by forced
from vibration.physics.lab.decay_fit import MAX_NFEV, fit_free_decay
from vibration.physics.lab.decay_record import FreeDecayFit

__all__ = [
    "ALIASES",
    "MAX_HALF_CYCLES",
    "MAX_NFEV",
    "MIN_OMEGA_N",
    "POWER_EXPONENT_RANGE",
    "TERMS",
    "FreeDecayFit",
    "damping_ode",
    "equivalent_zeta",
    "fit_free_decay",
    "free_decay_response",
    "law_name",
    "parse_law",
]
