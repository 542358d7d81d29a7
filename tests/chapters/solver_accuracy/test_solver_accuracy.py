"""Chapter 3, solver accuracy: the study against exact and independent results, its prose under other parameters."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from prose import header_problems, prose_problems, repeated, table_texts

from vibration import Oscillator, SineForce, steady_state
from vibration.book.chapters.solver_accuracy import Params, SolverStudy, figures, solver_accuracy_study, tables
from vibration.book.chapters.solver_accuracy.study import MACHINE_DEPENDENT, atol_for
from vibration.book.presentation.captions import CAPTION_WORDS, caption_words, check_caption
from vibration.book.presentation.style import WIDTH_IN, legend_overlap
from vibration.physics.model import ParameterError

# every test here builds on a study, a figure set or a browser that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

PACKAGE = Path(__file__).resolve().parents[3] / "src" / "vibration" / "book" / "chapters" / "solver_accuracy"

#: The paper's parameters, a stiffer and heavier oscillator, and a softer, lighter-damped one.
PARAMETER_SETS = {
    "paper": {},
    "heavy-stiff": {"m": 4.0, "k": 400.0, "F0": 40.0, "omega_res": 10.0, "c_nominal": 2.0, "t_end": 20.0},
    "soft-light": {"k": 5.0, "F0": 1.0, "omega_res": 2.2, "c_nominal": 0.05, "t_end": 100.0, "n_points": 4001},
}

TABLES = (tables.ladder_table, tables.steps_table, tables.pair_table)
FIGURES = (figures.work_precision_figure, figures.own_steps_figure)


@pytest.fixture(scope="module", params=list(PARAMETER_SETS))
def study(request) -> SolverStudy:
    return solver_accuracy_study(Params.from_values(PARAMETER_SETS[request.param]))


def test_errors_are_measured_against_the_exact_solution(study):
    """Tight runs are close to the closed form, so the closed form is right and the errors are the solvers'."""
    for method in study.methods:
        runs = study.ladder(method)
        assert runs[-1].err_x < 1e-3 * study.peak, (method, runs[-1])
        if method not in MACHINE_DEPENDENT:  # tightening the tolerance tightens the error, by at least 10x per rung
            for loose, tight in zip(runs, runs[1:], strict=False):
                assert tight.err_x < 0.1 * loose.err_x, (method, loose, tight)
    for r in study.runs:
        assert r.atol == atol_for(r.rtol) and r.rel_err_x == pytest.approx(r.err_x / study.peak, rel=1e-12)


def test_paper_run_is_scipys_default(study):
    assert (study.paper.method, study.paper.rtol, study.paper.atol) == ("RK45", 1e-3, 1e-6)


def test_the_common_error_is_reached_by_every_machine_independent_method(study):
    reach = study.reach
    for method in study.methods:
        best = min(r.err_x for r in study.ladder(method))
        if method not in MACHINE_DEPENDENT:
            assert best <= reach.target and reach.evaluations(method) is not None
    assert reach.evaluations(reach.cheapest) == min(n for _, n in reach.cost)


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_late_exact_peak_is_the_steady_amplitude_when_the_transient_has_died():
    """Independent route: the closed-form steady amplitude X = F0/|k - m ω² + i c ω|."""
    st = solver_accuracy_study()
    X = steady_state(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)).amplitude
    assert st.steps[0].late_exact_peak == pytest.approx(X, rel=1e-3)
    # the tight own-steps run misses the peak by less than the loose one
    assert st.steps[1].shortfall < st.steps[0].shortfall


def test_scipy_pair_is_dormand_prince():
    st = solver_accuracy_study(t_end=5.0, n_points=501)
    assert st.nodes == (0, Fraction(1, 5), Fraction(3, 10), Fraction(4, 5), Fraction(8, 9), 1)
    assert st.pair == "Dormand-Prince 5(4)"


def test_bad_parameters_are_named():
    with pytest.raises(ParameterError, match="n_points"):
        solver_accuracy_study(n_points=1)
    with pytest.raises(ParameterError, match="omega_res"):
        Params(omega_res=-1.0)


def test_table_headers_are_for_readers(study):
    for f in TABLES:
        assert header_problems(f(study)) == [], f.__name__


def test_no_paragraph_appears_twice(study):
    texts = table_texts([f(study) for f in TABLES])
    texts += [text for c in (f(study) for f in FIGURES) for text in (c.caption, c.remark) if text]
    assert repeated(texts) == []


def test_captions_match_their_figures_and_legends_cover_no_data(study):
    for f in FIGURES:
        c = f(study)
        check_caption(c.fig, c.caption)  # Captioned checked it too; a contradiction raises
        assert prose_problems(c.caption) == [], (c.name, c.caption)
        assert prose_problems(c.remark) == [], (c.name, c.remark)
        assert c.fig.get_figwidth() <= WIDTH_IN + 1e-9
        for ax in c.fig.axes:
            if ax.get_legend() is not None:
                assert legend_overlap(ax) == 0.0, (c.name, legend_overlap(ax))
        assert c.alt and "/" not in c.alt


def _numbers(s: str) -> list[float]:
    s = s.replace("−", "-")
    out = []
    for m in re.finditer(r"(\d+(?:\.\d+)?)(?:\s*×\s*10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+))?", s):
        v = float(m.group(1))
        if m.group(2):
            v *= 10.0 ** int(m.group(2).translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")))
        out.append(v)
    return out


def test_work_precision_caption_gives_the_tightening_direction_from_the_data(study):
    c = figures.work_precision_figure(study)
    rising, other = figures.tightening_direction(study)
    for method in rising:
        nfev = [r.nfev for r in study.ladder(method)]
        assert nfev == sorted(nfev)
    said = c.caption + " " + c.remark
    assert "tightens from left to right" in said
    assert "right to left" not in said
    assert "(left)" in c.caption and "(right)" in c.caption


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_captions_stay_within_the_books_limit():
    """Every figure and table caption is at most 60 words, at the paper's parameters and at a far set."""
    far = {"m": 3.0, "k": 80.0, "F0": 12.0, "c_nominal": 1.2, "omega_res": 5.16, "t_end": 30.0, "n_points": 2001}
    for values in ({}, far):
        st = solver_accuracy_study(Params.from_values(values))
        for item in [f(st) for f in FIGURES] + [f(st) for f in TABLES]:
            assert caption_words(item.caption) <= CAPTION_WORDS, (values, item.name, item.caption)


def test_caption_check_refuses_a_wrong_direction_word():
    """The check is live: a caption calling the exact curve dotted is refused."""
    st = solver_accuracy_study(t_end=5.0, n_points=501)
    c = figures.own_steps_figure(st)
    with pytest.raises(ValueError, match="dotted"):
        check_caption(c.fig, c.caption.replace("dashed", "dotted"))


def test_figures_use_the_books_exact_style():
    st = solver_accuracy_study(t_end=5.0, n_points=501)
    c = figures.own_steps_figure(st)
    exact = c.fig.axes[0].get_lines()[0]
    assert exact.get_linestyle() == "--" and exact.get_color() in ("#000000", "k", "black")


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_usage_example_runs_on_its_own():
    md = (PACKAGE / "usage.md").read_text(encoding="utf-8")
    assert md.startswith("# Chapter 3, ")
    blocks = re.findall(r"```python\n(.*?)```", md, flags=re.S)
    assert len(blocks) == 1
    out = subprocess.run([sys.executable, "-c", blocks[0]], capture_output=True, text=True, timeout=120, check=True)
    assert "RK45" in out.stdout and math.isfinite(float(re.search(r"error ([\d.e+-]+) m", out.stdout).group(1)))


def test_no_nan_or_inf_in_the_record(study):
    for r in study.runs:
        assert all(math.isfinite(v) for v in (r.err_x, r.err_v, r.rel_err_x))
    for s in study.steps:
        assert all(math.isfinite(v) for v in (s.late_mean_peak, s.late_low_peak, s.late_exact_peak))
    assert np.all(np.isfinite(study.exact.x))
