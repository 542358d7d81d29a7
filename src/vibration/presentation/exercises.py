"""Exercises and their answers: the records every chapter's ``exercises.py`` returns.

Each chapter package may hold a module ``exercises`` with

- ``OBJECTIVES``: three to five learning objectives, each starting with a verb a student can be
  examined on ("Compute ...", "Explain ...");
- ``PREREQUISITES``: what the reader should know first (short phrases);
- ``exercises(params) -> tuple[Exercise, ...]``: the chapter's exercises for one parameter record,
  every numerical answer computed by the package from those parameters.

Answers are numbers with a unit and a tolerance (checked by :meth:`Answer.accepts`), or the key of
the correct option of a multiple-choice question. ``worked`` holds the steps with the run's own
numbers, not only the result.

Examples
--------
>>> a = Answer(quantity="omega_d", value=4.4651, unit="rad/s", rtol=1e-3)
>>> a.accepts(4.466), a.accepts(0.7107)
(True, False)
>>> Answer(quantity="X", value=1.0, unit="m", rtol=-1.0)
Traceback (most recent call last):
...
vibration.physics.model.ParameterError: rtol = -1.0 must be >= 0 (the relative tolerance of answer X)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from ..physics.model import ParameterError

__all__ = ["KINDS", "Answer", "Checked", "Choice", "Exercise"]

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


@dataclass(frozen=True, kw_only=True)
class Checked:
    """The verdict on a student's answer: right or wrong, and a hint that does not give the answer away."""

    correct: bool
    hint: str
