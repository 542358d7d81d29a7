"""The book's notation, registered once: symbol, meaning, unit, defining equation and first chapter.

The registry is a data file next to this module (``notation.toml``), read once at import; the
glossary appendix is rendered from :data:`SYMBOLS`. Each symbol means one thing in the whole
book; the letters that meant two things are settled here (:data:`SETTLED`):

- ``Q`` is the quality factor; the weights of a linear-quadratic regulator are ``q_x``, ``q_v`` and
  ``q_u`` (never ``Q``, nor ``r``, the frequency ratio);
- ``f`` is a frequency in Hz; the tuning ratio of an absorber is ``ν = ω_a/ω_p``;
- ``Δ`` is a difference (``ΔE``, ``Δω``, ``Δk``); the friction angle of chapter 12 is ``θ_f``;
- ``c`` is a viscous damping coefficient; the resting angle of chapter 12 is ``θ_0``;
- ``p`` is a p-value; the exponent of a damping law is ``n``.

Examples
--------
>>> lookup("ω_d").meaning
'damped natural frequency'
>>> lookup("ζ").unit, lookup("ζ").first_chapter
('1', 1)
>>> lookup("Q").meaning
'quality factor'
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib.resources import files

__all__ = ["SETTLED", "SYMBOLS", "Symbol", "lookup"]


@dataclass(frozen=True, kw_only=True)
class Symbol:
    """One symbol of the book."""

    symbol: str  # as the book writes it in text, "_" starting a subscript ("ω_n")
    meaning: str
    unit: str  # SI unit; "1" when dimensionless
    equation: str  # its defining equation or relation (plain text, typeset symbols)
    first_chapter: int  # the chapter where it first appears (0: the front page)
    tex: tuple[str, ...] = ()  # how the chapters' equations write it ("\\omega_n"), for the coverage test


def _read(name: str = "notation.toml") -> tuple[tuple[Symbol, ...], dict[str, tuple[str, str]]]:
    """The symbols and the settled letters of the data file ``name`` next to this module."""
    data = tomllib.loads(files(__package__).joinpath(name).read_text(encoding="utf-8"))
    symbols = tuple(Symbol(**{**entry, "tex": tuple(entry.get("tex", ()))}) for entry in data["symbol"])
    settled = {letter: (kept, moved) for letter, (kept, moved) in data["settled"].items()}
    return symbols, settled


#: Every symbol of the book, in the order of its data file (``notation.toml``); and the letters that meant
#: two things, each with the meaning it keeps and what the other meaning is written as now.
SYMBOLS, SETTLED = _read()


def lookup(symbol: str) -> Symbol:
    """The registered symbol ``symbol`` (its first entry when a letter has one per chapter part)."""
    for s in SYMBOLS:
        if s.symbol == symbol:
            return s
    raise KeyError(f"{symbol!r} is not in the book's notation: add it to vibration/presentation/notation.toml")
