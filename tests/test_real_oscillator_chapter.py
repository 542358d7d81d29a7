"""Part III, the real oscillator: the study on the lab data, its tables, figures and sentences, its parameters."""

from __future__ import annotations

import ast
import json
import math
import re
import time
from pathlib import Path

import pytest

import vibration
from vibration.chapters.real_oscillator import figures, text, verdicts
from vibration.chapters.real_oscillator.params import SCHEMA, Params
from vibration.chapters.real_oscillator.study import QUANT_FLOOR, QUANT_STEP, pool, real_oscillator_study
from vibration.presentation.style import legend_overlap

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "12_real_oscillator.ipynb"
TABLES = (
    text.decay_table,
    text.pooled_table,
    text.peak_table,
    text.driven_table,
    text.model_table,
    text.prediction_table,
    text.prediction_pooled_table,
    verdicts.claims_table,
    verdicts.coverage_table,
    verdicts.two_sample_table,
)
SENTENCES = (
    text.provenance_text,
    text.key_results,
    text.law_sentence,
    text.brake_sentence,
    text.residual_sentence,
    text.peak_sentence,
    text.driven_sentence,
    text.calibration_sentence,
    text.prediction_sentence,
    text.failure_sentence,
    text.resonance_sentence,
    verdicts.twin_sentence,
    text.summary_text,
)


@pytest.fixture(scope="module")
def study():
    return real_oscillator_study()


def test_free_decays_in_physical_ranges(study):
    # Ranges from the hardware, not from a previous fit: the driven runs' phase passes pi/2 between 4.4 and
    # 4.6 rad/s, so omega_n lies there; a wheel that swings 15 half periods has zeta well below 0.1; the friction
    # angle is at least half an encoder step (else the decays would not stop off centre) and below the swings.
    for brake in ("off", "on"):
        ds = study.decays[brake]
        assert len(ds.runs) == 10
        wn = ds.pooled[("combined", "omega_n")]
        assert 4.4 < wn.mean < 4.6 and 0 < wn.stderr < 0.05
        z = ds.pooled[("combined", "zeta")]
        assert 0 <= z.mean < 0.1
        d = ds.pooled[("combined", "friction")]
        assert QUANT_STEP / 2 < d.mean < 0.5
        assert sum(ds.law_counts.values()) == 10
        for run in ds.runs:  # residuals above the rounding floor: the fits do not overfit the quantisation
            assert run.combined.residual_rms > QUANT_FLOOR
            assert run.chosen == min(("viscous", "coulomb", "combined"), key=lambda law: run.fits[law].bic)
    # the brake adds damping; its standard error combines the two pooled ones
    on, off = study.decays["on"].pooled, study.decays["off"].pooled
    assert study.brake_dzeta == pytest.approx(on[("combined", "zeta")].mean - off[("combined", "zeta")].mean)
    assert study.brake_dzeta_se == pytest.approx(
        math.hypot(on[("combined", "zeta")].stderr, off[("combined", "zeta")].stderr)
    )


def test_pool_inflates_by_birge_ratio():
    p = pool([1.0, 1.2, 0.8, 1.1], [0.01, 0.01, 0.01, 0.01])
    assert p.birge > 1 and p.stderr == pytest.approx(0.005 * p.birge)
    q = pool([1.0, 1.001], [0.1, 0.1])
    assert q.stderr == pytest.approx(0.1 / math.sqrt(2))


def test_driven_runs_and_windows(study):
    assert len(study.driven) == 54
    for d in study.driven:
        assert d.early.t_end <= d.late.t_start + 1e-6  # windows do not overlap
        assert d.early.periods + d.late.periods <= d.whole_periods
        assert 1.0 < d.late.drive_amp < 1.6  # the eccentric's amplitude, about 1.3 rad
        assert d.late.ratio_se > 0 and -math.pi / 2 <= d.late.lag < 1.5 * math.pi
        z_ok = abs(d.amp_change_z) <= study.params.z_steady
        assert d.steady == (z_ok and study.build_up_time <= d.duration)
    assert all(0 < d.late.lag < 1.0 for d in study.driven if d.omega < 0.85 * study.models["combined"].omega_n)


def test_calibration_uses_only_the_lowest_frequency_runs(study):
    n = study.params.n_calibration
    lowest = sorted(study.driven, key=lambda d: d.omega)[:n]
    assert {(d.session, d.run) for d in study.calibration_runs} == {(d.session, d.run) for d in lowest}
    for model in ("linear", "combined"):
        _, _, n_pred = study.pooled_error(model)
        _, _, n_cal = study.pooled_error(model, calibration=True)
        assert n_pred == len(study.driven) - n and n_cal == n
        # the pooled prediction error is the one of the prediction runs alone
        num = sum(
            float(((d.angle - study.prediction(model, d).theta) ** 2).sum()) for d in study.driven if d not in lowest
        )
        cnt = sum(d.angle.size for d in study.driven if d not in lowest)
        assert study.pooled_error(model)[0] == pytest.approx(math.sqrt(num / cnt))
    rows = text.prediction_pooled_table(study).rows
    assert [r["n"] for r in rows if r["runs"].startswith("calibration")] == [n, n]


def test_models_and_curves(study):
    lin, com = study.models["linear"], study.models["combined"]
    assert lin.friction == 0.0 and com.friction > 0
    assert 0.1 < lin.gain < 1.0 and 0.1 < com.gain < 1.0  # the static ratio at the slowest runs is about 0.4
    c = study.curves
    assert c.hb_max_rel_diff < 0.1  # harmonic balance within 10 % of Den Hartog's exact solution
    assert study.stick_drive_exact == pytest.approx(study.stick_drive_hb, rel=0.1)
    assert study.stick_drive_hb == pytest.approx(4 * com.friction / (math.pi * com.gain))


def test_tables_have_no_nan_and_units(study):
    for f in TABLES:
        t = f(study)
        assert t.name.startswith("tab-real-")
        r = repr(t)
        assert not re.search(r"\b(nan|inf)\b", r), (f.__name__, r)
        assert "_" not in "".join(c.header for c in t.columns).replace("ω_n", "").replace("s(ω_n)", "")


def test_figures_keep_legends_off_the_data(study):
    import matplotlib.pyplot as plt

    for f, kw in (
        (figures.decay_figure, {}),
        (figures.loss_figure, {}),
        (figures.response_figure, {}),
        (figures.response_figure, {"models": False}),
        (figures.prediction_figure, {}),
    ):
        fig = f(study, **kw).fig  # a Captioned figure
        for ax in fig.axes:
            assert legend_overlap(ax) == 0.0, (f.__name__, ax.get_title())
        plt.close(fig)


def test_sentences_follow_the_numbers(study):
    for f in SENTENCES:
        s = f(study)
        assert s and not re.search(r"\bnan\b", s) and "None" not in s, f.__name__
    # law counts
    off = study.decays["off"]
    top = max(off.law_counts, key=off.law_counts.get)
    assert f"**{text.LAW_TEXT[top]}** law in {off.law_counts[top]} of 10" in text.law_sentence(study)
    # the brake: resolved iff more than two standard errors
    z = study.brake_dzeta / study.brake_dzeta_se
    assert ("resolved)" in text.brake_sentence(study)) == (z > text.AGREE_Z)
    # the better predictor named is the one with the smaller pooled relative error
    better = (
        "linear viscous" if study.pooled_error("linear")[1] < study.pooled_error("combined")[1] else "viscous + Coulomb"
    )
    assert f"the **{better}** model predicts better" in text.prediction_sentence(study)
    # peak cross-check: the sentence names as many disagreements as the table has
    n_bad = sum(r["agree"] == "disagree" for r in text.peak_table(study).rows)
    assert (f"disagree on {n_bad} of" in text.peak_sentence(study)) or n_bad == 0
    # the provenance cites the repository and the commit from the data README
    assert study.provenance.commit in text.provenance_text(study)
    assert len(study.provenance.commit) == 40
    assert 3 <= len(text.front_findings(study)) <= 5


def test_claim_verdicts_follow_the_numbers(study):
    rows = verdicts.claims_table(study).rows
    amp = study.peak_ratio / study.low_ratio
    about = abs(math.log(amp / text.PAPER_AMPLIFICATION)) <= math.log(text.ABOUT_FACTOR)
    assert rows[0]["verdict"].startswith("supported") == about
    assert f"{amp:.3g}" in rows[0]["measured"]
    bounded = math.isfinite(study.steady_peak_combined) and math.isfinite(study.steady_peak_linear)
    assert rows[2]["verdict"].startswith("not supported") == bounded
    assert rows[3]["verdict"].startswith("partly") == (study.brake_band < 0.5)


def test_twin_coverage_and_two_sample(study):
    for c in study.coverage:
        assert c.covered == (c.ratio <= study.params.spread_ratio_max)
    for t in study.tests:
        assert 0 <= t.p <= 1 and t.runs_needed >= 2 and t.n_off == t.n_on == 10
    z = study.tests[0]
    assert (z.p < 0.05) == ("is told apart" in verdicts.twin_sentence(study))


def test_parameters_cell_equals_schema():
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    cells = [c for c in nb["cells"] if "parameters" in c.get("metadata", {}).get("tags", [])]
    assert len(cells) == 1
    src = "".join(cells[0]["source"])
    tree = ast.parse(src)
    values = {}
    for node in tree.body:
        assert isinstance(node, ast.AnnAssign), ast.dump(node)
        values[node.target.id] = ast.literal_eval(node.value)
        assert type(values[node.target.id]).__name__ == node.annotation.id
    assert values == SCHEMA.defaults()
    assert all("  # " in line for line in src.splitlines())
    assert Params() == Params(**SCHEMA.defaults())


@pytest.mark.parametrize(
    ("values", "name"),
    [
        ({"n_late": 0}, "n_late"),
        ({"brake": "maybe"}, "brake"),
        ({"n_early": 6, "n_late": 3}, "n_early"),
        ({"z_steady": float("nan")}, "z_steady"),
        ({"bogus": 1}, "bogus"),
    ],
)
def test_bad_parameters_are_refused(values, name):
    with pytest.raises(vibration.ParameterError, match=name):
        Params.from_values(values)


@pytest.mark.slow
@pytest.mark.parametrize(
    "values",
    [
        {"n_late": 3, "n_early": 1, "n_calibration": 6, "z_steady": 1.0, "brake": "off", "decay_runs": "1-5"},
        {
            "n_late": 12,
            "n_early": 6,
            "n_calibration": 1,
            "z_steady": 10.0,
            "decay_runs": "6-10",
            "spread_ratio_max": 10.0,
        },
    ],
)
def test_other_parameters_run_fast_and_stay_consistent(values):
    t0 = time.perf_counter()
    st = real_oscillator_study(Params.from_values(values))
    for f in TABLES:
        assert not re.search(r"\b(nan|inf)\b", repr(f(st)))
    for f in SENTENCES:
        assert not re.search(r"\bnan\b", f(st)), f.__name__
    assert time.perf_counter() - t0 < 60.0
    assert len(st.calibration_runs) == values["n_calibration"]
    assert st.pooled_error("linear")[2] == len(st.driven) - values["n_calibration"]
