"""Chapter 11 at its default parameters: tables, sentences and figures of the package, checked against the study's
numbers (recomputed here from the raw episode costs), the reader's notation, and no repetition."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from types import SimpleNamespace

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from drawn import drawn_once
from prose import ungrouped_counts

from vibration.book.chapters.learning import figures, summary, tables, text  # noqa: E402
from vibration.book.chapters.learning.study import ACTIVE, SEMI, learning_study  # noqa: E402
from vibration.book.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption  # noqa: E402
from vibration.book.presentation.style import legend_overlap  # noqa: E402

# every test here builds on a study or a book that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

NOTEBOOK = Path(__file__).resolve().parents[3] / "notebooks" / "11_learning.ipynb"


def active_controllers(st):
    return tables.controllers_table(st, "active")


def semi_controllers(st):
    return tables.controllers_table(st, "semi")


TABLES = (
    tables.lqr_table,
    tables.learning_table,
    tables.seed_table,
    active_controllers,
    tables.references_table,
    tables.robustness_table,
    semi_controllers,
    tables.checks_table,
)
SENTENCES = (
    text.platform_text,
    text.lqr_sentence,
    text.horizon_sentence,
    text.learning_sentence,
    text.seed_sentence,
    text.curvature_sentence,
    text.active_sentence,
    text.references_sentence,
    text.identify_design_sentence,
    text.robustness_sentence,
    text.semi_sentence,
    summary.key_results,
    summary.summary_text,
)
FIGURES = tuple(map(drawn_once, (figures.learning_figure, figures.surface_figure, figures.episode_figure)))

#: A number as the chapter prints it (minus signs, decimals, ×10ⁿ, superscript powers).
NUMBER = re.compile(r"[−-]?\d+(?:[.,]\d+)*(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?|10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+")


@pytest.fixture(scope="module")
def study():
    return learning_study()


# ----------------------------------------------------------------------------- checks shared with other parameters


def paired(cmp, a: int, b: int) -> tuple[float, float, float]:
    """Independent recomputation of law b against law a on the same episodes: J_b/J_a - 1, its error, resolved."""
    d = cmp.runs[b].cost - cmp.runs[a].cost
    base = float(np.mean(cmp.runs[a].cost))
    se = float(np.std(d, ddof=1) / math.sqrt(d.size))
    return float(np.mean(d)) / base, se / base, abs(float(np.mean(d))) > 3.0 * se


def _pct_before(sentence: str, phrase: str) -> float:
    """The percentage printed right before ``phrase`` ("11.3 % more than X" -> 11.3)."""
    m = re.search(r"([−-]?[\d.]+(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?) % " + re.escape(phrase), sentence)
    assert m, (phrase, sentence)
    value = m.group(1).replace("−", "-")
    if "×" in value:
        mant, power = value.split(" × 10")
        exp = int(power.translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")))
        return float(mant) * 10.0**exp
    return float(value)


def assert_compared(sentence: str, cmp, a: int, b: int, other: str) -> None:
    """The sentence states law b against ``other`` (law a) with the direction and size the episodes give."""
    rel, _, resolved = paired(cmp, a, b)
    if not resolved:
        assert f"the same as {other} within the sampling error" in sentence, (other, sentence)
        return
    word = "more" if rel > 0 else "less"
    value = _pct_before(sentence, f"{word} than {other}")
    assert value == pytest.approx(100 * abs(rel), rel=6e-3), (other, sentence)


def check_consistency(st) -> None:
    """Every verdict and comparison of the chapter's sentences against the study's numbers."""
    a, s = ACTIVE.index, SEMI.index
    learned = a("learned (ARS)")
    refs = text.references_sentence(st)
    assert_compared(refs, st.active, a("best fixed gain"), learned, "the best fixed gain")
    assert_compared(refs, st.active, a("LQR"), learned, "LQR")
    assert ("lower bound" in refs) == (not st.exo.within_bound)
    run = st.active.runs[learned]
    assert _pct_before(refs, "more than the exact optimum") == pytest.approx(
        100 * (float(np.mean(run.cost)) / st.exo.expected_cost - 1.0), rel=6e-3
    )
    act = text.active_sentence(st)
    assert_compared(act, st.active, a("best passive damper"), learned, "the best passive damper")
    assert ("drive the force to the bound" in act) == (float(np.max(np.abs(run.u))) >= st.res_task.u_max * (1 - 1e-9))
    semi = text.semi_sentence(st)
    for name in ("best constant damping", "clipped skyhook", "clipped LQR"):
        other = f"the {name}" if name.startswith("best") else name
        assert_compared(semi, st.semi, s(name), s("learned (ARS)"), other)
    ident = text.identify_design_sentence(st)
    rel, _, resolved = paired(st.active, learned, a("identified, then designed"))
    if resolved:
        word = "more" if rel > 0 else "less"
        assert _pct_before(ident, f"{word} than the learned law") == pytest.approx(100 * abs(rel), rel=6e-3)
    else:
        assert "the same as the learned law within the sampling error" in ident
    ratios = [r.expected_cost / st.ref.expected_cost for r in st.learners]
    assert ("Both meet the 5 % target" in text.learning_sentence(st)) == all(q <= 1.05 for q in ratios)
    assert ("stays below the bound" in text.lqr_sentence(st)) == (st.ref.peak_force <= st.task.u_max)
    assert ("is the best law for the task" in text.horizon_sentence(st)) == (st.ref.peak_force <= st.task.u_max)
    worst = {sd.method: sd.worst_ratio - 1.0 for sd in st.seeds}
    rounding = worst["cma"] < tables.EXCESS_FLOOR <= worst["ars"]
    assert ("converges to rounding level" in text.curvature_sentence(st)) == rounding
    key = summary.key_results(st)
    assert ("the learners reach the LQR optimum" in key) == all(q <= 1.05 for q in ratios)
    rb = st.robust.cost / st.robust.optimum[:, None]
    keeps = bool(np.all(rb[:, st.robust.laws.index("learned (ARS)")] < rb[:, st.robust.laws.index("LQR")]))
    assert ("keeps its advantage over LQR on every change tried" in summary.summary_text(st)) == keeps
    # the damping on a bound, recomputed from the episodes
    r = st.semi.runs[s("learned (ARS)")]
    ok = r.v != 0
    c = -r.u[ok] / r.v[ok]
    on = np.isclose(c, st.semi_task.c_min, rtol=0, atol=1e-9 * st.semi_task.c_max) | np.isclose(
        c, st.semi_task.c_max, rtol=0, atol=1e-9 * st.semi_task.c_max
    )
    assert _pct_before(semi, "of the time") == pytest.approx(100 * float(np.mean(on)), rel=6e-3)


def check_outputs(st) -> None:
    """No nan or inf anywhere, tables in the reader's notation, every caption true to its figure."""
    for f in TABLES:
        r = repr(f(st))
        assert not re.search(r"\b(nan|inf)\b", r), (f.__name__, r)
        assert not re.search(r"\d[eE][+-]?\d", r), (f.__name__, "e-notation", r)
    for f in SENTENCES:
        s = f(st)
        assert s and not re.search(r"\b(nan|inf|None)\b", s), f.__name__
        check_prose(s, f.__name__)
    for f in FIGURES:
        cap = f(st)
        assert isinstance(cap, Captioned) and cap.name.startswith("fig-learning-")
        check_caption(cap.fig, cap.caption)
        check_caption(cap.fig, cap.remark, layout=False)
        check_prose(cap.caption, f.__name__)
        check_prose(cap.remark, f.__name__)
        check_prose(cap.alt, f.__name__)
        for ax in cap.fig.axes:
            assert legend_overlap(ax) == 0.0, (f.__name__, ax.get_title())


def check_prose(s: str, where: str) -> None:
    """Typeset symbols only: no code names outside maths, no e-notation, no ASCII powers or square roots."""
    plain = re.sub(r"\$[^$]*\$", "", s)
    assert not re.search(r"[A-Za-z]_[A-Za-z0-9]", plain), (where, plain)
    assert not re.search(r"\d[eE][+-]?\d", s), (where, "e-notation", s)
    assert "^" not in plain and "sqrt" not in plain, (where, plain)


# ----------------------------------------------------------------------------- tests


def test_tables_sentences_and_figures_follow_the_numbers(study):
    check_outputs(study)
    check_consistency(study)


def test_known_values_at_the_paper_task(study):
    # the LQR of the default task (doctest of vibration.learn: K = [1.298, 9.268], J* = 0.7663 s)
    lqr = tables.lqr_table(study).rows[0]
    assert (lqr["kx"], lqr["kv"], lqr["J"]) == ("1.298", "9.268", "0.7663")
    assert "$u = -1.298\\,x - 9.268\\,v$" in text.lqr_sentence(study)
    rows = tables.learning_table(study).rows
    assert rows[-1]["method"] == "LQR (Riccati)" and rows[-1]["ratio"] == "1.00000"
    assert repr(tables.checks_table(study)).count("< 10⁻¹²") == 4
    assert study.active.names == ACTIVE and study.semi.names == SEMI


def test_one_number_of_significant_figures_per_column(study):
    for f in TABLES:
        t = f(study)
        for col in t.columns:
            cells = [row[col.key] for row in t.rows if isinstance(row[col.key], str)]
            numeric = [c for c in cells if re.fullmatch(r"[−-]?\d+\.\d+", c)]
            if len(numeric) < 2:
                continue
            sig = {len(c.lstrip("−-").replace(".", "").lstrip("0")) for c in numeric if float(c.replace("−", "-"))}
            assert len(sig) == 1, (f.__name__, col.header, numeric)


def test_every_count_is_grouped_in_threes(study):
    """Steps, episodes and samples of five or more digits read 960 000, never 960000 (nor with a plain space), in
    the sentences, captions, remarks and the tables as the reader sees them."""
    texts = [f(study) for f in SENTENCES]
    texts += [part for cap in (f(study) for f in FIGURES) for part in (cap.caption, cap.remark) if part]
    texts += [f(study)._repr_markdown_() for f in TABLES]
    found = [(n, text[:80]) for text in texts for n in ungrouped_counts(text)]
    assert found == []
    assert not any(re.search(r"\d{1,3}(?: \d{3})+(?!\d)", re.sub(r"\$[^$]*\$", "", t)) for t in texts)


def _paragraphs(st) -> list[str]:
    out = []
    blocks = [f(st) for f in SENTENCES]
    blocks += [part for cap in (f(st) for f in FIGURES) for part in (cap.caption, cap.remark) if part]
    for t in (f(st) for f in TABLES):
        out.append(t.caption)
        out.append("\n".join(" | ".join(str(v) for v in row.values()) for row in t.rows))
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    blocks += ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown"]
    for b in blocks:
        for para in re.split(r"\n\s*\n", b):
            for item in re.split(r"\n(?:> )?\* ", para):
                item = item.strip().lstrip(">* ").strip()
                if len(item) > 40:
                    out.append(item)
    return out


def test_no_paragraph_appears_twice(study):
    seen: dict[str, str] = {}
    for para in _paragraphs(study):
        key = NUMBER.sub("#", para)
        assert key not in seen, f"repeated:\n{para}\n---\n{seen[key]}"
        seen[key] = para


def test_no_sentence_appears_twice(study):
    seen: dict[str, str] = {}
    for para in _paragraphs(study):
        for sentence in re.split(r"(?<=[.;:])\s+(?=[A-Z*])", para):
            if len(sentence) < 60:
                continue
            key = NUMBER.sub("#", sentence)
            assert key not in seen, f"repeated sentence:\n{sentence}"
            seen[key] = sentence


def test_captions_name_the_layout_and_the_coinciding_curves(study):
    curves = figures.learning_figure(study)
    assert curves.caption.startswith("Left:") and "Right:" in curves.caption and "5 % band" not in curves.caption
    for res in study.learners:  # a learning curve is said to meet the optimum line exactly when it ends within 1 %
        ends = res.curve_cost[-1] <= (1 + figures.COINCIDE) * study.ref.expected_cost
        said = f"the {tables.SHORT_NAMES[res.method]} curve coincides with the optimum line" in curves.remark.replace(
            "The ", "the ", 1
        )
        assert said == ends
    surface = figures.surface_figure(study)
    assert "Left: ARS" in surface.caption and "Right: CMA-ES" in surface.caption
    episodes = figures.episode_figure(study)
    assert all(w in episodes.caption for w in ("Top:", "Middle:", "Bottom:"))
    # the caption says curves coincide exactly when two of them do (largest difference within 1 % of the panel)
    x = {n: study.semi.runs[study.s(n)].x[0] for n in figures.EPISODE_SHOW["semi"]}
    scale = max(float(np.max(np.abs(v))) for v in x.values())
    names = list(x)
    close = any(
        float(np.max(np.abs(x[p] - x[q]))) <= figures.COINCIDE * scale
        for i, p in enumerate(names)
        for q in names[i + 1 :]
    )
    middle = episodes.remark.split("With the semi-active damper,")[1].split(".")[0] if close else ""
    assert ("coincide" in middle) == close
    assert ("With the semi-active damper," in episodes.remark) == close
    assert "coincide" not in episodes.caption  # the findings are in the remark


def check_caption_words(st) -> None:
    """Every figure's and every table's caption says what is drawn or listed in at most 60 words."""
    assert CAPTION_WORDS == 60
    for item in [f(st) for f in FIGURES] + [f(st) for f in TABLES]:
        assert caption_words(item.caption) <= 60, (item.name, caption_words(item.caption), item.caption)


def test_every_caption_is_at_most_sixty_words(study):
    """At the default parameters."""
    check_caption_words(study)


@pytest.mark.slow
def test_every_caption_is_at_most_sixty_words_far_from_the_defaults():
    """At a far set: heavier, stiffer, more damped, forced harder at its resonance (a whole study: with the slow
    tests)."""
    check_caption_words(learning_study(m=3.0, k=80.0, F0=12.0, c_nominal=1.2, omega_res=5.16, n_eval=200))


def test_coinciding_and_groups():
    t = np.linspace(0, 1, 50)
    curves = {"a": np.sin(t), "b": np.sin(t) + 1e-4, "c": np.cos(t), "d": np.sin(t) - 1e-4}
    pairs = figures.coinciding(curves)
    assert ("a", "b") in pairs and ("a", "c") not in pairs
    assert figures.groups(list(curves), pairs) == [["a", "b", "d"]]
    st = SimpleNamespace(ref=SimpleNamespace(expected_cost=1.0))
    run = SimpleNamespace(curve_cost=np.array([3, 1.005, 1.02, 1.001, 1.0]), curve_episodes=np.arange(5) * 10)
    assert figures.settled_within(st, run) == 30.0  # back within 1 % for good from the fourth point
    run = SimpleNamespace(curve_cost=np.array([1.0, 1.5]), curve_episodes=np.arange(2))
    assert math.isnan(figures.settled_within(st, run))
