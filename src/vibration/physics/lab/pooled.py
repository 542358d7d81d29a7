"""Free-decay fits pooled over runs: coefficients with run-to-run standard errors, residuals against the
encoder step, and the information criterion summed over runs."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from vibration.physics.lab.amplitude import _as_runs
from vibration.physics.lab.decay import FreeDecayFit, equivalent_zeta, fit_free_decay, law_name, parse_law
from vibration.physics.lab.peaks import _resolution

_KEYS = ("omega_n", "zeta", "friction", "quadratic", "power", "power_exponent", "offset")


@dataclass(frozen=True, kw_only=True, eq=False)
class PooledDecayFit:
    """One damping law fitted to every run of a set.

    Attributes
    ----------
    law : str
        Canonical law string.
    mean : dict
        Mean over runs of "omega_n" (rad/s), "zeta", "friction" (rad), "quadratic" (1/rad), "power",
        "power_exponent", "offset" (rad). For the power law, "power" and "power_exponent" are those of the one
        power term whose equivalent damping ratio best matches the runs' own over the amplitudes they cover
        (coefficients with different exponents do not average); their ``stderr`` are the jackknife over runs (the
        term fitted again with each run left out).
    stderr : dict
        Run-to-run standard errors of those means (sample standard deviation / sqrt(n)); with a single
        run, that run's own fit error.
    fit_stderr : dict
        Median over runs of the fits' own standard errors (to compare with ``stderr``).
    coefficients : dict
        Mean of the law's terms only, keyed as :attr:`FreeDecayFit.coefficients`.
    residual_rms : float
        Root mean square of the residuals over every fitted sample of every run (rad).
    encoder_step : float
        Smallest step between distinct angles in the data (rad); ``rms_over_step`` is
        ``residual_rms / (encoder_step / sqrt(12))`` (1 for pure rounding noise).
    bic : float
        Sum of the runs' BIC.
    n_runs : int
        Runs fitted.
    fits : tuple of FreeDecayFit
        The per-run fits, in input order.
    """

    law: str
    mean: dict
    stderr: dict
    fit_stderr: dict
    coefficients: dict
    residual_rms: float
    encoder_step: float
    rms_over_step: float
    bic: float
    n_runs: int
    fits: tuple = field(repr=False)


#: Amplitudes (evenly spaced over those the runs cover) at which the pooled power term is matched to the runs'.
POWER_GRID = 64


def _pooled_power(fits, pairs, omega_n: float) -> tuple[float, float]:
    """Coefficient and exponent of the one power term whose equivalent damping ratio is closest, in least squares,
    to the mean of the runs' own power terms over the half-period amplitudes the runs cover.

    At each of :data:`POWER_GRID` amplitudes the target is the mean over the runs whose decay covers it, weighted
    by their number; the coefficient is linear (closed form) and the exponent is searched within
    :data:`~vibration.physics.lab.damping_laws.POWER_EXPONENT_RANGE`. Averaging the runs' coefficients and
    exponents separately would give a term that matches none of them away from one amplitude.
    """
    from scipy import optimize

    from vibration.physics.lab.amplitude import _curve
    from vibration.physics.lab.damping_laws import POWER_EXPONENT_RANGE

    ranges = []
    for t, y in pairs:
        x = _curve(t, y).amplitude
        x = x[x > 0]
        ranges.append((float(x.min()), float(x.max())) if x.size else (math.inf, -math.inf))
    lo, hi = min(r[0] for r in ranges), max(r[1] for r in ranges)
    mean_exponent = float(np.mean([f.power_exponent for f in fits]))
    if not lo < hi:  # no run has two half periods: nothing to match
        return 0.0, mean_exponent
    grid = np.linspace(lo, hi, POWER_GRID)
    cover = np.array([(grid >= a) & (grid <= b) for a, b in ranges])
    own = np.array([equivalent_zeta(grid, f.omega_n, power=max(f.power, 0.0), power_exponent=f.power_exponent)
                    for f in fits])  # fmt: skip
    weight = cover.sum(axis=0).astype(float)
    keep = weight > 0
    x, w = grid[keep], weight[keep]
    target = np.where(cover, own, 0.0).sum(axis=0)[keep] / w
    if not np.any(target > 0):
        return 0.0, mean_exponent

    def best(p: float) -> tuple[float, float]:
        unit = np.asarray(equivalent_zeta(x, omega_n, power=1.0, power_exponent=p))
        a = max(float(np.sum(w * unit * target) / np.sum(w * unit * unit)), 0.0)
        return a, float(np.sum(w * (a * unit - target) ** 2))

    res = optimize.minimize_scalar(
        lambda p: best(p)[1], bounds=POWER_EXPONENT_RANGE, method="bounded", options={"xatol": 1e-6, "maxiter": 200}
    )
    return best(float(res.x))[0], float(res.x)


def fit_free_decays(runs, law: str = "coulomb+viscous") -> PooledDecayFit:
    """Fit one law to each free decay and pool the coefficients with run-to-run standard errors.

    Parameters
    ----------
    runs : sequence
        Free decays, ``(t, theta)`` pairs (s, rad) or :class:`~vibration.physics.lab.logger.LoggerRun`.
    law : str
        As for :func:`~vibration.physics.lab.decay.fit_free_decay`.

    Returns
    -------
    PooledDecayFit

    Examples
    --------
    >>> import numpy as np
    >>> from vibration.physics.lab.decay import free_decay_response
    >>> t = np.arange(0.0, 10.0, 0.05)
    >>> runs = [(t, free_decay_response(t, 4.5, 0.0, friction=d, theta0=2.0)) for d in (0.04, 0.05, 0.06)]
    >>> p = fit_free_decays(runs, "coulomb")
    >>> round(p.coefficients["coulomb"], 6), round(p.stderr["friction"], 6)
    (0.05, 0.005774)
    """
    terms = parse_law(law)
    pairs = _as_runs("runs", runs)
    fits: list[FreeDecayFit] = [fit_free_decay(t, y, law_name(terms)) for t, y in pairs]
    n = len(fits)
    mean, stderr, fit_se = {}, {}, {}
    for k in _KEYS:
        v = np.array([getattr(f, k) for f in fits])
        mean[k] = float(v.mean())
        stderr[k] = float(v.std(ddof=1) / math.sqrt(n)) if n > 1 else float(fits[0].stderr[k])
        fit_se[k] = float(np.median([f.stderr[k] for f in fits]))
    if "power" in terms:  # a_i with different p_i do not average: one power term matching the runs' own
        mean["power"], mean["power_exponent"] = _pooled_power(fits, pairs, mean["omega_n"])
        if n > 2:  # its error: the jackknife over runs (leave one run out, fit again)
            drop = np.array([_pooled_power(fits[:i] + fits[i + 1 :], pairs[:i] + pairs[i + 1 :], mean["omega_n"])
                             for i in range(n)])  # fmt: skip
            spread = np.sqrt((n - 1) / n * np.sum((drop - drop.mean(axis=0)) ** 2, axis=0))
            stderr["power"], stderr["power_exponent"] = float(spread[0]), float(spread[1])
    coeffs = {}
    names = {"viscous": "zeta", "coulomb": "friction", "quadratic": "quadratic", "power": "power"}
    for key in fits[0].coefficients:
        coeffs[key] = mean[names.get(key, key)]
    rss = sum(float(f.residual_rms) ** 2 * f.n for f in fits)
    n_samples = sum(f.n for f in fits)
    steps = [s for s in (_resolution(np.asarray(y)) for _, y in pairs) if s > 0]
    step = float(min(steps)) if steps else 0.0
    rms = math.sqrt(rss / n_samples)
    return PooledDecayFit(
        law=law_name(terms),
        mean=mean,
        stderr=stderr,
        fit_stderr=fit_se,
        coefficients=coeffs,
        residual_rms=rms,
        encoder_step=step,
        rms_over_step=rms / (step / math.sqrt(12.0)) if step > 0 else math.inf,
        bic=float(sum(f.bic for f in fits)),
        n_runs=n,
        fits=tuple(fits),
    )
