"""Chapter 8, tuned mass dampers: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

import math

from vibration.physics.model import ParameterError
from vibration.presentation.parameters import damping_ratio_at_most, paper_window, shared
from vibration.presentation.schema import Param, Schema


def storey_rates(p: dict) -> None:
    """The building's modes fit the chapter's time grid: the highest resolved, the lowest at least one period long.

    A uniform shear building of n storeys has ω_j = 2 √(k_s/m_s) sin((2j − 1)π / (2(2n + 1))): all below
    2 √(k_s/m_s), the first one 2 √(k_s/m_s) sin(π / (2(2n + 1))).
    """
    rate = math.sqrt(p["storey_stiffness"] / p["storey_mass"])
    step = p["t_end"] / (p["n_points"] - 1)
    highest, first = 2.0 * rate, 2.0 * rate * math.sin(math.pi / (2.0 * (2 * p["n_storeys"] + 1)))
    shown = f"storey_stiffness = {p['storey_stiffness']!r} N/m and storey_mass = {p['storey_mass']!r} kg"
    if highest * step > math.pi:
        raise ParameterError(
            f"{shown} give modes up to {highest:.4g} rad/s, above the Nyquist frequency {math.pi / step:.4g} rad/s of "
            f"t_end/(n_points - 1) = {step:.4g} s: allowed √(storey_stiffness/storey_mass) <= "
            f"{math.pi / (2.0 * step):.4g} rad/s"
        )
    if first * p["t_end"] < 2.0 * math.pi:
        raise ParameterError(
            f"{shown} give a first mode of {first:.4g} rad/s, slower than one period in t_end = {p['t_end']!r} s: "
            f"allowed √(storey_stiffness/storey_mass) >= {2.0 * math.pi / (p['t_end'] * first / rate):.4g} rad/s"
        )


SCHEMA = Schema(
    "08_tmd",
    (
        shared("m", meaning="primary mass"),
        shared("k", meaning="primary spring stiffness"),
        shared("F0"),
        shared("c_nominal", meaning="primary damping coefficient"),
        shared("omega_res", meaning='"resonant" forcing frequency of the paper'),
        shared("t_end", meaning="end of the simulated window"),
        shared("n_points"),
        Param("mu", "μ", 0.05, "", 0.0, 1.0, "absorber mass over primary mass", low_open=True),
        Param("mistuning", "δ_k", 0.1, "", 0.0, 0.5, "largest relative error of the primary's stiffness"),
        Param("n_storeys", "n", 5, "", 1, 30, "storeys of the shear building"),
        Param(
            "storey_mass",
            "m_s",
            45359.237,
            "kg",
            0.001,
            1000000000.0,
            "floor mass (Chopra's 100 kips/g converted to SI)",
        ),
        Param(
            "storey_stiffness",
            "k_s",
            5523500.0,
            "N/m",
            0.001,
            1000000000000.0,
            "storey stiffness (Chopra's 31.54 kips/in converted to SI)",
        ),
        Param("zeta_building", "ζ_b", 0.05, "", 0.0, 0.99, "modal damping ratio of the building"),
        Param("mu_building", "μ_b", 0.02, "", 0.0, 1.0, "roof absorber mass over the first modal mass", low_open=True),
    ),
    together=(paper_window, damping_ratio_at_most(0.5), storey_rates),
)

Params = SCHEMA.record_type()
