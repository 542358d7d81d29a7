"""Periodic orbits of the forced Duffing oscillator by Newton shooting, with their Floquet multipliers."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..checks import OverBudget
from ..model import ParameterError, check_int, check_real
from .harmonic_balance import hb_amplitudes
from .model import MAX_RHS_EVALUATIONS, Duffing, _check_duffing, _Counted, _linear_rate, _rates, _x_ref


@dataclass(frozen=True, kw_only=True)
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
                raise OverBudget
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
    *,
    amplitude_guess: float | None = None,
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
    F0, omega : float
        Force amplitude, N (>= 0), and forcing frequency, rad/s (> 0).
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
    >>> [(round(o.amplitude, 3), o.stable) for o in (periodic_orbit(d, 5.0, 5.07, amplitude_guess=a) for a, _ in hb)]
    [(1.046, True), (1.62, False), (1.986, True)]
    """
    d = _check_duffing(duffing)
    F0 = check_real("F0", F0, low=0.0, unit="N")
    w = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    rtol = check_real("rtol", rtol, low=1e-13, high=1e-6)
    max_iterations = check_int("max_iterations", max_iterations, low=1, high=200)
    x, v = _orbit_start(d, F0, w, amplitude_guess, x0, v0)
    _check_orbit_work(d, F0, w, x)
    budget = _Counted(None, MAX_RHS_EVALUATIONS)
    try:
        return _shoot(d, F0, w, x, v, rtol, max_iterations, budget)
    except OverBudget:
        raise ParameterError(
            f"periodic_orbit spent its budget of {MAX_RHS_EVALUATIONS} right-hand-side evaluations at omega = "
            f"{w!r} rad/s ({_rates(d)}): allowed fewer max_iterations, a looser rtol, a higher omega or a less "
            "stiff oscillator"
        ) from None


def _orbit_start(d: Duffing, F0: float, w: float, amplitude_guess, x0, v0) -> tuple[float, float]:
    """The checked starting state ``(x, v)`` (m, m/s) of :func:`periodic_orbit`: ``(x0, v0)`` or the guess's."""
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
    return x, v


def _check_orbit_work(d: Duffing, F0: float, w: float, x: float) -> None:
    """Refuse up front a shooting of :func:`periodic_orbit` from ``x`` (m) whose two periods need too much work."""
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


# ------------------------------------------------------------------------ continuation and folds


@dataclass(frozen=True, kw_only=True)
class OrbitFold:
    """A fold (saddle-node) of the periodic orbit of the full equation: the branch turns back in omega."""

    omega: float  # fold frequency, rad/s
    amplitude: float  # half the peak-to-peak displacement of the orbit there, m
    multiplier: float  # the Floquet multiplier closest to +1 at the located fold (1 at an exact fold)
    det: float  # det(M - I) at the located fold (0 at an exact fold)


@dataclass(frozen=True, kw_only=True)
class OrbitBranch:
    """Periodic orbits of the forcing period along a branch, by pseudo-arclength continuation in omega."""

    omega: np.ndarray  # forcing frequency of each point, rad/s (in order along the branch)
    amplitude: np.ndarray  # half the peak-to-peak displacement, m
    x0: np.ndarray  # displacement at phase 0 of the forcing, m
    v0: np.ndarray  # velocity at phase 0, m/s
    max_multiplier: np.ndarray  # largest |Floquet multiplier| at each point
    folds: tuple[OrbitFold, ...]  # where the branch turns, in order along it

    @property
    def stable(self) -> np.ndarray:
        """Both multipliers inside the unit circle at each point."""
        return self.max_multiplier < 1.0


def _orbit_map(d: Duffing, F0: float, z: np.ndarray, rtol: float, budget, events: bool = False):
    """``G = P(x, v) - (x, v)`` and the monodromy matrix ``M`` at ``z = (x, v, omega)`` (and the amplitude)."""
    sol = _flow_period(d, F0, float(z[2]), float(z[0]), float(z[1]), rtol, events=events, budget=budget)
    yT = sol.y[:, -1]
    G = np.array([yT[0] - z[0], yT[1] - z[1]])
    M = np.array([[yT[2], yT[4]], [yT[3], yT[5]]])
    amp = math.nan
    if events:
        xe = sol.y_events[0][:, 0] if sol.y_events[0].size else sol.y[0]
        xa = np.concatenate([xe, sol.y[0]])
        amp = 0.5 * float(xa.max() - xa.min())
    return G, M, amp


def continue_orbits(
    duffing: Duffing,
    F0: float,
    omega_start: float,
    *,
    omega_end: float,
    amplitude_guess: float | None = None,
    step: float = 0.05,
    max_points: int = 400,
    rtol: float = 1e-10,
) -> OrbitBranch:
    """Follow the periodic orbit of the full equation from ``omega_start`` until omega leaves the range.

    Pseudo-arclength continuation (Keller) of the shooting equations ``P(x0, v0; omega) =
    (x0, v0)`` in the scaled unknowns ``(x0/a, v0/(a omega_start), omega/|omega_end -
    omega_start|)``: an Euler predictor along the tangent, Newton correction on the hyperplane
    normal to it (the monodromy matrix ``M`` from the variational equations, ``dP/domega`` by a
    forward difference), the step halved when Newton fails and lengthened when it converges fast.
    The tangent's omega component is proportional to ``det(M - I)``, so the branch turns in
    omega exactly where a Floquet multiplier passes +1: each sign change is a fold, located by
    the secant (Illinois) method on ``det(M - I)`` along the branch.

    Parameters
    ----------
    duffing : Duffing
        The damped oscillator (c > 0).
    F0 : float
        Force amplitude (> 0), N.
    omega_start, omega_end : float
        Start of the branch and the frequency it is followed to, rad/s (> 0, different); the
        branch stops when omega leaves the interval between them.
    amplitude_guess : float, optional
        One-harmonic amplitude of the starting orbit, m (default as :func:`periodic_orbit`).
    step : float
        Largest arclength step in the scaled unknowns (1e-4 to 0.5).
    max_points : int
        Most points along the branch (10 to 5000).
    rtol : float
        Relative tolerance of DOP853 (1e-12 to 1e-7).

    Returns
    -------
    OrbitBranch

    Examples
    --------
    >>> d = Duffing(m=1.0, c=0.5, k=20.0, k3=2.0)
    >>> b = continue_orbits(d, 5.0, 4.9, omega_end=5.25)
    >>> [round(f.omega, 4) for f in b.folds]           # rad/s: the branch turns twice
    [5.1079, 5.0447]
    """
    d, F0, w0, w1, step, max_points, rtol = _continuation_args(
        duffing, F0, omega_start, omega_end, step, max_points, rtol
    )
    orb = periodic_orbit(d, F0, w0, amplitude_guess=amplitude_guess, rtol=rtol)
    budget = _Counted(None, 400 * MAX_RHS_EVALUATIONS)
    a = max(orb.amplitude, 1e-300)
    scale = np.array([a, a * w0, abs(w1 - w0)])  # physical = scale * scaled
    lo, hi = min(w0, w1), max(w0, w1)
    correct = functools.partial(_correct_on_branch, d, F0, rtol, budget, scale, lo - abs(w1 - w0))
    z = np.array([orb.x0, orb.v0, w0])
    G, M, amp = _orbit_map(d, F0, z, rtol, budget, events=True)
    J = _branch_jacobian(d, F0, z, G, M, rtol, budget, scale)
    t = _branch_tangent(J, np.array([0.0, 0.0, 1.0 if w1 > w0 else -1.0]))
    pts, folds = _follow_branch(
        d, F0, z, t, (z.copy(), amp, M.copy()), step, max_points, (lo, hi), rtol, budget, correct
    )
    zs = np.array([p[0] for p in pts])
    mus = np.array([max(abs(m) for m in np.linalg.eigvals(p[2])) for p in pts])
    return OrbitBranch(
        omega=zs[:, 2],
        amplitude=np.array([p[1] for p in pts]),
        x0=zs[:, 0],
        v0=zs[:, 1],
        max_multiplier=mus,
        folds=tuple(folds),
    )


def _continuation_args(duffing, F0, omega_start, omega_end, step, max_points, rtol):
    """The checked arguments of :func:`continue_orbits`: ``(d, F0, w0, w1, step, max_points, rtol)``."""
    d = _check_duffing(duffing)
    if d.c <= 0.0:
        raise ParameterError(f"c = {d.c!r} N s/m is out of range: allowed c > 0 N s/m (continuation needs damping)")
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    w0 = check_real("omega_start", omega_start, low=0.0, low_open=True, unit="rad/s")
    w1 = check_real("omega_end", omega_end, low=0.0, low_open=True, unit="rad/s")
    if w0 == w1:
        raise ParameterError(f"omega_end = {w1!r} rad/s equals omega_start: allowed a different frequency")
    step = check_real("step", step, low=1e-4, high=0.5)
    max_points = check_int("max_points", max_points, low=10, high=5000)
    rtol = check_real("rtol", rtol, low=1e-12, high=1e-7)
    return d, F0, w0, w1, step, max_points, rtol


def _branch_jacobian(d, F0, z, G, M, rtol, budget, scale):
    """The 2 x 3 Jacobian of the scaled residual at z (physical), from M and a difference in omega."""
    dw = 1e-7 * z[2]
    G2, _, _ = _orbit_map(d, F0, z + np.array([0.0, 0.0, dw]), rtol, budget)
    J = np.column_stack([M - np.eye(2), (G2 - G) / dw]) * scale  # d G / d scaled
    return J / scale[:2, None]  # rows scaled as the unknowns


def _branch_tangent(J, prev):
    """The unit null vector of ``J`` (the branch's tangent), oriented along ``prev`` when given."""
    t = np.cross(J[0], J[1])
    t /= np.linalg.norm(t)
    return t if prev is None or np.dot(t, prev) >= 0 else -t


def _correct_on_branch(d, F0, rtol, budget, scale, w_floor, z0, t0, h):
    """Newton on G = 0 and t0 . (Z - Z0 - h t0) = 0; returns (z, G, M, J, iterations) or None.

    ``w_floor`` is the lowest omega (rad/s) a Newton iterate may reach before the step is refused.
    """
    zp = z0 + h * t0 * scale
    z = zp.copy()
    J = None
    for it in range(8):
        G, M, _ = _orbit_map(d, F0, z, rtol, budget)
        if not (np.all(np.isfinite(G)) and np.all(np.isfinite(M))):
            return None
        if it == 0 or J is None:
            J = _branch_jacobian(d, F0, z, G, M, rtol, budget, scale)
        else:
            J[:, :2] = (M - np.eye(2)) * scale[:2] / scale[:2, None]
        res = np.concatenate([G / scale[:2], [np.dot(t0, (z - zp) / scale)]])
        if np.max(np.abs(res[:2])) < 1e-10 and abs(res[2]) < 1e-10:
            return z, G, M, _branch_jacobian(d, F0, z, G, M, rtol, budget, scale), it
        try:
            dz = np.linalg.solve(np.vstack([J, t0]), -res)
        except np.linalg.LinAlgError:
            return None
        z = z + dz * scale
        if not (w_floor < z[2] and z[2] > 0):
            return None
    return None


def _follow_branch(d, F0, z, t, first, step, max_points, bounds, rtol, budget, correct):
    """Predictor-corrector steps from ``z`` along ``t`` until omega leaves ``bounds`` or ``max_points`` are
    reached; returns the points ``(z, amplitude, M)`` (``first`` the point at ``z``) and the folds passed."""
    lo, hi = bounds
    pts = [first]
    folds = []
    h = 0.2 * step
    try:
        while len(pts) < max_points:
            out = correct(z, t, h)
            if out is None:
                h *= 0.5
                if h < 1e-7:
                    raise ParameterError(
                        f"continue_orbits could not follow the branch past omega = {z[2]:.6g} rad/s (Newton "
                        "fails for every step): allowed a smaller step or another starting frequency"
                    )
                continue
            zn, Gn, Mn, Jn, its = out
            tn = _branch_tangent(Jn, t)
            if np.sign(tn[2]) != np.sign(t[2]) and tn[2] != 0.0:
                folds.append(_locate_fold(d, F0, z, t, h, correct, rtol, budget))
            _, _, amp = _orbit_map(d, F0, zn, rtol, budget, events=True)
            pts.append((zn.copy(), amp, Mn.copy()))
            z, t = zn, tn
            h = min(step, h * (1.5 if its <= 3 else 1.0))
            if not lo <= z[2] <= hi:
                break
    except OverBudget:
        raise ParameterError(
            f"continue_orbits spent its budget of {budget.limit} right-hand-side evaluations at omega = "
            f"{z[2]:.6g} rad/s ({_rates(d)}): allowed a narrower frequency range or a larger step"
        ) from None
    return pts, folds


def _locate_fold(d, F0, z, t, h, correct, rtol, budget) -> OrbitFold:
    """The fold between ``z`` and the point one step ``h`` along ``t``: det(M - I) = 0 by the Illinois method."""

    def f(s):
        out = correct(z, t, s)
        if out is None:
            return math.nan, None
        zn, _, Mn, _, _ = out
        return float(np.linalg.det(Mn - np.eye(2))), out

    fa, _ = f(0.0)
    fb, outb = f(h)
    sa, sb = 0.0, h
    side = 0
    best = outb
    for _ in range(40):
        if not (math.isfinite(fa) and math.isfinite(fb)) or fa == fb:
            break
        s = sb - fb * (sb - sa) / (fb - fa)
        fs, out = f(s)
        if out is None:
            break
        best = out
        if abs(fs) < 1e-12 or abs(sb - sa) < 1e-13:
            break
        if (fs > 0) == (fb > 0):
            sb, fb = s, fs
            if side == -1:
                fa *= 0.5
            side = -1
        else:
            sa, fa = s, fs
            if side == 1:
                fb *= 0.5
            side = 1
    zf, _, Mf, _, _ = best
    _, _, amp = _orbit_map(d, F0, zf, rtol, budget, events=True)
    mu = np.linalg.eigvals(Mf)
    closest = mu[np.argmin(np.abs(mu - 1.0))]
    return OrbitFold(
        omega=float(zf[2]),
        amplitude=amp,
        multiplier=float(closest.real),
        det=float(np.linalg.det(Mf - np.eye(2))),
    )
