"""The records of a chapter's exercises: answers, options, exercises, the sheet that builds them, a verdict."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

from vibration.physics.model import ParameterError

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
