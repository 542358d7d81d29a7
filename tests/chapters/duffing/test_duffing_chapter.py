"""Chapter 9, the Duffing oscillator: its study, tables, figures and sentences, at its defaults and at other
parameters from the schema's ranges.

What is checked: every caption passes the figure check and says what the numbers say; every sentence's
comparison or verdict agrees with the study record it was built from; no paragraph, table or caption
appears twice (numbers masked); each table column keeps one number of significant figures; no code name,
e-notation or untypeset unit reaches the reader; the notebook calls each chapter function once.
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from prose import ungrouped_counts

from vibration import ParameterError
from vibration.book.chapters.duffing import figures, notation, tables, text
from vibration.book.chapters.duffing.notation import apm, within
from vibration.book.chapters.duffing.params import SCHEMA, Params
from vibration.book.chapters.duffing.study import duffing_study
from vibration.book.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption
from vibration.book.presentation.numbers import sig
from vibration.book.presentation.style import case_style, legend_overlap
from vibration.physics.duffing import periodic_orbit

# every test here builds on a chapter study that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

NOTEBOOK = Path(__file__).resolve().parents[3] / "notebooks" / "09_duffing.ipynb"
USAGE = Path(__file__).resolve().parents[3] / "src" / "vibration" / "book" / "chapters" / "duffing" / "usage.md"

TABLES = (
    tables.hb_table,
    tables.stability_table,
    tables.fold_table,
    tables.history_table,
    tables.lyapunov_table,
    tables.lyapunov_runs_table,
    tables.lyapunov_convergence_table,
    tables.checks_table,
)
SENTENCES = (
    text.key_results,
    text.hb_sentence,
    text.stability_sentence,
    text.fold_sentence,
    text.trust_sentence,
    text.paper_sentence,
    text.lyapunov_sentence,
    text.published_sentence,
    text.summary,
)
FIGURES = (figures.frequency_response_figure, figures.sweep_figure, figures.paper_figure, figures.chaos_figure)

#: Two parameter sets from the schema's ranges besides the defaults. Heavy: four times the mass, twenty times
#: the stiffness and eight times the force, damped so strongly (c = 4 N s/m) that neither spring has a band
#: of three amplitudes. Soft: a softer, lighter-damped oscillator (ζ = 0.032) with folds, and Ueda's oscillator
#: forced into a periodic motion, so every verdict takes its other branch somewhere.
OTHER = {
    "heavy": {"m": 4.0, "k": 400.0, "F0": 40.0, "c_nominal": 4.0, "omega_res": 10.0, "t_end": 20.0,
              "omega_sweep_min": 7.0, "omega_sweep_max": 14.0, "n_sweep": 40, "n_lyapunov": 300},
    "soft": {"k": 10.0, "F0": 2.0, "c_nominal": 0.2, "k3_hard": 0.5, "k3_soft": -0.15, "omega_res": 3.0,
             "omega_sweep_min": 2.0, "omega_sweep_max": 5.0, "n_sweep": 40, "F0_ueda": 5.0, "F0_ueda_periodic": 1.0,
             "n_lyapunov": 300},
}  # fmt: skip


@pytest.fixture(scope="module")
def default():
    return duffing_study(Params())


@functools.cache
def _other(name: str):
    return duffing_study(Params(**OTHER[name]))


@pytest.fixture(
    scope="module",
    # the heavy set is a whole second study: it runs with the slow tests (the soft set stays)
    params=[pytest.param(name, marks=pytest.mark.slow) if name == "heavy" else name for name in sorted(OTHER)],
)
def other(request):
    return _other(request.param)


_FIGURES: dict[int, dict] = {}


def _figures(study) -> dict:
    """The chapter's figures for ``study``, drawn once per study: function -> Captioned."""
    if id(study) not in _FIGURES:
        _FIGURES[id(study)] = {make: make(study) for make in FIGURES}
    return _FIGURES[id(study)]


def _everything(study) -> list[tuple[str, str]]:
    """(where, text) of every paragraph, table and caption the chapter shows for ``study``."""
    out = []
    for make in SENTENCES:
        for para in re.split(r"\n(?=> \* |\* )|\n\n", make(study)):
            out.append((make.__name__, _reader(para)))
    for make in TABLES:
        out.append((make.__name__, repr(make(study))))
    for make, c in _figures(study).items():
        out.append((make.__name__, c.caption))
        if c.remark:
            out.append((make.__name__ + " remark", c.remark))
        out.append((make.__name__ + " alt", c.alt))
    return out


def _masked(text_: str) -> str:
    return re.sub(r"[−+-]?\d+(?:[.,\u2009]\d+)*(?:×10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?", "#", text_).strip()


# ------------------------------------------------------------------------------------- the record


def test_study_takes_the_params_record_or_keywords():
    with pytest.raises(ParameterError, match="n_sweep = 5"):
        duffing_study(n_sweep=5)
    with pytest.raises(ParameterError, match=r"c_nominal = 0\.0 N s/m .*allowed c_nominal > 0"):
        duffing_study(c_nominal=0.0)
    with pytest.raises(ParameterError, match=r"k3_soft = 0\.0 N/m³ .*allowed k3_soft < 0"):
        duffing_study(k3_soft=0.0)
    with pytest.raises(ParameterError, match="omega_sweep_max"):
        Params(omega_sweep_min=6.0, omega_sweep_max=5.0)
    with pytest.raises(ParameterError, match="params"):
        duffing_study({"m": 1.0})
    assert SCHEMA.names()[0] == "m"


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_sweep_points_are_periodic_orbits_of_the_full_equation(default):
    """Independently of the continuation: shooting from a sweep's end state at a frequency inside the band
    converges to an orbit of the same amplitude, within the sweep's steady tolerance."""
    case = default.hardening
    low, high = case.orbit_folds
    inside = np.flatnonzero((case.up.omega > low) & (case.up.omega < high))
    assert inside.size >= 2
    for res in (case.up, case.down):
        i = int(inside[inside.size // 2])
        orb = periodic_orbit(case.duffing, case.F0, float(res.omega[i]), x0=float(res.x_end[i]),
                             v0=float(res.v_end[i]))  # fmt: skip
        assert orb.amplitude == pytest.approx(res.amplitude[i], rel=1e-4)
        assert orb.stable
    # the drawn branch (points joined by straight lines) passes through the sweep points to within a few 0.1 %
    gap = max(c.sweep_orbit_gap() for c in default.cases)
    sweeps = _figures(default)[figures.sweep_figure]
    assert gap < 1e-2 and f"lie on it to within {within(gap)}" in f"{sweeps.caption} {sweeps.remark}"
    assert case.jump_up and case.jump_down


def test_fold_rows_follow_the_folds(default):
    for r in default.folds_compared:
        case = next(c for c in default.cases if c.label == r.case)
        low, high = case.orbit_folds
        assert r.orbit == (high if r.direction == "up" else low)
        assert r.hb == (case.folds.omega_high if r.direction == "up" else case.folds.omega_low)
        step = (default.params.omega_sweep_max - default.params.omega_sweep_min) / (default.params.n_sweep - 1)
        assert r.inside is True and r.bracket <= step / 100 * (1 + 1e-9)  # two refinements of ten steps each


# ----------------------------------------------------------------------------------- notation


#: The invisible span that carries a machine-dependent value and its tolerance (the reader sees its text).
SPAN = re.compile(r'<span class="vib-approx" data-value="([^"]*)" data-tol="([^"]*)">([^<]*)</span>')


def _reader(text_: str) -> str:
    """What the reader sees: the spans' texts without their markup."""
    return SPAN.sub(lambda m: m.group(3), text_)


def test_a_chaotic_exponent_reads_plainly_and_carries_its_tolerances():
    text_ = apm(0.10417, 0.00093, 20_000)
    assert _reader(text_) == "0.1042 ± 0.0009" and "≈" not in text_
    spans = SPAN.findall(text_)
    assert [(float(v), tol) for v, tol, _ in spans] == [
        (0.10417, f"a{float(f'{notation.EXPONENT_SPREAD / 20_000**0.5:.2g}'):g}"),
        (0.00093, f"f{notation.ERROR_FACTOR:g}"),
    ]
    # a power of ten is factored out once, outside both spans
    assert _reader(apm(5.12e-5, 2.7e-6, 1000)) == "(5.1 ± 0.3)×10⁻⁵"
    assert _reader(apm(0.104, float("nan"), 1000)) == "0.104"
    assert within(0.004) == "0.5 %" and within(0.00037) == "0.1 %" and within(0.03) == "5 %"


def _significant(cell: str) -> int | None:
    """Significant figures of a decimal number in a table cell; None for text, counts, ``—`` and exact zero."""
    cell = cell.rstrip("abcdefghijklmnopqrstuvwxyz")
    m = re.fullmatch(r"[−-]?(\d+\.\d+|\d+\.?\d*)(?:×10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?", cell)
    if not m or "." not in m.group(1) and "×" not in cell:
        return None
    digits = m.group(1).replace(".", "").lstrip("0")
    return len(digits) or None


@pytest.mark.parametrize("make", TABLES, ids=lambda f: f.__name__)
def test_each_column_has_one_number_of_significant_figures(make, default):
    t = make(default)
    for j, col in enumerate(t.columns):
        found = {s for s in (_significant(row[j]) for row in t.cells()) if s is not None}
        assert len(found) <= 1, (t.name, col.header, [row[j] for row in t.cells()])


# -------------------------------------------------------------------------------- repetition, notation


def test_no_paragraph_table_or_caption_appears_twice(default):
    items = _everything(default)
    seen: dict[str, str] = {}
    for where, para in items:
        key = _masked(para)
        assert key not in seen, f"{where} repeats {seen.get(key)}: {para[:100]!r}"
        seen[key] = where
    sentences: dict[str, str] = {}
    for where, para in items:
        if where.endswith(("_table", " alt")):  # alt texts are for screen readers, alongside the captions
            continue
        for s in re.split(r"(?<=[.;])\s+", para):
            key = _masked(s)
            if len(key) > 40:
                assert sentences.setdefault(key, where) == where, (
                    f"{where} repeats a sentence of {sentences[key]}: {s!r}"
                )


CODE_NAMES = re.compile(
    r"\b(omega_\w+|x_ss|c_sky|c_nominal|c_ueda|k3_\w+|F0\w*|zeta_\w+|n_\w+|t_end|K_v\*?)\b|\d(\.\d+)?e[+-]?\d|\^|sqrt\("
)


def test_reader_notation(default):
    for where, para in _everything(default):
        prose = re.sub(r"\$[^$]*\$", "", para)  # typeset maths ($\\omega_n$) is the reader's notation
        assert not CODE_NAMES.search(prose), (where, CODE_NAMES.search(prose).group(0), para[:120])
        assert "nan" not in re.findall(r"\bnan\b|\binf\b", para.lower()), where


# ------------------------------------------------------------------------ verdicts follow the numbers


def _check_verdicts(study) -> None:
    """Every comparison and verdict in the sentences, tables and captions agrees with the study's numbers."""
    for where, para in _everything(study):
        assert not re.search(r"\bnan\b|\binf\b", para.lower()), (where, para[:120])
        assert ungrouped_counts(para) == [], (where, ungrouped_counts(para), para[:120])  # counts grouped in threes
    # the captions meet the figures, and say the measured coincidences and jumps
    figs = _figures(study)
    for make, c in figs.items():
        assert isinstance(c, Captioned) and c.name.startswith("fig-duffing-")
        check_caption(c.fig, c.caption)
        check_caption(c.fig, c.remark, layout=False)
        for ax in c.fig.axes:
            if ax.get_legend() is not None and make is not figures.paper_figure:
                assert legend_overlap(ax) == 0.0, make.__name__
    shown = {make: f"{c.caption} {c.remark}" for make, c in figs.items()}  # the findings are in the remarks
    chaos = shown[figures.chaos_figure]
    coincide = all(study.method_gap(w) < figures.COINCIDE for w in ("chaotic", "periodic"))
    assert ("for each forcing the two methods' curves coincide" in chaos) == coincide
    sweeps = figs[figures.sweep_figure].remark.lower()
    jumps = [sum(j is not None for j in (case.jump_up, case.jump_down)) for case in study.cases]
    both = "for both springs" in sweeps
    assert not both or len(set(jumps)) == 1, sweeps
    for case, n in zip(study.cases, jumps, strict=True):
        part = sweeps.split("for both springs" if both else f"the {case.label} spring")[1].split(";")[0]
        assert ("both sweeps jump" in part) == (n == 2) and ("one sweep jumps" in part) == (n == 1)
    hb, hb_remark = figs[figures.frequency_response_figure].caption, figs[figures.frequency_response_figure].remark
    bistable = sum(c.folds.bistable for c in study.cases)
    assert ("unstable dashed" in hb) == (bistable > 0) and hb.count("dashed") == min(bistable, 1)
    assert ("Both springs give two stable branches" in hb_remark) == (bistable == 2)
    assert ("Both springs give a single-valued, stable curve" in hb_remark) == (bistable == 0)
    for case in study.cases:  # each bistable spring's folds are in the remark, to four figures
        folds_at = f"{case.folds.omega_low:.4g} and {case.folds.omega_high:.4g} rad/s"
        assert (folds_at in hb_remark) == case.folds.bistable, (case.label, hb_remark)
    paper = shown[figures.paper_figure].lower()
    x_lin = np.abs(study.paper_x_linear).max()
    assert ("the linear response (largest |x| " + sig(x_lin, 3) + " m) crosses the lines" in paper) == (
        x_lin > study.trust_amplitude
    )
    # sentences
    trust = text.trust_sentence(study)
    assert ("already beyond it" in trust) == (study.linear_amplitude > study.trust_amplitude)
    assert sig(study.trust_amplitude, 3) + " m" in trust
    hbs = text.hb_sentence(study)
    for case in study.cases:
        above = case.folds.peak_omega > case.linear_peak_omega
        clause = hbs.split(f"the {case.label} spring (k₃")[1].split(";")[0]
        assert ("moves the peak above" in clause) == above and ("moves the peak below" in clause) == (not above)
        assert ("lowers it" in clause) == (case.folds.peak_amplitude < case.linear_peak)
    checks = [ch for c in study.cases for ch in c.checks]
    stab = text.stability_sentence(study)
    if checks:
        assert ("agree on all" in stab) == all(ch.agree for ch in checks)
    else:
        assert "no root to check" in stab
    fold = text.fold_sentence(study)
    judged = [r.inside for r in study.folds_compared if r.inside is not None]
    assert ("brackets the fold of the periodic orbit" in fold) == (bool(judged) and all(judged))
    errs = [r.hb_error for r in study.folds_compared if math.isfinite(r.hb_error)]
    if errs:
        assert sig(max(abs(e) for e in errs), 2) + " rad/s" in fold
        assert ("every one-harmonic fold lies below the true one" in fold) == all(e < 0 for e in errs)
    paper_s = text.paper_sentence(study)
    assert ("whichever way" in paper_s) == (not study.history[0].depends_on_history)
    lyap = text.lyapunov_sentence(study)
    verdict = {1: "the motion is chaotic", -1: "the motion is not chaotic", 0: "not distinguishable from zero"}
    assert verdict[study.pooled.sign] in lyap
    assert ("agree within their errors" in lyap) == study.pooled.consistent
    assert apm(study.pooled.mean, study.pooled.standard_error, sum(e.n_periods for e in study.lyap_runs)) in lyap
    for where, para in _everything(study):
        assert not re.search(r"≈\s*[−+-]?\d|[=±]\s*≈", para), (where, para[:120])
    pub = text.published_sentence(study)
    if not study.published.applies:
        assert "no published value to compare with" in pub
    else:
        assert ("agrees with it within two standard errors" in pub) == (abs(study.published.z) <= text.AGREE_Z)
    key = text.key_results(study)
    assert key.startswith("> **Key results**")
    assert ("**Two steady states.**" in key) == math.isfinite(study.hardening.orbit_folds[0])
    assert (verdict[1] in key) == (study.pooled.sign > 0)
    hist = tables.history_table(study).caption
    for h in study.history:
        assert (f"at {h.where}" in hist.split(", not at")[0] and "depends" in hist) == h.depends_on_history
    summ = text.summary(study)
    assert ("grows tenfold" in summ) == (study.pooled.sign > 0)


def test_verdicts_follow_the_numbers_at_the_defaults(default):
    _check_verdicts(default)
    # the defaults: both springs bistable, every jump brackets its fold, Ueda's oscillator chaotic
    assert all(c.folds.bistable for c in default.cases) and default.pooled.sign == 1
    assert "already beyond it" in text.trust_sentence(default)  # 2.237 m > 1.77 m at k3 = 2 N/m^3


def test_verdicts_follow_the_numbers_at_other_parameters(other):
    _check_verdicts(other)


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_every_caption_is_at_most_sixty_words(default):
    """Every figure's and every table's caption says what is drawn or listed in at most 60 words, at the defaults
    and at a far parameter set (a heavier, stiffer, more strongly damped oscillator forced harder)."""
    assert CAPTION_WORDS == 60
    for study in (default, _other("heavy")):
        captions = [(f.name, f.caption) for f in _figures(study).values()]
        captions += [(t.name, t.caption) for t in (make(study) for make in TABLES)]
        for name, caption in captions:
            assert caption_words(caption) <= 60, (name, caption_words(caption), caption)


#: The response figure's caption is held tighter than the chapter's limit: it had grown to 65 words.
RESPONSE_CAPTION_WORDS = 55


def test_the_response_figure_caption_is_short_and_keeps_the_facts_a_reader_needs(default):
    """At most 55 words, counted both as the reader counts them and as plain whitespace-separated words, and still
    the oscillator's parameters with units, each panel's k₃ with its unit, the line styles and the colours."""
    caption = _figures(default)[figures.frequency_response_figure].caption
    assert len(caption.split()) <= RESPONSE_CAPTION_WORDS, (len(caption.split()), caption)
    assert caption_words(caption) <= RESPONSE_CAPTION_WORDS
    p = default.params
    soft = f"{p.k3_soft:g}".replace("-", "\u2212")
    facts = [
        f"m = {p.m:g} kg",
        f"k = {p.k:g} N/m",
        f"c = {p.c_nominal:g} N s/m",
        f"F₀ = {p.F0:g} N",
        f"left, hardening, k₃ = {p.k3_hard:g} N/m³ (vermillion)",
        f"right, softening, k₃ = {soft} N/m³ (sky blue)",
        "One-harmonic",
        "unstable dashed",
        "folds open circles",
        "backbones dotted black",
        "linear spring blue",
    ]
    assert [f for f in facts if f not in caption] == [], caption


def test_other_parameters_reach_both_branches_of_the_verdicts():
    """The two other sets between them take the other side of the defaults' verdicts (so the test above
    exercises both branches): no band of three amplitudes; the paper's amplitude below the trust limit; a
    periodic Ueda oscillator with no published value."""
    heavy = _other("heavy")
    assert not any(c.folds.bistable for c in heavy.cases)
    assert heavy.linear_amplitude < heavy.trust_amplitude
    assert "no root to check" in text.stability_sentence(heavy)


# ------------------------------------------------------------------------------- colours and notebook


def test_figures_use_the_books_case_colours(default):
    c = _figures(default)[figures.frequency_response_figure]
    colours = {ln.get_color().lower() for ax in c.fig.axes for ln in ax.get_lines()}
    for name in ("hardening", "softening", "linear"):
        assert case_style(name)["color"].lower() in colours
    c = _figures(default)[figures.paper_figure]
    lines = c.fig.axes[0].get_lines()
    assert lines[0].get_color() == case_style("linear")["color"]
    assert lines[1].get_color() == case_style("hardening")["color"]
    assert lines[2].get_color() == case_style("threshold")["color"] and lines[2].get_linestyle() == ":"


def _cells():
    return json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]


def test_notebook_calls_each_function_once_and_opens_with_the_question():
    cells = _cells()
    code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    calls = re.findall(r"^(?:display\(Markdown\()?(\w+)\(study\)", code, re.M)
    assert calls and len(calls) == len(set(calls)), calls
    for make in (*TABLES, *SENTENCES, *FIGURES):
        assert calls.count(make.__name__) == 1, make.__name__
    first_code = next(i for i, c in enumerate(cells) if "display(Markdown(key_results(study)))" in "".join(c["source"]))
    assert first_code <= 4 and "?" in "".join(cells[0]["source"])
    for c in cells:
        assert "mystnb" not in c.get("metadata", {}), "captions come from the package, not the cell metadata"
        if c["cell_type"] == "markdown":
            assert "Using the module" not in "".join(c["source"])


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_usage_block_runs_on_its_own(tmp_path):
    import subprocess
    import sys

    md = USAGE.read_text(encoding="utf-8")
    assert md.startswith("# Chapter 9, ")
    blocks = re.findall(r"```python\n(.*?)```", md, re.S)
    assert len(blocks) == 1
    script = tmp_path / "usage.py"
    script.write_text(blocks[0], encoding="utf-8")
    out = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert "rad/s" in out.stdout and "sweeping up" in out.stdout


# --------------------------------------------------------------- machine-dependent digits, measured


@pytest.mark.slow
def test_a_chaotic_run_started_one_ulp_away_stays_within_the_declared_tolerances(default, monkeypatch):
    """Another rounding anywhere sends a chaotic trajectory elsewhere; starting every run one unit in the last
    place away does the same on this machine. Every sentence and table of the chaos part must then read the
    same after the regression comparison's sanitizer, and every masked value lie within its tolerance."""
    from conftest import nbval_sanitize as _sanitize
    from nbval_numeric import mismatches

    from vibration.book.chapters.duffing import chaos as chaos_module

    runs = tuple(
        ((math.nextafter(x0, math.inf) if x0 else x0, math.nextafter(v0, math.inf) if v0 else v0), spp)
        for (x0, v0), spp in chaos_module.LYAPUNOV_RUNS
    )
    monkeypatch.setattr(chaos_module, "LYAPUNOV_RUNS", runs)
    moved = duffing_study(Params())
    assert moved.main_run.exponent != default.main_run.exponent  # the trajectory did move
    makes = (text.lyapunov_sentence, text.published_sentence, text.key_results, text.summary,
             tables.lyapunov_table, tables.lyapunov_runs_table, tables.lyapunov_convergence_table)  # fmt: skip
    for make in makes:
        ref, new = make(default), make(moved)
        if not isinstance(ref, str):
            ref, new = ref._repr_markdown_() + repr(ref), new._repr_markdown_() + repr(new)
        assert _sanitize(ref) == _sanitize(new), make.__name__
        assert not mismatches(ref, new), (make.__name__, [str(m) for m in mismatches(ref, new)])
    # a value moved beyond its tolerance fails: an exponent 10 standard errors off
    far = dataclasses.replace(moved.pooled, mean=default.pooled.mean + 10 * default.pooled.standard_error)
    ref = text.lyapunov_sentence(default)
    assert mismatches(ref, text.lyapunov_sentence(dataclasses.replace(moved, pooled=far)))


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_every_label_of_every_figure_lies_inside_the_figure(default):
    """What a figure draws (axis labels, tick labels, legends, colour bars) lies inside the figure: its tight
    bounding box is within the page's (Figure 9.5's right panel once lost the end of its axis label)."""
    cut = []
    for make, c in _figures(default).items():
        c.fig.draw_without_rendering()
        drawn, page = c.fig.get_tightbbox(), c.fig.bbox_inches
        margin = 0.01  # inch
        if drawn.x0 < page.x0 - margin or drawn.x1 > page.x1 + margin or drawn.y1 > page.y1 + margin:
            cut.append((make.__name__, [round(v, 3) for v in drawn.extents], [round(v, 3) for v in page.extents]))
        if drawn.y0 < page.y0 - margin:
            cut.append((make.__name__, "bottom", round(drawn.y0, 3)))
    assert cut == []
