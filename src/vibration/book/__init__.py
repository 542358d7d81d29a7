"""vibration.book: the book built on the library (needs the ``book`` extra).

``chapters`` (one package per chapter: its parameters, study, figures and tables), ``presentation`` (what the
chapters share: number format, tables, figure style, panels) and ``publishing`` (the report runner, the
chapter cache, the Sphinx and print builds, the exercise sheets). ``python -m vibration.report`` is its command
line.

The teaching helpers load on first use:

* ``check(exercise, answer)``: says whether an answer to an exercise is right, within its tolerance;
* ``exercises``, ``exercise_section``, ``objectives``: a chapter's exercises and objectives for a run's parameters;
* ``sweep``: a chapter's study over a grid of parameters, gathered into an xarray Dataset (extra ``scale``).
"""

from __future__ import annotations

import importlib

_HOMES = {
    "check": "vibration.book.publishing.sheets",
    "exercise_section": "vibration.book.publishing.sheets",
    "exercises": "vibration.book.publishing.sheets",
    "objectives": "vibration.book.publishing.sheets",
    "sweep": "vibration.book.publishing.sweep",
}

__all__ = sorted(_HOMES)


def __getattr__(name: str):
    if name not in _HOMES:
        raise AttributeError(f"module 'vibration.book' has no attribute {name!r}", name=name)
    value = getattr(importlib.import_module(_HOMES[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
