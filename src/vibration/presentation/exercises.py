"""Exercises and their answers: the records every chapter's ``exercises.py`` returns.

Each chapter package may hold a module ``exercises`` with

- ``SHEET``: a :class:`Sheet`, what the chapter declares once: its notebook, its question in one
  sentence and its level, three to five learning objectives (each starting with a verb a student
  can be examined on: "Compute ...", "Explain ...") and its prerequisites (short phrases). The
  module names the book reads, ``CHAPTER``, ``QUESTION``, ``LEVEL``, ``OBJECTIVES`` and
  ``PREREQUISITES``, are unpacked from it with :meth:`Sheet.module_constants`;
- ``exercises(params) -> tuple[Exercise, ...]``: the chapter's exercises for one parameter record,
  every numerical answer computed by the package from those parameters, each built by the sheet
  (:meth:`Sheet.numerical`, :meth:`Sheet.conceptual`, :meth:`Sheet.explore`), which fills in the chapter.

The words of a sheet are content a lecturer edits, so a chapter keeps them in a data file next to its
module, ``exercises.toml``, read by :meth:`SheetTemplate.read`: the sheet's question, level, objectives and
prerequisites, and for each exercise its id, kind, question and worked answer as templates with named
placeholders (``{mu}``, ``{x0:.5}`` for five significant digits), its answers (quantity, symbol, the name
of the value, unit, tolerances), the options of a conceptual one and the phrases a branch chooses. The
chapter's Python computes only the named values, and :meth:`SheetTemplate.fill` builds the exercises;
:class:`ChapterExercises` binds the two into the module's ``exercises`` (the data file read once, at import).

Answers are numbers with a unit and a tolerance (checked by :meth:`Answer.accepts`), or the key of
the correct option of a multiple-choice question. ``worked`` holds the steps with the run's own
numbers, not only the result.

Examples
--------
>>> a = Answer(quantity="omega_d", value=4.4651, unit="rad/s", rtol=1e-3)
>>> a.accepts(4.466), a.accepts(0.7107)
(True, False)
>>> sheet = Sheet(chapter="01_x", question="How fast?", level="core", prerequisites=("algebra",),
...               objectives=("Compute ω_d.", "Compute ζ.", "Explain the decay."))
>>> ex = sheet.numerical("01.1", text="ω_d (rad/s)?", worked="ω_n √(1 − ζ²) = 4.4651 rad/s.",
...                      answers=Answer(quantity="omega_d", value=4.4651, unit="rad/s", rtol=1e-3))
>>> ex.chapter, ex.kind, len(ex.answers)
('01_x', 'numerical', 1)
>>> sheet.conceptual("01.2", text="Is it damped?", worked="ζ > 0.", options={"a": "yes", "b": "no"},
...                  correct="a").choices[1]
Choice(key='b', text='no')
>>> Answer(quantity="X", value=1.0, unit="m", rtol=-1.0)
Traceback (most recent call last):
...
vibration.physics.model.ParameterError: rtol = -1.0 must be >= 0 (the relative tolerance of answer X)
"""

from __future__ import annotations

import math
import numbers
import string
import tomllib
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from importlib import resources
from typing import Literal

from ..physics.model import ParameterError

__all__ = [
    "KINDS",
    "LEVELS",
    "Answer",
    "ChapterExercises",
    "Checked",
    "Choice",
    "Exercise",
    "Sheet",
    "SheetTemplate",
    "TemplateError",
    "answer_markdown",
    "check_answer",
    "exercise_markdown",
    "fmt",
    "numeric_hint",
    "objectives_markdown",
    "objectives_text",
    "question_markdown",
    "section_markdown",
    "section_text",
    "tolerance_text",
]

#: The kinds of exercise: a number to compute, a multiple-choice question, one using sliders or a ``-p`` run.
KINDS = ("numerical", "conceptual", "explore")


@dataclass(frozen=True, kw_only=True)
class Answer:
    """One numerical answer: the quantity's name, its value in SI units and the tolerance a check allows."""

    quantity: str  # a short identifier, e.g. "omega_d"; the answers table's `quantity` column
    value: float  # the answer, in `unit`
    unit: str  # SI unit as the book writes it ("rad/s", "m"); "" when dimensionless
    rtol: float = 1e-2  # relative tolerance of a check
    atol: float = 0.0  # absolute tolerance of a check, in `unit`
    symbol: str = ""  # how the book writes the quantity ("ω<sub>d</sub>"); `quantity` when empty

    def __post_init__(self) -> None:
        if not isinstance(self.quantity, str) or not self.quantity:
            raise ParameterError(f"quantity = {self.quantity!r} must be a non-empty string")
        if not isinstance(self.value, (int, float)) or isinstance(self.value, bool) or not math.isfinite(self.value):
            raise ParameterError(f"value = {self.value!r} must be a finite number (answer {self.quantity})")
        for name in ("rtol", "atol"):
            tol = getattr(self, name)
            if not isinstance(tol, (int, float)) or isinstance(tol, bool) or not math.isfinite(tol) or tol < 0:
                kind = "relative" if name == "rtol" else "absolute"
                raise ParameterError(f"{name} = {tol!r} must be >= 0 (the {kind} tolerance of answer {self.quantity})")
        if self.rtol == 0 and self.atol == 0:
            raise ParameterError(f"rtol and atol are both 0: answer {self.quantity} could never be matched")

    def accepts(self, given: float) -> bool:
        """Whether ``given`` matches within ``atol + rtol |value|``."""
        return math.isfinite(given) and abs(given - self.value) <= self.atol + self.rtol * abs(self.value)


@dataclass(frozen=True, kw_only=True)
class Choice:
    """One option of a multiple-choice question."""

    key: str  # "a", "b", ...
    text: str


@dataclass(frozen=True, kw_only=True)
class Exercise:
    """One exercise of a chapter, with its worked answer."""

    id: str  # "04.2": chapter number, a dot, the exercise's number in the chapter
    chapter: str  # the notebook's stem, e.g. "04_frequency_response"
    kind: Literal["numerical", "conceptual", "explore"]
    text: str  # the question, in the book's Markdown (symbols typeset, units given)
    worked: str  # the worked answer: the steps with the run's own numbers
    answers: tuple[Answer, ...] = ()  # numerical answers (numerical and explore exercises)
    choices: tuple[Choice, ...] = ()  # options of a conceptual exercise
    correct: str | None = None  # key of the correct option of a conceptual exercise

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ParameterError(f"kind = {self.kind!r} is not allowed: allowed one of {', '.join(KINDS)}")
        if self.kind == "conceptual":
            keys = [c.key for c in self.choices]
            if len(keys) < 2 or len(set(keys)) != len(keys):
                raise ParameterError(f"exercise {self.id}: choices need two or more distinct keys, got {keys}")
            if self.correct not in keys:
                raise ParameterError(f"exercise {self.id}: correct = {self.correct!r} is not one of {keys}")
        elif not self.answers:
            raise ParameterError(f"exercise {self.id}: a {self.kind} exercise needs at least one answer")


#: The levels of a chapter: "core" (Part I, second year) or "advanced" (graduate).
LEVELS = ("core", "advanced")


@dataclass(frozen=True, kw_only=True)
class Sheet:
    """What a chapter's exercise module declares once; its builders fill in the chapter of every exercise."""

    chapter: str  # the notebook's stem, e.g. "04_frequency_response" (the chapter's SCHEMA.notebook)
    question: str  # the chapter's question, in one sentence
    level: Literal["core", "advanced"]
    objectives: tuple[str, ...]  # three to five, each starting with a verb a student can be examined on
    prerequisites: tuple[str, ...]  # what the reader should know first, short phrases

    def __post_init__(self) -> None:
        if self.level not in LEVELS:
            raise ParameterError(f"level = {self.level!r} is not allowed: allowed one of {', '.join(LEVELS)}")
        if not 3 <= len(self.objectives) <= 5:
            raise ParameterError(f"sheet {self.chapter}: {len(self.objectives)} objectives, allowed 3 to 5")
        if not self.prerequisites:
            raise ParameterError(f"sheet {self.chapter}: no prerequisites, allowed one or more")

    def module_constants(self) -> tuple[str, str, str, tuple[str, ...], tuple[str, ...]]:
        """``CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES``: the module names the book and the sheets read."""
        return self.chapter, self.question, self.level, self.objectives, self.prerequisites

    def numerical(self, id: str, *, text: str, worked: str, answers: Answer | tuple[Answer, ...]) -> Exercise:
        """Exercise ``id``: a number (or several) to compute from the run's parameters."""
        return self._answered(id, "numerical", text, worked, answers)

    def explore(self, id: str, *, text: str, worked: str, answers: Answer | tuple[Answer, ...]) -> Exercise:
        """Exercise ``id``: numbers to compute, then to read with the sliders or a ``-p`` run."""
        return self._answered(id, "explore", text, worked, answers)

    def conceptual(self, id: str, *, text: str, worked: str, options: Mapping[str, str], correct: str) -> Exercise:
        """Exercise ``id``: a multiple-choice question, ``options`` mapping each key ("a", "b", ...) to its text."""
        choices = tuple(Choice(key=key, text=option) for key, option in options.items())
        return Exercise(
            id=id, chapter=self.chapter, kind="conceptual", text=text, worked=worked, choices=choices, correct=correct
        )

    def _answered(self, id: str, kind: str, text: str, worked: str, answers: Answer | tuple[Answer, ...]) -> Exercise:
        answers = (answers,) if isinstance(answers, Answer) else tuple(answers)
        return Exercise(id=id, chapter=self.chapter, kind=kind, text=text, worked=worked, answers=answers)


@dataclass(frozen=True, kw_only=True)
class Checked:
    """The verdict on a student's answer: right or wrong, and a hint that does not give the answer away."""

    correct: bool
    hint: str


# ---------------------------------------------------------------------------------------------------------
# Checking a student's answer


#: Relative closeness under which a slip (a factor 2π, 2, 180/π, ...) is named in a hint.
_SLIP_RTOL = 0.03

_SLIPS: tuple[tuple[float, str, tuple[str, ...]], ...] = (
    # (given / answer, hint, units it applies to: () for any)
    (1.0 / (2.0 * math.pi), "This looks like a frequency in Hz; the answer is asked in rad/s (ω = 2π f).", ("rad/s",)),
    (2.0 * math.pi, "This looks like a frequency in rad/s; the answer is asked in Hz (f = ω/2π).", ("Hz",)),
    (180.0 / math.pi, "This looks like an angle in degrees; the answer is asked in rad.", ("rad",)),
    (math.pi / 180.0, "This looks like an angle in rad; the answer is asked in degrees.", ("°", "deg")),
    (2.0, "This is about twice the answer: a peak-to-peak value? The amplitude is half the peak-to-peak swing.", ()),
    (0.5, "This is about half the answer: check the factor 2 (amplitude against peak-to-peak, 2ζω_n, 2m).", ()),
    (2.0 * math.pi, "A factor 2π away: check rad/s against Hz, or a period against an angular frequency.", ()),
    (1.0 / (2.0 * math.pi), "A factor 2π away: check rad/s against Hz, or a period against an angular frequency.", ()),
    (-1.0, "The size is right, the sign is not.", ()),
)


def _near(given: float, target: float) -> bool:
    return target != 0 and abs(given - target) <= _SLIP_RTOL * abs(target)


def numeric_hint(answer: Answer, given: float) -> str:
    """A hint for a wrong number: the usual slip it looks like, else the direction; never the answer."""
    a = answer.value
    for factor, hint, units in _SLIPS:
        if (not units or answer.unit in units) and _near(given, factor * a):
            return hint
    for power in (-6, -3, 3, 6):
        if _near(given, a * 10.0**power):
            return f"Off by a factor 10^{power}: check the units ({answer.unit or 'dimensionless'}) and their prefixes."
    unit = f" ({answer.unit})" if answer.unit else " (dimensionless)"
    side = "too large" if given > a else "too small"
    return f"Not within the tolerance{unit}: the number is {side}. Redo the steps with the run's parameters."


def _as_number(value, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        try:
            import numpy as np  # a numpy scalar or 0-d array is a number too

            if isinstance(value, np.generic | np.ndarray) and np.ndim(value) == 0:
                return float(value)
        except ImportError:  # pragma: no cover
            pass
        raise ParameterError(f"answer = {value!r} must be a number ({what})")
    return float(value)


def check_answer(exercise: Exercise, given, *, quantity: str | None = None) -> Checked:
    """Whether ``given`` answers ``exercise``, with a hint that does not reveal the answer.

    Parameters
    ----------
    exercise : Exercise
        The exercise, its answers computed for the run's parameters.
    given : float, str, dict or sequence
        A number (one answer, or the one named by ``quantity``), the key of an option (conceptual), a
        mapping quantity -> number, or numbers in the order of the exercise's answers.
    quantity : str, optional
        Which of several answers ``given`` is.

    Examples
    --------
    >>> ex = Exercise(id="01.1", chapter="01_x", kind="numerical", text="ω_d?", worked="...",
    ...               answers=(Answer(quantity="omega_d", value=4.465, unit="rad/s", rtol=1e-3),))
    >>> check_answer(ex, 4.4652).correct
    True
    >>> print(check_answer(ex, 0.7107).hint)
    This looks like a frequency in Hz; the answer is asked in rad/s (ω = 2π f).
    """
    if exercise.kind == "conceptual":
        key = str(given).strip().lower().strip("()")
        keys = [c.key for c in exercise.choices]
        if key not in keys:
            return Checked(correct=False, hint=f"Answer with the key of an option: one of {', '.join(keys)}.")
        if key == exercise.correct:
            return Checked(correct=True, hint="Right.")
        return Checked(correct=False, hint=f"Not option {key}. Compute each reading with this run's parameters.")
    answers = {a.quantity: a for a in exercise.answers}
    if isinstance(given, dict):
        pairs = list(given.items())
    elif isinstance(given, (list, tuple)):
        if len(given) != len(exercise.answers):
            raise ParameterError(
                f"answer = {given!r} gives {len(given)} numbers: exercise {exercise.id} asks for "
                f"{len(exercise.answers)} ({', '.join(answers)})"
            )
        pairs = [(a.quantity, g) for a, g in zip(exercise.answers, given, strict=True)]
    elif quantity is not None:
        pairs = [(quantity, given)]
    elif len(exercise.answers) == 1:
        pairs = [(exercise.answers[0].quantity, given)]
    else:
        raise ParameterError(
            f"exercise {exercise.id} asks for {len(answers)} quantities ({', '.join(answers)}): name one with "
            "quantity=..., or give them all as a dict or in that order"
        )
    verdicts = []
    for name, value in pairs:
        if name not in answers:
            raise ParameterError(
                f"quantity = {name!r} is not asked in exercise {exercise.id}: allowed {', '.join(answers)}"
            )
        a = answers[name]
        number = _as_number(value, f"{name} in {a.unit or 'dimensionless'}")
        ok = a.accepts(number)
        verdicts.append((name, ok, "Right." if ok else numeric_hint(a, number)))
    correct = all(ok for _, ok, _ in verdicts)
    if len(verdicts) == 1:
        return Checked(correct=correct, hint=verdicts[0][2])
    return Checked(correct=correct, hint=" ".join(f"{name}: {hint}" for name, _, hint in verdicts))


# ---------------------------------------------------------------------------------------------------------
# Rendering


def tolerance_text(answer: Answer) -> str:
    """The tolerance a check allows, in words (``within 1 %``, ``within 0.01 m``)."""
    parts = []
    if answer.rtol:
        parts.append(f"{fmt(answer.rtol * 100, 3)} %")
    if answer.atol:
        parts.append(f"{fmt(answer.atol, 3)}{' ' + answer.unit if answer.unit else ''}")
    return "within " + " + ".join(parts)


def objectives_markdown(objectives, prerequisites) -> str:
    """The chapter's objectives and prerequisites as a Markdown block."""
    lines = ["**Learning objectives.** After this chapter you can:", ""]
    lines += [f"- {o}" for o in objectives]
    needs = "; ".join(prerequisites)
    lines += ["", "**Prerequisites.** " + needs[:1].upper() + needs[1:] + "."]
    return "\n".join(lines)


def objectives_text(objectives, prerequisites) -> str:
    """The same block as plain text."""
    return "\n".join(
        ["Learning objectives:"] + [f"- {o}" for o in objectives] + ["Prerequisites: " + "; ".join(prerequisites) + "."]
    )


def question_markdown(ex: Exercise) -> str:
    """The question of ``ex`` (its options for a conceptual one), without its answer."""
    label = {"numerical": "", "conceptual": " (multiple choice)", "explore": " (sliders or a run)"}[ex.kind]
    if ex.answers:
        asked = ", ".join(f"{a.symbol or a.quantity} ({a.unit or 'dimensionless'})" for a in ex.answers)
        how = f"*Answer:* {asked}, {tolerance_text(ex.answers[0])}."
    else:
        how = "*Answer:* the letter of one option."
    out = [f"**Exercise {ex.id}**{label}. {ex.text} {how}"]  # one paragraph: no line repeats on a page
    if ex.choices:
        out.append("")
        out += [f"- ({c.key}) {c.text}" for c in ex.choices]
    return "\n".join(out)


def answer_markdown(ex: Exercise) -> str:
    """The worked answer of ``ex``: its steps with the run's numbers, then the result."""
    out = [ex.worked]
    if ex.kind == "conceptual":
        choice = next(c for c in ex.choices if c.key == ex.correct)
        out += ["", f"**Answer:** ({choice.key}) {choice.text}"]
    return "\n".join(out)


def exercise_markdown(ex: Exercise, *, folded: bool = True) -> str:
    """The question of ``ex`` and its worked answer, folded under a ``<details>`` element when ``folded``."""
    if not folded:
        return question_markdown(ex)
    return "\n".join(
        [
            question_markdown(ex),
            "",
            '<details class="exercise-answer">',
            f"<summary>Worked answer {ex.id}</summary>",
            "",
            answer_markdown(ex),
            "",
            "</details>",
        ]
    )


def section_markdown(exercises, *, folded: bool = True) -> str:
    """Every exercise of a chapter, each question followed by its folded worked answer."""
    return "\n\n".join(exercise_markdown(ex, folded=folded) for ex in exercises)


def section_text(exercises) -> str:
    """The questions as plain text (no answers): what a notebook's text output holds."""
    lines = []
    for ex in exercises:
        lines.append(f"Exercise {ex.id} ({ex.kind}): {ex.text}")
        lines += [f"  ({c.key}) {c.text}" for c in ex.choices]
    return "\n".join(lines)


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def fmt(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant digits as the book writes numbers: a true minus, powers of ten as ×10ⁿ.

    >>> fmt(4.46514), fmt(-0.05), fmt(1.2e-5), fmt(1e-9), fmt(2.5e7)
    ('4.465', '−0.05', '1.2×10⁻⁵', '10⁻⁹', '2.5×10⁷')
    """
    text = f"{x:.{digits}g}"
    if "e" in text:
        mant, exp = text.split("e")
        power = "10" + str(int(exp)).translate(_SUPERSCRIPT)
        text = power if mant in ("1", "-1") else f"{mant}×{power}"
        text = ("-" + text) if mant == "-1" else text
    return text.replace("-", "−", 1) if text.startswith("-") else text


# ---------------------------------------------------------------------------------------------------------
# Sheets read from a data file


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
    >>> source = '''
    ... question = "How fast?"
    ... level = "core"
    ... objectives = ["Compute ω_d.", "Compute ζ.", "Explain the decay."]
    ... prerequisites = ["algebra"]
    ... [[exercise]]
    ... id = "01.1"
    ... kind = "numerical"
    ... text = "With ζ = {zeta}, compute ω<sub>d</sub> (rad/s)."
    ... worked = "ω<sub>d</sub> = {wd:.5} rad/s: the motion {moves}."
    ... phrases.moves = { yes = "oscillates", no = "creeps back" }
    ... answers = [{ quantity = "omega_d", value = "wd", unit = "rad/s", rtol = 1e-3 }]
    ... '''
    >>> book = SheetTemplate.parse(source, chapter="01_x")
    >>> (ex,) = book.fill({"zeta": 0.1, "wd": 4.465145, "moves": "yes"})
    >>> ex.text, ex.worked, ex.answers[0].value
    ('With ζ = 0.1, compute ω<sub>d</sub> (rad/s).', 'ω<sub>d</sub> = 4.4651 rad/s: the motion oscillates.', 4.465145)
    >>> book.fill({"zeta": 0.1, "moves": "yes"})  # doctest: +NORMALIZE_WHITESPACE
    Traceback (most recent call last):
    ...
    vibration.presentation.exercises.TemplateError: chapter 01_x, exercise 01.1, worked:
    the placeholder {wd} names no value the chapter computes
    """

    sheet: Sheet  # the chapter's sheet: its question, level, objectives and prerequisites
    exercises: tuple[Mapping[str, object], ...]  # each exercise's fields as the data file gives them
    number: Callable[..., str] = fmt  # how a real number is written: number(x) or number(x, digits)
    file: str = ""  # the data file inside the package ("vibration/chapters/tmd/exercises.toml"), named by errors

    @property
    def origin(self) -> str:
        """Where an error points: the data file (when read from one) and the chapter."""
        return f"{self.file}: chapter {self.sheet.chapter}" if self.file else f"chapter {self.sheet.chapter}"

    @classmethod
    def parse(cls, source: str, *, chapter: str, number: Callable[..., str] = fmt, file: str = "") -> SheetTemplate:
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
        cls, package: str, *, chapter: str, number: Callable[..., str] = fmt, name: str = "exercises.toml"
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
    >>> template = SheetTemplate.parse('''
    ... question = "How fast?"
    ... level = "core"
    ... objectives = ["Compute ω_d.", "Compute ζ.", "Explain the decay."]
    ... prerequisites = ["algebra"]
    ... [[exercise]]
    ... id = "01.1"
    ... kind = "numerical"
    ... text = "With ζ = {zeta}, compute 2ζ."
    ... worked = "2ζ = {two_zeta}."
    ... answers = [{ quantity = "two_zeta", value = "two_zeta", unit = "", rtol = 1e-3 }]
    ... ''', chapter="01_x")
    >>> exercises = ChapterExercises(template=template, params=Params,
    ...                              values=lambda p: {"zeta": p.zeta, "two_zeta": 2 * p.zeta})
    >>> [e.worked for e in exercises()], [e.worked for e in exercises(Params(zeta=0.3))]
    (['2ζ = 0.2.'], ['2ζ = 0.6.'])
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
        number: Callable[..., str] = fmt,
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
