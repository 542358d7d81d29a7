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

    ok = Table(
        rows=[{"a": 1.0}],
        columns=[Column(key="a", header="x_ss (m)")],
        caption="At t_end = 5 s and ω_res.",
        name="tab-x",
    )
    assert header_problems(ok) == []
    bad = Table(
        rows=[{"a": float("nan")}],
        columns=[Column(key="a", header="omega_res (rad/s)")],
        caption="F0 = 1e-5 N",
        name="tab-y",
    )
    assert len(header_problems(bad)) == 4


def test_repetition_check_sees_a_repeat_with_other_rounding():
    a = "The peak is 2.237 m.\n\n- It settles after 15.7 s."
    b = "- It settles after 15.65 s.\n- Something else."
    assert repeated([a, b]) == ["- It settles after 15.65 s."]
    assert repeated([a, "- It settles later."]) == []


def test_columns_read_key_header_digits_and_flags_from_a_text_block():
    from vibration.presentation.tables import Column, columns

    got = columns(
        """
        case   case
        c      c (N s/m)          3
        err    max |x − x_exact|  2  hidden
        omega  ω (rad/s)          4  nozeros
        """
    )
    assert got == [
        Column(key="case", header="case"),
        Column(key="c", header="c (N s/m)", digits=3),
        Column(key="err", header="max |x − x_exact|", digits=2, shown=False),
        Column(key="omega", header="ω (rad/s)", digits=4, zeros=False),
    ]


def test_columns_refuse_a_line_without_header_or_with_an_unknown_word():
    import pytest

    from vibration.presentation.tables import columns

    with pytest.raises(ValueError, match="two spaces apart"):
        columns("c (N s/m)")
    with pytest.raises(ValueError, match="'bold'"):
        columns("c  c (N s/m)  bold")


def test_self_checks_is_a_table_of_checks_with_the_given_headers():
    from vibration.presentation.tables import self_checks

    t = self_checks(
        [("energy balance", "< 10⁻¹²", True), ("poles", 0.0123456, False)],
        caption="Checks.",
        name="tab-checks",
        headers=("self-check", "difference", "passes"),
        digits=3,
    )
    assert [c.header for c in t.columns] == ["self-check", "difference", "passes"]
    assert t.cells() == [["energy balance", "< 10⁻¹²", "yes"], ["poles", "0.0123", "no"]]


def test_a_table_is_built_by_keyword_and_not_changed_afterwards():
    import dataclasses

    import pytest

    from vibration.presentation.tables import Column, Missing

    cols = [Column(key="a", header="a (m)")]
    with pytest.raises(TypeError):
        Table([{"a": 1.0}], cols, "Caption.", "tab-x")  # type: ignore[misc]
    t = Table(rows=[{"a": Missing(reason="none")}], columns=cols, caption="Caption.", name="tab-x")
    with pytest.raises(dataclasses.FrozenInstanceError):
        t.caption = "Other."  # type: ignore[misc]
    assert t.caption == "Caption." and t._marks == {"none": "a"}
