"""Chapter 6, stability and damping as a design choice: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.physics.model import ParameterError
from vibration.presentation.parameters import MAX_GROWTH, shared
from vibration.presentation.schema import Param, Schema


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
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("c_low", meaning="low damping coefficient"),
        shared("c_nominal"),
        shared("c_high"),
        Param(
            name="c_unstable",
            symbol="c_u",
            default=-0.1,
            unit="N s/m",
            low=-10000.0,
            high=0.0,
            meaning="damping of the flutter model (negative, or 0)",
        ),
        Param(
            name="t_growth",
            symbol="t_g",
            default=200.0,
            unit="s",
            low=0.0,
            high=2000.0,
            meaning="window of the growth comparison",
            low_open=True,
        ),
        Param(
            name="isolation_ratio",
            symbol="r_iso",
            default=3.0,
            unit="",
            low=1.4142135623730951,
            high=100.0,
            meaning="frequency ratio at which isolation is judged",
            low_open=True,
        ),
        Param(
            name="S0",
            symbol="S_0",
            default=0.1,
            unit="N² s/rad",
            low=0.0,
            high=1000000.0,
            meaning="two-sided spectral density of the white-noise force",
            low_open=True,
        ),
        Param(
            name="n_paths",
            symbol="N_paths",
            default=200,
            unit="",
            low=2,
            high=5000,
            meaning="Monte Carlo paths per damping",
        ),
        Param(
            name="seed",
            symbol="s",
            default=1,
            unit="",
            low=0,
            high=2147483647,
            meaning="seed of the Monte Carlo generator",
        ),
    ),
    together=(growth_window,),
)

Params = SCHEMA.record_type()
