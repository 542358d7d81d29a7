"""Learning chapter presentation: tables, sentences from results, figures with free legends."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from vibration.physics import learning as L  # noqa: E402
from vibration.presentation import learning as P  # noqa: E402
from vibration.presentation.style import legend_overlap  # noqa: E402


@pytest.fixture(scope="module")
def chapter():
    task = L.OscillatorTask()
    ref = L.lqr_reference(task)
    learners = [L.train(task, seed=0, method="ars", iterations=30), L.train(task, seed=0, method="cma")]
    res_task = L.resonance_task()
    semi_task = L.semi_active_task()
    active = L.compare_controllers(
        res_task, {"no control": [0, 0], "LQR": ref.gains, "learned": learners[1].gains}, 16, 0
    )
    semi = L.compare_controllers(
        semi_task, {"best constant damping": [0, 15.0], "clipped LQR": ref.gains, "learned": [25.0, 25.0]}, 16, 0
    )
    return task, ref, learners, active, semi


def test_tables_and_sentences(chapter):
    task, ref, learners, active, semi = chapter
    text = repr(P.lqr_table(task, ref))
    assert "1.298" in text and "9.268" in text and "0.7663" in text
    assert "$u = -1.298\\,x - 9.268\\,v$" in P.lqr_sentence(task, ref)
    lt = repr(P.learning_table(task, ref, learners))
    assert "CMA-ES" in lt and "—a" in lt
    assert "5 % target" in P.learning_sentence(task, ref, learners)
    ct = P.comparison_table(active, "cap", "tab-x", reference=1)
    assert ct.rows[1]["rel"] == 1.0
    assert "less than LQR" in P.comparison_sentence(active, 2, {"LQR": 1})
    note = P.closing_note(task, ref, learners, active, semi, 2, 1, 2, 0)
    assert "Learned-to-LQR expected-cost ratio" in note
    assert 0.0 <= P.bound_fraction(semi, 2) <= 1.0
    assert P.bound_fraction(semi, 0) == 1.0  # constant damping at c_max
    checks = repr(P.checks_table(L.verification(task, ref.gains)))
    assert checks.count("< 1e-12") == 4


def test_figures_keep_legends_off_the_data(chapter):
    task, ref, learners, active, semi = chapter
    fig = P.learning_figure(task, ref, learners)
    for ax in fig.axes:
        assert legend_overlap(ax) == 0.0
    plt.close(fig)
    fig = P.comparison_figure(active, semi, {"active": [1, 2], "semi": [0, 2], "damping": [1, 2]})
    for ax in fig.axes:
        assert legend_overlap(ax) == 0.0
    plt.close(fig)
