"""Part III, the real oscillator: the study on a lab folder, its tables, figures, sentences, CSV tables and verdicts,
on today's data and on another laboratory's simulated CASSY wheel (tests/pohl_generator.py)."""

from __future__ import annotations

import ast
import csv
import json
import math
import re
from pathlib import Path

import numpy as np
import pohl_generator as gen
import pytest

import vibration
from vibration.book.chapters.real_oscillator import figures, text, verdicts
from vibration.book.chapters.real_oscillator.params import SCHEMA, Params
from vibration.book.chapters.real_oscillator.study import real_oscillator_study
from vibration.book.presentation.style import legend_overlap

# every test here builds on a study or a book that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

NOTEBOOK = Path(__file__).resolve().parents[3] / "notebooks" / "12_real_oscillator.ipynb"
MAIN_TABLES = (text.law_table, text.brake_table, text.resonance_table, text.prediction_table, verdicts.claims_table)
DETAIL_TABLES = (text.pooled_table, text.steadiness_table, text.session_table, text.damping_csv)
SENTENCES = (
    text.provenance_text,
    text.key_results,
    text.law_sentence,
    text.brake_sentence,
    text.steadiness_sentence,
    text.prediction_sentence,
    text.simulation_sentence,
    text.session_sentence,
    text.summary_text,
)
FIGURES = (
    figures.damping_figure,
    figures.current_figure,
    figures.resonance_figure,
    figures.gain_figure,
    figures.drift_figure,
)
HEADERS = {
    "tab-real-damping": "brake,brake_current_A,zeta_eq,zeta_eq_stderr,band_low_rad,band_high_rad,law,n_runs",
    "tab-real-resonance": "brake,session,omega_rad_s,amplitude_rad,amplitude_stderr_rad,steady_runs,runs",
    "tab-real-claims": "claim_id,claim,verdict,detail",
}


@pytest.fixture(scope="module")
def study(real_oscillator_default):
    return real_oscillator_default


def _check_outputs(st, tmp_path):
    for f in MAIN_TABLES + DETAIL_TABLES:
        t = f(st)
        if t is None:
            continue
        assert not re.search(r"\b(nan|inf)\b", repr(t)), f.__name__
        assert len(t.caption.split()) <= 60, f.__name__
        if f in MAIN_TABLES:
            assert len(t.columns) <= 7, f.__name__
    for f in SENTENCES:
        s = f(st)
        assert s and not re.search(r"\bnan\b", s) and "None" not in s, f.__name__
    for f in FIGURES:
        c = f(st)
        if c is None:
            continue
        assert len(c.caption.split()) <= 60, f.__name__
        for ax in c.fig.axes:
            assert legend_overlap(ax) <= 0.05, f.__name__
    text.write_csv_tables(st, tmp_path)
    out = {}
    for name, header in HEADERS.items():
        lines = (tmp_path / f"{name}.csv").read_text(encoding="utf-8").splitlines()
        assert lines[0] == header
        rows = list(csv.DictReader(lines))
        for r in rows:
            for k, v in r.items():
                if k not in ("claim", "detail"):
                    assert "±" not in v and "−" not in v, (name, k, v)
            if name == "tab-real-claims":
                assert r["verdict"] in verdicts.VERDICTS
                assert "±" not in r["detail"] and "−" not in r["detail"]
        out[name] = rows
    return out


def test_todays_data(study, tmp_path):
    out = _check_outputs(study, tmp_path)
    claims = {r["claim_id"]: r for r in out["tab-real-claims"]}
    # all driven runs share one brake setting: "damping suppresses resonance" cannot be tested
    assert {d.run.brake for d in study.driven} == {"on"}
    assert claims["C18"]["verdict"] == "not testable with these data"
    assert "lower bound" not in claims["C09"]["detail"]
    # most resonant runs are steady by late drift
    n_st, n, near_st, near = text.steady_counts(study)
    assert near >= 10 and near_st > near / 2
    # the brake is called resolved exactly when both estimates exclude zero with one sign
    (a, b, d, j) = study.comparisons[0]
    assert (b, a) == ("on", "off")
    assert ("is resolved" in text.brake_sentence(study)) == text.brake_resolved(d, j)
    assert d.ci_low <= d.delta_zeta <= d.ci_high
    # an amplitude-dependent law is tried for every setting, and each law has a prediction with a sensitivity curve
    for s in study.settings:
        assert {"coulomb+quadratic", "coulomb+power"} <= set(s.fits)
    assert {law for (_, law) in study.predictions} == set(study.settings[-1].fits)
    for p in study.predictions.values():
        assert len(p.sensitivity) == 9
        # every law is also predicted by simulating each run from its measured start, on the same runs
        assert math.isfinite(p.sim_pooled_error) and set(p.sim_errors) == set(p.errors)
        assert len(p.sim_sensitivity) == 9
    # the sessions: the resonant amplitude per unit drive differs between them at matched frequency, and the
    # amplification of the session without low-frequency runs carries that spread as a systematic error
    assert [s.session for s in study.sessions] == ["1", "2"]
    assert study.spread.pairs >= 1 and study.spread.spread > 0.05
    assert "systematic" in claims["C09"]["detail"]
    # the CSV resonance table counts every driven run once
    assert sum(int(r["runs"]) for r in out["tab-real-resonance"]) == len(study.driven) == 54
    assert study.current_law is None and figures.current_figure(study) is None


def test_parameters_cell_equals_schema():
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    cells = [c for c in nb["cells"] if "parameters" in c.get("metadata", {}).get("tags", [])]
    assert len(cells) == 1
    src = "".join(cells[0]["source"])
    values = {n.target.id: ast.literal_eval(n.value) for n in ast.parse(src).body}
    assert values == SCHEMA.defaults()
    assert Params() == Params(**SCHEMA.defaults())


@pytest.mark.parametrize(
    ("values", "name"),
    [
        ({"periods": 1}, "periods"),
        ({"tolerance": float("nan")}, "tolerance"),
        ({"lab_data": "/nonexistent/folder"}, "lab_data"),
        ({"lab_data": 3}, "lab_data"),
        ({"bogus": 1}, "bogus"),
    ],
)
def test_bad_parameters_are_refused(values, name):
    with pytest.raises(vibration.ParameterError, match=name):
        Params.from_values(values)


def test_runner_accepts_lab_data_as_a_path(tmp_path):
    from vibration.book.publishing import report

    chapters = report.select(report.discover(), ["12_real_oscillator"])
    values = report.check_parameters(chapters, [("lab_data", str(tmp_path))])
    assert values["lab_data"] == str(tmp_path.resolve())
    with pytest.raises(vibration.ParameterError, match="lab_data"):
        report.check_parameters(chapters, [("lab_data", str(tmp_path / "missing"))])


@pytest.fixture(scope="module")
def other_lab(tmp_path_factory):
    folder = tmp_path_factory.mktemp("other_lab")
    gen.write_lab(folder)
    return folder


@pytest.mark.slow
def test_another_labs_wheel(other_lab, tmp_path):
    st = real_oscillator_study(lab_data=str(other_lab))
    out = _check_outputs(st, tmp_path)
    claims = {r["claim_id"]: r for r in out["tab-real-claims"]}
    # driven runs at two brake settings: the claim becomes testable, and 700 mA does lower the resonant amplitude
    assert claims["C18"]["verdict"] != "not testable with these data"
    assert claims["C18"]["verdict"] in ("partly supported", "supported")
    # more than two currents: the eddy-current law is drawn and its k recovered within 15 %
    assert st.current_law is not None and figures.current_figure(st) is not None
    assert st.current_law["k"] == pytest.approx(gen.K_BRAKE, rel=0.15)
    damping = {r["brake"]: r for r in out["tab-real-damping"]}
    assert set(damping) == {"0 mA", "200 mA", "400 mA", "700 mA"}
    assert float(damping["700 mA"]["brake_current_A"]) == pytest.approx(0.7)
    # the brake at 700 mA is resolved against 0 mA
    last = [c for c in st.comparisons if c[1] == "700 mA"][0]
    assert text.brake_resolved(last[2], last[3])
    # the rig's documented largest angle is quoted
    assert "can turn at most" in text.provenance_text(st)


@pytest.mark.slow
def test_notebook_runs_on_another_lab(other_lab, tmp_path):
    import papermill

    tables = tmp_path / "tables"
    import os

    os.environ["VIBRATION_TABLES_DIR"] = str(tables)
    try:
        papermill.execute_notebook(
            str(NOTEBOOK),
            str(tmp_path / "out.ipynb"),
            parameters={"lab_data": str(other_lab)},
            kernel_name="vibration",
            cwd=str(NOTEBOOK.parent),
            progress_bar=False,
        )
    finally:
        del os.environ["VIBRATION_TABLES_DIR"]
    rows = list(csv.DictReader((tables / "tab-real-claims.csv").read_text(encoding="utf-8").splitlines()))
    verdict = {r["claim_id"]: r["verdict"] for r in rows}
    assert verdict["C18"] != "not testable with these data"
    assert all(v in verdicts.VERDICTS for v in verdict.values())
    assert math.isfinite(float(next(csv.DictReader((tables / "tab-real-damping.csv").open()))["zeta_eq"]))


def test_the_schematic_says_what_the_rig_is_and_what_is_not_documented(study):
    from vibration.book.presentation.schematics import torsional_oscillator

    def told(fig):  # the caption says what is drawn; its remark, under the figure, what the data document
        return fig.caption + " " + fig.remark

    rig = study.data.rig
    cap = told(
        torsional_oscillator(
            description=rig.description, max_angle_rad=rig.max_angle_rad, encoder_step_rad=rig.encoder_step_rad
        )
    )
    assert rig.description.rstrip(".") in cap
    assert rig.max_angle_rad is None and "the largest angle the wheel can turn." in cap
    assert "Not documented" in cap and "push rod" in cap
    other = told(torsional_oscillator(description="a simulated wheel", max_angle_rad=30.0))
    assert "can turn at most 30 rad (1719°)" in other and "the largest angle the wheel can turn" not in other
    assert "The data do not describe the rig." in told(torsional_oscillator())


def test_the_pooled_power_law_follows_the_measured_damping_where_the_runs_overlap(study):
    """The drawn and predicted law of a setting is one power term: its equivalent damping ratio (Coulomb term
    included) must stay with the measured ratios over the amplitudes the runs share, not only at one amplitude.
    Measured ratios are binned by amplitude (0.25 rad bins of at least 8 cycles, from 1.2 rad up) and each bin's
    median compared with the pooled law at the bin's median amplitude."""
    from vibration.physics.lab.decay import equivalent_zeta

    checked = 0
    for s in study.settings:
        pooled = s.fits.get("coulomb+power")
        if pooled is None:
            continue
        m = pooled.mean
        x = np.concatenate([c.amplitude for c in s.curves])
        z = np.concatenate([c.zeta_eq for c in s.curves])
        edges = np.arange(1.2, x.max() + 0.25, 0.25)
        for a, b in zip(edges[:-1], edges[1:], strict=True):
            inside = (x >= a) & (x < b)
            if inside.sum() < 8:
                continue
            xm, zm = float(np.median(x[inside])), float(np.median(z[inside]))
            law = m["zeta"] + 2 * m["friction"] / (math.pi * xm)
            law += float(equivalent_zeta(xm, m["omega_n"], power=m["power"], power_exponent=m["power_exponent"]))
            assert abs(law / zm - 1) <= 0.12, (s.brake, xm, law, zm)
            checked += 1
    assert checked >= 8
