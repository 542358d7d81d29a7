"""Kernel-free panel: sliders for omega_n, zeta and Delta drawing the exact free decay over one measured decay.

The fragment embeds the measured decay (the typical run with the brake, see
:func:`~vibration.book.chapters.real_oscillator.figures.typical_decay`) and its combined-law fit as data,
and computes the model in the browser with the same piecewise closed form as
:func:`vibration.physics.lab.free_decay_response` (``panel/real_oscillator.js``, exposed as
``window.vibrationRealDecay.response`` for the tests). No live ipywidgets version: the static panel
works in JupyterLab too, since it needs no kernel.
"""

from __future__ import annotations

import html
import itertools
import json

from vibration.book.chapters.real_oscillator.figures import MODEL_STYLE, typical_decay
from vibration.book.chapters.real_oscillator.study import RealOscillatorStudy
from vibration.book.presentation.panels import line_style, panel_assets, screen_words

_counter = itertools.count(1)
#: Slider ranges: omega_n (rad/s), zeta, Delta (rad): (low, high, step).
RANGES = {"wn": (4.0, 5.0, 0.001), "zeta": (0.0, 0.1, 0.0005), "fr": (0.0, 0.3, 0.001)}
#: The measurement's grey dots and the combined law's line, as in the chapter's figures, with their legend words.
STYLES = {
    "measured": {**line_style({"color": "0.35"}), "label": "measured (20 Hz)"},
    "model": {**line_style(MODEL_STYLE["combined"]), "label": "viscous + Coulomb model"},
}


def decay_panel_html(st: RealOscillatorStudy, brake: str = "on") -> str:
    """Self-contained HTML fragment: three sliders, one SVG plot, the rms residual of the model in the window."""
    d = typical_decay(st, brake)
    f = d.combined
    data = {
        "t": [round(float(x), 4) for x in d.t],
        "angle": [round(float(x), 5) for x in d.angle],
        "t_start": f.t_start,
        "t_end": f.t_end,
        "offset": f.offset,
        "theta0": f.theta0,
        "t0": f.t0,
        "fit": {"omega_n": f.omega_n, "zeta": f.zeta, "friction": f.friction},
    }
    pid = f"vro-{next(_counter)}"
    e = html.escape
    start = {"wn": f.omega_n, "zeta": f.zeta, "fr": f.friction}
    label = {"wn": "natural frequency ω<sub>n</sub>", "zeta": "damping ratio ζ", "fr": "friction angle θ<sub>f</sub>"}
    controls = "\n".join(
        f'<label for="{pid}-{k}">{label[k]}</label><input type="range" class="vro-{k}" id="{pid}-{k}" '
        f'min="{lo:g}" max="{hi:g}" step="{step:g}" value="{start[k]!r}"><output class="vro-{k}-out"></output>'
        for k, (lo, hi, step) in RANGES.items()
    )
    title = "with" if brake == "on" else "without"
    controls_named = screen_words(": move ω<sub>n</sub>, ζ and θ<sub>f</sub>")
    where = screen_words(
        ", computed in your browser. The sliders start at the whole-trace fit.",
        ", with the whole-trace fit's parameters.",
    )
    return f"""<div class="vro-panel" id="{pid}" data-decay="{e(json.dumps(data))}" \
data-styles="{e(json.dumps(STYLES))}">
{panel_assets("vibration.book.chapters.real_oscillator", "real_oscillator.js", "real_oscillator.css", kit="vro")}\
<h3 class="vro-title">Free decay {title} the brake, run {d.run}{controls_named}</h3>
<p class="vro-sub">Dots: the measured angle (20 Hz, one-degree encoder). Line: the exact free decay with viscous and \
Coulomb friction from the fitted first extremum{where}</p>
<noscript>This panel needs JavaScript to draw its plot.</noscript>
<div class="vro-controls">
{controls}
<span></span><button type="button" class="vro-reset">reset to the fit</button><span></span>
</div>
<svg class="vro-plot" viewBox="0 0 640 300" role="img" aria-label="wheel angle in rad against time in s"></svg>
<p class="vro-readout">rms residual in the fitted window: <span class="vro-rms"></span></p>
<script>window.vibrationRealDecay.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


class DecayPanel:
    """The panel as a notebook output: HTML for people, a stable one-line text for nbval."""

    def __init__(self, st: RealOscillatorStudy, brake: str = "on") -> None:
        self._html = decay_panel_html(st, brake)
        d = typical_decay(st, brake)
        self._text = f"DecayPanel(brake={brake}, run={d.run}, sliders: ω_n, ζ, θ_f)"

    def _repr_html_(self) -> str:
        return self._html

    def __repr__(self) -> str:
        return self._text


def decay_panel(st: RealOscillatorStudy, brake: str = "on") -> DecayPanel:
    """The kernel-free free-decay panel of the chapter (see the module docstring)."""
    return DecayPanel(st, brake)


def panel(study: RealOscillatorStudy) -> DecayPanel:
    """The free-decay panel of the study's measurements, brake on.

    The chapter's one entry point for its panel, as in every chapter with a panel: in JupyterLab a live
    explorer, in the rendered book the same controls without a kernel.
    """
    return decay_panel(study)
