"""The record of a whole-trace free-decay fit: parameters, standard errors, residual statistics and the model."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from vibration.physics.lab._checks import as_series
from vibration.physics.lab.damping_laws import _response_general, equivalent_zeta
from vibration.physics.model import ParameterError

__all__ = ["FreeDecayFit"]


@dataclass(frozen=True, eq=False, kw_only=True)
class FreeDecayFit:
    """Least-squares fit of a damping law's free decay to a whole trace.

    Attributes
    ----------
    law : str
        Canonical ``+``-joined terms (``"coulomb+viscous"``, ``"coulomb+quadratic"``, ...).
    omega_n : float
        Natural angular frequency (rad/s).
    zeta : float
        Viscous damping ratio (0 when the law has no viscous term).
    friction : float
        Coulomb friction angle Delta (rad; 0 without the Coulomb term).
    offset : float
        Resting angle theta_0 of the spring (rad).
    theta0, t0 : float
        Angle (rad) and time (s) of the first extremum, where the fit starts.
    quadratic : float
        Quadratic coefficient b (1/rad) of b theta'|theta'| (0 when absent).
    power, power_exponent : float
        Coefficient a (rad^(1-p) s^(p-2)) and exponent p of a |theta'|^p sgn theta' (0 when absent).
    coefficients : dict
        The fitted terms only: "viscous" (zeta), "coulomb" (Delta, rad), "quadratic" (b, 1/rad),
        "power" (a) and "power_exponent" (p).
    stderr : dict
        Standard errors keyed "omega_n", "zeta", "friction", "offset", "theta0", "t0", "quadratic",
        "power", "power_exponent" (0 for a fixed parameter): the larger of ``stderr_naive`` and
        ``stderr_hac``.
    stderr_naive, stderr_hac : dict
        From ``s^2 (J^T J)^-1``, and the Newey-West (Bartlett, one half period of lags) sandwich
        that allows for correlated residuals.
    residual_rms : float
        Root mean square of the residuals (rad).
    aic, bic : float
        Akaike and Bayesian information criteria of the Gaussian likelihood, counting the fitted
        parameters and the noise variance.
    n : int
        Number of samples fitted; ``n_params`` the number of fitted parameters.
    n_half_periods : int
        Half periods between detected extrema inside the fitted window.
    t_start, t_end : float
        The fitted window (s).
    durbin_watson : float
        Durbin-Watson statistic of the residuals.
    ljung_box_p : float
        p-value of the Ljung-Box test of white residuals (20 lags or n/5).
    converged : bool
        Whether the least-squares solver reported convergence.
    residuals : numpy.ndarray
        Data minus model (rad) on the window.
    """

    law: str
    omega_n: float
    zeta: float
    friction: float
    offset: float
    theta0: float
    t0: float
    residual_rms: float
    aic: float
    bic: float
    n: int
    n_params: int
    n_half_periods: int
    t_start: float
    t_end: float
    durbin_watson: float
    ljung_box_p: float
    converged: bool
    residuals: np.ndarray = field(repr=False)
    stderr: dict = field(repr=False)
    stderr_naive: dict = field(repr=False)
    stderr_hac: dict = field(repr=False)
    quadratic: float = 0.0
    power: float = 0.0
    power_exponent: float = 0.0
    coefficients: dict = field(default_factory=dict, repr=False)

    def predict(self, t) -> np.ndarray:
        """Fitted angle (rad) at the times ``t`` (s)."""
        ta = as_series("t", t, unit="s", min_size=1)
        if ta.size > 1 and not np.all(np.diff(ta) > 0):
            raise ParameterError("t is not strictly increasing: allowed strictly increasing time (s)")
        return _response_general(
            ta,
            self.omega_n,
            self.zeta,
            self.friction,
            self.quadratic,
            self.power,
            self.power_exponent,
            self.offset,
            self.theta0,
            self.t0,
        )

    def zeta_eq(self, amplitude):
        """Equivalent viscous damping ratio at the half-period amplitude X (rad), Coulomb term included
        as its energy-balance equivalent 2 Delta / (pi X)."""
        x = np.asarray(amplitude, dtype=float)
        z = equivalent_zeta(
            x,
            self.omega_n,
            zeta=self.zeta,
            quadratic=self.quadratic,
            power=self.power,
            power_exponent=self.power_exponent or 2.0,
        )
        with np.errstate(divide="ignore"):
            return z + np.where(x > 0, 2.0 * self.friction / (math.pi * np.maximum(x, 1e-300)), np.inf)
