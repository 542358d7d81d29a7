r"""Sentences shared by the Part I chapters: numbers, typeset symbols, parameters and regimes.

Each function returns Markdown, shown in a notebook with ``display(Markdown(...))``; a run
with other parameters therefore says what its own tables say. Symbols are typeset for the
reader (:func:`tex`: ``c_low`` reads $c_\mathrm{low}$, ``omega_n`` reads $\omega_n$), never
written as code names.

Examples
--------
>>> tex("ω_res"), tex("F_0"), tex("m")
('$\\omega_\\mathrm{res}$', '$F_0$', '$m$')
>>> print(regime_clause(Oscillator(1.0, 15.0, 20.0)))
overdamped (ζ = 1.68 > 1: the free motion does not oscillate)
"""

from __future__ import annotations

import math

from ..physics.model import Oscillator, SineForce
from ..physics.paper import paper_defaults
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
    """A number for a sentence: ``digits`` significant figures, "∞" for infinity.

    Examples
    --------
    >>> g(2.23703819), g(78.2345, 3), g(float("inf"))
    ('2.237', '78.2', '∞')
    """
    return fmt(float(value), digits)


def sig(value: float, digits: int = 4) -> str:
    """Like :func:`g`, with a typographic minus and ×10ⁿ instead of e-notation (for prose).

    Examples
    --------
    >>> sig(2.43e-5, 3), sig(-1.5e6), sig(-0.25)
    ('2.43 × 10⁻⁵', '−1.5 × 10⁶', '−0.25')
    """
    text = fmt(float(value), digits)
    mant, _, exp = text.partition("e")
    mant = "−" + mant[1:] if mant.startswith("-") else mant
    return f"{mant} × 10{str(int(exp)).translate(_SUPERSCRIPT)}" if exp else mant


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def fixed(value: float, digits: int = 4) -> str:
    """A table cell with exactly ``digits`` significant figures, trailing zeros kept (one precision per column).

    Examples
    --------
    >>> fixed(9.9996), fixed(2.23703819), fixed(15.0, 3), fixed(2.43e-5, 3), fixed(float("inf"))
    ('10.00', '2.237', '15.0', '2.43 × 10⁻⁵', '∞')
    """
    v = float(value)
    if not math.isfinite(v):
        return g(v)
    text = f"{v:#.{digits}g}"
    if "e" in text:
        return sig(v, digits)
    text = text.rstrip(".")
    return "−" + text[1:] if text.startswith("-") else text


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
        text = f"{sym} = {g(value, 6)}{' ' + unit if unit else ''}"
        if name in paper and float(value) != paper[name]:
            changed.append(f"{text} (the paper's: {g(paper[name], 6)}{' ' + unit if unit else ''})")
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
    >>> print(regime_clause(Oscillator(1.0, -0.1, 20.0)))
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


def explorer_start(c: float) -> tuple[float, str]:
    """The damping the sliders start at (N s/m) and a sentence saying why, for a chapter's ``c``.

    The damping sliders are logarithmic, so they cannot hold c <= 0; such a run starts them at
    their lowest damping and says so.

    Examples
    --------
    >>> explorer_start(0.5)[0], explorer_start(-0.1)[0]
    (0.5, 0.01)
    """
    from .widgets import C_MIN

    if c > 0:
        return c, f"The sliders start at this run's damping, c = {g(c)} N s/m."
    what = "undamped" if c == 0 else "negative damping"
    return C_MIN, (
        f"This run's damping is c = {g(c)} N s/m ({what}); the damping sliders are logarithmic and cannot "
        f"hold it, so they start at their lowest value, c = {g(C_MIN)} N s/m. Chapter 1 shows the response "
        f"at c = {g(c)} N s/m."
    )


def explore_controls_markdown() -> str:
    """Which controls exist where: JupyterLab (all) and the rendered report (ω, c and reset)."""
    from . import static_page, widgets

    return (
        "* **In JupyterLab** (a running kernel): the forcing frequency ω (rad/s, the Hz value beside it) and "
        f"the damping c (N s/m, logarithmic, from {g(widgets.C_MIN)} to {g(widgets.C_MAX)} N s/m, through "
        "critical damping) redraw the figure while the slider moves; boxes for m (kg), k (N/m), F0 (N) and "
        "the window t_end (s) apply when Enter is pressed (a value out of range is reported in red and the "
        "figure keeps the last valid state); a check box overlays the paper's RK45 solution and its largest "
        "deviation from the exact displacement.\n"
        "* **In the rendered report** (no kernel): the same closed form runs in the browser with exactly "
        f"three controls, the forcing frequency ω (steps of {g(static_page.OMEGA_STEP)} rad/s), the damping c "
        f"(logarithmic, at least {g(static_page.C_MIN)} to {g(static_page.C_MAX)} N s/m) and a reset button; "
        "it draws x(t) and v(t) and the magnification curve like the JupyterLab figure, but m, k, F0, t_end "
        "and the RK45 overlay are fixed at this run's values."
    )


def explore_summary(values: dict) -> str:
    """Chapter 5's summary from the explorer's starting readout (``Explorer.values``)."""
    v = values
    settled = (
        f"it settles after {g(v['settling'], 3)} s, inside the {g(v['t_end'])} s window"
        if v["steady_reached"] == "yes"
        else f"it has not settled by t = {g(v['t_end'])} s"
    )
    bullets = [
        f"At the starting point ω/ω_n = {g(v['ratio'], 5)} and ζ = {g(v['zeta'], 3)}: the oscillator is "
        f"{v['regime']}, its steady amplitude is {g(v['amplitude'])} m ({g(v['magnification'], 3)} times the "
        f"static deflection) and {settled}.",
        "Near ω_n the steady amplitude is F0/(c ω): halving c doubles it and doubles the settling time; a few "
        "half-power bandwidths (c/m) away from ω_n the amplitude no longer depends on c.",
        "For ζ ≥ 1/√2 the magnification curve has no peak left to avoid; above ζ = 1 the transient no longer "
        "oscillates.",
    ]
    return "\n".join("- " + b for b in bullets)
