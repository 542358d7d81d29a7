"""A new chapter from a template: one package, one notebook, one test file.

``python -m vibration.report --new-chapter 13_topic`` writes

* ``src/vibration/book/chapters/topic/`` with ``params.py`` (the parameter schema), ``study.py`` (pure
  computation, a frozen record), ``tables.py`` (a table from the record);
* ``notebooks/13_topic.ipynb`` (title, question, parameters cell matching the schema, the prose in markdown
  cells with the numbers glued from the code cells, one call per table, versions);
* ``tests/chapters/topic/test_topic.py`` (the study against an independent closed form, the notebook's
  parameters against the schema).

The template's physics is a placeholder a chapter author replaces: the resonant peak of the
linear magnification, found on a grid and compared with its closed form. The runner finds the
chapter by its schema, range-checks its ``-p`` values and builds it into the book; the chapter joins
the part of the table of contents (``notebooks/contents.toml``) its author names, at its end.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

from ...physics.model import ParameterError
from .cli import SUBCOMMANDS
from .registry import add_chapter

_STEM = re.compile(r"(?P<number>[0-9]{2})_(?P<topic>[a-z][a-z0-9_]{1,40})")

_INIT = '''"""{title}: {question}"""

from vibration.book.chapters.{topic}.params import SCHEMA, Params
from vibration.book.chapters.{topic}.study import {record}, {topic}_study

__all__ = ["SCHEMA", "Params", "{record}", "{topic}_study"]
'''

_PARAMS = '''"""The chapter's parameters, declared once: the runner, the notebook and the study read them here."""

from __future__ import annotations

from vibration.book.presentation.schema import Param, Schema

SCHEMA = Schema(
    notebook="{stem}",
    params=(
        Param(name="{prefix}zeta", symbol="ζ", default=0.05, unit="", low=0.001, high=0.7, meaning="damping ratio"),
        Param(
            name="{prefix}n_grid",
            symbol="n",
            default=2001,
            unit="",
            low=101,
            high=100_001,
            meaning="frequency ratios on the grid",
        ),
    ),
)


Params = SCHEMA.record_type(module=__name__)
'''

_STUDY = '''"""The chapter's computation: pure functions returning one frozen record."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.{topic}.params import Params


@dataclass(frozen=True, kw_only=True)
class {record}:
    """What the chapter shows."""

    zeta: float  # damping ratio, 1
    r_peak: float  # frequency ratio of the largest magnification on the grid, 1
    peak: float  # largest magnification on the grid, 1
    peak_exact: float  # closed form 1 / (2 zeta sqrt(1 - zeta^2)), 1


def {topic}_study(params: Params | None = None, **values) -> {record}:
    """The resonant peak of the linear magnification on a grid, beside its closed form."""
    p = params or Params.from_values(values)
    r = np.linspace(0.0, 2.0, p.{prefix}n_grid)
    magnification = 1.0 / np.sqrt((1.0 - r**2) ** 2 + (2.0 * p.{prefix}zeta * r) ** 2)
    i = int(np.argmax(magnification))
    exact = 1.0 / (2.0 * p.{prefix}zeta * math.sqrt(1.0 - p.{prefix}zeta**2)) if p.{prefix}zeta < 2**-0.5 else 1.0
    return {record}(zeta=p.{prefix}zeta, r_peak=float(r[i]), peak=float(magnification[i]), peak_exact=exact)
'''

_TABLES = '''"""The chapter's tables, functions of the study's record (the prose is in the notebook)."""

from __future__ import annotations

from vibration.book.chapters.{topic}.study import {record}
from vibration.book.presentation.tables import Column, Table


def peak_table(st: {record}) -> Table:
    """The grid's peak beside the closed form."""
    rows = [{{"what": "grid", "peak": st.peak}}, {{"what": "closed form", "peak": st.peak_exact}}]
    columns = [Column(key="what", header="method"), Column(key="peak", header="largest X/X_st", digits=4)]
    return Table(rows=rows, columns=columns, caption="The resonant peak.", name="tab-{topic}")
'''

_TEST = '''"""Chapter {stem}: the study against its closed form, the notebook against the schema."""

import json
import re
from pathlib import Path

import pytest

from vibration.book.chapters.{topic} import SCHEMA, {topic}_study
from vibration.book.chapters.{topic}.tables import peak_table


@pytest.mark.parametrize("zeta", [0.01, 0.05, 0.3])
def test_the_grid_peak_meets_the_closed_form(zeta):
    st = {topic}_study({prefix}zeta=zeta, {prefix}n_grid=100_001)
    assert st.peak == pytest.approx(st.peak_exact, rel=1e-3)
    assert not re.search(r"\\bnan\\b", repr(peak_table(st)))


def test_the_notebook_declares_the_schema():
    path = Path(__file__).resolve().parents[3] / "notebooks" / "{stem}.ipynb"
    nb = json.loads(path.read_text(encoding="utf-8"))
    cell = next(c for c in nb["cells"] if "parameters" in c["metadata"].get("tags", []))
    declared = {{line.split(":")[0] for line in "".join(cell["source"]).splitlines()}}
    assert declared == {{p.name for p in SCHEMA.params}}
'''


def _notebook(stem: str, title: str, question: str, topic: str, prefix: str) -> dict:
    def code(source, tags=()):
        return {
            "cell_type": "code",
            "execution_count": None,
            "id": f"c{len(cells)}",
            "metadata": {"tags": list(tags)} if tags else {},
            "outputs": [],
            "source": source,
        }

    def md(source):
        return {"cell_type": "markdown", "id": f"c{len(cells)}", "metadata": {}, "source": source}

    cells: list[dict] = []
    cells.append(md(f"# {title}\n\n**Question.** {question}"))
    cells.append(
        code(
            f"{prefix}zeta: float = 0.05  # damping ratio, 1\n{prefix}n_grid: int = 2001  # frequency ratios, 1",
            tags=("parameters",),
        )
    )
    cells.append(
        code(
            f"from vibration.book.chapters.{topic} import Params, {topic}_study\n"
            f"from vibration.book.chapters.{topic}.tables import peak_table\n"
            "from vibration.book.presentation.glued import number\n\n"
            "params = Params.from_namespace(globals())  # every value checked against its allowed range\n"
            f"study = {topic}_study(params)",
            tags=("remove-cell",),
        )
    )
    cells.append(
        code(
            'number("zeta", study.zeta), number("peak", study.peak), number("peak_exact", study.peak_exact)\n'
            'number("gap_pct", 100 * abs(study.peak / study.peak_exact - 1), 2)\n'
            'print(f"grid peak {study.peak:.4g}, closed form {study.peak_exact:.4g}")'
        )
    )
    cells.append(
        md(
            "**Key results.** At ζ = {glue:text}`zeta` the grid finds a peak magnification of {glue:text}`peak`, "
            "{glue:text}`gap_pct` % from the closed form {glue:text}`peak_exact`."
        )
    )
    cells.append(
        md("## The peak\n\nThe magnification peaks near the natural frequency; its height falls as the damping grows.")
    )
    cells.append(code("peak_table(study)"))
    cells.append(
        md(
            "## Summary: what a designer takes away\n\n"
            "- Replace the template's model, study and words with the chapter's."
        )
    )
    # the versions the notebook ran with: shown in JupyterLab; the book lists its build's in an appendix
    cells.append(
        code(
            "import platform\n\nimport vibration\n\n"
            'print(f"python {platform.python_version()}, vibration {vibration.__version__}")',
            tags=("remove-cell",),
        )
    )
    return {
        "cells": cells,
        "metadata": {
            "kernelspec": {"display_name": "Python 3 (vibration)", "language": "python", "name": "vibration"},
            "language_info": {"name": "python"},
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }


def new_chapter(
    stem: str, root: Path, *, part: int = 2, package_dir: Path | None = None, prefix: str = ""
) -> list[Path]:
    """Write a chapter from the template; returns the files written (none is overwritten).

    Parameters
    ----------
    stem : str
        ``NN_topic``: the chapter number (two digits) and a lower-case topic name, e.g. ``13_damping_map``.
    root : Path
        The project folder (``notebooks/`` and ``tests/`` are written there).
    part : int
        The part of the table of contents (``notebooks/contents.toml``, 1-based) the chapter joins, at its
        end; a project without a table of contents gets one whose only part holds the chapter.
    package_dir : Path, optional
        Where the chapter package goes (default ``src/vibration/book/chapters`` under ``root``).
    prefix : str
        Prefix of the template's parameter names (a throw-away chapter keeps clear of other chapters' names).
    """
    m = _STEM.fullmatch(stem)
    if not m:
        raise ParameterError(f"stem = {stem!r} is not a chapter name: allowed NN_topic, e.g. 13_damping_map")
    topic = m["topic"]

    if topic in SUBCOMMANDS:  # "python -m vibration.report sweep" must stay the subcommand
        raise ParameterError(
            f"topic = {topic!r} is the runner's subcommand: allowed a topic other than {', '.join(SUBCOMMANDS)}"
        )
    root = Path(root)
    package = Path(package_dir or root / "src" / "vibration" / "book" / "chapters") / topic
    title = topic.replace("_", " ").capitalize()
    question = "What does this chapter ask? (Replace the template's question, model and study.)"
    record = "".join(w.capitalize() for w in topic.split("_")) + "Study"
    fill = {"stem": stem, "topic": topic, "title": title, "question": question, "record": record, "prefix": prefix}
    files = {
        package / "__init__.py": _INIT.format(**fill),
        package / "params.py": _PARAMS.format(**fill),
        package / "study.py": _STUDY.format(**fill),
        package / "tables.py": _TABLES.format(**fill),
        root / "notebooks" / f"{stem}.ipynb": json.dumps(_notebook(stem, title, question, topic, prefix), indent=1)
        + "\n",
        root / "tests" / "chapters" / topic / f"test_{topic}.py": _TEST.format(**fill),
    }
    existing = [p for p in files if p.exists()]
    if existing:
        raise ParameterError(f"stem = {stem!r}: {existing[0]} exists already: allowed a chapter that does not exist")
    add_chapter(stem, root, part)  # refuses a part that does not exist before anything is written
    for path, text in files.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return list(files)
