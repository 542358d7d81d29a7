"""Chapter 11, a learning controller: its parameters, declared once (the sampling step checked against the plant)."""

from __future__ import annotations

import inspect
import math

from vibration.book.presentation.parameters import (
    at_least,
    declared,
    ordered,
    sampling,
)
from vibration.physics.learning.studies import identify_then_design
from vibration.physics.model import ParameterError
from vibration.physics.twin.measurements import MIN_SAMPLES

#: Length of the identification record of the identify-then-design study, s.
ID_DURATION = inspect.signature(identify_then_design).parameters["duration"].default


def sampling_step(p: dict) -> None:
    """The sampling step resolves the plant (below the Nyquist step π/ω_n) and the identification record."""
    dt, wn = p["dt"], math.sqrt(p["k"] / p["m"])
    if not dt < math.pi / wn:
        raise ParameterError(
            f"dt = {dt!r} s is not below half the natural period π/ω_n = {math.pi / wn:.4g} s (m = {p['m']!r} kg, "
            f"k = {p['k']!r} N/m): allowed dt < {math.pi / wn:.4g} s"
        )
    if dt > ID_DURATION / MIN_SAMPLES:
        raise ParameterError(
            f"dt = {dt!r} s leaves fewer than {MIN_SAMPLES} samples in the {ID_DURATION:g} s identification record: "
            f"allowed dt <= {ID_DURATION / MIN_SAMPLES:.4g} s"
        )


SCHEMA = declared(
    __package__,
    together=(
        ordered("c_semi_min", "c_semi_max", "N s/m"),
        at_least("c_nominal", 0.0, "N s/m", why="a learner needs a passive plant"),
        sampling,
        sampling_step,
    ),
)

Params = SCHEMA.record_type(module=__name__)
