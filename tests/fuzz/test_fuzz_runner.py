"""The runner's ``-p`` combinations that used to start a kernel first (issue 32) are refused by the chapters'
schema rules, through the runner's own validation, before any kernel starts (chapters 6, 10 and 11; chapter 8's
extreme storey rates are not covered: its study finishes at both extremes, the failing cell is not identified)."""

from __future__ import annotations

import pytest

from vibration.book.chapters.digital_twin import params as twin_params
from vibration.book.chapters.digital_twin import study as twin_study
from vibration.book.publishing import report
from vibration.physics.model import ParameterError


@pytest.fixture(scope="module")
def chapters():
    return report.discover()


@pytest.fixture
def no_kernel(monkeypatch):
    import papermill

    def boom(*args, **kwargs):
        raise AssertionError("a kernel was started")

    monkeypatch.setattr(papermill, "execute_notebook", boom)
    monkeypatch.setattr(report, "run_chapter", boom)
    monkeypatch.setattr(report, "_execute_all", boom)


REFUSED = [
    # chapter 6: exp(-c_u t_g / 2m) = exp(1e7) cannot be drawn
    ("06", [("c_unstable", "-10000"), ("t_growth", "2000")], "t_growth", "allowed (-c_unstable/2m) t_growth <= 50"),
    ("06", [("c_unstable", "-1"), ("t_growth", "101")], "t_growth", "t_growth <= 100 s"),
    # chapter 10: a monitored record too short for its filter and its drop
    ("10", [("t_monitor", "5")], "t_monitor", "allowed t_monitor >= 66.67 s"),
    ("10", [("t_monitor", "1"), ("dt", "0.1")], "t_monitor", "allowed t_monitor >= 32 dt"),
    # chapter 11: a sampling step beyond the plant's natural period, or one leaving no identification record
    ("11", [("dt", "1.0")], "dt", "allowed dt < 0.7025 s"),
    ("11", [("dt", "0.5")], "dt", "allowed dt <= 0.3125 s"),
]


@pytest.mark.parametrize(("stem", "pairs", "name", "allowed"), REFUSED)
def test_the_combination_is_refused_before_any_kernel(chapters, no_kernel, stem, pairs, name, allowed):
    chosen = report.select(chapters, [stem])
    with pytest.raises(ParameterError) as info:
        report.check_parameters(chosen, pairs)
    msg = str(info.value)
    assert name in msg and allowed in msg, msg


@pytest.mark.parametrize(
    ("stem", "pairs"),
    [
        ("06", [("c_unstable", "-1"), ("t_growth", "100")]),  # exp(50): the largest growth allowed
        ("10", [("t_monitor", "66.7")]),
        ("11", [("dt", "0.3125")]),
    ],
)
def test_the_edge_of_each_rule_is_accepted(chapters, no_kernel, stem, pairs):
    chosen = report.select(chapters, [stem])
    assert set(report.check_parameters(chosen, pairs)) == {n for n, _ in pairs}


def test_the_monitoring_rule_reads_the_study_constants():
    assert twin_params.MONITOR_SETTLE == twin_study.KALMAN_SETTLE
    assert twin_params.MONITOR_BLOCK == twin_study.KALMAN_BLOCK
