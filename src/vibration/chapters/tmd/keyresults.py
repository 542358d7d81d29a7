"""Chapter 8's key results, declared once: the key-results box and the runner's ``sweep`` read them here.

The worst peak magnification |X_p|/(F0/k_p) of each tuning over the mistuning band (the primary's
stiffness off by up to ±δ_k), judged on the actual (damped) primary.
"""

from __future__ import annotations

from vibration.chapters.tmd.study import TUNINGS, tmd_study
from vibration.presentation.keyresults import KeyResult, KeyResults

#: Variable name of each tuning's worst peak (letters, digits and _), in the order of TUNINGS.
NAMES = dict(
    zip(
        TUNINGS,
        (
            "worst_peak_den_hartog",
            "worst_peak_hinf_closed",
            "worst_peak_h2_closed",
            "worst_peak_hinf",
            "worst_peak_h2",
            "worst_peak_robust",
        ),
        strict=True,
    )
)


def _worst(tuning: str):
    def read(study) -> float:
        return study.scores[tuning].worst_peak

    read.__name__ = f"worst_peak_of_{NAMES[tuning]}"
    return read


KEY_RESULTS = KeyResults(
    study=tmd_study,
    results=tuple(
        KeyResult(
            name=NAMES[t],
            unit="1",
            meaning=f"worst peak magnification over the mistuning band, {t} tuning",
            read=_worst(t),
        )
        for t in TUNINGS
    ),
)


def worst_peak(study, tuning: str) -> float:
    """The declared worst peak of ``tuning`` (one of TUNINGS) read from ``study``, 1."""
    return KEY_RESULTS[NAMES[tuning]].value(study)
