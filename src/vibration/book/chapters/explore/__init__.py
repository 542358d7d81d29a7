"""Chapter 5, explore the parameters: forcing-frequency and damping sliders over the exact response.

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the readout and the experiments
the chapter reports, one frozen record), :mod:`.tables` (the readout table; the prose is in the notebook),
:mod:`.widget` (the live JupyterLab explorer) and :mod:`.figure` (its figure), :mod:`.panel` with
``panel/sliders.{js,css}`` (the kernel-free panel of the book) and :mod:`.bench` (the slider-update benchmark).
"""

from vibration.book.chapters.explore.params import SCHEMA, Params
from vibration.book.chapters.explore.study import ExploreStudy, Readout, explore_study, readout

__all__ = ["SCHEMA", "ExploreStudy", "Params", "Readout", "explore_study", "readout"]
