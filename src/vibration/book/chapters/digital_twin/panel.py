"""Kernel-free slider panel of the digital-twin chapter, and its live JupyterLab explorer.

The panel (:func:`twin_panel_html`) shows *precomputed* identifications on a grid of noise levels and record
lengths (:func:`vibration.physics.twin.estimate_grid`), embedded as JSON and drawn by ``panel/twin.js``; the
JupyterLab explorer (:class:`TwinExplorer`) re-identifies live.
"""

from __future__ import annotations

import html
import json

import numpy as np

from vibration.book.chapters.digital_twin.study import DigitalTwinStudy
from vibration.book.presentation.numbers import sig
from vibration.book.presentation.panels import (
    KitExplorer,
    PanelIds,
    agg_figure,
    checked_panel_id,
    line_style,
    panel_assets,
    range_control,
)
from vibration.book.presentation.style import OKABE_ITO
from vibration.physics.model import Oscillator
from vibration.physics.twin import EstimateGrid, Identification, identify, random_force, synthetic_measurements

NAMES = ("m", "c", "k")
UNITS = ("kg", "N s/m", "N/m")

_ids = PanelIds("twin")
#: The truth as the book's exact case (black dashed), the identified model's intervals in its nominal blue, the
#: estimate a vermillion dot; with their legend words.
STYLES = {
    "truth": {**line_style("exact"), "label": "truth"},
    "interval": {**line_style("c_nominal"), "label": "95 % interval"},
    "estimate": {**line_style({"color": OKABE_ITO["vermillion"]}), "label": "estimate"},
}


def _grid_payload(grid: EstimateGrid) -> dict:
    return {
        "names": list(NAMES),
        "units": list(UNITS),
        "truth": grid.truth.tolist(),
        "noises": grid.noises.tolist(),
        "durations": grid.durations.tolist(),
        "estimates": grid.estimates.tolist(),
        "ci95": grid.ci95.tolist(),
    }


def twin_panel_html(grid: EstimateGrid, *, panel_id: str | None = None) -> str:
    """Self-contained HTML (no kernel, no network): noise and record-length sliders over precomputed fits.

    Parameters
    ----------
    grid : EstimateGrid
        One identification per (noise, record length), from
        :func:`vibration.physics.twin.estimate_grid`.
    panel_id : str, optional
        Element id prefix (a letter, then letters, digits, ``_`` or ``-``).

    Examples
    --------
    >>> from vibration.physics.twin import EstimateGrid
    >>> g = EstimateGrid(truth=np.array([1.0, 0.5, 20.0]), noises=np.array([0.01]), durations=np.array([10.0]),
    ...                  estimates=np.ones((1, 1, 3)), ci95=np.ones((1, 1, 3, 2)))
    >>> frag = twin_panel_html(g)
    >>> frag.startswith('<div class="twin-panel"'), "http" in frag
    (True, False)
    """
    panel_id = checked_panel_id(panel_id)
    payload = _grid_payload(grid)
    text = json.dumps(payload, sort_keys=True)
    pid = panel_id or _ids.new(payload)
    e = html.escape
    ni, nj = grid.noises.size, grid.durations.size
    pe = e(pid)
    noise = range_control(pe, "noise", "twin-noise", "noise std. / rms response", low=0, high=ni - 1, step=1,
                          value=ni // 2)  # fmt: skip
    length = range_control(pe, "len", "twin-len", "record length T", low=0, high=nj - 1, step=1, value=nj // 2)
    rows = "\n".join(
        f'<tr><th scope="row">{n} ({u})</th><td class="twin-true"></td><td class="twin-est"></td>'
        f'<td class="twin-lo"></td><td class="twin-hi"></td><td class="twin-in"></td></tr>'
        for n, u in zip(NAMES, UNITS, strict=True)
    )
    return f"""<div class="twin-panel" id="{e(pid)}" data-grid="{e(text)}" data-styles="{e(json.dumps(STYLES))}">
{panel_assets("vibration.book.chapters.digital_twin", "twin.js", "twin.css", kit="twin")}\
<h3 class="twin-title">Noise and record length against the estimates (precomputed)</h3>
<p class="twin-sub">Each position of the sliders shows one identification computed when the report was built \
(same force and noise draw throughout; only the slider's quantity changes): each parameter's relative error \
with its 95 % interval.</p>
<noscript>This panel needs JavaScript to draw its plot.</noscript>
<div class="twin-controls">
{noise}{length}</div>
<svg class="twin-plot" viewBox="0 0 640 200" role="img" \
aria-label="relative error of m, c and k in percent with 95 % intervals"></svg>
<table class="twin-estimates">
<thead><tr><th>parameter</th><th>true</th><th>estimate</th><th>95 % low</th><th>95 % high</th>\
<th>covers truth</th></tr></thead>
<tbody>
{rows}
</tbody></table>
<script>window.vibrationTwin.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


class TwinExplorer(KitExplorer):
    """JupyterLab explorer on the panel kit: noise and record-length sliders re-identifying a seeded record live.

    It shows each identified parameter over its true value with its 95 % interval, and a table of the same; its
    ``_repr_mimebundle_`` (the kit's) returns the widget view and, for renderers without a kernel (the book),
    :func:`twin_panel_html` over ``grid``.
    """

    def __init__(
        self,
        osc: Oscillator,
        grid: EstimateGrid,
        *,
        dt: float = 0.02,
        seed: int = 0,
        band: tuple[float, float] = (0.1, 2.0),
        rms: float = 2.0,
    ):
        import ipywidgets as widgets

        self.osc, self.grid, self.dt, self.seed = osc, grid, dt, seed
        t = np.arange(int(round(float(np.max(grid.durations)) / dt)) + 1) * dt
        self._t = t
        self._force = random_force(t, band=band, rms=rms, seed=seed)
        self._clean = synthetic_measurements(osc, t, self._force).x
        self._draw = np.random.default_rng(seed + 1).standard_normal(t.size)
        self.noise_slider = widgets.SelectionSlider(
            options=[(f"{v:g}", float(v)) for v in grid.noises],
            value=float(grid.noises[grid.noises.size // 2]),
            description="noise / rms",
            continuous_update=False,
        )
        self.length_slider = widgets.SelectionSlider(
            options=[(f"{v:g} s", float(v)) for v in grid.durations],
            value=float(grid.durations[grid.durations.size // 2]),
            description="T",
            continuous_update=False,
        )
        self.readout = widgets.HTML()
        self.image = widgets.Image(format="png", layout=widgets.Layout(max_width="100%", height="auto"))
        self.widget = widgets.VBox([self.noise_slider, self.length_slider, self.readout, self.image])
        self.fit: Identification | None = None
        self.watch(self.noise_slider, self.length_slider)
        self.update()

    def values(self) -> dict:
        """The record at the sliders' noise and length, identified: the fit and the true parameters."""
        n = int(round(self.length_slider.value / self.dt)) + 1
        clean = self._clean[:n]
        y = clean + self.noise_slider.value * float(np.sqrt(np.mean(clean**2))) * self._draw[:n]
        self.fit = identify(self._t[:n], self._force[:n], x=y, search="local")
        return {"fit": self.fit, "truth": (self.osc.m, self.osc.c, self.osc.k)}

    def figure(self, v: dict):
        fig = agg_figure(5.6, 2.6)
        ax = fig.subplots()
        fit, truth = v["fit"], v["truth"]
        for i in range(3):
            est, (lo, hi) = (fit.m, fit.c, fit.k)[i], fit.ci95[i]
            ax.plot([i, i], [lo / truth[i], hi / truth[i]], lw=4, color=STYLES["interval"]["color"],
                    label=STYLES["interval"]["label"] if i == 0 else None)  # fmt: skip
            ax.plot([i], [est / truth[i]], "o", color=STYLES["estimate"]["color"],
                    label=STYLES["estimate"]["label"] if i == 0 else None)  # fmt: skip
        ax.axhline(1.0, color=STYLES["truth"]["color"], ls="--", lw=1.0, label=STYLES["truth"]["label"])
        ax.set_xticks(range(3), [f"{name} ({unit})" for name, unit in zip(NAMES, UNITS, strict=True)])
        ax.set_xlim(-0.6, 2.6)
        ax.set_ylabel("estimate / true value")
        ax.legend(loc="upper left", bbox_to_anchor=(1.0, 1.0), frameon=False)
        return fig

    def readout_html(self, v: dict) -> str:
        fit, truth = v["fit"], v["truth"]
        cells = []
        for i, (name, unit) in enumerate(zip(NAMES, UNITS, strict=True)):
            est, (lo, hi) = (fit.m, fit.c, fit.k)[i], fit.ci95[i]
            inside = "yes" if lo <= truth[i] <= hi else "no"
            cells.append(
                f"<tr><th>{name} ({unit})</th><td>{sig(truth[i])}</td><td>{sig(est, 5)}</td>"
                f"<td>{sig(lo, 5)}</td><td>{sig(hi, 5)}</td><td>{inside}</td></tr>"
            )
        return (
            "<table><tr><th>parameter</th><th>true</th><th>estimate</th><th>95 % low</th><th>95 % high</th>"
            "<th>covers truth</th></tr>" + "".join(cells) + "</table>"
        )

    def panel_html(self) -> str:
        return twin_panel_html(self.grid)

    def summary(self) -> str:
        return (
            f"TwinExplorer(noise={self.noise_slider.value:g} of rms, T={self.length_slider.value:g} s, "
            f"m={self.osc.m:g} kg, c={self.osc.c:g} N s/m, k={self.osc.k:g} N/m)"
        )


def twin_explorer(st: DigitalTwinStudy) -> TwinExplorer:
    """The JupyterLab explorer (live) with the precomputed kernel-free panel for the book; see :class:`TwinExplorer`.

    It uses the study's asset, grid, sampling step, seed, force band and rms force.
    """
    p = st.params
    return TwinExplorer(st.asset, st.grid, dt=p.dt, seed=p.seed, band=st.band, rms=p.F_rms)


def panel(study: DigitalTwinStudy) -> TwinExplorer:
    """The identification explorer over the study's grid of estimates.

    The chapter's one entry point for its panel, as in every chapter with a panel: in JupyterLab a live
    explorer, in the rendered book the same controls without a kernel.
    """
    return twin_explorer(study)
