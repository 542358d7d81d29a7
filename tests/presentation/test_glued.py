"""Numbers glued into the prose: the book's number format, a tolerance only in the metadata, no nan, short
verdicts; and the nbval comparison that accepts a glued number within its declared tolerance."""

from __future__ import annotations

import ast

import pytest

from vibration.book.presentation import glued
from vibration.book.presentation.numbers import sig


@pytest.fixture
def shown(monkeypatch):
    out = []
    monkeypatch.setattr(glued, "_glue", lambda name, text, metadata=None: out.append((name, text, metadata)))
    return out


def test_a_number_is_glued_as_the_prose_writes_it_with_its_tolerance_out_of_sight(shown):
    assert glued.number("x", 0.450377, rtol=0.01) == sig(0.450377, 4) == "0.4504"
    assert glued.number("t", 78.2345, 3) == "78.2"
    (_, text, meta), (_, text2, meta2) = shown
    assert text == "0.4504" and meta == {"vibration": {"value": 0.450377, "tol": "r0.01"}}
    assert text2 == "78.2" and meta2 is None


def test_nan_and_long_phrases_are_refused(shown):
    with pytest.raises(ValueError, match="'x' is nan"):
        glued.number("x", float("nan"))
    with pytest.raises(ValueError, match="has 13 words: allowed at most 12"):
        glued.phrase("v", " ".join(["word"] * 13))
    assert glued.phrase("v", "far too small") == "far too small"


def test_the_glue_record_is_what_myst_nb_reads(monkeypatch):
    """The output has myst-nb's glue form: its text/plain under the papermill record prefix, the name in
    the scrapbook metadata, and a Python literal that myst-nb's text role reads back without quotes."""
    import IPython.display

    seen = []
    monkeypatch.setattr(IPython.display, "display", lambda data, raw, metadata: seen.append((data, metadata)))
    glued.number("x", 2.23705, rtol=1e-3)
    data, meta = seen[0]
    from myst_nb.core.variables import format_plain_text

    text = data["application/papermill.record/text/plain"]
    assert ast.literal_eval(text) == "2.237" and format_plain_text(text, "") == "2.237"
    assert meta["scrapbook"] == {"name": "x", "mime_prefix": "application/papermill.record/"}


def _record(value: float, text: str, tol: str | None) -> dict:
    meta = {"scrapbook": {"name": "x", "mime_prefix": "application/papermill.record/"}}
    if tol:
        meta["vibration"] = {"value": value, "tol": tol}
    return {"output_type": "display_data", "metadata": meta,
            "data": {"application/papermill.record/text/plain": repr(text)}}  # fmt: skip


def test_the_comparison_accepts_a_glued_number_within_its_tolerance_and_reports_one_outside():
    from nbval_numeric import settle_glued

    ref, near, far = _record(2.1, "2.1", "r0.05"), _record(2.15, "2.15", "r0.05"), _record(2.4, "2.4", "r0.05")
    assert settle_glued([near], [ref]) == [] and near["data"] == ref["data"]
    bad = settle_glued([far], [ref])
    assert len(bad) == 1 and bad[0].new == 2.4 and bad[0].reference == 2.1
    assert far["data"] != ref["data"]  # left for strict nbval to report too
    plain_ref, plain_new = _record(1.0, "1", None), _record(1.5, "1.5", None)
    assert settle_glued([plain_new], [plain_ref]) == [] and plain_new["data"] != plain_ref["data"]


def test_a_count_is_grouped_as_the_book_writes_counts(shown):
    assert glued.count("n", 15001) == "15\u202f001" and glued.count("m", 4526) == "4526"  # five digits and up
    glued.count("k", 11804, rtol=0.25)
    assert shown[-1][2] == {"vibration": {"value": 11804.0, "tol": "r0.25"}}
