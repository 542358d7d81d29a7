r"""Chapter 9, the Duffing oscillator: the whole computation, once, into frozen records (SI units, no prose).

The paper's oscillator with a cubic spring,

.. math::

    m\ddot x + c\dot x + kx + k_3x^3 = F_0\cos\omega t,

is studied two independent ways: harmonic balance (one harmonic, closed form, stability from the
slow flow) against the full equation (periodic orbits by shooting with their Floquet multipliers,
continued through the bistable band; stepped frequency sweeps by time integration). The paper's
resonance scenario is re-run with the hardening spring, and Ueda's oscillator
:math:`\ddot x + c_U\dot x + x^3 = F_U\cos t` gives the chaotic case with its largest Lyapunov
exponent, a standard error from batch means and runs that share no trajectory.

:func:`duffing_study` takes the chapter's validated :class:`~vibration.book.chapters.duffing.params.Params`
and returns a :class:`DuffingStudy`; figures, tables and sentences are functions of that record.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from vibration.book.chapters.duffing.chaos import (
    CONVERGENCE_LENGTHS,
    LYAPUNOV_RUNS,
    MAP_FORCES,
    MAP_OMEGAS,
    MAP_PERIODS,
    N_OTHER_RUNS,
    N_PERIODIC,
    N_SECTION,
    PUBLISHED_UEDA,
    UEDA_START,
    ChaosMap,
    ChaosStudy,
    ConvergenceRow,
    Pooled,
    Published,
    chaos_map,
    chaos_study,
    ueda_chaos,
)
from vibration.book.chapters.duffing.params import Params
from vibration.book.chapters.duffing.springs import (
    CONTINUATION_STEP,
    CURVE_REACH,
    FoldRow,
    HistoryRow,
    SpringCase,
    StabilityCheck,
    _fold_rows,
    _history,
    _spring,
)
from vibration.physics.duffing import (
    Duffing,
    LyapunovEstimate,
    LyapunovResult,
    duffing_response,
    hb_amplitudes,
    linear_trust_amplitude,
)
from vibration.physics.exact import exact_response
from vibration.physics.model import Oscillator, ParameterError, SineForce


@dataclass(frozen=True, eq=False, kw_only=True)
class DuffingStudy:
    """Everything chapter 9 shows, computed once (SI units)."""

    params: Params
    cases: tuple[SpringCase, SpringCase]  # hardening, softening
    linear_omega: np.ndarray = field(repr=False)  # linear spring over the hardening curve's range, rad/s
    linear_amplitude_curve: np.ndarray = field(repr=False)  # m
    folds_compared: tuple[FoldRow, ...]
    # the paper's scenario (hardening spring)
    trust_amplitude: float  # amplitude where the backbone leaves the half-power band, m
    linear_amplitude: float  # steady linear amplitude at omega_res, m
    paper_t: np.ndarray = field(repr=False)  # s
    paper_x_linear: np.ndarray = field(repr=False)  # m
    paper_x_duffing: np.ndarray = field(repr=False)  # m
    history: tuple[HistoryRow, ...]
    # chaos
    ueda: Duffing
    section_chaos: np.ndarray = field(repr=False)  # (x, v) once per forcing period, m and m/s
    section_periodic: np.ndarray = field(repr=False)
    periodic_qr: LyapunovResult = field(repr=False)
    periodic_benettin: LyapunovResult = field(repr=False)
    lyap_runs: tuple[LyapunovEstimate, ...] = field(repr=False)  # main run first, QR
    lyap_benettin: LyapunovEstimate = field(repr=False)  # two trajectories, main run's start
    pooled: Pooled
    convergence: tuple[ConvergenceRow, ...]
    floquet_periodic: float  # log max|mu| / T of the periodic Ueda orbit, 1/s (nan: not period 1)
    published: Published
    chaos_map: ChaosMap
    # self-checks
    amp_residual: float  # largest relative residual of the amplitude equation on the drawn curves
    liouville: float  # largest relative error of |mu1 mu2| against exp(-cT/m)
    qr_sum_error: float  # largest |lambda1 + lambda2 + c/m| of the QR runs, 1/s
    fold_multiplier_error: float  # largest |mu - 1| at the continued folds (nan: no fold)

    @property
    def hardening(self) -> SpringCase:
        return self.cases[0]

    @property
    def softening(self) -> SpringCase:
        return self.cases[1]

    @property
    def main_run(self) -> LyapunovEstimate:
        """The main chaotic run (variational equations with QR)."""
        return self.lyap_runs[0]

    @property
    def periodic_exponent(self) -> float:
        """Largest exponent of the periodic Ueda case (QR), 1/s."""
        return self.periodic_qr.exponents[0]

    def running(self, which: str, method: str) -> tuple[np.ndarray, np.ndarray]:
        """Running estimate of the largest exponent: (averaging time s, estimate 1/s) of ``which`` in
        ("chaotic", "periodic") by ``method`` in ("qr", "benettin")."""
        T = 2 * math.pi / self.params.omega_ueda  # forcing period, s
        if which == "chaotic":
            e = self.main_run if method == "qr" else self.lyap_benettin
            n = np.arange(1, e.n_periods + 1)
            return n * T, np.cumsum(e.increments) / (n * T)
        r = self.periodic_qr if method == "qr" else self.periodic_benettin
        return (np.arange(r.running.size) + 1) * T, r.running

    def method_gap(self, which: str, skip: int = 10) -> float:
        """Largest difference of the two methods' running estimates after the first ``skip`` periods,
        relative to the final estimate's magnitude."""
        _, a = self.running(which, "qr")
        _, b = self.running(which, "benettin")
        n = min(a.size, b.size)
        return float(np.max(np.abs(a[skip:n] - b[skip:n])) / abs(a[n - 1]))

    def section_points(self, which: str) -> int:
        """Distinct points (to 10⁻⁶ m and m/s) of the Poincaré section of the ``"chaotic"`` or ``"periodic"`` case
        (1: a period-1 orbit)."""
        sec = self.section_chaos if which == "chaotic" else self.section_periodic
        return int(np.unique(np.round(sec / 1e-6), axis=0).shape[0])


# ----------------------------------------------------------------------------------- computation


def _check_values(p: Params) -> None:
    """The chapter's needs beyond the schema's ranges: damping (the slow flow and the folds need c > 0), a
    softening spring that softens."""
    if not p.c_nominal > 0.0:
        raise ParameterError(
            f"c_nominal = {p.c_nominal!r} N s/m is out of range for the Duffing chapter: allowed c_nominal > 0 N s/m"
        )
    if not p.k3_soft < 0.0:
        raise ParameterError(f"k3_soft = {p.k3_soft!r} N/m³ is out of range: allowed k3_soft < 0 N/m³")


def duffing_study(params: Params | None = None, **values) -> DuffingStudy:
    """Compute chapter 9: harmonic balance, Floquet checks, sweeps, continued folds, the paper's scenario, chaos.

    Parameters
    ----------
    params : Params, optional
        The chapter's validated parameters (see :data:`~vibration.book.chapters.duffing.params.SCHEMA`); or give
        them as keyword arguments, checked by the schema (the others keep their defaults).

    Returns
    -------
    DuffingStudy
        Frozen record of every result the chapter shows.

    Raises
    ------
    ParameterError
        A value outside the schema's range, a damping ``c_nominal <= 0`` or ``k3_soft = 0``.

    Examples
    --------
    >>> s = duffing_study(n_sweep=40, n_lyapunov=200)
    >>> [c.label for c in s.cases], s.hardening.folds.bistable, s.hardening.orbit_folds[0] > 5.0   # rad/s
    (['hardening', 'softening'], True, True)
    """
    p = params if params is not None else Params.from_values(values)
    if not isinstance(p, Params):
        raise ParameterError(f"params = {p!r:.60} is not valid: allowed a duffing Params record or None")
    _check_values(p)
    ws = np.linspace(p.omega_sweep_min, p.omega_sweep_max, p.n_sweep)
    hard, r1, l1 = _spring("hardening", Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=p.k3_hard), p.F0, ws, p.omega_sweep_max)
    soft, r2, l2 = _spring("softening", Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=p.k3_soft), p.F0, ws, p.omega_sweep_max)
    cases = (hard, soft)
    lin = Duffing(m=p.m, c=p.c_nominal, k=p.k, k3=0.0)
    w_lin = np.linspace(hard.curve_omega.min(), hard.curve_omega.max(), 800)
    a_lin = np.array([hb_amplitudes(lin, p.F0, w)[0][0] for w in w_lin])

    t = np.linspace(0.0, p.t_end, 2001)
    x_lin = exact_response(
        Oscillator(m=p.m, c=p.c_nominal, k=p.k), SineForce(F0=p.F0, omega=p.omega_res), t
    ).x  # Part I's form
    x_duf, _ = duffing_response(hard.duffing, p.F0, p.omega_res, t=t, sine=True)

    chaos = ueda_chaos(p)
    fold_mu = [abs(f.multiplier - 1.0) for c in cases if c.branch for f in c.branch.folds]
    return DuffingStudy(
        params=p,
        cases=cases,
        linear_omega=w_lin,
        linear_amplitude_curve=a_lin,
        folds_compared=_fold_rows(cases),
        trust_amplitude=linear_trust_amplitude(hard.duffing),
        linear_amplitude=hb_amplitudes(lin, p.F0, p.omega_res)[0][0],
        paper_t=t,
        paper_x_linear=x_lin,
        paper_x_duffing=x_duf,
        history=_history(p, hard),
        amp_residual=max(r1, r2),
        liouville=max(l1, l2),
        fold_multiplier_error=max(fold_mu) if fold_mu else math.nan,
        **chaos,
    )


__all__ = [
    "CONTINUATION_STEP",
    "CONVERGENCE_LENGTHS",
    "CURVE_REACH",
    "LYAPUNOV_RUNS",
    "MAP_FORCES",
    "MAP_OMEGAS",
    "MAP_PERIODS",
    "N_OTHER_RUNS",
    "N_PERIODIC",
    "N_SECTION",
    "PUBLISHED_UEDA",
    "UEDA_START",
    "ChaosMap",
    "ChaosStudy",
    "ConvergenceRow",
    "DuffingStudy",
    "FoldRow",
    "HistoryRow",
    "Pooled",
    "Published",
    "SpringCase",
    "StabilityCheck",
    "chaos_map",
    "chaos_study",
    "duffing_study",
]
