"""Numbers within declared tolerances, compared beside strict nbval.

nbval compares a cell's stored outputs with the new ones as strings, after the regular expressions of
``tests/nbval_sanitize.cfg``; it has no numeric tolerance. A value whose last digits depend on the
machine's floating-point rounding is therefore written, in the plain-text form of its table only, as
``⟪value tolerance⟫`` (:class:`vibration.book.presentation.numbers.Approx`): the sanitizer masks the value
and keeps the tolerance, so strict nbval still compares everything else, the declared tolerance
included; this plugin then compares each masked value numerically with its reference, within the
tolerance the reference declares. The reader never sees the mark: the book renders the Markdown and
HTML forms, which write the value like any other number.

Tolerances: ``r0.25`` (relative, ``|new − ref| ≤ 0.25 |ref|``), ``f5`` (a factor, ``ref/5 ≤ new ≤ 5 ref``
with the same sign), ``a1e-10`` (absolute); several, joined by ``,``, pass when any one holds.

A number glued into a chapter's prose (:func:`vibration.book.presentation.glued.number`) declares its value
and tolerance in the output's metadata instead, so its text stays what the reader sees; within the
tolerance the new output is compared as equal to the reference (:func:`settle_glued`).

:func:`install` wraps ``nbval.plugin.IPyNbCell.compare_outputs``; ``tests/conftest.py`` calls it.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

#: One marked value: ``⟪2926 r0.25⟫`` (plain text) or ``data-value="2926" data-tol="r0.25"`` (HTML, Markdown).
MARK = re.compile(r"⟪(?P<value>[^ ⟫]+) (?P<tol>[^⟫]+)⟫|data-value=\"(?P<hvalue>[^\"]*)\" data-tol=\"(?P<htol>[^\"]*)\"")


def _parts(m: re.Match) -> tuple[float, str]:
    return float(m["value"] or m["hvalue"]), m["tol"] or m["htol"]


@dataclass(frozen=True, kw_only=True)
class Mismatch:
    """A marked value outside its tolerance."""

    reference: float
    new: float
    tolerance: str

    def __str__(self) -> str:
        return f"{self.new!r} is outside the tolerance {self.tolerance} of the reference {self.reference!r}"


def within(reference: float, new: float, tolerance: str) -> bool:
    """Whether ``new`` matches ``reference`` within ``tolerance`` (``r…``, ``f…``, ``a…``, joined by ``,``).

    >>> within(2926.0, 3011.0, "r0.25"), within(2926.0, 4000.0, "r0.25")
    (True, False)
    >>> within(0.0323, 0.1, "f5"), within(0.0323, 0.2, "f5"), within(0.0323, -0.0323, "f5")
    (True, False, False)
    >>> within(6e-15, 3e-11, "a1e-10"), within(6e-15, 3e-10, "a1e-10")
    (True, False)
    """
    if not (math.isfinite(reference) and math.isfinite(new)):
        return reference == new or (math.isnan(reference) and math.isnan(new))
    for part in tolerance.split(","):
        kind, amount = part[0], float(part[1:])
        if kind == "r" and abs(new - reference) <= amount * abs(reference):
            return True
        if kind == "a" and abs(new - reference) <= amount:
            return True
        if kind == "f":
            if reference == 0 or new == 0:
                if reference == new:
                    return True
            elif (reference > 0) == (new > 0) and 1 / amount <= new / reference <= amount:
                return True
        if kind not in "raf":
            raise ValueError(f"unknown tolerance {part!r} (r, f or a)")
    return False


def mismatches(reference: str, new: str) -> list[Mismatch]:
    """The marked values of ``new`` outside the tolerances declared by ``reference``.

    Different numbers of marks, or different declared tolerances, are left to strict nbval, which sees
    them in the sanitized strings.

    >>> mismatches("a ⟪2926 r0.25⟫ b ⟪0.03 f5⟫", "a ⟪3011 r0.25⟫ b ⟪0.04 f5⟫")
    []
    >>> [str(m) for m in mismatches("a ⟪2926 r0.25⟫", "a ⟪9000 r0.25⟫")]
    ['9000.0 is outside the tolerance r0.25 of the reference 2926.0']
    """
    ref, got = list(MARK.finditer(reference)), list(MARK.finditer(new))
    out = []
    for r, g in zip(ref, got, strict=False):
        (a, tol), (b, tol_new) = _parts(r), _parts(g)
        if tol != tol_new:
            continue
        if not within(a, b, tol):
            out.append(Mismatch(reference=a, new=b, tolerance=tol))
    return out


def _texts(outputs) -> list[str]:
    """Every string output of a cell (stream text and each MIME type's text), in order."""
    out = []
    for o in outputs:
        if isinstance(o.get("text"), str):
            out.append(o["text"])
        for value in (o.get("data") or {}).values():
            if isinstance(value, str):
                out.append(value)
            elif isinstance(value, list):
                out.append("".join(value))
    return out


def compare_numbers(test_outputs, ref_outputs) -> list[Mismatch]:
    """The mismatches of all marked values between a cell's new outputs and its reference outputs."""
    found = []
    for r, t in zip(_texts(ref_outputs), _texts(test_outputs), strict=False):
        if "⟪" in r or "data-tol=" in r:
            found += mismatches(r, t)
    return found


def _glued(output) -> dict | None:
    """The declared value and tolerance of a glued number (``metadata.vibration``), or ``None``."""
    meta = output.get("metadata") or {}
    return meta.get("vibration") if isinstance(meta.get("vibration"), dict) else None


def settle_glued(test_outputs, ref_outputs) -> list[Mismatch]:
    """Glued numbers with a declared tolerance: within it, the new output takes the reference's text (strict
    nbval then sees them equal); outside it, a mismatch. The outputs are compared in order."""
    found = []
    for r, t in zip(ref_outputs, test_outputs, strict=False):
        ref, new = _glued(r), _glued(t)
        if ref is None or new is None:
            continue
        if ref.get("tol") != new.get("tol"):
            continue  # a changed tolerance is a change strict nbval reports (the text differs)
        if within(float(ref["value"]), float(new["value"]), ref["tol"]):
            t["data"] = dict(r.get("data", {}))
        else:
            found.append(Mismatch(reference=float(ref["value"]), new=float(new["value"]), tolerance=ref["tol"]))
    return found


def install() -> None:
    """Wrap nbval's comparison: strict comparison of the sanitized strings, then the marked numbers."""
    from nbval import plugin

    original = plugin.IPyNbCell.compare_outputs
    if getattr(original, "_vibration_numeric", False):
        return

    def compare_outputs(self, test, ref, skip_compare=None):
        glued = settle_glued(test, ref)
        same = original(self, test, ref, skip_compare)
        bad = glued + compare_numbers(test, ref)
        if bad:
            self.comparison_traceback = list(getattr(self, "comparison_traceback", []))
            self.comparison_traceback += ["values outside their declared tolerance:"] + [f"  {m}" for m in bad]
            return False
        return same

    compare_outputs._vibration_numeric = True
    plugin.IPyNbCell.compare_outputs = compare_outputs
