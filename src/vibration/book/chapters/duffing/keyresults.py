"""Chapter 9's key results, declared once: the key-results box and the runner's ``sweep`` read them here.

The largest Lyapunov exponent of Ueda's oscillator at the run's damping and forcing, pooled over
independent runs, with its standard error (1/s). A sweep runs :func:`chaos_study` (those runs alone);
the chapter's full study carries the same ``pooled`` record.
"""

from __future__ import annotations

from vibration.book.chapters.duffing.study import chaos_study
from vibration.book.presentation.keyresults import KeyResult, KeyResults


def _exponent(study) -> float:
    return study.pooled.mean


def _standard_error(study) -> float:
    return study.pooled.standard_error


KEY_RESULTS = KeyResults(
    study=chaos_study,
    results=(
        KeyResult(
            name="lyapunov",
            unit="1/s",
            meaning="largest Lyapunov exponent of Ueda's oscillator, pooled over independent runs",
            read=_exponent,
        ),
        KeyResult(
            name="lyapunov_se",
            unit="1/s",
            meaning="standard error of the pooled largest Lyapunov exponent",
            read=_standard_error,
        ),
    ),
)
