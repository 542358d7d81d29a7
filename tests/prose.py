"""Checks every generated sentence, caption and table of the reader's text passes (imported by the
chapters' tests; tests/presentation/test_tables.py shows that each check can fail)."""

from __future__ import annotations

import math
import re

from vibration.book.presentation.tables import Table

#: Code names that must not reach a reader (they are typeset as symbols instead).
CODE_NAMES = (
    "omega_res",
    "omega_ref",
    "omega_n",
    "omega_max",
    "c_nominal",
    "c_low",
    "c_high",
    "c_min",
    "c_max",
    "c_sky",
    "x_ss",
    "t_end",
    "n_points",
    "n_omega",
    "n_damping",
    "zeta_p",
    "K_v*",
    "F0",
)

_NUMBER = re.compile(r"[-−]?(?:\d+(?:[.,]\d+)*)(?:\s*×\s*10[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+)?|10[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+")


def _outside_math_and_code(text: str) -> str:
    """The text without ``$...$`` maths, ``code`` spans and MyST roles such as {numref}`...`."""
    text = re.sub(r"\$\$.*?\$\$", " ", text, flags=re.S)
    text = re.sub(r"\$[^$]*\$", " ", text)
    return re.sub(r"(\{\w+\})?`[^`]*`", " ", text)


#: A count the reader sees ungrouped: five or more plain digits, not part of a decimal (0.000123456, 12345.6), a
#: grouped count (the narrow no-break space U+202F between groups), a word or identifier (run-12345, x12345), a path,
#: a DOI or an address (10.1016/j.jsv.2019.115012). Written out here, independently of the book's formatter.
UNGROUPED = re.compile(r"(?<![\d.,/:#\w\u202f-])\d{5,}(?![\d\w\u202f/]|[.,]\d)")


def ungrouped_counts(text: str) -> list[str]:
    """The runs of five or more plain digits a reader would see in ``text`` (Markdown or HTML), outside maths,
    code, HTML tags (attribute values) and the invisible plain form of machine-dependent values (``⟪...⟫``).

    >>> ungrouped_counts("RK45 needs 11804 evaluations; LSODA 4526, Radau 28\u202f232, t = 0.000123456 s.")
    ['11804']
    >>> ungrouped_counts('<td data-value="27010.6">27000</td> $N = 20000$ `n=64000` (doi 10.1016/j.x.2019.115012)')
    ['27000']
    >>> table = "```{list-table} Runs of 20000 periods.\\n:name: tab-12345\\n\\n* - 33409\\n```\\n"
    >>> ungrouped_counts(table + "```python\\nn = 10000\\n```")
    ['20000', '33409']
    """
    text = re.sub(r"^(`{3,}|~{3,})(?!\{)[^\n]*\n.*?^\1[ \t]*$", " ", text, flags=re.M | re.S)  # code blocks
    text = re.sub(r"^(?:`{3,}|~{3,})(?:\{[\w-]+\})?", " ", text, flags=re.M)  # a directive's fences: its text stays
    text = re.sub(r"^:[\w-]+:.*$", " ", text, flags=re.M)  # a directive's options (name, class, width)
    bare = _outside_math_and_code(text)
    bare = re.sub(r"<[^>]*>", " ", bare)
    bare = re.sub(r"⟪[^⟫]*⟫", " ", bare)
    return [m.group(0) for m in UNGROUPED.finditer(bare)]


#: Code names a table's caption, header or cell must not show (there a ``_`` becomes a subscript, so t_end and
#: x_ss render as symbols; these would not).
TABLE_CODE_NAMES = ("omega_", "zeta_", "K_v*", "F0", "n_points", "n_omega", "n_damping", "c_sky", "c_nominal")


def _table_words(text: str) -> list[str]:
    out = [f"code name: {n}" for n in TABLE_CODE_NAMES if re.search(rf"(?<![\w\\]){re.escape(n)}", text)]
    out += [p for p in prose_problems(text) if not p.startswith(("code name", "raw subscript"))]
    return out


def prose_problems(text: str) -> list[str]:
    """What a reader should not see in ``text`` (Markdown prose or a caption): empty if it is clean.

    >>> prose_problems("The peak is 2.2e-5 m at omega_res, x_ss = 3 m^2, sqrt(2) nan")  # doctest: +NORMALIZE_WHITESPACE
    ['e-notation: 2.2e-5', 'code name: omega_res', 'code name: x_ss', 'unit written m^2', 'sqrt( in prose',
     'nan or inf: nan']
    >>> prose_problems(r"At $\\omega_\\mathrm{res}$ = 4.47 rad/s the peak is 2.6 × 10⁻⁵ m (`t_eval`).")
    []
    """
    out = []
    bare = _outside_math_and_code(text)
    for m in re.finditer(r"(?<![\w.])\d+(?:\.\d+)?e[-+]?\d+\b", bare):
        out.append(f"e-notation: {m.group(0)}")
    for name in CODE_NAMES:
        if re.search(rf"(?<![\w\\]){re.escape(name)}(?!\w)", bare):
            out.append(f"code name: {name}")
    for m in re.finditer(r"(?<![\w\\])[A-Za-zωζφΔ]_\{?[A-Za-z]\w*", bare):
        if not any(m.group(0).startswith(n) for n in CODE_NAMES):
            out.append(f"raw subscript: {m.group(0)}")
    if re.search(r"\b(m|s|Hz|N)\^\d", bare):
        out.append("unit written " + re.search(r"\b(m|s|Hz|N)\^\d", bare).group(0))
    if "sqrt(" in bare:
        out.append("sqrt( in prose")
    for m in re.finditer(r"(?<![\w-])(nan|inf|NaN|Inf)(?![\w-])", bare):
        out.append(f"nan or inf: {m.group(0)}")
    out += [f"ungrouped count: {n}" for n in ungrouped_counts(text)]
    return out


def header_problems(table: Table) -> list[str]:
    """Code names in a table's caption, headers or text cells, and non-finite numbers in its cells."""
    out = [f"caption {p}" for p in _table_words(table.caption)]
    for c in table.columns:
        out += [f"header {c.header!r}: {p}" for p in _table_words(c.header)]
    for row in table.rows:
        for c in table.columns:
            v = row[c.key]
            if isinstance(v, float) and not math.isfinite(v):
                out.append(f"cell {c.header!r} is {v}")
            if isinstance(v, str):  # number cells (bounds like "< 1e-10" included) print as the table helper does
                out += [f"cell {v!r}: {p}" for p in _table_words(v) if not p.startswith("e-notation")]
    # what the reader sees (number cells included): the rendered table, caption and notes
    out += [f"ungrouped count {n} in the rendered table" for n in ungrouped_counts(table._repr_markdown_())]
    return out


def normalise(text: str) -> str:
    """A paragraph with every number replaced by ``#``, Markdown emphasis and spacing removed."""
    text = re.sub(r"[*_>`]", "", text)
    text = _NUMBER.sub("#", text)
    return re.sub(r"\s+", " ", text).strip().lower()


def paragraphs(text: str) -> list[str]:
    """The paragraphs and list items of a Markdown text (a table's plain text counts as one paragraph)."""
    out = []
    for block in re.split(r"\n\s*\n", text):
        items = re.split(r"\n(?=\s*(?:[-*]|> \*) )", block)
        out += [i.strip() for i in items if i.strip() and i.strip() not in (">", "> **Key results**")]
    return out


def repeated(texts: list[str]) -> list[str]:
    """The paragraphs that appear more than once among ``texts`` (after :func:`normalise`)."""
    seen: dict[str, str] = {}
    twice = []
    for text in texts:
        for p in paragraphs(text):
            key = normalise(p)
            if key.startswith("> **key results**"):
                continue
            if key in seen:
                twice.append(p)
            seen[key] = p
    return twice


def table_texts(tables: list[Table]) -> list[str]:
    """Each table as one paragraph: caption and rows, for the repetition check."""
    return [repr(t).replace("\n", " ") for t in tables]
