"""A Table's MyST rendering parses as a numbered table, with or without subscripts in its caption."""

from __future__ import annotations

import docutils.core
import docutils.nodes
import pytest
from myst_parser.parsers.docutils_ import Parser

from vibration.presentation.tables import Column, Missing, Table


def _doctree(text: str):
    return docutils.core.publish_doctree(text, parser=Parser(), settings_overrides={"report_level": 5})


@pytest.mark.parametrize(
    "caption",
    ["Steady amplitudes.", "Steady amplitude x_ss and settling time t_s (the transient stays below 2 % of x_ss)."],
)
def test_markdown_is_a_table_with_its_caption(caption):
    t = Table(
        [{"c": 0.5, "x": 2.2370381}, {"c": 15.0, "x": Missing(reason="no peak when ζ ≥ 1/√2")}],
        [Column(key="c", header="c (N s/m)", digits=3), Column(key="x", header="x_ss (m)", digits=4)],
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
