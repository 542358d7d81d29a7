"""Part I chapters run with other parameters say what their own tables say.

Each chapter is executed with papermill (in parallel, into a temporary folder) with changed
parameters; the sentences are read from the executed notebook's Markdown outputs and the
tables from the fixed-precision text of its Table outputs, and every statement of a regime,
of settling, of which case is largest, of a verdict and of the half-power band is checked
against the run's own table row.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from vibration.book.presentation.narrative import g
from vibration.book.publishing.report import execute_notebooks

pytestmark = [pytest.mark.notebooks, pytest.mark.slow]

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
REGIMES = ("underdamped", "overdamped", "critically damped", "undamped", "unstable")

#: (chapter, parameters) of each run.
RUNS = {
    "01-c_high-5": ("01_reproduction", {"c_high": 5.0}),
    "01-c_low-0.05": ("01_reproduction", {"c_low": 0.05}),
    "01-omega_res-3.5": ("01_reproduction", {"omega_res": 3.5}),
    "01-undamped-negative": ("01_reproduction", {"c_low": 0.0, "c_nominal": -0.1}),
    "01-four-dampings": ("01_reproduction", {"dampings": [0.1, 0.5, 2.0, 15.0]}),
    "01-two-dampings": ("01_reproduction", {"dampings": [3.0, 0.02]}),
    "02-c_low-0.05": ("02_claims_audit", {"c_low": 0.05}),
    "02-c_high-5-c_low-0": ("02_claims_audit", {"c_high": 5.0, "c_low": 0.0}),
    "04-omega_res-3.5": ("04_frequency_response", {"omega_res": 3.5}),
    "04-c_high-5-c_low-0.05": ("04_frequency_response", {"c_high": 5.0, "c_low": 0.05}),
    "04-c_low-0-c_high-0.7": ("04_frequency_response", {"c_low": 0.0, "c_high": 7.0}),
    "04-four-dampings": ("04_frequency_response", {"dampings": [0.1, 0.5, 2.0, 15.0]}),
}


def parse_tables(nb: dict) -> dict[str, list[dict[str, str]]]:
    """Every Table output of an executed notebook, by name: rows of {header: cell text}."""
    tables = {}
    for cell in nb["cells"]:
        for out in cell.get("outputs", []):
            text = "".join(out.get("data", {}).get("text/plain", ""))
            if not text.startswith("Table tab-"):
                continue
            lines = text.splitlines()
            name = lines[0].split()[1].rstrip(":")
            header, dashes = lines[1], lines[2]
            spans = [(m.start(), m.end()) for m in re.finditer(r"-+", dashes)]
            cols = [header[a : b + (1 if i == len(spans) - 1 else 0)].strip() for i, (a, b) in enumerate(spans)]
            rows = []
            for line in lines[3:]:
                if not line.startswith(tuple("CDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789")):
                    break
                if re.match(r"^[a-z]: ", line) or ": " in line[:40] and len(line) > len(dashes) + 5:
                    break
                cells = [
                    line[a : (spans[i + 1][0] if i + 1 < len(spans) else None)].strip()
                    for i, (a, _) in enumerate(spans)
                ]
                rows.append(dict(zip(cols, cells, strict=True)))
            tables[name] = rows
    return tables


def markdown_outputs(nb: dict) -> list[str]:
    """The Markdown displayed by the code cells (the generated sentences)."""
    texts = []
    for cell in nb["cells"]:
        for out in cell.get("outputs", []):
            md = out.get("data", {}).get("text/markdown")
            if md and out.get("output_type") == "display_data":
                texts.append("".join(md))
    return texts


@pytest.fixture(scope="module")
def executed(tmp_path_factory):
    """Execute every run of :data:`RUNS` once (3 kernels at a time); return {run: notebook dict}."""
    folder = tmp_path_factory.mktemp("narrative_runs")
    outs = {key: folder / f"{key}.ipynb" for key in RUNS}
    # each in its own process, as the runner does (papermill's cwd is process-wide)
    execute_notebooks([(NOTEBOOKS / f"{RUNS[key][0]}.ipynb", outs[key], RUNS[key][1]) for key in RUNS], jobs=3)
    return {key: json.loads(out.read_text(encoding="utf-8")) for key, out in outs.items()}


def _bullets(texts: list[str]) -> list[str]:
    return [line[2:] for t in texts for line in t.splitlines() if line.startswith("- **")]


def _regimes_in(text: str) -> set[str]:
    found = set()
    for word in REGIMES:
        if re.search(rf"(?<![a-z]){word}(?![a-z])", text):
            found.add(word)
    return found


def glued(nb: dict) -> dict[str, str]:
    """Every value an executed notebook glues into its prose, by name (the text the reader sees)."""
    import ast

    out = {}
    for cell in nb["cells"]:
        for o in cell.get("outputs", []):
            name = o.get("metadata", {}).get("scrapbook", {}).get("name")
            if name:
                out[name] = ast.literal_eval("".join(o["data"]["application/papermill.record/text/plain"]))
    return out


@pytest.mark.slow
@pytest.mark.parametrize("key", [k for k in RUNS if k.startswith("01")])
def test_reproduction_glued_words_follow_the_tables_and_the_closed_form(executed, key):
    import math

    from vibration.book.chapters.reproduction import Params

    nb = executed[key]
    p = Params.from_values(RUNS[key][1])
    rows = parse_tables(nb)["tab-reproduction-findings"]
    words = glued(nb)
    # one row per distinct run: the reference, the resonance, and each damping not equal to the nominal one
    assert len(rows) == 2 + sum(c != p.c_nominal for c in p.dampings), (key, [r["case"] for r in rows])
    # the quoted steady amplitude at resonance is the closed form, or its absence is said
    if p.c_nominal > 0:
        x = p.F0 / math.hypot(p.k - p.m * p.omega_res**2, p.c_nominal * p.omega_res)
        assert float(words["x_res_value"]) == pytest.approx(x, rel=5e-4), (key, words["x_res"])
    else:
        assert words["x_res"].startswith("none") and words["regime_note"], (key, words)
    # the damping called largest has the largest peak of the damping rows; the lightest's settling as tabled
    by_c = {float(r["c (N s/m)"].replace("−", "-")): r for r in rows[1:]}
    damping_rows = {c: by_c.get(c, rows[1]) for c in p.dampings}
    peaks = {c: float(r["peak |x| (m)"]) for c, r in damping_rows.items()}
    assert words["largest"] == f"c = {g(max(peaks, key=peaks.get))} N s/m", (key, words["largest"], peaks)
    settles = damping_rows[min(p.dampings)]["settles by t_end"] == "yes"
    assert words["lightest_settles"].startswith("settles after") == settles, (key, words["lightest_settles"])


@pytest.mark.slow
@pytest.mark.parametrize("key", [k for k in RUNS if k.startswith("02")])
def test_audit_counts_follow_the_table_and_say_when_the_case_changed(executed, key):
    nb = executed[key]
    tables = parse_tables(nb)
    claims = {row["claim"]: row for row in tables["tab-claims-audit"]}
    # the glued counts are the claims table's own
    words = glued(nb)
    verdicts = [row["verdict"] for row in claims.values()]
    for name, verdict in (("n_held", "reproduced"), ("n_number", "number differs"),
                          ("n_physics", "physics contradicts"), ("n_partly", "partly reproduced")):  # fmt: skip
        assert int(words[name]) == verdicts.count(verdict), (key, name, words[name])
    assert int(words["n_claims"]) == len(claims)
    from vibration.physics.audit import changed_text
    from vibration.physics.paper import load_claims, load_scenarios

    paper = load_scenarios()
    params = RUNS[key][1]
    for cl in load_claims():
        sid = cl["scenario_id"]
        uses_changed = sid and (
            ("c_low" in params and sid == "damping_low") or ("c_high" in params and sid == "damping_high")
        )
        if uses_changed:
            assert claims[cl["claim_id"]]["case run"] == "changed", (key, cl["claim_id"])
    assert changed_text(paper["damping_low"], paper["damping_low"]) == ""
    # the audit's regimes are the run's own: with c_high = 5 N s/m the "overdamped" claim is contradicted
    if params.get("c_high") == 5.0:
        assert claims["C05"]["exact"] == "underdamped" and claims["C05"]["verdict"] == "physics contradicts"
    if params.get("c_low") == 0.0:
        assert claims["C03"]["exact"] == "undamped"
        assert claims["C14"]["exact"] == "marginal"  # c = 0 forced off omega_n: bounded beats


@pytest.mark.slow
@pytest.mark.parametrize("key", [k for k in RUNS if k.startswith("04")])
def test_frequency_glued_words_follow_the_band_table(executed, key):
    """The count of dampings whose half-power band holds the resonant forcing, and the words that say what sets
    the nominal amplitude, as the chapter's own tables and the closed form say."""
    from vibration.book.chapters.frequency_response import Params

    nb = executed[key]
    p = Params.from_values(RUNS[key][1])
    band_rows = parse_tables(nb)["tab-frequency-band"]
    in_band = next(h for h in band_rows[0] if h.endswith("in band"))
    words = glued(nb)
    assert len(band_rows) == len(p.dampings)
    inside = sum(row[in_band] == "yes" for row in band_rows)
    assert words["inside"] == f"{inside} of the {len(p.dampings)} dampings compared", (key, words["inside"])
    assert words["omega_res"] == g(p.omega_res), (key, words["omega_res"])
    if p.c_nominal > 0:  # the nominal magnification at the resonant forcing is the closed form
        wn = (p.k / p.m) ** 0.5
        r, z = p.omega_res / wn, p.c_nominal / (2 * (p.k * p.m) ** 0.5)
        assert float(words["M_res_nom_value"]) == pytest.approx(
            1 / ((1 - r * r) ** 2 + (2 * z * r) ** 2) ** 0.5, rel=5e-4
        )
