"""How the chapter writes its numbers and names its cases, in prose, tables and figures.

* :func:`num`: a number for a sentence or caption, ``digits`` significant figures, powers of ten as
  ×10ⁿ (never e-notation), a typeset minus sign.
* :func:`cell`: a number for a table column, always ``digits`` significant figures (trailing zeros
  kept), so one column never mixes 16 with 17.42.
* :data:`LABELS`: the designs' names in tables and sentences (plain text, no code names).

Examples
--------
>>> num(0.000059), num(2.2370381, 3), num(-1.106, 4), num(float("inf")), num(1e-12)
('5.9×10⁻⁵', '2.24', '−1.106', '∞', '10⁻¹²')
>>> cell(16.0, 4), cell(17.4166, 4), cell(293.2, 3), cell(0.0, 3), cell(-5.9e-6, 2)
('16.00', '17.42', '293', '0', '−5.9×10⁻⁶')
"""

from __future__ import annotations

import math

_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")

#: The designs and runs as a reader reads them (tables, sentences).
LABELS = {
    "passive": "passive",
    "PD": "PD",
    "PD2": "PD with the PID's gains",
    "LQR": "LQR",
    "PID": "PID",
    "soft": "passive, soft",
    "firm": "passive, firm",
    "skyhook": "ideal skyhook (active)",
    "on-off": "on-off skyhook",
    "clipped": "clipped skyhook",
    "mr": "MR damper, on-off",
    "unlimited": "no force limit",
    "none": "limited, no anti-windup",
    "clamping": "limited, clamping",
    "back-calculation": "limited, back-calculation",
}


def _power(text: str) -> str:
    """``1.2e-05`` as ``1.2×10⁻⁵`` (``1e-12`` as ``10⁻¹²``); ``-`` as the typeset minus sign."""
    if "e" in text:
        mant, exp = text.split("e")
        power = f"10{str(int(exp)).translate(_SUPERSCRIPT)}"
        text = power if mant in ("1", "-1") else f"{mant}×{power}"
        text = f"-{text}" if mant == "-1" else text
    return text.replace("-", "−", 1) if text.startswith("-") else text


def num(value: float, digits: int = 3) -> str:
    """A number for prose: ``digits`` significant figures, trailing zeros dropped; ∞ and — where not finite."""
    v = float(value)
    if math.isnan(v):
        return "—"
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    return _power(f"{v:.{digits}g}")


def cell(value: float, digits: int = 3) -> str:
    """A number for a table column: exactly ``digits`` significant figures (an exact zero reads 0)."""
    v = float(value)
    if math.isnan(v):
        return "—"
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    if v == 0.0:
        return "0"
    text = f"{v:#.{digits}g}"
    if "e" in text:
        mant, exp = text.split("e")
        text = f"{mant.rstrip('.')}e{exp}"
    return _power(text.rstrip(".") if "e" not in text else text)


def pct(fraction: float, digits: int = 3) -> str:
    """A fraction as a percentage for prose: ``0.1434`` -> ``14.3 %``."""
    return f"{num(100.0 * fraction, digits)} %"


def signed_pct(fraction: float) -> str:
    """A relative error with its sign, whole percent: ``0.1`` -> ``+10 %``."""
    text = f"{100.0 * fraction:+.0f} %"
    return text.replace("-", "−")
