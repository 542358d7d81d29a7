"""Exercises and their answers: the records every chapter's ``exercises.py`` returns.

By concept: :mod:`.model` (the records), :mod:`.checking` (a student's answer), :mod:`.rendering` (Markdown
and text) and :mod:`.templates` (a chapter's data file, filled with its values).

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

from .checking import check_answer, numeric_hint
from .model import KINDS, LEVELS, Answer, Checked, Choice, Exercise, Sheet
from .rendering import (
    answer_markdown,
    exercise_markdown,
    objectives_markdown,
    objectives_text,
    question_markdown,
    section_markdown,
    section_text,
    tolerance_text,
)
from .templates import ChapterExercises, SheetTemplate, TemplateError

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
    "numeric_hint",
    "objectives_markdown",
    "objectives_text",
    "question_markdown",
    "section_markdown",
    "section_text",
    "tolerance_text",
]
