"""Numbers and short phrases for a chapter's prose, glued from its code cells.

A chapter's markdown quotes a computed value as ``{glue:text}`name```; the code cell beside it calls
:func:`number` (or :func:`phrase` for a verdict of a few words), which formats the value in the book's one
number format and stores it in the cell's outputs without showing it. A value whose last digits depend on
the machine's floating-point rounding carries its tolerance in the output's metadata (never in the text a
reader sees), where the project's nbval comparison reads it.

Examples
--------
>>> text(0.450427), text(78.2345, 3), text(float("inf"))
('0.4504', '78.2', '∞')
"""

from __future__ import annotations

import math

from .narrative import g
from .numbers import Approx, integer

#: Longest verdict a chapter may glue, in words: anything longer belongs in the notebook's markdown.
PHRASE_WORDS = 12


#: A number as the prose writes it (``digits`` significant figures, trailing zeros dropped): the book's one format.
text = g


def _tolerance(value: float, tolerance: dict) -> dict | None:
    """The output metadata that declares a machine-dependent value's tolerance (``None`` without one)."""
    return (
        {"vibration": {"value": float(value), "tol": Approx(value=value, **tolerance).tolerance()}}
        if tolerance
        else None
    )


def _glue(name: str, shown: str, metadata: dict | None = None) -> None:
    from IPython.display import display

    data = {"application/papermill.record/text/plain": repr(shown)}
    meta = {"scrapbook": {"name": name, "mime_prefix": "application/papermill.record/"}} | (metadata or {})
    display(data, raw=True, metadata=meta)


def number(name: str, value: float, digits: int = 4, **tolerance: float) -> str:
    """Glue ``value`` under ``name``, formatted by :func:`text`; returns the text.

    ``tolerance`` (``rtol=``, ``factor=`` or ``atol=``, as for :class:`~vibration.book.presentation.numbers.Approx`)
    marks a value whose last digits depend on the machine: the comparison of committed outputs then accepts a
    new value within it.
    """
    value = float(value)
    if math.isnan(value):
        raise ValueError(f"glued number {name!r} is nan: a chapter states why a quantity is missing, in words")
    shown = text(value, digits)
    _glue(name, shown, _tolerance(value, tolerance))
    return shown


def count(name: str, n: int, **tolerance: float) -> str:
    """Glue a count under ``name`` in the book's grouped form (``5 001``); ``tolerance`` as for :func:`number`."""
    shown = integer(n)
    _glue(name, shown, _tolerance(n, tolerance))
    return shown


def phrase(name: str, words: str) -> str:
    """Glue a short computed verdict (at most :data:`PHRASE_WORDS` words) under ``name``; returns it."""
    if len(words.split()) > PHRASE_WORDS:
        raise ValueError(f"glued phrase {name!r} has {len(words.split())} words: allowed at most {PHRASE_WORDS}")
    _glue(name, words)
    return words
