"""The reader's-text checks of tests/prose.py (imported by the chapters' tests) can fail."""

from __future__ import annotations

from prose import header_problems, prose_problems, repeated

from vibration.book.presentation.tables import Table


def test_prose_checks_can_fail():
    assert prose_problems("x_ss = 1") == ["code name: x_ss"]
    assert prose_problems("ω_res = 4.47 rad/s") == ["raw subscript: ω_res"]
    assert prose_problems("1.2e5 N") == ["e-notation: 1.2e5"]
    assert prose_problems("$x_\\mathrm{ss}$ and {numref}`fig-a_b`") == []


def test_table_checks_allow_rendered_subscripts_only():
    from vibration.book.presentation.tables import Column

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
    from vibration.book.presentation.tables import Column, columns

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

    from vibration.book.presentation.tables import columns

    with pytest.raises(ValueError, match="two spaces apart"):
        columns("c (N s/m)")
    with pytest.raises(ValueError, match="'bold'"):
        columns("c  c (N s/m)  bold")


def test_self_checks_is_a_table_of_checks_with_the_given_headers():
    from vibration.book.presentation.tables import self_checks

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

    from vibration.book.presentation.tables import Column, Missing

    cols = [Column(key="a", header="a (m)")]
    with pytest.raises(TypeError):
        Table([{"a": 1.0}], cols, "Caption.", "tab-x")  # type: ignore[misc]
    t = Table(rows=[{"a": Missing(reason="none")}], columns=cols, caption="Caption.", name="tab-x")
    with pytest.raises(dataclasses.FrozenInstanceError):
        t.caption = "Other."  # type: ignore[misc]
    assert t.caption == "Caption." and t._marks == {"none": "a"}


NNBSP = "\u202f"  # the narrow no-break space between a count's groups


def test_prose_check_finds_a_count_of_five_or_more_digits_written_ungrouped():
    assert prose_problems("RK45 needs 11804 evaluations.") == ["ungrouped count: 11804"]
    assert prose_problems("From 1800200 samples (16000 to 64000 steps per period).") == [
        "ungrouped count: 1800200",
        "ungrouped count: 16000",
        "ungrouped count: 64000",
    ]
    assert prose_problems('<span class="vib-approx" data-value="27010.6" data-tol="f10">27000</span> s') == [
        "ungrouped count: 27000"
    ]


def test_prose_check_passes_grouped_counts_short_counts_decimals_maths_and_identifiers():
    clean = (
        f"RK45 needs 11{NNBSP}804 evaluations, OP853 4526; 1{NNBSP}800{NNBSP}200 samples; t = 0.000123456 s; "
        "a value of 12345.6 m; $N = 20000$ in maths; `n_steps=64000` in code; ⟪120000 r0.25⟫ in the plain form; "
        '<td data-value="33409">33' + NNBSP + "409</td>; doi 10.1016/j.jsv.2019.115012; in 1999."
    )
    assert prose_problems(clean) == []


def test_an_integer_cell_is_a_count_grouped_for_the_reader_and_plain_in_the_csv(tmp_path):
    from vibration.book.presentation.tables import Approx, Column

    t = Table(
        rows=[{"n": 4096, "m": 20000}, {"n": 7, "m": Approx(value=28232, rtol=0.25)}],
        columns=[Column(key="n", header="steps"), Column(key="m", header="evaluations")],
        caption="Counts.",
        name="tab-counts",
    )
    assert t.cells() == [["4096", f"20{NNBSP}000"], ["7", f"28{NNBSP}232"]]
    for shown in (t._repr_markdown_(), t._repr_html_()):
        assert f"20{NNBSP}000" in shown and "20000" not in shown.replace('data-value="', "")
    assert header_problems(t) == []
    path = t.write_csv(tmp_path)
    assert path.read_text(encoding="utf-8").splitlines()[1].split(",")[1] == "20000"


def test_table_check_finds_an_ungrouped_count_given_as_text():
    from vibration.book.presentation.tables import Column

    t = Table(rows=[{"n": "64000"}], columns=[Column(key="n", header="steps")], caption="Counts.", name="tab-t")
    assert header_problems(t) == ["cell '64000': ungrouped count: 64000", "ungrouped count 64000 in the rendered table"]
    noted = Table(
        rows=[{"n": 3}],
        columns=[Column(key="n", header="alarms")],
        caption="Counts.",
        name="tab-n",
        notes=("False-alarm rows: 1800200 monitored samples.",),
    )
    assert header_problems(noted) == ["ungrouped count 1800200 in the rendered table"]
