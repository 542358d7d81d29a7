"""Chapter 8 as a reader meets it: no paragraph twice, the reader's notation, one count of significant figures
per table column, true captions, and every sentence true at parameters other than the paper's.

The parameter sets besides the defaults come from the schema's ranges: a heavier, stiffer, harder-driven primary
(m = 4 kg, k = 400 N/m, F0 = 40 N, so ω_p = 10 rad/s with the paper's 4.47 rad/s below resonance), and a softer,
lighter-damped one with a wider stiffness band, a lighter absorber and a taller, more flexible building.
"""

from __future__ import annotations

import math
import re
import subprocess
import sys
from importlib.resources import files

import numpy as np
import pytest

from vibration.book.chapters.tmd import figures, panel, tables, text
from vibration.book.chapters.tmd.designs import CLOSED, DESIGNS, H2, HINF, OPTIMA, ROBUST, TUNINGS
from vibration.book.chapters.tmd.digits import Sig
from vibration.book.chapters.tmd.params import SCHEMA
from vibration.book.chapters.tmd.study import tmd_study
from vibration.book.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption
from vibration.physics.model import ParameterError

# every test here builds on a study, a figure set or a browser that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

PARAMETER_SETS = {
    "defaults": {},
    "heavy": {"m": 4.0, "k": 400.0, "F0": 40.0},
    "soft": {
        "m": 2.0,
        "k": 5.0,
        "c_nominal": 0.05,
        "omega_res": 1.5,
        "mu": 0.02,
        "mistuning": 0.2,
        "n_storeys": 8,
        "storey_mass": 1.0e4,
        "storey_stiffness": 2.0e6,
        "zeta_building": 0.02,
        "mu_building": 0.05,
    },
}
FIGURES = (
    figures.fixed_points_figure,
    figures.magnification_figure,
    figures.time_response_figure,
    figures.robustness_figure,
    figures.modes_figure,
    figures.building_frf_figure,
    figures.building_ground_figure,
)
TABLES = (
    tables.tuning_table,
    tables.response_table,
    tables.design_table,
    tables.building_table,
    tables.building_load_table,
    tables.checks_table,
)
#: A number as the chapter prints it: sign, digits, decimals, an optional × 10ⁿ.
NUMBER = re.compile(r"[−-]?\d+(?:\.\d+)?(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
#: Code names and plain-text maths a reader must not meet in prose.
CODE_NAMES = re.compile(r"\b(?:zeta_[a-z]|omega_[a-z]+|x_ss|c_sky|K_v|mu_building|n_storeys|F0)\b|sqrt\(|\^\d")
E_NOTATION = re.compile(r"\d(?:\.\d+)?e[+-]?\d")


#: The heavy set builds a third whole chapter: it runs with the slow tests (the defaults and the soft set stay).
_SETS = [pytest.param(name, marks=pytest.mark.slow) if name == "heavy" else name for name in PARAMETER_SETS]


@pytest.fixture(scope="module", params=_SETS, ids=list(PARAMETER_SETS))
def chapter(request):
    """The study at one parameter set, every sentence, table and captioned figure of the chapter built from it."""
    st = tmd_study(n_points=501, **PARAMETER_SETS[request.param])
    sentences = text.chapter_texts(st) | {"sliders": panel.sliders_text(st)}
    return st, sentences, [t(st) for t in TABLES], [f(st) for f in FIGURES]


def _outside_maths(markdown: str) -> str:
    return re.sub(r"\$[^$]*\$", " ", markdown)


def test_no_paragraph_appears_twice(chapter):
    """Every paragraph, table and caption of the chapter is different after replacing each number by #."""
    _, sentences, tabs, figs = chapter
    paragraphs = dict(sentences)
    paragraphs |= {f"table {t.name}": repr(t) for t in tabs}
    paragraphs |= {f"caption of {t.name}": t.caption for t in tabs}
    paragraphs |= {f"note {i} of {t.name}": n for t in tabs for i, n in enumerate(t.notes)}
    paragraphs |= {f"caption of {f.name}": f.caption for f in figs}
    paragraphs |= {f"remark under {f.name}": f.remark for f in figs if f.remark}
    paragraphs |= {f"alt text of {f.name}": f.alt for f in figs}
    seen: dict[str, str] = {}
    for name, paragraph in paragraphs.items():
        key = NUMBER.sub("#", paragraph).strip()
        assert key not in seen, f"{name} repeats {seen.get(key)}: {paragraph[:100]!r}"
        seen[key] = name
    # no sentence of the body is repeated word for word in another paragraph either
    owner: dict[str, str] = {}
    for name, paragraph in sentences.items():
        for s in re.split(r"(?<=[.;:])\s+", paragraph):
            key = NUMBER.sub("#", s).strip()
            if len(key) > 40:
                assert owner.setdefault(key, name) == name, f"{name} and {owner[key]} share {s!r}"


def test_the_readers_notation(chapter):
    """Symbols typeset, no code names, no e-notation, units typeset, in prose, captions, headers, cells and notes."""
    _, sentences, tabs, figs = chapter
    for name, md in sentences.items():
        plain = _outside_maths(md)
        assert not CODE_NAMES.search(plain), (name, CODE_NAMES.search(plain))
        assert "_" not in plain.replace("\\_", ""), (name, plain)  # a subscript outside maths is a code name
        assert not E_NOTATION.search(md), (name, md)
        assert "^" not in plain and "**2" not in plain, name
    for t in tabs:
        for where in (t.caption, *(c.header for c in t.columns)):  # the table helper typesets _subscripts here
            assert not CODE_NAMES.search(where) and not E_NOTATION.search(where), (t.name, where)
        for note in t.notes:
            assert "_" not in note and not E_NOTATION.search(note) and not CODE_NAMES.search(note), (t.name, note)
        for cells in t.cells():
            for cell in cells:
                assert "_" not in cell and not E_NOTATION.search(cell), (t.name, cell)
    for f in figs:
        for words in (f.caption, f.remark):
            plain = _outside_maths(words)
            assert not CODE_NAMES.search(plain) and not E_NOTATION.search(words), (f.name, words)
            assert "_" not in plain, (f.name, words)
        assert "$" not in f.alt and "_" not in f.alt, (f.name, f.alt)


def _significant(cell: str) -> tuple[int, bool]:
    """Significant digits of a printed number, and whether trailing zeros make the count a lower bound."""
    mant = cell.split(" × ")[0].lstrip("−-")
    digits = mant.replace(".", "").lstrip("0")
    return len(digits), "." not in mant and digits.endswith("0")


def test_one_count_of_significant_figures_per_column(chapter):
    _, _, tabs, _ = chapter
    for t in tabs:
        for c in t.columns:
            cells = [str(r[c.key]) for r in t.rows if isinstance(r[c.key], Sig) and r[c.key].value != 0.0]
            cells = [x for x in cells if x not in ("∞", "−∞")]
            for cell in cells:
                n, at_least = _significant(cell)
                integer = "." not in cell.split(" × ")[0]  # 1270 at 4 figures, 12730 at 4 (the zero pads)
                assert n == c.digits or (at_least and n >= c.digits) or (integer and n > c.digits), (t.name, cell)


def test_every_caption_passes_its_check_and_says_true_coincidences(chapter):
    st, _, _, figs = chapter
    for f in figs:
        assert isinstance(f, Captioned)
        check_caption(f.fig, f.caption)  # Captioned checked it once; the stored caption is the checked one
        assert "nan" not in f.caption and "inf" not in f.caption.replace("infty", "")
    by_name = {f.name: f for f in figs}
    r = np.linspace(0.6, 1.4, 4001)
    curves = {n: figures.tmd_magnification(st.mu, s.tuning.f, s.tuning.zeta_a, r=r, zeta_p=st.zeta_p)
              for n, s in st.scores.items()}  # fmt: skip
    for fig_name, data in (("fig-tmd-magnification", curves), ("fig-tmd-robustness", st.robust)):
        shown = f"{by_name[fig_name].caption} {by_name[fig_name].remark}".lower()  # the findings are in the remark
        for group in (CLOSED, OPTIMA):
            for i, a in enumerate(group):
                for b in group[i + 1 :]:
                    d = float(np.max(np.abs(np.asarray(data[a]) / np.asarray(data[b]) - 1.0)))
                    said = f"the curves of {a.noun} and {b.noun} coincide".lower() in shown
                    assert said == (d < figures.COINCIDE), (fig_name, a, b, d)
    # the modes figure draws one panel per mode shown
    modes = by_name["fig-tmd-modes"].fig
    assert len(modes.axes) == min(st.building.n, figures.MAX_MODES)


def test_every_caption_is_at_most_sixty_words(chapter):
    """Figure and table captions say what is drawn or listed in at most 60 words, at every parameter set."""
    _, _, tabs, figs = chapter
    assert CAPTION_WORDS == 60
    for item in (*figs, *tabs):
        assert caption_words(item.caption) <= 60, (item.name, caption_words(item.caption), item.caption)


#: A number as a sentence writes it, read here without the book's formatter: true minus, "×10ⁿ", grouped digits.
_NUM = r"−?\d[\d\u202f]*(?:\.\d+)?(?:×10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?"
_POWERS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _value(written: str) -> float:
    mantissa, _, power = written.replace("−", "-").replace("\u202f", "").partition("×10")
    return float(mantissa) * 10.0 ** int(power.translate(_POWERS) or 0)


def _moves(sentence: str) -> list[tuple[str, float, float]]:
    """Every "falls from a to b" or "rises from a to b" a sentence states, with its two numbers."""
    return [
        (v, _value(a), _value(b)) for v, a, b in re.findall(rf"\b(falls|rises) from ({_NUM}) to ({_NUM})", sentence)
    ]


def _named(words: str):
    """The design a sentence names ("the robust min-max design", "Den Hartog's rule")."""
    found = [d for d in TUNINGS if words in (d.prose, d.noun, f"the {d.prose}")]
    assert len(found) == 1, words
    return found[0]


#: Four significant figures (three for a percentage), read back: within half a unit of the last digit.
_SHOWN, _SHOWN_PCT = 1e-3, 5e-3


def test_every_sentence_claims_only_what_its_numbers_say(chapter):
    """Each claim is read from the sentence and checked against the study's own numbers, not re-derived."""
    _check_claims(*chapter[:2])


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.parametrize(
    "changes",
    [
        {"c_nominal": 0.0},
        {"mu": 1.0, "mistuning": 0.5, "c_nominal": 4.4},
        {"mistuning": 0.0, "zeta_building": 0.99, "mu_building": 1.0},
    ],
    ids=["undamped", "far", "no-band"],
)
def test_sentences_and_tables_hold_at_far_parameters(changes):
    """At the schema's edges: the same claims, the design table's optima and the stated benefit kept."""
    st = tmd_study(n_points=201, **changes)
    _check_claims(st, text.chapter_texts(st))
    assert all(r["ok"] for r in tables.checks_table(st).rows)
    rows = {r["design"]: r for r in tables.design_table(st).rows}
    designs = {d.name: rows[d.name] for d in DESIGNS}  # every criterion's optimum wins its own column
    assert min(designs, key=lambda n: designs[n]["nominal"].value) == HINF.name
    worst = min(designs, key=lambda n: designs[n]["worst"].value)
    assert worst in ((ROBUST.name, HINF.name) if st.mistuning == 0 else (ROBUST.name,))
    if math.isfinite(st.scores[HINF].kept_low) and st.mistuning > 0:
        kept = re.search(rf"keeps ({_NUM}) % of its benefit", text.robustness_sentence(st))
        assert kept, text.robustness_sentence(st)
        assert _value(kept.group(1)) == pytest.approx(100 * st.scores[HINF].kept_low, rel=_SHOWN_PCT, abs=0.05)


def _check_claims(st, sentences):
    for name, s in sentences.items():
        assert not re.search(r"\bnan\b|\binf\b", s), (name, s)
        for verb, before, after in _moves(s):  # the verb agrees with the numbers it introduces
            assert (verb == "falls") == (after <= before), (name, s)
    h, rb = st.scores[HINF], st.scores[ROBUST]
    # the response and the building: the numbers moved are the study's amplitudes and peaks
    (_, before, after), *_ = _moves(sentences["response"])
    assert (before, after) == pytest.approx((st.amp_without, st.amp_with), rel=_SHOWN)
    building = _moves(sentences["building"])
    assert len(building) == len(st.load_cases)
    for (_, before, after), case in zip(building, st.load_cases, strict=True):
        assert (before, after) == pytest.approx(
            (case.scale * case.peak_without, case.scale * case.peak_with), rel=_SHOWN
        )
    mus = sorted(st.tunings)
    ((_, before, after),) = _moves(sentences["take-away 2"])
    assert (before, after) == pytest.approx((st.peaks_actual[mus[0]][HINF], st.peaks_actual[mus[-1]][HINF]), rel=_SHOWN)
    # "N % lower than without it": the absorber's reduction as stated, in the direction stated
    share, word = re.search(rf"({_NUM}) % (lower|higher) than without it", sentences["key result 1"]).groups()
    assert (word == "lower") == (st.amp_with < st.amp_without)
    assert _value(share) == pytest.approx(100 * abs(1 - st.amp_with / st.amp_without), rel=_SHOWN_PCT)
    # "lower than the best tuning derived for an undamped primary" is true of the closed forms' best peak
    if "lower than the best tuning" in sentences["key result 2"]:
        assert h.nominal_peak < min(st.peaks_actual[st.mu][d] for d in CLOSED)
    # the min-max design's worst peak against the H∞ optimum's
    if st.mistuning > 0:  # with no stiffness band there is no min-max design to state
        worst, word = re.search(
            rf"worst peak is ({_NUM}), {_NUM} % (lower|higher) than the H∞", sentences["key result 3"]
        ).groups()
        assert _value(worst) == pytest.approx(rb.worst_peak, rel=_SHOWN)
        assert (word == "lower") == (rb.worst_peak < h.worst_peak)
    if "it degrades, it does not collapse" in sentences["robustness"]:
        assert min(h.kept_low, h.kept_high) >= 0.5
    # a design named the winner of a criterion has the lowest value of it among the designs, the value stated
    for what, key in (("nominal peak", "nominal_peak"), ("rms displacement under white noise", "rms_ratio")):
        said = re.search(
            rf"(?:(the [^;:]+?) has the lowest {what}|the lowest {what} is that of ([^(]+?)) \(({_NUM})\)",
            sentences["design"],
        )
        if said is None:
            assert not all(math.isfinite(getattr(st.scores[d], key)) for d in DESIGNS), what
            continue
        winner = _named(said.group(1) or said.group(2))
        lowest = min(getattr(st.scores[d], key) for d in DESIGNS)
        assert getattr(st.scores[winner], key) == pytest.approx(lowest, rel=1e-9)
        assert _value(said.group(3)) == pytest.approx(lowest, rel=_SHOWN)
    rms = re.search(rf"H∞ optimum's rms is ({_NUM}) % (higher|lower) than the H2", sentences["design"])
    if rms:  # judged on the other's criterion, the H∞ optimum's rms against the H2 optimum's
        h2 = st.scores[H2]
        assert (rms.group(2) == "higher") == (h.rms_ratio > h2.rms_ratio)
        assert _value(rms.group(1)) == pytest.approx(
            100 * abs(h.rms_ratio / h2.rms_ratio - 1), rel=_SHOWN_PCT, abs=0.005
        )
    # the stroke: the design named has the smallest largest stroke, in metres as stated
    who, metres = re.search(
        rf"Of the \w+ designs (.+?) has the smallest largest stroke \(({_NUM}) m\)", sentences["stroke"]
    ).groups()
    winner = _named(who)
    assert st.scores[winner].stroke_peak == pytest.approx(min(st.scores[d].stroke_peak for d in DESIGNS), rel=1e-9)
    assert _value(metres) == pytest.approx(st.x_static * st.scores[winner].stroke_peak, rel=_SHOWN)
    travel = h.stroke_force * st.x_static / st.amp_with
    if "several times as far as" in sentences["take-away 4"]:
        assert travel >= 2
    if "moves less than the primary" in sentences["take-away 4"]:
        assert travel <= 1


def test_checks_hold_and_tables_are_finite(chapter):
    st, _, tabs, _ = chapter
    assert all(c.ok for c in st.checks), [c for c in st.checks if not c.ok]
    for t in tabs:
        for row in t.cells():
            assert not any(re.fullmatch(r"nan|inf", c) for c in row), (t.name, row)


def test_study_refuses_what_it_cannot_compute():
    with pytest.raises(ParameterError, match="c_nominal"):
        tmd_study(c_nominal=-0.1, n_points=11)
    with pytest.raises(ParameterError, match="c_nominal"):
        tmd_study(c_nominal=5.0, n_points=11)  # ζ_p = 0.56 > 0.5
    with pytest.raises(ParameterError, match="mu"):
        tmd_study(mu=0.0)
    assert SCHEMA.names()[:3] == ("m", "k", "F0")


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_study_record_follows_its_parameters():
    st = tmd_study(m=4.0, k=400.0, F0=40.0, n_points=201)
    assert st.omega_p == pytest.approx(10.0, rel=1e-15) and st.x_static == pytest.approx(0.1, rel=1e-15)
    assert st.zeta_p == pytest.approx(0.5 / (2 * math.sqrt(1600.0)), rel=1e-14)
    assert set(st.scores) == set(TUNINGS) and st.chosen is st.tunings[st.mu][HINF]


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_the_usage_example_runs_on_its_own(tmp_path):
    md = files("vibration.book.chapters.tmd").joinpath("usage.md").read_text(encoding="utf-8")
    assert md.startswith("# Chapter 8, ") and md.count("```python") == 1
    code = re.search(r"```python\n(.*?)```", md, re.S).group(1)
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "steady amplitude" in out.stdout
