"""Chapter 6, stability and damping as a design choice.

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the computation, one frozen
record), :mod:`.figures` (captioned figures), :mod:`.tables`, :mod:`.text` (the key results, one
paragraph per result and the designer's take-aways), :mod:`.verdicts` (the paper's three names for
its dampings, judged), :mod:`.words` (how numbers and symbols are written), :mod:`.panel` (the
kernel-free slider panel and its JupyterLab widget) and :mod:`.bench` (timings of the heaviest parts).
"""

from vibration.book.chapters.stability.params import SCHEMA, Params
from vibration.book.chapters.stability.study import StabilityStudy, stability_study

__all__ = ["SCHEMA", "Params", "StabilityStudy", "stability_study"]
