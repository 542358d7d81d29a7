"""The claims audit: each checkable claim of the paper against its own method and exact theory.

Verdict rule (:func:`verdict`), decided from the exact value:

* ``approx`` claims ("about X"): **reproduced** when the exact value rounds to
  the claim at the claim's own precision (within half a unit of its last
  stated digit, so "0.5" covers 0.45 to 0.55); **partly reproduced** when it is
  within a factor :data:`PARTLY_FACTOR` of the claim; else **number differs**.
* ``greater`` / ``less`` claims ("over X", "below X"): **reproduced** when the
  inequality holds, **partly reproduced** when it holds after relaxing X by
  the factor :data:`PARTLY_FACTOR`, else **number differs**.
* ``category`` claims (a word: a regime, stability, a method's name): **reproduced**
  when equal; otherwise **physics contradicts** when the word is about the motion
  (regime, stability, growth, settling) and **name differs** for the method's name.
* A quantity that does not exist in the run (a steady amplitude when c < 0) makes a
  numerical claim **physics contradicts**.

Beside each discrepancy the audit computes the *readings* that could explain it
(:func:`readings`): the same claim read as a peak-to-peak value, as a magnification
factor, as a transient still growing at the end of the window, and so on, each with the
number it gives and whether it matches the paper by the same rule. It says which
reading fits best, never which one the authors meant.

Examples
--------
>>> from vibration.physics.paper import load_claims, load_scenarios
>>> rows = {r["claim_id"]: r for r in audit_claims(load_scenarios(), load_claims(), n_points=2001)}
>>> rows["C09"]["verdict"], rows["C14"]["verdict"], rows["C20"]["verdict"]
('number differs', 'physics contradicts', 'name differs')
>>> rows["C09"]["best_reading"]
'2 x_ss at resonance / x_ss of reference'
"""

from __future__ import annotations

from .claims import COLUMNS, audit_claims, changed_text  # noqa: F401 - COLUMNS, changed_text kept reachable
from .readings import readings
from .resonance import half_power_band, resonant_peak
from .rk45 import RK_PAIRS, rk45_pair, scipy_rk45_nodes
from .verdicts import PARTLY_FACTOR, VERDICTS, claim_kind_text, half_unit, verdict

__all__ = [
    "PARTLY_FACTOR",
    "RK_PAIRS",
    "VERDICTS",
    "audit_claims",
    "claim_kind_text",
    "half_power_band",
    "half_unit",
    "readings",
    "resonant_peak",
    "rk45_pair",
    "scipy_rk45_nodes",
    "verdict",
]
