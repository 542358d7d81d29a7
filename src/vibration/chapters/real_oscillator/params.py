"""The chapter's parameters, declared once (name, symbol, default, unit, range, meaning).

Every parameter applies to any laboratory's folder: the folder itself (``lab_data``, with its
manifest), the late window and tolerance of the steadiness test, the grouping of driven runs by
measured drive frequency, and the calibration subset's distance from resonance.

Examples
--------
>>> Params().periods, Params.from_values({"periods": 4}).periods
(3, 4)
"""

from __future__ import annotations

from vibration.presentation.schema import Param, Schema

#: The default folder (the package's copy of data/lab_oscillator).
DEFAULT_LAB = "data/lab_oscillator"

SCHEMA = Schema(
    notebook="12_real_oscillator",
    params=(
        Param(
            name="lab_data",
            symbol="folder",
            default=DEFAULT_LAB,
            unit="",
            meaning="folder of logger files with a manifest runs.csv (and optionally rig.csv)",
            path=True,
        ),
        Param(
            name="periods",
            symbol="n_late",
            default=3,
            unit="",
            low=2,
            high=10,
            meaning="final drive periods over which a steady run may drift",
        ),
        Param(
            name="tolerance",
            symbol="tol",
            default=0.02,
            unit="",
            low=0.005,
            high=0.2,
            meaning="largest relative late drift of a steady run",
        ),
        Param(
            name="frequency_tolerance",
            symbol="tol_ω",
            default=0.01,
            unit="",
            low=0.001,
            high=0.05,
            meaning="relative spread of measured drive frequency within one group of driven runs",
        ),
        Param(
            name="calibration_detuning",
            symbol="r_cal",
            default=0.1,
            unit="",
            low=0.02,
            high=0.5,
            meaning="smallest |ω/ω_n − 1| of the runs that calibrate the drive gain (off resonance)",
        ),
    ),
)


Params = SCHEMA.record_type()
