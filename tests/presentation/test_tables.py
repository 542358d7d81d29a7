"""The reader's-text checks of tests/prose.py (imported by the chapters' tests) can fail."""

from __future__ import annotations

from prose import header_problems, prose_problems, repeated

from vibration.presentation.tables import Table


def test_prose_checks_can_fail():
    assert prose_problems("x_ss = 1") == ["code name: x_ss"]
    assert prose_problems("ω_res = 4.47 rad/s") == ["raw subscript: ω_res"]
    assert prose_problems("1.2e5 N") == ["e-notation: 1.2e5"]
    assert prose_problems("$x_\\mathrm{ss}$ and {numref}`fig-a_b`") == []


def test_table_checks_allow_rendered_subscripts_only():
    from vibration.presentation.tables import Column

    ok = Table([{"a": 1.0}], [Column(key="a", header="x_ss (m)")], caption="At t_end = 5 s and ω_res.", name="tab-x")
    assert header_problems(ok) == []
    bad = Table(
        [{"a": float("nan")}], [Column(key="a", header="omega_res (rad/s)")], caption="F0 = 1e-5 N", name="tab-y"
    )
    assert len(header_problems(bad)) == 4


def test_repetition_check_sees_a_repeat_with_other_rounding():
    a = "The peak is 2.237 m.\n\n- It settles after 15.7 s."
    b = "- It settles after 15.65 s.\n- Something else."
    assert repeated([a, b]) == ["- It settles after 15.65 s."]
    assert repeated([a, "- It settles later."]) == []
