"""Chapter 8's sentences against its own tables, at the defaults and at far runner values (issue 21)."""

from __future__ import annotations

import math
import re

import pytest

from vibration.chapters.tmd import tables, text
from vibration.chapters.tmd.designs import DESIGNS, HINF
from vibration.chapters.tmd.digits import sig
from vibration.chapters.tmd.study import tmd_study


@pytest.mark.parametrize(
    "changes",
    [
        {},
        {"c_nominal": 0.0},
        {"mu": 1.0, "mistuning": 0.5, "c_nominal": 4.4},
        {"mistuning": 0.0, "zeta_building": 0.99, "mu_building": 1.0},
    ],
    ids=["defaults", "undamped", "far", "no-band"],
)
def test_sentences_quote_the_tables(changes):
    st = tmd_study(n_points=201, **changes)
    rows = {r["design"]: r for r in tables.design_table(st).rows}
    body = " ".join(text.chapter_texts(st).values())
    assert "nan" not in body and "inf " not in body
    h, rb = rows["H∞ optimum"], rows["robust min-max"]
    assert str(h["nominal"]) in body and str(rb["worst"]) in body
    assert f"{sig(st.x_static * st.designs[HINF].stroke_force)} m" in text.stroke_sentence(st)
    assert all(r["ok"] for r in tables.checks_table(st).rows)
    # every criterion's optimum wins its own column among the designs
    designs = {d.name: rows[d.name] for d in DESIGNS}
    assert min(designs, key=lambda n: designs[n]["nominal"].value) == "H∞ optimum"
    worst = min(designs, key=lambda n: designs[n]["worst"].value)
    assert worst in (("robust min-max", "H∞ optimum") if st.mistuning == 0 else ("robust min-max",))
    if math.isfinite(st.designs[HINF].kept_low) and st.mistuning > 0:
        kept = re.search(r"keeps (\S+) % of its benefit", text.robustness_sentence(st))
        assert kept, text.robustness_sentence(st)
        shown = float(kept.group(1).replace("−", "-"))
        assert shown == pytest.approx(100 * st.designs[HINF].kept_low, rel=5e-3, abs=0.05)
    for case in st.load_cases:  # the building sentence says "falls" or "rises" as the table's numbers do
        verb = "falls" if case.peak_with <= case.peak_without else "rises"
        assert f"{verb} from {sig(case.scale * case.peak_without)}" in text.building_sentence(st)
