"""Tuples of named records (parameters, key results): each name declared once, a record found by its name.

Examples
--------
>>> from types import SimpleNamespace as R
>>> rows = (R(name="m"), R(name="k"))
>>> check_unique([r.name for r in rows], "a parameter")
>>> by_name(rows, "k") is rows[1]
True
>>> check_unique(["m", "m"], "a parameter")
Traceback (most recent call last):
...
ValueError: a parameter is declared twice in ['m', 'm']
"""

from __future__ import annotations


def check_unique(names: list[str], what: str) -> None:
    """Raise ``ValueError`` (``"<what> is declared twice in <names>"``) when a name stands twice in ``names``."""
    if len(set(names)) != len(names):
        raise ValueError(f"{what} is declared twice in {names}")


def by_name(items, name: str):
    """The first of ``items`` whose ``name`` attribute is ``name``; ``KeyError(name)`` when there is none."""
    for item in items:
        if item.name == name:
            return item
    raise KeyError(name)
