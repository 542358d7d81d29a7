"""The runner's ``-p`` combinations that used to start a kernel first (issue 32) are refused by the chapters'
schema rules, through the runner's own validation, before any kernel starts."""

from __future__ import annotations

import math

import pytest

from vibration.chapters.digital_twin import params as twin_params
from vibration.chapters.digital_twin import study as twin_study
from vibration.physics.model import ParameterError
from vibration.publishing import report


@pytest.fixture(scope="module")
def chapters():
    return report.discover()


@pytest.fixture
def no_kernel(monkeypatch):
    import papermill

    def boom(*args, **kwargs):
        raise AssertionError("a kernel was started")

    monkeypatch.setattr(papermill, "execute_notebook", boom)
    monkeypatch.setattr(report, "notebook_pool", boom)


REFUSED = [
    # chapter 6: exp(-c_u t_g / 2m) = exp(1e7) cannot be drawn
    ("06", [("c_unstable", "-10000"), ("t_growth", "2000")], "t_growth", "allowed (-c_unstable/2m) t_growth <= 50"),
    ("06", [("c_unstable", "-1"), ("t_growth", "101")], "t_growth", "t_growth <= 100 s"),
    # chapter 8: storey rates beyond the time grid (too fast to resolve, too slow for one period)
    ("08", [("storey_mass", "0.001"), ("storey_stiffness", "1e12")], "storey_stiffness", "Nyquist"),
    ("08", [("storey_mass", "1e9"), ("storey_stiffness", "0.001")], "storey_mass", "one period"),
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
        ("08", [("storey_mass", "45359.237"), ("storey_stiffness", "5523500")]),
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


def test_the_storey_rule_bounds_are_the_shear_building_frequencies():
    """The closed form ω_j = 2 √(k/m) sin((2j − 1)π / (2(2n + 1))) against the eigenvalues of the building."""
    import numpy as np

    from vibration.physics.tmd import shear_building

    n, m, k = 5, 45359.237, 5523500.0
    w = shear_building([m] * n, [k] * n, zeta=0.0).natural_frequencies
    j = np.arange(1, n + 1)
    closed = 2.0 * math.sqrt(k / m) * np.sin((2 * j - 1) * math.pi / (2 * (2 * n + 1)))
    np.testing.assert_allclose(w, closed, rtol=1e-10)
