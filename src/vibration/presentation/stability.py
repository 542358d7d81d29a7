"""Stability chapter: one study object, its figures, tables, sentences and sliders.

:func:`stability_study` runs every computation of the chapter once (all physics from
:mod:`vibration.physics.stability`); the figure, table and sentence functions only read
the resulting :class:`StabilityStudy`, so a run with other parameters never contradicts
its own tables. :func:`stability_explorer` gives the JupyterLab sliders; its
``_repr_mimebundle_`` also carries :func:`stability_panel_html`, the kernel-free panel
of the rendered book (``assets/stability.js``).
"""

from __future__ import annotations

import base64
import hashlib
import html
import io
import itertools
import json
import math
from dataclasses import dataclass, field
from importlib.resources import files

import numpy as np
from matplotlib.colors import LogNorm
from matplotlib.lines import Line2D
from matplotlib.ticker import FuncFormatter

from ..physics.exact import exact_response
from ..physics.model import Oscillator, ParameterError, SineForce, check_int, check_real
from ..physics.stability import (
    DesignMetrics,
    StepMetrics,
    damper_load,
    design_metrics,
    growth_envelope,
    isolation_frequency,
    peak_transmissibility,
    poles,
    settling_optimal_zeta,
    stability_class,
    step_metrics,
    step_response,
    transmissibility,
    white_noise_monte_carlo,
    white_noise_variance,
    white_noise_velocity_variance,
)
from .style import figure, place_legend
from .tables import Column, Missing, Table, fmt

__all__ = [
    "StabilityExplorer",
    "StabilityStudy",
    "checks_table",
    "cost_figure",
    "cost_sentence",
    "cost_table",
    "growth_figure",
    "growth_sentence",
    "growth_table",
    "labels_figure",
    "labels_sentence",
    "labels_table",
    "pole_figure",
    "poles_table",
    "random_sentence",
    "random_table",
    "stability_explorer",
    "stability_panel_html",
    "stability_sentence",
    "stability_study",
    "step_figure",
    "step_sentence",
    "step_table",
    "summary_text",
    "transmissibility_figure",
    "transmissibility_sentence",
    "transmissibility_table",
]

#: The paper's names for its three dampings (Discussion 4.2), in the order low, nominal, high.
LABELS = {"low": "comfort", "nominal": "optimised compromise", "high": "absolute stability"}
COLORS = {"low": "#1f77b4", "nominal": "#2ca02c", "high": "#d62728", "undamped": "#7f7f7f", "unstable": "#9467bd"}
BAND = 0.02  # settling band of the step response, fraction
NO_PEAK = Missing("no peak: the response rises monotonically")


def _c_text(c: float) -> str:
    return f"c = {fmt(c, 4)} N s/m"


def _pole_text(p: np.ndarray) -> str:
    a, b = p
    if a.imag != 0.0:
        return f"{fmt(a.real + 0.0, 4)} ± {fmt(abs(a.imag), 4)}i".replace("-", "−")
    return f"{fmt(a.real, 4)}, {fmt(b.real, 4)}".replace("-", "−")


@dataclass
class StabilityStudy:
    """Every number of the chapter, computed once by :func:`stability_study` (SI units)."""

    m: float  # mass, kg
    k: float  # stiffness, N/m
    F0: float  # force amplitude, N
    omega_res: float  # the paper's "resonant" forcing frequency, rad/s
    dampings: dict  # "low"/"nominal"/"high" -> c, N s/m
    c_unstable: float  # negative damping of the flutter model, N s/m
    t_growth: float  # window of the growth comparison, s
    isolation_ratio: float  # omega / omega_n at which isolation is judged, 1
    S0: float  # two-sided force spectral density, N^2 s/rad
    n_paths: int  # Monte Carlo paths
    seed: int  # Monte Carlo seed
    design: dict = field(default_factory=dict)  # name -> DesignMetrics
    steps: dict = field(default_factory=dict)  # name -> StepMetrics
    monte_carlo: dict = field(default_factory=dict)  # name -> MonteCarlo
    zeta_star: float = math.nan  # settling-optimal damping ratio, 1
    star: DesignMetrics | None = None  # design metrics at zeta_star
    growth: dict = field(default_factory=dict)  # case -> dict(t, x, env, osc, force)

    @property
    def omega_n(self) -> float:
        """Natural frequency, rad/s."""
        return math.sqrt(self.k / self.m)

    @property
    def c_crit(self) -> float:
        """Critical damping, N s/m."""
        return 2.0 * math.sqrt(self.k) * math.sqrt(self.m)

    def osc(self, c: float) -> Oscillator:
        return Oscillator(self.m, c, self.k)

    @property
    def c_star(self) -> float:
        """Damping of the settling-optimal ratio, N s/m."""
        return self.zeta_star * self.c_crit


def stability_study(
    m: float = 1.0,
    k: float = 20.0,
    F0: float = 5.0,
    omega_res: float = 4.47,
    c_low: float = 0.1,
    c_nominal: float = 0.5,
    c_high: float = 15.0,
    c_unstable: float = -0.1,
    t_growth: float = 200.0,
    isolation_ratio: float = 3.0,
    S0: float = 0.1,
    n_paths: int = 200,
    seed: int = 1,
) -> StabilityStudy:
    """Run the chapter: stability, growth, transmissibility, step, random load, cost.

    Parameters
    ----------
    m, k, F0 : float
        Mass (kg, > 0), stiffness (N/m, > 0), force amplitude (N, > 0).
    omega_res : float
        The paper's resonant forcing frequency, rad/s (> 0).
    c_low, c_nominal, c_high : float
        The paper's three dampings, N s/m (> 0, increasing).
    c_unstable : float
        Negative damping of the flutter model, N s/m (< 0, ``|zeta| < 1``).
    t_growth : float
        Window of the growth comparison, s (0 < t_growth <= 2000).
    isolation_ratio : float
        ``omega / omega_n`` at which isolation is judged (> sqrt 2, <= 100).
    S0 : float
        Two-sided white-noise force spectral density, N^2 s/rad (> 0).
    n_paths : int
        Monte Carlo paths per damping (2 to 5000).
    seed : int
        Monte Carlo seed (>= 0).

    Examples
    --------
    >>> s = stability_study(n_paths=20)
    >>> round(s.zeta_star, 4), s.design["high"].stability
    (0.7797, 'asymptotically stable')
    """
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    omega_res = check_real("omega_res", omega_res, low=0.0, low_open=True, unit="rad/s")
    dampings = {}
    for name, value in (("c_low", c_low), ("c_nominal", c_nominal), ("c_high", c_high)):
        dampings[name[2:]] = check_real(name, value, low=0.0, low_open=True, unit="N s/m")
    if not dampings["low"] < dampings["nominal"] < dampings["high"]:
        raise ParameterError(
            f"c_low, c_nominal, c_high = {c_low!r}, {c_nominal!r}, {c_high!r} N s/m: allowed c_low < c_nominal < c_high"
        )
    c_crit = 2.0 * math.sqrt(k * m)
    c_unstable = check_real("c_unstable", c_unstable, low=-c_crit, low_open=True, high=0.0, unit="N s/m")
    if c_unstable == 0.0:
        raise ParameterError(f"c_unstable = 0.0 N s/m is out of range: allowed -{c_crit:g} < c_unstable < 0 N s/m")
    t_growth = check_real("t_growth", t_growth, low=0.0, low_open=True, high=2000.0, unit="s")
    isolation_ratio = check_real("isolation_ratio", isolation_ratio, low=math.sqrt(2.0), low_open=True, high=100.0)
    S0 = check_real("S0", S0, low=0.0, low_open=True, unit="N^2 s/rad")
    n_paths = check_int("n_paths", n_paths, low=2, high=5000)
    seed = check_int("seed", seed, low=0, high=2**31 - 1)
    st = StabilityStudy(m, k, F0, omega_res, dampings, c_unstable, t_growth, isolation_ratio, S0, n_paths, seed)
    for i, (name, c) in enumerate(dampings.items()):
        osc = st.osc(c)
        st.design[name] = design_metrics(osc, isolation_ratio, BAND)
        st.steps[name] = step_metrics(osc, BAND)
        st.monte_carlo[name] = white_noise_monte_carlo(osc, S0, n_paths=n_paths, seed=seed + i)
    st.zeta_star = settling_optimal_zeta(BAND)
    st.star = design_metrics(st.osc(st.c_star), isolation_ratio, BAND)
    # growth: bounded (c_low at omega_res), linear (c = 0 at omega_n exactly), exponential (c_unstable)
    n = int(min(200_001, max(20_001, 40 * t_growth * st.omega_n)))
    t = np.linspace(0.0, t_growth, n)
    for case, c, w in (
        ("bounded", dampings["low"], omega_res),
        ("linear", 0.0, st.omega_n),
        ("exponential", c_unstable, omega_res),
    ):
        osc, force = st.osc(c), SineForce(F0, w)
        st.growth[case] = {
            "osc": osc,
            "force": force,
            "t": t,
            "x": exact_response(osc, force, t).x,
            "env": growth_envelope(osc, force, t),
        }
    return st


# ----------------------------------------------------------------------------- stability: poles


def _pole_cases(st: StabilityStudy) -> list[tuple[str, str, float]]:
    rows = [(name, f"{name} damping, “{LABELS[name]}”", c) for name, c in st.dampings.items()]
    rows.append(("undamped", "undamped", 0.0))
    rows.append(("unstable", "negative damping (flutter model)", st.c_unstable))
    return rows


def poles_table(st: StabilityStudy) -> Table:
    """Poles and stability of the paper's dampings, c = 0 and c < 0."""
    rows = []
    for _key, label, c in _pole_cases(st):
        osc = st.osc(c)
        s = stability_class(osc)
        rows.append(
            {
                "case": label,
                "c": c,
                "zeta": osc.damping_ratio,
                "poles": _pole_text(poles(osc)),
                "abscissa": s.spectral_abscissa,
                "asym": s.asymptotic,
                "lyap": s.lyapunov,
                "bibo": s.bibo,
                "verdict": s.verdict,
            }
        )
    return Table(
        rows,
        [
            Column("case", "case"),
            Column("c", "c (N s/m)", 3),
            Column("zeta", "ζ", 3),
            Column("poles", "poles s (1/s)"),
            Column("abscissa", "max Re s (1/s)", 3),
            Column("asym", "free motion decays"),
            Column("lyap", "free motion bounded"),
            Column("bibo", "bounded force, bounded x"),
            Column("verdict", "verdict"),
        ],
        caption="Poles of m s² + c s + k and the three notions of stability.",
        name="tab-stability-poles",
    )


def stability_sentence(st: StabilityStudy) -> str:
    """Which of the paper's dampings are stable, and how fast the 'unstable' one decays."""
    low = st.osc(st.dampings["low"])
    all_stable = all(stability_class(st.osc(c)).asymptotic for c in st.dampings.values())
    head = (
        "All three of the paper's dampings put both poles in the open left half-plane: each is asymptotically "
        "stable and bounded-input bounded-output stable."
        if all_stable
        else "Not all of the paper's dampings are stable."
    )
    return (
        f"{head} The low damping ({_c_text(low.c)}) that the paper calls unstable has its slowest free mode "
        f"decaying as exp(−t/τ) with τ = 2m/c = {fmt(low.time_constant, 3)} s; its response is bounded by "
        f"{fmt(st.design['low'].peak_magnification * st.F0 / st.k, 3)} m at any forcing frequency. Only c = 0 "
        f"(marginal: poles on the imaginary axis, a force at ω_n grows the response without bound) and c < 0 "
        f"(a pole in the right half-plane: the free motion itself grows as exp({fmt(-st.c_unstable / (2 * st.m), 3)} "
        "t/s)) are not stable."
    )


def pole_figure(st: StabilityStudy):
    """Poles in the complex plane: the whole locus over c, and a zoom near the imaginary axis."""
    fig, (ax, az) = figure(1, 2, height=3.9, gridspec_kw={"width_ratios": (1.25, 1.0)})
    wn = st.omega_n
    c_max = max(1.3 * st.dampings["high"], 2.2 * st.c_crit)
    cs = np.concatenate([np.linspace(st.c_unstable * 1.5, st.c_crit, 600), np.linspace(st.c_crit, c_max, 600)])
    locus = np.array([poles(st.osc(c)) for c in cs])
    for a in (ax, az):
        a.axvspan(-1e9, 0.0, color="#2ca02c", alpha=0.06, lw=0)
        a.axvline(0.0, color="0.3", lw=0.8)
        a.plot(locus[:, 0].real, locus[:, 0].imag, color="0.75", lw=1.0, zorder=1)
        a.plot(locus[:, 1].real, locus[:, 1].imag, color="0.75", lw=1.0, zorder=1)
    handles = [Line2D([], [], color="0.75", lw=1.0, label=r"locus as $c$ varies")]
    markers = {"low": "o", "nominal": "s", "high": "D", "undamped": "X", "unstable": "P"}
    for key, label, c in _pole_cases(st):
        p = poles(st.osc(c))
        for a in (ax, az):
            a.plot(p.real, p.imag, ls="none", marker=markers[key], ms=7, color=COLORS[key], zorder=3)
        short = label.split(",")[0]
        handles.append(
            Line2D([], [], ls="none", marker=markers[key], ms=7, color=COLORS[key], label=f"{short}: $c$ = {c:g} N s/m")
        )
    lo = min(locus.real.min(), -st.dampings["high"] / st.m)
    ax.set_xlim(lo * 1.05, 0.12 * abs(lo))
    ax.set_ylim(-1.4 * wn, 1.4 * wn)
    near = [poles(st.osc(c))[0] for _k, _l, c in _pole_cases(st) if abs(c) < st.c_crit / 2]
    re = [p.real for p in near] + [0.0]
    im = [p.imag for p in near]
    span_re, span_im = max(re) - min(re), max(max(im) - min(im), 1e-3 * wn)
    az.set_xlim(min(re) - 0.3 * span_re, max(re) + 0.3 * span_re)
    az.set_ylim(min(im) - 0.5 * span_im, max(im) + 0.5 * span_im)
    ax.text(0.03, 0.04, "stable half-plane", transform=ax.transAxes, color="#2ca02c", fontsize=8.5)
    for a in (ax, az):
        a.set_xlabel(r"Re $s$ (1/s)")
    ax.set_ylabel(r"Im $s$ (rad/s)")
    az.set_title(r"zoom near $s = i\,\omega_n$", fontsize=9)
    fig.legend(handles=handles, loc="outside upper center", ncols=2, frameon=False, fontsize=8)
    return fig


# ----------------------------------------------------------------------------- growth


def growth_figure(st: StabilityStudy):
    """The three ways a response grows, each with its closed-form envelope."""
    fig, axes = figure(3, 1, height=6.4, sharex=True)
    titles = {
        "bounded": "transient approaching a bounded steady state",
        "linear": "linear growth at exact undamped resonance",
        "exponential": "exponential growth with negative damping (flutter's linear model)",
    }
    colors = {"bounded": COLORS["low"], "linear": COLORS["undamped"], "exponential": COLORS["unstable"]}
    for ax, (case, g) in zip(axes, st.growth.items(), strict=True):
        osc, force = g["osc"], g["force"]
        ax.plot(g["t"], g["x"], color=colors[case], lw=0.5, label="exact response $x(t)$")
        ax.plot(g["t"], g["env"], color="k", lw=1.1, ls="--", label="closed-form envelope")
        ax.plot(g["t"], -g["env"], color="k", lw=1.1, ls="--")
        ax.set_title(
            f"{titles[case]}: $c$ = {osc.c:g} N s/m, $\\omega$ = {force.omega:.4g} rad/s", fontsize=9, loc="left"
        )
        ax.set_ylabel(r"$x$ (m)")
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4), useMathText=True)
    axes[-1].set_xlabel(r"time $t$ (s)")
    axes[0].legend(loc="lower right", bbox_to_anchor=(1.0, 1.18), ncols=2, frameon=False)
    return fig


def growth_table(st: StabilityStudy) -> Table:
    """Growth law, rate and the size reached at the end of the window, per case."""
    rows = []
    for case, g in st.growth.items():
        osc, force = g["osc"], g["force"]
        none = Missing("not this growth law")
        row = {
            "case": case,
            "c": osc.c,
            "omega": force.omega,
            "steady": none,
            "slope": none,
            "rate": none,
            "peak": float(np.max(np.abs(g["x"]))),
            "env_end": float(g["env"][-1]),
        }
        if case == "bounded":
            row["steady"] = st.F0 / math.hypot(st.k - st.m * force.omega**2, osc.c * force.omega)
        elif case == "linear":
            row["slope"] = st.F0 / (2.0 * st.m * st.omega_n)
        else:
            row["rate"] = -osc.c / (2.0 * st.m)
        rows.append(row)
    return Table(
        rows,
        [
            Column("case", "growth"),
            Column("c", "c (N s/m)", 3),
            Column("omega", "ω (rad/s)", 4),
            Column("steady", "steady amplitude (m)", 4),
            Column("slope", "F0/(2mω_n) (m/s)", 4),
            Column("rate", "−c/(2m) (1/s)", 3),
            Column("peak", "max |x| in window (m)", 4),
            Column("env_end", "envelope at t_end (m)", 4),
        ],
        caption=f"Three ways a response from rest grows over 0 to {st.t_growth:g} s (exact closed forms).",
        name="tab-stability-growth",
    )


def growth_sentence(st: StabilityStudy) -> str:
    """How the three cases compare at the end of the window."""
    b, lin, ex = (st.growth[c] for c in ("bounded", "linear", "exponential"))
    amp = st.F0 / math.hypot(st.k - st.m * st.omega_res**2, b["osc"].c * st.omega_res)
    return (
        f"Over {st.t_growth:g} s the paper's low damping reaches at most {fmt(float(np.max(np.abs(b['x']))), 3)} m "
        f"and its envelope closes in on the steady amplitude {fmt(amp, 3)} m (beating at ω_d − ω = "
        f"{fmt(b['osc'].damped_natural_frequency - st.omega_res, 2)} rad/s while it does); exact undamped "
        f"resonance reaches {fmt(float(np.max(np.abs(lin['x']))), 3)} m, growing by F0/(2mω_n) = "
        f"{fmt(st.F0 / (2 * st.m * st.omega_n), 3)} m each second for ever; negative damping "
        f"c = {ex['osc'].c:g} N s/m reaches {fmt(float(np.max(np.abs(ex['x']))), 3)} m and multiplies by "
        f"e every {fmt(2 * st.m / abs(ex['osc'].c), 3)} s. Only the last two are instability."
    )


# ----------------------------------------------------------------------------- transmissibility


def _family(st: StabilityStudy) -> list[tuple[str, float]]:
    """(label, c) of the transmissibility family: the paper's three, zeta = 0.2, zeta*, 1."""
    out = [(f"{name}: $c$ = {c:g} N s/m", c) for name, c in st.dampings.items()]
    for z, lab in ((0.2, r"$\zeta$ = 0.2"), (st.zeta_star, rf"$\zeta^*$ = {st.zeta_star:.3f}"), (1.0, r"$\zeta$ = 1")):
        out.append((lab, z * st.c_crit))
    return sorted(out, key=lambda p: p[1])


def transmissibility_figure(st: StabilityStudy):
    """|X/Y| against frequency for a family of dampings; all cross 1 at sqrt(2) omega_n."""
    fig, ax = figure(height=3.8)
    wn = st.omega_n
    w = np.unique(np.concatenate([np.linspace(0.0, 4.0 * wn, 3001), wn * (1 + np.linspace(-0.05, 0.05, 801))]))
    family = _family(st)
    cmap = __import__("matplotlib").colormaps["viridis"]
    for i, (label, c) in enumerate(family):
        col = cmap(i / max(1, len(family) - 1) * 0.9)
        bold = "N s/m" in label
        ax.semilogy(w, transmissibility(st.osc(c), w), color=col, lw=1.8 if bold else 1.0, label=label)
    ax.axvline(isolation_frequency(st.osc(1.0)), color="0.3", lw=0.8, ls="--")
    ax.axvline(st.isolation_ratio * wn, color="0.3", lw=0.8, ls=":")
    ax.axhline(1.0, color="0.3", lw=0.6)
    ax.annotate(
        r"$\sqrt{2}\,\omega_n$: $T = 1$ for every $\zeta$",
        (isolation_frequency(st.osc(1.0)), 1.0),
        xytext=(6, 30),
        textcoords="offset points",
        fontsize=8.5,
        arrowprops={"arrowstyle": "-", "color": "0.4", "lw": 0.6},
    )
    ax.text(st.isolation_ratio * wn, 1.5e-2, rf" $\omega$ = {st.isolation_ratio:g} $\omega_n$", fontsize=8.5)
    ax.set_ylim(1e-2, 200.0)
    ax.set_xlim(0.0, 4.0 * wn)
    ax.set_xlabel(r"base frequency $\omega$ (rad/s)")
    ax.set_ylabel(r"transmissibility $|X/Y|$ (1)")
    place_legend(ax, outside=True)
    return fig


def transmissibility_table(st: StabilityStudy) -> Table:
    """Transmissibility at resonance, at sqrt(2) omega_n and at the isolation ratio; its peak."""
    wn = st.omega_n
    rows = []
    for label, c in _family(st):
        osc = st.osc(c)
        wp, tp = peak_transmissibility(osc)
        rows.append(
            {
                "case": label.replace("$", "").replace("\\zeta", "ζ").replace("^*", "*").replace("c =", "c ="),
                "zeta": osc.damping_ratio,
                "t_res": float(transmissibility(osc, wn)),
                "t_iso": float(transmissibility(osc, math.sqrt(2.0) * wn)),
                "t_r": float(transmissibility(osc, st.isolation_ratio * wn)),
                "wp": wp,
                "tp": tp,
            }
        )
    r = st.isolation_ratio
    return Table(
        rows,
        [
            Column("case", "damping"),
            Column("zeta", "ζ", 3),
            Column("t_res", "T at ω_n", 4),
            Column("t_iso", "T at √2 ω_n", 4),
            Column("t_r", f"T at {r:g} ω_n", 4),
            Column("wp", "ω_peak (rad/s)", 4),
            Column("tp", "T_max", 4),
        ],
        caption="Base-excitation transmissibility |X/Y| of the damping family.",
        name="tab-stability-transmissibility",
    )


def transmissibility_sentence(st: StabilityStudy) -> str:
    """The isolation trade-off between the paper's low and high dampings."""
    lo, hi = st.design["low"], st.design["high"]
    r = st.isolation_ratio
    return (
        f"Under base motion the trade-off is real. At resonance the high damping transmits "
        f"{fmt(float(transmissibility(st.osc(hi.c), st.omega_n)), 3)} of the base motion against "
        f"{fmt(float(transmissibility(st.osc(lo.c), st.omega_n)), 3)} for the low damping; at ω = {r:g} ω_n "
        f"it transmits {fmt(hi.transmissibility, 3)} against {fmt(lo.transmissibility, 3)}, "
        f"{fmt(hi.transmissibility / lo.transmissibility, 3)} times more. Every curve passes through T = 1 at "
        f"√2 ω_n = {fmt(isolation_frequency(st.osc(1.0)), 4)} rad/s; above it more damping transmits more."
    )


# ----------------------------------------------------------------------------- step response


def step_figure(st: StabilityStudy):
    """Normalised step responses, and settling and rise times against the damping ratio."""
    fig, (ax, am) = figure(1, 2, height=3.6, gridspec_kw={"width_ratios": (1.2, 1.0)})
    wn = st.omega_n
    t_end = 12.0 * 2 * math.pi / wn
    t = np.linspace(0.0, t_end, 4001)
    ax.axhspan(1 - BAND, 1 + BAND, color="0.85", lw=0, label="±2 % band")
    cases = [(f"{n}: $c$ = {c:g} N s/m", c, COLORS[n]) for n, c in st.dampings.items()]
    cases.append((rf"$\zeta^*$ = {st.zeta_star:.3f}", st.c_star, "#ff7f0e"))
    for label, c, col in cases:
        ax.plot(t, step_response(st.osc(c), t), color=col, lw=1.0, label=label)
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"$k\,x / F$ (1)")
    ax.set_xlim(0.0, t_end)
    ax.set_ylim(-0.05, 2.05)
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02), ncols=2, frameon=False, fontsize=7.5)
    zetas = np.geomspace(0.005, 8.0, 700)
    metrics = [step_metrics(Oscillator(st.m, z * st.c_crit, st.k), BAND) for z in zetas]
    am.loglog(zetas, [s.settling_time for s in metrics], color="k", lw=1.0, label="2 % settling time")
    am.loglog(zetas, [s.rise_time for s in metrics], color="0.5", lw=1.0, ls="--", label="10–90 % rise time")
    for n in st.dampings:
        s = st.steps[n]
        am.plot([s.zeta], [s.settling_time], "o", color=COLORS[n], ms=6)
    am.plot([st.zeta_star], [st.star.settling_time], "*", color="#ff7f0e", ms=11, label=r"$\zeta^*$ (fastest)")
    am.set_xlabel(r"damping ratio $\zeta$ (1)")
    am.set_ylabel(r"time (s)")
    am.plot([], [], "o", color="0.4", ms=6, label="the paper's dampings")
    am.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02), ncols=2, frameon=False, fontsize=7.5)
    return fig


def step_table(st: StabilityStudy) -> Table:
    """Step metrics of the paper's three dampings and of the settling-optimal one."""
    rows = []
    items = [(f"{n} (“{LABELS[n]}”)", st.dampings[n], st.steps[n]) for n in st.dampings]
    items.append(("settling-optimal ζ*", st.c_star, step_metrics(st.osc(st.c_star), BAND)))
    for label, c, s in items:
        rows.append(
            {
                "case": label,
                "c": c,
                "zeta": s.zeta,
                "os": 100.0 * s.overshoot,
                "tp": s.peak_time if math.isfinite(s.peak_time) else NO_PEAK,
                "tr": s.rise_time,
                "ts": s.settling_time,
                "wts": st.omega_n * s.settling_time,
            }
        )
    return Table(
        rows,
        [
            Column("case", "damping"),
            Column("c", "c (N s/m)", 4),
            Column("zeta", "ζ", 4),
            Column("os", "overshoot (%)", 4),
            Column("tp", "t_peak (s)", 4),
            Column("tr", "t_rise (s)", 4),
            Column("ts", "t_s, 2 % (s)", 4),
            Column("wts", "ω_n t_s", 4),
        ],
        caption="Response to a step force, normalised by its final value F/k (exact; settling is the last exit "
        "from the 2 % band).",
        name="tab-stability-step",
    )


def step_sentence(st: StabilityStudy) -> str:
    """The settling-optimal damping and where the paper's three land."""
    s = {n: st.steps[n] for n in st.dampings}
    fastest = min(s, key=lambda n: s[n].settling_time)
    return (
        f"The 2 % settling time is shortest at ζ* = {st.zeta_star:.4f} (c = {fmt(st.c_star, 4)} N s/m here), where "
        f"the overshoot equals the band: t_s = {fmt(st.star.settling_time, 3)} s. Among the paper's dampings the "
        f"{fastest} one settles first ({fmt(s[fastest].settling_time, 3)} s); the low damping overshoots by "
        f"{fmt(100 * s['low'].overshoot, 3)} % and needs {fmt(s['low'].settling_time, 3)} s, the nominal "
        f"{fmt(100 * s['nominal'].overshoot, 3)} % and {fmt(s['nominal'].settling_time, 3)} s, the high one "
        f"{fmt(s['high'].settling_time, 3)} s without overshoot, "
        f"{fmt(s['high'].settling_time / st.star.settling_time, 3)} times the optimum."
    )


# ----------------------------------------------------------------------------- random load


def random_table(st: StabilityStudy) -> Table:
    """Stationary variance under white-noise force: closed form against Monte Carlo."""
    rows = []
    for n, c in st.dampings.items():
        osc, mc = st.osc(c), st.monte_carlo[n]
        exact = white_noise_variance(osc, st.S0)
        exact_v = white_noise_velocity_variance(osc, st.S0)
        rows.append(
            {
                "case": n,
                "c": c,
                "exact": exact,
                "mc": mc.variance,
                "se": mc.standard_error,
                "z": (mc.variance - exact) / mc.standard_error,
                "rms": math.sqrt(exact),
                "vexact": exact_v,
                "vmc": mc.velocity_variance,
                "vz": (mc.velocity_variance - exact_v) / mc.velocity_standard_error,
            }
        )
    return Table(
        rows,
        [
            Column("case", "damping"),
            Column("c", "c (N s/m)", 3),
            Column("exact", "πS0/(kc) (m²)", 4),
            Column("mc", "Monte Carlo (m²)", 4),
            Column("se", "std. error (m²)", 2),
            Column("z", "deviation (std. errors)", 2),
            Column("rms", "σ_x (m)", 3),
            Column("vexact", "πS0/(mc) (m²/s²)", 4),
            Column("vmc", "Monte Carlo (m²/s²)", 4),
            Column("vz", "deviation (std. errors)", 2),
        ],
        caption=f"Displacement and velocity variance under a white-noise force, S0 = {st.S0:g} N² s/rad "
        f"(two-sided); Monte Carlo with {st.n_paths} seeded paths per damping.",
        name="tab-stability-random",
    )


def random_sentence(st: StabilityStudy) -> str:
    """What damping does to the random response, and whether the simulation agrees."""
    rms = {n: math.sqrt(white_noise_variance(st.osc(c), st.S0)) for n, c in st.dampings.items()}
    zs = [
        abs(st.monte_carlo[n].variance - white_noise_variance(st.osc(c), st.S0)) / st.monte_carlo[n].standard_error
        for n, c in st.dampings.items()
    ]
    agree = "agrees with" if max(zs) < 4.0 else "does not agree with"
    return (
        f"Under a white-noise force the variance is π S0/(k c): the rms displacement falls as 1/√c, from "
        f"{fmt(rms['low'], 3)} m (low) to {fmt(rms['nominal'], 3)} m (nominal) and {fmt(rms['high'], 3)} m (high). "
        f"Here more damping helps at every level of the load. The simulation {agree} the closed form "
        f"(largest deviation {fmt(max(zs), 2)} standard errors)."
    )


# ----------------------------------------------------------------------------- cost


def cost_figure(st: StabilityStudy):
    """Damper force amplitude and mean dissipated power against forcing frequency."""
    fig, (af, ap) = figure(1, 2, height=3.3)
    wn = st.omega_n
    w = np.unique(np.concatenate([np.linspace(0.01 * wn, 3.0 * wn, 2001), wn * (1 + np.linspace(-0.03, 0.03, 601))]))
    for n, c in st.dampings.items():
        d = damper_load(st.osc(c), st.F0, w)
        af.semilogy(w, d.force_amplitude, color=COLORS[n], label=f"{n}: $c$ = {c:g} N s/m")
        ap.semilogy(w, d.mean_power, color=COLORS[n], label=f"{n}: $c$ = {c:g} N s/m")
    for a in (af, ap):
        a.axvline(wn, color="0.4", lw=0.7, ls="--")
        a.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
    af.axhline(st.F0, color="0.4", lw=0.7, ls=":")
    af.set_ylabel(r"damper force amplitude $c\,\omega |X|$ (N)")
    ap.set_ylabel(r"mean dissipated power (W)")
    fig.legend(*af.get_legend_handles_labels(), loc="outside upper center", ncols=3, frameon=False)
    return fig


def cost_table(st: StabilityStudy) -> Table:
    """Damper force amplitude and mean power at the paper's forcing frequency and at omega_n."""
    rows = []
    for n, c in st.dampings.items():
        osc = st.osc(c)
        for label, w in ((f"{st.omega_res:g} rad/s (paper)", st.omega_res), ("ω_n", st.omega_n)):
            d = damper_load(osc, st.F0, w)
            rows.append(
                {
                    "case": n,
                    "c": c,
                    "w": label,
                    "x": float(d.amplitude),
                    "f": float(d.force_amplitude),
                    "p": float(d.mean_power),
                }
            )
    return Table(
        rows,
        [
            Column("case", "damping"),
            Column("c", "c (N s/m)", 3),
            Column("w", "ω"),
            Column("x", "|X| (m)", 4),
            Column("f", "damper force (N)", 4),
            Column("p", "mean power (W)", 4),
        ],
        caption=f"Cost of damping under F0 = {st.F0:g} N on the mass, in the steady state.",
        name="tab-stability-cost",
    )


def cost_sentence(st: StabilityStudy) -> str:
    """The damper's load at resonance."""
    p = {n: float(damper_load(st.osc(c), st.F0, st.omega_n).mean_power) for n, c in st.dampings.items()}
    return (
        f"At ω_n the damper force equals the applied force F0 = {st.F0:g} N for every damping (it is what balances "
        f"the force there), and the mean power it must dissipate is F0²/(2c): {fmt(p['low'], 3)} W for the low, "
        f"{fmt(p['nominal'], 3)} W for the nominal and {fmt(p['high'], 3)} W for the high damping. At resonance a "
        "light damper works hardest; away from resonance the heavy one carries the larger force."
    )


# ----------------------------------------------------------------------------- the paper's labels


def labels_figure(st: StabilityStudy):
    """Pareto view: resonant peak against isolation, coloured by step settling time, with the paper's labels."""
    fig, ax = figure(height=4.0)
    zetas = np.geomspace(0.004, 6.0, 400)
    pts = [design_metrics(Oscillator(st.m, z * st.c_crit, st.k), st.isolation_ratio, BAND) for z in zetas]
    x = np.array([p.transmissibility for p in pts])
    y = np.array([p.peak_magnification for p in pts])
    ts = np.array([p.settling_time for p in pts])
    sc = ax.scatter(x, y, c=ts, s=6, cmap="viridis", norm=LogNorm(ts.min(), ts.max()), zorder=2)
    cb = fig.colorbar(sc, ax=ax, pad=0.02)
    cb.set_label(r"2 % step settling time $t_s$ (s)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    markers = {"low": "o", "nominal": "s", "high": "D"}
    for n, c in st.dampings.items():
        d = st.design[n]
        ax.plot(d.transmissibility, d.peak_magnification, markers[n], color=COLORS[n], ms=9, mec="k", zorder=3)
        ax.annotate(
            f"“{LABELS[n]}”\n$c$ = {c:g} N s/m, $t_s$ = {fmt(d.settling_time, 3)} s",
            (d.transmissibility, d.peak_magnification),
            xytext=(10, 4) if n != "high" else (-10, 14),
            ha="left" if n != "high" else "right",
            textcoords="offset points",
            fontsize=8,
        )
    s = st.star
    ax.plot(s.transmissibility, s.peak_magnification, "*", color="#ff7f0e", ms=13, mec="k", zorder=3)
    ax.annotate(
        rf"$\zeta^*$ = {st.zeta_star:.3f} (fastest settling)" + f"\n$c$ = {fmt(st.c_star, 3)} N s/m, $t_s$ = "
        f"{fmt(s.settling_time, 3)} s",
        (s.transmissibility, s.peak_magnification),
        xytext=(-6, -10),
        ha="right",
        va="top",
        textcoords="offset points",
        fontsize=8,
    )
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    ax.xaxis.set_minor_formatter(FuncFormatter(lambda v, _pos: f"{v:g}" if round(v / 10 ** math.floor(math.log10(v)))
                                               in (2, 3, 5) else ""))  # fmt: skip
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    ax.set_xlabel(rf"isolation: transmissibility at {st.isolation_ratio:g} $\omega_n$ (1, lower is better)")
    ax.set_ylabel(r"resonant peak $\max |X|/(F_0/k)$ (1, lower is better)")
    ax.set_ylim(0.5, max(y.max(), 1.5) * 1.6)
    return fig


def _label_rows(st: StabilityStudy) -> list[dict]:
    d = st.design
    rows = []
    lowest_peak = min(d, key=lambda n: d[n].peak_magnification)
    best_iso = min(d, key=lambda n: d[n].transmissibility)
    fastest = min(d, key=lambda n: d[n].settling_time)
    for n, c in st.dampings.items():
        x = d[n]
        if n == "low":
            other = d["nominal"]
            gain = 1.0 - x.transmissibility / other.transmissibility
            supported = n == best_iso
            check = (
                f"best isolation at {st.isolation_ratio:g} ω_n: {'yes' if supported else 'no'}, "
                f"{fmt(100 * gain, 2)} % below the nominal; for it, a "
                f"{fmt(x.peak_magnification / other.peak_magnification, 3)} times higher resonant peak and "
                f"{fmt(x.settling_time / other.settling_time, 3)} times longer settling"
            )
            verdict = "supported only in the isolation sense, at a high price" if supported else "not supported"
        elif n == "high":
            all_stable = all(v.stability == "asymptotically stable" for v in d.values())
            check = (
                f"lowest resonant peak: {'yes' if n == lowest_peak else 'no'}; "
                f"fastest settling of the three: {'yes' if n == fastest else 'no'}; "
                f"transmits {fmt(x.transmissibility / d['low'].transmissibility, 3)} times more at "
                f"{st.isolation_ratio:g} ω_n than the low damping"
            )
            verdict = (
                "not a distinction: all three are asymptotically stable"
                if all_stable
                else "the only stable one of the three"
            )
        else:
            lo, hi = d["low"], d["high"]
            between = all(
                min(getattr(lo, a), getattr(hi, a)) <= getattr(x, a) <= max(getattr(lo, a), getattr(hi, a))
                for a in ("peak_magnification", "transmissibility")
            )
            check = (
                f"between the other two on peak and isolation: {'yes' if between else 'no'}; settling "
                f"{fmt(x.settling_time / st.star.settling_time, 3)} times the optimum at ζ* = {st.zeta_star:.3f}"
            )
            verdict = (
                "a compromise, not an optimum: no stated weighting, and every ζ is Pareto-optimal on these axes"
                if between
                else "not a compromise on these axes"
            )
        rows.append(
            {
                "label": f"“{LABELS[n]}”",
                "c": c,
                "zeta": x.zeta,
                "peak": x.peak_magnification,
                "iso": x.transmissibility,
                "ts": x.settling_time,
                "rms": x.rms_per_sqrt_S0 * math.sqrt(st.S0),
                "check": check,
                "verdict": verdict,
            }
        )
    return rows


def labels_table(st: StabilityStudy) -> Table:
    """The paper's three labels checked against where each damping lands."""
    r = st.isolation_ratio
    return Table(
        _label_rows(st),
        [
            Column("label", "paper's label"),
            Column("c", "c (N s/m)", 3),
            Column("zeta", "ζ", 3),
            Column("peak", "resonant peak", 4),
            Column("iso", f"T at {r:g} ω_n", 3),
            Column("ts", "t_s, 2 % (s)", 3),
            Column("rms", "σ_x, white noise (m)", 3),
            Column("check", "where it lands"),
            Column("verdict", "verdict"),
        ],
        caption="The paper's names for its three dampings, checked on the axes of the trade-off.",
        name="tab-stability-labels",
    )


def labels_sentence(st: StabilityStudy) -> str:
    """One bullet per label, from the same rows as the table."""
    lines = [f"* {r['label']} (c = {fmt(r['c'], 3)} N s/m): {r['verdict']}; {r['check']}." for r in _label_rows(st)]
    return "\n".join(lines)


def checks_table(st: StabilityStudy) -> Table:
    """Rounding-level self-checks, printed as bounds."""
    zetas = np.geomspace(1e-4, 1e2, 200)
    cross = max(abs(float(transmissibility(Oscillator(st.m, z * st.c_crit, st.k), math.sqrt(2) * st.omega_n)) - 1.0)
                for z in zetas)  # fmt: skip
    roots = 0.0
    for _k, _l, c in _pole_cases(st):
        p, ref = poles(st.osc(c)), np.roots([st.m, c, st.k])
        roots = max(roots, float(np.max(np.abs(np.sort_complex(p) - np.sort_complex(ref)))) / st.omega_n)
    env = 0.0
    for g in st.growth.values():
        env = max(env, float(np.max((np.abs(g["x"]) - g["env"]) / np.maximum(g["env"], 1e-300))))
    band = 0.0
    for n, c in st.dampings.items():
        band = max(band, abs(abs(float(step_response(st.osc(c), st.steps[n].settling_time)) - 1.0) - BAND))
    rows = [
        {"check": "|T(√2 ω_n) − 1| over 200 ζ from 1e-4 to 100", "value": _bound(cross, 1e-13)},
        {"check": "poles against numpy.roots, relative to ω_n", "value": _bound(roots, 1e-12)},
        {"check": "|x| above its closed-form envelope, relative", "value": _bound(max(env, 0.0), 1e-12)},
        {"check": "| |y(t_s) − 1| − 0.02 | at the settling times", "value": _bound(band, 1e-12)},
    ]
    return Table(
        rows,
        [Column("check", "self-check"), Column("value", "value")],
        caption="Self-checks at rounding level (printed as bounds).",
        name="tab-stability-checks",
    )


def _bound(value: float, bound: float) -> str:
    return f"< {bound:g}" if value < bound else f"{value:.2e} (above {bound:g})"


def summary_text(st: StabilityStudy) -> str:
    """The chapter's findings as Markdown bullets."""
    d = st.design
    return "\n".join(
        [
            f"* All three of the paper's dampings are asymptotically stable; the low one decays with τ = "
            f"{fmt(st.osc(st.dampings['low']).time_constant, 3)} s. Instability needs c ≤ 0: linear growth at "
            f"exact undamped resonance, exponential growth with c < 0.",
            "* Under a force on the mass more damping lowers the response at every frequency and the random "
            "response too (σ_x ∝ 1/√c): no trade-off there.",
            f"* Under base motion it is a trade-off: all curves cross T = 1 at √2 ω_n; at {st.isolation_ratio:g} ω_n "
            f"the high damping transmits {fmt(d['high'].transmissibility, 3)}, the low one "
            f"{fmt(d['low'].transmissibility, 3)}.",
            f"* The step response settles fastest at ζ* = {st.zeta_star:.4f} (c = {fmt(st.c_star, 3)} N s/m, "
            f"t_s = {fmt(st.star.settling_time, 3)} s); the paper's three need {fmt(d['low'].settling_time, 3)}, "
            f"{fmt(d['nominal'].settling_time, 3)} and {fmt(d['high'].settling_time, 3)} s.",
            "* At resonance the damper force is F0 for every c and the power F0²/(2c): the light damper works hardest.",
        ]
    )


# ----------------------------------------------------------------------------- sliders

#: Range of the damping-ratio slider (log scale), 1.
ZETA_MIN, ZETA_MAX = 0.005, 5.0
#: Positions of the logarithmic slider.
ZETA_STEPS = 600
_counter = itertools.count(1)


def _asset(name: str) -> str:
    return files("vibration.presentation").joinpath("assets", name).read_text(encoding="utf-8")


def stability_panel_html(
    m: float = 1.0, k: float = 20.0, zeta: float = 0.0559, omega: float = 4.47, *, panel_id: str | None = None
) -> str:
    """Self-contained HTML + JavaScript panel: damping-ratio (log) and frequency sliders.

    Moves together the transmissibility curve (operating point at omega), the
    normalised step response with its 2 % band and settling time, and the poles in
    the complex plane. Computed in the browser by ``assets/stability.js``
    (``window.vibrationStability``), which the tests compare with the Python functions.

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
        digest = hashlib.sha1(json.dumps(params, sort_keys=True).encode()).hexdigest()[:8]
        panel_id = f"vst-{digest}-{next(_counter)}"
    e = html.escape
    pos = round(ZETA_STEPS * math.log(zeta / ZETA_MIN) / math.log(ZETA_MAX / ZETA_MIN))
    step = w_max / 1000.0
    return f"""<div class="vst-panel" id="{e(panel_id)}" data-params="{e(json.dumps(params))}">
<style>
{_asset("stability.css")}</style>
<h3 class="vst-title">Damping as a design choice: m = {m:g} kg, k = {k:g} N/m, ω<sub>n</sub> = {wn:.4g} rad/s</h3>
<p class="vst-sub">Move the damping ratio (logarithmic) and the base frequency; computed in your browser from the
closed forms.</p>
<noscript>This panel needs JavaScript to draw its plots.</noscript>
<div class="vst-controls">
<label for="{e(panel_id)}-z">damping ratio ζ (log scale)</label>
<input type="range" class="vst-zeta" id="{e(panel_id)}-z" min="0" max="{ZETA_STEPS}" step="1" value="{pos}">
<output class="vst-zeta-out" for="{e(panel_id)}-z"></output>
<label for="{e(panel_id)}-w">base frequency ω</label>
<input type="range" class="vst-omega" id="{e(panel_id)}-w" min="0" max="{w_max!r}" step="{step!r}" value="{omega!r}">
<output class="vst-omega-out" for="{e(panel_id)}-w"></output>
</div>
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
<script>
{_asset("stability.js")}</script>
<script>window.vibrationStability.mount(document.getElementById({json.dumps(panel_id)}));</script>
</div>
"""


class StabilityExplorer:
    """JupyterLab sliders (ipywidgets) over the same three views; the book shows the HTML panel.

    ``_repr_mimebundle_`` returns the widget view for JupyterLab and, for renderers
    without a kernel, :func:`stability_panel_html` at the current slider values.
    """

    def __init__(self, m: float = 1.0, k: float = 20.0, zeta: float = 0.0559, omega: float = 4.47) -> None:
        import ipywidgets as widgets

        stability_panel_html(m, k, zeta, omega, panel_id="check")  # validates the inputs
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
        for s in (self.zeta_slider, self.omega_slider):
            s.observe(lambda _change: self.update(), names="value")
        self.update()

    def values(self) -> dict:
        """Current numbers: c (N s/m), T at omega, poles (1/s), step metrics (s, fraction)."""
        zeta, w = float(self.zeta_slider.value), float(self.omega_slider.value)
        osc = Oscillator(self.m, zeta * 2 * math.sqrt(self.k * self.m), self.k)
        s = step_metrics(osc, BAND)
        return {"osc": osc, "T": float(transmissibility(osc, w)), "poles": poles(osc), "step": s, "omega": w}

    def update(self) -> None:
        v = self.values()
        fig = _explorer_figure(v, self.m, self.k)
        buf = io.BytesIO()
        fig.savefig(buf, format="png")
        self.image.value = buf.getvalue()
        s: StepMetrics = v["step"]
        self.readout.value = (
            f"c = {fmt(v['osc'].c, 4)} N s/m; T(ω) = {fmt(v['T'], 4)}; poles {_pole_text(v['poles'])} 1/s; "
            f"overshoot {fmt(100 * s.overshoot, 3)} %; rise {fmt(s.rise_time, 3)} s; "
            f"settling {fmt(s.settling_time, 3)} s"
        )

    def _repr_mimebundle_(self, **kwargs):
        data = self.widget._repr_mimebundle_(**kwargs) or {}
        data["text/html"] = stability_panel_html(
            self.m, self.k, float(self.zeta_slider.value), float(self.omega_slider.value)
        )
        data["image/png"] = base64.b64encode(self.image.value).decode("ascii")
        data["text/plain"] = (
            f"StabilityExplorer(m={self.m!r} kg, k={self.k!r} N/m, zeta={self.zeta_slider.value:.4g}, "
            f"omega={self.omega_slider.value:.4g} rad/s)"
        )
        return data


def _explorer_figure(v: dict, m: float, k: float):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(9.0, 2.9), dpi=90, layout="constrained")
    FigureCanvasAgg(fig)
    at, ast, ap = fig.subplots(1, 3, width_ratios=(1.2, 1.2, 0.8))
    osc, s = v["osc"], v["step"]
    wn = osc.natural_frequency
    w = np.linspace(0.0, 4 * wn, 1201)
    at.semilogy(w, transmissibility(osc, w), color="#1f77b4")
    at.plot([v["omega"]], [v["T"]], "o", color="#d62728")
    at.axvline(math.sqrt(2) * wn, color="0.4", ls="--", lw=0.8)
    at.set_xlabel("ω (rad/s)")
    at.set_ylabel("|X/Y|")
    t = np.linspace(0.0, max(12 * 2 * math.pi / wn, 1.2 * s.settling_time), 2001)
    ast.axhspan(1 - BAND, 1 + BAND, color="0.85")
    ast.plot(t, step_response(osc, t), color="#1f77b4")
    ast.axvline(s.settling_time, color="0.4", ls=":")
    ast.set_xlabel("t (s)")
    ast.set_ylabel("k x / F")
    p = v["poles"]
    th = np.linspace(0, 2 * math.pi, 200)
    ap.plot(wn * np.cos(th), wn * np.sin(th), color="0.8", lw=0.8)
    ap.plot(p.real, p.imag, "x", color="#d62728", ms=8, mew=2)
    ap.axvline(0.0, color="0.3", lw=0.8)
    ap.set_xlabel("Re s (1/s)")
    ap.set_ylabel("Im s (1/s)")
    ap.set_aspect("equal", adjustable="datalim")
    return fig


def stability_explorer(m: float = 1.0, k: float = 20.0, c: float = 0.5, omega: float = 4.47):
    """The chapter's sliders: :class:`StabilityExplorer` (ipywidgets in JupyterLab, HTML panel in the book).

    Starts at damping c (N s/m, > 0) and base frequency omega (rad/s, >= 0), moved into the
    sliders' ranges (damping ratio 0.005 to 5, frequency 0 to 4 omega_n) when outside.
    """
    osc = Oscillator(m, check_real("c", c, low=0.0, low_open=True, unit="N s/m"), k)
    omega = check_real("omega", omega, low=0.0, unit="rad/s")
    zeta = min(max(osc.damping_ratio, ZETA_MIN), ZETA_MAX)
    return StabilityExplorer(osc.m, osc.k, zeta, min(omega, 4.0 * osc.natural_frequency))
