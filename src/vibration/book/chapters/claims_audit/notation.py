r"""The reader's notation for the audit's words: code names become typeset symbols.

The physics layer (:mod:`vibration.physics.audit`) writes its reasons and readings in plain text
with code names (``x_ss``, ``F0``, ``ω_n``, ``t_end``, ``exp(0.05 t/s)``, ``2.94e3``). The chapter
shows them to readers: in Markdown prose as inline maths (:func:`prose`), in table cells, which
are escaped text, with Unicode subscripts (:func:`cell`).

Examples
--------
>>> print(prose("x_ss = F0/√((k − mω²)² + (cω)²) = 0.4504 m, 1.8 times F0/k = 0.25 m."))
$x_\mathrm{ss} = F_0/\sqrt{(k - m\omega^2)^2 + (c\omega)^2}$ = 0.4504 m, 1.8 times $F_0/k$ = 0.25 m.
>>> print(prose("beats with period 2.94e3 s; damping_nominal: c = -0.1 N s/m"))
beats with period 2.94×10³ s; nominal damping: c = −0.1 N s/m
>>> cell("2 x_ss at resonance / x_ss of reference"), cell("growing at t_end")
('2 xₛₛ at resonance / xₛₛ of reference', 'growing at the end of the window')
"""

from __future__ import annotations

import re

from vibration.book.presentation.findings import CASE_NAMES
from vibration.book.presentation.numbers import minus, superscript

#: Whole formulas first, then single symbols (the order matters: a replaced symbol is no longer code).
_PROSE: tuple[tuple[str, str], ...] = (
    ("x_ss = F0/√((k − mω²)² + (cω)²)", r"$x_\mathrm{ss} = F_0/\sqrt{(k - m\omega^2)^2 + (c\omega)^2}$"),
    ("F0/√((k − mω²)² + (cω)²)", r"$F_0/\sqrt{(k - m\omega^2)^2 + (c\omega)^2}$"),
    ("ω_n = √(k/m)", r"$\omega_n = \sqrt{k/m}$"),
    ("√(k/m)", r"$\sqrt{k/m}$"),
    ("ζ = c/(2√(km))", r"$\zeta = c/(2\sqrt{km})$"),
    ("v_ss = ω x_ss", r"$v_\mathrm{ss} = \omega x_\mathrm{ss}$"),
    ("x_ss/(F0/k)", r"$x_\mathrm{ss}/(F_0/k)$"),
    ("x_ss (1 − exp(−t/τ))", r"$x_\mathrm{ss}(1 - e^{-t/\tau})$"),
    ("t cos(ω_n t)", r"$t\cos\omega_n t$"),
    ("ω/ω_n", r"$\omega/\omega_n$"),
    ("x_ss", r"$x_\mathrm{ss}$"),
    ("v_ss", r"$v_\mathrm{ss}$"),
    ("ω_n", r"$\omega_n$"),
    ("F0/k", r"$F_0/k$"),
    ("F0/c", r"$F_0/c$"),
    ("F0", r"$F_0$"),
    ("t_end", r"$t_\mathrm{end}$"),
    ("peak |x|", r"peak $|x|$"),
    ("peak |v|", r"peak $|v|$"),
)

_CELL: tuple[tuple[str, str], ...] = (
    ("at t_end", "at the end of the window"),
    ("x_ss", "xₛₛ"),
    ("v_ss", "vₛₛ"),
    ("ω_n", "ωₙ"),
    ("F0", "F₀"),
    ("t_end", "the end of the window"),
)

_EXP = re.compile(r"exp\(([−-]?\d+(?:\.\d+)?) t/s\)")
_E_NOTATION = re.compile(r"(?<![\w.])(-?\d+(?:\.\d+)?)e([+-]?\d+)\b")
_MINUS_NUMBER = re.compile(r"(?<![\w)])-(?=\d)")
_SQRT_NUMBERS = re.compile(r"√\((\d+(?:\.\d+)?)/(\d+(?:\.\d+)?)\)")


def _ten(match: re.Match) -> str:
    return f"{minus(match.group(1))}×10{superscript(int(match.group(2)))}"  # the book's power of ten


def _case_ids(text: str) -> str:
    for sid, name in CASE_NAMES.items():
        text = re.sub(rf"\b{sid}\b", name, text)
    return text


def prose(text: str) -> str:
    """Audit text as Markdown for a sentence: symbols as inline maths, ×10ⁿ, case names, minus signs."""
    text = _E_NOTATION.sub(_ten, text)
    text = _EXP.sub(lambda m: rf"$e^{{{m.group(1).replace('−', '-')}\,t/\mathrm{{s}}}}$", text)
    text = _SQRT_NUMBERS.sub(r"$\\sqrt{\1/\2}$", text)
    for code, shown in _PROSE:
        text = text.replace(code, shown)
    text = _case_ids(text)
    return _outside_maths(text, lambda part: _MINUS_NUMBER.sub("−", part))


def cell(text: str) -> str:
    """Audit text for a table cell (escaped text): Unicode subscripts, ×10ⁿ, case names, minus signs."""
    text = _E_NOTATION.sub(_ten, text)
    for code, shown in _CELL:
        text = text.replace(code, shown)
    return _MINUS_NUMBER.sub("−", _case_ids(text))


def _outside_maths(text: str, change) -> str:
    parts = text.split("$")
    return "$".join(change(p) if i % 2 == 0 else p for i, p in enumerate(parts))


#: What a Markdown sentence must not contain once typeset: a code name or e-notation (tests use it).
CODE_LEFT = re.compile(r"(?<![\\$\w])[A-Za-zωζ]+_[A-Za-z]+\b|\b\d(?:\.\d+)?e[-+]?\d+\b|\bF0\b")


def code_left(markdown: str) -> list[str]:
    """The code names and e-notation numbers left in ``markdown`` outside its maths (``[]`` when clean)."""
    out: list[str] = []
    _outside_maths(markdown, lambda part: out.extend(m.group(0) for m in CODE_LEFT.finditer(part)) or part)
    return out
