"""Chapter 3, solver accuracy: how good is the paper's RK45, and what does accuracy cost?

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (every run, once, in one
frozen record), :mod:`.figures` (captioned figures) and :mod:`.tables`; the prose is in the notebook.
"""

from vibration.book.chapters.solver_accuracy.params import SCHEMA, Params
from vibration.book.chapters.solver_accuracy.study import SolverStudy, solver_accuracy_study

__all__ = ["SCHEMA", "Params", "SolverStudy", "solver_accuracy_study"]
