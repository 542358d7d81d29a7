"""Chapter 12 as the reader sees it (the committed notebook's text): one symbol, one meaning, one number one way.

The notebook's outputs are those of the package (strict nbval compares them), so these checks read what the
book prints: the letters the notation registry settled, angles whose degrees agree with their radians, and one
median where the chapter states the same quantity twice.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from vibration.book.presentation.notation import lookup

NOTEBOOK = Path(__file__).resolve().parents[3] / "notebooks" / "12_real_oscillator.ipynb"


@pytest.fixture(scope="module")
def text() -> str:
    """Markdown cells and Markdown or HTML outputs, tags removed."""
    parts = []
    for cell in json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]:
        if cell["cell_type"] == "markdown":
            parts.append("".join(cell["source"]))
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            for kind in ("text/markdown", "text/html"):
                if kind in data:
                    parts.append(re.sub(r"<[^>]+>", "", "".join(data[kind])))
    return "\n".join(parts)


def test_the_friction_angle_resting_angle_and_exponent_use_the_registry_letters(text):
    # Δ stays a difference (Δζ, ΔBIC): never a quantity of its own, as the friction angle was
    assert not re.search(r"Δ(?![A-Za-zζωκθ])", text), "Δ stands alone"
    assert "\\Delta" not in text
    # c is a damping, p a p-value, a and b the transient's constants, g gravity, u a control force
    for letter in ("c", "p", "a", "b", "g"):
        assert not re.search(rf"resting angle \${letter}\$|\${letter}\$ \(|the gain \${letter}\$", text), letter
    assert "u(t)" not in text
    for symbol, tex in (("θ_f", "\\theta_f"), ("θ_0", "\\theta_0"), ("n", "|^n")):
        assert lookup(symbol).first_chapter == 12
        assert tex in text, symbol
    # the fitted coefficients in the table carry the same letters
    assert re.search(r"θf = [0-9.]+ ± ", text) and re.search(r"; n = [0-9.]+ ± ", text)


def test_every_angle_in_degrees_is_its_printed_radians(text):
    pairs = re.findall(r"(\d+(?:\.\d+)?) rad \((\d+)°\)", text)
    assert len(pairs) >= 5
    for rad, deg in pairs:
        assert abs(math.degrees(float(rad)) - int(deg)) <= 0.5 + 1e-9, (rad, deg)


def test_the_time_to_ninety_percent_is_one_median(text):
    medians = set(re.findall(r"in a median (\d+(?:\.\d+)?) s", text))
    assert len(medians) == 1, medians
