"""The report's chapter cache: what a chapter depends on, and a rerun that executes only what changed."""

from __future__ import annotations

import json
from pathlib import Path

import grimp
import nbformat
import pytest

from vibration.book.publishing import report
from vibration.book.publishing.cache import ChapterCache, differences, import_closure, manifest, notebook_imports
from vibration.book.publishing.registry import add_chapter

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def graph():
    return grimp.build_graph("vibration", cache_dir=None)


def _notebook(path: Path, code: str, param: str = "a: float = 1.0  # a number, 1") -> Path:
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    cell = nbformat.v4.new_code_cell(param)
    cell.metadata["tags"] = ["parameters"]
    nb.cells = [cell, nbformat.v4.new_code_cell(code)]
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)
    return path


def test_imports_are_read_from_the_code_cells(tmp_path):
    nb = _notebook(
        tmp_path / "n.ipynb",
        "import numpy\nimport vibration\nfrom vibration.book.presentation import tables\n"
        "from vibration.physics.exact import x",
    )
    assert notebook_imports(nb) == {
        "vibration",
        "vibration.book.presentation",
        "vibration.book.presentation.tables",
        "vibration.physics.exact",
        "vibration.physics.exact.x",
    }


def test_the_closure_holds_what_a_module_imports_and_nothing_else(graph):
    closure = import_closure({"vibration.book.chapters.solver_accuracy.tables"}, graph)
    assert {
        "vibration.book.chapters.solver_accuracy.tables",
        "vibration.book.chapters.solver_accuracy.study",
        "vibration.book.presentation.tables",
        "vibration.physics.exact",
    } <= closure
    assert {
        "vibration.book.chapters.solver_accuracy",
        "vibration.book.chapters",
        "vibration",
    } <= closure  # __init__ files run first
    assert (
        "vibration.book.chapters.tmd.study" not in closure
        and "vibration.book.chapters.real_oscillator.study" not in closure
    )
    # the package's __init__ imports the whole physics library, so `import vibration` brings all of it
    assert "vibration.physics.tmd" in import_closure({"vibration"}, graph)


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_the_manifest_names_each_input_and_changes_with_it(tmp_path, graph):
    nb = _notebook(
        tmp_path / "notebooks" / "01_x.ipynb",
        "from vibration.book.presentation.tables import fmt\n"
        "from vibration.book.chapters.real_oscillator.panel import decay_panel",
    )
    first = manifest(nb, {"a": 2.0}, ROOT, graph=graph)
    assert "src/vibration/book/presentation/tables.py" in first and "src/vibration/physics/model.py" in first
    assert "src/vibration/book/chapters/tmd/study.py" not in first
    assert "src/vibration/book/chapters/real_oscillator/panel/real_oscillator.js" in first  # files beside the modules
    assert any(k.startswith("data/") for k in first)
    assert differences(first, manifest(nb, {"a": 2.0}, ROOT, graph=graph)) == []
    assert differences(first, manifest(nb, {"a": 3.0}, ROOT, graph=graph)) == ["parameters changed"]
    nb.write_text(nb.read_text().replace("fmt", "fmt, DASH"))
    assert differences(first, manifest(nb, {"a": 2.0}, ROOT, graph=graph)) == ["notebook changed"]


def test_a_half_written_entry_is_never_a_hit(tmp_path):
    cache = ChapterCache(tmp_path / "cache")
    (tmp_path / "cache").mkdir()
    (tmp_path / "cache" / "01_x.ipynb").write_text("{}")
    assert not cache.lookup("01_x", {"a": "1"}).hit
    (tmp_path / "cache" / "01_x.json").write_text("{not json")
    assert cache.lookup("01_x", {"a": "1"}).reasons == ("the cached run's record is unreadable",)


@pytest.mark.slow
@pytest.mark.notebooks
def test_a_second_run_reuses_unchanged_chapters_and_says_why_others_run(tmp_path):
    root = tmp_path / "project"
    code = "from vibration.book.presentation.tables import fmt\nprint(fmt(a * 2))"
    a = report.Chapter(path=_notebook(root / "notebooks" / "01_a.ipynb", code), params={})
    b = report.Chapter(path=_notebook(root / "notebooks" / "02_b.ipynb", code.replace("2)", "3)")), params={})
    add_chapter("01_a", root, 1), add_chapter("02_b", root, 1)  # the project's table of contents: one part
    chapters = report.discover(root)
    assert [c.name for c in chapters] == [a.name, b.name]
    out = tmp_path / "out"
    logs: list[str] = []
    report.run(chapters, {}, out, jobs=2, log=logs.append, pdf=False)
    assert sum(line.startswith("[start]") for line in logs) == 2
    logs.clear()
    report.run(chapters, {"a": 5.0}, out, jobs=2, log=logs.append, pdf=False)
    assert sorted(line for line in logs if line.startswith(("[start]", "[cached]"))) == [
        "[start] 01_a: parameters changed",
        "[start] 02_b: parameters changed",
    ]
    logs.clear()
    b.path.write_text(b.path.read_text().replace("a * 3", "a * 4"))
    report.run(chapters, {"a": 5.0}, out, jobs=2, log=logs.append, pdf=False)
    assert sorted(line for line in logs if line.startswith(("[start]", "[cached]"))) == [
        "[cached] 01_a: nothing it depends on changed",
        "[start] 02_b: notebook changed",
    ]
    executed = json.loads((out / "notebooks" / "01_a.ipynb").read_text())
    assert "".join(executed["cells"][-1]["outputs"][0]["text"]).strip() == "10"  # the cached run of a = 5


@pytest.mark.slow
@pytest.mark.notebooks
def test_nothing_changed_only_checks_and_one_edit_rebuilds_only_its_pages(tmp_path):
    """With nothing changed the runner builds nothing; one edited chapter runs alone and Sphinx reads its page again,
    not the others' (its environment is kept in the output folder), and the tree is still swapped whole."""
    root = tmp_path / "project"
    code = "from vibration.book.presentation.tables import fmt\nprint(fmt(a * 2))"
    _notebook(root / "notebooks" / "01_a.ipynb", code)
    b = _notebook(root / "notebooks" / "02_b.ipynb", code.replace("2)", "3)"))
    add_chapter("01_a", root, 1), add_chapter("02_b", root, 1)
    chapters = report.discover(root)
    out = tmp_path / "out"
    logs: list[str] = []
    report.run(chapters, {}, out, jobs=2, log=logs.append, pdf=False)
    index = out / "report" / "index.html"
    first = index.stat().st_mtime_ns
    logs.clear()
    report.run(chapters, {}, out, jobs=2, log=logs.append, pdf=False)
    assert not any(line.startswith(("[start]", "book:")) for line in logs), logs
    assert any(line.startswith("report: nothing changed (2 chapters and the book as built)") for line in logs), logs
    assert index.stat().st_mtime_ns == first  # the tree was not touched
    b.write_text(b.read_text().replace("a * 3", "a * 4"))
    logs.clear()
    report.run(chapters, {}, out, jobs=2, log=logs.append, pdf=False)
    assert [line for line in logs if line.startswith("[start]")] == ["[start] 02_b: notebook changed"]
    assert any(line.startswith("book:") and "1 page changed (02_b.ipynb)" in line for line in logs), logs
    sphinx_log = (out / "book-state" / "book-src" / "sphinx-html.log").read_text()
    assert "0 added, 1 changed, 0 removed" in sphinx_log  # Sphinx read the one changed page again, no other
    executed = json.loads((out / "notebooks" / "02_b.ipynb").read_text())
    assert "".join(executed["cells"][-1]["outputs"][0]["text"]).strip() == "4"
    assert (out / "report" / "01_a.html").is_file() and not list(out.glob(".report-*"))


def test_the_lab_folder_of_chapter_12_enters_its_manifest(tmp_path, graph):
    nb = _notebook(
        tmp_path / "notebooks" / "12_real_oscillator.ipynb",
        "from vibration.book.presentation.tables import fmt",
        'lab_data: str = "data/lab_oscillator"  # folder, path',
    )
    lab = tmp_path / "lab"
    lab.mkdir()
    (lab / "runs.csv").write_text("file,kind,brake,brake_current_A,session,run\na.csv,free,off,,1,\n")
    (lab / "a.csv").write_text("Zeit t / s;Weg &b_A1 / rad\n0;1\n")
    params = {"lab_data": str(lab)}
    first = manifest(nb, params, ROOT, graph=graph)
    assert first["parameter lab_data/a.csv"] != first["parameter lab_data/runs.csv"]
    assert differences(first, manifest(nb, params, ROOT, graph=graph)) == []
    (lab / "a.csv").write_text("Zeit t / s;Weg &b_A1 / rad\n0;2\n")
    assert differences(first, manifest(nb, params, ROOT, graph=graph)) == ["parameter lab_data/a.csv changed"]
    (lab / "b.csv").write_text("x")
    assert "parameter lab_data/b.csv is new" in differences(first, manifest(nb, params, ROOT, graph=graph))
    # the default folder is the project's copy of the lab data, hashed under the parameter's name too
    default = manifest(nb, {}, ROOT, graph=graph)
    assert "parameter lab_data/runs.csv" in default and default["parameter lab_data"] == "folder"
    # another chapter's notebook has no path parameter
    other = _notebook(tmp_path / "notebooks" / "01_x.ipynb", "from vibration.book.presentation.tables import fmt")
    assert not any(k.startswith("parameter ") for k in manifest(other, {"a": 1.0}, ROOT, graph=graph))
