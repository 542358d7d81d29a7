"""Chapter 11 as a package: its parameters, the notebook's parameters cell, bad input, the usage example, and the
whole chapter under other parameters from the schema's ranges."""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from pathlib import Path

import pytest

import vibration
from vibration.book.chapters.learning import SCHEMA, LearningStudy, Params, learning_study
from vibration.book.chapters.learning.study import ACTIVE, SEMI

ROOT = Path(__file__).resolve().parents[3]
NOTEBOOK = ROOT / "notebooks" / "11_learning.ipynb"
USAGE = ROOT / "src" / "vibration" / "book" / "chapters" / "learning" / "usage.md"


def test_parameters_cell_equals_schema():
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    cells = [c for c in nb["cells"] if "parameters" in c.get("metadata", {}).get("tags", [])]
    assert len(cells) == 1
    src = "".join(cells[0]["source"])
    values = {}
    for node in ast.parse(src).body:
        assert isinstance(node, ast.AnnAssign), ast.dump(node)
        values[node.target.id] = ast.literal_eval(node.value)
        assert type(values[node.target.id]).__name__ == node.annotation.id
    assert list(values) == list(SCHEMA.names())
    assert values == SCHEMA.defaults()
    assert Params() == Params(**SCHEMA.defaults())


def test_notebook_cells_are_one_call_each():
    """Nothing is computed in the notebook: after the imports, every code cell is one call (or the versions)."""
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    code = [c for c in nb["cells"] if c["cell_type"] == "code"]
    for cell in code[2:-1]:
        tree = ast.parse("".join(cell["source"]))
        assert len(tree.body) == 1 and isinstance(tree.body[0], ast.Expr), "".join(cell["source"])
        assert isinstance(tree.body[0].value, ast.Call)
        assert "mystnb" not in cell["metadata"], "captions come from the figure functions"
    text = json.dumps(nb)
    assert "presentation.learning" not in text and "Using it" not in text


@pytest.mark.parametrize(
    ("values", "name"),
    [
        ({"c_semi_min": 20.0}, "c_semi_min"),
        ({"n_seeds": 5}, "n_seeds"),
        ({"dt": 0.0}, "dt"),
        ({"u_max": float("nan")}, "u_max"),
        ({"bogus": 1}, "bogus"),
    ],
)
def test_bad_parameters_are_refused(values, name):
    with pytest.raises(vibration.ParameterError, match=name):
        Params.from_values(values)


def test_a_negative_plant_damping_is_refused_by_name():
    with pytest.raises(vibration.ParameterError, match="c_nominal"):
        learning_study(c_nominal=-0.1)


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_usage_example_runs_on_its_own(tmp_path):
    md = USAGE.read_text(encoding="utf-8")
    assert md.startswith("# Chapter 11, ")
    blocks = md.split("```python\n")
    assert len(blocks) == 2
    code = blocks[1].split("```")[0]
    out = subprocess.run(
        [sys.executable, "-I", "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=300, check=True
    )
    assert "learned cost / optimal cost = 1.0000" in out.stdout


@pytest.mark.slow
@pytest.mark.parametrize(
    "values",
    [
        # a heavier, stiffer plant under a larger force at its own resonance: the force bound binds for LQR
        {"m": 4.0, "k": 400.0, "F0": 40.0, "omega_res": 10.0, "n_eval": 200},
        # a softer, lightly damped plant with a weaker damper and a smaller force
        {"k": 5.0, "c_nominal": 0.1, "F0": 2.0, "omega_res": 2.2, "c_semi_max": 5.0, "n_eval": 200, "seed": 3},
    ],
)
def test_the_chapter_under_other_parameters(values):
    from test_learning_presentation import check_caption_words, check_consistency, check_outputs

    st = learning_study(**values)
    assert isinstance(st, LearningStudy) and st.params == Params.from_values(values)
    assert st.active.names == ACTIVE and st.semi.names == SEMI
    assert st.task.k == values["k"] and st.res_task.F0 == values["F0"]
    check_outputs(st)
    check_caption_words(st)
    check_consistency(st)
