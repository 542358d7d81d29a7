"""Exact discretisation (first-order hold), the sampled response, and its checks against independent references.

Synthetic test records (random force, stiffness history, simulated records) are in :mod:`.synthetic`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import signal

from ..checks import OverBudget, check_oscillator
from ..duffing import _Counted, _real_array
from ..model import N_POINTS_MAX, Oscillator, ParameterError, check_int, check_real
from .measurements import MAX_ABS, _finite_output, _sampling, _signal

__all__ = [
    "Discretization",
    "SampledResponse",
    "discretisation_checks",
    "discretize",
    "expm_batch",
    "sampled_response",
]

#: Work budget: right-hand-side evaluations of the ``solve_ivp`` reference of :func:`discretisation_checks`.
MAX_RHS_EVALUATIONS = 300_000


# --------------------------------------------------------------------------- exact discretisation


@dataclass(frozen=True, kw_only=True)
class Discretization:
    """Exact first-order-hold step: ``z[n+1] = phi z[n] + gamma0 F[n] + gamma1 F[n+1]``, ``z = (x, v)``."""

    dt: float  # step, s
    phi: np.ndarray  # (2, 2) state transition, (1, s; 1/s, 1)
    gamma0: np.ndarray  # (2,) weight of F[n], (m/N, m/(s N))
    gamma1: np.ndarray  # (2,) weight of F[n+1], (m/N, m/(s N))


_PADE13 = (
    64764752532480000.0,
    32382376266240000.0,
    7771770303897600.0,
    1187353796428800.0,
    129060195264000.0,
    10559470521600.0,
    670442572800.0,
    33522128640.0,
    1323241920.0,
    40840800.0,
    960960.0,
    16380.0,
    182.0,
    1.0,
)


def expm_batch(a: np.ndarray) -> np.ndarray:
    """Matrix exponential of a stack of small matrices, shape (..., n, n).

    Degree-13 Padé approximant with scaling and squaring (Higham 2005), in
    NumPy's stacked ``matmul`` and ``solve``: the same algorithm as
    ``scipy.linalg.expm`` (to which the tests compare it, relative 1e-13), without
    its per-call BLAS thread start-up, which dominates for 4 x 4 matrices on a
    busy machine.

    Examples
    --------
    >>> x = np.array([[0.0, 1.0], [-1.0, 0.0]])
    >>> bool(np.allclose(expm_batch(x), [[np.cos(1), np.sin(1)], [-np.sin(1), np.cos(1)]], rtol=0, atol=1e-15))
    True
    """
    a = _real_array("a", a, max_size=N_POINTS_MAX)
    if a.ndim < 2 or a.shape[-1] != a.shape[-2]:
        raise ParameterError(f"a has shape {a.shape}: allowed a stack of square matrices, shape (..., n, n)")
    n = a.shape[-1]
    norm = np.max(np.sum(np.abs(a), axis=-2), axis=-1)
    if not np.all(np.isfinite(norm)):
        raise ParameterError("a has a matrix whose 1-norm overflows: allowed matrices of finite 1-norm")
    s = np.maximum(0, np.ceil(np.log2(np.maximum(norm, 1e-300) / 5.371920351148152))).astype(int)
    a = a / (2.0**s)[..., None, None]
    b = _PADE13
    eye = np.broadcast_to(np.eye(n), a.shape)
    a2 = a @ a
    a4 = a2 @ a2
    a6 = a4 @ a2
    u = a @ (a6 @ (b[13] * a6 + b[11] * a4 + b[9] * a2) + b[7] * a6 + b[5] * a4 + b[3] * a2 + b[1] * eye)
    v = a6 @ (b[12] * a6 + b[10] * a4 + b[8] * a2) + b[6] * a6 + b[4] * a4 + b[2] * a2 + b[0] * eye
    r = np.linalg.solve(v - u, v + u)
    smax = int(np.max(s)) if s.size else 0
    with np.errstate(over="ignore", invalid="ignore"):
        for j in range(smax):
            sq = r @ r
            r = np.where((s > j)[..., None, None], sq, r)
    if not np.all(np.isfinite(r)):
        raise ParameterError(
            f"a has a matrix whose exponential overflows (1-norm up to {float(np.max(norm)):.3g}): allowed "
            "matrices whose exponential is a finite float"
        )
    return r


def _foh(m, c, k, h):
    """Batched exact FOH matrices for arrays of (m, c, k): phi (P,2,2), gamma0 (P,2), gamma1 (P,2)."""
    m, c, k = (np.atleast_1d(np.asarray(v, dtype=float)) for v in (m, c, k))
    p = m.size
    big = np.zeros((p, 4, 4))
    big[:, 0, 1] = h
    big[:, 1, 0] = -k / m * h
    big[:, 1, 1] = -c / m * h
    big[:, 1, 2] = h / m
    big[:, 2, 3] = 1.0
    try:
        e = expm_batch(big)
    except ParameterError:
        raise ParameterError(
            f"the step h = {h!r} s with c/m up to {float(np.max(np.abs(c / m))):.3g} 1/s and k/m up to "
            f"{float(np.max(k / m)):.3g} 1/s^2 overflows the exact step (exp(A h) is not a finite float): allowed "
            "a smaller step or a stable oscillator"
        ) from None
    phi = e[:, :2, :2]
    p0, p1 = e[:, :2, 2], e[:, :2, 3]
    return phi, p0 - p1, p1


def discretize(osc: Oscillator, dt: float) -> Discretization:
    """Exact discretisation of the oscillator for a force linear between samples (first-order hold).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    dt : float
        Sampling step, s (> 0).

    Examples
    --------
    >>> d = discretize(Oscillator(m=1.0, c=0.0, k=1.0), 0.5)
    >>> bool(np.allclose(d.phi, [[np.cos(0.5), np.sin(0.5)], [-np.sin(0.5), np.cos(0.5)]]))
    True
    >>> float(np.round(d.gamma0.sum() + d.gamma1.sum() - (1 - np.cos(0.5)) - np.sin(0.5), 12))  # constant F = 1 N
    0.0
    """
    check_oscillator(osc)
    dt = check_real("dt", dt, low=0.0, low_open=True, unit="s")
    phi, g0, g1 = _foh(osc.m, osc.c, osc.k, dt)
    return Discretization(dt=dt, phi=phi[0], gamma0=g0[0], gamma1=g1[0])


def _filters(phi, g0, g1, row, feed):
    """Second-order IIR coefficients of output ``row @ z + feed F`` and of the free response basis.

    Returns ``(b, a, free_b)``: ``lfilter(b, a, F)`` is the output from ``w[0] = 0``
    (``w = z - gamma1 F``), and ``free_b[j]`` gives ``row @ phi^n e_j`` as
    ``free_b[j][0] y[n] + free_b[j][1] y[n-1]`` with ``y = lfilter([1], a, delta)``.
    """
    tr = phi[0, 0] + phi[1, 1]
    det = phi[0, 0] * phi[1, 1] - phi[0, 1] * phi[1, 0]
    a = np.array([1.0, -tr, det])
    adj = np.array([[-phi[1, 1], phi[0, 1]], [phi[1, 0], -phi[0, 0]]])
    e = phi @ g1 + g0
    d = row @ g1 + feed
    b = np.array([d, row @ e + d * a[1], row @ adj @ e + d * a[2]])
    free_b = [(row[j], (row @ adj)[j]) for j in range(2)]
    return b, a, free_b


def _run(phi, g0, g1, row, feed, force, z0):
    """Output ``row @ z[n] + feed F[n]`` from state ``z0`` at the first sample (exact FOH)."""
    b, a, free_b = _filters(phi, g0, g1, row, feed)
    n = force.size
    delta = np.zeros(n)
    delta[0] = 1.0
    y = signal.lfilter([1.0], a, delta)
    y1 = np.concatenate([[0.0], y[:-1]])
    w0 = np.asarray(z0, float) - g1 * force[0]
    free = sum(w0[j] * (free_b[j][0] * y + free_b[j][1] * y1) for j in range(2))
    return signal.lfilter(b, a, force) + free


@dataclass(frozen=True, kw_only=True)
class SampledResponse:
    """Response at the samples: ``t`` (s), ``x`` (m), ``v`` (m/s), ``a`` (m/s^2)."""

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray


def sampled_response(osc: Oscillator, t, force, *, x0: float = 0.0, v0: float = 0.0) -> SampledResponse:
    """Exact response to a sampled force held linear between samples (first-order hold).

    Parameters
    ----------
    osc : Oscillator
        m (kg), c (N s/m), k (N/m).
    t : array_like
        Uniform, increasing sample times, s.
    force : array_like
        Force at ``t``, N.
    x0, v0 : float
        State at ``t[0]``: displacement (m) and velocity (m/s).

    Returns
    -------
    SampledResponse
        ``x`` (m), ``v`` (m/s) and ``a = (F - c v - k x) / m`` (m/s^2) at ``t``.

    Examples
    --------
    >>> from vibration import SineForce, exact_response
    >>> osc, f = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    >>> t = np.linspace(0.0, 10.0, 2001)
    >>> r = sampled_response(osc, t, f(t))
    >>> bool(np.max(np.abs(r.x - exact_response(osc, f, t).x)) < 2e-5)    # m: h^2 omega^2 F0 / 8 force interpolation
    True
    """
    check_oscillator(osc)
    t = _signal("t", t)
    if t.size < 2:
        raise ParameterError(f"t has {t.size} samples: allowed at least 2")
    h = _sampling(t, lambda i: f"t[{i}]")
    force = _signal("force", force, t.size)
    z0 = (check_real("x0", x0, unit="m"), check_real("v0", v0, unit="m/s"))
    phi, g0, g1 = (v[0] for v in _foh(osc.m, osc.c, osc.k, h))
    with np.errstate(over="ignore", invalid="ignore"):
        x = _run(phi, g0, g1, np.array([1.0, 0.0]), 0.0, force, z0)
        v = _run(phi, g0, g1, np.array([0.0, 1.0]), 0.0, force, z0)
        acc = (force - osc.c * v - osc.k * x) / osc.m
    for arr in (x, v, acc):
        _finite_output(
            arr,
            "the sampled response",
            f"the oscillator {osc} grows without bound over {float(t[-1] - t[0]):.3g} s, or the force or initial "
            "state is too large: allowed a response that stays a finite float",
        )
    return SampledResponse(t=t, x=x, v=v, a=acc)


def discretisation_checks(osc: Oscillator, F0: float, omega: float, *, t_end: float, n: int) -> dict:
    """Differences of :func:`sampled_response` from three independent references, with their bounds.

    Returns ``{name: (difference, bound)}`` (both in m):

    * the closed form :func:`vibration.exact_response` for ``F0 sin(omega t)`` on ``n``
      samples: the FOH interpolation error, bounded by ``h^2 omega^2 F0 / 8`` times the
      integral of ``|impulse response|`` (itself bounded by ``2 / (c omega_d)``, or
      ``t_end / m`` for the undamped case),
    * ``scipy.signal.cont2discrete(method="foh")`` with ``dlsim``: rounding level,
    * ``solve_ivp`` (DOP853, rtol 1e-12) sample by sample with the force held linear:
      integrator tolerance level (on the first 200 samples).

    Examples
    --------
    >>> ch = discretisation_checks(Oscillator(m=1.0, c=0.5, k=20.0), 5.0, 4.47, t_end=50.0, n=5001)
    >>> all(v < b for v, b in ch.values())
    True
    """
    from ..exact import exact_response
    from ..model import SineForce

    F0, omega, t_end, n = _checked_sine(osc, F0, omega, t_end, n)
    t = np.linspace(0.0, t_end, n)
    h = float(t[1] - t[0])
    m_ = _ivp_reference_samples(osc, omega, t_end, n, h)
    force = SineForce(F0=F0, omega=omega)
    f = force(t)
    ours = sampled_response(osc, t, f)
    exact = exact_response(osc, force, t)
    bound_sine = h * h * omega * omega * F0 / 8.0 * _impulse_response_integral(osc, t_end)
    yd = _foh_state_space_reference(osc, f, h)
    scale = max(float(np.max(np.abs(ours.x))), 1e-300)
    ref = _ivp_reference(osc, f, h, m_, scale)
    out = {
        "sine: closed form (interpolation error of the force)": (
            float(np.max(np.abs(ours.x - exact.x))),
            bound_sine,
        ),
        "first-order-hold discretisation of the state space, simulated (relative to max |x|)": (
            float(np.max(np.abs(ours.x - yd[:, 0]))) / scale,
            1e-10,
        ),
        "an adaptive integrator, force linear between samples (relative)": (
            float(np.max(np.abs(ours.x[:m_] - np.array(ref)))) / scale,
            1e-8,
        ),
    }
    _finite_output(
        list(out.values()), "a difference or bound", "allowed an oscillator and force whose responses stay finite"
    )
    return out


def _checked_sine(osc, F0, omega, t_end, n):
    """The arguments of :func:`discretisation_checks`, checked in order: ``(F0, omega, t_end, n)``."""
    check_oscillator(osc)
    F0 = check_real("F0", F0, low=0.0, high=MAX_ABS, unit="N")
    omega = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n = check_int("n", n, low=2, high=N_POINTS_MAX)
    return F0, omega, t_end, n


def _ivp_reference_samples(osc, omega, t_end, n, h) -> int:
    """Samples of the ``solve_ivp`` reference (at most 200), refused when their work exceeds the budget.

    DOP853 (12 evaluations a step) needs h lambda within its stability interval (about 6) and, at rtol 1e-12,
    steps of at most about a tenth of the fastest period.
    """
    wn = osc.natural_frequency
    lam = max(abs(osc.c) / osc.m, wn, omega)
    m_ = min(200, n)
    need = 12.0 * (m_ - 1) * max(h * lam / 6.0, 1.0)
    if not need <= MAX_RHS_EVALUATIONS:
        raise ParameterError(
            f"n = {n} samples over t_end = {t_end!r} s (step {h:.3g} s) with the fastest rate {lam:.3g} 1/s "
            f"(|c|/m = {abs(osc.c) / osc.m:.3g} 1/s, omega_n = {wn:.3g} rad/s, omega = {omega:.3g} rad/s) need at "
            f"least {need:.3g} right-hand-side evaluations for the solve_ivp reference: allowed at most "
            f"{MAX_RHS_EVALUATIONS} (more samples n, a shorter t_end or a less stiff oscillator)"
        )
    return m_


def _impulse_response_integral(osc, t_end) -> float:
    """Bound of the integral of ``|impulse response|`` over the record, s/kg."""
    wd = osc.damped_natural_frequency
    integral = 2.0 / (osc.c * wd) if osc.c > 0 and wd > 0 else t_end / osc.m * max(t_end, 1.0)
    if osc.c > 0 and wd == 0.0:
        integral = 1.0 / osc.k * 4.0
    return integral


def _foh_state_space_reference(osc, f, h):
    """States (x, v) at the samples from ``scipy.signal.cont2discrete(method="foh")`` and ``dlsim``."""
    a = np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]])
    b = np.array([[0.0], [1.0 / osc.m]])
    ad, bd, cd, dd, _ = signal.cont2discrete((a, b, np.eye(2), np.zeros((2, 1))), h, method="foh")
    with np.errstate(over="ignore", invalid="ignore"):
        _, yd, _ = signal.dlsim((ad, bd, cd, dd, h), f, x0=-dd[:, 0] * f[0])
    _finite_output(yd, "the cont2discrete + dlsim reference", "allowed a response that stays a finite float")
    return yd


def _ivp_reference(osc, f, h, m_, scale) -> list:
    """x at the first ``m_`` samples from ``solve_ivp`` (DOP853, rtol 1e-12), sample by sample, force linear."""
    from scipy.integrate import solve_ivp

    budget = _Counted(None, MAX_RHS_EVALUATIONS)
    z = np.zeros(2)
    ref = [0.0]
    for i in range(m_ - 1):
        slope = (f[i + 1] - f[i]) / h
        budget.fun = lambda s, y, i=i, slope=slope: [y[1], (f[i] + slope * s - osc.c * y[1] - osc.k * y[0]) / osc.m]
        try:
            sol = solve_ivp(budget, (0.0, h), z, method="DOP853", rtol=1e-12, atol=1e-14 * scale)
        except OverBudget:
            raise ParameterError(
                f"discretisation_checks spent its budget of {MAX_RHS_EVALUATIONS} right-hand-side evaluations on the "
                f"solve_ivp reference at sample {i} of {m_} (step {h:.3g} s, |c|/m = {abs(osc.c) / osc.m:.3g} 1/s, "
                f"omega_n = {osc.natural_frequency:.3g} rad/s): allowed more samples n, a shorter t_end or a less "
                "stiff oscillator"
            ) from None
        z = sol.y[:, -1]
        ref.append(z[0])
    return ref
