"""The chapter's parameters, declared once (name, symbol, default, unit, range, meaning).

The ranges keep every accepted combination under about a minute and the prose true: windows of
at least one whole drive period, calibration on at most the six slowest runs (the two lowest
motor voltages, far below resonance), a steady-state test at 1 to 10 standard errors.

Examples
--------
>>> Params().n_late, Params.from_values({"n_late": 4}).n_late
(6, 4)
>>> Params.from_values({"n_early": 5, "n_late": 3})  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
vibration.physics.model.ParameterError: n_early = 5 is out of range: allowed n_early <= n_late = 3 ...
"""

from __future__ import annotations

from vibration.physics.model import ParameterError
from vibration.presentation.schema import Param, Schema


def _early_not_longer(values: dict) -> None:
    if values["n_early"] > values["n_late"]:
        raise ParameterError(
            f"n_early = {values['n_early']} is out of range: allowed n_early <= n_late = {values['n_late']} "
            "(the early window may not be longer than the late one)"
        )


SCHEMA = Schema(
    "12_real_oscillator",
    (
        Param("n_late", "n_late", 6, "", 1, 12, "whole drive periods in the late window (the end of each run)"),
        Param("n_early", "n_early", 2, "", 1, 6, "whole drive periods in the early window (the start of each run)"),
        Param("n_calibration", "n_cal", 3, "", 1, 6, "lowest-frequency driven runs that calibrate the drive gain g"),
        Param(
            "z_steady",
            "z_steady",
            3.0,
            "",
            1.0,
            10.0,
            "standard errors by which early and late amplitudes may differ in a steady run",
        ),
        Param(
            "brake",
            "brake",
            "on",
            "",
            meaning="free decays whose fits predict the driven runs: with the magnetic brake (on) or without (off)",
            choices=("on", "off"),
        ),
        Param(
            "decay_runs", "runs", "all", "", meaning="free-decay runs used in each file", choices=("all", "1-5", "6-10")
        ),
        Param(
            "spread_ratio_max",
            "s_max",
            2.0,
            "",
            1.0,
            10.0,
            "largest ratio of run-to-run scatter to a run's standard error that still counts as covered",
        ),
    ),
    together=(_early_not_longer,),
)


Params = SCHEMA.record_type()
