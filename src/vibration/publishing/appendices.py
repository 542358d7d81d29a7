"""The book's appendices, generated: the table of symbols (from the chapters' parameter schemas),
the references (:mod:`vibration.presentation.references`) and "Using the package" (each chapter
package's ``usage.md``).

Examples
--------
>>> from vibration.presentation.schema import Param, Schema
>>> s = Schema("04_x", (Param("omega_max", "ω_max", 10.0, "rad/s", 0.0, 1e3, "upper frequency", low_open=True),))
>>> print(symbols_markdown({"04_x": s}).splitlines()[-4])
  - 0 < ω{sub}`max` ≤ 1000
"""

from __future__ import annotations

from importlib.resources import files

from ..presentation.references import bibliography_markdown
from ..presentation.tables import symbol_myst

#: (document name, title) of the appendices, in book order.
APPENDICES = (
    ("symbols", "Table of symbols"),
    ("using", "Using the package"),
    ("references", "References"),
)


def _number(notebook: str) -> int:
    return int(notebook.split("_", 1)[0])


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number(x: float) -> str:
    """A bound as the book writes numbers: a true minus, powers of ten as ×10ⁿ.

    >>> number(-1e4), number(1e6), number(2**31 - 1), number(0.001), number(1.4142135623730951)
    ('−10⁴', '10⁶', '2.147×10⁹', '0.001', '1.414')
    """
    if x == 0:
        return "0"
    sign = "−" if x < 0 else ""
    a = abs(x)
    if 1e-3 <= a < 1e4:
        return sign + f"{a:.4g}"
    exp = int(f"{a:e}".split("e")[1])
    mant = a / 10**exp
    head = "" if abs(mant - 1) < 1e-12 else f"{mant:.4g}×"
    return f"{sign}{head}10{str(exp).translate(_SUPERSCRIPT)}"


def _range(p) -> str:
    if p.choices:
        return ", ".join(map(str, p.choices))
    op = "<" if p.low_open else "≤"
    sym = symbol_myst(p.symbol)
    lo = "" if p.low is None else f"{number(p.low)} {op} "
    hi = "" if p.high is None else f" ≤ {number(p.high)}"
    return f"{lo}{sym}{hi}"


def symbols_markdown(schemas: dict) -> str:
    """The table of symbols: every parameter of every chapter once per (symbol, name, unit), with its chapters."""
    rows: dict[tuple, dict] = {}
    for notebook in sorted(schemas, key=_number):
        for p in schemas[notebook].params:
            key = (p.symbol, p.name, p.unit)
            row = rows.setdefault(key, {"param": p, "chapters": []})
            row["chapters"].append(_number(notebook))
    lines = [
        "# Table of symbols",
        "",
        "Every parameter a reader can change, as the book writes it, with its unit, its allowed range and "
        "the name that sets it in a run of the report (`python -m vibration.report -p NAME VALUE`). A "
        "symbol used by several chapters with one meaning is listed once.",
        "",
        "```{list-table} The book's parameters.",
        ":header-rows: 1",
        ":name: tab-symbols",
        "",
        "* - symbol",
        "  - meaning",
        "  - unit",
        "  - range",
        "  - set with",
        "  - chapters",
    ]
    for (symbol, name, unit), row in sorted(rows.items(), key=lambda kv: (min(kv[1]["chapters"]), kv[0][1])):
        p = row["param"]
        lines += [
            f"* - {symbol_myst(symbol)}",
            f"  - {p.meaning}",
            f"  - {unit or '1'}",
            f"  - {_range(p)}",
            f"  - `-p {name}`",
            f"  - {', '.join(map(str, sorted(set(row['chapters']))))}",
        ]
    lines.append("```")
    return "\n".join(lines)


def usage_markdown(packages: list[str]) -> str:
    """The appendix "Using the package": each chapter package's ``usage.md``, in chapter order."""
    parts = [
        "# Using the package",
        "",
        "The chapters call the package `vibration`; these short examples show the same calls outside the "
        "book, one per chapter. Each runs on its own in a fresh Python session (a test runs them).",
        "",
    ]
    for pkg in packages:
        usage = files(f"vibration.chapters.{pkg}").joinpath("usage.md")
        if usage.is_file():
            text = usage.read_text(encoding="utf-8").strip()
            parts += [text.replace("\n# ", "\n## ") if not text.startswith("# ") else "## " + text[2:], ""]
    return "\n".join(parts)


def references_markdown() -> str:
    """The References page."""
    return bibliography_markdown()
