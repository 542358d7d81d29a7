"""Chapter 7 as a reader meets it: every sentence, table and figure at the defaults and under other parameters.

* Nothing repeats: no two paragraphs (sentence blocks, bullets, captions, the notebook's Markdown) are equal once
  every number is replaced by ``#``.
* Reader's notation: no code names, e-notation, ``^2`` or ``sqrt(`` outside maths; one number of significant
  figures per table column; every figure's caption passes the shared check against the drawing.
* Under the runner-level set ``c_nominal = 3, omega_res = 2.5``, under ``m = 4, k = 400, F0 = 40`` and under a
  softer, lighter-damped plant, every stated comparison (the best design, the delay-margin ordering, the
  feasibility of the force-limited set point, the integrator's effect, the semi-active verdict, the better
  shaper) is checked against numbers recomputed here: the loop amplitudes from python-control's transfer
  functions, the holding force from k |x_ref| + F0, and the limited runs' own steady error.
"""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from pathlib import Path

import control
import numpy as np
import pytest
from prose import ungrouped_counts

from vibration.book.chapters.control import tables as T
from vibration.book.chapters.control import text as X
from vibration.book.chapters.control.figures import all_figures, closeness
from vibration.book.chapters.control.notation import LABELS, cell, num
from vibration.book.chapters.control.params import SCHEMA, Params
from vibration.book.chapters.control.study import control_study
from vibration.book.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption

# every test here builds on a study, a figure set or a browser that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[3]
NOTEBOOK = ROOT / "notebooks" / "07_control.ipynb"
USAGE = ROOT / "src" / "vibration" / "book" / "chapters" / "control" / "usage.md"

#: The parameter sets beyond the defaults (issue 21): the runner's, a heavy stiff plant, a soft light one.
OTHER = {
    "runner": {"c_nominal": 3.0, "omega_res": 2.5},
    "heavy": {"m": 4.0, "k": 400.0, "F0": 40.0},
    "soft": {"k": 10.0, "c_nominal": 0.2, "omega_res": 3.16, "F0": 2.0},
}
#: Fewer sweep frequencies keep the other sets affordable; the sentences do not depend on the grid's density.
CHEAP = {"n_sweep": 15}

TABLES = [getattr(T, name) for name in sorted(dir(T)) if name.endswith("_table") and not name.startswith("_")]
NUMBER = re.compile(r"[−-]?\d+(?:[.,]\d+)*(?:×10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?|10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+")


@pytest.fixture(scope="module")
def default():
    return control_study()


@pytest.fixture(scope="module", params=sorted(OTHER))
def other(request):
    return request.param, control_study(**OTHER[request.param], **CHEAP)


@pytest.fixture(scope="module")
def figs(default):
    """The default run's figures, drawn once for every test that reads them."""
    return all_figures(default)


@pytest.fixture(scope="module")
def paragraphs(default, figs) -> list[str]:
    """The default run's paragraphs."""
    return _paragraphs(default, figs)


def _paragraphs(study, figs) -> list[str]:
    """Every paragraph the chapter's code writes: sentence blocks split at bullets, table captions and notes,
    figure captions and the remarks under the figures."""
    out = []
    for block in X.all_text(study):
        for para in re.split(r"\n\s*\n|\n(?=- |> \* )", block):
            para = para.strip().lstrip(">*- ").strip()
            if para and para != "**Key results**":
                out.append(para)
    out += [t(study).caption for t in TABLES]
    out += [note for t in TABLES for note in t(study).notes]
    out += [c.caption for c in figs]
    out += [c.remark for c in figs if c.remark]
    return out


def _normal(text: str) -> str:
    return " ".join(NUMBER.sub("#", text).split())


def _prose(text: str) -> str:
    """Text outside Markdown maths and MyST roles."""
    return re.sub(r"\{numref\}`[^`]*`", "", re.sub(r"\$\$.*?\$\$|\$[^$]*\$", "", text, flags=re.S))


def _notebook_markdown() -> list[str]:
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    return ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown"]


# ----------------------------------------------------------------------------- the default run


def test_no_paragraph_appears_twice(paragraphs):
    paras = paragraphs + [p for md in _notebook_markdown() for p in md.split("\n\n") if len(p) > 40]
    seen: dict[str, str] = {}
    for p in paras:
        key = _normal(p)
        assert key not in seen, f"repeated paragraph:\n{p}\n--- and ---\n{seen[key]}"
        seen[key] = p


def test_no_sentence_appears_twice(paragraphs):
    """Stricter: no sentence of 40 characters or more is said twice, numbers aside (the summary says new things)."""
    seen: dict[str, str] = {}
    for p in paragraphs:
        for s in re.split(r"(?<=[.!?])\s+(?=[A-Z*])", p):
            if len(s) >= 40:
                key = _normal(s)
                assert key not in seen, f"repeated sentence: {s}"
                seen[key] = s


def test_key_results_box_opens_with_computed_numbers(default):
    box = X.key_results(default)
    assert box.startswith("> **Key results**\n>\n> * ")
    assert all(line.startswith(">") for line in box.splitlines())
    assert len(NUMBER.findall(box)) >= 10


CODE_NAMES = re.compile(
    r"\b(omega_\w+|x_ss|c_sky|c_min|c_max|c_nominal|x_ref|u_max|zeta_\w+|K_v\*|q_x|q_v|r_lqr|kp|kd|pid_\w+|"
    r"freq_error|n_points|t_end|n_sweep|f_mr|F0)\b"
)


ASCII_NAMES = re.compile(
    r"\b(omega|zeta|sqrt|r_lqr|pid_\w+|freq_error|n_points|n_sweep|f_mr|c_nominal|c_sa_\w+|kp|kd|F0)\b"
)


@pytest.mark.parametrize("where", ["sentences", "figure captions", "figure remarks"])
def test_prose_uses_the_readers_notation(default, figs, where):
    texts = {
        "sentences": X.all_text(default),
        "figure captions": [c.caption for c in figs],
        "figure remarks": [c.remark for c in figs],
    }[where]
    for text in texts:
        prose = _prose(text)
        assert not CODE_NAMES.search(prose), CODE_NAMES.search(prose)
        assert not re.search(r"[A-Za-zωζ]_[A-Za-z0-9]", prose), f"subscript outside maths: {prose}"
        assert not re.search(r"\d[eE][+-]?\d", prose), f"e-notation: {prose}"
        assert "^2" not in prose and "sqrt(" not in prose and "nan" not in prose.lower().split()


def test_every_count_is_grouped_in_threes(default, figs):
    """A count of five or more digits (steps per period, frequencies) reads 16 000, never 16000, in the
    sentences, captions, remarks and the tables as the reader sees them."""
    texts = _paragraphs(default, figs) + [t(default)._repr_markdown_() for t in TABLES]
    found = [(n, text[:80]) for text in texts for n in ungrouped_counts(text)]
    assert found == []


def test_tables_use_the_readers_notation_and_one_precision_per_column(default):
    for make in TABLES:
        t = make(default)
        text = repr(t)
        assert not re.search(r"\d[eE][+-]?\d", text), f"{t.name}: e-notation"
        # headers and captions may write symbols with "_" subscripts (the table helper typesets them), never
        # spelled-out code names; cells are not typeset, so they hold no "_" at all
        assert not ASCII_NAMES.search(t.caption + " ".join(c.header for c in t.columns)), t.name
        assert not any("_" in v for row in t.cells() for v in row), t.name
        assert not any("_" in note or ASCII_NAMES.search(note) for note in t.notes), t.name  # notes: not typeset
        assert "nan" not in text and "inf" not in text.replace("infinite", "")
        for j, col in enumerate(t.columns):
            digits = set()
            for row in t.cells():
                value = row[j]
                m = re.fullmatch(r"[−-]?(\d+(?:\.\d+)?)(?:×10[⁻⁰-⁹¹²³]+)?", value)
                if m is None or value in ("0",) or isinstance(t.rows[0][col.key], int):
                    continue
                mant = m.group(1).replace(".", "").lstrip("0")
                digits.add(len(mant))
            assert len(digits) <= 1, f"{t.name}, column {col.header!r}: mixed significant figures {digits}"


def test_cell_keeps_its_significant_figures():
    assert [cell(v, 3) for v in (16.0, 0.16, 2.0e-5, 123456.0, -0.0250)] == [
        "16.0",
        "0.160",
        "2.00×10⁻⁵",
        "1.23×10⁵",
        "−0.0250",
    ]
    assert num(3e-15) == "3×10⁻¹⁵" and num(1e-5) == "10⁻⁵" and num(1e-4) == "0.0001"


def test_every_figure_is_captioned_truthfully(figs):
    assert [f.name for f in figs] == [
        "fig-control-active",
        "fig-control-active-zoom",
        "fig-control-tradeoff",
        "fig-control-windup",
        "fig-control-transmissibility",
        "fig-control-mr",
        "fig-control-shaping",
    ]
    for f in figs:
        assert isinstance(f, Captioned)
        check_caption(f.fig, f.caption)  # Captioned checked it on construction; the figure is still the same
        assert "/" not in f.alt and f.alt.endswith(".")


def test_coinciding_curves_are_said_to_coincide_exactly_when_they_do(default, figs):
    a = default.active
    zoom = next(f for f in figs if f.name == "fig-control-active-zoom")
    tail = a.t >= a.t[-1] - 3 * 2 * math.pi / a.force.omega
    d = closeness(a.x["PD"][tail], a.x["LQR"][tail])
    # independent of the helper: the largest difference over the largest value, computed here
    ref = np.max(np.abs(a.x["PD"][tail] - a.x["LQR"][tail])) / max(np.max(np.abs(a.x["PD"][tail])),
                                                                  np.max(np.abs(a.x["LQR"][tail])))  # fmt: skip
    assert d == pytest.approx(ref, rel=1e-12)
    said = zoom.caption + " " + zoom.remark  # what the figure shows is said under it
    assert ("PD and LQR curves nearly coincide" in said) == (d < 0.05)
    assert "PID and PD curves nearly coincide" not in said  # 0.0366 m against 0.16 m at the defaults
    assert "coincide" not in zoom.caption


#: A parameter set far from the defaults: heavier, stiffer, lighter damped, forced off resonance.
FAR = {"m": 3.0, "k": 80.0, "F0": 12.0, "c_nominal": 1.2, "omega_res": 5.16}


def _assert_captions_short(st, figs) -> None:
    for f in figs:
        assert caption_words(f.caption) <= CAPTION_WORDS, (f.name, caption_words(f.caption), f.caption)
    for make in TABLES:
        t = make(st)
        assert caption_words(t.caption) <= CAPTION_WORDS, (t.name, caption_words(t.caption), t.caption)


@pytest.mark.slow
def test_every_caption_is_at_most_sixty_words_far_from_the_defaults():
    """The caption limit below holds for a run far from the defaults too (a whole study: with the slow tests)."""
    far = control_study(**FAR, **CHEAP)
    _assert_captions_short(far, all_figures(far))


def test_every_caption_is_at_most_sixty_words(default, figs):
    """Every figure's and every table's caption says what is drawn or listed in at most 60 words; the findings go
    to the remark under the figure or to the table's notes."""
    _assert_captions_short(default, figs)
    tradeoff = next(f for f in figs if f.name == "fig-control-tradeoff")
    assert "least-force curve" in tradeoff.remark and "least-force curve" not in tradeoff.caption


def test_the_panel_is_shown_once_and_figures_are_single_calls():
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    code = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]
    assert sum("panel(study)" in src for src in code) == 1
    assert not any("fig =" in src or "print(" in src and "version" not in src for src in code)
    assert not any("mystnb" in c["metadata"] for c in nb["cells"])
    assert not any("Using the module" in md for md in _notebook_markdown())


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_usage_block_runs_in_a_fresh_interpreter():
    src = USAGE.read_text(encoding="utf-8")
    assert src.startswith("# Chapter 7, Control\n")
    blocks = re.findall(r"```python\n(.*?)```", src, re.S)
    assert len(blocks) == 1
    run = subprocess.run([sys.executable, "-c", blocks[0]], capture_output=True, text=True, timeout=300, check=True)
    assert "LQR gains 17.42 N/m" in run.stdout


# ----------------------------------------------------------------------------- other parameters


def _loop_amplitude(p: Params, kx: float, ki: float, kv: float) -> float:
    """|x/F| times F0 at the forcing, from python-control's transfer functions (independent of the study)."""
    plant = control.tf([1.0], [p.m, p.c_nominal, p.k])
    ctrl = control.tf([kv, kx, ki], [1.0, 0.0]) if ki > 0 else control.tf([kv, kx], [1.0])
    loop = control.feedback(plant, ctrl)
    return p.F0 * abs(loop(1j * p.omega_res))


@pytest.mark.slow
def test_other_parameters_give_finite_true_text_tables_and_figures(other):
    name, st = other
    p, a, s, sh = st.params, st.active, st.semi, st.shaping
    texts = X.all_text(st)
    for text in texts:
        low = _prose(text).lower()
        assert " nan" not in low and "inf " not in low and "∞" not in low, (name, text)
    for make in TABLES:
        body = repr(make(st))
        assert "nan" not in body, (name, make.__name__)
    for f in all_figures(st):
        check_caption(f.fig, f.caption)

    # which design is best: the smallest unlimited-loop amplitude, from python-control
    amp = {n: _loop_amplitude(p, *((a.designs[n].kx, a.designs[n].ki, a.designs[n].kv))) for n in ("PD", "LQR", "PID")}
    for n, v in amp.items():
        assert a.designs[n].amplitude == pytest.approx(v, rel=1e-9)
    best = min(amp, key=amp.get)
    key = X.key_results(st)
    assert f"the **{LABELS[best]}** holds the smallest steady amplitude" in key
    resonant = abs(p.omega_res / math.sqrt(p.k / p.m) - 1.0) <= 0.05
    assert ("at resonance" in key) == resonant

    # delay margins: the shortest and the longest named in the box, the comparisons in the sentence
    dm = {n: a.designs[n].costs.delay_margin for n in ("PD", "LQR", "PID")}
    order = sorted(dm, key=dm.get)
    assert f"**{LABELS[order[0]]}** tolerates the shortest" in key
    assert f"**{LABELS[order[-1]]}** the longest" in key
    comp = X.comparison_sentence(st)
    for other_law in ("PD", "LQR"):
        word = "less than" if dm["PID"] < dm[other_law] else "more than"
        assert f"{word} the {other_law} (" in comp
    integ = "costs amplitude" if amp["PID"] > _loop_amplitude(p, p.pid_kp, 0.0, p.pid_kd) else "buys amplitude"
    assert integ in comp

    # feasibility of the force-limited set point
    needed = p.k * abs(p.x_ref) + p.F0
    feasible = needed <= p.u_max
    hold = X.hold_sentence(st)
    assert ("cannot succeed" in hold) == (not feasible) and ("cannot settle" in key) == (not feasible)
    assert f"{num(needed)} N" in key
    clamped = a.moves["clamping"]
    tail = clamped.run.t >= a.t_steady
    at_limit = float(np.mean(np.abs(clamped.run.u_demand[tail]) >= p.u_max))
    mean_error = float(np.mean(clamped.run.x[tail])) - p.x_ref
    if not feasible:  # the limited run really does not settle on the set point
        assert at_limit > 0.1 or abs(mean_error) > 1e-3
    else:
        settles = at_limit == 0.0 and abs(mean_error) < 1e-3 * abs(p.x_ref)
        assert ("the run with clamping settles" in key) == settles
    if a.hold.run is not None:  # the feasible move settles: mean error tiny, never at the limit in steady state
        assert abs(a.hold.run.mean_error) < 1e-3 and a.hold.run.saturated_ss == 0.0

    # verbs of the runs from rest
    act = X.active_sentences(st)
    for n in ("PD", "LQR", "PID"):
        verb = "falls" if a.metrics[n].rms_x_ss < a.metrics["passive"].rms_x_ss else "rises"
        assert f"with the {LABELS[n]} it {verb} to" in act
    move = X.move_sentence(st)
    assert ("Clamping cuts the overshoot" in move) == (a.moves["clamping"].overshoot < a.moves["none"].overshoot)

    # semi-active verdict at omega_n, recomputed from the sweep itself
    i1 = int(np.argmin(np.abs(s.ratios - 1.0)))
    t_cl = float(s.sweeps["clipped"].peak[i1])
    assert ("below 1, where every passive damper" in key) == (t_cl < 1.0)
    summ = X.summary(st)
    assert ("Semi-active damping is the safe middle ground" in summ) == (t_cl < 1.0)

    # the better shaper at this error
    better = "ZVD" if sh.residual["ZVD"] < sh.residual["ZV"] else "ZV"
    assert f"so {better} is the better shaper" in X.shaping_sentence(st)


@pytest.mark.slow
def test_the_parameters_cell_matches_the_schema():
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    cell_ = next(c for c in nb["cells"] if "parameters" in c["metadata"].get("tags", []))
    names = re.findall(r"^(\w+):", "".join(cell_["source"]), re.M)
    assert tuple(names) == SCHEMA.names()
