"""Chapter 8's key results, declared once: the key-results box and the runner's ``sweep`` read them here.

The worst peak magnification |X_p|/(F0/k_p) of each tuning over the mistuning band (the primary's
stiffness off by up to ±δ_k), judged on the actual (damped) primary.
"""

from __future__ import annotations

from vibration.book.chapters.tmd.designs import TUNINGS, Design
from vibration.book.chapters.tmd.study import tmd_study
from vibration.book.presentation.keyresults import KeyResult, KeyResults


def _name(tuning: Design) -> str:
    """The key result's variable name of ``tuning``'s worst peak: "worst_peak_hinf"."""
    return f"worst_peak_{tuning.key}"


def _worst(tuning: Design):
    def read(study) -> float:
        return study.scores[tuning].worst_peak

    read.__name__ = f"worst_peak_of_{_name(tuning)}"
    return read


KEY_RESULTS = KeyResults(
    study=tmd_study,
    results=tuple(
        KeyResult(
            name=_name(t),
            unit="1",
            meaning=f"worst peak magnification over the mistuning band, {t.name} tuning",
            read=_worst(t),
        )
        for t in TUNINGS
    ),
)


def worst_peak(study, tuning: Design) -> float:
    """The declared worst peak of ``tuning`` (a :class:`.Design`) read from ``study``, 1."""
    return KEY_RESULTS[_name(tuning)].value(study)
