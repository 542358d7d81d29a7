"""Every chapter finishes, well within the cell limit, under parameter sets far from the paper's.

The runner's cell limit (180 s) is a last resort; here each cell gets 120 s while two chapters share
two cores, so a chapter that would crawl under an accepted ``-p`` fails this test, naming the chapter
and the cell. The executed
notebooks must carry no error and no bare nan or inf in any text a reader sees.
"""

from __future__ import annotations

import json
import re

import pytest

from vibration.book.publishing import report

#: Far from the paper's (m = 1 kg, k = 20 N/m, F0 = 5 N, ω = 3 and 4.47 rad/s, c = 0.1, 0.5, 15 N s/m).
FAR = {
    "light and moderate damping, forced below resonance": {"c_high": "3", "c_low": "0.02", "omega_res": "2.5"},
    "soft, light damping, low resonance": {
        "k": "6.25", "c_low": "0.02", "c_nominal": "0.2", "c_high": "3", "omega_res": "2.5", "omega_ref": "1.5",
    },
    "heavy, stiff, strong force": {
        "m": "4", "k": "400", "F0": "40", "c_low": "1", "c_nominal": "4", "c_high": "120", "omega_res": "10",
        "omega_ref": "6",
    },
}  # fmt: skip
LIMIT_S = 120
_BARE = re.compile(r"(?<![\w.])(nan|inf)(?![\w.])")


def _texts(nb: dict):
    for i, cell in enumerate(nb["cells"]):
        for out in cell.get("outputs", []):
            assert out.get("output_type") != "error", (i, out.get("ename"), out.get("evalue"))
            data = out.get("data", {})
            for kind in ("text/plain", "text/markdown"):
                if kind in data:
                    yield i, "".join(data[kind])
            if out.get("output_type") == "stream":
                yield i, "".join(out.get("text", []))


@pytest.mark.far
@pytest.mark.slow
@pytest.mark.notebooks
@pytest.mark.parametrize("case", list(FAR))
def test_every_chapter_finishes_and_reads_cleanly_far_from_the_paper(case, tmp_path):
    chapters = report.discover()
    values = report.check_parameters(chapters, list(FAR[case].items()))
    logs: list[str] = []
    report.run(chapters, values, tmp_path, jobs=2, log=logs.append, pdf=False, cell_timeout=LIMIT_S, cache=False)
    times = {m[1]: float(m[2]) for m in (re.match(r"\[\d+/\d+\] (\S+) done in ([\d.]+) s", x) for x in logs) if m}
    assert set(times) == {c.name for c in chapters}, logs
    for path in sorted((tmp_path / "notebooks").glob("*.ipynb")):
        nb = json.loads(path.read_text(encoding="utf-8"))
        for i, text in _texts(nb):
            assert not _BARE.search(text), (path.name, i, text[:300])
