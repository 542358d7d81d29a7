"""Every number a reader sees follows the book's one number format, and no mark of the test machinery shows.

The rules are written here independently of :mod:`vibration.book.presentation.numbers` (regular expressions
over the text a reader sees: Markdown cells and the Markdown or HTML outputs the book renders), so a
formatter that drifts from them fails. Years, run numbers and counts are integers without signs and
pass every rule; a count grouped by narrow no-break spaces (U+202F) must be grouped in threes from the
right. Inline maths (``$...$``) is typeset, not a number format, and is left out.

Every chapter and the front page are checked (:data:`CHECKED`).
"""

from __future__ import annotations

import html
import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CHECKED = ("00", "01", "02", "03", "04", "05", "06", "07", "08", "09", "10", "11", "12")

#: (rule, pattern) pairs; each match is a violation.
RULES = [
    ("e-notation instead of ×10ⁿ", re.compile(r"(?<![\w.])\d+(?:\.\d+)?[eE][+-]?\d+\b")),
    ("hyphen instead of the minus sign", re.compile(r"(?:^|(?<=[\s(=\[,;:]))-\d")),
    ("spaces around × in a power of ten", re.compile(r"\d\s+×\s*10[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]|\d×\s+10[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]")),
    ("a decimal below 10⁻⁴ written in full", re.compile(r"(?<![\d.])0\.0000\d")),
    ("≈ glued to a number, or after = or ±", re.compile(r"≈\d|[=±]\s*≈")),
    ("nan or inf in the text", re.compile(r"\b(?:nan|inf)\b")),
    (
        "a count not grouped in threes from the right",
        re.compile(r"\d{4,}\u202f\d|\d\u202f(?=\d)(?!\d{3}(?!\d))|(?<![\d\u202f])\d\u202f\d{3}(?![\d\u202f])"),
    ),
    ("a mark of the test machinery", re.compile(r"⟪|⟫|regression comparison|papermill|vibdoc\d")),
]


def _visible(text: str) -> str:
    """The text a reader sees: tags, attributes, inline and display maths and code spans removed."""
    text = re.sub(r"<script.*?</script>|<style.*?</style>", " ", text, flags=re.S | re.I)
    text = re.sub(r"\$\$.*?\$\$|\$[^$\n]+\$", " ", text, flags=re.S)
    text = re.sub(r"<math.*?</math>", " ", text, flags=re.S)
    text = re.sub(r"```.*?```|~~~.*?~~~", lambda m: _fence_body(m.group(0)), text, flags=re.S)
    text = re.sub(r"`[^`\n]*`", " ", text)
    text = re.sub(r"<[^>]*>", " ", text)
    return html.unescape(text)


def _fence_body(block: str) -> str:
    """A list-table fence keeps its cells (they are what the reader sees); other fences are code."""
    first, _, body = block.partition("\n")
    if "list-table" not in first:
        return " "
    caption = first.split("}", 1)[-1]
    body = "\n".join(line for line in body.splitlines() if not line.startswith(":"))
    return caption + "\n" + body.rsplit("\n", 1)[0]


#: "value ± error" with both numbers written out (not a complex number "a ± bi", not a power of ten factored
#: out, which the rule reads as its mantissas).
_PAIR = re.compile(r"(?<![\w.×⁰¹²³⁴⁵⁶⁷⁸⁹])(−?\d+(?:\.\d+)?) ± (\d+(?:\.\d+)?)(?![\w.×])")


def _uncertainty_violations(seen: str) -> list[str]:
    """Pairs whose error has more figures than one (two when it starts with 1) or whose value stops at
    another decimal place than its error."""
    bad = []
    for m in _PAIR.finditer(seen):
        value, error = m.group(1), m.group(2)
        figures = error.replace(".", "").lstrip("0")
        if not figures or set(figures) == {"0"}:
            continue  # an exact error, "± 0"
        too_many = len(figures) > 2 or (len(figures) == 2 and figures[0] != "1" and not figures.endswith("0"))
        places = [len(x.partition(".")[2]) for x in (value, error)]
        if too_many or places[0] != places[1]:
            bad.append(seen[max(0, m.start() - 40) : m.end() + 40].replace("\n", " "))
    return bad


def violations(text: str) -> list[tuple[str, str]]:
    """(rule, context) of every violation in ``text``."""
    seen = _visible(text)
    out = []
    for rule, pattern in RULES:
        for m in pattern.finditer(seen):
            out.append((rule, seen[max(0, m.start() - 40) : m.end() + 40].replace("\n", " ")))
    out += [("an uncertainty not written value ± error to one decimal place", c) for c in _uncertainty_violations(seen)]
    return out


def test_the_rules_catch_what_they_should():
    bad = [
        "1.2e-05 m",
        "a drift of -0.5 m",
        "1.27 × 10⁵ N",
        "0.000012 s",
        "λ = ≈0.1037",
        "0.1 ± ≈0.0003",
        "x = nan",
        "not part of the regression comparison",
        "<td>⟪2926 r0.25⟫</td>",
        "9600\u202f00 steps",
        "96\u202f0000 steps",
        "1\u202f234 samples",
        "0.0449 ± 0.001 per run",
        "0.0011 ± 0.00078",
        "16 ± 0.054",
    ]
    for text in bad:
        assert violations(text), text
    good = [
        "1.27×10⁵ N",
        "−0.5 m",
        "in 2024, run 17 of 40",
        "960\u202f000 steps, 4096 samples, 1\u202f800\u202f200 samples, −33\u202f409",
        "<td>11\u202f804</td><td>20\u202f000</td>",
        "0.000512 s",
        "0.1037 ± 0.0003 s⁻¹",
        "0.0449 ± 0.0010, 12 ± 1, −2.47 ± 0.13, 1 ± 0",
        "poles −0.05000 ± 4.472i",
        "ζ ≈ 0.78",
        "Runge-Kutta 4(5)",
        "$10^{-6}$",
        "`1e-6`",
        '<span class="vib-approx" data-value="2.8e-08" data-tol="a1e-07">2.8×10⁻⁸</span>',
    ]
    for text in good:
        assert not violations(text), (text, violations(text))


def _reader_texts(path: Path):
    """The Markdown cells and the outputs the book renders (Markdown, else HTML) of one notebook."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    for i, cell in enumerate(nb["cells"]):
        if cell["cell_type"] == "markdown":
            yield i, "".join(cell["source"])
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            for mime in ("text/markdown", "text/html"):
                if mime in data:
                    yield i, "".join(data[mime])
                    break


@pytest.mark.parametrize("number", CHECKED)
def test_committed_chapter_follows_the_number_format(number):
    (path,) = (ROOT / "notebooks").glob(f"{number}_*.ipynb")
    found = [(i, rule, ctx) for i, text in _reader_texts(path) for rule, ctx in violations(text)]
    assert not found, "\n".join(f"cell {i}: {rule}: …{ctx}…" for i, rule, ctx in found[:20])


def test_built_pages_follow_the_number_format():
    """Every built page of the checked chapters (after `make report`)."""
    pages = [p for p in (ROOT / "build" / "report").glob("*.html") if p.name[:2] in CHECKED]
    if not pages:
        pytest.skip("no built book in build/report (make report builds it)")
    found = []
    for page in pages:
        text = page.read_text(encoding="utf-8")
        article = re.search(r"<article.*?</article>", text, flags=re.S)
        text = re.sub(r"<script.*?</script>|<style.*?</style>", " ", article.group(0) if article else text, flags=re.S)
        text = re.sub(r'<div class="cell_input.*?</div>\s*</div>', " ", text, flags=re.S)
        found += [(page.name, rule, ctx) for rule, ctx in violations(text)]
    assert not found, "\n".join(f"{p}: {rule}: …{ctx}…" for p, rule, ctx in found[:20])
