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

from vibration.chapters.tmd import figures, panel, tables, text
from vibration.chapters.tmd.designs import CLOSED, DESIGNS, H2, HINF, OPTIMA, ROBUST, TUNINGS
from vibration.chapters.tmd.digits import Sig
from vibration.chapters.tmd.params import SCHEMA
from vibration.chapters.tmd.study import tmd_study
from vibration.physics.model import ParameterError
from vibration.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption

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
    curves = {n: figures.tmd_magnification(st.mu, s.tuning.f, s.tuning.zeta_a, r, st.zeta_p)
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


def test_sentences_state_what_the_numbers_say(chapter):
    st, sentences, _, _ = chapter
    for name, s in sentences.items():
        assert not re.search(r"\bnan\b|\binf\b", s), (name, s)
    h, rb, h2 = st.scores[HINF], st.scores[ROBUST], st.scores[H2]
    # the response: falls or rises as the amplitudes do
    verb = "falls" if st.amp_with <= st.amp_without else "rises"
    assert sentences["response"].count(verb) >= 1
    assert ("lower than without it" in sentences["key result 1"]) == (st.amp_with < st.amp_without)
    # the best closed form against the optimum for the actual damping
    closed = min(st.peaks_actual[st.mu][r] for r in CLOSED)
    assert ("lower than the best tuning" in sentences["key result 2"]) == (h.nominal_peak < closed)
    gain = 1 - h.nominal_peak / closed
    assert ("Tune for the primary you have" in sentences["take-away 1"]) == (gain >= 0.01)
    # the min-max design against the H∞ optimum
    rel = f"{'lower' if rb.worst_peak < h.worst_peak else 'higher'} than the H∞ optimum's"
    assert rel in sentences["key result 3"]
    assert ("it degrades, it does not collapse" in sentences["robustness"]) == (min(h.kept_low, h.kept_high) >= 0.5)
    # each criterion's winner is the one the design sentence names
    design = sentences["design"]
    for key, owner, what in (
        ("nominal_peak", HINF, "nominal peak"),
        ("rms_ratio", H2, "rms displacement under white noise"),
    ):
        vals = {n: getattr(st.scores[n], key) for n in DESIGNS}
        if not all(math.isfinite(v) for v in vals.values()):
            continue
        best = min(vals, key=vals.get)
        if best == owner or math.isclose(vals[best], vals[owner], rel_tol=1e-9):
            assert f"the {owner.prose} has the lowest {what}" in design
        else:
            assert f"the lowest {what} is that of {text._the(best)}" in design
    if math.isfinite(h.rms_ratio):
        word = "higher" if h.rms_ratio > h2.rms_ratio else "lower"
        assert re.search(rf"H∞ optimum's rms is [\d.]+ % {word}", design), design
    # the stroke: the design with the smallest largest stroke is the one named
    zmin = min(DESIGNS, key=lambda n: st.scores[n].stroke_peak)
    assert text._the(zmin) + " has the smallest largest stroke" in sentences["stroke"]
    travel = h.stroke_force * st.x_static / st.amp_with
    assert ("several times as far as" in sentences["take-away 4"]) == (travel >= 2)
    # the building: falls or rises as the load cases do, and the mass share is the table's
    for case in st.load_cases:
        verb = "falls" if case.peak_with <= case.peak_without else "rises"
        assert verb in sentences["building"]
    mus = sorted(st.tunings)
    peaks = [st.peaks_actual[x][HINF] for x in mus]
    assert ("falls from" in sentences["take-away 2"]) == (peaks[-1] <= peaks[0])


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


def test_study_record_follows_its_parameters():
    st = tmd_study(m=4.0, k=400.0, F0=40.0, n_points=201)
    assert st.omega_p == pytest.approx(10.0, rel=1e-15) and st.x_static == pytest.approx(0.1, rel=1e-15)
    assert st.zeta_p == pytest.approx(0.5 / (2 * math.sqrt(1600.0)), rel=1e-14)
    assert set(st.scores) == set(TUNINGS) and st.chosen is st.tunings[st.mu][HINF]


def test_the_usage_example_runs_on_its_own(tmp_path):
    md = files("vibration.chapters.tmd").joinpath("usage.md").read_text(encoding="utf-8")
    assert md.startswith("# Chapter 8, ") and md.count("```python") == 1
    code = re.search(r"```python\n(.*?)```", md, re.S).group(1)
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "steady amplitude" in out.stdout
