"""A chapter's cells tagged "details" fold into one <details> section of its page, open in print."""

from __future__ import annotations

import nbformat

from vibration.book.publishing.book import ChapterPage, fold_details, prepare


def _cell(kind: str, source: str, tags=(), outputs=()):
    cell = nbformat.v4.new_markdown_cell(source) if kind == "md" else nbformat.v4.new_code_cell(source)
    if kind != "md":
        cell.outputs = list(outputs)
    if tags:
        cell.metadata["tags"] = list(tags)
    return cell


FIGURE = nbformat.v4.new_output("display_data", data={"image/png": "iVBORw0KGgo=", "text/plain": "<Figure>"})
TABLE = nbformat.v4.new_output("execute_result", data={"text/html": "<table><tr><td>1</td></tr></table>"})


def test_each_run_of_tagged_cells_is_one_fold_and_untagged_cells_stay_out():
    cells = [
        _cell("md", "## Main\n\nText."),
        _cell("md", "### Convergence\n\nWhy.", ["details"]),
        _cell("code", "t()", ["details"], [TABLE]),
        _cell("md", "## Next"),
        _cell("code", "f()", ["details"], [FIGURE]),
        _cell("code", "g()", ["details"], [TABLE, TABLE]),
    ]
    out = [c.source for c in fold_details(cells)]
    assert out == [
        "## Main\n\nText.",
        '<details class="vib-details"><summary>Details: Convergence</summary>',
        "\nWhy.",
        "t()",
        "</details>",
        "## Next",
        '<details class="vib-details"><summary>Details: 1 figure, 2 tables</summary>',
        "f()",
        "g()",
        "</details>",
    ]


def test_no_heading_opens_a_section_inside_a_fold():
    cells = [_cell("md", "x", ["details"]), _cell("md", "#### Inner heading\nmore", ["details"])]
    out = [c.source for c in fold_details(cells)]
    assert out[2] == "**Inner heading**\nmore" and not any(s.lstrip().startswith("#") for s in out)


def test_the_book_page_folds_what_the_notebook_tags():
    nb = nbformat.v4.new_notebook()
    nb.cells = [
        _cell("md", "# 9. T"),
        _cell("md", "### Checks", ["details"]),
        _cell("code", "c()", ["details"], [TABLE]),
    ]
    sources = [c.source for c in prepare(ChapterPage(name="09_t", notebook=nb, part="P")).cells]
    assert sources.count("</details>") == 1 and sources[1].startswith('<details class="vib-details">')


def test_each_section_at_the_folds_level_gets_its_own_fold():
    cells = [
        _cell("md", "### Runs\nA", ["details"]),
        _cell("md", "#### Inside\nB", ["details"]),
        _cell("md", "### Trade-off\nC", ["details"]),
    ]
    out = [c.source for c in fold_details(cells)]
    assert [s for s in out if s.startswith("<details")] == [
        '<details class="vib-details"><summary>Details: Runs</summary>',
        '<details class="vib-details"><summary>Details: Trade-off</summary>',
    ]
    assert "**Inside**\nB" in out and out.count("</details>") == 2
