"""Chapter 4's key results, declared once: the key-results box and the runner's ``sweep`` read them here.

At the paper's "resonant" forcing frequency ω_res and the nominal damping c_nominal: the steady
amplitude X (m) and the magnification M = X / (F0/k).
"""

from __future__ import annotations

from vibration.book.chapters.frequency_response.study import frequency_response_study
from vibration.book.presentation.keyresults import KeyResult, KeyResults


def _nominal(study):
    """The nominal-damping case of the study."""
    return study.nominal


def _magnification(study) -> float:
    return _nominal(study).M_res


def _amplitude(study) -> float:
    return _nominal(study).M_res * study.params.F0 / study.params.k


KEY_RESULTS = KeyResults(
    study=frequency_response_study,
    results=(
        KeyResult(
            name="X_res",
            unit="m",
            meaning="steady amplitude at the resonant forcing frequency and the nominal damping",
            read=_amplitude,
        ),
        KeyResult(
            name="M_res",
            unit="1",
            meaning="magnification X/(F0/k) at the resonant forcing frequency and the nominal damping",
            read=_magnification,
        ),
    ),
)
