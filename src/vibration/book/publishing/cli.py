"""What the runner's command lines share: parsing a ``-p`` value, negative values, SIGTERM, subcommands."""

from __future__ import annotations

import math
import re

from ...physics.model import ParameterError

__all__ = ["SUBCOMMANDS", "convert", "protect_negative_values", "terminate"]

#: The runner's subcommands (its first argument, which no chapter may take as its name): name -> the
#: ``module:function`` that takes the remaining arguments and returns the exit status.
SUBCOMMANDS = {
    "sweep": "vibration.book.publishing.sweep:main",
    "exercises": "vibration.book.publishing.sheets:main",
}


def convert(name: str, text: str, type_name: str):
    """Parse ``text`` as the declared type of parameter ``name``."""
    text = text.strip()
    if type_name == "int":
        try:
            return int(text)
        except ValueError:
            raise ParameterError(f"{name} = {text!r} is not an integer: allowed an integer") from None
    if type_name == "float":
        try:
            value = float(text)
        except ValueError:
            raise ParameterError(f"{name} = {text!r} is not a number: allowed a real number") from None
        if not math.isfinite(value):
            raise ParameterError(f"{name} = {text!r} is not finite: allowed a finite real number")
        return value
    if type_name == "list":
        import json

        try:
            value = json.loads(text)
        except ValueError:
            value = None
        if not isinstance(value, list):
            raise ParameterError(f"{name} = {text!r} is not a list: allowed a JSON list such as '[0.1, 0.5, 15]'")
        return value
    if type_name == "bool":
        low = text.lower()
        if low not in ("true", "false", "1", "0"):
            raise ParameterError(f"{name} = {text!r} is not a boolean: allowed true or false")
        return low in ("true", "1")
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":  # a quoted literal, as notebooks write them
        return text[1:-1]
    return text


def protect_negative_values(argv: list[str]) -> list[str]:
    """``-p c_low -2e4``, ``-g c_nominal -1:1:3``: argparse would read ``-2e4`` and ``-1:1:3`` as options; a
    leading space keeps each a value (the value of ``-p`` or ``-g``: the second word after it).

    Examples
    --------
    >>> protect_negative_values(["-p", "c_low", "-2e4", "01"])
    ['-p', 'c_low', ' -2e4', '01']
    >>> protect_negative_values(["04", "-g", "c_nominal", "-1:1:3", "-g", "m", "-.5,1"])
    ['04', '-g', 'c_nominal', ' -1:1:3', '-g', 'm', ' -.5,1']
    >>> protect_negative_values(["-p", "m", "--no-pdf"])  # a missing value stays missing
    ['-p', 'm', '--no-pdf']
    """
    out = list(argv)
    for i in range(2, len(out)):
        if out[i - 2] in ("-p", "--parameter", "-g", "--grid") and _NEGATIVE.match(out[i]):
            out[i] = " " + out[i]
    return out


#: A negative number (``-2``, ``-2.5e4``, ``-.5``, ``-inf``): an option such as ``--no-pdf`` is not one.
_NEGATIVE = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


def terminate(signum, frame):
    """SIGTERM ends the run like Ctrl-C, so the temporary folder is removed."""
    raise KeyboardInterrupt
