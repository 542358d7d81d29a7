"""The notation registry covers chapters 1-5, the glossary and answers appendices, downloads, tracks and licences."""

from __future__ import annotations

import collections
import json
import re
from pathlib import Path

import nbformat
import pytest

from vibration.book.presentation.notation import SETTLED, SYMBOLS, lookup
from vibration.book.presentation.references import REFERENCES, paper_citation
from vibration.book.publishing import sheets
from vibration.book.publishing.appendices import APPENDICES, answers_markdown, glossary_markdown, usage_markdown

ROOT = Path(__file__).resolve().parents[2]
PART_ONE = ["01_reproduction", "02_claims_audit", "03_solver_accuracy", "04_frequency_response", "05_explore"]
#: LaTeX tokens that are not physical symbols (functions, spacing, operators, Euler's e, the differential d).
NOT_SYMBOLS = {
    "\\sqrt", "\\frac", "\\sin", "\\cos", "\\tan", "\\big", "\\Big", "\\qquad", "\\ne", "\\pm", "\\mp", "\\approx",
    "\\in", "\\left", "\\right", "\\int", "\\tfrac", "\\mathrm", "\\pi", "\\infty", "\\le", "\\ge", "\\cdot",
    "\\times", "\\quad", "\\to", "\\text", "\\lvert", "\\rvert", "\\max", "\\min", "\\exp", "\\log", "\\ln", "e", "d",
    "\\dot", "\\ddot", "\\operatorname", "\\mathrm{atol}", "\\mathrm{rtol}", "\\omega_n\\sin\\omega", "\\Im", "\\Re",
}  # fmt: skip
TOKEN = re.compile(r"\\[a-zA-Z]+(?:_\{?\\?[a-zA-Z0-9]+)?|\b[a-zA-Z](?:_\{?\\?[a-zA-Z0-9]+)?")


def _math_of(stem: str) -> list[str]:
    nb = json.loads((ROOT / "notebooks" / f"{stem}.ipynb").read_text())
    texts = []
    for cell in nb["cells"]:
        if cell["cell_type"] == "markdown":
            texts.append("".join(cell["source"]))
        for out in cell.get("outputs", []):
            md = out.get("data", {}).get("text/markdown")
            if md:
                texts.append("".join(md))
    return [m for t in texts for m in re.findall(r"\$\$?([^$]+)\$\$?", t)]


def test_every_symbol_of_part_one_prose_is_registered():
    known = {t for s in SYMBOLS for t in s.tex}
    missing = collections.Counter()
    for stem in PART_ONE:
        for math in _math_of(stem):
            math = re.sub(r"\\mathrm\{(atol|rtol)\}", "", math)
            for tok in TOKEN.findall(math):
                tok = tok.rstrip("{").replace("{", "")
                if tok in NOT_SYMBOLS or tok in known:
                    continue
                missing[tok] += 1
    assert not missing, f"symbols of chapters 1-5 missing from the notation registry: {dict(missing)}"


def test_registry_gives_one_meaning_per_symbol_and_settles_the_clashes():
    names = [s.symbol for s in SYMBOLS]
    assert len(names) == len(set(names))
    for s in SYMBOLS:
        assert s.meaning and s.unit and s.equation and 0 <= s.first_chapter <= 12, s
    assert lookup("Q").meaning == "quality factor" and lookup("q_u").first_chapter == 7
    assert lookup("ν").meaning.startswith("tuning ratio") and lookup("f").unit == "Hz"
    assert {"Q", "f", "Δ", "c", "p"} <= set(SETTLED)
    assert lookup("θ_0").first_chapter == 12 and lookup("θ_f").first_chapter == 12
    for letter in ("ζ", "ω_d", "Q", "M", "X", "φ"):  # what the lecturer found undefined
        assert lookup(letter)


def test_parameter_symbols_keep_the_registrys_meaning():
    """A chapter's parameter table writes a symbol the notation registry defines only for that quantity (its unit),
    and one symbol has one unit in every chapter (issue 29: one symbol, one meaning)."""
    from vibration.book.publishing.registry import chapter_schemas

    units = collections.defaultdict(set)
    for notebook, schema in chapter_schemas().items():
        for p in schema.params:
            units[p.symbol].add((p.unit.strip() or "1", notebook[:2]))
    registry = {s.symbol: s.unit.strip() or "1" for s in SYMBOLS}
    clashes = {
        symbol: sorted(found)
        for symbol, found in units.items()
        if len({u for u, _ in found}) > 1 or (symbol in registry and {u for u, _ in found} != {registry[symbol]})
    }
    assert clashes == {}


def test_glossary_page_lists_every_symbol():
    md = glossary_markdown()
    assert md.startswith("# Glossary of symbols")
    rows = md.count("\n* - ") - 1  # minus the header row
    assert rows == len(SYMBOLS)
    assert "ω{sub}`d` = ω{sub}`n` √(1 − ζ²)" in md and "quality factor" in md


def test_appendices_in_book_order():
    names = [n for n, _ in APPENDICES]
    assert names[:2] == ["glossary", "symbols"] and "answers" in names and "licences" in names
    assert dict(APPENDICES)["symbols"] == "Running the chapters with other parameters"


def test_answers_appendix_gathers_the_folded_answers():
    from vibration.book.presentation.exercises import section_markdown

    folded = section_markdown(sheets.exercises("04"))
    md = answers_markdown([("4. Frequency response and design", "04_frequency_response", [folded])])
    ids = re.findall(r"^\*\*(\d\d\.\d)\.\*\*", md, re.M)
    assert ids == [e.id for e in sheets.exercises("04")]
    assert "<details" not in md and "0.4504 m" in md  # the default run's amplitude at 3 rad/s, unfolded


def test_usage_starts_from_the_downloaded_wheel():
    md = usage_markdown([])
    first = md.split("\n\n")[1]
    assert sheets.wheel_name() in first and "_static/downloads/" in first


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_downloads_notebook_with_outputs_and_wheel(tmp_path):
    class Page:
        name = "04_frequency_response"
        notebook = nbformat.read(ROOT / "notebooks" / "04_frequency_response.ipynb", as_version=4)

    written = sheets.write_downloads([Page()], tmp_path)
    nb = nbformat.read(written[0], as_version=4)
    assert any(c.get("outputs") for c in nb.cells if c.cell_type == "code")
    assert written[1].name == sheets.wheel_name() and written[1].stat().st_size > 10_000
    cell = sheets.download_cell("04_frequency_response")
    links = re.findall(r'href="([^"]+)"', cell.source)
    assert links == ["_static/downloads/04_frequency_response.ipynb", f"_static/downloads/{sheets.wheel_name()}"]


def test_tracks_plan_and_citation():
    for stem, mod in sheets._modules().items():
        blurb = sheets.chapter_blurb(stem)
        assert blurb.endswith("?"), stem
        assert mod.LEVEL == ("core" if int(stem[:2]) <= 5 else "advanced")
    plan = sheets.course_plan_markdown()
    assert "core course" in plan and "| weeks |" in plan
    paper = REFERENCES[0]
    assert paper.key == "paper" and "not stated" in paper.venue and "2017" in paper.venue
    assert "Authors, venue and year not stated" in paper_citation()
    front = "".join(
        "".join(c["source"]) for c in json.loads((ROOT / "notebooks" / "00_overview.ipynb").read_text())["cells"]
    )
    assert "core course" in front and "CC BY 4.0" in front and "MIT License" in front


def test_licence_files():
    code = (ROOT / "LICENSE").read_text()
    text = (ROOT / "LICENSE-text").read_text()
    assert code.startswith("MIT License") and "CC BY 4.0" in code
    assert "Creative Commons Attribution 4.0 International" in text and "data/lab_oscillator" in text
