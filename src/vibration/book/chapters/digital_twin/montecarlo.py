"""Monte Carlo identification in batches: the estimator of :func:`~vibration.physics.twin.identify`, many at once.

Every Monte Carlo experiment of the chapter identifies hundreds of records that share the sampling
times and the noise-free force and differ only in their noise. :func:`identify` solves one record at a
time (about 20 ms each, mostly solver overhead); here all runs of an experiment take their Gauss-Newton
steps together: the exact first-order-hold recursion of every run and of its finite-difference
neighbours runs in one compiled loop, the 5 x 5 normal equations are solved as a stack. The estimator
is the same (output-error least squares on the exact discrete model in m, c, k and the initial state;
covariance ``s^2 (J^T J)^-1`` with ``s^2 = RSS / (N - 5)``; Student-t 95 % intervals), so the batch must
reproduce :func:`identify` run by run: :func:`agreement` measures that, the chapter prints it and a test
checks it.

Each run draws its noise from its own generator, seeded by ``(seed, stream, run)``: experiments with
different streams share no draws (independent draws per noise level and per case).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy import signal
from scipy.stats import t as student_t

from vibration.physics.model import Oscillator, ParameterError
from vibration.physics.twin import (
    WHITENESS_LAGS,
    CoverageExperiment,
    RunResults,
    expm_batch,
    identify,
    input_correlation,
    ljung_box,
    random_force,
    synthetic_measurements,
)

#: Gauss-Newton iterations at most, and step halvings per iteration at most (every loop is bounded).
MAX_ITERATIONS = 40
MAX_HALVINGS = 12
#: Convergence: largest relative step of m, c, k.
STEP_TOL = 1e-11
#: Iterations that recompute the Jacobian (the others are chord steps with the last one).
REFRESH = frozenset({1, 2, 3, 5, 9, 17, 33})
#: Relative finite-difference step of m, c, k for the Jacobian.
FD_STEP = 1e-6
#: Runs solved together (memory: about 9 x BATCH x samples doubles per iteration).
BATCH = 200


@njit(cache=True)
def _responses(phi, g0, g1, z0, force, row, out):  # pragma: no cover - compiled
    """Displacement of P parameter sets: z[n+1] = phi z[n] + g0 F[n] + g1 F[n+1], force row ``row[p]``."""
    count, n = out.shape
    for p in range(count):
        f00, f01, f10, f11 = phi[p, 0, 0], phi[p, 0, 1], phi[p, 1, 0], phi[p, 1, 1]
        a0, a1, b0, b1 = g0[p, 0], g0[p, 1], g1[p, 0], g1[p, 1]
        x, v = z0[p, 0], z0[p, 1]
        r = row[p]
        fp = force[r, 0]
        out[p, 0] = x
        for i in range(n - 1):
            fn = force[r, i + 1]
            xn = f00 * x + f01 * v + a0 * fp + b0 * fn
            v = f10 * x + f11 * v + a1 * fp + b1 * fn
            x = xn
            fp = fn
            out[p, i + 1] = x


def _foh(m, c, k, h):
    """Exact FOH matrices for arrays of (m, c, k): phi (P, 2, 2), gamma0 (P, 2), gamma1 (P, 2)."""
    big = np.zeros((m.size, 4, 4))
    big[:, 0, 1] = h
    big[:, 1, 0] = -k / m * h
    big[:, 1, 1] = -c / m * h
    big[:, 1, 2] = h / m
    big[:, 2, 3] = 1.0
    e = expm_batch(big)
    p0, p1 = e[:, :2, 2], e[:, :2, 3]
    return np.ascontiguousarray(e[:, :2, :2]), np.ascontiguousarray(p0 - p1), np.ascontiguousarray(p1)


def _simulate(params, forces, rows, h):
    """Displacement for each row of ``params`` (m, c, k, x0, v0) driven by ``forces[rows]``."""
    phi, g0, g1 = _foh(params[:, 0], params[:, 1], params[:, 2], h)
    out = np.empty((params.shape[0], forces.shape[1]))
    _responses(phi, g0, g1, np.ascontiguousarray(params[:, 3:5]), forces, rows.astype(np.int64), out)
    return out


def _jacobian(p, forces, h):
    """Model output (R, N) and Jacobian (R, 5, N) of each run's parameters p (R, 5)."""
    r = p.shape[0]
    sets = [p]
    for j in range(3):
        for sign in (1.0, -1.0):
            q = p.copy()
            q[:, j] *= 1.0 + sign * FD_STEP
            sets.append(q)
    free = np.repeat(p, 2, axis=0)
    free[:, 3:5] = np.tile(np.eye(2), (r, 1))
    zero_row = forces.shape[0] - 1  # the last force row is zero
    rows = np.concatenate([np.tile(np.arange(r), 7), np.full(2 * r, zero_row)])
    out = _simulate(np.concatenate(sets + [free]), forces, rows, h)
    y = out[:r]
    jac = np.empty((r, 5, forces.shape[1]))
    for j in range(3):
        hi, lo = out[(1 + 2 * j) * r : (2 + 2 * j) * r], out[(2 + 2 * j) * r : (3 + 2 * j) * r]
        jac[:, j] = (hi - lo) / (2.0 * FD_STEP * p[:, j : j + 1])
    jac[:, 3] = out[7 * r :: 2]
    jac[:, 4] = out[7 * r + 1 :: 2]
    return y, jac


def _normal(jac, res=None):
    """Column scales (R, 5), scaled Gram matrices (R, 5, 5) and scaled gradients (R, 5) of each run."""
    scale = np.sqrt(np.sum(jac * jac, axis=2))
    js = jac / scale[:, :, None]
    gram = js @ js.transpose(0, 2, 1)
    grad = None if res is None else (js @ res[:, :, None])[..., 0]
    return scale, gram, grad


@dataclass(frozen=True, kw_only=True)
class BatchFit:
    """Least-squares fits of R records: estimates, standard errors, intervals, residuals."""

    params: np.ndarray  # (R, 5) m (kg), c (N s/m), k (N/m), x0 (m), v0 (m/s)
    stderr: np.ndarray  # (R, 3) of m, c, k
    ci95: np.ndarray  # (R, 3, 2)
    residual: np.ndarray  # (R, N) measured minus model, m
    iterations: int  # Gauss-Newton iterations taken by the slowest run


def fit_batch(t, forces, ys, *, start) -> BatchFit:
    """Output-error least squares of each record (``forces[i]``, ``ys[i]``), all runs together.

    Gauss-Newton on (m, c, k, x0, v0) from ``start`` (an Oscillator, started from rest, or the five values),
    each step halved until the run's residual sum of squares falls (at most :data:`MAX_HALVINGS` times), at
    most :data:`MAX_ITERATIONS` steps.
    """
    t = np.asarray(t, float)
    h = float(t[1] - t[0])
    ys = np.atleast_2d(np.asarray(ys, float))
    runs, n = ys.shape
    forces = np.atleast_2d(np.asarray(forces, float))
    if forces.shape[0] == 1 and runs > 1:
        forces = np.repeat(forces, runs, axis=0)
    forces = np.vstack([forces, np.zeros((1, n))])
    first = [start.m, start.c, start.k, 0.0, 0.0] if isinstance(start, Oscillator) else list(start)
    p = np.tile(first, (runs, 1))
    active = np.ones(runs, bool)
    js = np.empty((runs, 5, n))
    scale = np.empty((runs, 5))
    gram = np.empty((runs, 5, 5))
    it = 0
    for it in range(1, MAX_ITERATIONS + 1):
        idx = np.nonzero(active)[0]
        if it in REFRESH:  # Gauss-Newton with a fresh Jacobian; in between, chord steps reuse it
            y, jac = _jacobian(p[idx], forces[np.append(idx, runs)], h)
            scale[idx] = np.sqrt(np.sum(jac * jac, axis=2))
            js[idx] = jac / scale[idx][:, :, None]
            gram[idx] = js[idx] @ js[idx].transpose(0, 2, 1)
        else:
            y = _simulate(p[idx], forces, idx, h)
        res = ys[idx] - y
        cost = np.sum(res * res, axis=1)
        grad = (js[idx] @ res[:, :, None])[..., 0]
        step = np.linalg.solve(gram[idx], grad[..., None])[..., 0] / scale[idx]
        alpha = np.ones(idx.size)
        todo = np.ones(idx.size, bool)
        new = p[idx].copy()
        for _ in range(MAX_HALVINGS):
            trial = p[idx] + alpha[:, None] * step
            ok = np.all(trial[:, :3] > 0.0, axis=1)
            sub = np.nonzero(todo & ok)[0]
            if sub.size:
                yt = _simulate(trial[sub], forces, idx[sub], h)
                ct = np.sum((ys[idx[sub]] - yt) ** 2, axis=1)
                better = ct <= cost[sub] * (1.0 + 1e-15)
                new[sub[better]] = trial[sub[better]]
                todo[sub[better]] = False
            if not todo.any():
                break
            alpha[todo] *= 0.5
        rel = np.max(np.abs((new[:, :3] - p[idx, :3]) / p[idx, :3]), axis=1)
        p[idx] = new
        active[idx[(rel < STEP_TOL) | todo]] = False
        if not active.any():
            break
    y, jac = _jacobian(p, forces, h)
    res = ys - y
    dof = n - 5
    s2 = np.sum(res * res, axis=1) / dof
    scale, gram, _ = _normal(jac)
    inv = np.linalg.inv(gram) / (scale[:, :, None] * scale[:, None, :])
    se = np.sqrt(s2[:, None] * np.diagonal(inv, axis1=1, axis2=2)[:, :3])
    q = float(student_t.ppf(0.975, dof))
    ci = np.stack([p[:, :3] - q * se, p[:, :3] + q * se], axis=-1)
    return BatchFit(params=p, stderr=se, ci95=ci, residual=res, iterations=it)


def ar1(runs: int, n: int, colour: float, *, rngs) -> np.ndarray:
    """(runs, n) stationary AR(1) noise of unit variance and lag-one correlation ``colour``, one generator per run."""
    w = np.stack([g.standard_normal(n + 1) for g in rngs]) if runs else np.empty((0, n + 1))
    if colour == 0.0:
        return w[:, 1:]
    y, _ = signal.lfilter([math.sqrt(1.0 - colour * colour)], [1.0, -colour], w[:, 1:], axis=1, zi=colour * w[:, :1])
    return y


def experiment(
    osc: Oscillator,
    t,
    force,
    *,
    clean,
    noise_sd: float,
    runs: int,
    seed: int,
    stream: int,
    force_sd: float = 0.0,
    colour: float = 0.0,
    noise: float,
    case: str = "as assumed",
    lags: int = WHITENESS_LAGS,
) -> CoverageExperiment:
    """Identify ``runs`` noisy copies of one record; each run's noise from ``default_rng([seed, stream, run])``.

    ``noise_sd`` (m): response-noise standard deviation; ``force_sd`` (N): force-noise standard deviation;
    ``colour``: lag-one correlation of the response noise; ``noise``: the relative level to record.
    """
    t = np.asarray(t, float)
    n = t.size
    truth = np.array([osc.m, osc.c, osc.k])
    out = RunResults.empty(runs)
    # every run starts from the fit of the noise-free record: a few steps from its own optimum
    start = fit_batch(t, force, clean, start=osc).params[0]
    for lo in range(0, runs, BATCH):
        hi = min(runs, lo + BATCH)
        rngs = [np.random.default_rng([seed, stream, i]) for i in range(lo, hi)]
        ys = clean + noise_sd * ar1(hi - lo, n, colour, rngs=rngs)
        forces = force + force_sd * np.stack([g.standard_normal(n) for g in rngs]) if force_sd > 0.0 else force
        fit = fit_batch(t, forces, ys, start=start)
        out.estimates[lo:hi], out.stderr[lo:hi], out.ci95[lo:hi] = fit.params[:, :3], fit.stderr, fit.ci95
        fmat = np.broadcast_to(forces, (hi - lo, n))
        for i in range(hi - lo):
            out.whiteness_p[lo + i] = ljung_box(fit.residual[i], lags)[1]
            out.input_p[lo + i] = input_correlation(fit.residual[i], fmat[i], lags)[1]
    return out.experiment(
        truth, noise=noise, duration=float(t[-1] - t[0]), dt=float(t[1] - t[0]), sensor="x", case=case
    )


def design(osc: Oscillator, duration: float, dt: float, *, seed: int, band, rms: float):
    """The experiments' shared design: times (s), force (N) and noise-free displacement (m)."""
    n = int(round(duration / dt)) + 1
    t = np.arange(n) * dt
    force = random_force(t, band=band, rms=rms, seed=seed)
    return t, force, synthetic_measurements(osc, t, force).x


def agreement(osc: Oscillator, t, force, *, clean, noise_sd: float, seed: int, stream: int, runs: int = 3) -> float:
    """Largest relative difference of m, c, k and their standard errors between the batch and :func:`identify`.

    Over the first ``runs`` runs of an experiment (same draws as :func:`experiment`).
    """
    if runs < 1:
        raise ParameterError(f"runs = {runs!r}: allowed at least 1")
    rngs = [np.random.default_rng([seed, stream, i]) for i in range(runs)]
    ys = clean + noise_sd * ar1(runs, t.size, 0.0, rngs=rngs)
    fit = fit_batch(t, force, ys, start=osc)
    worst = 0.0
    for i in range(runs):
        ref = identify(t, force, x=ys[i], search="local")
        a = np.array([ref.m, ref.c, ref.k, *ref.stderr])
        b = np.concatenate([fit.params[i, :3], fit.stderr[i]])
        worst = max(worst, float(np.max(np.abs(b - a) / np.abs(a))))
    return worst
