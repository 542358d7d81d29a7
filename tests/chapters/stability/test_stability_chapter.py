"""Chapter 6 as a textbook chapter: no repetition, the reader's notation, true captions, one visual language,
and sentences that follow the numbers under other parameters.

The comparisons the sentences state are re-derived here from closed forms written out in this file
(transmissibility, white-noise variance, damper power, e-folding time, the support-force optimum), not
read back from the functions that wrote the sentences.
"""

from __future__ import annotations

import functools
import math
import re
import subprocess
import sys
from importlib.resources import files
from pathlib import Path

import nbformat
import numpy as np
import pytest

from vibration.book.chapters.stability import figures, panel, tables, text, verdicts
from vibration.book.chapters.stability.study import stability_study
from vibration.book.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption
from vibration.book.presentation.style import CASES
from vibration.physics.stability import stability_class

NOTEBOOK = Path(__file__).resolve().parents[3] / "notebooks" / "06_stability.ipynb"

#: Two parameter sets from the schema's ranges besides the defaults (heavier and stiffer; softer and lighter
#: damped), and one with zero and negative dampings in the paper's three slots.
OTHER = {
    "heavy-stiff": {"m": 4.0, "k": 400.0, "F0": 40.0, "isolation_ratio": 6.0},
    "soft-light": {
        "m": 2.0,
        "k": 5.0,
        "c_low": 0.02,
        "c_nominal": 0.1,
        "c_high": 1.0,
        "c_unstable": -0.05,
        "omega_res": 1.5,
        "isolation_ratio": 2.5,
        "S0": 0.5,
    },
    "not-positive": {"c_low": 0.0, "c_nominal": -0.05, "c_high": 0.3, "c_unstable": 0.0, "t_growth": 60.0},
}
FIGURES = (
    figures.pole_figure,
    figures.growth_figure,
    figures.transmissibility_figure,
    figures.step_figure,
    figures.cost_figure,
    figures.labels_figure,
)
TABLES = (
    tables.poles_table,
    tables.growth_table,
    tables.transmissibility_table,
    tables.step_table,
    tables.random_table,
    tables.random_force_table,
    tables.cost_table,
    verdicts.labels_table,
    tables.checks_table,
)
SENTENCES = (
    text.key_results,
    text.stability_sentence,
    text.growth_sentence,
    text.transmissibility_sentence,
    text.step_sentence,
    text.random_sentence,
    text.force_tradeoff_text,
    text.cost_sentence,
    verdicts.labels_sentence,
    panel.explorer_sentence,
    text.takeaways_text,
)
NUMBER = re.compile(r"[−-]?\d+(?:\.\d+)?(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
CODE_NAMES = re.compile(r"\b(omega_\w+|x_ss|c_sky|zeta_p|K_v\*?|c_(low|nominal|high|unstable|crit)|F0|S0|t_growth)\b")


@pytest.fixture(scope="module")
def study():
    return stability_study()


@pytest.fixture(scope="module", params=list(OTHER))
def other(request):
    return stability_study(n_paths=20, **OTHER[request.param])


@functools.cache
def _chapter(st) -> dict[str, object]:
    """Everything the chapter shows for a study: sentences (Markdown), tables and captioned figures, by name."""
    out: dict[str, object] = {f.__name__: f(st) for f in SENTENCES}
    out |= {f.__name__: f(st) for f in TABLES}
    out |= {f.__name__: f(st) for f in FIGURES}
    return out


def _prose(md: str) -> str:
    """Markdown with its maths ($...$) and quotations ("...", “...”) left out: what must read as plain words."""
    md = re.sub(r"\$[^$]*\$", " ", md)
    return re.sub(r"“[^”]*”|\"[^\"]*\"", " ", md)


def _norm(s: str) -> str:
    return re.sub(r"\s+", " ", NUMBER.sub("#", s)).strip()


def _paragraphs(md: str) -> list[str]:
    """Paragraphs and list items of a Markdown text (a list item is a paragraph of its own)."""
    out = []
    for block in re.split(r"\n\s*\n", md):
        items = re.split(r"\n(?=\s*(?:>\s*)?[*-] )", block)
        out += [re.sub(r"^[>\s*-]+", "", i).strip() for i in items if i.strip(" >\n")]
    return [p for p in out if p and not p.startswith("#") and p != "**Key results**"]


# ----------------------------------------------------------------------------- no repetition


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_no_paragraph_sentence_table_or_caption_appears_twice(study):
    nb = nbformat.read(str(NOTEBOOK), as_version=4)
    paragraphs = []
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            paragraphs += _paragraphs(cell.source)
    shown = _chapter(study)
    for item in shown.values():
        if isinstance(item, str):
            paragraphs += _paragraphs(item)
        elif isinstance(item, Captioned):
            paragraphs.append(item.caption)
            if item.remark:
                paragraphs.append(item.remark)
    seen: dict[str, str] = {}
    for p in paragraphs:
        key = _norm(p)
        assert key not in seen, f"paragraph appears twice:\n{p}\n{seen[key]}"
        seen[key] = p
    # sentences too: no sentence of 40 characters or more is said twice anywhere in the chapter
    sentences: dict[str, str] = {}
    for p in paragraphs:
        for s in re.split(r"(?<=[.!?])\s+(?=[A-Z“\"])", p):
            key = _norm(s)
            if len(key) >= 40:
                assert key not in sentences, f"sentence appears twice: {s}"
                sentences[key] = s
    # tables and captions: each shown once, none equal to another after the numbers are replaced
    tabs = [_norm(repr(t).split("\n", 1)[1]) for t in shown.values() if hasattr(t, "columns")]
    assert len(set(tabs)) == len(tabs)
    caps = [_norm(t.caption) for t in shown.values() if hasattr(t, "caption")]
    assert len(set(caps)) == len(caps)
    # the paper's labels: the sentence after the table judges them in its own words, it does not list the rows
    rows = verdicts.labels_table(study).rows
    labels = verdicts.labels_sentence(study)
    assert "\n" not in labels and not any(r["verdict"] in labels or r["check"] in labels for r in rows)


def test_notebook_cells_are_single_calls_and_figures_carry_no_static_caption():
    nb = nbformat.read(str(NOTEBOOK), as_version=4)
    first = nb.cells[0].source
    assert first.startswith("# 6. ") and "**Overview: the question.**" in first
    codes = [c for c in nb.cells if c.cell_type == "code"]
    assert "key_results(study)" in codes[2].source  # the key results right after the imports
    for cell in codes[3:-1]:
        assert "\n" not in cell.source.strip(), cell.source  # one call per cell
        assert "mystnb" not in cell.metadata
    assert not any("Using the module" in c.source for c in nb.cells)


def test_key_results_box(study):
    box = text.key_results(study)
    assert box.startswith("> **Key results**\n>\n> * ")
    assert all(line.startswith(">") for line in box.splitlines())
    assert len(re.findall(NUMBER, box)) >= 10  # computed numbers, not words alone


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_usage_example_runs_on_its_own(tmp_path):
    md = files("vibration.book.chapters.stability").joinpath("usage.md").read_text(encoding="utf-8")
    assert md.startswith("# Chapter 6, ") and md.count("```python") == 1
    code = re.search(r"```python\n(.*?)```", md, re.S).group(1)
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "0.1317" in out.stdout and "15.54 s" in out.stdout  # T(3 ωn) and the 2 % settling time of c = 0.5


# ----------------------------------------------------------------------------- the reader's notation


def _check_notation(shown: dict) -> None:
    for name, item in shown.items():
        if isinstance(item, str):
            plain = _prose(item)
            assert "_" not in plain, (name, plain)  # a subscript outside maths would show as code
            assert not CODE_NAMES.search(plain), (name, CODE_NAMES.search(plain))
            assert not re.search(r"\d[eE][+-]?\d|\^|sqrt\(|m2\b", plain), (name, plain)
            assert not re.search(r"\b(nan|inf)\b", item), (name, item)
        elif isinstance(item, Captioned):
            for words in (_prose(item.caption), _prose(item.remark), item.alt):
                assert "_" not in words and not CODE_NAMES.search(words), (name, words)
                assert not re.search(r"\d[eE][+-]?\d|\^|sqrt\(|\bnan\b|\binf\b", words), (name, words)
        else:  # a table: headers use the helper's subscripts; cells are plain text
            assert not re.search(r"\b(nan|inf)\b", repr(item)), name
            for row in item.rows:
                for col in item.columns:
                    v = row[col.key]
                    if isinstance(v, str):
                        assert "_" not in v and not re.search(r"\d[eE][+-]?\d", v), (name, v)
            assert not CODE_NAMES.search(item.caption.replace("F_0", "").replace("S_0", "")), (name, item.caption)


def test_notation_at_the_defaults(study):
    _check_notation(_chapter(study))


def _digits(cell: str) -> int | None:
    """Significant figures of a number cell ("0.0500" -> 3, "1.20 × 10⁵" -> 3); None for words and zeros."""
    m = re.fullmatch(r"[−-]?(\d+(?:\.\d*)?)(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?", cell)
    if not m:
        return None
    digits = m.group(1).replace(".", "").lstrip("0")
    return len(digits) if digits else None


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_each_table_column_has_one_number_of_significant_figures(study, other):
    for st in (study, other):
        for f in TABLES:
            t = _chapter(st)[f.__name__]
            for col in t.columns:
                counts = {_digits(v) for v in (row[col.key] for row in t.rows) if isinstance(v, str)} - {None}
                assert len(counts) <= 1, (t.name, col.header, counts)


# ----------------------------------------------------------------------------- one visual language


def test_the_papers_dampings_keep_their_book_colours(study):
    expected = {n: CASES[f"c_{n}"]["color"].lower() for n in ("low", "nominal", "high")}
    for f in FIGURES:
        c = _chapter(study)[f.__name__]
        lines = [ln for ax in c.fig.axes for ln in ax.get_lines()]
        lines += [h for leg in c.fig.legends for h in leg.legend_handles]
        for ln in lines:
            label = str(ln.get_label())
            for n, colour in expected.items():
                if label.startswith(f"{n}:") or label.startswith(f"{n} damping:"):
                    got = ln.get_color() if isinstance(ln.get_color(), str) else None
                    assert got is not None and got.lower() == colour, (f.__name__, label, got)
    # the nominal damping is the same blue in every figure that draws it, and never the old green
    cap = _chapter(study)["transmissibility_figure"]
    colours = {str(ln.get_color()).lower() for ax in cap.fig.axes for ln in ax.get_lines()}
    assert CASES["c_nominal"]["color"].lower() in colours and "#2ca02c" not in colours


def _said(c: Captioned) -> str:
    """What a figure says in words: its caption and the remark under it."""
    return c.caption + " " + c.remark


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_coinciding_curves_are_said_to_coincide():
    same = stability_study(c_nominal=15.0, n_paths=20, t_growth=30.0)  # nominal = high
    step = _said(figures.step_figure(same))
    assert "The nominal and high curves coincide" in step
    assert "coincide" in _said(figures.cost_figure(same))
    assert "The markers of the nominal damping and the high damping coincide" in _said(figures.pole_figure(same))
    apart = stability_study(n_paths=20, t_growth=30.0)
    assert "coincide" not in _said(figures.step_figure(apart))
    cap = _said(figures.transmissibility_figure(apart))  # low and nominal: 44.7 against 9 at resonance,
    assert "coincide" not in cap  # but within a few per cent of each other above sqrt(2) omega_n
    gap = re.search(r"the low and nominal curves lie within (\d+) %", cap)
    assert gap and 1 <= int(gap.group(1)) <= 10


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_captions_are_at_most_sixty_words_and_findings_go_under_the_figure(study):
    """Every figure's and table's caption is at most 60 words at the defaults and under a far parameter set."""
    far = stability_study(
        m=3.0, k=80.0, F0=12.0, c_low=0.0, c_nominal=-0.05, c_high=40.0, c_unstable=0.0, omega_res=5.16,
        t_growth=60.0, isolation_ratio=6.0, n_paths=20,
    )  # fmt: skip
    for st in (study, far):
        shown = _chapter(st)
        for name in [f.__name__ for f in FIGURES] + [t.__name__ for t in TABLES]:
            cap = shown[name].caption
            assert caption_words(cap) <= CAPTION_WORDS, (name, caption_words(cap), cap)
    # what the figures show is said under them, not in the caption
    trans = _chapter(study)["transmissibility_figure"]
    assert "Every curve passes through $T$ = 1" in trans.remark and "passes through" not in trans.caption


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_captions_follow_the_layout(study):
    for f in FIGURES:
        c = _chapter(study)[f.__name__]
        check_caption(c.fig, c.caption)  # Captioned checked it already; a second look costs nothing
        assert c.name.startswith("fig-stability-") and c.alt.endswith(".")
    grow = _chapter(study)["growth_figure"].caption
    assert all(w in grow for w in ("Top:", "middle:", "bottom:"))
    for f in (figures.pole_figure, figures.step_figure, figures.cost_figure):
        cap = _chapter(study)[f.__name__].caption
        assert "Left:" in cap and ("Right:" in cap or "right:" in cap), cap


# ----------------------------------------------------------------------------- under other parameters


def _T(m: float, c: float, k: float, w: float) -> float:
    """Base-excitation transmissibility, written out."""
    z, r = c / (2 * math.sqrt(k * m)), w / math.sqrt(k / m)
    return math.sqrt((1 + (2 * z * r) ** 2) / ((1 - r * r) ** 2 + (2 * z * r) ** 2))


def _num(s: str) -> float:
    s = s.replace("−", "-")
    m = re.fullmatch(r"(-?[\d.]+)(?: × 10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+))?", s)
    exp = m.group(2)
    power = int(exp.translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789"))) if exp else 0
    return float(m.group(1)) * 10.0**power


def _close(printed: str, value: float, digits: int = 3) -> bool:
    return _num(printed) == pytest.approx(value, rel=0.6 * 10.0 ** (1 - digits))


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_everything_builds_finite_and_checked_under_other_parameters(other):
    shown = _chapter(other)
    _check_notation(shown)
    for item in shown.values():
        if isinstance(item, Captioned):
            check_caption(item.fig, item.caption)
            assert not re.search(r"\b(nan|inf)\b", item.caption + item.alt)


def test_sentences_state_what_the_numbers_say(study, other):
    for st in (study, other):
        m, k = st.m, st.k
        pos = st.positive()
        # stability: every damping's verdict, from the sign of c
        s = text.stability_sentence(st)
        verdict = {c: ("asymptotically stable" if c > 0 else "marginally stable" if c == 0 else "unstable")
                   for c in st.dampings.values()}  # fmt: skip
        assert all(stability_class(st.osc(c)).verdict == v for c, v in verdict.items())
        if set(verdict.values()) == {"asymptotically stable"}:
            assert s.startswith("All three")
        else:
            for c, v in verdict.items():
                clause = re.search(rf"([^;]*) (is|are) {v} ", s).group(1)
                assert f"$c$ = {text.num(c, 4)} N s/m" in clause, (c, v, s)
        # isolation: the ratio of the heavier's to the lighter's transmissibility at the isolation ratio
        s = text.transmissibility_sentence(st)
        times = re.search(r", (\S+) times as much", s).group(1)
        if st.distinct_positive():
            lo, hi = pos[0][1], pos[-1][1]
        else:
            lo, hi = 0.2 * st.c_crit, st.c_crit
        w = st.isolation_ratio * st.omega_n
        assert _close(times, _T(m, hi, k, w) / _T(m, lo, k, w)), (times, s)
        assert _num(times) > 1.0  # above sqrt(2) omega_n more damping transmits more
        # step: the damping said to settle first is the one with the shortest settling time
        s = text.step_sentence(st)
        if st.steps:
            first = re.search(r"the (\w+) one settles first", s).group(1)
            assert first == min(st.steps, key=lambda n: st.steps[n].settling_time)
        # random load: the largest rms is the lightest positive damping's (variance pi S0 / (k c))
        s = text.random_sentence(st)
        if pos:
            assert f"the largest is the {pos[0][0]} damping's" in s
            for n, c in pos:
                assert f"{text.num(math.sqrt(math.pi * st.S0 / (k * c)), 3)} m ({n}," in s
        # the damper at resonance: power F0^2 / (2c), the lightest works hardest
        s = text.cost_sentence(st)
        if pos:
            assert f"The {pos[0][0]} damping, the lightest, works hardest" in s
            for n, c in pos:
                assert f"{text.num(st.F0**2 / (2 * c), 3)} W ({n}," in s
        # support force: least at c = sqrt(km), variance 2 pi S0 sqrt(k/m)
        s = text.force_tradeoff_text(st)
        assert f"= {text.num(math.sqrt(k * m), 3)} N s/m" in s
        assert f"{text.num(2 * math.pi * st.S0 * math.sqrt(k / m), 3)} N²" in s
        # growth: e-folding time 2m/|c| of the flutter model, or no exponential growth at c = 0
        s = text.growth_sentence(st)
        if st.c_unstable < 0:
            assert f"multiplies by e every {text.num(2 * m / -st.c_unstable, 3)} s" in s
        else:
            assert "no exponential growth" in s
        # the paper's labels, judged from the order of the values of c
        head = verdicts.labels_sentence(st).split(". ")[0]
        if " while " in head:
            held, failed = head.split(" while ", 1)
        elif "all three names" in head:
            held, failed = head, ""
        else:
            held, failed = "", head
        c = st.dampings
        if all(v > 0 for v in c.values()):  # "absolute stability" distinguishes nothing when all are stable
            assert "“absolute stability”" in failed, head
        if all(v > 0 for v in c.values()) and len(set(c.values())) == 3:
            between = min(c["low"], c["high"]) < c["nominal"] < max(c["low"], c["high"])
            assert ("“optimised compromise”" in held) == between, head
            assert ("“comfort”" in held) == (c["low"] == min(c.values())), head  # the lightest isolates best
        # take-aways: the support-force optimum and the settling-optimal ratio
        s = text.takeaways_text(st)
        assert (
            f"aim at {text.num(math.sqrt(k * m), 3)} N s/m" in s and "ζ = 0.78 (" in s
        )  # the 2 % settling optimum, independent of m and k
        # key results: the same isolation ratio as the body, in other words
        assert f"passes {times} times the motion" in text.key_results(st)


def test_figures_follow_the_run(other):
    st = other
    cap = _chapter(st)["transmissibility_figure"].caption
    if st.isolation_ratio > 4:
        assert "beyond the plotted range" in cap and "dash-dotted" not in cap
    else:
        assert "dash-dotted" in cap
    step = _chapter(st)["step_figure"]
    drawn = [ln.get_label() for ln in step.fig.axes[0].get_lines() if not str(ln.get_label()).startswith("_")]
    assert len(drawn) == sum(c >= 0 for c in st.dampings.values()) + 1  # the run's c >= 0 and the optimum
    for n, c in st.by_value():
        named = f"{n} ($c$ = {text.num(c, 4)} N s/m)"
        assert named in (step.caption if c >= 0.0 else step.remark)  # a drawn damping is named in the caption
        assert (f"{named} grows without bound and is not drawn" in _said(step)) == (c < 0.0)
    growth = _chapter(st)["growth_figure"]
    ends = [float(np.max(ax.get_lines()[0].get_xdata())) for ax in growth.fig.axes]
    assert ends[0] == pytest.approx(st.t_growth)
