"""The sheet loader: templates filled from a chapter's values, and the errors a data file that does not fit gets."""

from __future__ import annotations

import pytest

from vibration.book.presentation.exercises import Answer, Sheet, SheetTemplate, TemplateError

SOURCE = """
question = "How fast?"
level = "core"
objectives = ["Compute ω_d.", "Compute ζ.", "Explain the decay."]
prerequisites = ["algebra"]

[[exercise]]
id = "01.1"
kind = "numerical"
text = "With ζ = {zeta}, compute ω<sub>d</sub> (rad/s)."
worked = "ω<sub>d</sub> = {wd:.5} rad/s; the motion {moves}."
phrases.moves = { yes = "oscillates at {wd:.2} rad/s", no = "creeps back" }
answers = [{ quantity = "omega_d", symbol = "ω<sub>d</sub>", value = "wd", unit = "rad/s", rtol = 1e-3, atol = "tiny" }]

[[exercise]]
id = "01.2"
kind = "conceptual"
when = "damped"
text = "Is c = {c} N s/m a damping?"
worked = "It is {c} N s/m."
options = { a = "yes", b = "no" }
correct = "{key}"
"""

VALUES = {"zeta": 0.1, "wd": 4.465145, "moves": "yes", "tiny": 1e-9, "damped": True, "c": 2.0, "key": "a", "n": 3}


def test_fill_builds_the_records_a_module_would():
    sheet = Sheet(
        chapter="01_x",
        question="How fast?",
        level="core",
        objectives=("Compute ω_d.", "Compute ζ.", "Explain the decay."),
        prerequisites=("algebra",),
    )
    template = SheetTemplate.parse(SOURCE, chapter="01_x")
    assert template.sheet == sheet
    assert template.fill(VALUES) == (
        sheet.numerical(
            "01.1",
            text="With ζ = 0.1, compute ω<sub>d</sub> (rad/s).",
            worked="ω<sub>d</sub> = 4.4651 rad/s; the motion oscillates at 4.5 rad/s.",
            answers=Answer(
                quantity="omega_d", symbol="ω<sub>d</sub>", value=4.465145, unit="rad/s", rtol=1e-3, atol=1e-9
            ),
        ),
        sheet.conceptual(
            "01.2",
            text="Is c = 2 N s/m a damping?",
            worked="It is 2 N s/m.",
            options={"a": "yes", "b": "no"},
            correct="a",
        ),
    )


def test_when_false_leaves_the_exercise_out():
    template = SheetTemplate.parse(SOURCE, chapter="01_x")
    assert [e.id for e in template.fill({**VALUES, "damped": False})] == ["01.1"]


def test_a_placeholder_without_a_value_names_chapter_exercise_and_placeholder():
    template = SheetTemplate.parse(SOURCE, chapter="01_x")
    values = {k: v for k, v in VALUES.items() if k != "c"}
    with pytest.raises(
        TemplateError, match=r"chapter 01_x, exercise 01\.2, text: the placeholder \{c\} names no value"
    ):
        template.fill(values)


def test_an_answer_naming_a_missing_value_is_reported():
    template = SheetTemplate.parse(SOURCE, chapter="01_x")
    values = {k: v for k, v in VALUES.items() if k != "tiny"}
    with pytest.raises(TemplateError, match=r"chapter 01_x, exercise 01\.1, answer omega_d: atol = 'tiny'"):
        template.fill(values)


def test_a_phrase_key_that_is_not_offered_is_reported():
    template = SheetTemplate.parse(SOURCE, chapter="01_x")
    with pytest.raises(
        TemplateError, match=r"exercise 01\.1, worked: phrase moves = 'maybe' is not one of 'yes', 'no'"
    ):
        template.fill({**VALUES, "moves": "maybe"})


def test_an_unknown_field_is_refused_when_read():
    with pytest.raises(TemplateError, match=r"chapter 01_x, exercise 01\.1: field answer is not allowed"):
        SheetTemplate.parse(SOURCE.replace("answers = ", "answer = "), chapter="01_x")
