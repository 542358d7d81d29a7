"""A content-hash cache of executed chapters: a chapter runs again only when something it depends on changed.

A chapter depends on its notebook, the parameter values it is run with, the package modules it
imports (its import closure, read from the source by grimp, the graph library behind import-linter,
so a lazy import inside a function counts too), the non-Python files beside those modules (panel
scripts and styles), the project's ``data/`` folder and the environment (Python, the pinned
packages), and every folder a path parameter names (chapter 12's ``lab_data``: each file in it, so
changing a file of another laboratory's folder runs the chapter again). Each of those is hashed
(SHA-256) into a manifest; a cached run is reused when its manifest is the same, and otherwise the
differences say why the chapter runs again.

Why not jupyter-cache: it keys a notebook on its code cells only, not on the package the cells
call, so a change in ``src/`` would not re-run the chapter that uses it; and it stores its own
executed copy, while the book needs papermill's (with the injected parameters). The cache here is
a folder of plain files (``<chapter>.json``, ``<chapter>.ipynb``, ``<chapter>-tables/``).
"""

from __future__ import annotations

import ast
import hashlib
import json
import shutil
import sys
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path

from .registry import chapter_schemas

#: Bump when the manifest's meaning changes, so older entries are not reused.
VERSION = 1
#: Packages whose versions enter every manifest (the rest follow from environment.txt).
PACKAGES = ("numpy", "scipy", "matplotlib", "numba", "papermill", "nbclient", "ipykernel")


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def notebook_imports(notebook: Path, package: str = "vibration") -> set[str]:
    """The ``package`` modules the notebook's code cells import (``import x``, ``from x import y``)."""
    nb = json.loads(notebook.read_text(encoding="utf-8"))
    found: set[str] = set()
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "code":
            continue
        source = "".join(cell.get("source", []))
        try:
            tree = ast.parse(source)
        except SyntaxError:
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                found |= {a.name for a in node.names if a.name.split(".")[0] == package}
            elif isinstance(node, ast.ImportFrom) and node.module and node.module.split(".")[0] == package:
                found.add(node.module)
                found |= {f"{node.module}.{a.name}" for a in node.names}  # submodules imported by name
    return found


def import_closure(modules: set[str], graph) -> set[str]:
    """The modules, their parent packages (whose ``__init__`` runs first) and everything those import."""
    start = set()
    for name in modules:
        parts = name.split(".")
        start |= {".".join(parts[:i]) for i in range(1, len(parts) + 1)}
    start = {m for m in start if m in graph.modules}
    closure = set(start)
    for m in start:
        closure |= graph.find_upstream_modules(m)
    parents = set()  # importing a module runs its parents' __init__ first
    for name in closure:
        parts = name.split(".")
        parents |= {".".join(parts[:i]) for i in range(1, len(parts))}
    return closure | {m for m in parents if m in graph.modules}


def manifest(notebook: Path, params: dict, root: Path, *, graph) -> dict[str, str]:
    """What the chapter's executed notebook depends on: a label (a path or a name) -> its SHA-256."""
    import vibration

    src = Path(vibration.__file__).resolve().parent.parent  # the folder that holds the package
    out = {
        "cache version": str(VERSION),
        "notebook": _sha(notebook.read_bytes()),
        "parameters": _sha(json.dumps(params, sort_keys=True, default=repr).encode()),
        "python": sys.version,
    }
    for pkg in PACKAGES:
        try:
            out[f"package {pkg}"] = metadata.version(pkg)
        except metadata.PackageNotFoundError:
            out[f"package {pkg}"] = "absent"
    env = root / "environment.txt"
    if env.is_file():
        out["environment.txt"] = _sha(env.read_bytes())
    folders = set()
    for name in sorted(import_closure(notebook_imports(notebook), graph)):
        path = _module_file(src, name)
        if path is None:
            continue
        out[_label(path, root)] = _sha(path.read_bytes())
        folders.add(path.parent)
    for folder in folders:  # panel scripts, styles and other files the modules read beside them
        for path in sorted(folder.rglob("*")):
            if path.is_file() and path.suffix not in (".py", ".pyc") and "__pycache__" not in path.parts:
                out[_label(path, root)] = _sha(path.read_bytes())
    data = root / "data"
    if data.is_dir():
        for path in sorted(data.rglob("*")):
            if path.is_file():
                out[_label(path, root)] = _sha(path.read_bytes())
    for name, folder in path_parameters(notebook, params, root).items():
        out.update(folder_digest(f"parameter {name}", folder))
    return out


def path_parameters(notebook: Path, params: dict, root: Path) -> dict[str, Path]:
    """The folders the chapter's path parameters name (``Param(path=True)``), by parameter name.

    A value equal to the declared default is taken relative to the project folder (as the chapter resolves
    it); any other value is the folder itself.
    """

    schema = chapter_schemas().get(Path(notebook).stem)
    if schema is None:
        return {}
    out = {}
    for p in schema.params:
        if not p.path:
            continue
        value = params.get(p.name, p.default)
        folder = root / str(value) if value == p.default else Path(str(value)).expanduser()
        out[p.name] = folder
    return out


def folder_digest(label: str, folder: Path) -> dict[str, str]:
    """``label/<file>`` -> SHA-256 of each file under ``folder`` (``label`` -> "absent" without the folder)."""
    folder = Path(folder)
    if not folder.is_dir():
        return {label: "absent"}
    out = {label: "folder"}
    for path in sorted(folder.rglob("*")):
        if path.is_file() and "__pycache__" not in path.parts:
            out[f"{label}/{path.relative_to(folder).as_posix()}"] = _sha(path.read_bytes())
    return out


def _module_file(src: Path, name: str) -> Path | None:
    base = src.joinpath(*name.split("."))
    for path in (base / "__init__.py", base.with_suffix(".py")):
        if path.is_file():
            return path
    return None


def _label(path: Path, root: Path) -> str:
    try:
        return str(path.resolve().relative_to(root.resolve()))
    except ValueError:
        return path.name


def differences(old: dict[str, str], new: dict[str, str]) -> list[str]:
    """What changed between two manifests, in words (first the notebook and parameters, then files)."""
    changed = [k for k in new if k in old and old[k] != new[k]]
    added = [k for k in new if k not in old]
    removed = [k for k in old if k not in new]
    return [f"{k} changed" for k in changed] + [f"{k} is new" for k in added] + [f"{k} is gone" for k in removed]


@dataclass(frozen=True, kw_only=True)
class Lookup:
    """The cache's answer for one chapter: a reusable run, or why it must run again."""

    hit: bool
    reasons: tuple[str, ...]  # empty on a hit
    elapsed_s: float = 0.0  # the cached run's own execution time


class ChapterCache:
    """Executed chapters in a folder, keyed by their manifests."""

    def __init__(self, folder: Path):
        self.folder = Path(folder)

    def _paths(self, name: str) -> tuple[Path, Path, Path]:
        return self.folder / f"{name}.json", self.folder / f"{name}.ipynb", self.folder / f"{name}-tables"

    def lookup(self, name: str, current: dict[str, str]) -> Lookup:
        meta, nb, _ = self._paths(name)
        if not (meta.is_file() and nb.is_file()):
            return Lookup(hit=False, reasons=("no cached run",))
        try:
            stored = json.loads(meta.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return Lookup(hit=False, reasons=("the cached run's record is unreadable",))
        diff = differences(stored.get("manifest", {}), current)
        if diff:
            return Lookup(hit=False, reasons=tuple(diff))
        return Lookup(hit=True, reasons=(), elapsed_s=float(stored.get("elapsed_s", 0.0)))

    def last_elapsed(self, name: str) -> float | None:
        """The execution time of the chapter's last stored run, s (None when it never ran): longest first."""
        meta, _, _ = self._paths(name)
        try:
            return float(json.loads(meta.read_text(encoding="utf-8"))["elapsed_s"])
        except (OSError, ValueError, KeyError, TypeError):
            return None

    def notebook(self, name: str) -> Path:
        """The cached executed notebook of chapter ``name``."""
        return self._paths(name)[1]

    def book_matches(self, digest: str) -> bool:
        """Whether the book in the output tree was built from inputs with this digest."""
        try:
            return json.loads((self.folder / "book.json").read_text(encoding="utf-8")).get("digest") == digest
        except (OSError, ValueError, AttributeError):
            return False

    def remember_book(self, digest: str) -> None:
        """Record the digest of a book just swapped into place (written last: a half-built tree has none)."""
        self.folder.mkdir(parents=True, exist_ok=True)
        (self.folder / "book.json").write_text(json.dumps({"digest": digest}), encoding="utf-8")

    def forget_book(self) -> None:
        (self.folder / "book.json").unlink(missing_ok=True)

    def restore(self, name: str, notebook_to: Path, tables_to: Path) -> None:
        """Copy the cached executed notebook and its tables into a build."""
        _, nb, tables = self._paths(name)
        shutil.copy2(nb, notebook_to)
        if tables.is_dir():
            for path in tables.iterdir():
                shutil.copy2(path, tables_to / path.name)

    def store(self, name: str, current: dict[str, str], executed: Path, *, tables: Path, elapsed_s: float) -> None:
        """Keep a successful run; the record is written last, so a half-written entry is never a hit."""
        self.folder.mkdir(parents=True, exist_ok=True)
        meta, nb, cached_tables = self._paths(name)
        meta.unlink(missing_ok=True)
        shutil.copy2(executed, nb)
        shutil.rmtree(cached_tables, ignore_errors=True)
        if tables.is_dir():
            shutil.copytree(tables, cached_tables)
        meta.write_text(json.dumps({"manifest": current, "elapsed_s": elapsed_s}, indent=1), encoding="utf-8")
