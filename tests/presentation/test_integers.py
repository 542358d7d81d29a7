"""Counts (steps, samples, evaluations, episodes) are grouped in threes by a narrow no-break space.

The expected strings are written out by hand from the rule in :mod:`vibration.book.presentation.numbers`:
five or more digits are grouped in threes from the right by U+202F, four or fewer stay together, a
negative count carries the true minus sign U+2212.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from vibration.book.presentation.numbers import integer, parse

NNBSP = "\u202f"  # narrow no-break space
MINUS = "\u2212"

WRITTEN = [
    (0, "0"),
    (7, "7"),
    (4096, "4096"),
    (9999, "9999"),
    (10000, "10\u202f000"),
    (11804, "11\u202f804"),
    (20000, "20\u202f000"),
    (33409, "33\u202f409"),
    (99999, "99\u202f999"),
    (100000, "100\u202f000"),
    (200001, "200\u202f001"),
    (960000, "960\u202f000"),
    (1800200, "1\u202f800\u202f200"),
    (3200000, "3\u202f200\u202f000"),
    (1234567890, "1\u202f234\u202f567\u202f890"),
    (-4096, "\u22124096"),
    (-33409, "\u221233\u202f409"),
]


@pytest.mark.parametrize(("n", "text"), WRITTEN)
def test_a_count_is_written_by_the_rule(n, text):
    assert integer(n) == text


@pytest.mark.parametrize(
    ("n", "text"),
    [
        (np.int64(20000), "20\u202f000"),
        (np.int32(11804), "11\u202f804"),
        (20000.0, "20\u202f000"),
        (np.float64(-4096.0), "\u22124096"),
    ],
)
def test_numpy_integers_and_whole_floats_are_counts_too(n, text):
    assert integer(n) == text


def test_the_separator_is_the_narrow_no_break_space_and_never_a_comma_or_plain_space():
    text = integer(960000)
    assert text[3] == NNBSP
    assert " " not in text and "," not in text and "\u00a0" not in text


@pytest.mark.parametrize("bad", [1.5, -0.25, float("nan"), float("inf"), True, False, "12", None])
def test_a_value_that_is_no_whole_number_is_refused(bad, raises_parameter_error):
    with raises_parameter_error("n", bad, "whole number"):
        integer(bad)


@pytest.mark.parametrize(("n", "text"), WRITTEN)
def test_parse_reads_a_grouped_count_back(n, text):
    assert parse(text) == n


@pytest.mark.parametrize(
    "text",
    [
        "1\u202f234",
        "12\u202f34",
        "960\u202f00",
        "1234\u202f567",
        "\u202f960",
        "960\u202f",
        "9\u202f6\u202f0",
        "1.5\u202f000",
        "1\u202f234\u202f56",
    ],
)
def test_parse_refuses_groups_the_rule_does_not_write(text):
    with pytest.raises(ValueError, match="grouped in threes"):
        parse(text)


@given(st.integers(min_value=-(10**15), max_value=10**15))
def test_every_count_reads_back_and_shows_its_digits_in_order(n):
    text = integer(n)
    assert parse(text) == n
    body = text.removeprefix(MINUS)
    assert text.startswith(MINUS) == (n < 0)
    assert body.replace(NNBSP, "") == str(abs(n))
    groups = body.split(NNBSP)
    if len(str(abs(n))) < 5:
        assert groups == [str(abs(n))]
    else:
        assert 1 <= len(groups[0]) <= 3 and all(len(g) == 3 for g in groups[1:])
