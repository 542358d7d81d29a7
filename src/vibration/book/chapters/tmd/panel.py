"""Chapter 8's sliders: the kernel-free HTML panel (the book) and the ipywidgets explorer (JupyterLab).

The panel draws the primary's magnification |X_p|/(F0/k_p) against r = ω/ω_p for slider values of
μ, f, ζ_a and ζ_p, computed in the browser by ``panel/tmd.js`` (``window.vibrationTMD``) with the same
closed forms as :mod:`vibration.physics.tmd`; the tests compare the two. Colours follow the book's
visual language: the closed-form H∞ tuning black dashed, the primary without absorber grey.
"""

from __future__ import annotations

import html
import json
import math

import numpy as np

from vibration.book.chapters.tmd.digits import sig
from vibration.book.chapters.tmd.study import TMDStudy
from vibration.book.presentation import panels as kit
from vibration.book.presentation.style import OKABE_ITO, case_style
from vibration.physics.model import check_real
from vibration.physics.tmd import (
    MU_MAX,
    den_hartog,
    h2_tuning,
    hinf_tuning,
    tmd_fixed_points,
    tmd_magnification,
    tmd_peak,
)

__all__ = ["MU_RANGE", "F_RANGE", "ZETA_A_RANGE", "ZETA_P_RANGE", "TMDExplorer", "sliders_text", "tmd_explorer",
           "tmd_panel_html"]  # fmt: skip


#: Ranges of the sliders (μ and ζ_a on logarithmic scales), 1.
MU_RANGE = (0.005, 0.25)
F_RANGE = (0.7, 1.3)
ZETA_A_RANGE = (0.005, 1.0)
ZETA_P_RANGE = (0.0, 0.3)
#: Frequency-ratio window of the slider plots, 1.
R_RANGE = (0.4, 1.6)
_SLIDER_RULES = (("dh", "Den Hartog"), ("hinf", "H∞ (Nishihara–Asami)"), ("h2", "H2 (Warburton)"))
_ids = kit.PanelIds("vtm")
#: The panel's lines and marks with their legend words, as the JupyterLab explorer draws them.
STYLES = {
    "curve": {**kit.line_style({"color": OKABE_ITO["blue"]}), "label": "with the absorber of the sliders"},
    "opt": {**kit.line_style("exact"), "label": "H∞ tuning for this μ"},
    "bare": {**kit.line_style({"color": OKABE_ITO["grey"]}), "label": "without absorber"},
    "fixed": {**kit.line_style({"color": OKABE_ITO["black"]}), "label": "fixed points P, Q of the undamped primary"},
    "peak": {**kit.line_style({"color": OKABE_ITO["vermillion"]}), "label": "peak"},
}


def _slider_values(mu, f, zeta_a, zeta_p) -> tuple[float, float, float, float]:
    """Validated slider values; f and ζ_a default to the H∞ closed form at mu."""
    mu = check_real("mu", mu, low=MU_RANGE[0], high=MU_RANGE[1])
    opt = hinf_tuning(mu)
    f = check_real("f", opt.f if f is None else f, low=F_RANGE[0], high=F_RANGE[1], unit="(ω_a/ω_p)")
    zeta_a = check_real("zeta_a", opt.zeta_a if zeta_a is None else zeta_a, low=ZETA_A_RANGE[0], high=ZETA_A_RANGE[1])
    zeta_p = check_real("zeta_p", zeta_p, low=ZETA_P_RANGE[0], high=ZETA_P_RANGE[1])
    return mu, f, zeta_a, zeta_p


def tmd_panel_html(mu=0.05, f=None, zeta_a=None, *, zeta_p=0.0, panel_id: str | None = None) -> str:
    """Self-contained HTML + JavaScript panel: μ, f, ζ_a and ζ_p sliders over the magnification curve.

    Draws |X_p|/(F0/k_p) against r = ω/ω_p for the slider values, the H∞ tuning of the
    same μ (dashed), the primary without absorber and Den Hartog's fixed points P and Q
    (exact for an undamped primary); reads out the peak, the fixed points and the
    tunings of Den Hartog, H∞ (Nishihara and Asami's closed form) and H2 (Warburton) for
    the current μ with the peaks they give; three buttons set f and ζ_a to a rule.
    Computed in the browser by ``panel/tmd.js`` (``window.vibrationTMD``), which the
    tests compare with :func:`~vibration.tmd_magnification`, :func:`~vibration.tmd_peak`,
    :func:`~vibration.tmd_fixed_points` and the three tuning functions.

    Parameters
    ----------
    mu : float
        Mass ratio m_a/m_p, 1 (0.005 to 0.25).
    f : float, optional
        Tuning ratio ω_a/ω_p, 1 (0.7 to 1.3); default the H∞ optimum at mu.
    zeta_a : float, optional
        Absorber damping ratio c_a/(2 m_a ω_a), 1 (0.005 to 1); default the H∞ optimum at mu.
    zeta_p : float
        Primary damping ratio, 1 (0 to 0.3).
    panel_id : str, optional
        Prefix of element ids (default: hash of the parameters and a counter).

    Examples
    --------
    >>> frag = tmd_panel_html()
    >>> frag.startswith('<div class="vtm-panel"'), "http" in frag, frag.count("<input")
    (True, False, 4)
    """
    mu, f, zeta_a, zeta_p = _slider_values(mu, f, zeta_a, zeta_p)
    params = {"mu": mu, "f": f, "zeta_a": zeta_a, "zeta_p": zeta_p}
    if panel_id is None:
        panel_id = _ids.new(params)
    e = html.escape
    pid = e(panel_id)
    sub = kit.screen_words(
        "Move the mass ratio μ and the absorber damping ζ<sub>a</sub> (logarithmic), the tuning "
        "f = ω<sub>a</sub>/ω<sub>p</sub> and the primary damping ζ<sub>p</sub>; computed in your browser from the "
        "closed forms.",
        "Drawn from the closed forms at the starting mass ratio μ, tuning f = ω<sub>a</sub>/ω<sub>p</sub>, "
        "absorber damping ζ<sub>a</sub> and primary damping ζ<sub>p</sub>.",
    )
    return f"""<div class="vtm-panel" id="{pid}" data-params="{e(json.dumps(params))}" \
data-styles="{e(json.dumps(STYLES))}">
{kit.panel_assets("vibration.book.chapters.tmd", "tmd.js", "tmd.css", kit="vtm")}\
<h3 class="vtm-title">Tuned mass damper: the primary's magnification against the frequency ratio</h3>
<p class="vtm-sub">{sub}</p>
<noscript>This panel needs JavaScript to draw its plot.</noscript>
<div class="vtm-controls">
{_sliders_html(pid, mu, f, zeta_a, zeta_p)}\
</div>
{_body_html()}\
<script>window.vibrationTMD.mount(document.getElementById({json.dumps(panel_id)}));</script>
</div>
"""


def _sliders_html(pid: str, mu: float, f: float, zeta_a: float, zeta_p: float) -> str:
    """The four sliders at their starting values, μ and ζ_a on logarithmic scales (``pid`` HTML-escaped)."""
    lg = math.log10

    def slider(cls, label, lo, hi, value, log):
        a, b, v = (lg(lo), lg(hi), lg(value)) if log else (lo, hi, value)
        return kit.range_control(pid, cls, f"vtm-{cls}", label, low=repr(a), high=repr(b), step="any", value=repr(v))

    return (
        slider("mu", "mass ratio μ = m<sub>a</sub>/m<sub>p</sub> (log)", *MU_RANGE, mu, True)
        + slider("f", "tuning f = ω<sub>a</sub>/ω<sub>p</sub>", *F_RANGE, f, False)
        + slider(
            "za",
            "absorber damping ζ<sub>a</sub> = c<sub>a</sub>/(2 m<sub>a</sub> ω<sub>a</sub>) (log)",
            *ZETA_A_RANGE,
            zeta_a,
            True,
        )
        + slider("zp", "primary damping ζ<sub>p</sub>", *ZETA_P_RANGE, zeta_p, False)
    )


def _body_html() -> str:
    """The rule buttons, the plot and the readout tables (the peak, P and Q, each rule's tuning), filled by the
    script."""
    e = html.escape
    rules = "".join(
        f'<tr><th>{e(name)}</th><td class="vtm-{key}-f"></td><td class="vtm-{key}-za"></td>'
        f'<td class="vtm-{key}-p0"></td><td class="vtm-{key}-p"></td></tr>\n'
        for key, name in _SLIDER_RULES
    )
    buttons = "".join(
        f'<button type="button" class="vtm-rule" data-rule="{key}">{e(name.split(" (")[0])}</button>'
        for key, name in _SLIDER_RULES
    )
    return f"""<div class="vtm-buttons">set f and ζ<sub>a</sub> to the rule for this μ: {buttons}</div>
<div class="vtm-body">
<figure><svg class="vtm-plot" viewBox="0 0 640 330" role="img"
aria-label="primary's magnification against the frequency ratio"></svg></figure>
<div>
<table class="vtm-readout"><tbody>
<tr><th>peak |X<sub>p</sub>|/(F<sub>0</sub>/k<sub>p</sub>)</th><td class="vtm-r-peak"></td></tr>
<tr><th>peak without absorber</th><td class="vtm-r-bare"></td></tr>
<tr><th>fixed point P (ζ<sub>p</sub> = 0)</th><td class="vtm-r-p"></td></tr>
<tr><th>fixed point Q (ζ<sub>p</sub> = 0)</th><td class="vtm-r-q"></td></tr>
</tbody></table>
<table class="vtm-rules"><caption>Tunings for the current μ (ζ<sub>a</sub> on ω<sub>a</sub>)</caption>
<thead><tr><th>rule</th><th>f</th><th>ζ<sub>a</sub></th><th>peak, ζ<sub>p</sub> = 0</th>
<th>peak, current ζ<sub>p</sub></th></tr></thead>
<tbody>
{rules}</tbody></table>
</div>
</div>
"""


class TMDExplorer(kit.KitExplorer):
    """JupyterLab sliders (ipywidgets) for μ, f, ζ_a and ζ_p over the magnification curve.

    ``_repr_mimebundle_`` returns the widget view for JupyterLab and, for renderers
    without a kernel (the book), :func:`tmd_panel_html` at the current slider values.
    """

    def __init__(self, mu=0.05, f=None, zeta_a=None, zeta_p=0.0) -> None:
        import ipywidgets as widgets

        mu, f, zeta_a, zeta_p = _slider_values(mu, f, zeta_a, zeta_p)
        self.mu_slider = widgets.FloatLogSlider(
            value=mu, base=10.0, min=math.log10(MU_RANGE[0]), max=math.log10(MU_RANGE[1]), step=0.005,
            description="μ", readout_format=".4g",
        )  # fmt: skip
        self.f_slider = widgets.FloatSlider(
            value=f, min=F_RANGE[0], max=F_RANGE[1], step=0.0005, description="f = ωₐ/ωₚ", readout_format=".4f"
        )
        self.zeta_a_slider = widgets.FloatLogSlider(
            value=zeta_a, base=10.0, min=math.log10(ZETA_A_RANGE[0]), max=math.log10(ZETA_A_RANGE[1]), step=0.005,
            description="ζₐ", readout_format=".4g",
        )  # fmt: skip
        self.zeta_p_slider = widgets.FloatSlider(
            value=zeta_p, min=ZETA_P_RANGE[0], max=ZETA_P_RANGE[1], step=0.001, description="ζₚ",
            readout_format=".3f",
        )  # fmt: skip
        self.rule_buttons = widgets.ToggleButtons(
            options=["Den Hartog", "H∞", "H2"], value=None, description="set rule", tooltips=[]
        )
        self.image = widgets.Image(format="png")
        self.readout = widgets.HTML()
        sliders = (self.mu_slider, self.f_slider, self.zeta_a_slider, self.zeta_p_slider)
        self.widget = widgets.VBox(
            [widgets.HBox(sliders[:2]), widgets.HBox(sliders[2:]), self.rule_buttons, self.readout, self.image]
        )
        self.watch(*sliders)
        self.rule_buttons.observe(self._apply_rule, names="value")
        self.update()

    def _apply_rule(self, change) -> None:
        rule = change["new"]
        if rule is None:
            return
        t = {"Den Hartog": den_hartog, "H∞": hinf_tuning, "H2": h2_tuning}[rule](float(self.mu_slider.value))
        with self.f_slider.hold_trait_notifications(), self.zeta_a_slider.hold_trait_notifications():
            self.f_slider.value = min(max(t.f, F_RANGE[0]), F_RANGE[1])
            self.zeta_a_slider.value = min(max(t.zeta_a, ZETA_A_RANGE[0]), ZETA_A_RANGE[1])
        self.rule_buttons.value = None
        self.update()

    def values(self) -> dict:
        """Current numbers: slider values, peak and its r, fixed points, the rules' tunings and peaks (all 1)."""
        mu, f = float(self.mu_slider.value), float(self.f_slider.value)
        za, zp = float(self.zeta_a_slider.value), float(self.zeta_p_slider.value)
        rules = {"Den Hartog": den_hartog(mu), "H∞": hinf_tuning(mu), "H2": h2_tuning(mu)}
        rp, hp = tmd_fixed_points(mu, f)
        return {
            "mu": mu,
            "f": f,
            "zeta_a": za,
            "zeta_p": zp,
            "peak": tmd_peak(mu, f, za, zeta_p=zp),
            "fixed": (rp, hp),
            "rules": rules,
            "rule_peaks": {n: tmd_peak(mu, t.f, t.zeta_a, zeta_p=zp) for n, t in rules.items()},
        }

    def figure(self, v: dict):
        fig = kit.agg_figure(7.5, 3.6)
        ax = fig.subplots()
        mu, f, za, zp = v["mu"], v["f"], v["zeta_a"], v["zeta_p"]
        r = np.linspace(*R_RANGE, 2401)
        rp, hp = v["fixed"]
        top = max(2.0 * math.sqrt(1.0 + 2.0 / mu), 1.15 * float(hp.max()))
        with np.errstate(divide="ignore"):
            bare = 1.0 / np.hypot((1.0 - r) * (1.0 + r), 2.0 * zp * r)
        opt = v["rules"]["H∞"]
        ax.plot(r, np.minimum(bare, 2 * top), color=OKABE_ITO["grey"], lw=1.0, label="without absorber")
        ax.plot(r, tmd_magnification(mu, f, za, r=r, zeta_p=zp), color=OKABE_ITO["blue"], lw=1.8,
                label="with the sliders' absorber")  # fmt: skip
        ax.plot(r, tmd_magnification(mu, opt.f, opt.zeta_a, r=r, zeta_p=zp), lw=1.2,
                label=r"H$\infty$ tuning for this $\mu$", **case_style("exact"))  # fmt: skip
        ax.plot(rp, hp, "o", color="k", ms=5, label=r"fixed points P, Q ($\zeta_p = 0$)")
        ax.set_xlim(*R_RANGE)
        ax.set_ylim(0.0, top)
        ax.set_xlabel(r"frequency ratio $r = \omega/\omega_p$ (1)")
        ax.set_ylabel(r"$|X_p|\,/\,(F_0/k_p)$ (1)")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
        return fig

    def readout_html(self, v: dict) -> str:
        rp, hp = v["fixed"]
        rows = "".join(
            f"<tr><td>{html.escape(n)}</td><td>{sig(t.f)}</td><td>{sig(t.zeta_a)}</td><td>{sig(t.peak)}</td>"
            f"<td>{sig(v['rule_peaks'][n])}</td></tr>"
            for n, t in v["rules"].items()
        )
        return (
            f"<p>peak |X<sub>p</sub>|/(F<sub>0</sub>/k<sub>p</sub>) = {sig(v['peak'])}; fixed points P "
            f"(r = {sig(rp[0])}, {sig(hp[0])}) and Q (r = {sig(rp[1])}, {sig(hp[1])}) for ζ<sub>p</sub> = 0; "
            f"ζ′<sub>a</sub> = f ζ<sub>a</sub> = {sig(v['f'] * v['zeta_a'])}</p>"
            "<table><tr><th>rule</th><th>f</th><th>ζ<sub>a</sub></th><th>peak, ζ<sub>p</sub> = 0</th>"
            "<th>peak, current ζ<sub>p</sub></th></tr>"
            f"{rows}</table>"
        )

    def panel_html(self) -> str:
        return tmd_panel_html(float(self.mu_slider.value), float(self.f_slider.value),
                              float(self.zeta_a_slider.value), zeta_p=float(self.zeta_p_slider.value))  # fmt: skip

    def summary(self) -> str:
        return (
            f"TMDExplorer(mu={self.mu_slider.value:.4g}, f={self.f_slider.value:.4g}, "
            f"zeta_a={self.zeta_a_slider.value:.4g}, zeta_p={self.zeta_p_slider.value:.4g})"
        )


def tmd_explorer(mu=0.05, f=None, zeta_a=None, *, zeta_p=0.0) -> TMDExplorer:
    """The chapter's sliders: :class:`TMDExplorer` (ipywidgets in JupyterLab, HTML panel in the book).

    Starts at mass ratio mu, tuning f and absorber damping zeta_a (default: the H∞
    closed-form optimum at mu) and primary damping zeta_p, each moved into its slider's
    range when outside (μ 0.005 to 0.25, f 0.7 to 1.3, ζ_a 0.005 to 1, ζ_p 0 to 0.3).

    Parameters
    ----------
    mu : float
        Mass ratio m_a/m_p, 1 (> 0).
    f : float, optional
        Tuning ratio ω_a/ω_p, 1 (> 0).
    zeta_a : float, optional
        Absorber damping ratio c_a/(2 m_a ω_a), 1 (> 0).
    zeta_p : float
        Primary damping ratio c_p/(2 m_p ω_p), 1 (>= 0).

    Returns
    -------
    TMDExplorer

    Examples
    --------
    >>> ex = tmd_explorer(0.05)
    >>> round(ex.values()["peak"], 4)     # the H∞ optimum of an undamped primary
    6.4079
    """
    mu = check_real("mu", mu, low=0.0, low_open=True, high=MU_MAX)
    if f is not None:
        f = check_real("f", f, low=0.0, low_open=True, unit="(ω_a/ω_p)")
    if zeta_a is not None:
        zeta_a = check_real("zeta_a", zeta_a, low=0.0, low_open=True)
    zeta_p = check_real("zeta_p", zeta_p, low=0.0)

    def clip(x, lo_hi):
        return None if x is None else min(max(x, lo_hi[0]), lo_hi[1])

    mu = clip(mu, MU_RANGE)
    return TMDExplorer(mu, clip(f, F_RANGE), clip(zeta_a, ZETA_A_RANGE), clip(zeta_p, ZETA_P_RANGE))


def sliders_text(st: TMDStudy) -> str:
    """Which controls exist in JupyterLab and in the rendered book, and where they start (Markdown)."""
    mu = min(max(st.mu, MU_RANGE[0]), MU_RANGE[1])
    moved = "" if mu == st.mu else f" (this run's μ = {st.mu:g} is outside the slider's range)"
    t = hinf_tuning(mu)
    return (
        f"Four sliders set the mass ratio μ ({MU_RANGE[0]:g} to {MU_RANGE[1]:g}) and the absorber damping ratio "
        f"$\\zeta_a$ ({ZETA_A_RANGE[0]:g} to {ZETA_A_RANGE[1]:g}, on the absorber's own frequency), both on "
        f"logarithmic scales, the tuning ratio $f = \\omega_a/\\omega_p$ ({F_RANGE[0]:g} to {F_RANGE[1]:g}) and the "
        f"primary damping ratio $\\zeta_p$ ({ZETA_P_RANGE[0]:g} to {ZETA_P_RANGE[1]:g}); three buttons set $f$ and "
        "$\\zeta_a$ to Den Hartog's, the H∞ and the H2 tuning of the current μ. The plot shows the magnification "
        "against $r = \\omega/\\omega_p$ with the H∞ curve of the same μ (black dashed), the primary without "
        "absorber (grey), the fixed points P and Q and the peak; a readout lists the peak, P and Q and each rule's "
        "tuning with the peaks it gives on an undamped and on the current primary. In the notebook with a running "
        "kernel these are live widgets computed by the package; in the rendered book, without a kernel, the same "
        f"controls compute the closed forms in your browser. Both start at μ = {mu:g}{moved} with the H∞ tuning "
        f"$f$ = {sig(t.f)}, $\\zeta_a$ = {sig(t.zeta_a)} on an undamped primary ($\\zeta_p$ = 0), where P and Q are "
        f"exact; set $\\zeta_p$ to {sig(st.zeta_p, 3)} for this run's primary, where they are only approximate."
    )


def panel(study: TMDStudy) -> TMDExplorer:
    """The absorber explorer started at the study's mass ratio with the H∞ tuning.

    The chapter's one entry point for its panel, as in every chapter with a panel: in JupyterLab a live
    explorer, in the rendered book the same controls without a kernel.
    """
    return tmd_explorer(study.mu)
