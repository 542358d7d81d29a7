"""Tables for people and for nbval: one object, three representations.

A :class:`Table` is a list of row dicts, the columns to show (header with symbol and
unit, significant digits) and a caption. It renders as

* ``text/markdown``: a MyST ``list-table`` with caption and label, so the book numbers it
  per chapter and ``{numref}`` can refer to it;
* ``text/html``: the same table for JupyterLab;
* ``text/plain``: a fixed-precision aligned text table, the surface strict nbval compares.

A cell that does not exist is :class:`Missing` (with the reason, shown once as a footnote)
and reads "—", never ``nan``. Headers are plain text with an optional ``_`` subscript
(``x_ss (m)`` renders x with subscript ss). When ``$VIBRATION_TABLES_DIR`` is set (the
report runner sets it), showing a table also writes ``<name>.csv`` there.

Examples
--------
>>> t = Table(
...     [{"c": 0.5, "xss": 2.2370381}, {"c": 15.0, "xss": Missing("no peak when ζ ≥ 1/√2")}],
...     [Column("c", "c (N s/m)", 3), Column("xss", "x_ss (m)", 4)],
...     caption="Steady amplitudes.",
...     name="tab-demo",
... )
>>> print(repr(t))
Table tab-demo: Steady amplitudes.
c (N s/m)  x_ss (m)
---------  --------
0.500      2.237
15.0       —a
a: no peak when ζ ≥ 1/√2
"""

from __future__ import annotations

import csv
import html
import math
import os
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

TABLES_ENV = "VIBRATION_TABLES_DIR"
DASH = "—"
#: Text width reserved for an ≈ cell in the plain-text table ("≈-1.234e-10").
APPROX_WIDTH = 11
_MARKS = "abcdefghijklmnopqrstuvwxyz"


@dataclass(frozen=True)
class Missing:
    """A quantity that does not exist in this case, and why (shown as a footnote)."""

    reason: str


@dataclass(frozen=True)
class Approx:
    """A number whose printed digits depend on the machine: shown as "≈value", not compared by nbval.

    Adaptive step controllers at loose tolerances amplify last-bit differences of floating-point
    rounding (CPU, vector maths library, BLAS build) into different step sequences, so their step
    counts and errors differ between machines in the second or third digit. Such a cell prints as
    ``≈2829``; the nbval sanitizer (``tests/nbval_sanitize.cfg``) masks it, and a test compares it
    with the reference within a stated relative tolerance instead.

    >>> fmt(Approx(2829)), fmt(Approx(0.0338123), 3)
    ('≈2829', '≈0.0338')
    """

    value: float


#: The footnote that explains a table's ≈ cells.
APPROX_NOTE = (
    "≈: these digits depend on the machine's floating-point rounding (the text says why), so they differ "
    "between computers and are not part of the regression comparison."
)


@dataclass(frozen=True)
class Column:
    """One column: the row key, the header (symbol and unit), significant digits."""

    key: str  # key in each row dict
    header: str  # e.g. "ω (rad/s)"; a "_" starts a subscript up to the next space or "("
    digits: int = 4  # significant figures of floats
    zeros: bool = True  # keep trailing zeros, so a column shows one number of significant figures (0.100, 15.0)


def fmt(value, digits: int = 4, zeros: bool = False) -> str:
    """Fixed-precision text of a cell: floats to ``digits`` significant figures.

    Examples
    --------
    >>> fmt(2.23703819), fmt(0.000123456), fmt(True), fmt(None), fmt(float("nan")), fmt("overdamped")
    ('2.237', '0.0001235', 'yes', '—', '—', 'overdamped')
    >>> fmt(1.273e5, 4), fmt(-2.5e-9, 2), fmt(1e-12), fmt(31540.0, 3)
    ('1.273×10⁵', '−2.5×10⁻⁹', '10⁻¹²', '3.15×10⁴')
    >>> fmt(-0.1), fmt(-1e-9)
    ('−0.1', '−10⁻⁹')
    >>> fmt(0.1, 3, zeros=True), fmt(15.0, 3, zeros=True), fmt(2.0e-5, 2, zeros=True), fmt(1234.0, 3, zeros=True)
    ('0.100', '15.0', '2.0×10⁻⁵', '1.23×10³')
    """
    if value is None or isinstance(value, Missing):
        return DASH
    if isinstance(value, Approx):
        return "≈" + fmt(value.value, digits, zeros)
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    if isinstance(value, int | np.integer):
        return str(int(value))
    if isinstance(value, float | np.floating):
        v = float(value)
        if math.isnan(v):
            return DASH
        if math.isinf(v):
            return "∞" if v > 0 else "−∞"
        text = f"{v:#.{digits}g}" if zeros else f"{v:.{digits}g}"
        if zeros:
            text = text.rstrip(".") if "e" not in text else text.replace(".e", "e")
        if "e" in text:  # the book's number format: a power of ten, never e-notation
            mant, exp = text.split("e")
            power = "10" + str(int(exp)).translate(_SUPERSCRIPT)
            text = power if mant == "1" else f"-{power}" if mant == "-1" else f"{mant}×{power}"
        return text.replace("-", "−", 1) if text.startswith("-") else text  # a true minus sign
    return str(value)


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


#: A subscript in a header or caption: word characters (and ∞), so "|x − x_exact| (m)", "M(ω_ref)",
#: "t_s, 2 %" and "ω_1," end it at the bar, bracket or comma.
_SUB = re.compile(r"_([\w∞]+)")


def _sub_html(text: str) -> str:
    """Header or caption as HTML, ``_sub`` as ``<sub>``.

    Examples
    --------
    >>> _sub_html("max |x − x_exact| (m)")
    'max |x − x<sub>exact</sub>| (m)'
    """
    return _SUB.sub(lambda m: f"<sub>{m.group(1)}</sub>", html.escape(text))


def _sub_myst(text: str) -> str:
    """Header or caption as MyST: ``_sub`` becomes the ``{sub}`` role, everything else escaped.

    Examples
    --------
    >>> _sub_myst("σ_x (m)")
    'σ{sub}`x` (m)'
    >>> _sub_myst("M(ω_ref)"), _sub_myst("t_s, 2 % (s)"), _sub_myst("J_∞ (s)")
    ('M(ω{sub}`ref`)', 't{sub}`s`, 2 % (s)', 'J{sub}`∞` (s)')
    >>> _sub_myst("Bands ω_1, ω_2 (rad/s).")
    'Bands ω{sub}`1`, ω{sub}`2` (rad/s).'
    """
    out, last = [], 0
    for m in _SUB.finditer(text):
        out.append(_escape_md(text[last : m.start()]))
        out.append("{sub}`" + m.group(1) + "`")
        last = m.end()
    out.append(_escape_md(text[last:]))
    return "".join(out)


def _escape_md(text: str) -> str:
    return re.sub(r"([\\`*_\[\]|<>#])", r"\\\1", text)


@dataclass
class Table:
    """Rows with headers, units and a caption; see the module docstring."""

    rows: Sequence[dict]
    columns: Sequence[Column]
    caption: str
    name: str  # label for {numref}, e.g. "tab-claims"; also the CSV file name
    notes: Sequence[str] = ()  # footnotes below the table (besides the Missing reasons)
    csv: bool = True  # write <name>.csv when $VIBRATION_TABLES_DIR is set
    _marks: dict = field(init=False, repr=False)

    def __post_init__(self) -> None:
        if not self.rows:
            raise ValueError(f"table {self.name!r} has no rows")
        keys = {c.key for c in self.columns}
        for i, row in enumerate(self.rows):
            absent = keys - set(row)
            if absent:
                raise ValueError(f"table {self.name!r}: row {i} lacks column(s) {sorted(absent)}")
        reasons: dict[str, str] = {}
        for row in self.rows:
            for c in self.columns:
                v = row[c.key]
                if isinstance(v, Missing) and v.reason not in reasons:
                    reasons[v.reason] = _MARKS[len(reasons) % len(_MARKS)]
        self._marks = reasons

    # -- cells ---------------------------------------------------------------
    def cells(self) -> list[list[str]]:
        """Text of every cell (footnote marks appended to missing values)."""
        out = []
        for row in self.rows:
            line = []
            for c in self.columns:
                v = row[c.key]
                text = fmt(v, c.digits, c.zeros)
                if isinstance(v, Missing):
                    text += self._marks[v.reason]
                line.append(text)
            out.append(line)
        return out

    def footnotes(self) -> list[str]:
        """The Missing reasons (``a: ...``), the note on ≈ cells if any, then the notes."""
        approx = any(isinstance(row[c.key], Approx) for row in self.rows for c in self.columns)
        return (
            [f"{mark}: {reason}" for reason, mark in self._marks.items()]
            + ([APPROX_NOTE] if approx else [])
            + list(self.notes)
        )

    # -- representations -----------------------------------------------------
    def __repr__(self) -> str:
        heads = [c.header for c in self.columns]
        cells = self.cells()
        # An ≈ cell counts with a fixed width, so that its machine-dependent digits cannot move the layout.
        widths = [
            max(
                len(h),
                *(
                    APPROX_WIDTH if isinstance(row[c.key], Approx) else len(r[i])
                    for row, r in zip(self.rows, cells, strict=True)
                ),
            )
            for i, (h, c) in enumerate(zip(heads, self.columns, strict=True))
        ]
        lines = [f"Table {self.name}: {self.caption}"]
        lines.append("  ".join(h.ljust(w) for h, w in zip(heads, widths, strict=True)).rstrip())
        lines.append("  ".join("-" * w for w in widths))
        lines += ["  ".join(v.ljust(w) for v, w in zip(r, widths, strict=True)).rstrip() for r in cells]
        lines += self.footnotes()
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{_sub_html(c.header)}</th>" for c in self.columns)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(v)}</td>" for v in r) + "</tr>" for r in self.cells())
        notes = "".join(f"<p class='vib-table-note'>{html.escape(n)}</p>" for n in self.footnotes())
        return (
            f"<div class='vib-table' id='{html.escape(self.name)}'><table>"
            f"<caption>{_sub_html(self.caption)}</caption>"
            f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>{notes}</div>"
        )

    def _repr_markdown_(self) -> str:
        caption = _sub_myst(self.caption)
        # A backtick fence may not carry backticks in its info string (CommonMark), and the caption's
        # {sub} roles have them: such captions open a tilde fence, which may.
        fence = "~~~" if "`" in caption else "```"
        lines = [f"{fence}{{list-table}} {caption}", ":header-rows: 1", f":name: {self.name}"]
        lines.append(":class: vib-table")
        lines.append("")
        lines.append("* - " + "\n  - ".join(_sub_myst(c.header) for c in self.columns))
        for r in self.cells():
            lines.append("* - " + "\n  - ".join(_escape_md(v) for v in r))
        lines.append(fence)
        if self.footnotes():
            lines.append("")
            lines.append("<div class='vib-table-notes'>" + "<br>".join(map(html.escape, self.footnotes())) + "</div>")
        return "\n".join(lines)

    def _repr_mimebundle_(self, include=None, exclude=None):
        self.write_csv()
        return {"text/plain": repr(self), "text/html": self._repr_html_(), "text/markdown": self._repr_markdown_()}

    # -- files ---------------------------------------------------------------
    def write_csv(self, folder: str | os.PathLike | None = None) -> Path | None:
        """Write every column (full precision, 10 significant figures) to ``<name>.csv``."""
        folder = folder or os.environ.get(TABLES_ENV)
        if not (folder and self.csv):
            return None
        path = Path(folder) / f"{self.name}.csv"
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("w", newline="", encoding="utf-8") as fh:
            writer = csv.writer(fh, lineterminator="\n")
            writer.writerow([c.header for c in self.columns])
            for row in self.rows:
                writer.writerow([_csv_cell(row[c.key]) for c in self.columns])
        return path


def bound(value: float, tol: float) -> str | Missing:
    """A check against its stated tolerance: ``"< tol"`` when it holds, else the value and the tolerance.

    The printed tolerance, not the value's order of magnitude, is what reproduces on every machine:
    a rounding-level difference of 3e-15 on one CPU may be 1.2e-14 on another.

    >>> bound(3e-15, 1e-12), bound(2.5e-9, 1e-12), bound(float("nan"), 1e-12)
    ('< 10⁻¹²', '2.5×10⁻⁹ (above 10⁻¹²)', Missing(reason='not computed for this case'))
    """
    if not math.isfinite(value):
        return Missing("not computed for this case") if math.isnan(value) else Missing("infinite")
    if abs(value) < tol:
        return f"< {fmt(tol)}"
    return f"{fmt(abs(value), 2)} (above {fmt(tol)})"


def _csv_cell(value) -> str:
    if isinstance(value, Missing):
        return ""
    value = value.value if isinstance(value, Approx) else value
    if isinstance(value, float | np.floating) and math.isfinite(value):
        return f"{float(value):.10g}"  # machine-readable: e-notation, not the book's ×10ⁿ
    return fmt(value, 10)


def table(rows: Iterable[dict], columns: Sequence[Column | tuple], caption: str, name: str, notes=()) -> Table:
    """Shorthand: columns may be ``(key, header, digits)`` tuples."""
    cols = [c if isinstance(c, Column) else Column(*c) for c in columns]
    return Table(list(rows), cols, caption, name, tuple(notes))


def symbol_html(text: str) -> str:
    """A symbol or header as HTML: ``ω_res`` -> ``ω<sub>res</sub>`` (the public form of the table helper's rule)."""
    return _sub_html(text)


def symbol_myst(text: str) -> str:
    """A symbol or header as MyST: ``ω_res`` -> ``ω{sub}`res```, everything else escaped."""
    return _sub_myst(text)
