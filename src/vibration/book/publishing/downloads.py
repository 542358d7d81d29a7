"""What the book offers for download beside each chapter: its executed notebook and the package's wheel."""

from __future__ import annotations

import os
import shutil
import sys
import tempfile
from pathlib import Path

from ...physics.model import ParameterError
from .registry import project_root

__all__ = ["build_wheel", "download_cell", "drop_print_figures", "wheel_name", "write_downloads"]


def wheel_name() -> str:
    """The file name of the package's wheel as the book offers it."""
    from importlib.metadata import version

    return f"vibration-{version('vibration')}-py3-none-any.whl"


def download_cell(stem: str):
    """The Markdown cell under a chapter's title: its notebook and the package, as downloads of the book."""
    import nbformat

    return nbformat.v4.new_markdown_cell(
        f'<p class="vib-downloads">Download <a href="_static/downloads/{stem}.ipynb" download>this chapter\'s '
        f'notebook</a> (with its outputs) and <a href="_static/downloads/{wheel_name()}" download>the package</a> '
        '(see "Using the package").</p>'
    )


def _source_tree() -> Path:
    """The package's source (the folder of its ``pyproject.toml``), wherever the notebooks are."""

    here = Path(__file__).resolve()
    for candidate in (*here.parents, project_root()):
        if (candidate / "pyproject.toml").is_file() and (candidate / "src" / "vibration").is_dir():
            return candidate
    raise ParameterError(
        "the package's source (pyproject.toml beside src/vibration) was not found, so its wheel cannot be offered "
        "for download: run the book from a source checkout, or set $VIBRATION_ROOT to one"
    )


def build_wheel(folder: Path) -> Path:
    """The package's wheel, built into ``folder`` from a copy of its sources; returns its path.

    A copy, so setuptools' scratch folders (``build/lib``, which would keep deleted modules) stay out of the
    project; the same sources give the same bytes (zip times from ``SOURCE_DATE_EPOCH``), so an unchanged
    package leaves the book's downloads, and so the book, unchanged.
    """
    import subprocess

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="vibration-wheel-") as tmp:
        tree = _source_tree()
        copy = Path(tmp) / "src-copy"
        copy.mkdir()
        for name in ("pyproject.toml", "README.md", "LICENSE", "LICENSE-text"):
            if (tree / name).is_file():
                shutil.copy2(tree / name, copy / name)
        shutil.copytree(tree / "src", copy / "src", ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
        cmd = [sys.executable, "-m", "pip", "wheel", str(copy), "--no-deps", "--no-build-isolation", "-q"]
        env = {**os.environ, "SOURCE_DATE_EPOCH": os.environ.get("SOURCE_DATE_EPOCH", "315532800")}
        done = subprocess.run([*cmd, "-w", str(folder)], capture_output=True, text=True, timeout=300, env=env)
    wheel = folder / wheel_name()
    if done.returncode != 0 or not wheel.exists():
        raise RuntimeError(f"the package's wheel was not built: {done.stderr.strip()[-400:]}")
    return wheel


def drop_print_figures(nb) -> None:
    """The SVG copy of each figure that also carries a PNG (the print edition's, see
    :data:`vibration.book.presentation.captions.FORMATS_ENV`) removed from ``nb``: a download shows the PNG.

    >>> import nbformat
    >>> out = nbformat.v4.new_output("display_data", {"image/png": "AA==", "image/svg+xml": "<svg/>"},
    ...                              metadata={"image/svg+xml": {"width": 672}})
    >>> nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("f", outputs=[out])])
    >>> drop_print_figures(nb); sorted(out.data), dict(out.metadata)
    (['image/png'], {})
    """
    for cell in nb.cells:
        for out in cell.get("outputs", []) if cell.cell_type == "code" else []:
            data = out.get("data", {})
            if "image/png" in data and data.pop("image/svg+xml", None) is not None:
                out.get("metadata", {}).pop("image/svg+xml", None)


def write_downloads(pages, folder: Path) -> list[Path]:
    """Each chapter's executed notebook and the package's wheel in ``folder`` (copied into the book)."""

    import nbformat

    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for p in pages:
        nb = nbformat.from_dict(p.notebook)
        nb.metadata.pop("papermill", None)
        drop_print_figures(nb)
        path = folder / f"{p.name}.ipynb"
        nbformat.write(nb, path)
        written.append(path)
    wheel = folder / wheel_name()
    if not wheel.exists():
        build_wheel(folder)
    written.append(wheel)
    return written
