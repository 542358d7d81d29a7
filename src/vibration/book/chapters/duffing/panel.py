"""Chapter 9's slider panel: k₃ and F₀ move the harmonic-balance curve (all branches), its backbone and folds.

:func:`hb_panel_html` is the kernel-free panel (``panel/duffing.js`` computes the closed forms in the
browser, exposed as ``window.vibrationDuffing`` for the tests); :func:`hb_explorer` is the JupyterLab
widget (ipywidgets), whose ``text/html`` bundle is that panel at the sliders' values, so renderers without a
kernel still get a working panel.
"""

from __future__ import annotations

import html
import json
import math
from typing import TYPE_CHECKING

import numpy as np

from vibration.book.chapters.duffing.figures import STABLE_LS, UNSTABLE_LS, plot_curve
from vibration.book.presentation.numbers import sig
from vibration.book.presentation.panels import KitExplorer, PanelIds, agg_figure, line_style, panel_assets, screen_words
from vibration.book.presentation.style import case_style, place_legend
from vibration.physics.duffing import Duffing, backbone, folds, response_curve
from vibration.physics.model import check_real

if TYPE_CHECKING:  # annotations only
    from vibration.book.chapters.duffing.study import DuffingStudy

_ids = PanelIds("vib-duffing")


def _colors() -> dict:
    return {name: case_style(name)["color"] for name in ("hardening", "softening")}


#: The panel's looks and legend words: the springs' colours from the book's cases, the chapter's line styles of
#: stable and unstable branches, the backbone black dotted, the folds as open circles.
STYLES = {
    "hardening": {**line_style({"color": case_style("hardening")["color"]}), "label": "hardening"},
    "softening": {**line_style({"color": case_style("softening")["color"]}), "label": "softening"},
    "stable": {**line_style({"color": "k", "linestyle": STABLE_LS}), "label": "stable"},
    "unstable": {**line_style({"color": "k", "linestyle": UNSTABLE_LS}), "label": "unstable"},
    "backbone": {**line_style({"color": "k", "linestyle": ":"}), "label": "backbone"},
    "folds": {**line_style({"color": "k"}), "label": "folds"},
}


def _panel_params(m, c, k, k3, F0, omega_max, k3_range, F0_max) -> dict:
    """The slider panel's values; a range left as None covers the chapter's case (twice its value, at least the
    paper's range), so that a run with other parameters still shows its resonance and its force."""
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    c = check_real("c", c, low=0.0, low_open=True, unit="N s/m")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    if omega_max is None:
        omega_max = max(8.0, 2.0 * math.sqrt(k / m))
    if k3_range is None:
        k3_range = max(5.0, 2.0 * abs(check_real("k3", k3, unit="N/m^3")))
    if F0_max is None:
        F0_max = max(20.0, 2.0 * check_real("F0", F0, low=0.0, low_open=True, unit="N"))
    k3_range = check_real("k3_range", k3_range, low=0.0, low_open=True, unit="N/m^3")
    k3 = check_real("k3", k3, low=-k3_range, high=k3_range, unit="N/m^3")
    F0_max = check_real("F0_max", F0_max, low=0.0, low_open=True, unit="N")
    F0 = check_real("F0", F0, low=0.0, low_open=True, high=F0_max, unit="N")
    omega_max = check_real("omega_max", omega_max, low=0.0, low_open=True, unit="rad/s")
    return {"m": m, "c": c, "k": k, "k3": k3, "F0": F0, "omega_max": omega_max, "k3_range": k3_range, "F0_max": F0_max}


def hb_panel_html(
    m: float = 1.0,
    c: float = 0.5,
    k: float = 20.0,
    *,
    k3: float = 2.0,
    F0: float = 5.0,
    omega_max: float | None = None,
    k3_range: float | None = None,
    F0_max: float | None = None,
) -> str:
    """Kernel-free slider panel: k3 and F0 move the harmonic-balance curve (all branches).

    Self-contained HTML (inline ``panel/duffing.css`` and ``panel/duffing.js``, no URL): the browser
    computes the curve by the amplitude parametrisation of :func:`vibration.physics.duffing.response_curve`,
    its stability, the folds and the peak by the closed forms of :mod:`vibration.physics.duffing`.

    Parameters
    ----------
    m, c, k : float
        Mass (kg), damping (N s/m, > 0), linear stiffness (N/m, > 0).
    k3 : float
        Starting cubic stiffness, N/m^3, within ``±k3_range``.
    F0 : float
        Starting force amplitude, N, in ``(0, F0_max]``.
    omega_max : float, optional
        Right end of the frequency axis, rad/s (default: 8 or twice the natural frequency, the larger).
    k3_range : float, optional
        The k3 slider spans ``-k3_range`` to ``k3_range`` N/m^3 (default: 5 or twice |k3|, the larger).
    F0_max : float, optional
        The F0 slider spans ``F0_max / 200`` to ``F0_max`` N (default: 20 or twice F0, the larger).

    Returns
    -------
    str
        ``<div class="vib-duffing" ...>`` with its style, controls, an SVG and scripts.

    Examples
    --------
    >>> frag = hb_panel_html()
    >>> frag.startswith('<div class="vib-duffing"'), "<script src" in frag or "<link" in frag
    (True, False)
    """
    params = _panel_params(m, c, k, k3, F0, omega_max, k3_range, F0_max)
    k3_range, F0_max = params["k3_range"], params["F0_max"]
    pid = _ids.new(params)
    e = html.escape
    where = screen_words(", computed in your browser")
    return f"""<div class="vib-duffing" id="{e(pid)}" data-params="{e(json.dumps(params))}" \
data-styles="{e(json.dumps(STYLES))}">
{panel_assets("vibration.book.chapters.duffing", "duffing.js", "duffing.css")}\
<p class="vd-sub">One-harmonic frequency response of \
<i>m ẍ + c ẋ + k x + k<sub>3</sub> x<sup>3</sup> = F<sub>0</sub> cos(ωt)</i> \
with m = {m:g} kg, c = {c:g} N s/m, k = {k:g} N/m{where}: solid stable, \
dashed unstable, dotted the backbone, circles the folds.</p>
<noscript>This panel needs JavaScript to draw its plot.</noscript>
<div class="vd-controls">
<label for="{e(pid)}-k3">cubic stiffness k<sub>3</sub></label>
<input type="range" class="vd-k3" id="{e(pid)}-k3" min="{-k3_range:g}" max="{k3_range:g}" \
step="{k3_range / 500:g}" value="{params["k3"]!r}">
<output class="vd-k3-out" for="{e(pid)}-k3"></output>
<label for="{e(pid)}-F0">force amplitude F<sub>0</sub></label>
<input type="range" class="vd-F0" id="{e(pid)}-F0" min="{F0_max / 200:g}" max="{F0_max:g}" \
step="{F0_max / 200:g}" value="{params["F0"]!r}">
<output class="vd-F0-out" for="{e(pid)}-F0"></output>
</div>
<svg class="vd-plot" viewBox="0 0 640 300" role="img" \
aria-label="amplitude in m against forcing frequency in rad/s"></svg>
<p class="vd-readout"></p>
<script>window.vibrationDuffing.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


class HBExplorer(KitExplorer):
    """JupyterLab sliders (ipywidgets) for k3 and F0 over the harmonic-balance curve, on the panel kit.

    Displays as the live widget in JupyterLab (the curve and a readout of its peak and folds); renderers
    without a kernel get the kernel-free panel of :func:`hb_panel_html` at the same parameters.
    """

    def __init__(self, m=1.0, c=0.5, k=20.0, k3=2.0, F0=5.0, omega_max=None, k3_range=None, F0_max=None):
        import ipywidgets as widgets

        self.params = _panel_params(m, c, k, k3, F0, omega_max, k3_range, F0_max)
        k3_range, F0_max = self.params["k3_range"], self.params["F0_max"]
        self.k3_slider = widgets.FloatSlider(value=k3, min=-k3_range, max=k3_range, step=k3_range / 500,
                                             description="k₃ (N/m³)", continuous_update=False)  # fmt: skip
        self.F0_slider = widgets.FloatSlider(value=F0, min=F0_max / 200, max=F0_max, step=F0_max / 200,
                                             description="F₀ (N)", continuous_update=False)  # fmt: skip
        self.image = widgets.Image(format="png", layout=widgets.Layout(max_width="100%", height="auto"))
        self.readout = widgets.HTML()
        self.widget = widgets.VBox([widgets.HBox([self.k3_slider, self.F0_slider]), self.readout, self.image])
        self.watch(self.k3_slider, self.F0_slider)
        self.update()

    def values(self) -> dict:
        """The oscillator at the sliders' k3, the force (N), its response curve, backbone and folds."""
        p = self.params
        d = Duffing(m=p["m"], c=p["c"], k=p["k"], k3=float(self.k3_slider.value))
        F0 = float(self.F0_slider.value)
        w, a, stable = response_curve(d, F0, p["omega_max"], n=801)
        a_bb = np.linspace(0.0, 1.1 * np.nanmax(a), 200)
        return {"duffing": d, "F0": F0, "curve": (w, a, stable), "backbone": (backbone(d, a_bb), a_bb),
                "folds": folds(d, F0)}  # fmt: skip

    def figure(self, v: dict):
        fig = agg_figure(6.4, 3.4)
        ax = fig.subplots()
        d, (w, a, stable), f = v["duffing"], v["curve"], v["folds"]
        plot_curve(ax, w, a, stable=stable, color=_colors()["hardening" if d.k3 >= 0 else "softening"],
                   label=f"$k_3$ = {sig(d.k3, 3)} N/m$^3$")  # fmt: skip
        ax.plot(*v["backbone"], "k:", lw=0.8, label="backbone")
        if f.bistable:
            ax.plot([f.omega_low, f.omega_high], [f.amplitude_low, f.amplitude_high], "o", mfc="white", color="k",
                    label="folds")  # fmt: skip
        ax.set_xlim(0.0, self.params["omega_max"])
        ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
        ax.set_ylabel(r"amplitude $A$ (m)")
        place_legend(ax)
        return fig

    def readout_html(self, v: dict) -> str:
        f = v["folds"]
        peak = (
            f"peak A = {sig(f.peak_amplitude, 3)} m at ω = {sig(f.peak_omega, 3)} rad/s"
            if math.isfinite(f.peak_amplitude)
            else "the curve does not close (no peak)"
        )
        if f.bistable:
            band = f"three amplitudes between ω = {sig(f.omega_low, 3)} and {sig(f.omega_high, 3)} rad/s"
        elif math.isfinite(f.omega_high):
            band = f"a fold at ω = {sig(f.omega_high, 3)} rad/s, the curve running off to low frequencies"
        else:
            band = "one amplitude at every frequency"
        return f"{peak}; {band}"

    def panel_html(self) -> str:
        return hb_panel_html(**dict(self.params, k3=float(self.k3_slider.value), F0=float(self.F0_slider.value)))

    def summary(self) -> str:
        return f"HBExplorer(k₃ = {sig(float(self.k3_slider.value))} N/m³, F₀ = {sig(float(self.F0_slider.value))} N)"


def hb_explorer(m=1.0, c=0.5, k=20.0, *, k3=2.0, F0=5.0, omega_max=None, k3_range=None, F0_max=None) -> HBExplorer:
    """JupyterLab explorer of the harmonic-balance curve (k3 in N/m^3 and F0 in N sliders).

    Parameters are those of :func:`hb_panel_html` (kg, N s/m, N/m, N/m^3, N, rad/s).

    Examples
    --------
    >>> ex = hb_explorer()
    >>> ex.k3_slider.value = -1.0                 # a softening spring: the peak leans to lower frequencies
    >>> print(ex.readout.value)
    peak A = 2.59 m at ω = 3.85 rad/s; three amplitudes between ω = 3.84 and 3.96 rad/s
    >>> ex.params["omega_max"] == 2 * 20**0.5     # rad/s: the frequency axis reaches twice ω_n
    True
    """
    return HBExplorer(m, c, k, k3, F0, omega_max, k3_range, F0_max)


def panel(study: DuffingStudy) -> HBExplorer:
    """The harmonic-balance explorer of the study's hardening spring.

    The chapter's one entry point for its panel, as in every chapter with a panel: in JupyterLab a live
    explorer, in the rendered book the same controls without a kernel.
    """
    p = study.params
    return hb_explorer(m=p.m, c=p.c_nominal, k=p.k, k3=p.k3_hard, F0=p.F0)
