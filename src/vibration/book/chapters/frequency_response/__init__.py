"""Chapter 4, frequency response and design: magnification, half-power bands, energy and a design map.

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (every result, once, in one
frozen record), :mod:`.figures` (captioned figures), :mod:`.tables` and :mod:`.keyresults` (the numbers a
sweep gathers); the prose is in the notebook.
"""

from vibration.book.chapters.frequency_response.params import SCHEMA, Params
from vibration.book.chapters.frequency_response.study import FrequencyStudy, frequency_response_study

__all__ = ["SCHEMA", "FrequencyStudy", "Params", "frequency_response_study"]
