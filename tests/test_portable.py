"""The regression surface holds on other machines: machine-dependent digits are masked and checked here.

`make test` runs strict nbval in another numerical environment than the one `make notebooks` wrote the
references in (see the Makefile's PORTABLE). Cells whose digits depend on last-bit rounding print as
``≈value``; the sanitizer masks them, and this module checks them against the committed reference with
stated tolerances instead.
"""

from __future__ import annotations

import configparser
import json
import re
from pathlib import Path

from vibration.chapters.solver_accuracy.study import MACHINE_DEPENDENT, solver_accuracy_study
from vibration.chapters.solver_accuracy.text import ladder_table
from vibration.presentation.tables import Approx

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks" / "03_solver_accuracy.ipynb"


def _sanitizers() -> list[tuple[re.Pattern, str]]:
    cfg = configparser.ConfigParser()
    cfg.read(ROOT / "tests" / "nbval_sanitize.cfg", encoding="utf-8")
    return [(re.compile(cfg[s]["regex"]), cfg[s]["replace"]) for s in cfg.sections()]


def _sanitize(text: str) -> str:
    for pattern, replace in _sanitizers():
        text = pattern.sub(replace, text)
    return text


def _number(text: str) -> float:
    """A table cell's number: plain, e-notation, or the book's ×10ⁿ with a true minus."""
    text = text.replace("−", "-")
    m = re.fullmatch(r"(?:(-?[\d.]+)×)?(-?)10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)", text)
    if m:
        power = 10.0 ** int(m.group(3).translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")))
        return float(m.group(1) or f"{m.group(2)}1") * power
    return float(text)


def _reference_ladder() -> dict[tuple[str, str], list[float]]:
    """The committed ladder's ≈ cells: (method, rtol) -> [evaluations, err x, err v, relative]."""
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    for cell in nb["cells"]:
        for out in cell.get("outputs", []):
            text = "".join(out.get("data", {}).get("text/plain", []))
            if text.startswith("Table tab-solvers-ladder"):
                rows = {}
                for line in text.splitlines():
                    parts = line.split()
                    if parts and parts[0] in MACHINE_DEPENDENT:
                        rows[(parts[0], parts[1])] = [_number(p.lstrip("≈")) for p in parts[3:7]]
                return rows
    raise AssertionError("the ladder table is missing from the committed notebook")


def test_sanitizer_masks_machine_dependent_cells_only():
    a = "LSODA   0.001   1e-6           ≈2926        ≈0.0323                ≈0.148"
    b = "LSODA   0.001   1e-6           ≈29260       ≈0.0315                ≈0.1"
    assert _sanitize(a) == _sanitize(b)
    assert _sanitize("<td>≈2926</td>") == _sanitize("<td>≈3011</td>")
    # digits that are not marked still count
    assert _sanitize("RK45 1436 0.012") != _sanitize("RK45 1437 0.012")


def test_machine_dependent_ladder_cells_stay_near_the_reference():
    """LSODA's evaluations within 25 % and its errors within a factor 5 of the committed reference.

    A last-bit change of the input moves them by up to about 10 % and a factor 4 (measured by nudging F0
    by one unit in the last place); a larger change means the method itself changed, not the rounding.
    """
    ref = _reference_ladder()
    assert ref, "no machine-dependent rows in the committed ladder"
    table = ladder_table(solver_accuracy_study())
    seen = 0
    for row, cells in zip(table.rows, table.cells(), strict=True):
        if row["method"] not in MACHINE_DEPENDENT:
            assert not any(isinstance(row[k], Approx) for k in row)
            continue
        assert all(isinstance(row[k], Approx) for k in ("nfev", "ex", "ev", "rel"))
        nfev, ex, ev, rel = (row[k].value for k in ("nfev", "ex", "ev", "rel"))
        r_nfev, r_ex, r_ev, r_rel = ref[(cells[0], cells[1])]
        assert abs(nfev / r_nfev - 1) < 0.25, (cells, nfev, r_nfev)
        for new, old in ((ex, r_ex), (ev, r_ev), (rel, r_rel)):
            assert 1 / 5 < new / old < 5, (cells, new, old)
        seen += 1
    assert seen == len(ref)
