"""Every Part I figure keeps its legends off the data (measured, not hoped), for the paper's and changed runs."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import pytest

from vibration.presentation import frequency_tables as ft
from vibration.presentation import plotting, solvers
from vibration.presentation.findings import reproduce, scenarios_from
from vibration.presentation.front import headline, headline_figure
from vibration.presentation.style import WIDTH_IN, legend_overlap

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
    rep = reproduce(scenarios_from(*args), n_points=2001)
    st = ft.frequency_study(*args, n_points=2001)
    dm = ft.design_map(st, 10.0, 40, 0.01, 20.0, 30)
    figs = {
        "ch1 resonance": plotting.resonance_figure(rep),
        "ch1 damping": plotting.damping_figure(rep),
        "ch4 response": ft.response_curves(st),
        "ch4 decomposition": ft.decomposition(st),
        "ch4 energy": ft.energy(st),
        "ch4 design": ft.design_figure(st, dm),
        "front": headline_figure(headline(*args), n_points=2001),
    }
    if key == "paper":
        so = solvers.solver_study(p["m"], p["k"], p["F0"], 20.0, p["omega_res"], c_nom, n_points=2001)
        figs["ch3 work-precision"] = solvers.work_precision(so)
        figs["ch3 steps"] = solvers.own_steps(so)
    return figs


@pytest.mark.parametrize("key", list(DAMPINGS))
def test_part_one_legends_cover_no_data_and_figures_fit_the_column(key):
    figs = _figures(key)
    try:
        for name, fig in figs.items():
            assert fig.get_figwidth() <= WIDTH_IN + 1e-9, (key, name, fig.get_figwidth())
            legends = 0
            for ax in fig.axes:
                if ax.get_legend() is not None:
                    legends += 1
                    assert legend_overlap(ax) == 0.0, (key, name, ax.get_ylabel(), legend_overlap(ax))
            assert legends or name == "ch4 design", f"{key}: {name} has no legend"
    finally:
        for fig in figs.values():
            plt.close(fig)


def test_legend_overlap_sees_a_legend_on_the_data():
    """The check can fail: a legend forced onto a line covers data."""
    import numpy as np

    from vibration.presentation.style import figure

    fig, ax = figure()
    t = np.linspace(0.0, 1.0, 50)
    ax.plot(t, 0.5 + 0 * t, label="flat line through the centre")
    ax.legend(loc="center")
    assert legend_overlap(ax) > 0.0
    plt.close(fig)
