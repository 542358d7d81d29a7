r"""Free decays with viscous and Coulomb (dry) friction: exact response, damping laws, least-squares fit.


The model, for an angle :math:`\theta(t)` in rad,

.. math::

    \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2(\theta - c) = -\omega_n^2\,\Delta\,\mathrm{sgn}(\dot\theta),

has the natural angular frequency :math:`\omega_n` (rad/s), the damping ratio :math:`\zeta`, the
resting angle :math:`c` (rad, ``offset``) and the Coulomb friction expressed as the equivalent angle
:math:`\Delta` (rad, ``friction``): the friction torque divided by the spring stiffness. Between two
velocity reversals the sign is constant and the motion is a viscous free oscillation about
:math:`c - \mathrm{sgn}(\dot\theta)\Delta`, so the exact solution is piecewise closed form. Every
half cycle lasts :math:`\pi/\omega_d` with :math:`\omega_d = \omega_n\sqrt{1-\zeta^2}`, and the
distances :math:`a_k = |\theta_k - c|` of consecutive extrema from the resting angle obey

.. math::

    a_{k+1} = q\,a_k - (1 + q)\Delta, \qquad q = e^{-\pi\zeta/\sqrt{1-\zeta^2}},

a loss per half period of :math:`(1-q)a_k + (1+q)\Delta`: proportional to the amplitude for
viscous damping, the constant :math:`2\Delta` for pure Coulomb friction. The wheel sticks for good
at the first extremum inside the dead band :math:`|\theta_k - c| \le \Delta`.

The pieces live in :mod:`~vibration.physics.lab.coulomb_decay` (the exact response),
:mod:`~vibration.physics.lab.damping_laws` (amplitude-dependent laws, their equivalent viscous ratio,
the energy-balance model and its numerical check), :mod:`~vibration.physics.lab.decay_fit` (the
whole-trace fit), :mod:`~vibration.physics.lab.decay_record` (its result) and
:mod:`~vibration.physics.lab.decay_uncertainty` (its standard errors); this module gathers their names.
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
