"""The disturbed task's references (exact optimum, best fixed gain), the curvature, the seed and robustness studies,
checked against independent methods."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import scipy.optimize

from vibration.physics import learning as L
from vibration.physics.learning import disturbance as D
from vibration.physics.learning import studies as S


@pytest.fixture(scope="module")
def short():
    """A short disturbed task (200 steps) that a dense least-squares solve can handle."""
    return L.resonance_task(n_steps=200, F0=5.0, omega=4.0)


def _batch_optimum(task) -> float:
    """Expected optimal cost by dense least squares over the whole force sequence (no Riccati recursion).

    The states are affine in the forces: s = G u + H s0 + f, so the optimal cost from s0 is a quadratic
    V(s0) = s0'M s0 + 2 b's0 + c0, and with E s0 = 0, E s0 s0' = diag(S) it is c0 + sum_i S_ii M_ii,
    M_ii = (V(e_i) + V(-e_i)) / 2 - c0.
    """
    a_d, b_d = L.zoh(task)
    d = L.disturbance_increments(task)
    n = task.n_steps
    g = np.zeros((2 * n, n))
    pw = [np.eye(2)]
    for _ in range(n):
        pw.append(a_d @ pw[-1])
    for k in range(1, n):
        for j in range(k):
            g[2 * k : 2 * k + 2, j] = pw[k - 1 - j] @ b_d
    qs = np.sqrt(task.dt * np.array([task.q_x, task.q_v]))
    rs = np.sqrt(task.dt * task.r)

    def value(s0):
        f = np.zeros(2 * n)
        s = np.asarray(s0, float)
        for k in range(n):
            f[2 * k : 2 * k + 2] = s
            s = a_d @ s + d[k]
        w = np.tile(qs, n)
        a = np.vstack([w[:, None] * g, rs * np.eye(n)])
        rhs = -np.concatenate([w * f, np.zeros(n)])
        u, *_ = np.linalg.lstsq(a, rhs, rcond=None)
        res = a @ u - rhs
        return float(res @ res)

    c0 = value([0.0, 0.0])
    cov = np.diag(task.initial_covariance)
    total = c0
    for i in range(2):
        e = np.zeros(2)
        e[i] = 1.0
        total += cov[i] * (0.5 * (value(e) + value(-e)) - c0)
    return total


def test_exosystem_optimum_matches_dense_least_squares(short):
    opt = D.exosystem_optimum(short)
    np.testing.assert_allclose(opt.expected_cost, _batch_optimum(short), rtol=1e-8)


def test_exosystem_increments_are_the_exact_disturbance_increments():
    task = L.resonance_task()
    a_z, _, _ = D.exosystem_matrices(task)
    w = np.column_stack([np.sin(task.omega * task.t), np.cos(task.omega * task.t)])
    d = L.disturbance_increments(task)
    # 1e-11: cancellation in p(t + dt) - A_d p(t)
    np.testing.assert_allclose(w @ a_z[:2, 2:].T, d, rtol=0, atol=1e-11 * np.abs(d).max())


def test_optimum_without_disturbance_is_lqr():
    task = L.OscillatorTask()
    np.testing.assert_allclose(D.exosystem_optimum(task).expected_cost, L.lqr_reference(task).expected_cost, rtol=1e-9)


def test_references_are_ordered_and_the_fixed_gain_is_stationary():
    task = L.resonance_task()
    exo, fixed, lqr = D.exosystem_optimum(task), D.best_fixed_gain(task), L.lqr_reference(task)
    assert exo.expected_cost < fixed.expected_cost < lqr.expected_cost
    h = 1e-4
    for e in np.eye(2) * h:
        jp, jm = L._moments(task, fixed.gains + e)[0], L._moments(task, fixed.gains - e)[0]
        assert abs(jp - jm) / (2 * h) < 1e-6
        assert min(jp, jm) >= fixed.expected_cost - 1e-12


def test_fixed_gain_cost_matches_cubature_of_simulated_episodes():
    # the exact cost of a linear law against the environment's own episodes (force bound lifted so it is linear)
    task = replace(L.resonance_task(), u_max=1e4)
    fixed = D.best_fixed_gain(task)
    nodes, weights = np.polynomial.legendre.leggauss(3)
    xs, vs = np.meshgrid(nodes * task.x0_max, nodes * task.v0_max, indexing="ij")
    wts = np.outer(weights, weights).ravel() / 4.0
    costs = L.episode_costs(task, fixed.gains, np.column_stack([xs.ravel(), vs.ravel()]))[0]
    np.testing.assert_allclose(costs @ wts, fixed.expected_cost, rtol=1e-10)


def test_every_single_state_objective_has_the_lqr_minimiser():
    # why CMA-ES converges to rounding level: common random numbers give objectives with one shared minimiser
    task = L.OscillatorTask()
    k_lqr = L.lqr_reference(task).gains
    for s0 in ([0.7, -0.2], [-0.1, 0.9]):
        res = scipy.optimize.minimize(
            lambda g, s0=s0: float(L.episode_costs(task, g, s0)[0, 0]),
            k_lqr + [0.5, -0.5],
            method="Nelder-Mead",
            options={"xatol": 1e-9, "fatol": 1e-15, "maxiter": 2000},
        )
        np.testing.assert_allclose(res.x, k_lqr, atol=2e-3)


def test_hessian_matches_a_quadratic_fit():
    task = L.OscillatorTask()
    k = L.lqr_reference(task).gains
    curv = D.cost_hessian(task, k)
    # independent: least-squares quadratic through a 5 x 5 grid of exact costs
    d = np.linspace(-0.05, 0.05, 5)
    pts = np.array([(a, b) for a in d for b in d])
    j = np.array([L._moments(task, k + p)[0] for p in pts])
    a = np.column_stack([np.ones(len(pts)), pts, pts[:, 0] ** 2 / 2, pts[:, 0] * pts[:, 1], pts[:, 1] ** 2 / 2])
    coef, *_ = np.linalg.lstsq(a, j, rcond=None)
    hess = np.array([[coef[3], coef[4]], [coef[4], coef[5]]])
    np.testing.assert_allclose(curv.hessian, hess, rtol=1e-4)
    vals = np.linalg.eigvalsh(hess)
    np.testing.assert_allclose(curv.ratio, vals[1] / vals[0], rtol=1e-3)


def test_seed_study_reproduces_single_runs():
    st = S.seed_study(None, "ars", seeds=(0, 3), iterations=30)
    ref = L.lqr_reference()
    for s, ratio in zip(st.seeds, st.final_ratio, strict=True):
        res = L.train(None, seed=int(s), method="ars", iterations=30)
        np.testing.assert_allclose(ratio, res.expected_cost / ref.expected_cost, rtol=1e-12)
    assert np.all(st.final_ratio >= 1.0 - 1e-9)  # nothing beats the optimum


def test_robustness_sampled_costs_agree_with_exact_costs():
    task = L.resonance_task()
    lqr = L.lqr_reference(task).gains
    rb = S.robustness_study(task, {"LQR": lqr}, n_episodes=400)
    for v, t in enumerate(rb.tasks):
        exact, peak = L._moments(t, lqr)
        assert peak <= t.u_max  # the law is linear on every changed plant: its exact cost applies
        assert abs(rb.cost[v, 0] - exact) < 4 * rb.stderr[v, 0]
        assert rb.optimum[v] <= exact


def test_identify_then_design_recovers_the_plant():
    task = L.resonance_task()
    d = S.identify_then_design(task, duration=10.0, noise=0.01, seed=3)
    truth = np.array([task.m, task.c, task.k])
    assert np.all(np.abs(d.fitted - truth) < 5 * d.stderr)
    np.testing.assert_allclose(d.fixed_gains, D.best_fixed_gain(task).gains, rtol=0.02)


def test_a_small_force_bound_makes_the_exact_optimum_a_lower_bound():
    # the chapter's sentences say "lower bound" exactly when this flag is off (checked by
    # tests/chapters/learning/test_learning_chapter.py under parameters where the bound binds)
    task = L.resonance_task(u_max=15.0)
    exo, fixed = D.exosystem_optimum(task), D.best_fixed_gain(task)
    assert not exo.within_bound and exo.peak_force > task.u_max
    assert not fixed.within_bound
    assert D.exosystem_optimum(L.resonance_task()).within_bound
