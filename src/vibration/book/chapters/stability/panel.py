"""The chapter's sliders: the kernel-free HTML panel of the book and the JupyterLab widget.

Both move the damping ratio (logarithmic) and the base frequency, and show together the
transmissibility curve with its operating point, the normalised step response with its 2 % band and
settling time, and the poles in the complex plane. The panel computes the closed forms in the browser
(``panel/stability.js``, ``window.vibrationStability``, which the tests compare with the Python
functions); the widget draws them with matplotlib and carries the panel for renderers without a kernel.
"""

from __future__ import annotations

import html
import json
import math

import numpy as np

from vibration.book.chapters.stability.figures import LOCUS_GREY, REF_GREY, look
from vibration.book.chapters.stability.study import BAND, StabilityStudy
from vibration.book.chapters.stability.words import WN, c_text, num, pole_text, sig
from vibration.book.presentation import panels as kit
from vibration.physics.model import Oscillator, check_real
from vibration.physics.stability import StepMetrics, poles, step_metrics, step_response, transmissibility

#: Range of the damping-ratio slider (log scale), 1.
ZETA_MIN, ZETA_MAX = 0.005, 5.0
#: Positions of the logarithmic slider.
ZETA_STEPS = 600
_ids = kit.PanelIds("vst")
#: The panel's colours, as the chapter's figures draw them: the nominal damping's curve, black marks, grey references.
STYLES = {
    "curve": kit.line_style(look("nominal")),
    "point": kit.line_style({"color": "#000000"}),
    "reference": kit.line_style({"color": REF_GREY}),
    "locus": kit.line_style({"color": LOCUS_GREY}),
}


def stability_panel_html(
    m: float = 1.0, k: float = 20.0, zeta: float = 0.0559, *, omega: float = 4.47, panel_id: str | None = None
) -> str:
    """Self-contained HTML + JavaScript panel: damping-ratio (log) and frequency sliders.

    Parameters
    ----------
    m : float
        Mass, kg (> 0).
    k : float
        Stiffness, N/m (> 0).
    zeta : float
        Initial damping ratio, 1 (0.005 to 5).
    omega : float
        Initial base frequency, rad/s (0 to 4 omega_n).
    panel_id : str, optional
        Prefix of element ids (default: hash of the parameters and a counter).

    Examples
    --------
    >>> frag = stability_panel_html()
    >>> frag.startswith('<div class="vst-panel"'), "http" in frag
    (True, False)
    """
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    zeta = check_real("zeta", zeta, low=ZETA_MIN, high=ZETA_MAX)
    wn = math.sqrt(k / m)
    w_max = 4.0 * wn
    omega = check_real("omega", omega, low=0.0, high=w_max, unit="rad/s")
    params = {"m": m, "k": k, "zeta": zeta, "omega": omega, "zeta_min": ZETA_MIN, "zeta_max": ZETA_MAX, "w_max": w_max}
    if panel_id is None:
        panel_id = _ids.new(params)
    e = html.escape
    pos = round(ZETA_STEPS * math.log(zeta / ZETA_MIN) / math.log(ZETA_MAX / ZETA_MIN))
    pid = e(panel_id)
    zeta_control = kit.range_control(pid, "z", "vst-zeta", "damping ratio ζ (log scale)", low=0, high=ZETA_STEPS,
                                     step=1, value=pos)  # fmt: skip
    omega_control = kit.range_control(pid, "w", "vst-omega", "base frequency ω", low=0, high=repr(w_max),
                                      step=repr(w_max / 1000.0), value=repr(omega))  # fmt: skip
    sub = kit.screen_words(
        "Move the damping ratio (logarithmic) and the base frequency; computed in your browser from the closed forms.",
        "Drawn from the closed forms at the starting damping ratio and base frequency.",
    )
    return f"""<div class="vst-panel" id="{e(panel_id)}" data-params="{e(json.dumps(params))}" \
data-styles="{e(json.dumps(STYLES))}">
{kit.panel_assets("vibration.book.chapters.stability", "stability.js", "stability.css", kit="vst")}\
<h3 class="vst-title">Damping as a design choice: m = {m:g} kg, k = {k:g} N/m, ω<sub>n</sub> = {wn:.4g} rad/s</h3>
<p class="vst-sub">{sub}</p>
<noscript>This panel needs JavaScript to draw its plots.</noscript>
<div class="vst-controls">
{zeta_control}{omega_control}</div>
<div class="vst-body">
<figure><svg class="vst-trans" viewBox="0 0 420 260" role="img"
aria-label="transmissibility against base frequency in rad/s"></svg>
<figcaption>Transmissibility |X/Y| (log); dot: ω; dashed: √2 ω<sub>n</sub>.</figcaption></figure>
<figure><svg class="vst-step" viewBox="0 0 420 260" role="img"
aria-label="normalised step response against time in s"></svg>
<figcaption>Step response k x / F; band ±2 %; dotted: settling time.</figcaption></figure>
<figure><svg class="vst-poles" viewBox="0 0 260 260" role="img"
aria-label="poles in the complex plane"></svg>
<figcaption>Poles s (1/s); the circle has radius ω<sub>n</sub>.</figcaption></figure>
</div>
<table class="vst-readout"><tbody>
<tr><th>damping c</th><td class="vst-r-c"></td><th>transmissibility at ω</th><td class="vst-r-t"></td></tr>
<tr><th>poles</th><td class="vst-r-poles"></td><th>overshoot</th><td class="vst-r-os"></td></tr>
<tr><th>rise time (10–90 %)</th><td class="vst-r-tr"></td><th>settling time (2 %)</th><td class="vst-r-ts"></td></tr>
</tbody></table>
<script>window.vibrationStability.mount(document.getElementById({json.dumps(panel_id)}));</script>
</div>
"""


class StabilityExplorer(kit.KitExplorer):
    """JupyterLab sliders (ipywidgets) over the same three views; the book shows the HTML panel.

    ``_repr_mimebundle_`` returns the widget view for JupyterLab and, for renderers
    without a kernel, :func:`stability_panel_html` at the current slider values.
    """

    def __init__(self, m: float = 1.0, k: float = 20.0, zeta: float = 0.0559, omega: float = 4.47) -> None:
        import ipywidgets as widgets

        stability_panel_html(m, k, zeta, omega=omega, panel_id="check")  # validates the inputs
        self.m, self.k = float(m), float(k)
        wn = math.sqrt(k / m)
        self.zeta_slider = widgets.FloatLogSlider(
            value=zeta,
            base=10.0,
            min=math.log10(ZETA_MIN),
            max=math.log10(ZETA_MAX),
            step=math.log10(ZETA_MAX / ZETA_MIN) / ZETA_STEPS,
            description="ζ",
            readout_format=".3g",
        )
        self.omega_slider = widgets.FloatSlider(
            value=omega, min=0.0, max=4 * wn, step=4 * wn / 1000, description="ω (rad/s)", readout_format=".3f"
        )
        self.image = widgets.Image(format="png")
        self.readout = widgets.HTML()
        self.widget = widgets.VBox([widgets.HBox([self.zeta_slider, self.omega_slider]), self.readout, self.image])
        self.watch(self.zeta_slider, self.omega_slider)
        self.update()

    def values(self) -> dict:
        """Current numbers: c (N s/m), T at omega, poles (1/s), step metrics (s, fraction)."""
        zeta, w = float(self.zeta_slider.value), float(self.omega_slider.value)
        osc = Oscillator(m=self.m, c=zeta * 2 * math.sqrt(self.k * self.m), k=self.k)
        s = step_metrics(osc, BAND)
        return {"osc": osc, "T": float(transmissibility(osc, w)), "poles": poles(osc), "step": s, "omega": w}

    def figure(self, v: dict):
        fig = kit.agg_figure(9.0, 2.9)
        at, ast, ap = fig.subplots(1, 3, width_ratios=(1.2, 1.2, 0.8))
        osc, s = v["osc"], v["step"]
        wn = osc.natural_frequency
        line = look("nominal")["color"]
        w = np.linspace(0.0, 4 * wn, 1201)
        at.semilogy(w, transmissibility(osc, w), color=line)
        at.plot([v["omega"]], [v["T"]], "o", color="k")
        at.axvline(math.sqrt(2) * wn, color="0.4", ls="--", lw=0.8)
        at.set_xlabel("ω (rad/s)")
        at.set_ylabel("|X/Y|")
        t = np.linspace(0.0, max(12 * 2 * math.pi / wn, 1.2 * s.settling_time), 2001)
        ast.axhspan(1 - BAND, 1 + BAND, color="0.85")
        ast.plot(t, step_response(osc, t), color=line)
        ast.axvline(s.settling_time, color="0.4", ls=":")
        ast.set_xlabel("t (s)")
        ast.set_ylabel("k x / F")
        p = v["poles"]
        th = np.linspace(0, 2 * math.pi, 200)
        ap.plot(wn * np.cos(th), wn * np.sin(th), color="0.8", lw=0.8)
        ap.plot(p.real, p.imag, "x", color="k", ms=8, mew=2)
        ap.axvline(0.0, color="0.3", lw=0.8)
        ap.set_xlabel("Re s (1/s)")
        ap.set_ylabel("Im s (1/s)")
        ap.set_aspect("equal", adjustable="datalim")
        return fig

    def readout_html(self, v: dict) -> str:
        s: StepMetrics = v["step"]
        return (
            f"c = {sig(v['osc'].c, 4)} N s/m; T(ω) = {sig(v['T'], 4)}; poles {pole_text(v['poles'])} 1/s; "
            f"overshoot {sig(100 * s.overshoot, 3)} %; rise {sig(s.rise_time, 3)} s; "
            f"settling {sig(s.settling_time, 3)} s"
        )

    def panel_html(self) -> str:
        return stability_panel_html(self.m, self.k, float(self.zeta_slider.value), omega=float(self.omega_slider.value))

    def summary(self) -> str:
        return (
            f"StabilityExplorer(m={self.m!r} kg, k={self.k!r} N/m, zeta={self.zeta_slider.value:.4g}, "
            f"omega={self.omega_slider.value:.4g} rad/s)"
        )


def stability_explorer(st: StabilityStudy) -> StabilityExplorer:
    """The chapter's sliders at the run's nominal damping and the paper's forcing frequency.

    Both are moved into the sliders' ranges (damping ratio 0.005 to 5, frequency 0 to 4 omega_n) when
    outside; a nominal damping c <= 0 starts at the lowest damping ratio (:func:`explorer_sentence` says so).
    """
    osc = st.osc(st.dampings["nominal"])
    zeta = min(max(osc.damping_ratio, ZETA_MIN), ZETA_MAX)
    return StabilityExplorer(st.m, st.k, zeta, min(st.omega_res, 4.0 * st.omega_n))


def explorer_sentence(st: StabilityStudy) -> str:
    """Where the sliders start, and why when the run's nominal damping or frequency is outside their range."""
    c = st.dampings["nominal"]
    zeta = st.osc(c).damping_ratio
    start = min(max(zeta, ZETA_MIN), ZETA_MAX)
    text = f"The sliders start at ζ = {num(start, 4)}"
    if zeta == start:
        text += f", the nominal damping of this run ({c_text(c)})"
    elif c <= 0.0:
        text += (
            f", their lowest value: the nominal damping of this run ({c_text(c)}) is not positive, and the sliders "
            "cover positive damping only"
        )
    else:
        text += f", the end of their range nearest to the nominal damping of this run ({c_text(c)}, ζ = {num(zeta, 4)})"
    w_max = 4.0 * st.omega_n
    if st.omega_res <= w_max:
        return text + f", and at the paper's forcing frequency {num(st.omega_res, 4)} rad/s."
    return text + f", and at {num(w_max, 4)} rad/s = 4 {WN}, the top of the frequency slider."


def panel(study: StabilityStudy) -> StabilityExplorer:
    """The pole explorer started at the study's oscillator and forcing.

    The chapter's one entry point for its panel, as in every chapter with a panel: in JupyterLab a live
    explorer, in the rendered book the same controls without a kernel.
    """
    return stability_explorer(study)
