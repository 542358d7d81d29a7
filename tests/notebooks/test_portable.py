"""The regression surface holds on other machines, and still catches a real change.

`make test` runs strict nbval in another numerical environment than the one `make notebooks` wrote the
references in (see the Makefile's PORTABLE). Table cells whose digits depend on last-bit rounding are
written ``⟪value tolerance⟫`` in the plain-text form only: the sanitizer masks the value and keeps the
declared tolerance, and the numeric plugin (``tests/nbval_numeric.py``) compares the value within it.
The reader's forms (Markdown, HTML) write the number like any other.
"""

from __future__ import annotations

import json
import re
import textwrap
from pathlib import Path

import nbformat
import pytest
from conftest import nbval_sanitize
from nbval_numeric import MARK, mismatches, within

from vibration.book.chapters.solver_accuracy.study import MACHINE_DEPENDENT, solver_accuracy_study
from vibration.book.chapters.solver_accuracy.tables import ERROR_FACTOR, NFEV_RTOL, ladder_table
from vibration.book.presentation.tables import Approx, Column, Table

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "03_solver_accuracy.ipynb"


def test_sanitizer_masks_the_value_and_keeps_the_tolerance():
    a = "LSODA   0.001   1e-6   ⟪2926 r0.25⟫   ⟪0.0323 f5⟫"
    b = "LSODA   0.001   1e-6   ⟪29260 r0.25⟫  ⟪0.0315 f5⟫"
    assert nbval_sanitize(a).split() == nbval_sanitize(b).split()
    # the padding after a cell follows the width of its value's digits, so it is masked with the value
    assert nbval_sanitize("λ  ⟪0.000879392 f3⟫   0.1") == nbval_sanitize("λ  ⟪0.00124365 f3⟫    0.1")
    html_a = '<td><span class="vib-approx" data-value="2926.4" data-tol="r0.25">2926</span></td>'
    html_b = '<td><span class="vib-approx" data-value="3011" data-tol="r0.25">3011</span></td>'
    assert nbval_sanitize(html_a) == nbval_sanitize(html_b) != nbval_sanitize(html_a.replace("r0.25", "r0.5"))
    # a changed declared tolerance is a strict difference
    assert nbval_sanitize("⟪2926 r0.25⟫") != nbval_sanitize("⟪2926 r0.5⟫")
    # digits that are not marked still count
    assert nbval_sanitize("RK45 1436 0.012") != nbval_sanitize("RK45 1437 0.012")


def test_reader_sees_clean_numbers_and_nbval_sees_the_tolerance():
    t = Table(
        rows=[{"n": Approx(value=2926.0, rtol=0.25), "e": Approx(value=0.03231, factor=5.0)}],
        columns=[Column(key="n", header="evaluations"), Column(key="e", header="error (m)", digits=3)],
        caption="c",
        name="tab-t",
    )
    reader = t._repr_html_() + t._repr_markdown_()
    assert ">2926</span>" in reader and ">0.0323</span>" in reader
    visible = re.sub(r"<[^>]*>", "", reader)
    assert not re.search(r"[≈⟪⟫]|data-", visible)
    assert "regression" not in reader
    plain = repr(t)
    assert [(m["value"], m["tol"]) for m in MARK.finditer(plain)] == [("2926", "r0.25"), ("0.03231", "f5")]


def test_tolerances_are_applied_as_declared():
    # independent arithmetic: 25 % of 2926 is 731.5; a factor 5 of 0.0323 spans 0.00646 to 0.1615
    assert within(2926.0, 2926.0 + 731.0, "r0.25") and not within(2926.0, 2926.0 + 732.0, "r0.25")
    assert within(0.0323, 0.1614, "f5") and not within(0.0323, 0.1616, "f5")
    assert within(0.0323, 0.00647, "f5") and not within(0.0323, 0.00645, "f5")
    assert not mismatches("⟪1 r0.1⟫ ⟪2 a0.5⟫", "⟪1.09 r0.1⟫ ⟪2.4 a0.5⟫")
    assert len(mismatches('data-value="1" data-tol="r0.1"', 'data-value="1.2" data-tol="r0.1"')) == 1
    assert len(mismatches("⟪1 r0.1⟫ ⟪2 a0.5⟫", "⟪1.2 r0.1⟫ ⟪2.6 a0.5⟫")) == 2


def test_ladder_declares_its_machine_dependent_cells():
    table = ladder_table(solver_accuracy_study(t_end=10.0, n_points=1001))
    for row in table.rows:
        cells = [row[k] for k in ("nfev", "ex", "ev", "rel")]
        if row["method"] in MACHINE_DEPENDENT:
            assert [c.rtol for c in cells[:1]] == [NFEV_RTOL]
            assert all(c.factor == ERROR_FACTOR for c in cells[1:])
        else:
            assert not any(isinstance(c, Approx) for c in cells)


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_committed_ladder_matches_this_machine_within_its_tolerances():
    """The committed reference against a run here: what `make test` checks under PORTABLE, without a kernel."""
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    ref = next(
        "".join(out["data"]["text/plain"])
        for cell in nb["cells"]
        for out in cell.get("outputs", [])
        if "".join(out.get("data", {}).get("text/plain", [])).startswith("Table tab-solvers-ladder")
    )
    new = repr(ladder_table(solver_accuracy_study()))
    assert MARK.search(ref), "no marked cells in the committed ladder"
    assert nbval_sanitize(ref) == nbval_sanitize(new)
    assert mismatches(ref, new) == []


# ----------------------------------------------------------------------------- through nbval itself

_CELL = "from vibration.book.presentation.tables import Approx, Column, Table\n" + textwrap.dedent(
    """
    Table(rows=[{"n": Approx(value=VALUE, rtol=0.25), "k": 7}],
          columns=[Column(key="n", header="evaluations"), Column(key="k", header="count")], caption="c", name="tab-t")
    """
)


def _notebook(path: Path, reference: float, value: float) -> None:
    """A one-cell notebook whose stored output shows ``reference`` and whose code now yields ``value``."""
    from vibration.book.presentation.tables import Table as T

    table = T(
        rows=[{"n": Approx(value=reference, rtol=0.25), "k": 7}],
        columns=[Column(key="n", header="evaluations"), Column(key="k", header="count")],
        caption="c",
        name="tab-t",
    )
    cell = nbformat.v4.new_code_cell(_CELL.replace("VALUE", repr(value)), execution_count=1)
    data = table._repr_mimebundle_()
    cell.outputs = [nbformat.v4.new_output("execute_result", data=data, execution_count=1)]
    nb = nbformat.v4.new_notebook(cells=[cell])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)


@pytest.mark.slow  # over 1 s: make test-slow runs it
@pytest.mark.notebooks
@pytest.mark.parametrize(
    ("value", "passes"), [(3000.0, True), (2000.0, False), pytest.param(2926.0 * 1.3, False, marks=pytest.mark.slow)]
)
def test_nbval_with_the_plugin_fails_beyond_the_tolerance_and_passes_within(pytester, value, passes):
    pytester.makeconftest(
        f"import sys\nsys.path.insert(0, {str(ROOT / 'tests')!r})\n"
        "def pytest_configure(config):\n    import nbval_numeric\n    nbval_numeric.install()\n"
    )
    (pytester.path / "sanitize.cfg").write_text((ROOT / "tests" / "nbval_sanitize.cfg").read_text("utf-8"), "utf-8")
    _notebook(pytester.path / "t.ipynb", 2926.0, value)
    result = pytester.runpytest_subprocess(
        "-p", "nbval", "--nbval", "--nbval-sanitize-with", "sanitize.cfg", "-p", "no:cacheprovider", "t.ipynb"
    )
    outcomes = result.parseoutcomes()
    if passes:
        assert outcomes.get("passed") == 1 and not outcomes.get("failed"), result.stdout.str()
    else:
        assert outcomes.get("failed") == 1, result.stdout.str()
        assert "outside the tolerance r0.25" in result.stdout.str()
