"""The front page: the paper's headline numbers beside the exact ones, and what Part I finds.

Modules: :mod:`.params` (the page's parameter schema), :mod:`.study` (the exact headline values and the audit's
verdicts, one frozen record), :mod:`.figures` and :mod:`.tables`; the findings are written in the notebook.
"""

from vibration.book.chapters.overview.params import SCHEMA, Params
from vibration.book.chapters.overview.study import OverviewStudy, overview_study

__all__ = ["SCHEMA", "OverviewStudy", "Params", "overview_study"]
