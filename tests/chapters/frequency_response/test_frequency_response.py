"""Chapter 4, frequency response and design: the study against closed forms, its prose under other parameters."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from drawn import drawn_once
from prose import header_problems, prose_problems, repeated, table_texts

from vibration import Oscillator, SineForce, exact_response
from vibration.book.chapters.frequency_response import (
    FrequencyStudy,
    Params,
    figures,
    frequency_response_study,
    tables,
)
from vibration.book.presentation.captions import CAPTION_WORDS, caption_words, check_caption
from vibration.book.presentation.style import WIDTH_IN, legend_overlap, series_style
from vibration.physics.model import ParameterError

PACKAGE = Path(__file__).resolve().parents[3] / "src" / "vibration" / "book" / "chapters" / "frequency_response"

#: The paper's parameters (on a coarser design grid), a heavier and stiffer oscillator, and a softer one whose
#: low damping is zero (undamped: no band, no steady state to estimate from).
PARAMETER_SETS = {
    "paper": {"n_omega": 60, "n_damping": 40},
    "heavy-stiff": {
        "m": 4.0,
        "k": 400.0,
        "F0": 40.0,
        "t_end": 20.0,
        "omega_ref": 6.0,
        "omega_res": 10.0,
        "c_low": 0.4,
        "c_nominal": 2.0,
        "c_high": 60.0,
        "omega_max": 30.0,
        "c_max": 100.0,
        "n_omega": 60,
        "n_damping": 40,
    },
    "soft-light": {
        "k": 5.0,
        "F0": 1.0,
        "t_end": 100.0,
        "omega_ref": 1.5,
        "omega_res": 2.2,
        "c_low": 0.0,
        "c_nominal": 0.05,
        "c_high": 0.5,
        "omega_max": 5.0,
        "c_max": 5.0,
        "n_points": 4001,
        "n_omega": 60,
        "n_damping": 40,
    },
}

TABLES = (
    tables.dampings_table,
    tables.band_table,
    tables.estimates_table,
    tables.decomposition_table,
    tables.energy_table,
    tables.checks_table,
    tables.design_table,
)
FIGURES = tuple(
    map(
        drawn_once,
        (figures.response_figure, figures.decomposition_figure, figures.energy_figure, figures.design_figure),
    )
)


@pytest.fixture(scope="module", params=list(PARAMETER_SETS))
def study(request) -> FrequencyStudy:
    return frequency_response_study(Params.from_values(PARAMETER_SETS[request.param]))


def test_self_checks_hold(study):
    assert study.checks and all(c.ok for c in study.checks), [c for c in study.checks if not c.ok]


def test_peaks_and_bands_against_the_closed_forms(study):
    """Peak height 1/(2ζ√(1-ζ²)) and, for light damping, a half-power band c/m wide (to O(ζ²))."""
    for c in study.cases:
        if c.steady and c.M_peak is not None:
            z = c.zeta
            assert c.M_peak == pytest.approx(1 / (2 * z * math.sqrt(1 - z * z)), rel=1e-12)
            # the drawn curve never exceeds the peak and comes within 1 % of it
            assert np.max(c.magnification) <= c.M_peak * (1 + 1e-12)
            if z < 0.05:
                assert c.hi - c.lo == pytest.approx(c.c / c.osc.m, rel=2 * z)
        if c.inside is not None:
            assert c.inside == (c.lo is None or c.lo <= c.omega_res) and c.omega_res <= c.hi


def test_decomposition_adds_up_and_the_energy_balances(study):
    assert np.max(np.abs(study.total.x - study.steady - study.transient.x)) <= 1e-9 * max(1.0, study.decomposition.X)
    assert study.energy_residual(0) < 1e-10 and study.energy_residual(1) > study.energy_residual(0)


def test_design_map_against_direct_evaluation(study):
    """A grid cell's peak equals the exact response's peak computed directly (independent of the map's kernel)."""
    dm, p = study.design, study.params
    for i, j in ((0, 0), (len(dm.dampings) // 2, len(dm.omegas) // 2), (-1, -1)):
        r = exact_response(Oscillator(m=p.m, c=dm.dampings[i], k=p.k), SineForce(F0=p.F0, omega=dm.omegas[j]), study.t)
        assert dm.peaks[i, j] == pytest.approx(np.max(np.abs(r.x)), rel=1e-9)
    lo, hi = dm.danger_band
    assert lo <= dm.largest[0] <= hi and dm.flatness >= 1.0


def test_what_sets_the_amplitude_follows_the_numbers(study):
    for ctl in study.controls:
        if ctl.setter == "stiffness":
            assert ctl.M >= 0.9 * ctl.undamped and ctl.doubled > 0.9
        elif ctl.setter == "damping":
            assert ctl.M >= 0.9 * ctl.damping_only and ctl.doubled == pytest.approx(0.5, abs=0.1)


def test_table_headers_are_for_readers(study):
    for f in TABLES:
        assert header_problems(f(study)) == [], (f.__name__, header_problems(f(study)))


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_no_paragraph_appears_twice(study):
    texts = table_texts([f(study) for f in TABLES])
    texts += [text for c in (f(study) for f in FIGURES) for text in (c.caption, c.remark) if text]
    assert repeated(texts) == []


def test_captions_match_their_figures(study):
    for f in FIGURES:
        c = f(study)
        check_caption(c.fig, c.caption)
        assert prose_problems(c.caption) == [], (c.name, c.caption)
        assert prose_problems(c.remark) == [], (c.name, c.remark)
        assert c.fig.get_figwidth() <= WIDTH_IN + 1e-9
        for ax in c.fig.axes:
            if ax.get_legend() is not None:
                assert legend_overlap(ax) == 0.0, (c.name, legend_overlap(ax))
        assert c.alt and "/" not in c.alt


@pytest.mark.parametrize("dampings", [[0.1, 0.5, 2.0, 15.0], [3.0, 0.02]])
def test_a_list_of_dampings_gives_one_curve_and_row_each_and_keeps_the_nominal_case(dampings):
    st = frequency_response_study(dampings=dampings, n_points=1001, n_omega=20, n_damping=10)
    assert [c.c for c in st.cases] == dampings and [c.case for c in st.cases] == list(range(len(dampings)))
    assert st.nominal.c == st.params.c_nominal  # the decomposition, the energy and the controls use it
    assert len(tables.dampings_table(st).cells()) == len(dampings)
    for c in st.cases:
        assert c.M_res == pytest.approx(
            1 / math.hypot(1 - (st.params.omega_res / st.omega_n) ** 2, 2 * c.zeta * st.params.omega_res / st.omega_n),
            rel=1e-12,
        )


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_dampings_keep_the_books_colours(study):
    fig = figures.response_figure(study).fig
    lines = [ln for ln in fig.axes[0].get_lines() if len(ln.get_xdata()) > 2]
    drawn = [c for c in study.cases if c.steady]
    assert [ln.get_color() for ln in lines] == [series_style(c.case)["color"] for c in drawn]


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_coinciding_curves_are_said_to_coincide():
    st = frequency_response_study(dampings=[0.5, 0.502, 15.0], n_points=1001, n_omega=20, n_damping=10)
    fig = figures.response_figure(st)
    assert "The c = 0.5 N s/m and c = 0.502 N s/m curves coincide to within 1 %." in fig.caption + " " + fig.remark
    apart = figures.response_figure(frequency_response_study(n_points=1001, n_omega=20, n_damping=10))
    assert "coincide" not in apart.caption + " " + apart.remark


@pytest.mark.slow  # over 1 s: make test-slow runs it
def test_negative_damping_is_left_out_of_the_figure_and_said_so():
    st = frequency_response_study(c_low=-0.05, t_end=20.0, n_points=1001, n_omega=20, n_damping=10)
    cap = figures.response_figure(st).caption
    assert "The damping c = −0.05 N s/m has no steady state and is not drawn" in cap


def test_bad_parameters_are_named():
    with pytest.raises(ParameterError, match="c_min"):
        frequency_response_study(c_min=0.0)
    with pytest.raises(ParameterError, match="c_max"):
        Params(c_min=5.0, c_max=1.0)


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_usage_example_runs_on_its_own():
    md = (PACKAGE / "usage.md").read_text(encoding="utf-8")
    assert md.startswith("# Chapter 4, ")
    blocks = re.findall(r"```python\n(.*?)```", md, flags=re.S)
    assert len(blocks) == 1
    out = subprocess.run([sys.executable, "-c", blocks[0]], capture_output=True, text=True, timeout=300, check=True)
    assert "c = 0.5 N s/m underdamped" in out.stdout and "largest displacement" in out.stdout


def test_no_nan_or_inf_in_the_words(study):
    for f in (lambda s, f=f: f(s).caption + " " + f(s).remark for f in FIGURES):
        assert not re.search(r"\b(nan|inf)\b", f(study))


#: Far from the paper: heavier and stiffer, lightly damped at its nominal, heavily damped (ζ ≈ 1.9) at its high.
FAR = {"m": 3.0, "k": 80.0, "F0": 12.0, "omega_ref": 3.4, "omega_res": 5.16, "c_low": 0.2, "c_nominal": 1.2,
       "c_high": 60.0, "n_omega": 60, "n_damping": 40}  # fmt: skip


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.parametrize("values", [{}, FAR], ids=["defaults", "far"])
def test_captions_stay_within_the_books_limit(values):
    """Every figure and table caption of the chapter is at most 60 words; what a figure shows is in its remark."""
    st = frequency_response_study(Params.from_values(values))
    for item in [f(st) for f in FIGURES] + [f(st) for f in TABLES]:
        assert caption_words(item.caption) <= CAPTION_WORDS, (item.name, item.caption)
    for f in (figures.decomposition_figure, figures.energy_figure, figures.design_figure):
        assert f(st).remark, f.__name__


def test_the_prose_states_the_half_power_samples_the_study_uses():
    """The hand-written section on the damping estimates names the grid the half-power points are read from; the
    count is written grouped (200 001 with a narrow no-break space) and equals the study's."""
    import json

    from vibration.book.chapters.frequency_response.study import HALF_POWER_SAMPLES

    path = Path(__file__).resolve().parents[3] / "notebooks" / "04_frequency_response.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    prose = [c for c in cells if c["cell_type"] == "markdown" and "half-power points" in "".join(c["source"])]
    stated = [m for c in prose for m in re.findall(r"\(([\d\u202f]+) samples within", "".join(c["source"]))]
    assert stated == ["200\u202f001"]
    assert int(stated[0].replace("\u202f", "")) == HALF_POWER_SAMPLES
