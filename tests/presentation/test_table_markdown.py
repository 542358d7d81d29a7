"""A Table's MyST rendering parses as a numbered table, with or without subscripts in its caption."""

from __future__ import annotations

import re
from dataclasses import replace

import docutils.core
import docutils.nodes
import pytest
from myst_parser.parsers.docutils_ import Parser

from vibration.book.presentation.tables import Column, Missing, Table


def _doctree(text: str):
    return docutils.core.publish_doctree(text, parser=Parser(), settings_overrides={"report_level": 5})


@pytest.mark.parametrize(
    "caption",
    ["Steady amplitudes.", "Steady amplitude x_ss and settling time t_s (the transient stays below 2 % of x_ss)."],
)
def test_markdown_is_a_table_with_its_caption(caption):
    t = Table(
        rows=[{"c": 0.5, "x": 2.2370381}, {"c": 15.0, "x": Missing(reason="no peak when ζ ≥ 1/√2")}],
        columns=[Column(key="c", header="c (N s/m)", digits=3), Column(key="x", header="x_ss (m)", digits=4)],
        caption=caption,
        name="tab-demo",
    )
    tree = _doctree(t._repr_markdown_())
    tables = list(tree.findall(docutils.nodes.table))
    assert len(tables) == 1, t._repr_markdown_()
    title = next(tables[0].findall(docutils.nodes.title))
    assert "{sub}" not in title.astext() and "`" not in title.astext()
    assert "tab-demo" in tables[0]["ids"] or "tab-demo" in tables[0]["names"]
    if "_ss" in caption:
        assert [s.astext() for s in title.findall(docutils.nodes.subscript)] == ["ss", "s", "ss"]
    rows = list(tables[0].findall(docutils.nodes.row))
    assert len(rows) == 3 and "2.237" in rows[1].astext()


def _wide(n_rows: int, n_cols: int) -> Table:
    cols = [Column(key=f"q{j}", header=f"q{j} (m)") for j in range(n_cols)]
    rows = [{f"q{j}": f"r{i}c{j}" for j in range(n_cols)} for i in range(n_rows)]
    return Table(rows=rows, columns=cols, caption="Wide.", name="tab-wide")


def _html_grid(t: Table) -> list[list[str]]:
    body = t._repr_html_()
    return [re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", tr) for tr in re.findall(r"<tr>(.*?)</tr>", body)]


def test_a_wide_table_with_few_cases_is_turned_for_the_reader():
    t = _wide(3, 9)
    grid = _html_grid(t)
    assert [len(r) for r in grid] == [4] * 9, "one row per quantity, one column per case plus the quantity"
    assert grid[0] == ["q0 (m)", "r0c0", "r1c0", "r2c0"]
    assert grid[5] == ["q5 (m)", "r0c5", "r1c5", "r2c5"]
    md = t._repr_markdown_()
    assert ":stub-columns: 1" in md and md.count("* - ") == 9
    # the plain text nbval compares keeps one row per case, nine columns
    assert repr(t).splitlines()[1].split() == [f"q{j}" if k == 0 else "(m)" for j in range(9) for k in (0, 1)]


@pytest.mark.parametrize(("n_rows", "n_cols"), [(7, 9), (3, 7)])
def test_a_table_that_fits_or_has_many_cases_is_not_turned(n_rows, n_cols):
    grid = _html_grid(_wide(n_rows, n_cols))
    assert len(grid) == n_rows + 1 and {len(r) for r in grid} == {n_cols}


def test_a_turned_table_parses_as_a_table_of_seven_columns_at_most():
    tree = _doctree(_wide(6, 12)._repr_markdown_())
    (table,) = tree.findall(docutils.nodes.table)
    (group,) = table.findall(docutils.nodes.tgroup)
    assert group["cols"] == 7 and len(list(table.findall(docutils.nodes.row))) == 12


def test_a_column_not_shown_stays_in_the_plain_text_and_the_csv(tmp_path):
    t = _wide(16, 8)
    t = Table(
        rows=t.rows,
        columns=[*t.columns[:3], replace(t.columns[3], shown=False), *t.columns[4:]],
        caption="Wide.",
        name="tab-wide",
    )
    grid = _html_grid(t)
    assert {len(r) for r in grid} == {7} and all("r0c3" not in c for r in grid for c in r)
    assert "r0c3" in repr(t)
    assert "r0c3" in t.write_csv(tmp_path).read_text(encoding="utf-8")
