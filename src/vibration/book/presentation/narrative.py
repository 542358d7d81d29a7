r"""Sentences shared by the Part I chapters: numbers, typeset symbols, parameters and regimes.

Each function returns Markdown, shown in a notebook with ``display(Markdown(...))``; a run
with other parameters therefore says what its own tables say. Symbols are typeset for the
reader (:func:`tex`: ``c_low`` reads $c_\mathrm{low}$, ``omega_n`` reads $\omega_n$), never
written as code names.

Examples
--------
>>> tex("ω_res"), tex("F_0"), tex("m")
('$\\omega_\\mathrm{res}$', '$F_0$', '$m$')
>>> print(regime_clause(Oscillator(m=1.0, c=15.0, k=20.0)))
overdamped (ζ = 1.68 > 1: the free motion does not oscillate)
"""

from __future__ import annotations

import math

from ...physics.model import Oscillator, SineForce
from ...physics.paper import paper_defaults
from .numbers import column, sig
from .parameters import SHARED
from .tables import fmt

#: Greek letters of the symbols in schemas and sentences, as TeX commands.
GREEK = {"ω": r"\omega", "ζ": r"\zeta", "σ": r"\sigma", "τ": r"\tau", "φ": r"\varphi", "Δ": r"\Delta", "μ": r"\mu"}


def tex(symbol: str) -> str:
    """A schema symbol (``"ω_res"``, ``"c_low"``, ``"F_0"``) as inline Markdown maths.

    A one-character or numeric subscript stays italic (ω_n, F_0); a word becomes upright (ω_res).
    """
    base, _, sub = symbol.partition("_")
    body = "".join(GREEK.get(ch, ch) for ch in base)
    if sub:
        sub = sub if len(sub) == 1 or sub.isdigit() else rf"\mathrm{{{sub}}}"
        body += f"_{sub}" if len(sub) == 1 else f"_{{{sub}}}" if sub.isdigit() else f"_{sub}"
    return f"${body}$"


#: Symbol (typeset) and unit of the paper's parameters, for the sentence that lists what a run changed.
PARAMETER_TEXT = {name: (tex(p.symbol), p.unit) for name, p in SHARED.items()}


def g(value: float, digits: int = 4) -> str:
    """A number for a sentence (:func:`vibration.book.presentation.numbers.sig`): ``digits`` significant figures.

    Examples
    --------
    >>> g(2.23703819), g(78.2345, 3), g(float("inf")), g(-0.25)
    ('2.237', '78.2', '∞', '−0.25')
    """
    return sig(float(value), digits)


#: The table-cell form, one precision per column (:func:`vibration.book.presentation.numbers.column`).
fixed = column


def listing(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``.

    >>> listing(["c = 0.1 N s/m", "c = 0.5 N s/m"])
    'c = 0.1 N s/m and c = 0.5 N s/m'
    """
    items = list(items)
    if not items:
        return ""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def parameters_sentence(**values: float) -> str:
    """Which of the paper's parameters this run changed (keyword arguments: name = value).

    Examples
    --------
    >>> print(parameters_sentence(m=1.0, c_high=15.0))
    This run uses the paper's parameters ($m$ = 1 kg, $c_\\mathrm{high}$ = 15 N s/m).
    >>> print(parameters_sentence(m=1.0, c_high=5.0))
    This run changes the paper's parameters: $c_\\mathrm{high}$ = 5 N s/m (the paper's: 15 N s/m). Every number, \
regime and verdict below is computed with the run's values; quotations keep the paper's.
    """
    paper = paper_defaults()
    changed, same = [], []
    for name, value in values.items():
        sym, unit = PARAMETER_TEXT.get(name, (name, ""))
        text = f"{sym} = {sig(value, 6)}{' ' + unit if unit else ''}"
        if name in paper and float(value) != paper[name]:
            changed.append(f"{text} (the paper's: {sig(paper[name], 6)}{' ' + unit if unit else ''})")
        else:
            same.append(text)
    if not changed:
        return f"This run uses the paper's parameters ({', '.join(same)})."
    return (
        f"This run changes the paper's parameters: {'; '.join(changed)}. Every number, regime and verdict "
        "below is computed with the run's values; quotations keep the paper's."
    )


def regime_clause(osc: Oscillator, force: SineForce | None = None, t_end: float | None = None) -> str:
    """The regime word with what it means for this oscillator (and forcing, when given).

    Examples
    --------
    >>> print(regime_clause(Oscillator(m=1.0, c=-0.1, k=20.0)))
    unstable (negative damping, ζ = −0.0112: the free vibration grows as $e^{0.05\\,t/\\mathrm{s}}$)
    """
    zeta = osc.damping_ratio
    reg = osc.regime
    if reg == "underdamped":
        return f"underdamped (ζ = {g(zeta, 3)} < 1: the free motion oscillates and decays)"
    if reg == "overdamped":
        return f"overdamped (ζ = {g(zeta, 3)} > 1: the free motion does not oscillate)"
    if reg == "critically damped":
        return "critically damped (ζ = 1)"
    if reg == "unstable":
        return (
            f"unstable (negative damping, ζ = {sig(zeta, 3)}: the free vibration grows as "
            f"$e^{{{fmt(-osc.decay_rate, 3)}\\,t/\\mathrm{{s}}}}$)"
        )
    # undamped
    text = "undamped (c = 0: the free vibration never decays"
    if force is not None and force.omega > 0:
        wn, w = osc.natural_frequency, force.omega
        if w == wn:
            text += r"; at exact resonance the forced response grows without bound, as $t\cos\omega_n t$"
        else:
            beat = 2 * math.pi / abs(wn - w)
            text += rf"; forced at $\omega/\omega_n$ = {g(w / wn, 5)} the response beats with period {g(beat, 3)} s"
            if t_end is not None and beat > 4 * t_end:
                text += (
                    f", so over {g(t_end)} s it grows almost linearly, like the $t\\cos\\omega_n t$ of exact resonance"
                )
    return text + ")"
