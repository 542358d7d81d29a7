"""Exercises as the book and the notebooks show them: Markdown with folded worked answers, and plain text."""

from __future__ import annotations

from vibration.book.presentation.numbers import sig

from .model import Answer, Exercise


def tolerance_text(answer: Answer) -> str:
    """The tolerance a check allows, in words (``within 1 %``, ``within 0.01 m``)."""
    parts = []
    if answer.rtol:
        parts.append(f"{sig(answer.rtol * 100, 3)} %")
    if answer.atol:
        parts.append(f"{sig(answer.atol, 3)}{' ' + answer.unit if answer.unit else ''}")
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
