"""A chapter's key results, declared once: name, unit, meaning and how to read each from its study.

A chapter package's ``keyresults.py`` holds one :class:`KeyResults`: the study function a sweep
runs at every point (the smallest computation that yields the key results; the chapter's full
study carries the same attributes) and the :class:`KeyResult` records. The key-results box on the
chapter's page and the runner's ``sweep`` both read the numbers through :meth:`KeyResult.read`, so
the box and a sweep point at the same parameters cannot disagree.

Examples
--------
>>> from types import SimpleNamespace
>>> r = KeyResult(name="X", unit="m", meaning="steady amplitude", read=lambda st: st.amplitude)
>>> r.read(SimpleNamespace(amplitude=2.5))
2.5
>>> ks = KeyResults(study=lambda p: SimpleNamespace(amplitude=p.F0 / 2.0), results=(r,))
>>> ks.values(ks.study(SimpleNamespace(F0=3.0)))
{'X': 1.5}
>>> ks["X"].unit, ks.names()
('m', ('X',))
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from .named import by_name, check_unique

_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")


@dataclass(frozen=True, kw_only=True)
class KeyResult:
    """One headline number of a chapter.

    Attributes
    ----------
    name : str
        A variable name (letters, digits, ``_``): the sweep's variable and the CSV's column value.
    unit : str
        SI unit as CF writes it (``"m"``, ``"1/s"``), ``"1"`` when dimensionless.
    meaning : str
        What it is, in words (the sweep's ``long_name``).
    read : callable
        ``read(study) -> float``: the value, from the chapter's study record.
    """

    name: str
    unit: str
    meaning: str
    read: Callable[[object], float]

    def __post_init__(self) -> None:
        if not _NAME.match(self.name):
            raise ValueError(f"key result name {self.name!r} is not a variable name: allowed letters, digits and _")

    def value(self, study) -> float:
        """The value read from ``study``, as a float."""
        return float(self.read(study))


@dataclass(frozen=True, kw_only=True)
class KeyResults:
    """A chapter's key results and the study function that computes them from its ``Params`` record."""

    study: Callable[[object], object]  # Params -> study record (picklable: a module-level function)
    results: tuple[KeyResult, ...]

    def __post_init__(self) -> None:
        check_unique([r.name for r in self.results], "a key result")

    def __getitem__(self, name: str) -> KeyResult:
        return by_name(self.results, name)

    def names(self) -> tuple[str, ...]:
        """The results' names, in declaration order."""
        return tuple(r.name for r in self.results)

    def values(self, study) -> dict[str, float]:
        """Every key result read from ``study``: name -> value (in its unit)."""
        return {r.name: r.value(study) for r in self.results}
