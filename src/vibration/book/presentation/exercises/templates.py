"""Sheets read from a chapter's data file (``exercises.toml``) and filled with the values the chapter computes."""

from __future__ import annotations

import math
import numbers
import string
import tomllib
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from importlib import resources

from vibration.book.presentation.numbers import sig
from vibration.physics.model import ParameterError

from .model import Answer, Exercise, Sheet


class TemplateError(ValueError):
    """A sheet's data file does not fit its chapter: a placeholder, a phrase or a field it names is missing."""


#: The fields a sheet's data file sets at its top, each required, and the array of its exercises.
_SHEET_FIELDS = ("question", "level", "objectives", "prerequisites")
#: The fields an exercise of a data file may set, by kind, and those it must set.
_FIELDS = {
    "numerical": {"id", "kind", "text", "worked", "answers", "when", "phrases"},
    "explore": {"id", "kind", "text", "worked", "answers", "when", "phrases"},
    "conceptual": {"id", "kind", "text", "worked", "options", "correct", "when", "phrases"},
}
_REQUIRED = {
    "numerical": ("id", "text", "worked", "answers"),
    "explore": ("id", "text", "worked", "answers"),
    "conceptual": ("id", "text", "worked", "options", "correct"),
}
_ANSWER_FIELDS = {"quantity", "symbol", "value", "unit", "rtol", "atol"}
_ANSWER_REQUIRED = ("quantity", "value", "unit")


#: A one-exercise sheet in the data file's format: the examples below parse and fill it.
EXAMPLE_SHEET = """
question = "How fast?"
level = "core"
objectives = ["Compute ω_d.", "Compute ζ.", "Explain the decay."]
prerequisites = ["algebra"]
[[exercise]]
id = "01.1"
kind = "numerical"
text = "With ζ = {zeta}, compute ω<sub>d</sub> (rad/s)."
worked = "ω<sub>d</sub> = {wd:.5} rad/s: the motion {moves}."
phrases.moves = { yes = "oscillates", no = "creeps back" }
answers = [{ quantity = "omega_d", value = "wd", unit = "rad/s", rtol = 1e-3 }]
"""


def _real(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _check_template(where: str, template) -> None:
    """``template`` is a string whose placeholders parse (``{name}``, ``{name:.3}``, ``{{`` for a brace)."""
    if not isinstance(template, str):
        raise TemplateError(f"{where} = {template!r:.80} is not allowed: allowed a string")
    try:
        keys = [key for _, key, _, _ in string.Formatter().parse(template) if key is not None]
    except ValueError as exc:
        raise TemplateError(f"{where}: {exc} (a literal brace is written twice: {{{{ or }}}})") from exc
    for key in keys:
        if not key.isidentifier():
            raise TemplateError(f"{where}: the placeholder {{{key}}} is not allowed: allowed a value's name")


def _check_exercise(where: str, item: Mapping) -> None:
    """The fields of one exercise of a data file: known, present, of the right type, templates that parse."""
    kind = item.get("kind")
    if kind not in _FIELDS:
        raise TemplateError(f"{where}: kind = {kind!r} is not allowed: allowed one of {', '.join(_FIELDS)}")
    unknown = sorted(set(item) - _FIELDS[kind])
    if unknown:
        raise TemplateError(f"{where}: field {unknown[0]} is not allowed in a {kind} exercise")
    missing = [name for name in _REQUIRED[kind] if name not in item]
    if missing:
        raise TemplateError(f"{where}: field {missing[0]} is missing (a {kind} exercise sets it)")
    if not isinstance(item["id"], str):
        raise TemplateError(f'{where}: id = {item["id"]!r} is not allowed: allowed a string such as "04.2"')
    if "when" in item and not (isinstance(item["when"], str) and item["when"].isidentifier()):
        raise TemplateError(f"{where}: when = {item['when']!r} is not allowed: allowed the name of a value")
    _check_template(f"{where}, text", item["text"])
    _check_template(f"{where}, worked", item["worked"])
    phrases = item.get("phrases", {})
    if not isinstance(phrases, Mapping):
        raise TemplateError(f"{where}: phrases = {phrases!r:.80} is not allowed: allowed a table of tables")
    for key, options in phrases.items():
        if not isinstance(options, Mapping) or not options:
            raise TemplateError(f"{where}: phrases.{key} = {options!r:.80} is not allowed: allowed a table of texts")
        for choice, text in options.items():
            _check_template(f"{where}, phrase {key}.{choice}", text)
    if kind == "conceptual":
        if not isinstance(item["options"], Mapping) or len(item["options"]) < 2:
            raise TemplateError(f"{where}: options = {item['options']!r:.80} is not allowed: allowed two or more")
        for key, option in item["options"].items():
            _check_template(f"{where}, option {key}", option)
        _check_template(f"{where}, correct", item["correct"])
        return
    answers = item["answers"]
    if not isinstance(answers, list) or not answers or not all(isinstance(a, Mapping) for a in answers):
        raise TemplateError(f"{where}: answers = {answers!r:.80} is not allowed: allowed a list of one or more tables")
    for n, answer in enumerate(answers, 1):
        label = f"{where}, answer {answer.get('quantity', n)}"
        unknown = sorted(set(answer) - _ANSWER_FIELDS)
        if unknown:
            raise TemplateError(f"{label}: answer field {unknown[0]} is not allowed")
        missing = [name for name in _ANSWER_REQUIRED if name not in answer]
        if missing:
            raise TemplateError(f"{label}: field {missing[0]} is missing (every answer sets it)")
        for name in ("quantity", "symbol", "unit"):
            if name in answer and not isinstance(answer[name], str):
                raise TemplateError(f"{label}: {name} = {answer[name]!r} is not allowed: allowed a string")
        for name in ("value", "rtol", "atol"):
            ref = answer.get(name)
            if ref is None or isinstance(ref, str) and ref.isidentifier():
                continue
            if not _real(ref) or (name != "value" and ref < 0):
                allowed = "a finite number" if name == "value" else "a number >= 0"
                raise TemplateError(f"{label}: {name} = {ref!r} is not allowed: allowed {allowed} or a value's name")


class _Filler(string.Formatter):
    """``str.format`` for one exercise: reals through the sheet's number format, phrases chosen by a value."""

    def __init__(self, where: str, values: Mapping[str, object], phrases: Mapping[str, Mapping[str, str]], number):
        super().__init__()
        self.where, self.values, self.phrases, self.number = where, values, phrases, number

    def fill(self, template: str) -> str:
        return self.vformat(template, (), {})

    def get_value(self, key, args, kwargs):
        if key not in self.values:
            raise TemplateError(f"{self.where}: the placeholder {{{key}}} names no value the chapter computes")
        value = self.values[key]
        if key not in self.phrases:
            return value
        if value not in self.phrases[key]:
            raise TemplateError(
                f"{self.where}: phrase {key} = {value!r} is not one of {', '.join(map(repr, self.phrases[key]))}"
            )
        return self.fill(self.phrases[key][value])

    def format_field(self, value, format_spec: str) -> str:
        if isinstance(value, numbers.Real) and not isinstance(value, numbers.Integral):
            if not format_spec:
                return self.number(value)
            if format_spec.startswith(".") and format_spec[1:].isdigit():
                return self.number(value, int(format_spec[1:]))
        return format(value, format_spec)


@dataclass(frozen=True, kw_only=True)
class SheetTemplate:
    """A chapter's sheet and its exercises as its data file words them; :meth:`fill` builds the exercises.

    Examples
    --------
    >>> book = SheetTemplate.parse(EXAMPLE_SHEET, chapter="01_x")
    >>> (ex,) = book.fill({"zeta": 0.1, "wd": 4.465145, "moves": "yes"})
    >>> ex.text, ex.worked, ex.answers[0].value
    ('With ζ = 0.1, compute ω<sub>d</sub> (rad/s).', 'ω<sub>d</sub> = 4.4651 rad/s: the motion oscillates.', 4.465145)
    >>> book.fill({"zeta": 0.1, "moves": "yes"})  # doctest: +NORMALIZE_WHITESPACE
    Traceback (most recent call last):
    ...
    vibration.book.presentation.exercises.templates.TemplateError: chapter 01_x, exercise 01.1, worked:
    the placeholder {wd} names no value the chapter computes
    """

    sheet: Sheet  # the chapter's sheet: its question, level, objectives and prerequisites
    exercises: tuple[Mapping[str, object], ...]  # each exercise's fields as the data file gives them
    number: Callable[..., str] = sig  # how a real number is written: number(x) or number(x, digits)
    file: str = ""  # the data file inside the package ("vibration/book/chapters/tmd/exercises.toml"), named by errors

    @property
    def origin(self) -> str:
        """Where an error points: the data file (when read from one) and the chapter."""
        return f"{self.file}: chapter {self.sheet.chapter}" if self.file else f"chapter {self.sheet.chapter}"

    @classmethod
    def parse(cls, source: str, *, chapter: str, number: Callable[..., str] = sig, file: str = "") -> SheetTemplate:
        """The sheet of ``chapter`` from the TOML text ``source`` (read from ``file``, named by every error).

        Every field is checked here: a field missing or not allowed, a template whose braces do not parse,
        a tolerance below zero raise :class:`TemplateError`; a placeholder naming no value is found by :meth:`fill`.
        """
        origin = f"{file}: chapter {chapter}" if file else f"chapter {chapter}"
        try:
            data = tomllib.loads(source)
        except tomllib.TOMLDecodeError as exc:
            raise TemplateError(f"{origin}: the file is not valid TOML: {exc}") from exc
        unknown = sorted(set(data) - {*_SHEET_FIELDS, "exercise"})
        if unknown:
            allowed = ", ".join((*_SHEET_FIELDS, "[[exercise]]"))
            raise TemplateError(f"{origin}: field {unknown[0]} is not allowed at the top: allowed {allowed}")
        missing = [name for name in _SHEET_FIELDS if name not in data]
        if missing:
            raise TemplateError(f"{origin}: field {missing[0]} is missing (every sheet sets it)")
        for name in ("objectives", "prerequisites"):
            if not isinstance(data[name], list) or not all(isinstance(x, str) for x in data[name]):
                raise TemplateError(f"{origin}: {name} = {data[name]!r:.80} is not allowed: allowed a list of strings")
        if not isinstance(data["question"], str):
            raise TemplateError(f"{origin}: question = {data['question']!r:.80} is not allowed: allowed a string")
        try:
            sheet = Sheet(
                chapter=chapter,
                question=data["question"],
                level=data["level"],
                objectives=tuple(data["objectives"]),
                prerequisites=tuple(data["prerequisites"]),
            )
        except ParameterError as exc:
            raise TemplateError(f"{origin}: {exc}") from exc
        items = data.get("exercise", [])
        if not isinstance(items, list) or not all(isinstance(item, Mapping) for item in items):
            raise TemplateError(f"{origin}: exercise is not allowed as a value: allowed [[exercise]] tables")
        seen = set()
        for n, item in enumerate(items, 1):
            where = f"{origin}, exercise {item['id']}" if isinstance(item.get("id"), str) else f"{origin}, exercise {n}"
            _check_exercise(where, item)
            if item["id"] in seen:
                raise TemplateError(f"{where}: id {item['id']} is set twice: allowed once")
            seen.add(item["id"])
        return cls(sheet=sheet, exercises=tuple(items), number=number, file=file)

    @classmethod
    def read(
        cls, package: str, *, chapter: str, number: Callable[..., str] = sig, name: str = "exercises.toml"
    ) -> SheetTemplate:
        """The sheet of ``chapter`` from the data file ``name`` of the package ``package``."""
        source = resources.files(package).joinpath(name).read_text(encoding="utf-8")
        return cls.parse(source, chapter=chapter, number=number, file=f"{package.replace('.', '/')}/{name}")

    def fill(self, values: Mapping[str, object]) -> tuple[Exercise, ...]:
        """The exercises for the chapter's computed ``values``: each placeholder filled, each answer looked up.

        An exercise with ``when = "name"`` is set only when the value ``name`` is true.
        """
        out = []
        for item in self.exercises:
            where = f"{self.origin}, exercise {item['id']}"
            if "when" in item:
                if item["when"] not in values:
                    raise TemplateError(f"{where}: when = {item['when']!r} names no value the chapter computes")
                if not values[item["when"]]:
                    continue
            out.append(self._exercise(where, item, values))
        return tuple(out)

    def _exercise(self, where: str, item: Mapping, values: Mapping[str, object]) -> Exercise:
        phrases = item.get("phrases", {})

        def fill(field: str, template: str) -> str:
            return _Filler(f"{where}, {field}", values, phrases, self.number).fill(template)

        text, worked = fill("text", item["text"]), fill("worked", item["worked"])
        if item["kind"] == "conceptual":
            options = {key: fill(f"option {key}", option) for key, option in item["options"].items()}
            correct = fill("correct", item["correct"])
            return self.sheet.conceptual(item["id"], text=text, worked=worked, options=options, correct=correct)
        answers = tuple(self._answer(where, answer, values) for answer in item["answers"])
        build = self.sheet.numerical if item["kind"] == "numerical" else self.sheet.explore
        return build(item["id"], text=text, worked=worked, answers=answers)

    @staticmethod
    def _answer(where: str, answer: Mapping[str, object], values: Mapping[str, object]) -> Answer:
        fields = dict(answer)
        for name in ("value", "rtol", "atol"):
            ref = fields.get(name)
            if isinstance(ref, str):
                if ref not in values:
                    quantity = fields.get("quantity")
                    raise TemplateError(
                        f"{where}, answer {quantity}: {name} = {ref!r} names no value the chapter computes"
                    )
                fields[name] = values[ref]
        return Answer(**fields)


@dataclass(frozen=True, kw_only=True)
class ChapterExercises:
    """A chapter's ``exercises`` function: its data file's sheet, filled with the values the chapter computes.

    A chapter's ``exercises.py`` defines ``values(params) -> dict`` (the numbers its templates name) and binds

    .. code-block:: python

        exercises = ChapterExercises.read(__package__, Params, values)
        SHEET = exercises.sheet
        CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()

    so the module's ``exercises(params)`` reads its ``exercises.toml`` once, at import, and fills it per call.

    Examples
    --------
    >>> import dataclasses
    >>> @dataclasses.dataclass(frozen=True)
    ... class Params:
    ...     zeta: float = 0.1
    >>> def values(p):
    ...     return {"zeta": p.zeta, "wd": 4.47 * (1 - p.zeta**2) ** 0.5, "moves": "yes"}
    >>> template = SheetTemplate.parse(EXAMPLE_SHEET, chapter="01_x")
    >>> exercises = ChapterExercises(template=template, params=Params, values=values)
    >>> [e.worked for e in exercises()], [e.worked for e in exercises(Params(zeta=0.3))]
    (['ω<sub>d</sub> = 4.4476 rad/s: the motion oscillates.'], ['ω<sub>d</sub> = 4.2641 rad/s: the motion oscillates.'])
    >>> exercises({"zeta": 0.3})  # doctest: +NORMALIZE_WHITESPACE
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: params = {'zeta': 0.3} is not allowed: allowed a Params record
    of chapter 01_x or None (its defaults)
    """

    template: SheetTemplate  # the sheet and its exercises as the chapter's data file words them
    params: type  # the chapter's parameter record type (``Params``); ``params()`` gives the defaults
    values: Callable[..., Mapping[str, object]]  # values(params): the numbers the templates name

    @classmethod
    def read(
        cls,
        package: str,
        params: type,
        values: Callable[..., Mapping[str, object]],
        *,
        number: Callable[..., str] = sig,
        name: str = "exercises.toml",
    ) -> ChapterExercises:
        """The exercises of the chapter package ``package``, worded in its data file ``name``.

        The chapter is ``params.SCHEMA.notebook``; ``number`` writes a real number (``number(x, digits)``).
        """
        template = SheetTemplate.read(package, chapter=params.SCHEMA.notebook, number=number, name=name)
        return cls(template=template, params=params, values=values)

    @property
    def sheet(self) -> Sheet:
        """The chapter's sheet: its question, level, objectives and prerequisites."""
        return self.template.sheet

    def __call__(self, params=None) -> tuple[Exercise, ...]:
        """The chapter's exercises for the record ``params`` (None: the defaults), answers computed by the package."""
        if params is None:
            params = self.params()
        if not isinstance(params, self.params):
            raise ParameterError(
                f"params = {params!r:.200} is not allowed: allowed a {self.params.__name__} record of chapter "
                f"{self.sheet.chapter} or None (its defaults)"
            )
        return self.template.fill(self.values(params))
