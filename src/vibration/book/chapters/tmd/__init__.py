"""Chapter 8, tuned mass dampers: how far can a small tuned absorber cut the paper's resonance, and a building's?

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the computation, one frozen
record), :mod:`.tables`, :mod:`.text` (sentences, the key results and the take-aways), :mod:`.figures`
(captioned figures), :mod:`.panel` (the kernel-free slider panel and its JupyterLab widget, with
``panel/tmd.js`` and ``panel/tmd.css``), :mod:`.digits` (how numbers print) and :mod:`.bench`
(timings of the heaviest computations against naive alternatives).
"""

from vibration.book.chapters.tmd.designs import DESIGNS, RULES, TUNINGS, Design
from vibration.book.chapters.tmd.figures import (
    building_frf_figure,
    building_ground_figure,
    fixed_points_figure,
    magnification_figure,
    modes_figure,
    robustness_figure,
    time_response_figure,
)
from vibration.book.chapters.tmd.panel import TMDExplorer, sliders_text, tmd_explorer, tmd_panel_html
from vibration.book.chapters.tmd.params import SCHEMA, Params
from vibration.book.chapters.tmd.study import TMDStudy, tmd_study
from vibration.book.chapters.tmd.tables import (
    building_load_table,
    building_table,
    checks_table,
    design_table,
    response_table,
    tuning_table,
)
from vibration.book.chapters.tmd.text import (
    building_sentence,
    design_sentence,
    key_results,
    response_sentence,
    robustness_sentence,
    stroke_sentence,
    takeaways,
    tuning_sentence,
)

__all__ = [
    "DESIGNS",
    "Design",
    "RULES",
    "SCHEMA",
    "TUNINGS",
    "Params",
    "TMDExplorer",
    "TMDStudy",
    "building_frf_figure",
    "building_ground_figure",
    "building_load_table",
    "building_sentence",
    "building_table",
    "checks_table",
    "design_sentence",
    "design_table",
    "fixed_points_figure",
    "key_results",
    "magnification_figure",
    "modes_figure",
    "response_sentence",
    "response_table",
    "robustness_figure",
    "robustness_sentence",
    "sliders_text",
    "stroke_sentence",
    "takeaways",
    "time_response_figure",
    "tmd_explorer",
    "tmd_panel_html",
    "tmd_study",
    "tuning_sentence",
    "tuning_table",
]
