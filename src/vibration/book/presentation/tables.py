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
...     rows=[{"c": 0.5, "xss": 2.2370381}, {"c": 15.0, "xss": Missing(reason="no peak when ζ ≥ 1/√2")}],
...     columns=[Column(key="c", header="c (N s/m)", digits=3), Column(key="xss", header="x_ss (m)", digits=4)],
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

from .numbers import Approx, column, integer, plain_width, sig
from .numbers import bound as _bound

TABLES_ENV = "VIBRATION_TABLES_DIR"
DASH = "—"
_MARKS = "abcdefghijklmnopqrstuvwxyz"
#: The widest table the reader sees; a wider one with few enough rows is shown turned (:meth:`Table.transposed`).
MAX_COLUMNS = 7


@dataclass(frozen=True, kw_only=True)
class Missing:
    """A quantity that does not exist in this case, and why (shown as a footnote)."""

    reason: str


@dataclass(frozen=True, kw_only=True)
class Composite:
    """A cell that joins words and numbers, some of them machine-dependent (:class:`Approx`).

    ``parts`` holds text and ``(Approx, digits)`` pairs, each number written as a table cell (``digits``
    significant figures, trailing zeros kept); the reader sees one line of text, the plain form
    writes each Approx with its tolerance (``⟪value tolerance⟫``), and its width is fixed, as an Approx cell's.

    >>> c = Composite(parts=("a = ", (Approx(value=0.012345, rtol=0.1), 3), " ± ", (Approx(value=0.0021, factor=3), 2)))
    >>> str(c), c.plain()
    ('a = 0.0123 ± 0.0021', 'a = ⟪0.012345 r0.1⟫ ± ⟪0.0021 f3⟫')
    >>> Composite(parts=("θ_f = ", "0.11")).html()
    'θ<sub>f</sub> = 0.11'
    """

    parts: tuple

    def _each(self, number) -> str:
        return "".join(p if isinstance(p, str) else number(*p) for p in self.parts)

    def __str__(self) -> str:
        return self._each(lambda a, d: column(a.number(), d))

    def plain(self) -> str:
        return self._each(lambda a, d: a.plain())

    def html(self) -> str:
        """The reader's form: text escaped, ``_sub`` as a subscript (``θ_f``), each Approx in its span."""
        return "".join(
            _sub_html(p) if isinstance(p, str) else p[0].html(column(p[0].number(), p[1])) for p in self.parts
        )

    def width(self) -> int:
        return sum(len(p) if isinstance(p, str) else plain_width(p[0]) for p in self.parts)


@dataclass(frozen=True, kw_only=True)
class Column:
    """One column: the row key, the header (symbol and unit), significant digits."""

    key: str  # key in each row dict
    header: str  # e.g. "ω (rad/s)"; a "_" starts a subscript up to the next space or "("
    digits: int = 4  # significant figures of floats
    zeros: bool = True  # keep trailing zeros, so a column shows one number of significant figures (0.100, 15.0)
    shown: bool = True  # False: a derived column kept for the CSV file and the plain text, not shown to the reader


def text_rows(spec: str) -> list[list[str]]:
    """The lines of a text block as lists of fields, separated by two or more spaces; blank lines skipped.

    >>> text_rows('''
    ...     natural frequency ωₙ  omega_n  rad/s
    ...
    ...     damping ratio ζ       zeta
    ... ''')
    [['natural frequency ωₙ', 'omega_n', 'rad/s'], ['damping ratio ζ', 'zeta']]
    """
    return [re.split(r"\s{2,}", line.strip()) for line in spec.splitlines() if line.strip()]


#: What may follow a column's header in a :func:`columns` spec, besides its significant digits.
_FLAGS = {"hidden": {"shown": False}, "nozeros": {"zeros": False}}


def columns(spec: str) -> list[Column]:
    """A table's columns written as data, one column a line: ``key  header  digits  flags``.

    The fields are separated by two or more spaces (a header may hold single spaces); the digits
    (default 4) and the flags are optional. ``hidden`` is a column kept for the CSV file and the plain
    text only (``shown=False``); ``nozeros`` drops trailing zeros (``zeros=False``). Blank lines are skipped.

    Examples
    --------
    >>> cols = columns('''
    ...     case    case
    ...     c       c (N s/m)       3
    ...     ratio   error / stated  3  hidden
    ...     omega   ω (rad/s)       4  nozeros
    ... ''')
    >>> [(c.key, c.header, c.digits, c.shown, c.zeros) for c in cols]  # doctest: +NORMALIZE_WHITESPACE
    [('case', 'case', 4, True, True), ('c', 'c (N s/m)', 3, True, True),
     ('ratio', 'error / stated', 3, False, True), ('omega', 'ω (rad/s)', 4, True, False)]
    >>> columns("c  c (N s/m)  three")
    Traceback (most recent call last):
    ...
    ValueError: column line 'c  c (N s/m)  three': 'three' is neither a number of digits nor one of hidden, nozeros
    """
    out = []
    for fields in text_rows(spec):
        line = "  ".join(fields)
        if len(fields) < 2:
            raise ValueError(f"column line {line.strip()!r}: allowed 'key  header  digits  flags' (two spaces apart)")
        options: dict = {}
        for word in fields[2:]:
            if word.isdigit():
                options["digits"] = int(word)
            elif word in _FLAGS:
                options.update(_FLAGS[word])
            else:
                allowed = ", ".join(_FLAGS)
                raise ValueError(
                    f"column line {line.strip()!r}: {word!r} is neither a number of digits nor one of {allowed}"
                )
        out.append(Column(key=fields[0], header=fields[1], **options))
    return out


def fmt(value, digits: int = 4, zeros: bool = False) -> str:
    """Text of a cell: floats in the book's number format (:func:`vibration.book.presentation.numbers.sig`).

    An integer cell is a count (steps, samples, evaluations) and is written by
    :func:`vibration.book.presentation.numbers.integer`: five or more digits are grouped in threes. An identifier
    (a year, a seed, a run number) is a name, not an amount: give it to the table as text.

    An :class:`Approx` cell reads like any other number (its tolerance goes to the plain-text form only).

    Examples
    --------
    >>> fmt(2.23703819), fmt(0.000123456), fmt(True), fmt(None), fmt(float("nan")), fmt("overdamped")
    ('2.237', '0.0001235', 'yes', '—', '—', 'overdamped')
    >>> fmt(1.273e5, 4), fmt(-2.5e-9, 2), fmt(1e-12), fmt(31540.0, 3), fmt(Approx(value=2829.0, rtol=0.25))
    ('1.273×10⁵', '−2.5×10⁻⁹', '10⁻¹²', '3.15×10⁴', '2829')
    >>> fmt(-0.1), fmt(-1e-9), fmt(-3), fmt(4096), fmt(200001), fmt(Approx(value=28232, rtol=0.25))
    ('−0.1', '−10⁻⁹', '−3', '4096', '200\u202f001', '28\u202f232')
    >>> fmt(0.1, 3, zeros=True), fmt(15.0, 3, zeros=True), fmt(2.0e-5, 2, zeros=True), fmt(1234.0, 3, zeros=True)
    ('0.100', '15.0', '2.0×10⁻⁵', '1.23×10³')
    """
    if value is None or isinstance(value, Missing):
        return DASH
    if isinstance(value, Approx):
        return fmt(value.value, digits, zeros)
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    if isinstance(value, int | np.integer):
        return integer(value)
    if isinstance(value, float | np.floating):
        return sig(float(value), digits, zeros=zeros)
    return str(value)


#: A subscript in a header or caption: word characters (and ∞), so "|x − x_exact| (m)", "M(ω_ref)",
#: "t_s, 2 %" and "ω_1," end it at the bar, bracket or comma.
_SUB = re.compile(r"_([\w∞]+)")


#: A MyST cross-reference in a caption (``{numref}`tab-x```), or a subscript.
_ROLE_OR_SUB = re.compile(r"(?P<role>\{(?:numref|ref|eq)\}`[^`]+`)|_(?P<sub>[\w∞]+)")
_ROLE = re.compile(r"\{(?:numref|ref|eq)\}`([^`]+)`")


#: The words a cross-reference in a Markdown output shows where nothing numbers it (JupyterLab):
#: "the table", "the figure", "the next figure", "the previous table".
REFERENCE_WORDS = r"the (?:next |previous )?(?:figure|table)"


def cross_reference(label: str, words: str | None = None) -> str:
    """A cross-reference for a sentence a chapter shows as a Markdown output: ``{numref}`the table <tab-x>```.

    JupyterLab renders each output on its own, with no figure or table to number, and shows ``words``
    ("the figure" or "the table" by the label's prefix unless given); the book drops the words, so Sphinx
    numbers and links the reference ("Table 3.1"), as it does the Markdown cells'
    (:mod:`vibration.book.publishing.crossrefs`).

    Examples
    --------
    >>> cross_reference("tab-energy"), cross_reference("fig-zoom", "the next figure")
    ('{numref}`the table <tab-energy>`', '{numref}`the next figure <fig-zoom>`')
    """
    words = words or ("the figure" if label.startswith("fig") else "the table")
    if not re.fullmatch(REFERENCE_WORDS, words):
        raise ValueError(f"words = {words!r}: allowed {REFERENCE_WORDS}")
    return f"{{numref}}`{words} <{label}>`"


def _sub_html(text: str) -> str:
    """Header or caption as HTML, ``_sub`` as ``<sub>``.

    Examples
    --------
    >>> _sub_html("max |x − x_exact| (m)")
    'max |x − x<sub>exact</sub>| (m)'
    >>> _sub_html("split in {numref}`tab-energy`")
    "split in <a href='#tab-energy'>the table</a>"
    """
    parts, last = [], 0
    for m in _ROLE.finditer(text):  # a cross-reference: a link to the table or figure it names
        parts.append(_SUB.sub(lambda s: f"<sub>{s.group(1)}</sub>", html.escape(text[last : m.start()])))
        word = "the figure" if m.group(1).startswith("fig") else "the table"
        parts.append(f"<a href='#{html.escape(m.group(1))}'>{word}</a>")
        last = m.end()
    parts.append(_SUB.sub(lambda s: f"<sub>{s.group(1)}</sub>", html.escape(text[last:])))
    return "".join(parts)


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
    >>> _sub_myst("Split in {numref}`tab-a_b` (x_ss).")
    'Split in {numref}`tab-a_b` (x{sub}`ss`).'
    """
    out, last = [], 0
    for m in _ROLE_OR_SUB.finditer(text):
        if m.group("role"):  # a cross-reference stays a MyST role, so the book numbers it
            out.append(_escape_md(text[last : m.start()]))
            out.append(m.group(0))
            last = m.end()
            continue
        out.append(_escape_md(text[last : m.start()]))
        out.append("{sub}`" + m.group("sub") + "`")
        last = m.end()
    out.append(_escape_md(text[last:]))
    return "".join(out)


def _escape_md(text: str) -> str:
    return re.sub(r"([\\`*_\[\]|<>#])", r"\\\1", text)


@dataclass(frozen=True, kw_only=True)
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
        object.__setattr__(self, "_marks", reasons)

    # -- cells ---------------------------------------------------------------
    def cells(self, *, plain: bool = False) -> list[list[str]]:
        """Text of every cell, as the reader sees it (``plain=False``) or as nbval compares it.

        The reader's form writes :class:`Approx` cells like any other number and leaves the footnote
        marks of missing values to the renderer (:meth:`_mark`); the plain form appends the mark
        (``—a``) and writes an Approx cell with its declared tolerance (``⟪2829 r0.25⟫``).
        """
        out = []
        for row in self.rows:
            line = []
            for c in self.columns:
                v = row[c.key]
                if plain and isinstance(v, Approx | Composite):
                    text = v.plain()
                else:
                    text = fmt(v, c.digits, c.zeros)
                if plain and isinstance(v, Missing):
                    text += self._marks[v.reason]
                line.append(text)
            out.append(line)
        return out

    def _mark(self, row: int, col: int) -> str:
        """The footnote mark of a missing cell (``""`` for every other cell)."""
        v = self.rows[row][self.columns[col].key]
        return self._marks[v.reason] if isinstance(v, Missing) else ""

    def _reader(self, row: int, col: int, text: str) -> str:
        """A cell's text for the reader; an :class:`Approx` cell wrapped in its invisible tolerance span."""
        v = self.rows[row][self.columns[col].key]
        if isinstance(v, Composite):
            return v.html()
        return v.html(text) if isinstance(v, Approx) else text

    def footnotes(self) -> list[str]:
        """The Missing reasons (``a: ...``), then the notes."""
        return [f"{mark}: {reason}" for reason, mark in self._marks.items()] + list(self.notes)

    def _notes_html(self) -> list[str]:
        """The footnotes for the reader: each mark as a superscript before its reason."""
        return [f"<sup>{m}</sup> {html.escape(r)}" for r, m in self._marks.items()] + [
            html.escape(n) for n in self.notes
        ]

    # -- representations -----------------------------------------------------
    def __repr__(self) -> str:
        heads = [c.header for c in self.columns]
        cells = self.cells(plain=True)
        # An Approx cell counts with a fixed width, so that its machine-dependent digits cannot move the layout.
        widths = [
            max(
                len(h),
                *(
                    plain_width(row[c.key])
                    if isinstance(row[c.key], Approx)
                    else row[c.key].width()
                    if isinstance(row[c.key], Composite)
                    else len(r[i])
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

    def transposed(self) -> bool:
        """Whether the reader sees the table turned: one row per quantity, one column per case.

        A table wider than :data:`MAX_COLUMNS` whose cases fit across the page is shown turned, so no table
        in the book is wider than seven columns; the plain text (what nbval compares) and the CSV file keep
        the table as it is built, one row per case.
        """
        return len(self._shown()) > MAX_COLUMNS and len(self.rows) + 1 <= MAX_COLUMNS

    def _shown(self) -> list[int]:
        """Indices of the columns the reader sees."""
        return [j for j, c in enumerate(self.columns) if c.shown]

    def _grid(self, escape, header, sup) -> tuple[list[str], list[list[str]]]:
        """Header cells and body rows for the reader (cells escaped by ``escape``, marks by ``sup``).

        The header is made of the column headers, or, turned (:meth:`transposed`), of the first column's
        header and cells; the body rows then start with the other headers.
        """
        cells = self.cells()

        def cell(i: int, j: int) -> str:
            mark = self._mark(i, j)
            return self._reader(i, j, escape(cells[i][j])) + (sup(mark) if mark else "")

        shown = self._shown()
        first, *rest = shown
        if not self.transposed():
            return [header(self.columns[j].header) for j in shown], [
                [cell(i, j) for j in shown] for i in range(len(self.rows))
            ]
        head = [header(self.columns[first].header)] + [cell(i, first) for i in range(len(self.rows))]
        body = [[header(self.columns[j].header)] + [cell(i, j) for i in range(len(self.rows))] for j in rest]
        return head, body

    def _repr_html_(self) -> str:
        head_cells, rows = self._grid(html.escape, _sub_html, "<sup>{}</sup>".format)
        head = "".join(f"<th>{h}</th>" for h in head_cells)
        first = "th scope='row'" if self.transposed() else "td"
        body = "".join(
            "<tr>"
            + "".join(f"<{first}>{v}</{first.split()[0]}>" if j == 0 else f"<td>{v}</td>" for j, v in enumerate(r))
            + "</tr>"
            for r in rows
        )
        notes = "".join(f"<p class='vib-table-note'>{n}</p>" for n in self._notes_html())
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
        if self.transposed():
            lines.append(":stub-columns: 1")
        lines.append(":class: vib-table")
        lines.append("")
        head, rows = self._grid(_escape_md, _sub_myst, "{{sup}}`{}`".format)
        for r in [head, *rows]:
            lines.append("* - " + "\n  - ".join(r))
        lines.append(fence)
        notes = self._notes_html()
        if notes:
            lines.append("")
            lines.append("<div class='vib-table-notes'>" + "<br>".join(notes) + "</div>")
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
    """A check against its stated tolerance (:func:`vibration.book.presentation.numbers.bound`) as a table cell.

    >>> bound(3e-15, 1e-12), bound(2.5e-9, 1e-12), bound(float("nan"), 1e-12)
    ('< 10⁻¹²', '2.5×10⁻⁹ (above 10⁻¹²)', Missing(reason='not computed for this case'))
    >>> bound(float("inf"), 1e-12)
    Missing(reason='infinite')
    """
    if math.isinf(value):
        return Missing(reason="infinite")
    text = _bound(value, tol)
    return Missing(reason="not computed for this case") if text is None else text


def self_checks(
    checks: Iterable[tuple],
    *,
    caption: str,
    name: str,
    headers: tuple[str, ...] = ("check", "bound"),
    digits: int = 4,
) -> Table:
    """A chapter's self-checks: one row a check, what it compares, its value and, when told, whether it passes.

    Parameters
    ----------
    checks : iterable of tuples
        Each check's description and its value (a bound such as ``"< 10⁻¹²"`` as :func:`bound` prints it,
        a number or a :class:`Missing`), then, with a third header, whether it passes.
    caption, name : str
        The table's caption and label.
    headers : tuple of two or three str
        The headers of the columns.
    digits : int
        Significant figures of a value given as a number.

    Examples
    --------
    >>> print(repr(self_checks([("residual, relative", bound(3e-15, 1e-12))], caption="Checks.", name="tab-c")))
    Table tab-c: Checks.
    check               bound
    ------------------  -------
    residual, relative  < 10⁻¹²
    >>> t = self_checks([("energy", 2.5e-3, False)], caption="C.", name="tab-d", headers=("check", "difference", "ok"))
    >>> t.rows, [c.header for c in t.columns]
    ([{'check': 'energy', 'value': 0.0025, 'ok': False}], ['check', 'difference', 'ok'])
    """
    if len(headers) not in (2, 3):
        raise ValueError(f"headers = {headers!r}: allowed two or three headers (check, value and whether it passes)")
    keys = ("check", "value", "ok")[: len(headers)]
    rows = [dict(zip(keys, check, strict=True)) for check in checks]
    cols = [Column(key=k, header=h, digits=digits) for k, h in zip(keys, headers, strict=True)]
    return Table(rows=rows, columns=cols, caption=caption, name=name)


def _csv_cell(value) -> str:
    if isinstance(value, Missing):
        return ""
    value = value.value if isinstance(value, Approx) else value
    if isinstance(value, float | np.floating) and math.isfinite(value):
        return f"{float(value):.10g}"  # machine-readable: e-notation, not the book's ×10ⁿ
    if isinstance(value, int | np.integer) and not isinstance(value, bool | np.bool_):
        return str(int(value))  # machine-readable: no group separators
    return fmt(value, 10)


def table(rows: Iterable[dict], columns: Sequence[Column | tuple], caption: str, *, name: str, notes=()) -> Table:
    """Shorthand: columns may be ``(key, header, digits)`` tuples."""
    cols = [
        c if isinstance(c, Column) else Column(**dict(zip(("key", "header", "digits"), c, strict=False)))
        for c in columns
    ]
    return Table(rows=list(rows), columns=cols, caption=caption, name=name, notes=tuple(notes))


def symbol_html(text: str) -> str:
    """A symbol or header as HTML: ``ω_res`` -> ``ω<sub>res</sub>`` (the public form of the table helper's rule)."""
    return _sub_html(text)


def symbol_myst(text: str) -> str:
    """A symbol or header as MyST: ``ω_res`` -> ``ω{sub}`res```, everything else escaped."""
    return _sub_myst(text)
