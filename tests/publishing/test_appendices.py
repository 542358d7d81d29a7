"""The generated appendices: every usage example runs on its own, the table of symbols covers every parameter."""

import re
import subprocess
import sys
from importlib.resources import files

import pytest

from vibration.book.publishing.appendices import symbols_markdown, usage_markdown
from vibration.book.publishing.registry import chapter_packages, chapter_schemas

USAGE = [
    (pkg, files(f"vibration.book.chapters.{pkg}").joinpath("usage.md"))
    for pkg in chapter_packages().values()
    if files(f"vibration.book.chapters.{pkg}").joinpath("usage.md").is_file()
]


@pytest.mark.slow
@pytest.mark.parametrize("pkg, path", USAGE, ids=[u[0] for u in USAGE])
def test_each_usage_example_runs_in_a_fresh_interpreter(pkg, path):
    blocks = re.findall(r"```python\n(.*?)```", path.read_text(encoding="utf-8"), re.S)
    assert len(blocks) >= 1, f"{pkg}/usage.md has no python block"
    for code in blocks:
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=240)
        assert done.returncode == 0, f"{pkg}: {done.stderr[-1500:]}"
        assert done.stdout.strip(), f"{pkg}: the example prints nothing"


def test_the_appendix_gathers_every_usage_example():
    text = usage_markdown(list(chapter_packages().values()))
    assert text.count("```python") == sum(p.read_text(encoding="utf-8").count("```python") for _, p in USAGE)


def test_the_table_of_symbols_lists_every_parameter_once():
    schemas = chapter_schemas()
    text = symbols_markdown(schemas)
    for schema in schemas.values():
        for p in schema.params:
            assert f"`-p {p.name}`" in text, p.name
    rows = re.findall(r"^  - `-p (\w+)`$", text, re.M)
    assert len(rows) == len({(p.symbol, p.name, p.unit) for s in schemas.values() for p in s.params})
    assert not re.search(r"\d[eE][+-]?\d", text), "ranges in the book's number format"
