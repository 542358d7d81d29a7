"""Damping against amplitude on the real oscillator: the law each brake setting's free decays choose, the band
of amplitudes all settings cover, and the brake law against the brake current.

Choices, stated once:

* **Laws.** Each candidate law is fitted to every free decay of a brake setting; the setting's law is
  the one of smallest BIC summed over its runs, and each run's own choice is counted.
* **Band.** The brake settings are compared over the amplitudes all of them cover: from the largest of
  their 10th percentiles of half-period amplitude to the smallest of their 90th percentiles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from vibration.physics.lab import damping_vs_amplitude, fit_free_decays
from vibration.physics.model import ParameterError

#: Candidate damping laws, from the paper's to the amplitude-dependent ones.
LAWS = ("viscous", "coulomb", "coulomb+viscous", "coulomb+quadratic", "coulomb+power")
#: The paper's model (a linear viscous damper).
PAPER_LAW = "viscous"
#: Percentiles of each setting's half-period amplitudes that bound the comparison band.
BAND_PERCENTILES = (10.0, 90.0)


@dataclass(frozen=True, kw_only=True, eq=False)
class Setting:
    """The free decays of one brake setting.

    Attributes
    ----------
    brake : str
        Its label; ``current`` the brake current (A) or None.
    runs : tuple
        The LabRun records.
    curves : tuple of DampingCurve
        Damping against amplitude, per run.
    fits : dict
        Law -> PooledDecayFit.
    law : str
        The law of smallest summed BIC.
    wins : dict
        Law -> number of runs whose own BIC chose it.
    amplitude_range : tuple
        Smallest and largest half-period amplitude (rad).
    zeta_eq, zeta_eq_stderr : float
        Mean over runs of the run's mean zeta_eq inside the comparison band, and its run-to-run error.
    n_band : int
        Runs with half periods inside the band.
    """

    brake: str
    current: float | None
    law: str
    wins: dict
    amplitude_range: tuple
    zeta_eq: float
    zeta_eq_stderr: float
    n_band: int
    runs: tuple = field(repr=False)
    curves: tuple = field(repr=False)
    fits: dict = field(repr=False)


def _setting_curves(runs) -> tuple:
    return tuple(damping_vs_amplitude(r.t, r.angle) for r in runs)


def _band(settings_curves) -> tuple | None:
    lows, highs = [], []
    for curves in settings_curves:
        x = np.concatenate([c.amplitude for c in curves]) if curves else np.array([])
        if x.size < 3:
            return None
        lo, hi = np.percentile(x, BAND_PERCENTILES)
        lows.append(lo)
        highs.append(hi)
    lo, hi = float(max(lows)), float(min(highs))
    return (lo, hi) if lo < hi else None


def _band_stats(curves, band) -> tuple[float, float, int]:
    if band is None:
        return math.nan, math.nan, 0
    lo, hi = band
    per = [c.zeta_eq[(c.amplitude >= lo) & (c.amplitude <= hi)] for c in curves]
    per = [float(v.mean()) for v in per if v.size]
    if not per:
        return math.nan, math.nan, 0
    se = float(np.std(per, ddof=1) / math.sqrt(len(per))) if len(per) > 1 else math.nan
    return float(np.mean(per)), se, len(per)


def _setting(brake, current, runs, band) -> Setting:
    curves = _setting_curves(runs)
    fits = {}
    for law in LAWS:
        try:
            fits[law] = fit_free_decays(runs, law)
        except ParameterError:
            continue
    if not fits:
        raise ParameterError(f"lab_data: no free decay of brake setting {brake!r} could be fitted")
    law = min(fits, key=lambda k: fits[k].bic)
    wins = dict.fromkeys(fits, 0)
    for i in range(len(runs)):
        best = min(fits, key=lambda k: fits[k].fits[i].bic)
        wins[best] += 1
    x = np.concatenate([c.amplitude for c in curves])
    z, zse, n_band = _band_stats(curves, band)
    return Setting(
        brake=brake,
        current=current,
        runs=tuple(runs),
        curves=curves,
        fits=fits,
        law=law,
        wins=wins,
        amplitude_range=(float(x.min()), float(x.max())) if x.size else (math.nan, math.nan),
        zeta_eq=z,
        zeta_eq_stderr=zse,
        n_band=n_band,
    )


def brake_resolved(d, j) -> bool:
    """Resolved when both estimates exclude 0 (two standard errors) with the same sign."""
    joint_out = abs(j.delta_zeta) > 2.0 * j.stderr
    return bool(d.resolved and joint_out and np.sign(d.delta_zeta) == np.sign(j.delta_zeta))


def _current_law(settings) -> dict | None:
    pts = [
        (s.current, s.fits["coulomb+viscous"])
        for s in settings
        if s.current is not None and "coulomb+viscous" in s.fits
    ]
    if len(pts) <= 2:
        return None
    i2 = np.array([p[0] ** 2 for p in pts])
    z = np.array([p[1].mean["zeta"] for p in pts])
    se = np.array([max(p[1].stderr["zeta"], 1e-6) for p in pts])
    X = np.column_stack([np.ones_like(i2), i2])
    W = 1.0 / se**2
    cov = np.linalg.pinv(X.T @ (X * W[:, None]))
    coef = cov @ (X.T @ (W * z))
    chi2 = float(np.sum(W * (z - X @ coef) ** 2))
    dof = max(1, len(pts) - 2)
    scale = max(1.0, math.sqrt(chi2 / dof))
    return {
        "zeta0": float(coef[0]),
        "k": float(coef[1]),
        "zeta0_stderr": float(math.sqrt(cov[0, 0]) * scale),
        "k_stderr": float(math.sqrt(cov[1, 1]) * scale),
        "chi2": chi2,
        "dof": dof,
        "currents": tuple(float(p[0]) for p in pts),
        "zeta": tuple(float(v) for v in z),
        "zeta_stderr": tuple(float(v) for v in se),
    }
