"""Checking a student's answer: right or wrong, and a hint that names the usual slip without the answer."""

from __future__ import annotations

import math

from vibration.physics.model import ParameterError

from .model import Answer, Checked, Exercise

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
