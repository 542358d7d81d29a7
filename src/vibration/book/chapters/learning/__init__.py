"""Chapter 11, a learning controller measured against its optimum.

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the computation, one
frozen record), :mod:`.tables`, :mod:`.text` (sentences), :mod:`.summary` (the key-results box
and the designer's conclusions), :mod:`.figures`, :mod:`.notation` (how numbers are printed) and
:mod:`.bench` (training time of the learners). The gymnasium environment stays the public API
:mod:`vibration.learn`.
"""

from vibration.book.chapters.learning.params import SCHEMA, Params
from vibration.book.chapters.learning.study import LearningStudy, Paired, learning_study

__all__ = ["SCHEMA", "LearningStudy", "Paired", "Params", "learning_study"]
