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
        "power_exponent", "offset" (rad). For the power law, "power" is the coefficient whose
        equivalent damping ratio at the runs' median half-period amplitude, with the mean exponent,
        equals the mean over runs of theirs (coefficients with different exponents do not average).
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


def _reference_amplitude(pairs) -> float:
    """Median half-period amplitude of the runs (rad): where the power term's pooled coefficient is matched."""
    from vibration.physics.lab.amplitude import _curve

    x = np.concatenate([_curve(t, y).amplitude for t, y in pairs])
    return float(np.median(x)) if x.size else 1.0


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
    if "power" in terms:  # a_i with different p_i do not average: match the mean equivalent ratio at X_ref
        x_ref = _reference_amplitude(pairs)
        z_ref = np.mean(
            [equivalent_zeta(x_ref, f.omega_n, power=f.power, power_exponent=f.power_exponent) for f in fits]
        )
        unit = float(equivalent_zeta(x_ref, mean["omega_n"], power=1.0, power_exponent=mean["power_exponent"]))
        mean["power"] = float(z_ref) / unit if unit > 0 else 0.0
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
