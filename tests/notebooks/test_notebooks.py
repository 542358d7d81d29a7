"""The chapters follow the report's skeleton, and their defaults are the paper's (from data/)."""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

import pytest

from vibration import paper_defaults
from vibration.book.publishing import report

NOTEBOOKS = sorted((Path(__file__).resolve().parents[2] / "notebooks").glob("*.ipynb"))
TYPES = {"float": float, "int": int, "str": str, "bool": bool, "list": list}


def _nb(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))


def _src(cell) -> str:
    return "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]


def _tags(cell) -> list[str]:
    return cell.get("metadata", {}).get("tags", [])


def test_there_are_chapters():
    assert len(NOTEBOOKS) >= 5, [p.name for p in NOTEBOOKS]


def _is_literal(value: ast.expr) -> bool:
    """A constant, or a signed numeric constant such as ``-0.1`` (papermill reads both as literals)."""
    if isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.USub | ast.UAdd):
        return isinstance(value.operand, ast.Constant) and isinstance(value.operand.value, int | float)
    if isinstance(value, ast.List):  # a list parameter: a list of literals
        return all(_is_literal(x) for x in value.elts)
    return isinstance(value, ast.Constant)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_exactly_one_literal_parameters_cell_with_types_and_units(path):
    cells = [c for c in _nb(path)["cells"] if "parameters" in _tags(c)]
    assert len(cells) == 1
    src = _src(cells[0])
    tree = ast.parse(src)
    lines = src.splitlines()
    for node in tree.body:
        assert isinstance(node, ast.AnnAssign), f"{path.name}: not an annotated assignment: {ast.unparse(node)}"
        assert _is_literal(node.value), f"{path.name}: {ast.unparse(node)} is not a literal"
        assert isinstance(node.annotation, ast.Name) and node.annotation.id in TYPES
        assert isinstance(ast.literal_eval(node.value), TYPES[node.annotation.id]), ast.unparse(node)
        line = lines[node.lineno - 1]
        assert "#" in line and "," in line.split("#", 1)[1], f"{path.name}: no 'meaning, unit' comment: {line}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_parameter_defaults_are_the_papers(path):
    cell = next(c for c in _nb(path)["cells"] if "parameters" in _tags(c))
    declared = {
        n.target.id: ast.literal_eval(n.value) for n in ast.parse(_src(cell)).body if isinstance(n, ast.AnnAssign)
    }
    defaults = paper_defaults()
    shared = set(declared) & set(defaults)
    if path.stem in report.chapter_schemas() and not shared:
        return  # a chapter package of its own (Part III measures hardware): its schema is checked in test_report
    assert shared, f"{path.name} declares none of the paper's parameters"
    for name in shared:
        assert declared[name] == defaults[name], f"{path.name}: {name} = {declared[name]} != {defaults[name]}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_skeleton_and_no_physics_in_notebooks(path):
    nb = _nb(path)
    cells = nb["cells"]
    assert nb["metadata"]["kernelspec"]["name"] == "vibration"
    assert cells[0]["cell_type"] == "markdown" and _src(cells[0]).startswith("# ")
    opening = _src(cells[0]) + _src(cells[1])
    assert "?" in opening, f"{path.name}: a chapter opens with its question"
    if not path.name.startswith("00_"):  # then the key-results box, before any table or figure
        # the key results: written in a markdown cell (numbers glued), or, in a chapter not yet rewritten, an output
        shown = next((i for i, c in enumerate(cells) for o in c.get("outputs", []) if "image/png" in o.get("data", {})
                      or "Table tab-" in "".join(o.get("data", {}).get("text/plain", ""))), len(cells))  # fmt: skip
        boxed = [
            i
            for i, c in enumerate(cells)
            for o in c.get("outputs", [])
            if "".join(o.get("data", {}).get("text/markdown", "")).lstrip().startswith("> **Key results**")
        ]
        written = [i for i, c in enumerate(cells) if _src(c).lstrip().startswith("**Key results.**")]
        first = min(boxed + written, default=None)  # fmt: skip
        assert first is not None, f"{path.name}: no key results"
        assert first < shown, f"{path.name}: the key results come before the first table or figure"
    if path.name.startswith("00_"):
        # the front page is the book's title page, not a chapter: its title, an overview, the run's headline
        # numbers (glued into its findings, and tables) instead of a summary section
        assert any(c["cell_type"] == "markdown" and "{glue:text}" in _src(c) for c in cells), "front page: no findings"
    else:
        assert any(c["cell_type"] == "markdown" and re.search(r"Summary|takes? away", _src(c)) for c in cells), (
            f"{path.name}: the chapter ends with what a designer takes away"
        )
    assert "__version__" in _src(cells[-1]), "the last cell prints the library versions"
    code = [c for c in cells if c["cell_type"] == "code"]
    for c in code:
        tree = ast.parse(_src(c))
        kinds = (
            ast.FunctionDef | ast.ClassDef if "show-input" in _tags(c) else ast.FunctionDef | ast.ClassDef | ast.Lambda
        )
        defs = [n for n in ast.walk(tree) if isinstance(n, kinds)]
        assert not defs, (
            f"{path.name}: define functions in src/vibration, not in notebooks (a lesson cell may pass a lambda)"
        )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_only_live_widget_cells_skip_nbval_and_outputs_are_committed(path):
    code = [c for c in _nb(path)["cells"] if c["cell_type"] == "code"]
    for c in code:
        if "nbval-ignore-output" in _tags(c):
            assert re.search(r"(explorer|panel)\(", _src(c)), (
                f"{path.name}: only slider cells may skip nbval: {_src(c)[:80]}"
            )
    assert all(c.get("execution_count") for c in code), f"{path.name}: re-execute it (make notebooks)"
    printed = [c for c in code if "show_table(" in _src(c) or "print(" in _src(c) or "_table(" in _src(c)]
    assert printed and all(c["outputs"] for c in printed), f"{path.name}: tables without outputs"
    for c in code:
        for out in c["outputs"]:
            assert out["output_type"] != "error", f"{path.name}: committed with an error"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_papermill_reads_every_parameter_with_its_help(path):
    import papermill

    inspected = papermill.inspect_notebook(str(path))
    cell = next(c for c in _nb(path)["cells"] if "parameters" in _tags(c))
    names = [n.target.id for n in ast.parse(_src(cell)).body]
    assert list(inspected) == names
    for name, info in inspected.items():
        assert info["help"], f"{path.name}: papermill could not read the comment of {name}"
        assert info["inferred_type_name"] in TYPES, f"{path.name}: {name} has no type papermill understands"


PART_ONE = [p for p in NOTEBOOKS if p.name[:2] in ("01", "02", "03", "04", "05")]
#: A number followed by a unit: a result, which must come from a presentation function, not from prose.
NUMBER_WITH_UNIT = re.compile(r"(?<![\w.])[-+]?\d+(\.\d+)?\s*(N s/m|N·s/m|rad/s|m/s|kg|N/m|Hz)\b")


@pytest.mark.parametrize("path", PART_ONE, ids=lambda p: p.stem)
def test_part_one_prose_states_no_results_outside_quotes(path):
    """Numbers with units in Part I's Markdown cells appear only inside quotations of the paper."""
    for cell in _nb(path)["cells"]:
        if cell["cell_type"] != "markdown":
            continue
        for line in _src(cell).splitlines():
            if line.lstrip().startswith(">"):
                continue
            assert not NUMBER_WITH_UNIT.search(line), f"{path.name}: a result written by hand: {line!r}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_figure_carries_its_caption_label_and_alt_text(path):
    """Every figure output is a Captioned figure (caption, fig- label, alt text in its metadata); no cell keeps
    a hand-written caption; every table is a Table object (tab- label)."""
    from vibration.book.presentation.captions import METADATA_KEY

    for cell in _nb(path)["cells"]:
        if cell["cell_type"] != "code":
            continue
        src = _src(cell)
        assert "figure" not in cell["metadata"].get("mystnb", {}), (path.name, "a hand-written caption", src[:60])
        for out in cell.get("outputs", []):
            if "image/png" in out.get("data", {}) and "text/html" not in out.get("data", {}):
                facts = out.get("metadata", {}).get(METADATA_KEY, {})
                assert facts.get("caption") and facts.get("alt") and facts.get("name", "").startswith("fig-"), (
                    path.name,
                    src[:60],
                )
        assert "show_table(" not in src and "print(format_table" not in src, (path.name, src[:60])
        for out in cell.get("outputs", []):
            plain = "".join(out.get("data", {}).get("text/plain", ""))
            assert "nan" not in re.findall(r"\bnan\b", plain), (path.name, plain[:80])


def _reader_texts(path: Path):
    """(where, text) of everything a reader of ``path`` sees as text: its Markdown cells, and its cells' Markdown
    and HTML outputs (scripts and style sheets left out) and figure captions and alt texts."""
    from vibration.book.presentation.captions import METADATA_KEY

    for i, cell in enumerate(_nb(path)["cells"]):
        if cell["cell_type"] == "markdown":
            yield f"cell {i} (Markdown)", _src(cell)
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            if "text/markdown" in data:
                yield f"cell {i} output (Markdown)", "".join(data["text/markdown"])
            if "text/html" in data:
                page = "".join(data["text/html"])
                yield f"cell {i} output (HTML)", re.sub(r"<(script|style)\b.*?</\1>", " ", page, flags=re.S)
            facts = out.get("metadata", {}).get(METADATA_KEY, {})
            for key in ("caption", "alt"):
                if facts.get(key):
                    yield f"cell {i} figure {key}", facts[key]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_count_the_reader_sees_is_grouped(path):
    """No run of five or more plain digits in the text, tables, captions or panels of a chapter as built (counts
    are grouped in threes by a narrow no-break space); maths, code and attribute values are left out."""
    from prose import ungrouped_counts

    found = [(where, n) for where, text in _reader_texts(path) for n in ungrouped_counts(text)]
    assert found == [], (path.name, found)
