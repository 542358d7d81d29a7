"""Exercises for a run, checked answers and exercise sheets: ``python -m vibration.report exercises``.

Every chapter package may hold a module ``exercises`` (objectives, prerequisites and
``exercises(params)``, see :mod:`vibration.book.presentation.exercises`). This module, in the layer that
sees every chapter, gathers them:

- :func:`exercises` and :func:`check`: a chapter's exercises for any accepted parameters, and the
  verdict on a student's answer with a hint that never states the answer;
- :func:`objectives` and :func:`exercise_section`: the two notebook cells that open and close a
  chapter (the section remembers the run's parameters, so a later ``check`` uses them);
- :func:`main`: the runner's ``exercises`` subcommand, writing sheets, answer keys and
  ``tables/answers.csv`` for one run, a roster (``--variants roster.csv``) or ``N`` drawn sets
  (``--variants N --seed S``), with no notebook executed.

Examples
--------
>>> [e.id for e in exercises("04")][:2]
['04.1', '04.2']
>>> check("04.2", 0.5, quantity="bandwidth").correct
True
>>> print(check("04.2", 0.5 / 6.283185307179586, quantity="bandwidth").hint)
This looks like a frequency in Hz; the answer is asked in rad/s (ω = 2π f).
"""

from __future__ import annotations

import argparse
import csv
import html
import importlib
import math
import re
import sys
import time
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from ...physics.model import ParameterError
from ..presentation.exercises import (
    Checked,
    Exercise,
    answer_markdown,
    check_answer,
    objectives_markdown,
    objectives_text,
    question_markdown,
    section_markdown,
    section_text,
)
from .cli import protect_negative_values
from .downloads import build_wheel as build_wheel  # the downloads, importable from here as before
from .downloads import download_cell as download_cell
from .downloads import wheel_name as wheel_name
from .downloads import write_downloads as write_downloads
from .registry import chapter_packages

__all__ = [
    "ANSWERS_HEADER",
    "TEACHING_RANGES",
    "check",
    "exercise_section",
    "fold_answers",
    "exercises",
    "main",
    "objectives",
    "teaching_variants",
]

#: The columns of ``tables/answers.csv``.
ANSWERS_HEADER = ("id", "chapter", "exercise", "quantity", "value", "unit", "rtol", "atol")

#: Ranges ``--variants N`` draws from (low, high, unit), inside every chapter's schema; a set's
#: ``omega_res`` is its own natural frequency and ``omega_ref`` two thirds of it (to 0.01 rad/s),
#: so "resonant" and "reference" keep their meaning for every student.
TEACHING_RANGES: dict[str, tuple[float, float, str]] = {
    "m": (0.5, 2.0, "kg"),
    "k": (10.0, 40.0, "N/m"),
    "F0": (2.0, 10.0, "N"),
    "c_low": (0.05, 0.2, "N s/m"),
    "c_nominal": (0.3, 1.0, "N s/m"),
    "c_high": (10.0, 20.0, "N s/m"),
}

#: Most students of one roster or draw, and the wall-time budget of one student's answers, s.
MAX_STUDENTS = 5000
STUDENT_BUDGET_S = 60.0

_RUN_PARAMS: dict[str, object] = {}  # chapter stem -> the parameters its exercise section was shown with


def _packages() -> dict[str, str]:

    return chapter_packages()


def _modules() -> dict[str, object]:
    """Notebook stem -> the chapter's ``exercises`` module, for the chapters that have one."""
    out = {}
    for stem, pkg in _packages().items():
        name = f"vibration.book.chapters.{pkg}.exercises"
        try:
            out[stem] = importlib.import_module(name)
        except ModuleNotFoundError as exc:
            if exc.name != name:
                raise
    return out


def _stem(chapter: str) -> str:
    """The notebook stem of ``chapter`` ("04", "4", "04_frequency_response" or "frequency_response")."""
    stems = _packages()
    key = str(chapter).strip()
    for stem, pkg in stems.items():
        number = stem.split("_", 1)[0]
        if key in (stem, pkg, number) or (key.isdigit() and int(key) == int(number)):
            return stem
    raise ParameterError(f"chapter = {chapter!r} does not exist: allowed {', '.join(stems)}")


def _module(chapter: str):
    stem = _stem(chapter)
    mods = _modules()
    if stem not in mods:
        raise ParameterError(f"chapter {stem} has no exercises: allowed {', '.join(mods)}")
    return stem, mods[stem]


def _params(stem: str, params):
    """The chapter's ``Params`` record from ``params`` (None: the run's or the defaults; a mapping; a record)."""
    Params = importlib.import_module(f"vibration.book.chapters.{_packages()[stem]}.params").Params
    if params is None:
        params = _RUN_PARAMS.get(stem)
    if params is None:
        return Params()
    if isinstance(params, Params):
        return params
    if hasattr(params, "as_dict"):
        params = params.as_dict()
    if not isinstance(params, Mapping):
        raise ParameterError(
            f"params = {params!r} is not allowed: allowed a mapping of names to values, a Params record or None"
        )
    names = set(Params.SCHEMA.names())
    return Params.from_values({k: v for k, v in params.items() if k in names})


def exercises(chapter: str, *, params=None) -> list[Exercise]:
    """The exercises of ``chapter`` for ``params``, every numerical answer computed from them.

    Parameters
    ----------
    chapter : str
        "04", "04_frequency_response" or "frequency_response".
    params : mapping or Params, optional
        Parameter values (names of the chapter's schema; others are ignored). Default: the values the
        chapter's exercise section was last shown with in this session, else the chapter's defaults.

    Returns
    -------
    list of Exercise
    """
    stem, mod = _module(chapter)
    return list(mod.exercises(_params(stem, params)))


def check(exercise_id: str, answer, *, params=None, quantity: str | None = None) -> Checked:
    """Whether ``answer`` answers exercise ``exercise_id`` ("04.2"), with a hint; the answer is never shown.

    ``answer`` is a number (with ``quantity`` naming it when the exercise asks for several), a mapping
    quantity -> number, the numbers in the order asked, or the letter of an option. ``params`` as in
    :func:`exercises`.
    """
    if not isinstance(exercise_id, str) or not re.fullmatch(r"\d{2}\.\d+", exercise_id):
        raise ParameterError(
            f"exercise_id = {exercise_id!r:.60} is not an exercise: allowed a chapter number and an exercise number, "
            'such as "04.2"'
        )
    number = exercise_id.split(".", 1)[0]
    try:
        stem = _stem(number)
    except ParameterError:
        raise ParameterError(
            f"exercise_id = {exercise_id!r} names no chapter: allowed one of {', '.join(sorted(_packages()))}"
        ) from None
    found = [e for e in exercises(stem, params=params) if e.id == exercise_id]
    if not found:
        ids = ", ".join(e.id for e in exercises(stem, params=params))
        raise ParameterError(f"exercise_id = {exercise_id!r} does not exist for these parameters: allowed {ids}")
    return check_answer(found[0], answer, quantity=quantity)


class _Block:
    """A notebook output: Markdown, plain text and (optionally) metadata the book build reads."""

    def __init__(self, markdown: str, text: str, metadata: dict | None = None) -> None:
        self.markdown, self.text, self.metadata = markdown, text, metadata

    def _repr_markdown_(self):
        return (self.markdown, self.metadata) if self.metadata else self.markdown

    def __repr__(self) -> str:
        return self.text


def objectives(chapter: str) -> _Block:
    """The chapter's learning objectives and prerequisites (the notebook's first cell after the parameters)."""
    _, mod = _module(chapter)
    return _Block(
        objectives_markdown(mod.OBJECTIVES, mod.PREREQUISITES), objectives_text(mod.OBJECTIVES, mod.PREREQUISITES)
    )


_INTRO = "Every number below follows this run's parameters. "
#: Both introductions name no code and no tool, and read the same on screen and on paper: how to call the
#: checker is in the appendix on running the chapters (:func:`vibration.book.publishing.appendices.symbols_markdown`).
_CHECKED = (
    "The chapter's notebook checks an answer: it says whether the answer is right within the stated tolerance "
    "and gives a hint if not, without giving the answer away (the appendix on running the chapters shows how)."
)
_INTRO_NOTEBOOK = _INTRO + _CHECKED + " The worked answers are in the book's appendix of answers."
_INTRO_BOOK = (
    _INTRO
    + _CHECKED
    + " The worked answers are in the appendix of answers, and on the web page also under each exercise."
)

#: Key of the exercise section's output metadata: the chapter and the parameters it was shown with.
SECTION_KEY = "vibration-exercises"


def exercise_section(chapter: str, params=None) -> _Block:
    """The chapter's closing exercises for the run's ``params``, questions only; later :func:`check` calls use them.

    The output's metadata records the chapter and its parameters, so that the book build folds each
    worked answer under its question (:func:`fold_answers`); the notebook itself stores no answer.
    """
    stem, _ = _module(chapter)
    record = _params(stem, params)
    _RUN_PARAMS[stem] = record
    exs = exercises(stem, params=record)
    md = _INTRO_NOTEBOOK + "\n\n" + section_markdown(exs, folded=False)
    meta = {SECTION_KEY: {"chapter": stem, "params": record.as_dict()}}
    return _Block(md, "Exercises\n" + section_text(exs), meta)


def fold_answers(nb) -> int:
    """Replace each exercise section's output in ``nb`` by its questions with their worked answers folded.

    The answers are recomputed from the parameters the section recorded. Returns how many sections
    were folded.
    """
    done = 0
    for cell in nb.cells:
        for out in cell.get("outputs", []) if cell.cell_type == "code" else []:
            info = out.get("metadata", {}).get("text/markdown", {}).get(SECTION_KEY)
            if not info:
                continue
            exs = exercises(info["chapter"], params=dict(info["params"]))
            out["data"]["text/markdown"] = _INTRO_BOOK + "\n\n" + section_markdown(exs)
            done += 1
    return done


# ---------------------------------------------------------------------------------------------------------
# Sheets


def _md_html(text: str) -> str:
    from markdown_it import MarkdownIt

    return MarkdownIt("commonmark", {"html": True}).render(text)


_STYLE = (
    "body{font-family:sans-serif;max-width:48em;margin:2em auto;line-height:1.45}"
    "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:.2em .6em;text-align:left}"
    ".answer{background:#f4f6f8;border-left:4px solid #5a7;padding:.3em 1em;margin-bottom:1.5em}"
)


def _params_table(stems: list[str], values: Mapping) -> str:
    """Every parameter of the sheet's chapters with this sheet's value (bold where it is not the book's)."""
    seen, rows = set(), []
    for stem in stems:
        schema = importlib.import_module(f"vibration.book.chapters.{_packages()[stem]}.params").SCHEMA
        for p in schema.params:
            if p.name in seen:
                continue
            seen.add(p.name)
            value = values.get(p.name, p.default)
            shown = html.escape(f"{value:g}" if isinstance(value, float) else str(value))
            shown = f"<strong>{shown}</strong>" if p.name in values else shown
            rows.append(
                f"<tr><td>{html.escape(p.symbol)}</td><td>{shown}</td><td>{html.escape(p.unit)}</td>"
                f"<td>{html.escape(p.meaning)}</td><td><code>{html.escape(p.name)}</code></td></tr>"
            )
    head = "<tr><th>symbol</th><th>value</th><th>unit</th><th>meaning</th><th>name</th></tr>"
    return f"<table>{head}{''.join(rows)}</table>"


def _sheet_html(sid: str, values: Mapping, sections: list[tuple[str, list[Exercise]]], *, key: bool) -> str:
    title = f"Exercises: {sid}" + (" (answers)" if key else "")
    stems = [stem for stem, _ in sections]
    body = [f"<h1>{html.escape(title)}</h1>", "<h2>Your parameters</h2>", _params_table(stems, values)]
    for stem, exs in sections:
        body.append(f"<h2>{html.escape(stem)}</h2>")
        for ex in exs:
            body.append(_md_html(question_markdown(ex)))
            if key:
                values_md = "".join(f"<li>{a.symbol or a.quantity} = {a.value:.6g} {a.unit}</li>" for a in ex.answers)
                body.append(
                    f'<div class="answer">{_md_html(answer_markdown(ex))}'
                    + (f"<ul>{values_md}</ul>" if values_md else "")
                    + "</div>"
                )
    return (
        f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
        f"<style>{_STYLE}</style></head><body>{''.join(body)}</body></html>\n"
    )


def _answer_rows(sid: str, sections) -> list[tuple]:
    rows = []
    for stem, exs in sections:
        for ex in exs:
            if ex.kind == "conceptual":
                rows.append((sid, stem, ex.id, "choice", ex.correct, "", "", ""))
            for a in ex.answers:
                rows.append((sid, stem, ex.id, a.quantity, repr(float(a.value)), a.unit, repr(a.rtol), repr(a.atol)))
    return rows


def _sections(stems: list[str], values: Mapping) -> list[tuple[str, list[Exercise]]]:
    t0 = time.perf_counter()
    out = []
    for stem in stems:
        out.append((stem, exercises(stem, params=values)))
        if time.perf_counter() - t0 > STUDENT_BUDGET_S:
            raise RuntimeError(f"one set of answers took over {STUDENT_BUDGET_S:g} s (stopped at chapter {stem})")
    return out


def _accepting(stems: list[str]) -> dict[str, object]:
    """Parameter name -> the schemas (of ``stems``) that declare it."""
    out: dict[str, list] = {}
    for stem in stems:
        schema = importlib.import_module(f"vibration.book.chapters.{_packages()[stem]}.params").SCHEMA
        for name in schema.names():
            out.setdefault(name, []).append(schema)
    return out


def _typed(name: str, text: str, schemas: list, where: str):
    param = schemas[0][name]
    try:
        if isinstance(param.default, int) and not isinstance(param.default, bool):
            value = int(text)
        elif isinstance(param.default, float):
            value = float(text)
        else:
            value = text
    except ValueError:
        raise ParameterError(f"{where}: {name} = {text!r} is not a number") from None
    try:
        for schema in schemas:
            value = schema[name].check(value)
    except ParameterError as exc:
        raise ParameterError(f"{where}: {exc}") from None
    return value


def _validate(values: dict, stems: list[str], where: str) -> dict:
    accepting = _accepting(stems)
    for stem in stems:
        schema = importlib.import_module(f"vibration.book.chapters.{_packages()[stem]}.params").SCHEMA
        try:
            schema.check({k: v for k, v in values.items() if k in schema.names()})
        except ParameterError as exc:
            raise ParameterError(f"{where}: {exc} (chapter {stem})") from None
    unknown = [k for k in values if k not in accepting]
    if unknown:
        raise ParameterError(
            f"{where}: parameter {unknown[0]!r} is not declared by any chapter asked: allowed {', '.join(accepting)}"
        )
    return values


def read_roster(path: Path, stems: list[str]) -> list[tuple[str, dict]]:
    """The students of a roster CSV (first column ``id``, then ``-p`` names), each row validated."""
    accepting = _accepting(stems)
    with open(path, newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    if not rows or not rows[0] or rows[0][0].strip() != "id":
        raise ParameterError(f"{path.name}: the first column must be 'id', found {rows[0][:1] if rows else 'nothing'}")
    header = [h.strip() for h in rows[0]]
    for col, name in enumerate(header[1:], start=2):
        if name not in accepting:
            raise ParameterError(
                f"{path.name}, column {col} ({name!r}): not a parameter of the chapters asked: "
                f"allowed {', '.join(accepting)}"
            )
    if len(rows) - 1 > MAX_STUDENTS:
        raise ParameterError(f"{path.name}: {len(rows) - 1} students: allowed at most {MAX_STUDENTS}")
    out, seen = [], set()
    for line, row in enumerate(rows[1:], start=2):
        if not any(cell.strip() for cell in row):
            continue
        if len(row) != len(header):
            raise ParameterError(f"{path.name}, row {line}: {len(row)} cells, the header has {len(header)}")
        sid = row[0].strip()
        if not sid or not all(ch.isalnum() or ch in "-_" for ch in sid) or sid == "run" or sid in seen:
            raise ParameterError(
                f"{path.name}, row {line}, column 1 (id): {sid!r} must be a unique name of letters, digits, - or _ "
                "(not 'run')"
            )
        seen.add(sid)
        values = {}
        for col, (name, text) in enumerate(zip(header[1:], row[1:], strict=True), start=2):
            if text.strip():
                values[name] = _typed(name, text.strip(), accepting[name], f"{path.name}, row {line}, column {col}")
        out.append((sid, _validate(values, stems, f"{path.name}, row {line}")))
    return out


def teaching_variants(n: int, seed: int, stems: list[str]) -> list[tuple[str, dict]]:
    """``n`` parameter sets drawn uniformly within :data:`TEACHING_RANGES` (3 significant digits)."""
    if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= MAX_STUDENTS:
        raise ParameterError(f"--variants = {n!r} is out of range: allowed an integer 1 <= N <= {MAX_STUDENTS}")
    rng = np.random.default_rng(seed)
    accepting = _accepting(stems)
    out = []
    for i in range(n):
        values = {name: float(f"{rng.uniform(lo, hi):.3g}") for name, (lo, hi, _) in TEACHING_RANGES.items()}
        wn = math.sqrt(values["k"] / values["m"])
        values["omega_res"] = round(wn, 2)
        values["omega_ref"] = round(2 * wn / 3, 2)
        values = {k: v for k, v in values.items() if k in accepting}
        out.append((f"s{i + 1:03d}", _validate(values, stems, f"variant {i + 1}")))
    return out


def write_sheets(stems: list[str], students: list[tuple[str, dict]], out: Path) -> Path:
    """Each student's sheet and key in ``out/sheets``, every answer in ``out/tables/answers.csv``."""
    sheets, tables = out / "sheets", out / "tables"
    sheets.mkdir(parents=True, exist_ok=True)
    tables.mkdir(parents=True, exist_ok=True)
    rows = []
    for sid, values in students:
        sections = _sections(stems, values)
        (sheets / f"{sid}.html").write_text(_sheet_html(sid, values, sections, key=False), encoding="utf-8")
        (sheets / f"{sid}-answers.html").write_text(_sheet_html(sid, values, sections, key=True), encoding="utf-8")
        rows += _answer_rows(sid, sections)
    path = tables / "answers.csv"
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(ANSWERS_HEADER)
        w.writerows(rows)
    return path


def main(argv: list[str]) -> int:
    """``python -m vibration.report exercises [CHAPTER ...] [-p NAME VALUE ...] [--variants ...] --out DIR``."""
    parser = argparse.ArgumentParser(
        prog="python -m vibration.report exercises", description="exercise sheets and answer keys, no notebook run"
    )
    parser.add_argument("chapters", nargs="*", help="chapters (default: every chapter with exercises)")
    parser.add_argument("-p", "--parameter", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    parser.add_argument("--variants", help="a roster CSV (first column id, then -p names) or a number N of sets")
    parser.add_argument("--seed", type=int, default=0, help="seed of --variants N (default 0)")
    parser.add_argument("--out", required=True, help="output folder: sheets/ and tables/answers.csv")

    args = parser.parse_args(protect_negative_values(list(argv)))
    try:
        mods = _modules()
        stems = [_stem(c) for c in args.chapters] or list(mods)
        missing = [s for s in stems if s not in mods]
        if missing:
            raise ParameterError(f"chapter {missing[0]} has no exercises: allowed {', '.join(mods)}")
        accepting = _accepting(stems)
        base = {}
        for name, text in args.parameter:
            if name not in accepting:
                raise ParameterError(
                    f"parameter {name!r} (value {text!r}) is not declared by the chapters asked: "
                    f"allowed {', '.join(accepting)}"
                )
            base[name] = _typed(name, text.strip(), accepting[name], "-p")
        _validate(base, stems, "-p")
        if args.variants is None:
            students = [("run", base)]
        elif args.variants.strip().isdigit():
            students = [(s, base | v) for s, v in teaching_variants(int(args.variants), args.seed, stems)]
        else:
            students = [(s, base | v) for s, v in read_roster(Path(args.variants), stems)]
        for sid, values in students:
            _validate(values, stems, f"student {sid}")
        path = write_sheets(stems, students, Path(args.out))
    except (ParameterError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except RuntimeError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    print(f"wrote {len(students)} sheet(s) and their keys to {Path(args.out) / 'sheets'}, answers to {path}")
    return 0


# ---------------------------------------------------------------------------------------------------------
# The book: chapter blurbs and the course plan (the downloads: vibration.book.publishing.downloads)

#: Weeks of a suggested one-semester course: (weeks, chapters, exercises, what).
COURSE_PLAN = (
    ("1–2", "1", "01.1–01.5", "the model, its exact solution and the paper's method"),
    ("3", "2", "02.1–02.5", "reading a paper's claims against the exact solution"),
    ("4", "3", "03.1–03.4", "what a numerical solution's error depends on"),
    ("5–6", "4", "04.1–04.5", "frequency response, bandwidth, quality factor, energy"),
    ("7", "5", "05.1–05.4", "exploring the response with the sliders; a sheet per student"),
    ("8–12 (optional)", "6–8", "06.1–08.3", "advanced: stability and design, control, absorbers"),
)


def chapter_blurb(stem: str) -> str:
    """ "(core) Question?" for the front page: the chapter's question and level, or "" when it has none."""
    mod = _modules().get(stem)
    if mod is None or not hasattr(mod, "QUESTION"):
        return ""
    return f"*{mod.LEVEL}*: {mod.QUESTION}"


def course_plan_markdown() -> str:
    """The suggested course plan: Part I as a second-year course, then optional advanced chapters."""
    lines = [
        "### A suggested course",
        "",
        "Part I (chapters 1–5) is the core course, for second-year engineering students who know Newton's second "
        "law and linear ordinary differential equations; Parts II and III are advanced (graduate) material. "
        "Every chapter opens with its learning objectives and ends with exercises whose answers follow the run's "
        "parameters; the runner writes each student a sheet with their own numbers and a key.",
        "",
        "| weeks | chapters | exercises | topic |",
        "|---|---|---|---|",
    ]
    lines += [f"| {w} | {c} | {e} | {t} |" for w, c, e, t in COURSE_PLAN]
    return "\n".join(lines)
