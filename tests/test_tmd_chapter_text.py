"""Chapter 8's sentences against its own tables, at the defaults and at far runner values (issue 21)."""

from __future__ import annotations

import math

import pytest

from vibration.presentation import tmd as chapter

DEFAULTS = dict(m=1.0, k=20.0, c=0.5, F0=5.0, omega_res=4.47, t_end=50.0, mu=0.05, mistuning=0.1, n_storeys=5,
                storey_mass=45359.237, storey_stiffness=5523500.0, zeta_building=0.05, mu_building=0.02,
                n_points=201)  # fmt: skip


@pytest.mark.parametrize(
    "changes",
    [
        {},
        {"c": 0.0},
        {"mu": 1.0, "mistuning": 0.5, "c": 4.4},
        {"mistuning": 0.0, "zeta_building": 0.99, "mu_building": 1.0},
    ],
    ids=["defaults", "undamped", "far", "no-band"],
)
def test_sentences_quote_the_tables(changes):
    ch = chapter.tmd_chapter(**{**DEFAULTS, **changes})
    rows = {r["design"]: r for r in chapter.design_table(ch).rows}
    text = " ".join(
        f(ch)
        for f in (chapter.design_sentence, chapter.stroke_sentence, chapter.robustness_sentence,
                  chapter.building_sentence, chapter.summary_sentence, chapter.response_sentence)
    )  # fmt: skip
    assert "nan" not in text and "inf " not in text
    h, rb = rows["H∞ optimum"], rows["robust min-max"]
    assert f"{h['nominal']:.4g}" in text and f"{rb['worst']:.4g}" in text
    assert f"{5.0 / 20.0 * ch.designs['H∞ optimum'].stroke_force:.4g} m" in chapter.stroke_sentence(ch)
    assert all(c.ok if hasattr(c, "ok") else c["ok"] for c in chapter.checks_table(ch).rows)
    # every criterion's optimum wins its own column
    assert min(rows, key=lambda n: rows[n]["nominal"]) == "H∞ optimum"
    assert (
        min(rows, key=lambda n: rows[n]["worst"]) in ("robust min-max", "H∞ optimum")
        if ch.mistuning == 0
        else (min(rows, key=lambda n: rows[n]["worst"]) == "robust min-max")
    )
    if math.isfinite(ch.designs["H∞ optimum"].kept_low) and ch.mistuning > 0:
        assert f"{100 * ch.designs['H∞ optimum'].kept_low:.3g} %" in chapter.robustness_sentence(ch)
    for case in ch.load_cases:  # the building sentence says "falls" or "rises" as the table's numbers do
        verb = "falls" if case.peak_with <= case.peak_without else "rises"
        assert f"{verb} from {case.scale * case.peak_without:.4g}" in chapter.building_sentence(ch)
