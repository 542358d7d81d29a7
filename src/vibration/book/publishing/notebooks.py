"""The report's chapters: the notebooks of the table of contents, chosen by name, and their parameters.

A chapter's ``-p NAME VALUE`` pairs are checked against the schemas of the chapters that declare
them before any kernel starts (:func:`check_parameters`); :func:`chapter_parameters` gives the book
each declared parameter with the value a run used.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ...physics.model import ParameterError
from .cli import convert
from .pages import Parameter, differs, split_help
from .registry import chapter_schemas, project_root, read_contents

__all__ = ["Chapter", "chapter_parameters", "check_parameters", "discover", "select"]


@dataclass(frozen=True, kw_only=True)
class Chapter:
    """One notebook of the report."""

    path: Path  # source notebook
    params: dict  # papermill's inspection: name -> {inferred_type_name, default, help}

    @property
    def name(self) -> str:
        """File stem, e.g. ``01_reproduction``."""
        return self.path.stem

    def matches(self, key: str) -> bool:
        """Whether ``key`` names this chapter (stem, number or stem without number)."""
        num, _, rest = self.name.partition("_")
        return key in (self.name, rest) or (key.isdigit() and num.isdigit() and int(key) == int(num))


def discover(root: Path | None = None) -> list[Chapter]:
    """All chapters in ``notebooks/``, in the order of the table of contents (``notebooks/contents.toml``)."""
    import papermill

    root = root or project_root()
    paths = [root / "notebooks" / f"{stem}.ipynb" for stem in read_contents(root).order]
    return [Chapter(path=p, params=papermill.inspect_notebook(str(p))) for p in paths]


def select(chapters: list[Chapter], keys: list[str]) -> list[Chapter]:
    """The chapters named by ``keys`` (all when empty), in report order."""
    if not keys:
        return chapters
    chosen = []
    for key in keys:
        hits = [c for c in chapters if c.matches(key)]
        if not hits:
            names = ", ".join(c.name for c in chapters)
            raise ParameterError(f"chapter {key!r} does not exist: allowed {names}")
        chosen += [c for c in hits if c not in chosen]
    return [c for c in chapters if c in chosen]


def check_parameters(chapters: list[Chapter], pairs: list[tuple[str, str]]) -> dict[str, object]:
    """Validate ``-p NAME VALUE`` pairs against the schemas of the chapters that declare them.

    Each chapter's schema (its package's ``params.SCHEMA``) is the one source of a parameter's type
    and range and of the rules that tie several together; a value shared by several chapters must
    suit each of them. Returns the typed values. Raises :class:`ParameterError` naming the
    parameter, its value and what is allowed.
    """
    schemas = chapter_schemas()
    asked = {name for name, _ in pairs}
    missing = [ch.name for ch in chapters if ch.name not in schemas and asked & set(ch.params)]
    if missing:  # a chapter without a schema runs at its notebook's own values, but takes no -p value
        raise ParameterError(
            f"chapter {missing[0]} has no parameter schema, so -p cannot set its parameters: allowed chapters with a "
            f"package vibration.book.chapters.<topic> holding params.SCHEMA (python -m vibration.report --new-chapter "
            f"writes one)"
        )
    declared: dict[str, str] = {}
    for ch in chapters:
        for name, info in ch.params.items():
            declared.setdefault(name, info.get("inferred_type_name") or "str")
    values: dict[str, object] = {}
    for name, text in pairs:
        if name not in declared:
            allowed = ", ".join(sorted(declared))
            raise ParameterError(
                f"parameter {name!r} (value {text!r}) is not declared by any chapter run: allowed {allowed}"
            )
        value = convert(name, text, declared[name])
        for ch in chapters:
            if name in ch.params and ch.name in schemas:
                value = schemas[ch.name][name].check(value)  # each chapter's own range
        values[name] = list(value) if isinstance(value, tuple) else value  # papermill writes a list literal
    for ch in chapters:  # the chapter's rules that tie several of its parameters together
        if ch.name in schemas:
            schemas[ch.name].check({k: v for k, v in values.items() if k in ch.params})
    return values


def chapter_parameters(ch: Chapter, values: dict) -> list:
    """The chapter's declared parameters with the values this run used (for the book)."""
    import ast

    from ...physics.paper import paper_defaults

    paper = paper_defaults()
    schema = chapter_schemas().get(ch.name)
    out = []
    for name, info in ch.params.items():
        try:
            default = ast.literal_eval(info.get("default", ""))
        except (ValueError, SyntaxError):
            default = info.get("default")
        meaning, unit = split_help(info.get("help", ""))
        symbol = ""
        if schema is not None and name in schema.names():  # the schema is the source; the cell's comment a fallback
            param = schema[name]
            meaning, unit, symbol = param.meaning or meaning, param.unit, param.symbol
        is_paper = name in paper and not differs(default, paper[name])
        value = values.get(name, default)
        if schema is not None and name in schema.names() and schema[name].default_from and not value:
            # an empty list stands for the values of its sources: show those (c_low, c_nominal, c_high)
            full = schema.defaults() | {k: v for k, v in values.items() if k in schema.names()}
            value = default = list(schema[name].resolved(full))
        out.append(
            Parameter(
                name=name,
                value=value,
                default=default,
                meaning=meaning,
                unit=unit,
                paper=is_paper,
                symbol=symbol,
            )
        )
    return out
