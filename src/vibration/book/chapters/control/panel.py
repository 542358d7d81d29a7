"""Kernel-free panel: LQR force weight, ideal skyhook gain, input shaper and natural-frequency error.

The fragment computes the linear cases in the browser from their closed forms (``panel/control.js``,
exposed as ``window.vibrationControl`` for the tests): the LQR loop without a force limit, the ideal
skyhook's transmissibility and the shaped move. It loads nothing and works in JupyterLab and in the
rendered book alike, so the chapter shows it once; there is no separate live ipywidgets version.
"""

from __future__ import annotations

import html
import itertools
import json
import math

from vibration.book.chapters.control.figures import SHAPER_STYLE
from vibration.book.chapters.control.params import Params
from vibration.book.chapters.control.study import ControlStudy
from vibration.book.presentation.panels import line_style, panel_assets

_counter = itertools.count(1)
#: Slider ranges: log10 of the LQR weight r (1/N²), skyhook gain (N s/m), frequency error (%); widened to the start.
LOG_R = (-7.0, 2.0)
C_SKY_MAX = 60.0
ERROR_PCT = 50.0
#: Line styles and legend words: the book's cases for the plant and the designs, the chapter's shaper styles.
STYLES = {
    "passive": {**line_style("passive"), "label": "passive"},
    "LQR": {**line_style("LQR"), "label": "LQR"},
    "skyhook": {**line_style("skyhook"), "label": "ideal skyhook"},
    "none": {**line_style(SHAPER_STYLE["none"]), "label": "unshaped step"},
    "ZV": {**line_style(SHAPER_STYLE["ZV"]), "label": "ZV-shaped command"},
    "ZVD": {**line_style(SHAPER_STYLE["ZVD"]), "label": "ZVD-shaped command"},
}


def control_panel_html(params: Params | None = None, **values) -> str:
    """Self-contained HTML + inline JavaScript at the chapter's parameters (validated by the schema).

    Examples
    --------
    >>> html_ = control_panel_html()
    >>> html_.startswith('<div class="vc-panel"'), "http" in html_
    (True, False)
    """
    p = params if params is not None else Params.from_values(values)
    data = {"m": p.m, "c": p.c_nominal, "k": p.k, "F0": p.F0, "omega": p.omega_res, "q_x": p.q_x, "q_v": p.q_v,
            "t_end": p.t_end, "move": p.move}  # fmt: skip
    pid = f"vc-{next(_counter)}"
    e = html.escape
    lr = math.log10(p.r_lqr)
    lo_r, hi_r = min(LOG_R[0], lr), max(LOG_R[1], lr)
    sky_max = max(C_SKY_MAX, p.c_sky)
    err = round(100 * p.freq_error)
    lo_e, hi_e = min(-ERROR_PCT, err), max(ERROR_PCT, err)
    return f"""<div class="vc-panel" id="{pid}" data-params="{e(json.dumps(data))}" \
data-styles="{e(json.dumps(STYLES))}">
{panel_assets("vibration.book.chapters.control", "control.js", "control.css")}\
<h3 class="vc-title">Explore without a kernel: m = {p.m:g} kg, c = {p.c_nominal:g} N s/m, k = {p.k:g} N/m</h3>
<noscript>This panel needs JavaScript to draw its plots.</noscript>
<div class="vc-grid">
<figure><figcaption>LQR at F<sub>0</sub> = {p.F0:g} N, ω = {p.omega_res:g} rad/s, no force limit</figcaption>
<label>weight r of the force (logarithmic) \
<input type="range" class="vc-logr" min="{lo_r:g}" max="{hi_r:g}" step="0.05" value="{lr:g}"></label>
<output class="vc-r-out"></output>
<svg class="vc-active" viewBox="0 0 420 240" role="img" aria-label="displacement x in m against time t in s"></svg>
<p class="vc-active-read"></p></figure>
<figure><figcaption>Ideal skyhook under base motion</figcaption>
<label>skyhook damping <input type="range" class="vc-csky" min="0" max="{sky_max:g}" step="0.5" \
value="{p.c_sky:g}"></label>
<output class="vc-csky-out"></output>
<svg class="vc-sky" viewBox="0 0 420 240" role="img" aria-label="transmissibility against frequency ratio"></svg>
<p class="vc-sky-read"></p></figure>
<figure><figcaption>Move of {p.move:g} m, input shaping</figcaption>
<label>shaper <select class="vc-kind"><option value="none">none</option><option value="ZV">ZV</option>\
<option value="ZVD" selected>ZVD</option></select></label>
<label>natural-frequency error <input type="range" class="vc-err" min="{lo_e:g}" max="{hi_e:g}" step="1" \
value="{err}"></label>
<output class="vc-err-out"></output>
<svg class="vc-shape" viewBox="0 0 420 240" role="img" aria-label="displacement x in m against time t in s"></svg>
<p class="vc-shape-read"></p></figure>
</div>
<script>window.vibrationControl.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


class ControlPanel:
    """The panel as a notebook output: HTML for people, a stable one-line text for nbval."""

    def __init__(self, params: Params) -> None:
        self._html = control_panel_html(params)
        self._text = "ControlPanel(sliders: LQR weight r, skyhook damping, shaper and natural-frequency error)"

    def _repr_html_(self) -> str:
        return self._html

    def __repr__(self) -> str:
        return self._text


def control_panel(study: ControlStudy | Params | None = None, **values) -> ControlPanel:
    """The kernel-free panel of the chapter at the study's (or the given) parameters."""
    if isinstance(study, ControlStudy):
        return ControlPanel(study.params)
    return ControlPanel(study if study is not None else Params.from_values(values))


def panel(study: ControlStudy) -> ControlPanel:
    """The suspension and active-control panel at the study's parameters.

    The chapter's one entry point for its panel, as in every chapter with a panel: in JupyterLab a live
    explorer, in the rendered book the same controls without a kernel.
    """
    return control_panel(study)
