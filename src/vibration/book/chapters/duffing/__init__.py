"""Chapter 9, the Duffing oscillator: what happens to the paper's resonance when the spring is not linear?

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the computation, one frozen
record), :mod:`.figures` (captioned figures), :mod:`.tables`, :mod:`.text` (sentences, the key-results box
and the summary), :mod:`.notation` (how numbers are written), :mod:`.panel` (the slider panel and its
JupyterLab widget) and :mod:`.bench` (the sweep benchmark).
"""

from vibration.book.chapters.duffing.figures import chaos_figure, frequency_response_figure, paper_figure, sweep_figure
from vibration.book.chapters.duffing.panel import HBExplorer, hb_explorer, hb_panel_html
from vibration.book.chapters.duffing.params import SCHEMA, Params
from vibration.book.chapters.duffing.study import DuffingStudy, duffing_study
from vibration.book.chapters.duffing.tables import (
    checks_table,
    fold_table,
    hb_table,
    history_table,
    lyapunov_convergence_table,
    lyapunov_runs_table,
    lyapunov_table,
    stability_table,
)
from vibration.book.chapters.duffing.text import (
    fold_sentence,
    hb_sentence,
    key_results,
    lyapunov_sentence,
    paper_sentence,
    published_sentence,
    stability_sentence,
    summary,
    trust_sentence,
)

__all__ = [
    "SCHEMA",
    "DuffingStudy",
    "HBExplorer",
    "Params",
    "chaos_figure",
    "checks_table",
    "duffing_study",
    "fold_sentence",
    "fold_table",
    "frequency_response_figure",
    "hb_explorer",
    "hb_panel_html",
    "hb_sentence",
    "hb_table",
    "history_table",
    "key_results",
    "lyapunov_convergence_table",
    "lyapunov_runs_table",
    "lyapunov_sentence",
    "lyapunov_table",
    "paper_figure",
    "paper_sentence",
    "published_sentence",
    "stability_sentence",
    "stability_table",
    "summary",
    "sweep_figure",
    "trust_sentence",
]
