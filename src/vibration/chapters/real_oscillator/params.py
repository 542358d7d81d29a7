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
    "12_real_oscillator",
    (
        Param(
            "lab_data",
            "folder",
            DEFAULT_LAB,
            "",
            meaning="folder of logger files with a manifest runs.csv (and optionally rig.csv)",
            path=True,
        ),
        Param("periods", "n_late", 3, "", 2, 10, "final drive periods over which a steady run may drift"),
        Param("tolerance", "tol", 0.02, "", 0.005, 0.2, "largest relative late drift of a steady run"),
        Param(
            "frequency_tolerance",
            "tol_ω",
            0.01,
            "",
            0.001,
            0.05,
            "relative spread of measured drive frequency within one group of driven runs",
        ),
        Param(
            "calibration_detuning",
            "r_cal",
            0.1,
            "",
            0.02,
            0.5,
            "smallest |ω/ω_n − 1| of the runs that calibrate the drive gain (off resonance)",
        ),
    ),
)


Params = SCHEMA.record_type()
