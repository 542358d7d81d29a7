"""The book's one number format: every number a reader sees is written by this module.

Rules
-----
* **Significant figures.** A float is rounded to ``digits`` significant figures (round half to even,
  as Python's ``format``); with ``zeros=True`` trailing zeros are kept, so a column shows one precision
  (0.100, 15.0).
* **Powers of ten.** A number is written as a power of ten, ``1.27×10⁵``, never in e-notation, when
  its magnitude is below 10⁻⁴, or when its integer part needs more digits than the significant
  figures shown (31540 at 3 figures is 3.15×10⁴; 1234 at 4 figures stays 1234). A mantissa of 1 is
  left out (10⁻¹²).
* **Minus.** Negative numbers carry the true minus sign "−" (U+2212), never a hyphen.
* **Integers** (:func:`integer`: counts of steps, samples, evaluations, episodes) of five or more digits are
  grouped in threes from the right by a narrow no-break space (U+202F), "960 000", so a number never
  breaks across lines; four digits stay together, "4096". Years, run numbers, seeds and other identifiers
  are names, not amounts, and are written as they are.
* **Uncertainty.** ``value ± error``: the error to one significant figure (two when its leading digit
  is 1), the value to the same decimal place: "0.1037 ± 0.0003"; a power of ten is factored out
  once, "(5.1 ± 0.3)×10⁻⁵".
* **Table columns** (:func:`column`) keep trailing zeros, so a column shows one precision; an exact zero is "0".
* **Intervals** "0.52 to 0.61"; **percentages** of a fraction "0.21 %", signed changes "+10 %";
  **bounds** of a check "< 10⁻¹²".
* **Machine-dependent values** (:class:`Approx`) read like any other number; their tolerance is
  declared beside the value and is what the regression comparison applies (see ``tests/nbval_numeric.py``).

The panels' JavaScript (``assets/plot.js``) implements :func:`sig` and the power-of-ten rule again for
the browser; ``tests/presentation/test_plot_js.py`` compares the two character for character.

Examples
--------
>>> sig(2.23703819), sig(0.0000123456), sig(0.000512, 3), sig(-127300.0, 4)
('2.237', '1.235×10⁻⁵', '0.000512', '−1.273×10⁵')
>>> pm(0.10372, 0.00031), pm(5.12e-5, 2.7e-6), interval(0.523, 0.6071, 2), percent(0.0021)
('0.1037 ± 0.0003', '(5.1 ± 0.3)×10⁻⁵', '0.52 to 0.61', '0.21 %')
"""

from __future__ import annotations

import math
import numbers
import re
from dataclasses import dataclass, field

from ...physics.model import ParameterError

#: Below this magnitude a number is written as a power of ten.
SMALL = 1e-4
MINUS = "−"
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def superscript(n: int) -> str:
    """An integer exponent in superscript digits with a superscript minus: ``-12`` -> ``⁻¹²``."""
    return str(int(n)).translate(_SUPERSCRIPT)


def minus(text: str) -> str:
    """Replace ASCII hyphens used as minus signs (at the start, after a space, "(", "×10" or "e") by "−".

    >>> minus("-0.5 to -2"), minus("x-ray")
    ('−0.5 to −2', 'x-ray')
    """
    out = []
    for i, ch in enumerate(text):
        prev = text[i - 1] if i else " "
        nxt = text[i + 1] if i + 1 < len(text) else ""
        out.append(MINUS if ch == "-" and (prev in " ([=/" or i == 0) and (nxt.isdigit() or nxt == ".") else ch)
    return "".join(out)


def sig(value: float, digits: int = 4, *, zeros: bool = False) -> str:
    """A float to ``digits`` significant figures in the book's format (see the module docstring).

    Examples
    --------
    >>> sig(1.273e5, 4), sig(-2.5e-9, 2), sig(1e-12), sig(31540.0, 3), sig(1234.0, 4)
    ('1.273×10⁵', '−2.5×10⁻⁹', '10⁻¹²', '3.15×10⁴', '1234')
    >>> sig(0.1, 3, zeros=True), sig(15.0, 3, zeros=True), sig(2.0e-5, 2, zeros=True), sig(1234.0, 3, zeros=True)
    ('0.100', '15.0', '2.0×10⁻⁵', '1.23×10³')
    >>> sig(float("inf")), sig(-float("inf")), sig(0.0), sig(-1e-9)
    ('∞', '−∞', '0', '−10⁻⁹')
    """
    v = float(value)
    if math.isnan(v):
        return "—"
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    digits = max(1, int(digits))
    text = f"{v:#.{digits}g}" if zeros else f"{v:.{digits}g}"
    if zeros:
        text = text.rstrip(".") if "e" not in text else text.replace(".e", "e")
    if "e" in text:  # a power of ten, never e-notation
        mant, exp = text.split("e")
        power = "10" + superscript(int(exp))
        text = power if mant == "1" else f"-{power}" if mant == "-1" else f"{mant}×{power}"
    return MINUS + text[1:] if text.startswith("-") else text


#: The thousands separator of :func:`integer`: a narrow no-break space.
GROUP = "\u202f"


def integer(n: int) -> str:
    """A count in the book's format: five or more digits grouped in threes by :data:`GROUP`, true minus.

    Parameters
    ----------
    n : int
        A whole number (an ``int``, a NumPy integer, or a float with no fractional part), 1.

    Raises
    ------
    ParameterError
        If ``n`` is a bool, not a number, or not a whole number.

    Examples
    --------
    >>> integer(960000), integer(200001), integer(11804), integer(4096), integer(-33409), integer(7)
    ('960\u202f000', '200\u202f001', '11\u202f804', '4096', '−33\u202f409', '7')
    """
    whole = isinstance(n, numbers.Integral) or (isinstance(n, numbers.Real) and float(n).is_integer())
    if isinstance(n, bool) or not whole:
        raise ParameterError(
            f"integer n = {n!r} is not allowed: allowed a whole number (an int, or a float without a fraction)"
        )
    value = int(n)
    digits = str(abs(value))
    if len(digits) >= 5:
        digits = f"{abs(value):,}".replace(",", GROUP)
    return (MINUS if value < 0 else "") + digits


def column(value: float, digits: int = 4) -> str:
    """A table cell: exactly ``digits`` significant figures, trailing zeros kept (one precision per column).

    An exact zero reads "0": it has no significant figures to show.

    >>> column(9.9996), column(2.23703819), column(15.0, 3), column(2.43e-5, 3), column(float("inf")), column(0.0)
    ('10.00', '2.237', '15.0', '2.43×10⁻⁵', '∞', '0')
    """
    v = float(value)
    if not math.isfinite(v) or v == 0:
        return sig(v, digits)
    return sig(v, digits, zeros=True)


def power(x: float) -> str:
    """An exact power of ten as 10ⁿ: ``1e-9`` -> ``10⁻⁹``.

    >>> power(1e-9), power(1000.0)
    ('10⁻⁹', '10³')
    """
    return "10" + superscript(round(math.log10(float(x))))


def signed(value: float, digits: int = 2) -> str:
    """:func:`sig` with an explicit sign: ``+0.27``, ``−0.11`` (a difference or a z-score).

    >>> signed(0.2731), signed(-0.1149), signed(0.0)
    ('+0.27', '−0.11', '0')
    """
    text = sig(value, digits)
    return "+" + text if float(value) > 0 else text


def _decimals_of(error: float) -> tuple[int, float]:
    """Decimal place (power of ten of the last digit) and the rounded error: 1 figure, 2 when it starts with 1."""
    e = abs(float(error))
    place = math.floor(math.log10(e))
    figures = 2 if round(e / 10.0**place, 0) < 2 else 1
    place -= figures - 1
    rounded = round(e / 10.0**place) * 10.0**place
    if rounded >= 10.0 ** (place + figures):  # 9.7 -> 10: one place up
        place += 1
    return place, round(e / 10.0**place) * 10.0**place


def pm(value: float, error: float) -> str:
    """``value ± error``, the value to the error's last digit.

    Examples
    --------
    >>> pm(0.10372, 0.00031), pm(-2.466, 0.13), pm(12.3456, 0.97), pm(1.0, 0.0)
    ('0.1037 ± 0.0003', '−2.47 ± 0.13', '12 ± 1', '1 ± 0')
    >>> pm(5.12e-5, 2.7e-6), pm(float("nan"), 0.1)
    ('(5.1 ± 0.3)×10⁻⁵', '—')
    """
    v, e = float(value), abs(float(error))
    if not (math.isfinite(v) and math.isfinite(e)):
        return "—"
    if e == 0:
        return f"{sig(v, 6)} ± 0"
    place, e = _decimals_of(e)
    scale = max(abs(v), e)
    power = math.floor(math.log10(scale)) if scale > 0 else 0
    if scale < SMALL or power >= 5:
        k = 10.0**power
        inner = _pm_fixed(v / k, e / k, place - power)
        return f"({inner})×10{superscript(power)}"
    return _pm_fixed(v, e, place)


def error(value: float) -> str:
    """An error alone, rounded as :func:`pm` rounds it (one figure, two when it starts with 1): a second,
    systematic error written after ``pm``'s.

    >>> error(1.43), error(0.27), error(0.0149), error(9.7)
    ('1.4', '0.3', '0.015', '10')
    """
    e = abs(float(value))
    if not math.isfinite(e) or e == 0:
        return sig(e)
    return sig(_decimals_of(e)[1], 2)


def pm_figures(value: float, error: float) -> tuple[int, int]:
    """The significant figures :func:`pm` gives a value and its error, for a pair whose two numbers are written
    apart (each a machine-dependent :class:`Approx`, say).

    >>> pm_figures(0.10372, 0.00031), pm_figures(4.4762, 0.0049), pm_figures(0.004, 0.057)
    ((4, 1), (4, 1), (1, 1))
    """
    e = abs(float(error))
    if not (math.isfinite(e) and e > 0 and math.isfinite(float(value))):
        return 4, 2
    place, rounded = _decimals_of(e)
    v = abs(float(value))
    value_figures = math.floor(math.log10(v)) - place + 1 if v > 0 else 1
    return max(1, value_figures), math.floor(math.log10(rounded)) - place + 1


def _pm_fixed(v: float, e: float, place: int) -> str:
    decimals = max(0, -place)
    vr = round(v, -place) if place > 0 else v
    er = round(e, -place) if place > 0 else e
    return minus(f"{vr:.{decimals}f} ± {er:.{decimals}f}")


def interval(low: float, high: float, digits: int = 3) -> str:
    """A range "low to high", both ends to ``digits`` significant figures.

    >>> interval(-0.5, 2.0), interval(4.421, 4.519, 4)
    ('−0.5 to 2', '4.421 to 4.519')
    """
    return f"{sig(low, digits)} to {sig(high, digits)}"


def percent(fraction: float, digits: int = 3) -> str:
    """A fraction as a percentage with ``digits`` significant figures: 0.0021 -> "0.21 %".

    A percentage keeps every digit of its integer part (112 %, never 1.1×10² %).

    >>> percent(0.0021), percent(-0.5), percent(0.14336), percent(1.0), percent(1.12, 2), percent(0.997, 2)
    ('0.21 %', '−50 %', '14.3 %', '100 %', '112 %', '99.7 %')
    """
    v = 100.0 * float(fraction)
    if math.isfinite(v) and abs(v) >= 1.0:
        digits = max(digits, math.floor(math.log10(abs(v))) + 1)
        if "e" in f"{v:.{digits}g}":  # 99.7 at two digits rounds to 1e+02
            digits += 1
    return f"{sig(v, digits)} %"


def signed_percent(fraction: float, decimals: int = 0) -> str:
    """A relative change with its sign, in percent with ``decimals`` decimals: 0.1 -> "+10 %".

    >>> signed_percent(0.1), signed_percent(-0.034, 1), signed_percent(0.0)
    ('+10 %', '−3.4 %', '+0 %')
    """
    return minus(f"{100.0 * float(fraction):+.{decimals}f} %")


def bound(value: float, tol: float) -> str | None:
    """A check against its tolerance: ``"< tol"`` when it holds, else the value and the tolerance.

    The printed tolerance, not the value's order of magnitude, is what reproduces on every machine.
    Returns ``None`` for a value that was not computed (nan); the table shows it as missing.

    >>> bound(3e-15, 1e-12), bound(2.5e-9, 1e-12), bound(float("nan"), 1e-12)
    ('< 10⁻¹²', '2.5×10⁻⁹ (above 10⁻¹²)', None)
    """
    v = float(value)
    if math.isnan(v):
        return None
    if abs(v) < tol:
        return f"< {sig(tol)}"
    return f"{sig(abs(v), 2)} (above {sig(tol)})"


@dataclass(frozen=True, kw_only=True)
class Approx:
    """A number whose last digits depend on the machine's floating-point rounding, with its tolerance.

    The reader sees it like any other number. The regression comparison (strict nbval plus the
    project's numeric plugin, ``tests/nbval_numeric.py``) compares it with the committed reference
    within the tolerance declared here, beside the value: a relative ``rtol``, a ``factor`` (for errors
    that scatter by multiples) or an absolute ``atol``; at least one is needed. In the plain-text
    representation (the nbval surface) it is written ``⟪value tolerance⟫``.

    >>> a, b, c = Approx(value=2829, rtol=0.25), Approx(value=0.0338123, factor=5), Approx(value=6e-15, atol=1e-10)
    >>> a.plain(), b.plain(), c.plain()
    ('⟪2829 r0.25⟫', '⟪0.0338123 f5⟫', '⟪6e-15 a1e-10⟫')
    """

    value: float
    rtol: float | None = field(default=None, kw_only=True)  # relative tolerance, |new − ref| ≤ rtol |ref|
    factor: float | None = field(default=None, kw_only=True)  # ref / factor ≤ new ≤ ref × factor
    atol: float | None = field(default=None, kw_only=True)  # absolute tolerance, same unit as the value

    def __post_init__(self) -> None:
        if self.rtol is None and self.factor is None and self.atol is None:
            # the old shared form Approx(value) of the chapters not yet migrated: a factor of 10
            object.__setattr__(self, "factor", 10.0)
        for name in ("rtol", "factor", "atol"):
            t = getattr(self, name)
            if t is not None and not (math.isfinite(t) and t > 0 and (name != "factor" or t > 1)):
                allowed = "> 1" if name == "factor" else "> 0"
                raise ParameterError(f"Approx {name} = {t!r} is not allowed: allowed a finite value {allowed}")

    def tolerance(self) -> str:
        """The declared tolerance as the plugin reads it: ``r0.25``, ``f5``, ``a1e-10`` (joined by ``,``)."""
        parts = []
        if self.rtol is not None:
            parts.append(f"r{self.rtol:g}")
        if self.factor is not None:
            parts.append(f"f{self.factor:g}")
        if self.atol is not None:
            parts.append(f"a{self.atol:g}")
        return ",".join(parts)

    def number(self) -> float:
        """The value as a float (a value given as text in the book's format is read back with :func:`parse`)."""
        return parse(self.value) if isinstance(self.value, str) else float(self.value)

    def plain(self) -> str:
        """The machine form for the plain-text table, which the numeric plugin compares."""
        return f"⟪{self.number():.6g} {self.tolerance()}⟫"

    def html(self, text: str) -> str:
        """The reader's ``text`` of the value in a span that carries the value and its tolerance.

        The span is invisible to the reader; the sanitizer masks the value and the text, and the numeric
        plugin compares the value within the tolerance.

        >>> Approx(value=2829.4, rtol=0.25).html("2829")
        '<span class="vib-approx" data-value="2829.4" data-tol="r0.25">2829</span>'
        """
        return (
            f'<span class="vib-approx" data-value="{float(self.value):.6g}" data-tol="{self.tolerance()}">{text}</span>'
        )


def parse(text: str) -> float:
    """A number written in the book's format read back: true minus, ×10ⁿ, "∞", grouped counts.

    A count's groups must be as :func:`integer` writes them (five or more digits, threes from the right);
    any other use of :data:`GROUP` inside a number raises ``ValueError``.

    >>> parse("−1.273×10⁵"), parse("10⁻¹²"), parse("0.1542"), parse("−∞"), parse("960\u202f000")
    (-127300.0, 1e-12, 0.1542, -inf, 960000.0)
    """
    t = re.sub(rf"^[^\S{GROUP}]+|[^\S{GROUP}]+$", "", str(text)).replace(MINUS, "-").replace("∞", "inf")
    if GROUP in t:
        if not re.fullmatch(rf"[-+]?(?:\d{{2,3}}|\d(?={GROUP}\d{{3}}{GROUP}))(?:{GROUP}\d{{3}})+", t):
            raise ValueError(f"{text!r} is not a count grouped in threes from the right (five or more digits)")
        return float(t.replace(GROUP, ""))
    m = re.fullmatch(r"(?:([-+]?[\d.]+)×)?([-+]?)10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)", t)
    if m:
        return float(f"{m.group(1) or m.group(2) + '1'}e{m.group(3).translate(_FROM_SUPERSCRIPT)}")
    return float(t)


_FROM_SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def approx(value: float, digits: int = 4, **tolerance: float) -> str:
    """A machine-dependent number for a sentence: :func:`sig`, in the invisible span of :meth:`Approx.html`.

    ``tolerance`` is ``rtol=``, ``factor=`` or ``atol=`` as for :class:`Approx`.

    >>> approx(2926.0, rtol=0.25)
    '<span class="vib-approx" data-value="2926" data-tol="r0.25">2926</span>'
    """
    return Approx(value=value, **tolerance).html(sig(value, digits))


#: Width of an Approx cell in a plain-text table: the widest value text plus its tolerance.
def plain_width(cell: Approx) -> int:
    """Width reserved for an :class:`Approx` cell, so its machine-dependent digits cannot move the layout."""
    return len("⟪-1.23457e-100 ⟫") + len(cell.tolerance())
