"""Chapter 1, the paper reproduced: its scenarios by its own method and exactly, side by side.

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the runs, one frozen
record), :mod:`.figures` (the paper's Figures 1 and 2 redrawn, and the method's error) and
:mod:`.tables` (its tables); the prose is in the notebook.
"""

from vibration.book.chapters.reproduction.params import SCHEMA, Params
from vibration.book.chapters.reproduction.study import CaseRun, ReproductionStudy, reproduction_study

__all__ = ["SCHEMA", "CaseRun", "Params", "ReproductionStudy", "reproduction_study"]
