"""Chapter 6 executed by papermill with the runner's damping overrides: no error, and sentences that agree
with the same run's tables (stability verdicts, which damping is largest or settles first, missing values).

The three runs execute in parallel (separate kernels) with a small Monte Carlo, so the file stays well
under a minute on two cores.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from vibration.book.chapters.stability.words import num
from vibration.book.publishing.report import execute_notebooks

pytestmark = [pytest.mark.notebooks, pytest.mark.slow]

NOTEBOOK = Path(__file__).resolve().parents[3] / "notebooks" / "06_stability.ipynb"
RUNS = {
    "c_low=0": {"c_low": 0.0},
    "c_low=-0.1": {"c_low": -0.1},
    "c_high=0.3": {"c_high": 0.3},
    "c_nominal=0.05, c_unstable=0": {"c_nominal": 0.05, "c_unstable": 0.0},
}
FAST = {"n_paths": 20, "t_growth": 60.0}


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    import nbformat

    tmp = tmp_path_factory.mktemp("stability-runs")
    outs = {key: tmp / f"run-{i}.ipynb" for i, key in enumerate(RUNS)}
    # each in its own process, as the runner does (papermill's cwd is process-wide)
    execute_notebooks([(NOTEBOOK, outs[key], {**RUNS[key], **FAST}) for key in RUNS], jobs=2, kernel="python3")
    return {key: nbformat.read(str(out), as_version=4) for key, out in outs.items()}


def _outputs(nb) -> tuple[dict[str, str], list[str]]:
    """Tables by name (their text/plain) and the Markdown sentences, in order."""
    tables, texts = {}, []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        for out in cell.get("outputs", []):
            assert out.output_type != "error", "".join(out.get("traceback", []))
            data = out.get("data", {})
            if "text/markdown" in data:
                texts.append(data["text/markdown"])
            plain = data.get("text/plain", "")
            m = re.match(r"Table (tab-stability-[\w-]+):", plain)
            if m:
                tables[m.group(1)] = plain
    return tables, texts


def _rows(plain: str) -> list[dict]:
    """Rows of a fixed-width text table, split at the column spans of its dash line."""
    lines = plain.splitlines()
    dash = next(i for i, line in enumerate(lines) if set(line) <= {"-", " "} and "-" in line)
    spans = [m.span() for m in re.finditer(r"-+", lines[dash])]
    spans = [(a, spans[i + 1][0] if i + 1 < len(spans) else None) for i, (a, _b) in enumerate(spans)]
    head = [lines[dash - 1][a:b].strip() for a, b in spans]
    rows = []
    for line in lines[dash + 1 :]:
        if not line.strip() or re.match(r"[a-z]{1,2}: ", line):  # footnotes of missing values follow
            break
        rows.append({h: line[a:b].strip() for h, (a, b) in zip(head, spans, strict=True)})
    return rows


def _num(text: str) -> float | None:
    text = text.replace("−", "-")
    try:
        return float(text)
    except ValueError:
        return None  # "—" (missing) or words


def _c(cell: str) -> str:
    """A damping from a table cell ("−0.100") as the sentences write it ("$c$ = −0.1 N s/m")."""
    return f"$c$ = {num(float(cell.replace('−', '-')), 4)} N s/m"


def _sentence(texts: list[str], start: str) -> str:
    return next(t for t in texts if t.startswith(start))


@pytest.mark.parametrize("key", list(RUNS))
def test_run_has_no_error_and_its_sentences_follow_its_tables(runs, key):
    tables, texts = _outputs(runs[key])
    assert len(tables) == 9, sorted(tables)
    for plain in tables.values():
        assert not re.search(r"\b(nan|inf)\b", plain), plain

    # stability: each paper damping's verdict in the table is the one the sentence gives it
    poles = [r for r in _rows(tables["tab-stability-poles"]) if "damping" in r["case"]]
    assert [_num(r["c (N s/m)"]) for r in poles] == sorted(_num(r["c (N s/m)"]) for r in poles)  # by value
    stab = _sentence(texts, "All three") if all(r["verdict"] == "asymptotically stable" for r in poles) else None
    if stab is None:
        stab = _sentence(texts, "Of this run's dampings")
        for verdict in {r["verdict"] for r in poles}:
            cs = [r["c (N s/m)"] for r in poles if r["verdict"] == verdict]
            clause = re.search(rf"([^;]*) (is|are) {verdict} ", stab)
            assert clause, (verdict, stab)
            for c in cs:
                assert _c(c) in clause.group(1), (c, verdict, stab)

    # the run's dampings that are not stable show "—" for settling, variance and resonant peak
    labels = _rows(tables["tab-stability-labels"])
    for r in labels:
        c = _num(r["c (N s/m)"])
        missing = [r[h].startswith("—") for h in ("resonant peak", "t_s, 2 % (s)", "σ_x, white noise (m)")]
        assert all(missing) if c <= 0 else not any(missing), r

    # random load: the largest rms in the table is the one the sentence names
    rnd = [r for r in _rows(tables["tab-stability-random"]) if _num(r["σ_x (m)"]) is not None]
    sentence = _sentence(texts, "Under a white-noise force")
    if rnd:
        largest = max(rnd, key=lambda r: _num(r["σ_x (m)"]))["damping"]
        assert f"the largest is the {largest} damping's" in sentence
        assert "agrees with" in sentence
    else:
        assert "no stationary response" in sentence
    for r in _rows(tables["tab-stability-random"]):
        if _num(r["σ_x (m)"]) is None:
            assert _c(r["c (N s/m)"]) in sentence.split("With ")[-1]

    # step: the damping that settles first in the table is the one the sentence names
    step = [r for r in _rows(tables["tab-stability-step"]) if not r["damping"].startswith("settling-optimal")]
    settling = [(r["damping"].split()[0], _num(r["t_s, 2 % (s)"])) for r in step if _num(r["t_s, 2 % (s)"])]
    sentence = _sentence(texts, "The 2 % settling time")
    if settling:
        assert f"the {min(settling, key=lambda p: p[1])[0]} one settles first" in sentence
    else:
        assert "None of this run's dampings settles" in sentence
    for r in step:
        name = r["damping"].split()[0]
        if _num(r["t_s, 2 % (s)"]) is None:
            assert re.search(rf"{name} \(\$c\$ = [^)]*\) [^;]*never settles", sentence), (name, sentence)

    # labels: one paragraph that judges every label, without repeating the table's rows
    judged = _sentence(texts, "On this run's numbers")
    for r in labels:
        assert r["paper's label"] in judged and r["verdict"] not in judged


def test_negative_damping_is_called_unstable_and_missing(runs):
    tables, texts = _outputs(runs["c_low=-0.1"])
    rows = {r["paper's label"]: r for r in _rows(tables["tab-stability-labels"])}
    assert rows["“comfort”"]["resonant peak"].startswith("—")
    assert "$c$ = −0.1 N s/m is unstable" in _sentence(texts, "Of this run's dampings")
    tables, texts = _outputs(runs["c_low=0"])
    assert "$c$ = 0 N s/m is marginally stable" in _sentence(texts, "Of this run's dampings")
    # c_high = 0.3 < c_nominal = 0.5: "heaviest" is the nominal one, by value
    tables, texts = _outputs(runs["c_high=0.3"])
    assert "the heaviest (nominal, $c$ = 0.5 N s/m)" in _sentence(texts, "Under base motion")
    tables, texts = _outputs(runs["c_nominal=0.05, c_unstable=0"])
    assert "no exponential growth" in _sentence(texts, "Over ")
