"""Chapter 6, stability and damping as a design choice: its parameters (a growth window a float holds)."""

from __future__ import annotations

import math

from vibration.physics.model import ParameterError
from vibration.presentation.parameters import (
    MAX_GROWTH,
    count,
    damping,
    positive,
    quantity,
    seed,
    shared,
    shared_params,
)
from vibration.presentation.schema import Schema


def growth_window(p: dict) -> None:
    """The growth comparison's window stays within what a float holds for the flutter model's negative damping."""
    c, m, t = p["c_unstable"], p["m"], p["t_growth"]
    exponent = -c / (2.0 * m) * t
    if exponent > MAX_GROWTH:
        raise ParameterError(
            f"t_growth = {t!r} s with c_unstable = {c!r} N s/m and m = {m!r} kg grows the response like "
            f"exp({exponent:.3g}): allowed (-c_unstable/2m) t_growth <= {MAX_GROWTH:g} "
            f"(t_growth <= {MAX_GROWTH * 2.0 * m / -c:.4g} s)"
        )


SCHEMA = Schema(
    notebook="06_stability",
    params=(
        *shared_params("m", "k", "F0"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("c_low", meaning="low damping coefficient"),
        *shared_params("c_nominal", "c_high"),
        damping("c_unstable", "c_u", -0.1, low=-1e4, high=0.0, meaning="damping of the flutter model (negative, or 0)"),
        positive("t_growth", "t_g", 200.0, unit="s", high=2000.0, meaning="window of the growth comparison"),
        quantity(
            "isolation_ratio",
            "r_iso",
            3.0,
            unit="",
            low=math.sqrt(2.0),
            high=100.0,
            meaning="frequency ratio at which isolation is judged",
            low_open=True,
        ),
        positive(
            "S0", "S_0", 0.1, unit="N² s/rad", high=1e6, meaning="two-sided spectral density of the white-noise force"
        ),
        count("n_paths", "N_paths", 200, low=2, high=5000, meaning="Monte Carlo paths per damping"),
        seed(1, meaning="seed of the Monte Carlo generator"),
    ),
    together=(growth_window,),
)

Params = SCHEMA.record_type(module=__name__)
