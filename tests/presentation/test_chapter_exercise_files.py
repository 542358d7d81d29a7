"""Every chapter's exercises.toml: it loads, every placeholder it names is filled, and a file that does not fit
its chapter fails with an error naming the file and the key."""

from __future__ import annotations

import importlib
import importlib.util
import pkgutil
import string
import sys
import textwrap
import tomllib
from importlib import resources

import pytest

from vibration.book import chapters
from vibration.book.presentation.exercises import ChapterExercises, SheetTemplate, TemplateError
from vibration.physics.model import ParameterError

#: The chapter packages that set exercises, found by walking the package (not from the book's registry).
CHAPTERS = sorted(
    info.name
    for info in pkgutil.iter_modules(chapters.__path__)
    if info.ispkg and importlib.util.find_spec(f"vibration.book.chapters.{info.name}.exercises") is not None
)

#: Parameter sets beside the defaults that take the other branches of the sheets (names a chapter lacks are
#: dropped; a set its schema refuses is skipped): no damping at all, heavy damping, a light low damping.
VARIANTS = (
    {"c_nominal": 0.0, "c_low": 0.0, "c_high": 0.0, "c_unstable": 0.0},
    {"c_nominal": 20.0, "c_low": 20.0, "c_high": 40.0, "c_flutter": 5.0},
    {"m": 2.0, "k": 30.0, "F0": 3.0, "c_nominal": 0.8, "c_low": 0.15, "c_high": 12.0, "omega_ref": 2.5},
)
#: Chapters whose exercises read a data folder: each parameter set is a whole analysis, so only the defaults.
SLOW = {"real_oscillator"}


def _data(chapter: str) -> dict:
    return tomllib.loads(
        resources.files(f"vibration.book.chapters.{chapter}").joinpath("exercises.toml").read_text("utf-8")
    )


def _module(chapter: str):
    return importlib.import_module(f"vibration.book.chapters.{chapter}.exercises")


def _records(chapter: str) -> list:
    Params = importlib.import_module(f"vibration.book.chapters.{chapter}.params").Params
    out = [Params()]
    for values in () if chapter in SLOW else VARIANTS:
        try:
            out.append(Params.from_values({k: v for k, v in values.items() if k in Params.SCHEMA.names()}))
        except ParameterError:
            continue
    return out


def _names(template: str) -> set[str]:
    return {key for _, key, _, _ in string.Formatter().parse(template) if key is not None}


def _placeholders(data: dict) -> set[str]:
    """Every name the file's templates, phrases, conditions and answers ask of the chapter, read directly."""
    out = set()
    for item in data["exercise"]:
        texts = [item["text"], item["worked"], item.get("correct", ""), *item.get("options", {}).values()]
        for key, phrases in item.get("phrases", {}).items():
            out.add(key)
            texts += phrases.values()
        for text in texts:
            out |= _names(text)
        if "when" in item:
            out.add(item["when"])
        for answer in item.get("answers", ()):
            out |= {answer[f] for f in ("value", "rtol", "atol") if isinstance(answer.get(f), str)}
    return out


def test_the_chapters_with_exercises_are_found():
    assert {"reproduction", "claims_audit", "solver_accuracy", "stability", "real_oscillator", "tmd"} <= set(CHAPTERS)
    assert len(CHAPTERS) == 12


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_the_data_file_loads_and_is_the_modules_sheet(chapter):
    data = _data(chapter)
    mod = _module(chapter)
    assert isinstance(mod.exercises, ChapterExercises)
    assert mod.exercises.template.file == f"vibration/book/chapters/{chapter}/exercises.toml"
    assert (mod.QUESTION, mod.LEVEL) == (data["question"], data["level"])
    assert mod.OBJECTIVES == tuple(data["objectives"]) and mod.PREREQUISITES == tuple(data["prerequisites"])
    assert mod.SHEET.chapter == mod.CHAPTER == importlib.import_module(mod.__package__ + ".params").SCHEMA.notebook
    assert [item["id"] for item in mod.exercises.template.exercises] == [item["id"] for item in data["exercise"]]


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.parametrize("chapter", CHAPTERS)
def test_every_placeholder_is_filled(chapter):
    mod, data = _module(chapter), _data(chapter)
    computed, shown = set(), set()
    for params in _records(chapter):
        computed |= set(mod.values(params))
        for ex in mod.exercises(params):
            shown.add(ex.id)
            rendered = [ex.text, ex.worked, ex.correct or "", *(c.text for c in ex.choices)]
            rendered += [f"{a.quantity} {a.symbol} {a.unit}" for a in ex.answers]
            for text in rendered:
                assert "{" not in text and "}" not in text, f"{ex.id}: a placeholder left in {text!r}"
            assert not ex.choices or ex.correct in {c.key for c in ex.choices}
    assert shown == {item["id"] for item in data["exercise"]}, "an exercise no parameter set shows"
    # placeholders inside phrases a branch did not take are checked too: each names a value the chapter computes
    assert _placeholders(data) <= computed, sorted(_placeholders(data) - computed)


def test_no_record_means_the_defaults_and_another_record_is_refused():
    mod = _module("solver_accuracy")
    Params = importlib.import_module("vibration.book.chapters.solver_accuracy.params").Params
    assert mod.exercises() == mod.exercises(Params())
    assert mod.exercises(Params(t_end=80.0)) != mod.exercises(Params())
    with pytest.raises(ParameterError, match=r"params = \{'t_end': 80\.0\} is not allowed: allowed a Params record"):
        mod.exercises({"t_end": 80.0})


# ---------------------------------------------------------------------------------------------------------
# A data file that does not fit: read from a package of its own, so the error names a real file

SOURCE = textwrap.dedent(
    """\
    question = "How fast?"
    level = "core"
    objectives = ["Compute ω_d.", "Compute ζ.", "Explain the decay."]
    prerequisites = ["algebra"]

    [[exercise]]
    id = "01.1"
    kind = "numerical"
    text = "With ζ = {zeta}, compute ω<sub>d</sub> (rad/s)."
    worked = "ω<sub>d</sub> = {wd:.5} rad/s."
    answers = [{ quantity = "omega_d", symbol = "ω<sub>d</sub>", value = "wd", unit = "rad/s", rtol = 1e-3 }]

    [[exercise]]
    id = "01.2"
    kind = "conceptual"
    text = "Is it damped?"
    worked = "ζ = {zeta} > 0."
    options = { a = "yes", b = "no" }
    correct = "a"
    """
)
VALUES = {"zeta": 0.1, "wd": 4.465145}
FILE = "sheetdata/exercises.toml"


def _read(tmp_path, monkeypatch, source: str) -> SheetTemplate:
    package = tmp_path / "sheetdata"
    package.mkdir()
    (package / "__init__.py").write_text("", encoding="utf-8")
    (package / "exercises.toml").write_text(source, encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.delitem(sys.modules, "sheetdata", raising=False)  # each test's own folder, not a cached one
    importlib.invalidate_caches()
    return SheetTemplate.read("sheetdata", chapter="01_x")


def test_the_fitting_file_reads_and_fills(tmp_path, monkeypatch):
    template = _read(tmp_path, monkeypatch, SOURCE)
    assert template.file == FILE
    first, second = template.fill(VALUES)
    assert (first.text, first.worked) == (
        "With ζ = 0.1, compute ω<sub>d</sub> (rad/s).",
        "ω<sub>d</sub> = 4.4651 rad/s.",
    )
    assert second.worked == "ζ = 0.1 > 0."


def test_an_unknown_placeholder_names_the_file_the_exercise_and_the_placeholder(tmp_path, monkeypatch):
    template = _read(tmp_path, monkeypatch, SOURCE.replace("ζ = {zeta} > 0", "ζ = {zeta_typo} > 0"))
    with pytest.raises(
        TemplateError,
        match=rf"^{FILE}: chapter 01_x, exercise 01\.2, worked: the placeholder \{{zeta_typo\}} names no value",
    ):
        template.fill(VALUES)


def test_an_unknown_placeholder_in_a_chapters_own_file_is_found(tmp_path, monkeypatch):
    """The stability chapter's own file with one placeholder misspelt, filled with the chapter's own values."""
    stability = _module("stability")
    source = resources.files("vibration.book.chapters.stability").joinpath("exercises.toml").read_text("utf-8")
    assert source.count("{omega_iso}") == 1
    template = _read(tmp_path, monkeypatch, source.replace("{omega_iso}", "{omega_isolation}"))
    broken = ChapterExercises(template=template, params=stability.exercises.params, values=stability.values)
    with pytest.raises(TemplateError, match=rf"^{FILE}: chapter 01_x, exercise 06\.3, worked: the placeholder "
                       r"\{omega_isolation\} names no value"):  # fmt: skip
        broken()


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda s: s.replace('level = "core"\n', ""), r"field level is missing"),
        (lambda s: s.replace('question = "How fast?"\n', ""), r"field question is missing"),
        (
            lambda s: s.replace('worked = "ω<sub>d</sub> = {wd:.5} rad/s."\n', ""),
            r"exercise 01\.1: field worked is missing",
        ),
        (lambda s: s.replace('correct = "a"\n', ""), r"exercise 01\.2: field correct is missing"),
        (lambda s: s.replace(', unit = "rad/s"', ""), r"exercise 01\.1, answer omega_d: field unit is missing"),
        (lambda s: s.replace('id = "01.2"\n', ""), r"exercise 2: field id is missing"),
        (lambda s: s.replace("[[exercise]]", "[[exercises]]"), r"field exercises is not allowed at the top"),
        (lambda s: s.replace("rtol = 1e-3", "rtol = -1e-3"), r"answer omega_d: rtol = -0\.001 is not allowed"),
        (lambda s: s.replace("{wd:.5}", "{wd:.5"), r"exercise 01\.1, worked: .*brace is written twice"),
        (
            lambda s: s.replace("{zeta}, compute", "{zeta.real}, compute"),
            r"01\.1, text: the placeholder \{zeta\.real\}",
        ),
        (lambda s: s.replace('id = "01.2"', 'id = "01.1"'), r"exercise 01\.1: id 01\.1 is set twice"),
        (lambda s: s.replace('level = "core"', 'level = "basic"'), r"level = 'basic' is not allowed"),
        (lambda s: s.replace('question = "How fast?"', "question = How fast?"), r"the file is not valid TOML"),
    ],
)
def test_a_file_that_does_not_fit_fails_when_read_naming_the_file_and_the_key(tmp_path, monkeypatch, edit, message):
    source = edit(SOURCE)
    assert source != SOURCE
    with pytest.raises(TemplateError, match=rf"^{FILE}: chapter 01_x.*{message}"):
        _read(tmp_path, monkeypatch, source)
