"""Chapter 10 as a reader gets it: no paragraph twice, true words under other parameters, every parameter used.

The default-parameter and other-parameter runs take about half a minute each: marked slow.
"""

from __future__ import annotations

import math
import re

import matplotlib
import numpy as np
import pytest
from drawn import drawn_once
from prose import ungrouped_counts

from vibration.book.chapters.digital_twin import figures, tables, text
from vibration.book.chapters.digital_twin.study import digital_twin_study
from vibration.book.presentation.captions import CAPTION_WORDS, caption_words, check_caption

matplotlib.use("Agg")

SMALL = dict(t_record=30.0, runs=20, sweep_runs=5, assumption_runs=20, t_monitor=120.0, detect_runs=5)
#: Two parameter sets from the schema's ranges besides the defaults: a heavier, stiffer asset driven harder;
#: a softer, lighter-damped one with noisier sensors.
OTHER = {
    "heavy": dict(m=4.0, k=400.0, F_rms=40.0, f_max=5.0, runs=60, assumption_runs=60, detect_runs=20),
    "soft": dict(m=1.0, k=8.0, c_nominal=0.2, noise=0.1, runs=60, assumption_runs=60, detect_runs=20),
}
TABLES = (
    tables.checks_table,
    tables.identification_table,
    tables.coverage_table,
    tables.assumption_table,
    tables.kalman_table,
    tables.detection_table,
    tables.run_length_table,
)
FIGURES = tuple(
    map(
        drawn_once,
        (figures.identification_figure, figures.scaling_figure, figures.tracking_figure, figures.tradeoff_figure),
    )
)
CODE_NAMES = re.compile(r"\b(omega_\w+|x_ss|c_sky|zeta_p|K_v\*|F_rms|f_max|t_record|k_std)\b")


def _normalise(paragraph: str) -> str:
    return re.sub(r"[−-]?\d+(?:[.,]\d+)?(?:e[+-]?\d+)?(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?", "#", paragraph).strip()


def _everything(st) -> list[str]:
    out = list(text.paragraphs(st))
    out += [repr(make(st)) for make in TABLES]
    out += [make(st).caption for make in FIGURES]
    out += [make(st).remark for make in FIGURES]
    return out


def _check_words(st) -> None:
    """No nan or inf, no code names, no e-notation in prose; each stated comparison agrees with the numbers."""
    prose = list(text.paragraphs(st)) + [f"{c.caption} {c.remark}" for c in (make(st) for make in FIGURES)]
    for block in prose + [repr(make(st)) for make in TABLES]:
        assert not re.search(r"\b(nan|inf)\b", block), block
    for block in prose + [make(st)._repr_markdown_() for make in TABLES]:
        assert ungrouped_counts(block) == [], (ungrouped_counts(block), block[:160])  # counts grouped in threes
    for block in prose:
        assert not CODE_NAMES.search(block), block
        assert not re.search(r"\{(?!numref\})", block), block  # an unformatted placeholder
        assert not re.search(r"\d\.?\d*e[+-]?\d", block), block
    fit, truth = st.fit, st.asset
    ls = abs(fit.k / truth.k - 1)
    fd = [abs(e.k / truth.k - 1) for e in (st.half_power, st.circle) if e.k is not None and math.isfinite(e.k)]
    if fd:
        word = "more" if min(fd) > ls else "less"
        assert f"{word} than the time-domain fit" in text.frf_sentence(st)
    walk = next(c for c in st.kalman if c.truth == "random walk")
    honest = abs(walk.ratio - 1) <= walk.halfwidth
    assert ("is not mis-specified" in text.kalman_sentence(st)) == honest
    cov, hw = st.coverage.coverage, st.coverage.coverage_uncertainty
    ok = bool(np.all(np.abs(cov - 0.95) <= hw))
    assert ("so the intervals are honest" in text.coverage_sentence(st)) == ok
    j = st.threshold_index
    for label, ex in st.detection.items():
        assert f"{float(ex.mean_delay[j]):.3g} s for the {label}" in text.key_results(st)
    flags = [ex.flagged() for lb, ex in st.assumptions.experiments.items() if lb != "as assumed"]
    assert ("every broken assumption is flagged" in text.assumption_sentence(st)) == (min(flags) >= 0.5)


@pytest.fixture(scope="module")
def default():
    return digital_twin_study()


@pytest.mark.slow
def test_no_paragraph_twice_at_default_parameters(default):
    seen = {}
    for block in _everything(default):
        for para in [p for p in re.split(r"\n\s*\n", block) if p.strip()]:
            key = _normalise(para)
            assert key not in seen, f"repeated: {para[:120]!r}"
            seen[key] = para


@pytest.mark.slow
def test_default_words_and_captions(default):
    _check_words(default)
    for make in FIGURES:
        cap = make(default)
        check_caption(cap.fig, cap.caption)
        check_caption(cap.fig, cap.remark, layout=False)
    _check_caption_words(default)
    # the coverage target of the chapter: every share within 3 % (95 % half-width)
    assert tables.flag_halfwidth(default) <= 0.03


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(OTHER))
def test_other_parameter_sets(name):
    st = digital_twin_study(**OTHER[name])
    assert st.asset.k == OTHER[name].get("k", 20.0)
    _check_words(st)
    for make in FIGURES:
        cap = make(st)
        check_caption(cap.fig, cap.caption)
        check_caption(cap.fig, cap.remark, layout=False)
    for make in TABLES:
        make(st)
    _check_caption_words(st)


def _check_caption_words(st) -> None:
    """Every figure's and every table's caption says what is drawn or listed in at most 60 words."""
    assert CAPTION_WORDS == 60
    for item in [make(st) for make in FIGURES] + [make(st) for make in TABLES]:
        assert caption_words(item.caption) <= 60, (item.name, caption_words(item.caption), item.caption)


#: Far from the defaults: three times the mass, four times the stiffness, more damping, six times the force.
FAR = dict(m=3.0, k=80.0, c_nominal=1.2, F_rms=12.0)


@pytest.mark.slow  # over 1 s: make test-slow runs it
@pytest.mark.parametrize("values", [{}, pytest.param(FAR, marks=pytest.mark.slow)], ids=["defaults", "far"])
def test_every_caption_is_at_most_sixty_words(values):
    """At the default parameters and far from them (short runs: the captions name no run count)."""
    _check_caption_words(digital_twin_study(**SMALL, **values))


def _fingerprint(st) -> dict:
    return {
        "force rms": float(np.sqrt(np.mean(st.test.force**2))),
        "test": float(np.sum(st.test.x)),
        "checks": tuple(v for v, *_ in st.checks.values()),
        "coverage": float(np.sum(st.coverage.estimates)),
        "sweeps": float(sum(np.sum(e.estimates) for e in st.by_noise + st.by_length)),
        "assumptions": float(sum(np.sum(e.estimates) for e in st.assumptions.experiments.values())),
        "monitored": float(np.sum(st.monitored.force)),
        "kalman": tuple(c.actual for c in st.kalman),
        "detection": float(sum(np.nansum(e.first_crossing) for e in st.detection.values())),
        "run lengths": tuple(st.run_lengths.alarms.tolist()),
        "delay theory": tuple(d.mean_delay for d in st.delay_theory.values()),
        "grid": float(np.sum(st.grid.estimates)),
    }


@pytest.mark.slow
@pytest.mark.parametrize(("name", "value"), [("f_max", 3.0), ("F_rms", 5.0), ("dt", 0.025)])
def test_every_parameter_reaches_every_part(name, value):
    base = _fingerprint(digital_twin_study(**SMALL))
    changed = _fingerprint(digital_twin_study(**{**SMALL, name: value}))
    same = [part for part in base if part != "force rms" and base[part] == changed[part]]
    if name == "F_rms":
        # a linear twin with noise relative to the response: scaling the force scales every record and leaves
        # each relative result as it was; the records themselves and the absolute check must see it
        assert changed["force rms"] == pytest.approx(base["force rms"] * value / 2.0, rel=1e-9)
        same = [p for p in same if p in ("checks", "test", "monitored")]
    assert same == [], f"{name} does not reach {same}"
