"""Every Part I figure keeps its legends off the data (measured, not hoped), for the paper's and changed runs."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import pytest

from vibration.book.chapters.overview import overview_study
from vibration.book.chapters.overview.figures import headline_figure
from vibration.book.chapters.reproduction import figures as reproduction_figures
from vibration.book.chapters.reproduction import reproduction_study
from vibration.book.presentation.style import WIDTH_IN, legend_overlap

PAPER = {"m": 1.0, "k": 20.0, "F0": 5.0, "t_end": 50.0, "omega_ref": 3.0, "omega_res": 4.47}
DAMPINGS = {
    "paper": (0.1, 0.5, 15.0),
    "c_high-5-c_low-0.05": (0.05, 0.5, 5.0),
    "omega_res-3.5": (0.1, 0.5, 15.0),
}


def _figures(key: str):
    c_low, c_nom, c_high = DAMPINGS[key]
    p = dict(PAPER, omega_res=3.5) if key == "omega_res-3.5" else PAPER
    args = (p["m"], p["k"], p["F0"], p["t_end"], p["omega_ref"], p["omega_res"], c_low, c_nom, c_high)
    names = ("m", "k", "F0", "t_end", "omega_ref", "omega_res", "c_low", "c_nominal", "c_high")
    rep = reproduction_study(**dict(zip(names, args, strict=True)), n_points=2001)
    figs = {
        "ch1 resonance": reproduction_figures.resonance_figure(rep).fig,
        "ch1 damping": reproduction_figures.damping_figure(rep).fig,
        "ch1 error": reproduction_figures.error_figure(rep).fig,
        "front": headline_figure(overview_study(**{n: v for n, v in zip(names, args, strict=True)})).fig,
    }
    return figs


@pytest.mark.slow  # over 2 s: make test-slow runs it
@pytest.mark.parametrize("key", list(DAMPINGS))
def test_part_one_legends_cover_no_data_and_figures_fit_the_column(key):
    figs = _figures(key)
    try:
        for name, fig in figs.items():
            assert fig.get_figwidth() <= WIDTH_IN + 1e-9, (key, name, fig.get_figwidth())
            legends = len(fig.legends)  # a figure-wide legend sits outside every panel
            for ax in fig.axes:
                if ax.get_legend() is not None:
                    legends += 1
                    assert legend_overlap(ax) == 0.0, (key, name, ax.get_ylabel(), legend_overlap(ax))
            assert legends, f"{key}: {name} has no legend"
    finally:
        for fig in figs.values():
            plt.close(fig)


def test_legend_overlap_sees_a_legend_on_the_data():
    """The check can fail: a legend forced onto a line covers data."""
    import numpy as np

    from vibration.book.presentation.style import figure

    fig, ax = figure()
    t = np.linspace(0.0, 1.0, 50)
    ax.plot(t, 0.5 + 0 * t, label="flat line through the centre")
    ax.legend(loc="center")
    assert legend_overlap(ax) > 0.0
    plt.close(fig)
