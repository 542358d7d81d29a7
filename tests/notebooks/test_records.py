"""Each notebook builds its parameter record in one call and uses its parameters only through it; each chapter
with a panel offers it through one entry point, ``panel(study)``."""

from __future__ import annotations

import ast
import importlib
import inspect
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
PANEL_CHAPTERS = ["explore", "stability", "control", "tmd", "duffing", "digital_twin", "real_oscillator"]


def _code_cells(path: Path) -> list[tuple[list[str], ast.Module]]:
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return [(c["metadata"].get("tags", []), ast.parse("".join(c["source"]))) for c in cells if c["cell_type"] == "code"]


def _parameter_names(tree: ast.Module) -> set[str]:
    return {node.target.id for node in tree.body if isinstance(node, ast.AnnAssign)}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_the_record_is_built_in_one_call_and_the_parameters_are_read_through_it(path):
    cells = _code_cells(path)
    (start,) = [i for i, (tags, _) in enumerate(cells) if "parameters" in tags]
    names = _parameter_names(cells[start][1])
    assert names, f"{path.name}: its parameters cell declares no annotated parameter"
    calls = [
        node
        for _, tree in cells[start + 1 :]
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "from_namespace"
    ]
    assert len(calls) == 1, f"{path.name}: the record is not built by one from_namespace call"
    raw = sorted(
        {
            (i, node.id)
            for i, (_, tree) in enumerate(cells[start + 1 :], start + 1)
            for node in ast.walk(tree)
            if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and node.id in names
        }
    )
    assert raw == [], f"{path.name}: parameters read as bare globals, not through the record: {raw}"


def test_the_check_sees_a_bare_parameter(tmp_path):
    """The scan above finds a parameter read as a global (what chapter 8's notebook once did with ``mu``)."""
    nb = {
        "cells": [
            {"cell_type": "code", "metadata": {"tags": ["parameters"]}, "source": "mu: float = 0.05  # ratio, 1"},
            {"cell_type": "code", "metadata": {}, "source": "params = Params.from_namespace(globals())"},
            {"cell_type": "code", "metadata": {}, "source": "tmd_explorer(mu)"},
        ]
    }
    path = tmp_path / "99_x.ipynb"
    path.write_text(json.dumps(nb), encoding="utf-8")
    with pytest.raises(AssertionError, match=r"\(2, 'mu'\)"):
        test_the_record_is_built_in_one_call_and_the_parameters_are_read_through_it(path)


@pytest.mark.parametrize("chapter", PANEL_CHAPTERS)
def test_each_chapter_panel_has_one_entry_point_taking_its_study(chapter):
    module = importlib.import_module(f"vibration.book.chapters.{chapter}.panel")
    assert list(inspect.signature(module.panel).parameters) == ["study"]
    (path,) = [p for p in NOTEBOOKS if f"vibration.book.chapters.{chapter}" in p.read_text(encoding="utf-8")]
    called = [
        ast.unparse(node)
        for _, tree in _code_cells(path)
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "panel"
    ]
    assert called == ["panel(study)"], f"{path.name} calls {called}"


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_the_tmd_panel_starts_where_the_study_is():
    from vibration.book.chapters.tmd.panel import panel
    from vibration.book.chapters.tmd.study import tmd_study
    from vibration.physics.tmd import hinf_tuning

    study = tmd_study(mu=0.1)
    explorer = panel(study)
    assert explorer.mu_slider.value == pytest.approx(0.1)
    assert explorer.f_slider.value == pytest.approx(hinf_tuning(0.1).f)
