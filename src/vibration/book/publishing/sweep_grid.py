"""A sweep's grid: the swept axes and the fixed values of a chapter's study, every value checked against the
chapter's schema before anything runs (:func:`make_grid`)."""

from __future__ import annotations

import importlib
import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from ...physics.model import ParameterError
from .cli import convert
from .registry import chapter_packages

__all__ = ["FORMAT", "MAX_POINTS", "Axis", "Grid", "chapter_key_results", "chapter_schema", "make_grid", "parse_values"]

#: Most points one sweep may have (a budget: a mistyped N cannot queue a billion tasks).
MAX_POINTS = 1_000_000
#: Version of the files in DIR (grid.json, points.jsonl): a resume refuses another.
FORMAT = 1


# ------------------------------------------------------------------------------ the grid


@dataclass(frozen=True, kw_only=True)
class Axis:
    """One swept parameter: its name and values (in its schema's unit), and whether they are log-spaced."""

    name: str
    values: tuple
    log: bool = False


@dataclass(frozen=True, kw_only=True)
class Grid:
    """A validated sweep: the chapter's package, its swept axes and its fixed values (all checked)."""

    chapter: str  # notebook stem, e.g. "09_duffing"
    package: str  # vibration.book.chapters.<package>
    axes: tuple[Axis, ...]
    fixed: dict  # parameter -> value, every parameter not swept (the schema's defaults where not given)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(a.values) for a in self.axes)

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    def points(self):
        """``(index, values)`` of every point, ``values`` a full parameter mapping, in C order."""
        for index in itertools.product(*(range(n) for n in self.shape)):
            yield index, self.fixed | {a.name: a.values[i] for a, i in zip(self.axes, index, strict=True)}

    def describe(self) -> dict:
        """The grid as JSON-able data (``grid.json``; a resume compares it)."""
        return {
            "format": FORMAT,
            "chapter": self.chapter,
            "axes": [{"name": a.name, "values": list(a.values), "log": a.log} for a in self.axes],
            "fixed": self.fixed,
        }


def _is_int(param) -> bool:
    return isinstance(param.default, int) and not isinstance(param.default, bool)


def parse_values(param, spec: str) -> Axis:
    """``START:STOP:N`` (linear), ``START:STOP:Nlog`` (geometric) or ``V1,V2,...`` for ``param`` (a schema Param).

    Examples
    --------
    >>> from vibration.book.presentation.schema import Param
    >>> w = Param(name="omega", symbol="ω", default=1.0, unit="rad/s", low=0.0, high=10.0, meaning="frequency")
    >>> parse_values(w, "1:2:3").values, parse_values(w, "1:4:3log").values, parse_values(w, "0.5, 2").values
    ((1.0, 1.5, 2.0), (1.0, 2.0, 4.0), (0.5, 2.0))
    >>> parse_values(Param(name="n", symbol="n", default=3, unit="", low=1, high=99, meaning="count"), "1:4:3").values
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: n grid 1:4:3 gives 2.5, not an integer: allowed integer values on an \
integer grid (e.g. 1:5:3)
    """

    name, text = param.name, spec.strip()
    type_name = "int" if _is_int(param) else "float" if isinstance(param.default, float) else "str"
    if not text:
        raise ParameterError(f"{name} grid {spec!r} is empty: allowed START:STOP:N, START:STOP:Nlog or V1,V2,...")
    parts = text.split(":")
    if len(parts) == 3 and type_name != "str":
        try:
            start, stop = (convert(name, s, "float") for s in parts[:2])
        except ParameterError as exc:
            raise ParameterError(
                f"{name} grid {spec!r}: {exc}; allowed START:STOP:N, START:STOP:Nlog or V1,V2,... (e.g. -1:1:3)"
            ) from None
        count, log = parts[2].strip(), parts[2].strip().lower().endswith("log")
        count = count[:-3] if log else count
        try:
            n = int(count)
        except ValueError:
            raise ParameterError(f"{name} grid {spec!r}: N = {count!r} is not an integer: allowed N >= 1") from None
        if n < 1:
            raise ParameterError(f"{name} grid {spec!r} is empty (N = {n}): allowed N >= 1")
        if n > MAX_POINTS:
            raise ParameterError(f"{name} grid {spec!r} has N = {n}: allowed N <= {MAX_POINTS}")
        if log:
            if not (start > 0 and stop > 0):
                raise ParameterError(
                    f"{name} grid {spec!r} is logarithmic from {start:g} to {stop:g}: allowed START > 0 and STOP > 0"
                )
            raw = np.geomspace(start, stop, n) if n > 1 else np.array([start])
        else:
            raw = np.linspace(start, stop, n) if n > 1 else np.array([start])
        if type_name == "int":
            if log:
                raw = np.round(raw)
            bad = [v for v in raw if abs(v - round(v)) > 1e-9 * max(1.0, abs(v))]
            if bad:
                raise ParameterError(
                    f"{name} grid {spec} gives {bad[0]:g}, not an integer: allowed integer values on an integer grid "
                    f"(e.g. {int(start)}:{int(start) + 2 * max(1, n - 1)}:{n})"
                )
            values = tuple(int(round(v)) for v in raw)
        else:
            values = tuple(float(v) for v in raw)
    else:
        try:
            values = tuple(convert(name, s, type_name) for s in text.split(",") if s.strip())
        except ParameterError as exc:
            raise ParameterError(
                f"{name} grid {spec!r}: {exc}; allowed START:STOP:N, START:STOP:Nlog or V1,V2,..."
            ) from None
        if not values:
            raise ParameterError(f"{name} grid {spec!r} is empty: allowed START:STOP:N, START:STOP:Nlog or V1,V2,...")
        log = False
    if len(set(values)) != len(values):
        raise ParameterError(f"{name} grid {spec!r} repeats a value ({values}): allowed distinct values")
    return Axis(name=name, values=tuple(param.check(v) for v in values), log=log)


def _resolve(chapter: str) -> tuple[str, str]:
    """(notebook stem, package) of a chapter named by stem, number or topic, that declares key results."""

    packages = chapter_packages()
    found = None
    for stem, pkg in packages.items():
        num, _, rest = stem.partition("_")
        key = str(chapter)
        if key in (stem, rest, pkg) or (key.isdigit() and num.isdigit() and int(key) == int(num)):
            found = (stem, pkg)
            break
    swept = [s for s, p in packages.items() if chapter_key_results(p) is not None]
    if found is None:
        raise ParameterError(f"chapter {chapter!r} does not exist: allowed {', '.join(swept)}")
    if chapter_key_results(found[1]) is None:
        raise ParameterError(
            f"chapter {chapter!r} declares no key results (vibration.book.chapters.{found[1]}.keyresults): allowed "
            f"{', '.join(swept)}"
        )
    return found


def chapter_key_results(package: str):
    try:
        module = importlib.import_module(f"vibration.book.chapters.{package}.keyresults")
    except ModuleNotFoundError as exc:
        if exc.name == f"vibration.book.chapters.{package}.keyresults":
            return None
        raise
    return module.KEY_RESULTS


def chapter_schema(package: str):
    return importlib.import_module(f"vibration.book.chapters.{package}.params").SCHEMA


def make_grid(chapter: str, grid: Mapping[str, Sequence | str], params: Mapping | None = None) -> Grid:
    """Validate a sweep before anything runs: every value, and every point together with the fixed values.

    ``grid`` maps a parameter to its values (a sequence, or a ``START:STOP:N[log]`` / ``V1,V2`` string);
    ``params`` fixes others (typed values or strings). Raises :class:`ParameterError` naming the
    parameter: unknown, swept twice or also fixed, out of range, an empty grid, or a combination the
    schema's rules refuse.
    """

    stem, package = _resolve(chapter)
    schema = chapter_schema(package)
    names = schema.names()
    if not grid:
        raise ParameterError("the grid is empty: allowed at least one -g NAME VALUES of " + ", ".join(names))
    axes = []
    for name, spec in grid.items():
        if name not in names:
            raise ParameterError(f"parameter {name!r} is not one of {stem}'s: allowed {', '.join(names)}")
        param = schema[name]
        if param.items is not None:
            raise ParameterError(
                f"parameter {name!r} is a list and cannot be swept: allowed a sweep of one of its elements' own "
                f"parameters, or -p {name} with one list"
            )
        if isinstance(spec, str):
            axes.append(parse_values(param, spec))
            continue
        values = tuple(np.asarray(spec).tolist()) if not isinstance(spec, (list, tuple)) else tuple(spec)
        if not values:
            raise ParameterError(f"{name} grid is empty: allowed one or more values")
        if len(set(values)) != len(values):
            raise ParameterError(f"{name} grid repeats a value ({values}): allowed distinct values")
        if _is_int(param):
            bad = [v for v in values if isinstance(v, bool) or float(v) != int(float(v))]
            if bad:
                raise ParameterError(f"{name} = {bad[0]!r} is not an integer: allowed an integer grid")
            values = tuple(int(v) for v in values)
        axes.append(Axis(name=name, values=tuple(param.check(v) for v in values)))
    fixed_in = {}
    for name, value in (params or {}).items():
        if name not in names:
            raise ParameterError(
                f"parameter {name!r} (value {value!r}) is not one of {stem}'s: allowed {', '.join(names)}"
            )
        if name in grid:
            raise ParameterError(f"parameter {name!r} is both swept and fixed: allowed one of -g {name} or -p {name}")
        param = schema[name]
        if isinstance(value, str) and not param.choices:
            value = convert(name, value, "list" if param.items else "int" if _is_int(param) else "float")
        fixed_in[name] = param.check(value)
    fixed = schema.defaults() | schema.check(fixed_in)
    for a in axes:
        fixed.pop(a.name)
    g = Grid(chapter=stem, package=package, axes=tuple(axes), fixed=fixed)
    if g.size > MAX_POINTS:
        raise ParameterError(f"the grid has {g.size} points: allowed at most {MAX_POINTS}")
    for _, values in g.points():  # the rules that tie parameters together, at every point
        schema.check({k: v for k, v in values.items() if k in {a.name for a in axes} | set(fixed_in)})
    return g
