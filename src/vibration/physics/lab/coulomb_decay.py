r"""Free decay with viscous and Coulomb (dry) friction: the exact, piecewise closed-form response.


The model, for an angle :math:`\theta(t)` in rad,

.. math::

    \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2(\theta - \theta_0)
    = -\omega_n^2\,\theta_f\,\mathrm{sgn}(\dot\theta),

has the natural angular frequency :math:`\omega_n` (rad/s), the damping ratio :math:`\zeta`, the
resting angle :math:`c` (rad, ``offset``) and the Coulomb friction expressed as the equivalent angle
:math:`\theta_f` (rad, ``friction``): the friction torque divided by the spring stiffness. Between two
velocity reversals the sign is constant and the motion is a viscous free oscillation about
:math:`\theta_0 - \mathrm{sgn}(\dot\theta)\theta_f`, so the exact solution is piecewise closed form. Every
half cycle lasts :math:`\pi/\omega_d` with :math:`\omega_d = \omega_n\sqrt{1-\zeta^2}`, and the
distances :math:`a_k = |\theta_k - \theta_0|` of consecutive extrema from the resting angle obey

.. math::

    a_{k+1} = q\,a_k - (1 + q)\theta_f, \qquad q = e^{-\pi\zeta/\sqrt{1-\zeta^2}},

a loss per half period of :math:`(1-q)a_k + (1+q)\theta_f`: proportional to the amplitude for
viscous damping, the constant :math:`2\theta_f` for pure Coulomb friction. The wheel sticks for good
at the first extremum inside the dead band :math:`|\theta_k - \theta_0| \le \theta_f`.
"""

from __future__ import annotations

import math

import numpy as np

from vibration.physics.lab._checks import as_series
from vibration.physics.model import ParameterError, check_real

__all__ = ["MAX_HALF_CYCLES", "MIN_OMEGA_N", "free_decay_response"]

#: Smallest natural angular frequency (rad/s) the responses accept: far below it the half period overflows.
MIN_OMEGA_N = 1e-6
#: Largest number of half cycles the exact response evaluates.
MAX_HALF_CYCLES = 100_000


def _extrema_sequence(theta0, offset, friction, q, n_half):
    """Extremum values e_k, centres and the index of the half cycle where the motion stops (or n_half)."""
    e = np.empty(n_half + 1)
    centre = np.empty(n_half)
    e[0] = theta0
    stop = n_half
    for k in range(n_half):
        d = e[k] - offset
        if abs(d) <= friction:  # inside the dead band: the spring cannot overcome static friction
            stop = k
            e[k + 1 :] = e[k]
            centre[k:] = e[k]
            break
        centre[k] = offset + math.copysign(friction, d)
        e[k + 1] = centre[k] - q * (e[k] - centre[k])
    return e, centre, stop


def _response(t, omega_n, zeta, friction, offset, theta0, t0):
    wd = omega_n * math.sqrt(1.0 - zeta * zeta)
    half = math.pi / wd
    q = math.exp(-zeta * omega_n * half)
    n_half = int(max(0.0, math.ceil((t[-1] - t0) / half))) + 1
    if n_half > MAX_HALF_CYCLES:
        raise ParameterError(
            f"t spans {n_half} half periods which is out of range: allowed at most {MAX_HALF_CYCLES} (omega_n * "
            "duration too large)"
        )
    e, centre, stop = _extrema_sequence(theta0, offset, friction, q, n_half)
    ratio = zeta / math.sqrt(1.0 - zeta * zeta)
    out = np.empty_like(t)
    before = t < t0
    if before.any():  # back from the first extremum, moving towards it: centre on the other side
        tau = t[before] - t0
        d = theta0 - offset
        c_prev = offset - math.copysign(friction, d) if d != 0 else offset
        h = np.exp(-zeta * omega_n * tau) * (np.cos(wd * tau) + ratio * np.sin(wd * tau))
        out[before] = c_prev + (theta0 - c_prev) * h
    after = ~before
    k = np.minimum(np.floor((t[after] - t0) / half).astype(np.int64), n_half - 1)
    tau = t[after] - t0 - k * half
    h = np.exp(-zeta * omega_n * tau) * (np.cos(wd * tau) + ratio * np.sin(wd * tau))
    val = centre[k] + (e[k] - centre[k]) * h
    val = np.where(k >= stop, e[min(stop, n_half)], val)
    out[after] = val
    return out


def free_decay_response(t, omega_n, zeta, *, friction, offset=0.0, theta0=1.0, t0=0.0) -> np.ndarray:
    r"""Exact free decay with viscous and Coulomb friction, starting at rest from an extremum.

    Parameters
    ----------
    t : array_like
        Times (s), strictly increasing; times before ``t0`` are evaluated backwards along the half
        cycle that ends at the extremum.
    omega_n : float
        Natural angular frequency (rad/s), 1e-6 <= omega_n <= 1e6.
    zeta : float
        Damping ratio, 0 <= zeta < 1.
    friction : float
        Coulomb friction as an equivalent angle Delta (rad), >= 0.
    offset : float
        Resting angle c (rad) of the spring.
    theta0 : float
        Angle (rad) at the extremum at ``t0``, where the velocity is zero.
    t0 : float
        Time of that extremum (s).

    Returns
    -------
    numpy.ndarray
        Angle (rad) at ``t``.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.array([0.0, np.pi / 4.0, np.pi / 2.0])
    >>> free_decay_response(t, 2.0, 0.0, friction=0.1, theta0=1.0).round(12).tolist()  # 1 -> -(1 - 2*0.1) in pi/2 s
    [1.0, 0.1, -0.8]
    """
    ta = as_series("t", t, unit="s", min_size=1)
    if ta.size > 1 and not np.all(np.diff(ta) > 0):
        raise ParameterError("t is not strictly increasing: allowed strictly increasing time (s)")
    omega_n = check_real("omega_n", omega_n, low=MIN_OMEGA_N, high=1e6, unit="rad/s")
    zeta = check_real("zeta", zeta, low=0.0, high=0.999)
    friction = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    offset = check_real("offset", offset, low=-1e6, high=1e6, unit="rad")
    theta0 = check_real("theta0", theta0, low=-1e6, high=1e6, unit="rad")
    t0 = check_real("t0", t0, low=-1e9, high=1e9, unit="s")
    return _response(ta, omega_n, zeta, friction, offset, theta0, t0)
