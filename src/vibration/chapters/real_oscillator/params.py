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

from vibration.presentation.parameters import count, ratio
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
        count("periods", "n_late", 3, low=2, high=10, meaning="final drive periods over which a steady run may drift"),
        ratio("tolerance", "tol", 0.02, low=0.005, high=0.2, meaning="largest relative late drift of a steady run"),
        ratio(
            "frequency_tolerance",
            "tol_ω",
            0.01,
            low=0.001,
            high=0.05,
            meaning="relative spread of measured drive frequency within one group of driven runs",
        ),
        ratio(
            "calibration_detuning",
            "r_cal",
            0.1,
            low=0.02,
            high=0.5,
            meaning="smallest |ω/ωₙ − 1| of the runs that calibrate the drive gain (off resonance)",
        ),
    ),
)


Params = SCHEMA.record_type(module=__name__)
