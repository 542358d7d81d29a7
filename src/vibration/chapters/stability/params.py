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
    "06_stability",
    (
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("c_low", meaning="low damping coefficient"),
        shared("c_nominal"),
        shared("c_high"),
        Param("c_unstable", "c_u", -0.1, "N s/m", -10000.0, 0.0, "damping of the flutter model (negative, or 0)"),
        Param("t_growth", "t_g", 200.0, "s", 0.0, 2000.0, "window of the growth comparison", low_open=True),
        Param(
            "isolation_ratio",
            "r_iso",
            3.0,
            "",
            1.4142135623730951,
            100.0,
            "frequency ratio at which isolation is judged",
            low_open=True,
        ),
        Param(
            "S0",
            "S_0",
            0.1,
            "N² s/rad",
            0.0,
            1000000.0,
            "two-sided spectral density of the white-noise force",
            low_open=True,
        ),
        Param("n_paths", "N_paths", 200, "", 2, 5000, "Monte Carlo paths per damping"),
        Param("seed", "s", 1, "", 0, 2147483647, "seed of the Monte Carlo generator"),
    ),
    together=(growth_window,),
)

Params = SCHEMA.record_type()
