r"""Steady forced amplitude of a damping law by harmonic balance (one harmonic, equivalent linearisation).

For :math:`\ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\Delta\,\mathrm{sgn}\dot\theta + b\dot\theta|\dot\theta|
+ a|\dot\theta|^p\mathrm{sgn}\dot\theta + \omega_n^2\theta = \omega_n^2 g U \sin\omega t` and
:math:`\theta \approx X\sin(\omega t - \varphi)`, the first harmonic of the damping force is
:math:`D(X)\cos(\omega t-\varphi)` with

.. math::

    D(X) = 2\zeta\omega_n\omega X + \frac{8 b\,\omega^2 X^2}{3\pi} + \frac{2 I_{p+1}}{\pi} a(\omega X)^p
    + \frac{4\omega_n^2\Delta}{\pi}, \qquad I_m = \int_0^\pi \sin^m u\,du,

and the amplitude solves :math:`X^2(\omega_n^2-\omega^2)^2 + D(X)^2 = (\omega_n^2 g U)^2`. The wheel does
not move steadily (X = 0) when :math:`4\omega_n^2\Delta/\pi \ge \omega_n^2 g U` (Den Hartog's
harmonic-balance limit).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import optimize

from vibration.physics.lab.decay import _sine_power_integral
from vibration.physics.model import ParameterError, check_real

#: Amplitudes above this (rad) count as unbounded.
X_MAX = 1e6


def law_forced_amplitude(
    omega, *, omega_n, force, zeta=0.0, friction=0.0, quadratic=0.0, power=0.0, power_exponent=2.0
) -> np.ndarray:
    """Steady amplitude (rad) by harmonic balance at each drive frequency.

    Parameters
    ----------
    omega : float or array_like
        Drive angular frequencies (rad/s), > 0.
    omega_n : float
        Natural angular frequency (rad/s), > 0.
    force : float
        Static deflection g U (rad) the drive would give at zero frequency, >= 0.
    zeta, friction, quadratic, power, power_exponent : float
        The law's coefficients (-, rad, 1/rad, rad^(1-p) s^(p-2), -), all >= 0.

    Returns
    -------
    numpy.ndarray
        X (rad); 0 where friction holds the wheel; ``inf`` where no velocity term bounds it.

    Examples
    --------
    >>> float(law_forced_amplitude(4.5, omega_n=4.5, force=0.1, zeta=0.05)[0])  # F / (2 zeta)
    1.0
    """
    try:
        w = np.atleast_1d(np.asarray(omega, dtype=float))
    except (TypeError, ValueError):
        raise ParameterError(f"omega = {omega!r:.80} is not a number: allowed finite frequencies > 0 (rad/s)") from None
    if isinstance(omega, (bool, np.bool_)) or w.ndim != 1 or not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ParameterError(f"omega = {omega!r:.80} is out of range: allowed finite frequencies > 0 (rad/s)")
    wn = check_real("omega_n", omega_n, low=0.0, low_open=True, high=1e6, unit="rad/s")
    f = check_real("force", force, low=0.0, high=1e6, unit="rad")
    z = check_real("zeta", zeta, low=0.0, high=10.0)
    d = check_real("friction", friction, low=0.0, high=1e6, unit="rad")
    b = check_real("quadratic", quadratic, low=0.0, high=1e6, unit="1/rad")
    a = check_real("power", power, low=0.0, high=1e6)
    p = check_real("power_exponent", power_exponent, low=0.0, high=20.0)
    big_f = wn * wn * f
    d0 = 4.0 * wn * wn * d / math.pi
    kp = 2.0 * _sine_power_integral(p + 1.0) / math.pi if a else 0.0
    out = np.empty(w.size)
    for i, om in enumerate(w):
        if d0 >= big_f:
            out[i] = 0.0
            continue
        det = (wn * wn - om * om) ** 2

        def h(x, om=om, det=det):
            dx = 2.0 * z * wn * om * x + 8.0 * b * om * om * x * x / (3.0 * math.pi) + d0
            if a:
                dx += kp * a * (om * x) ** p
            return x * x * det + dx * dx - big_f * big_f

        hi = 1.0
        while h(hi) < 0 and hi < X_MAX:
            hi *= 4.0
        if h(hi) < 0:
            out[i] = math.inf
            continue
        out[i] = optimize.brentq(h, 0.0, hi, xtol=1e-12, rtol=1e-12, maxiter=200)
    return out
