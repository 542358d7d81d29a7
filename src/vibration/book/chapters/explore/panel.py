"""The kernel-free slider panel of chapter 5: works in a static HTML page, no kernel, no libraries, no network.

:func:`slider_panel_html` returns one self-contained HTML fragment (a ``<div>`` with its own
``<style>`` and inline ``<script>``) that stands in for the live ipywidgets explorer in the rendered
book. The response is computed in the browser from the closed form (steady state plus free transient,
``panel/sliders.js``), and the same JavaScript is exposed as ``window.vibrationSliders.compute(params)``
so the tests can compare its numbers with :func:`vibration.exact_response`.

The plots are drawn by the book's plotting helper (``presentation/assets/plot.js``) in the line styles of
the JupyterLab figure (:data:`STYLES`, passed to the script as ``data-styles``). What the panel draws and
how is read from what it is given and from its own files (:func:`panel_facts`): the line style of each
marked line from :data:`STYLES`, the logarithmic magnification axis from the script, the width below which
the plots stack from the CSS container query. The panel's captions and the chapter's description of it are
written from those facts.

Several panels may share one page: the script defines ``window.vibrationSliders`` once and each panel is
mounted on its own ``div.vib-panel``; element ids carry a per-panel prefix.
"""

from __future__ import annotations

import html
import json
import math
import re
from dataclasses import dataclass
from importlib.resources import files
from typing import TYPE_CHECKING

from vibration.book.chapters.explore.figure import STYLE
from vibration.book.chapters.explore.study import C_MAX, C_MIN
from vibration.book.presentation.panels import PanelIds, checked_panel_id, line_style, panel_assets
from vibration.physics.model import check_int, check_real

if TYPE_CHECKING:  # annotations only
    from vibration.book.chapters.explore.study import ExploreStudy
    from vibration.book.chapters.explore.widget import Explorer

#: Positions of the logarithmic damping slider.
C_STEPS = 1000

#: Step of the forcing-frequency slider, rad/s.
OMEGA_STEP = 0.01

_ids = PanelIds("vib")

#: The panel's line styles, those of the JupyterLab figure (:data:`~vibration.book.chapters.explore.figure.STYLE`):
#: the response and the magnification curve blue, the steady-state amplitudes and the operating point
#: vermillion, the settling time and the natural frequency grey.
STYLES = {
    "response": line_style(STYLE["response"]),
    "curve": line_style(STYLE["curve"]),
    "envelope": line_style(STYLE["envelope"]),
    "settle": line_style(STYLE["marker"]),
    "natural": line_style(STYLE["marker"]),
    "point": line_style({"color": STYLE["point"]["color"]}),
}


def asset(name: str) -> str:
    """Text of ``vibration/book/chapters/explore/panel/<name>``."""
    return files("vibration.book.chapters.explore").joinpath("panel", name).read_text(encoding="utf-8")


@dataclass(frozen=True, kw_only=True)
class PanelFacts:
    """What the panel draws: line-style words, the width below which plots stack, its frequency plot's axes."""

    envelope: str  # line style of the ± steady-state amplitude lines: "dashed", "dotted" or "solid"
    settle: str  # line style of the settling-time line
    natural: str  # line style of the natural-frequency line
    stack_below_px: int  # container width (CSS px) at or below which the magnification plot moves below
    log_magnification: bool  # the magnification axis is logarithmic
    hz_axis: bool  # the frequency plot has a second axis in Hz


def _dash_word(css: str, cls: str) -> str:
    """Line style in words of the CSS rule of ``cls`` (its ``stroke-dasharray``)."""
    rule = re.search(rf"\.{re.escape(cls)}\s*\{{([^}}]*)\}}", css)
    dash = re.search(r"stroke-dasharray:\s*([\d. ]+)", rule.group(1)) if rule else None
    return _pattern_word(dash.group(1) if dash else "")


def _pattern_word(dash: str) -> str:
    """Line style in words of an SVG dash pattern: none solid, a first dash of 4 px or more dashed, else dotted."""
    first = dash.split()[0] if dash.strip() else ""
    if not first:
        return "solid"
    return "dashed" if float(first) >= 4 else "dotted"


def panel_facts() -> PanelFacts:
    """The panel's drawing facts: its line styles (:data:`STYLES`, which ``panel/sliders.js`` draws with), the
    magnification axis and the frequency axis's unit from ``panel/sliders.js``, the stacking width from
    ``panel/sliders.css``."""
    css, js = asset("sliders.css"), asset("sliders.js")
    stack = re.search(r"@container \(max-width: (\d+)px\)\s*\{\s*\.vib-panel \.vib-body", css)
    freq = js.split("function drawFreq", 1)[1].split("function setText", 1)[0]
    return PanelFacts(
        envelope=_pattern_word(STYLES["envelope"]["dash"]),
        settle=_pattern_word(STYLES["settle"]["dash"]),
        natural=_pattern_word(STYLES["natural"]["dash"]),
        stack_below_px=int(stack.group(1)) if stack else 0,
        log_magnification=re.search(r"\by: \{[^}]*\blog: true", freq) is not None,
        hz_axis="(Hz)" in freq,
    )


def time_caption(facts: PanelFacts) -> str:
    """Caption of the panel's time plots (HTML)."""
    return (
        f"Displacement x(t) and velocity v(t) from rest; {facts.envelope}: ± steady-state amplitudes; "
        f"{facts.settle}: 2 % settling time."
    )


def frequency_caption(facts: PanelFacts) -> str:
    """Caption of the panel's frequency plot (HTML)."""
    scale = ", logarithmic" if facts.log_magnification else ""
    return f"Steady-state magnification{scale}; dot: operating point; {facts.natural}: ω<sub>n</sub>."


def _checked_values(m, k, F0, c, omega, t_end, n_points) -> tuple[dict, float]:
    """The panel's values, checked, with the damping slider's range (``c_min``, ``c_max``, N s/m) as the script
    reads them (``data-params``); and the top of the forcing-frequency slider, rad/s."""
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    F0 = check_real("F0", F0, low=0.0, unit="N")
    c_crit = 2.0 * math.sqrt(k) * math.sqrt(m)
    c = check_real("c", c, low=0.0, low_open=True, unit="N s/m")
    c_min = min(C_MIN, c)  # the slider always reaches C_MIN and the starting value
    c_max = max(C_MAX, 2.0 * c_crit, c)
    omega = check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    n_points = check_int("n_points", n_points, low=2, high=100_001)
    wn = math.sqrt(k / m)
    w_max = math.ceil(max(3.0 * wn, 1.5 * omega) * 10.0) / 10.0  # rad/s, on the 0.1 grid
    params = {
        "m": m,
        "c": c,
        "k": k,
        "F0": F0,
        "omega": omega,
        "t_end": t_end,
        "n_points": n_points,
        "c_min": c_min,
        "c_max": c_max,
    }
    return params, w_max


def _controls_html(pid: str, omega: float, c: float, w_max: float, c_pos: int) -> str:
    """The panel's controls: the forcing-frequency slider, the logarithmic damping slider and the reset button."""
    e = html.escape
    return f"""<div class="vib-controls">
<label for="{e(pid)}-omega">forcing frequency ω</label>
<input type="range" class="vib-omega" id="{e(pid)}-omega" min="{OMEGA_STEP:g}" max="{w_max:g}" \
step="{OMEGA_STEP:g}" value="{omega!r}" aria-describedby="{e(pid)}-omega-out">
<output class="vib-omega-out" id="{e(pid)}-omega-out" for="{e(pid)}-omega"></output>
<label for="{e(pid)}-c">damping c (log scale)</label>
<input type="range" class="vib-logc" id="{e(pid)}-c" min="0" max="{C_STEPS}" step="1" value="{c_pos}" \
aria-describedby="{e(pid)}-c-out">
<output class="vib-c-out" id="{e(pid)}-c-out" for="{e(pid)}-c"></output>
<span></span><button type="button" class="vib-reset">reset ω = {omega:g} rad/s, c = {c:g} N s/m</button>
</div>
"""


def _body_html(facts: PanelFacts) -> str:
    """The panel's plots (time and frequency, with their captions) and its readout table, to be filled by the script."""
    readout = [
        ("natural frequency ω<sub>n</sub>", "vib-r-wn", "regime", "vib-r-regime"),
        ("damping ratio ζ", "vib-r-zeta", "frequency ratio ω/ω<sub>n</sub>", "vib-r-ratio"),
        ("steady-state amplitude", "vib-r-amp", "magnification X/(F<sub>0</sub>/k)", "vib-r-mag"),
        ("peak |x| in the window", "vib-r-peak", "2 % settling time", "vib-r-settle"),
        ("velocity amplitude ω|X|", "vib-r-vamp", "peak |v| in the window", "vib-r-peakv"),
    ]
    rows = "\n".join(
        f'<tr><th scope="row">{a}</th><td class="{ca}"></td><th scope="row">{b}</th><td class="{cb}"></td></tr>'
        for a, ca, b, cb in readout
    )
    return f"""<div class="vib-body">
<figure class="vib-fig-time">
<svg class="vib-time" viewBox="0 0 640 270" role="img" \
aria-label="displacement x in m against time t in s"></svg>
<svg class="vib-vel" viewBox="0 0 640 270" role="img" \
aria-label="velocity v in m/s against time t in s"></svg>
<figcaption>{time_caption(facts)}</figcaption>
</figure>
<figure class="vib-fig-freq">
<svg class="vib-freq" viewBox="0 0 340 270" role="img" \
aria-label="magnification against forcing frequency in rad/s"></svg>
<figcaption>{frequency_caption(facts)}</figcaption>
</figure>
<table class="vib-readout">
{rows}
<tr><th scope="row">steady state reached in the window</th><td class="vib-r-settled" colspan="3"></td></tr>
</table>
</div>
"""


def slider_panel_html(
    m: float = 1.0,
    k: float = 20.0,
    F0: float = 5.0,
    *,
    c: float = 0.5,
    omega: float = 4.47,
    t_end: float = 50.0,
    n_points: int = 2001,
    panel_id: str | None = None,
) -> str:
    """Self-contained HTML fragment with forcing-frequency and damping sliders.

    The panel shows the response from rest, displacement ``x(t)`` and velocity ``v(t)`` on
    ``linspace(0, t_end, n_points)``, as SVG polylines, a frequency-response plot (magnification against
    omega, log scale) with the operating point marked, and a readout (natural frequency, damping ratio,
    regime, steady-state amplitude, peak ``|x|`` in the window, 2 % settling time and whether it falls inside
    the window). Everything is computed in the browser; the fragment loads nothing.

    Parameters
    ----------
    m, k, F0 : float
        The oscillator: mass (kg, > 0), stiffness (N/m, > 0) and force amplitude (N, >= 0).
    c : float
        Initial damping, N s/m (> 0); the logarithmic slider spans ``min(C_MIN, c)`` to
        ``max(C_MAX, 2 c_crit, c)`` N s/m, so 0.01 and 20 N s/m are always reachable. The JavaScript closed
        form has no near-resonance branch: below about 1e-6 N s/m at exact undamped resonance it loses accuracy.
    omega : float
        Initial forcing frequency, rad/s (> 0); the slider spans 0.01 rad/s to ``max(3 omega_n, 1.5 omega)``
        in steps of 0.01 rad/s.
    t_end : float
        End of the time window, s (> 0).
    n_points : int
        Samples in the window (2 to 100001).
    panel_id : str, optional
        Prefix of the element ids; by default a hash of the parameters and a counter, so several panels on
        one page never collide.

    Returns
    -------
    str
        HTML: ``<div class="vib-panel" data-params='...'>`` with a ``<style>``, the controls, three ``<svg>``
        plots, a readout table and three ``<script>`` elements (the plotting helper, ``panel/sliders.js`` and
        the call that mounts this panel).

    Examples
    --------
    >>> frag = slider_panel_html(omega=3.0)
    >>> frag.startswith('<div class="vib-panel"'), "http" in frag
    (True, False)
    """
    params, w_max = _checked_values(m, k, F0, c, omega, t_end, n_points)
    m, k, F0, c, omega, t_end = (params[name] for name in ("m", "k", "F0", "c", "omega", "t_end"))
    pid = checked_panel_id(panel_id) or _ids.new(params)
    c_pos = round(C_STEPS * math.log(c / params["c_min"]) / math.log(params["c_max"] / params["c_min"]))
    e = html.escape
    facts = panel_facts()
    return f"""<div class="vib-panel" id="{e(pid)}" data-params="{e(json.dumps(params))}" \
data-styles="{e(json.dumps(STYLES))}">
{panel_assets("vibration.book.chapters.explore", "sliders.js", "sliders.css", kit="vib")}\
<h3 class="vib-title">Explore without a kernel: m = {m:g} kg, k = {k:g} N/m, F<sub>0</sub> = {F0:g} N, \
window 0 to {t_end:g} s</h3>
<p class="vib-sub">Response from rest, <i>m x'' + c x' + k x = F<sub>0</sub> sin(ωt)</i>, computed in \
your browser from the closed form (steady state plus transient). Here only ω, c and reset are controls; \
m, k, F<sub>0</sub>, the window and the RK45 overlay need the running notebook. The damping slider is logarithmic.</p>
<noscript>This panel needs JavaScript to draw its plots.</noscript>
{_controls_html(pid, omega, c, w_max, c_pos)}{_body_html(facts)}\
<script>window.vibrationSliders.mount(document.getElementById({json.dumps(pid)}));</script>
</div>
"""


def panel(study: ExploreStudy) -> Explorer:
    """The slider explorer started at the study's parameters.

    The chapter's one entry point for its panel, as in every chapter with a panel: in JupyterLab a live
    explorer, in the rendered book the same controls without a kernel.
    """
    from vibration.book.chapters.explore.widget import live_explorer  # the widget module imports this one

    return live_explorer(study)
