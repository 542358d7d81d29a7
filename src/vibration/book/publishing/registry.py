"""The book's table of contents and its chapter registry: one place the runner and the book read.

``notebooks/contents.toml`` lists the book's title, its front page and its parts, each with its
chapters (notebook stems) in reading order. A notebook in ``notebooks/`` that the file does not
list, or a listed chapter without its notebook, is refused with the file's name, so a new chapter
lands in the part its author names (``--new-chapter 13_topic --part 2`` adds it), never in one a
number range would pick.

The chapter packages are found by their schemas (``vibration.book.chapters.<name>.params.SCHEMA``), so
an installed package without the notebooks still knows its chapters' parameters.
"""

from __future__ import annotations

import importlib
import os
import pkgutil
import tomllib
from dataclasses import dataclass
from pathlib import Path

from ...physics.model import ParameterError

__all__ = [
    "CONTENTS_FILE",
    "Contents",
    "Part",
    "add_chapter",
    "chapter_packages",
    "chapter_schemas",
    "project_root",
    "read_contents",
]

#: The table of contents, relative to the project folder.
CONTENTS_FILE = Path("notebooks") / "contents.toml"


@dataclass(frozen=True, kw_only=True)
class Part:
    """One part of the book: its heading and its chapters' notebook stems, in reading order."""

    title: str
    chapters: tuple[str, ...]


@dataclass(frozen=True, kw_only=True)
class Contents:
    """The book's table of contents: title, front page (a notebook stem, or empty for none) and parts."""

    title: str
    front: str
    parts: tuple[Part, ...]

    @property
    def order(self) -> tuple[str, ...]:
        """Every notebook stem in reading order, the front page first."""
        front = (self.front,) if self.front else ()
        return (*front, *(stem for part in self.parts for stem in part.chapters))

    def part_of(self, stem: str) -> Part | None:
        """The part holding chapter ``stem`` (None for the front page)."""
        return next((part for part in self.parts if stem in part.chapters), None)


def project_root() -> Path:
    """The project folder (holding ``notebooks/``): ``$VIBRATION_ROOT``, the source checkout this package
    runs from, or the working directory; an installed package without the notebooks says what to set."""
    env = os.environ.get("VIBRATION_ROOT")
    if env:
        return Path(env)
    here = Path(__file__).resolve()
    for candidate in (*here.parents, Path.cwd()):
        if (candidate / "notebooks").is_dir() and (candidate / "src" / "vibration").is_dir():
            return candidate
    if (Path.cwd() / "notebooks").is_dir():
        return Path.cwd()
    raise ParameterError(
        "no notebooks/ folder found next to the package or in the working directory: set $VIBRATION_ROOT "
        "to the project folder (the one holding notebooks/)"
    )


def _text(table: dict, key: str, where: str) -> str:
    value = table.get(key)
    if not isinstance(value, str) or not value.strip():
        raise ParameterError(f"{where}: {key} = {value!r} is not a text: allowed a non-empty string")
    return value


def read_contents(root: Path | None = None) -> Contents:
    """The table of contents of the project at ``root`` (default :func:`project_root`), checked against
    its notebooks: every notebook listed once, every listed chapter present."""
    root = root or project_root()
    path = root / CONTENTS_FILE
    if not path.is_file():
        raise ParameterError(f"{path} is missing: the book's table of contents lists its parts and chapters there")
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise ParameterError(f"{path} is not valid TOML: {exc}") from None
    where = str(CONTENTS_FILE)
    parts = []
    for i, table in enumerate(data.get("parts", ()), 1):
        chapters = table.get("chapters")
        if not isinstance(chapters, list) or not all(isinstance(c, str) for c in chapters):
            raise ParameterError(f"{where}: part {i} chapters = {chapters!r} is not a list of notebook stems")
        parts.append(Part(title=_text(table, "title", f"{where}, part {i}"), chapters=tuple(chapters)))
    front = data.get("front", "")
    if not isinstance(front, str):
        raise ParameterError(f"{where}: front = {front!r} is not a notebook stem: allowed a stem or empty")
    contents = Contents(title=_text(data, "title", where), front=front, parts=tuple(parts))
    listed = contents.order
    twice = sorted({stem for stem in listed if listed.count(stem) > 1})
    if twice:
        raise ParameterError(f"{where} lists {', '.join(twice)} more than once: allowed once each")
    present = {p.stem for p in (root / "notebooks").glob("*.ipynb") if not p.name.startswith(".")}
    missing = [stem for stem in listed if stem not in present]
    if missing:
        raise ParameterError(f"{where} lists {', '.join(missing)}, which notebooks/ does not hold")
    unlisted = sorted(present - set(listed))
    if unlisted:
        raise ParameterError(
            f"notebooks/{unlisted[0]}.ipynb is in no part of {where}: add it to a part's chapters "
            f"(unlisted: {', '.join(unlisted)})"
        )
    return contents


def add_chapter(stem: str, root: Path, part: int) -> Path:
    """Append chapter ``stem`` to part number ``part`` (1-based) of ``root``'s table of contents; a project
    without one gets one whose only part holds the chapter. Returns the file's path."""
    path = root / CONTENTS_FILE
    if not path.is_file():
        path.parent.mkdir(parents=True, exist_ok=True)
        text = f'title = "Chapters"\nfront = ""\n\n[[parts]]\ntitle = "Chapters"\nchapters = ["{stem}"]\n'
        path.write_text(text, encoding="utf-8")
        return path
    text = path.read_text(encoding="utf-8")
    n_parts = len(tomllib.loads(text).get("parts", ()))
    if not 1 <= part <= n_parts:
        raise ParameterError(f"part = {part} is not a part of {CONTENTS_FILE}: allowed 1 to {n_parts}")
    blocks = text.split("[[parts]]")
    block = blocks[part]
    head, sep, tail = block.partition("chapters = [")
    close = tail.index("]")
    listed = tail[:close].rstrip().rstrip(",")
    entry = f'"{stem}"'
    if "\n" in listed:  # one chapter a line
        tail = f"{listed},\n    {entry},\n" + tail[close:]
    else:
        tail = (f"{listed}, {entry}" if listed.strip() else entry) + tail[close:]
    blocks[part] = head + sep + tail
    path.write_text("[[parts]]".join(blocks), encoding="utf-8")
    return path


def chapter_packages() -> dict[str, str]:
    """Notebook stem -> chapter package name (``vibration.book.chapters.<name>``), sorted by stem."""
    from .. import chapters

    out = {}
    for info in pkgutil.iter_modules(chapters.__path__):
        if info.ispkg:
            schema = importlib.import_module(f"{chapters.__name__}.{info.name}.params").SCHEMA
            out[schema.notebook] = info.name
    return dict(sorted(out.items()))


def chapter_schemas() -> dict:
    """The parameter schemas of the chapter packages (``vibration.book.chapters.<name>.params.SCHEMA``), by notebook."""
    return {
        nb: importlib.import_module(f"vibration.book.chapters.{pkg}.params").SCHEMA
        for nb, pkg in chapter_packages().items()
    }
