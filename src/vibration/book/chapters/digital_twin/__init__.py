"""Chapter 10, a digital twin: identify the oscillator from records, say how sure, track and detect a change.

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the whole computation, one frozen
record), :mod:`.montecarlo` (the identification of many records at once), :mod:`.cusum` (the detector's run
lengths, measured and from theory), :mod:`.figures`, :mod:`.tables`, :mod:`.text` (sentences and the key-results
box), :mod:`.panel` (the kernel-free slider panel and its JupyterLab explorer) and :mod:`.bench` (timings).
"""

from vibration.book.chapters.digital_twin.params import SCHEMA, Params
from vibration.book.chapters.digital_twin.study import DigitalTwinStudy, digital_twin_study

__all__ = ["SCHEMA", "Params", "DigitalTwinStudy", "digital_twin_study"]
