"""Periodic orbits of the forced Duffing oscillator by Newton shooting, with their Floquet multipliers."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model import ParameterError, check_int, check_real
from .harmonic_balance import hb_amplitudes
from .model import MAX_RHS_EVALUATIONS, Duffing, _check_duffing, _Counted, _linear_rate, _OverBudget, _rates, _x_ref


@dataclass(frozen=True)
class PeriodicOrbit:
    """A periodic orbit of the forcing period, found by shooting, with its Floquet multipliers."""

    omega: float  # forcing frequency, rad/s
    x0: float  # displacement at phase 0 of the forcing, m
    v0: float  # velocity at phase 0, m/s
    amplitude: float  # half the peak-to-peak displacement, m
    multipliers: tuple[complex, complex]  # eigenvalues of the monodromy matrix
    residual: float  # |P(x0, v0) - (x0, v0)| of the converged orbit, m (velocity / omega)
    iterations: int  # Newton iterations

    @property
    def stable(self) -> bool:
        """Both multipliers inside the unit circle."""
        return max(abs(mu) for mu in self.multipliers) < 1.0


def _flow_period(d: Duffing, F0: float, w: float, x0: float, v0: float, rtol: float, events=False, budget=None):
    """One forcing period of the state and its variational equations (DOP853); ``budget`` a :class:`_Counted`."""
    from scipy.integrate import solve_ivp

    m, c, k, k3 = d.m, d.c, d.k, d.k3

    def rhs(t, y):
        if budget is not None:
            budget.calls += 1
            if budget.calls > budget.limit:
                raise _OverBudget
        x, v = y[0], y[1]
        jx = -(k + 3.0 * k3 * x * x) / m
        return (
            v,
            (F0 * math.cos(w * t) - c * v - k * x - k3 * x**3) / m,
            y[3],
            jx * y[2] - c / m * y[3],
            y[5],
            jx * y[4] - c / m * y[5],
        )

    def turning(t, y):
        return y[1]

    T = 2.0 * math.pi / w
    xr = max(abs(x0), abs(v0) / w, 1e-300)
    with np.errstate(over="ignore", invalid="ignore"):
        sol = solve_ivp(
            rhs,
            (0.0, T),
            (x0, v0, 1.0, 0.0, 0.0, 1.0),
            method="DOP853",
            rtol=rtol,
            atol=rtol * xr * 1e-3,
            events=turning if events else None,
        )
    return sol


def periodic_orbit(
    duffing: Duffing,
    F0: float,
    omega: float,
    amplitude_guess: float | None = None,
    *,
    x0: float | None = None,
    v0: float | None = None,
    rtol: float = 1e-11,
    max_iterations: int = 40,
) -> PeriodicOrbit:
    """Periodic orbit of the full equation by Newton shooting, with its Floquet multipliers.

    Newton's method on ``P(x0, v0) - (x0, v0) = 0``, ``P`` the flow over one forcing period
    (``solve_ivp``, DOP853, with the variational equations giving the monodromy matrix
    ``M = dP/d(x0, v0)``). The orbit is stable when both eigenvalues of ``M`` (the Floquet
    multipliers) lie inside the unit circle; their product is ``exp(-c T / m)`` (Liouville),
    a check of the integration. Works on unstable orbits too (the middle harmonic-balance
    branch), which time integration alone cannot reach.

    Parameters
    ----------
    duffing : Duffing
        The oscillator.
    F0 : float
        Force amplitude, N (>= 0).
    omega : float
        Forcing frequency, rad/s (> 0).
    amplitude_guess : float, optional
        Start from the one-harmonic solution with this amplitude (m); its phase is taken
        from the amplitude equation. Default: the largest harmonic-balance amplitude.
    x0, v0 : float, optional
        Start from this state at phase 0 instead (m, m/s).
    rtol : float
        Relative tolerance of DOP853 (1e-13 to 1e-6).
    max_iterations : int
        Newton iterations allowed (1 to 200).

    Returns
    -------
    PeriodicOrbit

    Raises
    ------
    ParameterError
        When Newton's method does not converge from the guess.

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> hb = hb_amplitudes(d, 5.0, 5.07)
    >>> [(round(a, 3), s) for a, s in hb]          # m, slow-flow stability
    [(1.041, True), (1.625, False), (1.97, True)]
    >>> [(round(o.amplitude, 3), o.stable) for o in (periodic_orbit(d, 5.0, 5.07, a) for a, _ in hb)]
    [(1.046, True), (1.62, False), (1.986, True)]
    """
    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    rtol = check_real("rtol", rtol, low=1e-13, high=1e-6)
    max_iterations = check_int("max_iterations", max_iterations, low=1, high=200)
    if (x0 is None) != (v0 is None):
        raise ParameterError(f"x0 = {x0!r:.30} and v0 = {v0!r:.30}: allowed both given (m, m/s) or both None")
    if x0 is None:
        if amplitude_guess is None:
            hb = hb_amplitudes(d, F0, w)
            if not hb:
                raise ParameterError(
                    f"omega = {w!r} rad/s is the undamped linear oscillator's resonance (no steady amplitude): "
                    "allowed c > 0, k3 != 0 or another omega"
                )
            amplitude_guess = max(hb)[0]
        A = check_real("amplitude_guess", amplitude_guess, low=0.0, unit="m")
        # a cos(wt) + b sin(wt): from the cosine/sine balance, a = (s + y) A^2 / F0, b = c w A^2 / F0
        s, y = d.k - d.m * w * w, d.kappa * A * A
        if F0 > 0:
            a, b = (s + y) * A * A / F0, d.c * w * A * A / F0
        else:
            a, b = A, 0.0
        x, v = a, b * w
    else:
        x = check_real("x0", x0, unit="m")
        v = check_real("v0", v0, unit="m/s")
    if not (math.isfinite(x) and math.isfinite(v)):
        raise ParameterError(
            f"amplitude_guess = {amplitude_guess!r} m gives a non-finite starting state: allowed a smaller guess"
        )
    # each period needs h lambda within DOP853's stability interval (about 6), 12 evaluations a step
    T = 2.0 * math.pi / w
    lam = _linear_rate(d, max(abs(x), _x_ref(d, F0) if F0 > 0 else 0.0))
    need = 2.0 * 12.0 * max(T * lam / 6.0, 1.0)
    if not need <= MAX_RHS_EVALUATIONS:
        raise ParameterError(
            f"omega = {w!r} rad/s (period {T:.3g} s) needs at least {need:.3g} right-hand-side evaluations for two "
            f"periods (step <= 6/lambda, lambda = {lam:.3g} 1/s: {_rates(d)}), more than {MAX_RHS_EVALUATIONS}: "
            "allowed a higher omega or a less stiff oscillator (smaller c/m, k/m)"
        )
    budget = _Counted(None, MAX_RHS_EVALUATIONS)
    try:
        return _shoot(d, F0, w, x, v, rtol, max_iterations, budget)
    except _OverBudget:
        raise ParameterError(
            f"periodic_orbit spent its budget of {MAX_RHS_EVALUATIONS} right-hand-side evaluations at omega = "
            f"{w!r} rad/s ({_rates(d)}): allowed fewer max_iterations, a looser rtol, a higher omega or a less "
            "stiff oscillator"
        ) from None


def _shoot(d: Duffing, F0: float, w: float, x: float, v: float, rtol: float, max_iterations: int, budget):
    """Damped Newton shooting from ``(x, v)``, then the orbit's multipliers (see :func:`periodic_orbit`)."""
    res = math.inf
    it = 0
    for it in range(1, max_iterations + 1):  # noqa: B007
        sol = _flow_period(d, F0, w, x, v, rtol, budget=budget)
        yT = sol.y[:, -1]
        g = np.array([yT[0] - x, yT[1] - v])
        M = np.array([[yT[2], yT[4]], [yT[3], yT[5]]])
        res = math.hypot(g[0], g[1] / w)
        scale = max(abs(x), abs(v) / w, _x_ref(d, F0) if F0 > 0 else 1.0)
        if res <= 1e-9 * scale:
            break
        try:
            dx = np.linalg.solve(M - np.eye(2), -g)
        except np.linalg.LinAlgError:
            break
        if not np.all(np.isfinite(dx)):
            break
        lam = 1.0  # damped Newton: halve the step until the residual decreases
        while lam > 1e-3:
            xt, vt = x + lam * dx[0], v + lam * dx[1]
            yt = _flow_period(d, F0, w, xt, vt, rtol, budget=budget).y[:, -1]
            if math.isfinite(yt[0]) and math.hypot(yt[0] - xt, (yt[1] - vt) / w) < res:
                break
            lam *= 0.5
        x, v = xt, vt
        if not (math.isfinite(x) and math.isfinite(v)):
            break
    else:
        it = max_iterations
    if not res <= 1e-7 * max(abs(x), abs(v) / w, 1e-300):
        raise ParameterError(
            f"periodic_orbit did not converge at omega = {w!r} rad/s (residual {res:.3g} m): allowed a guess "
            "closer to a periodic orbit (amplitude_guess or x0, v0)"
        )
    sol = _flow_period(d, F0, w, x, v, rtol, events=True, budget=budget)
    yT = sol.y[:, -1]
    M = np.array([[yT[2], yT[4]], [yT[3], yT[5]]])
    if not np.all(np.isfinite(M)):
        raise ParameterError(
            f"periodic_orbit: the monodromy matrix at omega = {w!r} rad/s is not finite (overflow): allowed "
            "parameters whose orbit and its variations stay finite over one period"
        )
    mu = np.linalg.eigvals(M)
    xe = sol.y_events[0][:, 0] if sol.y_events[0].size else sol.y[0]
    xa = np.concatenate([xe, sol.y[0]])
    return PeriodicOrbit(
        omega=w,
        x0=x,
        v0=v,
        amplitude=0.5 * float(xa.max() - xa.min()),
        multipliers=(complex(mu[0]), complex(mu[1])),
        residual=res,
        iterations=it,
    )
