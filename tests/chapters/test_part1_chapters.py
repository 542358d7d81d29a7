"""Part I, chapters 0 (front page), 1 (reproduction) and 2 (claims audit) as textbook chapters.

The studies against independent computations (closed forms written out here, SciPy's RK45 called
directly, the audit's own verdict rule); every sentence, table and caption built at the paper's
parameters and at other parameter sets, checked for code notation, nan/inf, repeated paragraphs,
mixed precision within a column, the book's case colours, and each stated comparison re-derived
from the numbers.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from vibration.book.chapters.claims_audit import claims_audit_study
from vibration.book.chapters.claims_audit import tables as audit_text
from vibration.book.chapters.claims_audit.notation import cell, code_left, prose
from vibration.book.chapters.overview import figures as front_figures
from vibration.book.chapters.overview import overview_study
from vibration.book.chapters.overview import tables as front_text
from vibration.book.chapters.reproduction import figures as rep_figures
from vibration.book.chapters.reproduction import reproduction_study
from vibration.book.chapters.reproduction import tables as rep_tables
from vibration.book.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption
from vibration.book.presentation.style import case_style
from vibration.physics.audit import verdict

ROOT = Path(__file__).resolve().parents[2]

#: Other parameter sets from the schemas' ranges: heavier and stiffer; softer and lighter damped; zero and
#: negative damping.
OTHER = {
    "heavy": dict(m=4.0, k=400.0, F0=40.0, omega_ref=6.0, omega_res=10.0, c_low=0.4, c_nominal=2.0, c_high=60.0),
    "soft": dict(
        m=1.0, k=5.0, F0=1.0, t_end=100.0, omega_ref=1.0, omega_res=2.2, c_low=0.02, c_nominal=0.1, c_high=8.0
    ),
    "zero-negative": dict(c_low=0.0, c_nominal=-0.1, c_high=5.0),
}
SETS = {"paper": {}, **OTHER}


@pytest.fixture(scope="module", params=list(SETS))
def chapters(request):
    """The three studies at one parameter set, with every text, table and figure of the chapters built."""
    values = SETS[request.param]
    rep = reproduction_study(**values, n_points=2001)
    audit = claims_audit_study(**values, n_points=2001)
    front = overview_study(**values)
    figures = [
        rep_figures.resonance_figure(rep),
        rep_figures.damping_figure(rep),
        rep_figures.error_figure(rep),
        front_figures.headline_figure(front),
    ]
    texts = {}
    tables = [
        rep_tables.findings_table(rep),
        rep_tables.methods_table(rep),
        audit_text.claims_table(audit),
        audit_text.verdict_table(audit),
        audit_text.reasons_table(audit),
        front_text.headline_table(front),
        front_text.verdict_table(front),
    ]
    readings = audit_text.readings_table(audit)
    tables += [readings] if readings is not None else []
    return {"key": request.param, "rep": rep, "audit": audit, "front": front, "figures": figures, "texts": texts,
            "tables": tables}  # fmt: skip


# ----------------------------------------------------------------------------- the studies, independently


def _steady(m, c, k, F0, w):
    return F0 / math.hypot(k - m * w * w, c * w)


def test_reproduction_matches_the_closed_form_and_scipy_called_directly():
    st = reproduction_study(n_points=2001)
    p = st.params
    for sid, sc in st.scenarios.items():
        f = st.cases[sid]
        osc, force = sc.oscillator, sc.force
        assert f.x_ss == pytest.approx(_steady(p.m, osc.c, p.k, p.F0, force.omega), rel=1e-12)
        assert f.v_ss == pytest.approx(force.omega * f.x_ss, rel=1e-12)
        assert f.zeta == pytest.approx(osc.c / (2 * math.sqrt(p.k * p.m)), rel=1e-12)
        t = np.linspace(0.0, p.t_end, p.n_points)
        sol = solve_ivp(
            lambda t, y, o=osc, fo=force: [y[1], (fo.F0 * math.sin(fo.omega * t) - o.c * y[1] - o.k * y[0]) / o.m],
            (0.0, p.t_end), [0.0, 0.0], t_eval=t,
        )  # fmt: skip
        assert f.peak_x_rk45 == pytest.approx(np.max(np.abs(sol.y[0])), rel=1e-9)
        assert f.settles == (f.t_settle <= p.t_end)
    # the paper's resonance case and its nominal damping (the list's second) are one run; the others distinct
    assert [list(r) for r in st.runs] == [["reference"], ["resonance", "damping_1"], ["damping_0"], ["damping_2"]]
    assert st.paper["resonance"] is st.paper["damping_1"]
    assert [st.cases[s].c for s in st.dampings] == [p.c_low, p.c_nominal, p.c_high]
    # the steady amplitude bounds the late window: after settling the peak is x_ss within 2 %
    res = st.cases["resonance"]
    late = st.exact["resonance"].t > res.t_settle
    assert np.max(np.abs(st.exact["resonance"].x[late])) == pytest.approx(res.x_ss, rel=0.02)


def test_the_audit_study_types_every_row_and_its_decay_rates_are_the_closed_forms():
    st = claims_audit_study(n_points=2001)
    assert len(st.claims) == len(st.rows) == 20
    assert sum(st.counts.values()) == 20
    for c, row in zip(st.claims, st.rows, strict=True):
        assert c.claim_id == row["claim_id"] and c.verdict == row["verdict"] and c.best.description == c.best_reading
    p = st.params
    # underdamped: the slowest free mode decays at c/(2m); overdamped: at the slower real root
    assert st.slowest_decay["damping_low"] == pytest.approx(p.c_low / (2 * p.m), rel=1e-12)
    s = p.c_high / (2 * p.m)
    assert st.slowest_decay["damping_high"] == pytest.approx(s - math.sqrt(s * s - p.k / p.m), rel=1e-9)


def test_the_front_page_values_are_the_closed_forms():
    st = overview_study()
    p = st.params
    assert st.x_res == pytest.approx(_steady(p.m, p.c_nominal, p.k, p.F0, p.omega_res), rel=1e-12)
    assert st.ratio == pytest.approx(st.x_res / _steady(p.m, p.c_nominal, p.k, p.F0, p.omega_ref), rel=1e-12)
    assert st.growth_low == pytest.approx(-p.c_low / (2 * p.m), rel=1e-12)
    assert st.verdicts == claims_audit_study(n_points=5001).counts
    assert st.n_claims == 20


# ----------------------------------------------------------------------------- the reader's text


def _paragraphs(markdown: str) -> list[str]:
    """Paragraphs, list items and quoted lines of a Markdown text, as the book's proofreading splits them."""
    out = []
    for block in re.split(r"\n\s*\n", markdown):
        lines = [ln.strip() for ln in block.splitlines() if ln.strip()]
        if any(re.match(r"^(>\s*)?[-*] ", ln) for ln in lines):
            out += [re.sub(r"^(>\s*)?[-*] ", "", ln) for ln in lines if re.match(r"^(>\s*)?[-*] ", ln)]
        else:
            out.append(" ".join(ln.lstrip("> ") for ln in lines))
    return [p for p in out if len(p) >= 12]


def _normal(text: str) -> str:
    """The book's normalisation: maths dropped (the proofreader skips it), every number replaced by #."""
    text = re.sub(r"\$[^$]*\$", "", text)
    return re.sub(r"[−-]?\d[\d.,]*(?:\s?×\s?10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?", "#", " ".join(text.split()))


def _notebook_markdown(name: str) -> list[str]:
    nb = json.loads((ROOT / "notebooks" / name).read_text(encoding="utf-8"))
    return ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown"]


@pytest.mark.parametrize(
    "notebook, keys, figures, tables",
    [
        ("01_reproduction.ipynb", ("rep ",), (0, 1, 2), (0, 1)),
        ("02_claims_audit.ipynb", ("audit ",), (), (2, 3, 4, 7)),
        ("00_overview.ipynb", ("front ",), (3,), (5, 6)),
    ],
    ids=["chapter 1", "chapter 2", "front page"],
)
def test_no_paragraph_appears_twice_in_a_chapter(chapters, notebook, keys, figures, tables):
    """Every sentence, list item, caption and the notebook's own prose, numbers normalised: each once."""
    paragraphs = [p for k, t in chapters["texts"].items() if k.startswith(keys) for p in _paragraphs(t)]
    paragraphs += [p for md in _notebook_markdown(notebook) for p in _paragraphs(md)]
    paragraphs += [chapters["figures"][i].caption for i in figures]
    paragraphs += [chapters["figures"][i].remark for i in figures if chapters["figures"][i].remark]
    paragraphs += [chapters["tables"][i].caption for i in tables if i < len(chapters["tables"])]
    seen: dict[str, str] = {}
    for p in paragraphs:
        key = _normal(p)
        assert key not in seen, f"repeated: {p!r} and {seen[key]!r}"
        seen[key] = p


def test_no_code_notation_nan_or_inf_in_the_readers_text(chapters):
    for name, text in chapters["texts"].items():
        prose_only = "\n".join(ln for ln in text.splitlines() if not ln.lstrip().startswith('> "'))  # quotes stay
        assert code_left(prose_only) == [], (chapters["key"], name, code_left(prose_only))
        assert not re.search(r"\b(nan|inf)\b|\"None\"", text), (chapters["key"], name)
    for fig in chapters["figures"]:
        assert code_left(fig.caption) == [] and code_left(fig.alt) == [], fig.name
        assert not re.search(r"\b(nan|inf)\b", fig.caption + fig.alt), fig.name
    for table in chapters["tables"]:
        for row in table.cells():
            for text in (t for t in row if not t.startswith("“")):  # the paper's words, quoted, stay as written
                assert not re.search(r"\b(nan|inf)\b|^None$|_|\de[-+]?\d", text), (table.name, text)


def _significant(text: str) -> int | None:
    """Significant digits of a number cell ("0.04504" -> 4, "10.00" -> 4); None for words and inputs."""
    m = re.fullmatch(r"[−-]?(\d+(?:\.\d+)?)( [a-zA-Z/]+)?", text)
    if not m:
        return None
    digits = m.group(1).replace(".", "").lstrip("0")
    return len(digits) or None  # an exact zero is written "0"


#: Columns that show inputs (parameters as given) or counts, not computed values.
INPUT_COLUMNS = {"c (N s/m)", "ω (rad/s)", "claims", "claim"}


def test_one_precision_per_table_column(chapters):
    for table in chapters["tables"]:
        cells = table.cells()
        for j, col in enumerate(table.columns):
            if col.header in INPUT_COLUMNS:
                continue
            counts = {_significant(row[j]) for row in cells} - {None}
            # a value that rounds to a power of ten keeps its zeros ("10.00"), so one count per column
            assert len(counts) <= 1, (table.name, col.header, [row[j] for row in cells])


def test_captions_pass_their_figure_check_and_the_cases_keep_their_colours(chapters):
    rep = chapters["rep"]
    for fig in chapters["figures"]:
        assert isinstance(fig, Captioned)
        check_caption(fig.fig, fig.caption)
    resonance, damping, error, front = chapters["figures"]
    # the damping columns in the paper's case colours (by position in the list), RK45 solid, exact black dashed
    for ax, case in zip(damping.fig.axes[: len(rep.dampings)], ("c_low", "c_nominal", "c_high"), strict=True):
        rk45, exact = ax.get_lines()[:2]
        assert matplotlib.colors.to_hex(rk45.get_color()) == case_style(case)["color"].lower()
        assert matplotlib.colors.to_hex(exact.get_color()) == "#000000" and exact.get_linestyle() == "--"
    colours = {matplotlib.colors.to_hex(line.get_color()) for line in resonance.fig.axes[0].get_lines()}
    assert {case_style("c_nominal")["color"].lower(), case_style("reference")["color"].lower()} <= colours
    assert (
        matplotlib.colors.to_hex(front.fig.axes[0].get_lines()[0].get_color())
        == case_style("c_nominal")["color"].lower()
    )


def test_chapter_one_captions_stay_within_the_books_limit(chapters):
    """Every figure and table caption of chapter 1 is at most 60 words, at the paper's and the other parameters."""
    resonance, damping, error, _front = chapters["figures"]
    findings, methods = chapters["tables"][:2]
    for item in (resonance, damping, error, findings, methods):
        assert caption_words(item.caption) <= CAPTION_WORDS, (chapters["key"], item.name, item.caption)


@pytest.mark.parametrize("dampings", [[0.1, 0.5, 2.0, 15.0], [0.3, 7.0], [0.05]])
def test_a_list_of_dampings_gives_one_run_column_and_row_each_at_the_closed_form(dampings):
    st = reproduction_study(dampings=dampings, n_points=1001)
    p = st.params
    assert [st.cases[s].c for s in st.dampings] == dampings
    for sid in st.dampings:
        assert st.cases[sid].x_ss == pytest.approx(_steady(p.m, st.cases[sid].c, p.k, p.F0, p.omega_res), rel=1e-12)
    fig = rep_figures.damping_figure(st)
    assert len(fig.fig.axes) == 2 * len(dampings)
    rows = rep_tables.findings_table(st).cells()
    assert len(rows) == len(st.runs) == 2 + len(dampings) - (p.c_nominal in dampings)


def test_the_audits_counts_and_reasons_follow_its_verdicts(chapters):
    st = chapters["audit"]
    judged = [c for c in st.claims if c.paper_method_value not in ("", None) and c.exact_value is not None]
    same = sum(verdict(c.kind, c.paper_value, c.paper_method_value, quantity=c.quantity.split(" [")[0]) == c.verdict
               for c in judged)  # fmt: skip
    assert audit_text.solver_agreement(st)[:2] == (same, len(judged))
    # one row per claim, each quoted once, with its verdict; a failed claim names its best reading
    rows = {row["id"]: row for row in audit_text.reasons_table(st).rows}
    for c in st.claims:
        row = rows[c.claim_id]
        assert row["verdict"] == c.verdict and c.quote in row["quote"]
        assert isinstance(row["best"], str) == (c.verdict != "reproduced")
    gap = audit_text.largest_gap(st)
    numeric = [c for c in st.claims if c.verdict != "reproduced" and math.isfinite(c.factor) and c.factor > 0]
    assert (gap is None) == (not numeric)
    if gap is not None:
        assert abs(math.log(gap.factor)) == max(abs(math.log(c.factor)) for c in numeric)


def test_the_front_pages_stability_word_follows_the_poles(chapters):
    st = chapters["front"]
    p = st.params
    poles = np.roots([p.m, p.c_low, p.k])
    growth = float(np.max(poles.real))
    assert st.growth_low == pytest.approx(growth, abs=1e-12)
    word = "stable" if growth < -1e-12 else "unstable" if growth > 1e-12 else "marginally stable"
    assert front_text.stability_word(st) == word


# ----------------------------------------------------------------------------- the notation helpers


def test_the_audit_notation_leaves_no_code_and_keeps_quantities_readable():
    assert code_left(prose("x_ss = 2.237 m; ω/ω_n = 1; F0/k; t_end; exp(-2.5 t/s); 2.94e3 s")) == []
    assert code_left("the peak x_ss and 1.2e5") == ["x_ss", "1.2e5"], "the check can fail"
    assert cell("magnification x_ss/(F0/k) at resonance") == "magnification xₛₛ/(F₀/k) at resonance"
    assert "−0.1" in prose("c = -0.1 N s/m") and "$e^{-2.5" in prose("grows as exp(-2.5 t/s)")
