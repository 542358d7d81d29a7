"""The book's appendices, generated: the glossary (from the notation registry
:mod:`vibration.book.presentation.notation`), "Running the chapters with other parameters" (from the
chapters' parameter schemas), "Using the package" (each chapter package's ``usage.md``), the answers
to the exercises (gathered from the chapters as this run computed them), the licences and the
references (:mod:`vibration.book.presentation.references`).

Examples
--------
>>> from vibration.book.presentation.schema import Param, Schema
>>> omega_max = Param(name="omega_max", symbol="ω_max", default=10.0, unit="rad/s", low=0.0, high=1e3,
...                   meaning="upper frequency", low_open=True)
>>> s = Schema(notebook="04_x", params=(omega_max,))
>>> print(symbols_markdown({"04_x": s}).splitlines()[-4])
  - 0 < ω{sub}`max` ≤ 1000
"""

from __future__ import annotations

import re
from importlib.resources import files

from ..presentation.notation import SETTLED, SYMBOLS
from ..presentation.numbers import sig
from ..presentation.references import bibliography_markdown
from ..presentation.tables import symbol_myst

#: (document name, title) of the appendices, in book order.
APPENDICES = (
    ("glossary", "Glossary of symbols"),
    ("symbols", "Running the chapters with other parameters"),
    ("using", "Using the package"),
    ("answers", "Answers to the exercises"),
    ("licences", "Licences"),
    ("references", "References"),
)


def _number(notebook: str) -> int:
    return int(notebook.split("_", 1)[0])


def _range(p) -> str:
    if p.choices:
        return ", ".join(map(str, p.choices))
    op = "<" if p.low_open else "≤"
    sym = symbol_myst(p.symbol)
    lo = "" if p.low is None else f"{sig(p.low)} {op} "
    hi = "" if p.high is None else f" ≤ {sig(p.high)}"
    return f"{lo}{sym}{hi}"


def symbols_markdown(schemas: dict) -> str:
    """The table of symbols: every parameter of every chapter once per (symbol, name, unit), with its chapters."""
    rows: dict[tuple, dict] = {}
    for notebook in sorted(schemas, key=_number):
        for p in schemas[notebook].params:
            key = (p.symbol, p.name, p.unit)
            row = rows.setdefault(key, {"param": p, "chapters": []})
            row["chapters"].append(_number(notebook))
    lines = [
        "# Running the chapters with other parameters",
        "",
        "Every parameter a reader can change, as the book writes it, with its unit, its allowed range and "
        "the name that sets it in a run of the report (`python -m vibration.report -p NAME VALUE`; "
        "`python -m vibration.report exercises -p NAME VALUE --out DIR` writes the exercise sheets and their "
        "answers for the same values). A symbol used by several chapters with one meaning is listed once; "
        "the {doc}`glossary` defines the physical symbols.",
        "",
        'In a chapter\'s notebook, `vibration.book.check("04.2", 0.8, quantity="bandwidth")` says whether 0.8 answers '
        "the bandwidth asked by exercise 04.2 within its stated tolerance, for the parameters the notebook's "
        "exercises were shown with, and gives a hint if not, without showing the answer. An exercise that asks for "
        'several quantities takes them together as a mapping (`{"bandwidth": 0.8, "Q": 5.6}`) or one at a '
        'time with `quantity=`; a multiple-choice exercise takes the letter of an option (`"b"`). The worked '
        "answers are in {doc}`answers`.",
        "",
        "```{list-table} The book's parameters.",
        ":header-rows: 1",
        ":name: tab-symbols",
        "",
        "* - symbol",
        "  - meaning",
        "  - unit",
        "  - range",
        "  - set with",
        "  - chapters",
    ]
    for (symbol, name, unit), row in sorted(rows.items(), key=lambda kv: (min(kv[1]["chapters"]), kv[0][1])):
        p = row["param"]
        lines += [
            f"* - {symbol_myst(symbol)}",
            f"  - {p.meaning}",
            f"  - {unit or '1'}",
            f"  - {_range(p)}",
            f"  - `-p {name}`",
            f"  - {', '.join(map(str, sorted(set(row['chapters']))))}",
        ]
    lines.append("```")
    return "\n".join(lines)


def usage_markdown(packages: list[str]) -> str:
    """The appendix "Using the package": each chapter package's ``usage.md``, in chapter order."""
    from importlib.metadata import version

    wheel = f"vibration-{version('vibration')}-py3-none-any.whl"
    parts = [
        "# Using the package",
        "",
        f'Install the package from this book\'s download, <a href="_static/downloads/{wheel}" download>{wheel}</a> '
        "(Python 3.11), into a fresh environment. The library alone needs NumPy, SciPy and Numba; the "
        "`book` extra adds what the chapters' notebooks use (Matplotlib, the sliders, JupyterLab with MyST "
        "rendering):",
        "",
        "```sh",
        "python -m venv .venv && . .venv/bin/activate",
        f'pip install "{wheel}[book]"      # or just {wheel} for the library',
        "jupyter lab                                       # then open a chapter's downloaded notebook",
        "```",
        "",
        "Each chapter page offers its notebook, with its outputs, to open beside it and run. The chapters "
        "call the package `vibration`; these short examples show the same calls outside the book, one per "
        "chapter. Each runs on its own in a fresh Python session (a test runs them).",
        "",
    ]
    for pkg in packages:
        usage = files(f"vibration.book.chapters.{pkg}").joinpath("usage.md")
        if usage.is_file():
            text = usage.read_text(encoding="utf-8").strip()
            parts += [text.replace("\n# ", "\n## ") if not text.startswith("# ") else "## " + text[2:], ""]
    return "\n".join([*parts, *environment_markdown()])


#: (distribution, name as written) of the packages the chapters compute with, in the order listed.
COMPUTING = (
    ("numpy", "NumPy"),
    ("scipy", "SciPy"),
    ("matplotlib", "Matplotlib"),
    ("numba", "Numba"),
    ("control", "python-control"),
    ("ipywidgets", "ipywidgets"),
    ("gymnasium", "Gymnasium"),
    ("cma", "cma"),
)


def environment_markdown() -> list[str]:
    """The section naming the Python and package versions this edition was built with.

    These are the versions of the build's own environment (a package that is not installed is left out);
    chapters run elsewhere (on a cluster's workers) record theirs in their notebook's last cell.

    >>> lines = environment_markdown()
    >>> lines[0], "NumPy " in lines[2]
    ('## The computing environment of this edition', True)
    """
    import platform
    from importlib.metadata import PackageNotFoundError, version

    found = []
    for dist, name in COMPUTING:
        try:
            found.append(f"{name} {version(dist)}")
        except PackageNotFoundError:
            continue
    return [
        "## The computing environment of this edition",
        "",
        f"This edition was built with Python {platform.python_version()} and "
        + ", ".join(found)
        + " (the pinned list of every package is the source's environment.txt); "
        "each chapter's notebook ends by printing the versions of its own run.",
        "",
    ]


def references_markdown() -> str:
    """The References page."""
    return bibliography_markdown()


def _sym(text: str) -> str:
    """A registry symbol ("ω_n", "Δk/k") typeset for MyST (subscripts as ``{sub}``)."""
    return symbol_myst(text) if "_" in text else text


def glossary_markdown() -> str:
    """The glossary: every symbol of the notation registry with meaning, unit, defining equation, first chapter."""
    lines = [
        "# Glossary of symbols",
        "",
        "Every physical symbol of the book, with its meaning, its SI unit, the equation or relation that "
        "defines it and the chapter where it first appears (0 is the front page). Each symbol means one "
        "thing throughout; the letters that meant two things are settled below the table.",
        "",
        "```{list-table} The book's symbols.",
        ":header-rows: 1",
        ":name: tab-glossary",
        "",
        "* - symbol",
        "  - meaning",
        "  - unit",
        "  - defined by",
        "  - first in chapter",
    ]
    for s in sorted(SYMBOLS, key=lambda s: s.first_chapter):
        lines += [
            f"* - {_sym(s.symbol)}",
            f"  - {s.meaning}",
            f"  - {s.unit}",
            f"  - {_equation(s.equation)}",
            f"  - {s.first_chapter}",
        ]
    lines += ["```", "", "**Letters with one meaning each.**", ""]
    lines += [f"- {letter}: {_equation(kept)}; {_equation(moved)}." for letter, (kept, moved) in SETTLED.items()]
    return "\n".join(lines)


def _equation(text: str) -> str:
    """Subscripts of a plain-text equation ("ω_n = √(k/m)") as MyST ``{sub}`` roles."""
    return re.sub(r"(?<=[^\s(,/])_([^\W_]+)", lambda m: f"{{sub}}`{m.group(1)}`", text)


_DETAILS = re.compile(
    r'<details class="exercise-answer">\s*<summary>Worked answer ([0-9.]+)</summary>(.*?)</details>', re.S
)


def answers_markdown(chapters: list[tuple[str, str, list[str]]]) -> str:
    """The answers appendix: each chapter's worked answers, as its exercise section showed them.

    ``chapters`` holds (title, page name, Markdown outputs of the chapter) in book order; the worked
    answers are the folded blocks of the chapter's exercise section, so they carry this run's numbers.

    >>> md = '**Exercise 04.1**. Q?\\n\\n<details class="exercise-answer">\\n<summary>Worked answer 04.1</summary>'
    >>> print(answers_markdown([("4. Frequency", "04_x", [md + "\\n\\nX = 1 m.\\n\\n</details>"])]).splitlines()[-1])
    **04.1.** X = 1 m.
    """
    lines = [
        "# Answers to the exercises",
        "",
        "The worked answers of every chapter's exercises, with the numbers of this run (folded under each "
        "exercise on the chapter's page). A run with other parameters recomputes them.",
    ]
    for title, _name, outputs in chapters:
        found = [(m.group(1), m.group(2).strip()) for text in outputs for m in _DETAILS.finditer(text)]
        if not found:
            continue
        lines += ["", f"## {title}", ""]
        for ex_id, body in found:
            lines += [f"**{ex_id}.** {body}", ""]  # the id opens the answer's first paragraph
    return "\n".join(lines).rstrip() + "\n"


LICENCES = """# Licences

- **Code**: the package `vibration`, the notebooks' code and the build scripts are under the MIT License
  (the file `LICENSE` of the source tree).
- **Text and figures**: the chapters' prose, tables and figures are under the Creative Commons Attribution
  4.0 International licence, CC BY 4.0 (the file `LICENSE-text`): share and adapt them, with credit.
- **Data**: the paper's scenarios and claims are transcribed from the audited paper; the measurements of
  the torsional oscillator in `data/lab_oscillator/` keep the provenance and terms stated in their own
  README, which these licences do not replace.
"""


_PROVENANCE = re.compile(r"repository\s+`([\w.-]+/[\w.-]+)`, folder `([^`]+)`, commit\s+`([0-9a-f]{40})`")


def lab_data_source() -> tuple[str, str, str]:
    """(repository, folder, commit) of the lab measurements, read from their README (the one statement of it)."""
    readme = files("vibration").joinpath("_data", "lab_oscillator", "README.md").read_text(encoding="utf-8")
    found = _PROVENANCE.search(" ".join(readme.split()))
    if not found:
        raise RuntimeError("data/lab_oscillator/README.md no longer states its repository, folder and commit")
    return found.group(1), found.group(2), found.group(3)


def licences_markdown() -> str:
    """The Licences page, with the lab data's source repository and commit.

    >>> "/tree/450ede098ea5bcfd3f51e0d5e36f97752548f206/" in licences_markdown()
    True
    """
    repo, folder, commit = lab_data_source()
    url = f"https://github.com/{repo}/tree/{commit}/{folder.strip('/')}"
    return LICENCES + (
        "\n## The laboratory data\n\n"
        f"The measurements of Part III come from the public repository [{repo}]({url}), folder `{folder}`, "
        f"commit `{commit}`; the files are reproduced byte for byte under new names. That repository states no "
        "licence: cite it, with the commit, wherever the data are used.\n"
    )
