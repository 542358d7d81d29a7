"""Chapter 8 (tuned mass damper, MDOF structures): the heaviest computations against naive alternatives.

Each case is timed side by side in the same run (:func:`median_time`, the median of repeated calls);
the naive alternatives are what a reader would write first, and their accuracy is printed next to
the time so a ratio is never bought with a wrong answer:

* the exact peak max_r |H| (real roots of the stationarity polynomial in r²) against the largest
  sample of |H| on a dense grid of 20001 ratios;
* the numerical H∞ optimum for the paper's damped primary (Nelder-Mead on the exact peak, then the
  equal-peak conditions) against Nelder-Mead on the grid peak;
* the roof receptance of the five-storey building with its roof absorber over 3001 frequencies
  (``MDOF.frf``: one complex solve per frequency) against an explicit inverse per frequency and
  against one batched ``numpy.linalg.solve``;
* the exact time response of the two-mass system on 5001 samples (complex modal superposition)
  against the augmented matrix exponential per sample and DOP853 at rtol 1e-10.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import minimize

from vibration.book.presentation.timing import median_time, table
from vibration.physics.tmd import (
    add_absorber,
    first_mode_absorber,
    hinf_tuning,
    shear_building,
    tmd_magnification,
    tmd_peak,
    tmd_system,
)

MU, ZETA_P = 0.05, 0.5 / (2.0 * math.sqrt(20.0))  # the chapter's mass ratio, the paper's primary (c = 0.5 N s/m)
R_GRID = np.linspace(0.0, 3.0, 20001)


def _grid_peak(mu: float, f: float, za: float, zp: float) -> float:
    return float(np.max(tmd_magnification(mu, f, za, r=R_GRID, zeta_p=zp)))


def _naive_hinf(mu: float, zp: float) -> tuple[float, float]:
    """Nelder-Mead over (f, ln ζ_a) of the grid peak, from Den Hartog's point."""

    def cost(x):
        f, lz = x
        if not 0.0 < f <= 10.0 or lz > 2.0:
            return math.inf
        return math.log(_grid_peak(mu, f, math.exp(lz), zp))

    x0 = [1.0 / (1.0 + mu), 0.5 * math.log(3.0 * mu / (8.0 * (1.0 + mu)))]
    res = minimize(cost, x0, method="Nelder-Mead", options={"xatol": 1e-9, "fatol": 1e-13})
    return float(res.x[0]), math.exp(float(res.x[1]))


def _bench_peak(quick: bool) -> None:
    t = hinf_tuning(MU, ZETA_P)
    f, za = t.f * 1.01, t.zeta_a
    exact = tmd_peak(MU, f, za, zeta_p=ZETA_P)
    t_exact = median_time(lambda: tmd_peak(MU, f, za, zeta_p=ZETA_P), 100 if quick else 400)
    t_grid = median_time(lambda: _grid_peak(MU, f, za, ZETA_P), 20 if quick else 80)
    err = abs(_grid_peak(MU, f, za, ZETA_P) / exact - 1.0)
    table(
        "peak magnification of the primary with a TMD (mu 0.05, paper's damping, 1 % off the H-inf tuning)",
        [
            ("tmd_peak (stationarity polynomial, exact)", t_exact, None, ""),
            (f"largest sample on 20001 ratios (rel. error {err:.1e})", t_grid, t_grid / t_exact, ""),
        ],
    )


def _bench_hinf(quick: bool) -> None:
    k = 1 if quick else 3
    t = hinf_tuning(MU, ZETA_P)
    t_opt = median_time(lambda: hinf_tuning(MU, ZETA_P), k)
    t_naive = median_time(lambda: _naive_hinf(MU, ZETA_P), k)
    f, za = _naive_hinf(MU, ZETA_P)
    excess = tmd_peak(MU, f, za, zeta_p=ZETA_P) / t.peak - 1.0
    table(
        "numerical H-inf optimum for the paper's damped primary (mu 0.05)",
        [
            ("hinf_tuning (Nelder-Mead on the exact peak + equal-peak solve)", t_opt, None, ""),
            (f"Nelder-Mead on the 20001-sample grid peak (peak {excess:+.1e} rel.)", t_naive, t_naive / t_opt, ""),
        ],
    )


def _bench_frf(quick: bool) -> None:
    kips, inch, g = 4448.2216152605, 0.0254, 9.80665
    b = shear_building([100 * kips / g] * 5, [31.54 * kips / inch] * 5, 0.05)
    a = first_mode_absorber(b, 0.02)
    bt = add_absorber(b, -1, a.m_a, k_a=a.k_a, c_a=a.c_a)
    w1 = float(b.natural_frequencies[0])
    w = np.linspace(0.3 * w1, 1.8 * w1, 3001)
    load = np.r_[np.zeros(b.n - 1), 1.0, 0.0]

    def naive():
        return np.array([np.linalg.inv(bt.K - x * x * bt.M + 1j * x * bt.C) @ load for x in w])

    def batched():
        D = bt.K[None] - (w * w)[:, None, None] * bt.M[None] + 1j * w[:, None, None] * bt.C[None]
        return np.linalg.solve(D, np.broadcast_to(load.astype(complex), (w.size, bt.n))[..., None])[..., 0]

    ref = bt.frf(w, load)
    err_n = float(np.max(np.abs(naive() - ref) / np.abs(ref).max()))
    err_b = float(np.max(np.abs(batched() - ref) / np.abs(ref).max()))
    n = 5 if quick else 15
    t_frf = median_time(lambda: bt.frf(w, load), n)
    t_naive = median_time(naive, n)
    t_batch = median_time(batched, n)
    table(
        "roof receptance of the five-storey building with a roof TMD, 3001 frequencies (6 x 6 complex systems)",
        [
            ("MDOF.frf (one complex solve per frequency)", t_frf, None, ""),
            (f"explicit inverse per frequency (max diff {err_n:.0e} of the peak)", t_naive, t_naive / t_frf, ""),
            (f"one batched numpy.linalg.solve (max diff {err_b:.0e})", t_batch, t_batch / t_frf, "(< 1: faster)"),
        ],
    )


def _bench_response(quick: bool) -> None:
    m, c, k, F0, w = 1.0, 0.5, 20.0, 5.0, 4.47
    model = tmd_system(m, c, k, tuning=hinf_tuning(MU, ZETA_P))
    t = np.linspace(0.0, 50.0, 5001)
    p = np.array([F0, 0.0])
    A = model.state_matrix
    Minv_p = np.linalg.solve(model.M, p)

    def rhs(tt, z):
        dz = A @ z
        dz[2:] += Minv_p * math.sin(w * tt)
        return dz

    def dop():
        return solve_ivp(rhs, (0.0, 50.0), np.zeros(4), method="DOP853", t_eval=t, rtol=1e-10, atol=1e-12).y[0]

    x = model.response(t, p, w, method="modal").x[:, 0]
    sub = t[::50]
    err_e = float(np.max(np.abs(model.response(sub, p, w, method="expm").x[:, 0] - x[::50])))
    err_d = float(np.max(np.abs(dop() - x)))
    n = 5 if quick else 20
    t_modal = median_time(lambda: model.response(t, p, w, method="modal"), n)
    t_expm = median_time(lambda: model.response(sub, p, w, method="expm"), 1 if quick else 3) * (t.size / sub.size)
    t_dop = median_time(dop, 1 if quick else 3)
    table(
        "exact response of the primary with its TMD, 5001 samples on [0, 50] s (expm timed on 1/50, scaled)",
        [
            ("MDOF.response, complex modal superposition", t_modal, None, ""),
            (f"augmented expm per sample (max |dx| {err_e:.0e} m)", t_expm, t_expm / t_modal, ""),
            (f"DOP853, rtol 1e-10, atol 1e-12 (max |dx| {err_d:.0e} m)", t_dop, t_dop / t_modal, ""),
        ],
    )


def run(quick: bool) -> None:
    """Time chapter 8's heaviest computations against naive alternatives (printed tables, no assertions)."""
    _bench_peak(quick)
    _bench_hinf(quick)
    _bench_frf(quick)
    _bench_response(quick)


if __name__ == "__main__":
    run(quick=True)
