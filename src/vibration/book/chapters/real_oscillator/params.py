"""The chapter's parameters, declared once in ``params.toml`` (name, symbol, default, unit, range, meaning).

Every parameter applies to any laboratory's folder: the folder itself (``lab_data``, with its
manifest), the late window and tolerance of the steadiness test, the grouping of driven runs by
measured drive frequency, and the calibration subset's distance from resonance.

Examples
--------
>>> Params().periods, Params.from_values({"periods": 4}).periods
(3, 4)
"""

from __future__ import annotations

from vibration.book.presentation.parameters import declared

SCHEMA = declared(__package__)

#: The default folder (the package's copy of data/lab_oscillator).
DEFAULT_LAB = SCHEMA["lab_data"].default


Params = SCHEMA.record_type(module=__name__)
