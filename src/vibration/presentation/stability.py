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

import numpy as np
from matplotlib.colors import LogNorm
from matplotlib.lines import Line2D
from matplotlib.ticker import FuncFormatter

from ..physics.exact import exact_response, steady_state
from ..physics.model import Oscillator, SineForce, check_int, check_real
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
    white_noise_force_optimum,
    white_noise_force_variance,
    white_noise_monte_carlo,
    white_noise_variance,
    white_noise_velocity_variance,
)
from .static_page import _asset
from .style import figure, place_legend
from .tables import Column, Missing, Table, bound, fmt

__all__ = [
    "StabilityExplorer",
    "StabilityStudy",
    "checks_table",
    "cost_figure",
    "cost_sentence",
    "cost_table",
    "explorer_sentence",
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
    dampings: dict  # "low"/"nominal"/"high" -> c, N s/m (any sign, any order)
    c_unstable: float  # damping of the flutter model, N s/m (<= 0)
    t_growth: float  # window of the growth comparison, s
    isolation_ratio: float  # omega / omega_n at which isolation is judged, 1
    S0: float  # two-sided force spectral density, N^2 s/rad
    n_paths: int  # Monte Carlo paths
    seed: int  # Monte Carlo seed
    design: dict = field(default_factory=dict)  # name -> DesignMetrics
    steps: dict = field(default_factory=dict)  # name -> StepMetrics (only c > 0)
    monte_carlo: dict = field(default_factory=dict)  # name -> MonteCarlo (only c > 0)
    zeta_star: float = math.nan  # settling-optimal damping ratio, 1
    star: DesignMetrics | None = None  # design metrics at zeta_star
    growth: dict = field(default_factory=dict)  # case -> dict(t, x, env, osc, force, capped)
    bounded_source: str = ""  # where the damping of the bounded growth case comes from

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

    def by_value(self) -> list[tuple[str, float]]:
        """The paper's three dampings as (name, c), sorted by the value of c (ties in paper order)."""
        order = list(self.dampings)
        return sorted(self.dampings.items(), key=lambda p: (p[1], order.index(p[0])))

    def positive(self) -> list[tuple[str, float]]:
        """The asymptotically stable ones (c > 0), by value."""
        return [(n, c) for n, c in self.by_value() if c > 0.0]


#: Reasons shown in tables (as "—" with a footnote) and used in sentences.
WHY_UNDAMPED_PEAK = Missing("unbounded: with c = 0 a force at ω_n grows the response like t")
WHY_NO_STEADY = Missing("no steady state: with c < 0 every free motion grows")
WHY_NO_SETTLING_0 = Missing("never settles: with c = 0 the step response oscillates for ever")
WHY_NO_VARIANCE = Missing("no stationary variance: with c ≤ 0 it grows without bound")


def _paper_zeta() -> float:
    """Damping ratio of the paper's low damping (0.1 N s/m, 1 kg, 20 N/m), the fallback of the bounded case."""
    return 0.1 / (2.0 * math.sqrt(20.0))


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
        The paper's three dampings, N s/m: any finite values, any sign, any order
        (quantities that do not exist for ``c <= 0`` are reported as missing).
    c_unstable : float
        Damping of the flutter model, N s/m (<= 0; 0 gives no exponential growth, which
        the sentences then say). Its growth case is drawn up to a growth factor ``e^50``.
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
    >>> s = stability_study(c_low=-0.1, c_high=0.3, n_paths=20, t_growth=20.0)
    >>> [n for n, _c in s.by_value()], s.design["low"].stability, "low" in s.monte_carlo
    (['low', 'high', 'nominal'], 'unstable', False)
    """
    m = check_real("m", m, low=0.0, low_open=True, unit="kg")
    k = check_real("k", k, low=0.0, low_open=True, unit="N/m")
    F0 = check_real("F0", F0, low=0.0, low_open=True, unit="N")
    omega_res = check_real("omega_res", omega_res, low=0.0, low_open=True, unit="rad/s")
    dampings = {}
    for name, value in (("c_low", c_low), ("c_nominal", c_nominal), ("c_high", c_high)):
        dampings[name[2:]] = check_real(name, value, unit="N s/m") + 0.0  # -0.0 is 0
        Oscillator(m, dampings[name[2:]], k)  # representable rates, or a ParameterError naming c
    c_unstable = check_real("c_unstable", c_unstable, high=0.0, unit="N s/m") + 0.0
    Oscillator(m, c_unstable, k)
    t_growth = check_real("t_growth", t_growth, low=0.0, low_open=True, high=2000.0, unit="s")
    isolation_ratio = check_real("isolation_ratio", isolation_ratio, low=math.sqrt(2.0), low_open=True, high=100.0)
    S0 = check_real("S0", S0, low=0.0, low_open=True, unit="N^2 s/rad")
    n_paths = check_int("n_paths", n_paths, low=2, high=5000)
    seed = check_int("seed", seed, low=0, high=2**31 - 1)
    st = StabilityStudy(m, k, F0, omega_res, dampings, c_unstable, t_growth, isolation_ratio, S0, n_paths, seed)
    for i, (name, c) in enumerate(dampings.items()):
        osc = st.osc(c)
        st.design[name] = design_metrics(osc, isolation_ratio, BAND)
        if c > 0.0:
            st.steps[name] = step_metrics(osc, BAND)
            st.monte_carlo[name] = white_noise_monte_carlo(osc, S0, n_paths=n_paths, seed=seed + i)
    st.zeta_star = settling_optimal_zeta(BAND)
    st.star = design_metrics(st.osc(st.c_star), isolation_ratio, BAND)
    # growth: bounded (the lightest positive damping with oscillating poles, at omega_res),
    # linear (c = 0 at omega_n exactly), exponential (c_unstable at omega_res)
    candidates = [(n, c) for n, c in st.positive() if c < st.c_crit]
    if candidates:
        name, c_b = candidates[0]
        st.bounded_source = f"the lightest positive damping of this run ({name}, c = {fmt(c_b, 4)} N s/m)"
    else:
        c_b = _paper_zeta() * st.c_crit
        st.bounded_source = (
            f"c = {fmt(c_b, 4)} N s/m (none of this run's dampings is positive with oscillating poles; "
            f"this is the paper's damping ratio ζ = {_paper_zeta():.4f})"
        )
    rate = stability_class(st.osc(c_unstable)).spectral_abscissa
    t_exp = t_growth if rate <= 0.0 else min(t_growth, MAX_GROWTH / rate)
    for case, c, w, t_end in (
        ("bounded", c_b, omega_res, t_growth),
        ("linear", 0.0, st.omega_n, t_growth),
        ("exponential", c_unstable, omega_res, t_exp),
    ):
        n = int(min(200_001, max(20_001, 40 * t_end * max(st.omega_n, w))))
        t = np.linspace(0.0, t_end, n)
        osc, force = st.osc(c), SineForce(F0, w)
        st.growth[case] = {
            "osc": osc,
            "force": force,
            "t": t,
            "x": exact_response(osc, force, t).x,
            "env": growth_envelope(osc, force, t),
            "capped": t_end < t_growth,
        }
    return st


#: Largest growth exponent drawn for the exponential case (e^50 ~ 5e21).
MAX_GROWTH = 50.0


# ----------------------------------------------------------------------------- stability: poles


def _pole_cases(st: StabilityStudy) -> list[tuple[str, str, float]]:
    rows = [(name, f"{name} damping, “{LABELS[name]}”", c) for name, c in st.by_value()]
    rows.append(("undamped", "undamped", 0.0))
    rows.append(("unstable", "flutter model", st.c_unstable))
    return rows


def poles_table(st: StabilityStudy) -> Table:
    """Poles and stability of the paper's dampings (sorted by value), c = 0 and the flutter model."""
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


def _list(items: list[str]) -> str:
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def stability_sentence(st: StabilityStudy) -> str:
    """Which of the run's dampings are stable, the paper's claim about the low one, and the flutter model."""
    groups: dict[str, list[str]] = {}
    for _n, c in st.by_value():
        groups.setdefault(stability_class(st.osc(c)).verdict, []).append(_c_text(c))
    if list(groups) == ["asymptotically stable"]:
        head = (
            f"All three of this run's dampings ({_list(groups['asymptotically stable'])}) put both poles in the open "
            "left half-plane: each is asymptotically stable and bounded-input bounded-output stable."
        )
    else:
        parts = []
        for verdict, why in (
            ("asymptotically stable", "both poles in the open left half-plane"),
            (
                "marginally stable",
                "poles on the imaginary axis: bounded free motion, but a force at ω_n grows the "
                "response without bound, so not bounded-input bounded-output stable",
            ),  # fmt: skip
            ("unstable", "a pole in the right half-plane: the free motion itself grows"),
        ):
            if verdict in groups:
                cs = groups[verdict]
                parts.append(f"{_list(cs)} {'is' if len(cs) == 1 else 'are'} {verdict} ({why})")
        head = "Of this run's dampings, " + "; ".join(parts) + "."
    low = st.osc(st.dampings["low"])
    s_low = stability_class(low)
    if s_low.asymptotic:
        claim = (
            f"The low damping ({_c_text(low.c)}) that the paper calls unstable is asymptotically stable: its slowest "
            f"free mode decays as exp(−t/τ) with τ = {fmt(low.time_constant, 3)} s, and its steady response is "
            f"bounded by {fmt(st.design['low'].peak_magnification * st.F0 / st.k, 3)} m at any forcing frequency."
        )
    else:
        claim = f"The low damping of this run ({_c_text(low.c)}) is {s_low.verdict}, as the paper says of its own."
    s_u = stability_class(st.osc(st.c_unstable))
    if st.c_unstable < 0.0:
        tail = (
            f" The flutter model ({_c_text(st.c_unstable)}) has its largest pole at Re s = "
            f"{fmt(s_u.spectral_abscissa, 3)} 1/s: its free motion grows as exp({fmt(s_u.spectral_abscissa, 3)} t/s)."
        )
    else:
        tail = " The flutter model is set to c = 0 here: it is the undamped case, marginally stable, with no growth."
    return (
        f"{head} {claim}{tail} With a positive stiffness k, instability needs c ≤ 0 "
        "(with k ≤ 0 the equilibrium is unstable whatever c)."
    )


def pole_figure(st: StabilityStudy):
    """Poles in the complex plane: the whole locus over c, and a zoom near the imaginary axis."""
    fig, (ax, az) = figure(1, 2, height=3.9, gridspec_kw={"width_ratios": (1.25, 1.0)})
    wn = st.omega_n
    cases = _pole_cases(st)
    c_lo = min(min(c for _k, _l, c in cases) * 1.5, -0.1 * st.c_crit)
    c_max = max(1.3 * max(st.dampings.values()), 2.2 * st.c_crit)
    cs = np.concatenate([np.linspace(c_lo, 0.0, 400), np.linspace(0.0, st.c_crit, 400)[1:]])
    cs = np.concatenate([cs, np.linspace(st.c_crit, c_max, 600)[1:]])
    locus = np.array([poles(st.osc(c)) for c in cs])
    for a in (ax, az):
        a.axvspan(-1e300, 0.0, color="#2ca02c", alpha=0.06, lw=0)
        a.axvline(0.0, color="0.3", lw=0.8)
        a.plot(locus[:, 0].real, locus[:, 0].imag, color="0.75", lw=1.0, zorder=1)
        a.plot(locus[:, 1].real, locus[:, 1].imag, color="0.75", lw=1.0, zorder=1)
    handles = [Line2D([], [], color="0.75", lw=1.0, label=r"locus as $c$ varies")]
    markers = {"low": "o", "nominal": "s", "high": "D", "undamped": "X", "unstable": "P"}
    for key, label, c in cases:
        p = poles(st.osc(c))
        for a in (ax, az):
            a.plot(p.real, p.imag, ls="none", marker=markers[key], ms=7, color=COLORS[key], zorder=3)
        short = label.split(",")[0]
        handles.append(
            Line2D([], [], ls="none", marker=markers[key], ms=7, color=COLORS[key], label=f"{short}: $c$ = {c:g} N s/m")
        )
    marked = np.concatenate([poles(st.osc(c)) for _k, _l, c in cases])
    lo = min(float(marked.real.min()), -0.2 * wn)
    hi = max(float(marked.real.max()), 0.0)
    pad = 0.08 * (hi - lo)
    ax.set_xlim(lo - pad, hi + pad)
    ax.set_ylim(-1.4 * wn, 1.4 * wn)
    near = [poles(st.osc(c))[0] for _k, _l, c in cases if abs(c) < st.c_crit / 2]
    re = [p.real for p in near] + [0.0]
    im = [p.imag for p in near]
    span_re = max(max(re) - min(re), 1e-3 * wn)
    span_im = max(max(im) - min(im), 1e-3 * wn)
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


def _growth_title(st: StabilityStudy, case: str) -> str:
    g = st.growth[case]
    c = g["osc"].c
    if case == "bounded":
        return "transient approaching a bounded steady state"
    if case == "linear":
        return "linear growth at exact undamped resonance"
    if c == 0.0:
        return "flutter model set to c = 0: no negative damping, no exponential growth"
    return "exponential growth with negative damping (flutter's linear model)"


def growth_figure(st: StabilityStudy):
    """The three ways a response grows, each with its closed-form envelope."""
    same = len({float(g["t"][-1]) for g in st.growth.values()}) == 1
    fig, axes = figure(3, 1, height=6.4, sharex=same)
    colors = {"bounded": COLORS["low"], "linear": COLORS["undamped"], "exponential": COLORS["unstable"]}
    for ax, (case, g) in zip(axes, st.growth.items(), strict=True):
        osc, force = g["osc"], g["force"]
        ax.plot(g["t"], g["x"], color=colors[case], lw=0.5, label="exact response $x(t)$")
        ax.plot(g["t"], g["env"], color="k", lw=1.1, ls="--", label="closed-form envelope (bound)")
        ax.plot(g["t"], -g["env"], color="k", lw=1.1, ls="--")
        ax.set_title(
            f"{_growth_title(st, case)}: $c$ = {osc.c:g} N s/m, $\\omega$ = {force.omega:.4g} rad/s",
            fontsize=9,
            loc="left",
        )
        ax.set_ylabel(r"$x$ (m)")
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4), useMathText=True)
        if not same or ax is axes[-1]:
            ax.set_xlabel(r"time $t$ (s)")
    axes[0].legend(loc="lower right", bbox_to_anchor=(1.0, 1.18), ncols=2, frameon=False)
    return fig


def growth_table(st: StabilityStudy) -> Table:
    """Growth law, rate and the size reached at the end of the window, per case."""
    rows = []
    for case, g in st.growth.items():
        osc, force = g["osc"], g["force"]
        none = Missing("not this growth law")
        rate = stability_class(osc).spectral_abscissa
        row = {
            "case": case if not (case == "exponential" and osc.c == 0.0) else "none (flutter model at c = 0)",
            "c": osc.c,
            "omega": force.omega,
            "t_end": float(g["t"][-1]),
            "steady": none,
            "slope": none,
            "rate": none,
            "peak": float(np.max(np.abs(g["x"]))),
            "env_end": float(g["env"][-1]),
        }
        if case == "bounded":
            row["steady"] = steady_state(osc, force).amplitude
        elif case == "linear":
            row["slope"] = st.F0 / (2.0 * st.m * st.omega_n)
        elif osc.c < 0.0:
            row["rate"] = rate
        rows.append(row)
    return Table(
        rows,
        [
            Column("case", "growth"),
            Column("c", "c (N s/m)", 3),
            Column("omega", "ω (rad/s)", 4),
            Column("t_end", "window (s)", 4),
            Column("steady", "steady amplitude (m)", 4),
            Column("slope", "F0/(2mω_n) (m/s)", 4),
            Column("rate", "max Re s (1/s)", 3),
            Column("peak", "max |x| in window (m)", 4),
            Column("env_end", "envelope at window end (m)", 4),
        ],
        caption=f"Three ways a response from rest grows over up to {st.t_growth:g} s (exact closed forms).",
        name="tab-stability-growth",
    )


def growth_sentence(st: StabilityStudy) -> str:
    """How the three cases compare at the end of their windows."""
    b, lin, ex = (st.growth[c] for c in ("bounded", "linear", "exponential"))
    ob = b["osc"]
    amp = steady_state(ob, b["force"]).amplitude
    text = (
        f"Over {st.t_growth:g} s, {st.bounded_source} forced at {st.omega_res:g} rad/s reaches at most "
        f"{fmt(float(np.max(np.abs(b['x']))), 3)} m and its envelope closes in on the steady amplitude "
        f"{fmt(amp, 3)} m (beating at |ω_d − ω| = {fmt(abs(ob.damped_natural_frequency - st.omega_res), 2)} rad/s "
        f"while it does); exact undamped resonance reaches {fmt(float(np.max(np.abs(lin['x']))), 3)} m, growing by "
        f"F0/(2mω_n) = {fmt(st.F0 / (2 * st.m * st.omega_n), 3)} m each second for ever; "
    )
    c = ex["osc"].c
    if c < 0.0:
        rate = stability_class(ex["osc"]).spectral_abscissa
        window = (
            f"over {fmt(float(ex['t'][-1]), 3)} s (drawn until the growth factor reaches e^{MAX_GROWTH:g})"
            if ex["capped"]
            else f"over {st.t_growth:g} s"
        )
        text += (
            f"negative damping c = {c:g} N s/m reaches {fmt(float(np.max(np.abs(ex['x']))), 3)} m {window} and "
            f"multiplies by e every {fmt(1.0 / rate, 3)} s. Only the last two are instability."
        )
    else:
        text += (
            f"the flutter model is set to c = 0, so its case is undamped forcing at {st.omega_res:g} rad/s, which "
            f"stays below {fmt(float(ex['env'].max()), 3)} m: no exponential growth. Only exact undamped resonance "
            "grows without bound here."
        )
    return text


# ----------------------------------------------------------------------------- transmissibility


def _family(st: StabilityStudy) -> list[tuple[str, float]]:
    """(label, c) of the transmissibility family: the run's positive dampings, zeta = 0.2, zeta*, 1; by value."""
    out = [(f"{name}: $c$ = {c:g} N s/m", c) for name, c in st.positive()]
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
    if st.isolation_ratio <= 4.0:
        ax.text(st.isolation_ratio * wn, 1.5e-2, rf" $\omega$ = {st.isolation_ratio:g} $\omega_n$", fontsize=8.5)
    ax.set_ylim(1e-2, 200.0)
    ax.set_xlim(0.0, 4.0 * wn)
    ax.set_xlabel(r"base frequency $\omega$ (rad/s)")
    ax.set_ylabel(r"transmissibility $|X/Y|$ (1)")
    place_legend(ax, outside=True)
    return fig


def transmissibility_table(st: StabilityStudy) -> Table:
    """Transmissibility at resonance, at sqrt(2) omega_n and at the isolation ratio; its peak (c <= 0 included)."""
    wn = st.omega_n
    rows = []
    family = _family(st) + [(f"{n}: c = {c:g} N s/m", c) for n, c in st.by_value() if c <= 0.0]
    for label, c in sorted(family, key=lambda p: p[1]):
        osc = st.osc(c)
        row = {
            "case": label.replace("$", "").replace("\\zeta", "ζ").replace("^*", "*"),
            "zeta": osc.damping_ratio,
        }
        if c < 0.0:
            row.update({key: WHY_NO_STEADY for key in ("t_res", "t_iso", "t_r", "wp", "tp")})
        else:
            wp, tp = peak_transmissibility(osc)
            t_res = float(transmissibility(osc, wn))
            row.update(
                {
                    "t_res": t_res if math.isfinite(t_res) else WHY_UNDAMPED_PEAK,
                    "t_iso": float(transmissibility(osc, math.sqrt(2.0) * wn)),
                    "t_r": float(transmissibility(osc, st.isolation_ratio * wn)),
                    "wp": wp,
                    "tp": tp if math.isfinite(tp) else WHY_UNDAMPED_PEAK,
                }
            )
        rows.append(row)
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
        caption="Base-excitation transmissibility |X/Y| (steady state) of the damping family, by damping.",
        name="tab-stability-transmissibility",
    )


def transmissibility_sentence(st: StabilityStudy) -> str:
    """The isolation trade-off between the lightest and heaviest positive dampings of the run."""
    r = st.isolation_ratio
    pos = st.positive()
    if len({c for _n, c in pos}) >= 2:
        (nl, cl), (nh, ch) = pos[0], pos[-1]
        light = f"the lightest positive damping of this run ({nl}, {_c_text(cl)})"
        heavy = f"the heaviest ({nh}, {_c_text(ch)})"
    else:
        cl, ch = 0.2 * st.c_crit, st.c_crit
        light, heavy = f"ζ = 0.2 ({_c_text(cl)})", f"ζ = 1 ({_c_text(ch)})"
    lo, hi = st.osc(cl), st.osc(ch)
    t_lo_res, t_hi_res = float(transmissibility(lo, st.omega_n)), float(transmissibility(hi, st.omega_n))
    t_lo, t_hi = float(transmissibility(lo, r * st.omega_n)), float(transmissibility(hi, r * st.omega_n))
    text = (
        f"Under base motion the trade-off is real. At resonance {heavy} transmits {fmt(t_hi_res, 3)} of the base "
        f"motion against {fmt(t_lo_res, 3)} for {light}; at ω = {r:g} ω_n it transmits {fmt(t_hi, 3)} against "
        f"{fmt(t_lo, 3)}, {fmt(t_hi / t_lo, 3)} times as much. Every curve passes "
        f"through T = 1 at √2 ω_n = {fmt(isolation_frequency(st.osc(1.0)), 4)} rad/s; above it more damping "
        "transmits more."
    )
    if len({c for _n, c in pos}) < 2:
        text += " Fewer than two of this run's dampings are positive, so the comparison uses ζ = 0.2 and ζ = 1."
    bad = [n for n, c in st.by_value() if c < 0.0]
    if bad:
        text += f" Negative damping ({_list([_c_text(st.dampings[n]) for n in bad])}) has no steady state to transmit."
    return text


# ----------------------------------------------------------------------------- step response


def step_figure(st: StabilityStudy):
    """Normalised step responses (c >= 0), and settling and rise times against the damping ratio."""
    fig, (ax, am) = figure(1, 2, height=3.6, gridspec_kw={"width_ratios": (1.2, 1.0)})
    wn = st.omega_n
    t_end = 12.0 * 2 * math.pi / wn
    t = np.linspace(0.0, t_end, 4001)
    ax.axhspan(1 - BAND, 1 + BAND, color="0.85", lw=0, label="±2 % band")
    cases = [(f"{n}: $c$ = {c:g} N s/m", c, COLORS[n]) for n, c in st.by_value() if c >= 0.0]
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
    for n, s in st.steps.items():
        am.plot([s.zeta], [s.settling_time], "o", color=COLORS[n], ms=6)
    am.plot([st.zeta_star], [st.star.settling_time], "*", color="#ff7f0e", ms=11, label=r"$\zeta^*$ (fastest)")
    am.set_xlabel(r"damping ratio $\zeta$ (1)")
    am.set_ylabel(r"time (s)")
    am.plot([], [], "o", color="0.4", ms=6, label="the run's dampings (c > 0)")
    am.legend(loc="lower left", bbox_to_anchor=(0.0, 1.02), ncols=2, frameon=False, fontsize=7.5)
    return fig


def _step_row(st: StabilityStudy, label: str, c: float, s: StepMetrics | None) -> dict:
    row = {"case": label, "c": c, "zeta": st.osc(c).damping_ratio}
    if s is not None:
        row.update(
            {
                "os": 100.0 * s.overshoot,
                "tp": s.peak_time if math.isfinite(s.peak_time) else NO_PEAK,
                "tr": s.rise_time,
                "ts": s.settling_time,
                "wts": st.omega_n * s.settling_time,
            }
        )
    elif c == 0.0:  # y = 1 - cos(omega_n t): peak 2 at pi/omega_n, crossings of 0.1 and 0.9 in closed form
        wn = st.omega_n
        row.update(
            {
                "os": 100.0,
                "tp": math.pi / wn,
                "tr": (math.acos(0.1) - math.acos(0.9)) / wn,
                "ts": WHY_NO_SETTLING_0,
                "wts": WHY_NO_SETTLING_0,
            }
        )
    else:
        why = Missing("grows without bound: c < 0")
        row.update({key: why for key in ("os", "tp", "tr", "ts", "wts")})
    return row


def step_table(st: StabilityStudy) -> Table:
    """Step metrics of the run's three dampings (by value) and of the settling-optimal one."""
    rows = [_step_row(st, f"{n} (“{LABELS[n]}”)", c, st.steps.get(n)) for n, c in st.by_value()]
    rows.append(_step_row(st, "settling-optimal ζ*", st.c_star, step_metrics(st.osc(st.c_star), BAND)))
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
    """The settling-optimal damping and where the run's three land, by value."""
    text = (
        f"The 2 % settling time is shortest at ζ* = {st.zeta_star:.4f} (c = {fmt(st.c_star, 4)} N s/m here), where "
        f"the overshoot equals the band: t_s = {fmt(st.star.settling_time, 3)} s."
    )
    parts = []
    for n, c in st.by_value():
        if n in st.steps:
            s = st.steps[n]
            over = f"overshoots by {fmt(100 * s.overshoot, 3)} %" if s.overshoot > 0.0 else "does not overshoot"
            parts.append(
                f"{n} ({_c_text(c)}) {over} and settles in {fmt(s.settling_time, 3)} s, "
                f"{fmt(s.settling_time / st.star.settling_time, 3)} times the optimum"
            )
        elif c == 0.0:
            parts.append(f"{n} ({_c_text(c)}) overshoots by 100 % and never settles: it oscillates for ever")
        else:
            parts.append(f"{n} ({_c_text(c)}) never settles: its step response grows without bound")
    text += " By damping: " + "; ".join(parts) + "."
    if st.steps:
        fastest = min(st.steps, key=lambda n: st.steps[n].settling_time)
        text += f" Of this run's dampings the {fastest} one settles first."
    else:
        text += " None of this run's dampings settles."
    return text


# ----------------------------------------------------------------------------- random load


def random_table(st: StabilityStudy) -> Table:
    """Stationary variance under white-noise force: closed form against Monte Carlo (c > 0), by damping."""
    rows = []
    for n, c in st.by_value():
        row = {"case": n, "c": c}
        if n in st.monte_carlo:
            osc, mc = st.osc(c), st.monte_carlo[n]
            exact = white_noise_variance(osc, st.S0)
            exact_v = white_noise_velocity_variance(osc, st.S0)
            row.update(
                {
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
        else:
            row.update({key: WHY_NO_VARIANCE for key in ("exact", "mc", "se", "z", "rms", "vexact", "vmc", "vz")})
        rows.append(row)
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
        f"(two-sided); Monte Carlo with {st.n_paths} paths per damping, independent draws for each damping "
        f"(seeds {st.seed}, {st.seed} + 1, ... in the order of the table), so the deviations are independent.",
        name="tab-stability-random",
    )


def random_sentence(st: StabilityStudy) -> str:
    """What damping does to the random response, and whether the simulation agrees."""
    pos = [(n, c) for n, c in st.by_value() if n in st.monte_carlo]
    bad = [(n, c) for n, c in st.by_value() if n not in st.monte_carlo]
    text = "Under a white-noise force the stationary variance is π S0/(k c): the rms displacement falls as 1/√c."
    if pos:
        rms = [f"{fmt(math.sqrt(white_noise_variance(st.osc(c), st.S0)), 3)} m ({n}, {_c_text(c)})" for n, c in pos]
        largest = pos[0][0]
        zs = [
            abs(st.monte_carlo[n].variance - white_noise_variance(st.osc(c), st.S0)) / st.monte_carlo[n].standard_error
            for n, c in pos
        ]
        agree = "agrees with" if max(zs) < 4.0 else "does not agree with"
        text += (
            f" By damping: {_list(rms)}; the largest is the {largest} damping's. For the displacement, more "
            "damping helps at every level of the load; for the force passed to the support it does not (below). "
            f"The simulation {agree} the closed form (largest deviation {fmt(max(zs), 2)} "
            "standard errors)."
        )
    if bad:
        text += (
            f" With {_list([_c_text(c) for _n, c in bad])} there is no stationary response: the variance grows "
            "without bound, like t for c = 0 and exponentially for c < 0."
        )
    return text


def random_force_rows(st: StabilityStudy) -> list[dict]:
    c_opt, v_opt = white_noise_force_optimum(st.m, st.k, st.S0)
    rows = []
    for n, c in st.by_value():
        if c > 0.0:
            v = white_noise_force_variance(st.osc(c), st.S0)
            rows.append({"case": n, "c": c, "var": v, "ratio": v / v_opt})
        else:
            rows.append({"case": n, "c": c, "var": WHY_NO_VARIANCE, "ratio": WHY_NO_VARIANCE})
    rows.append({"case": "least force variance, c = √(km)", "c": c_opt, "var": v_opt, "ratio": 1.0})
    return rows


def random_force_table(st: StabilityStudy) -> Table:
    """Variance of the force passed to the support under white noise, by damping, and its optimum."""
    return Table(
        random_force_rows(st),
        [
            Column("case", "damping"),
            Column("c", "c (N s/m)", 3),
            Column("var", "var F_T (N²)", 3),
            Column("ratio", "over the least", 3),
        ],
        caption=(
            f"Force passed to the support, F_T = k x + c v, under a white-noise force of S0 = {st.S0:g} N² s/rad: "
            "its stationary variance πS0(k/c + c/m) (x and v are uncorrelated in the stationary state), and the "
            "least over all dampings, 2πS0√(k/m) at c = √(km)."
        ),
        name="tab-stability-random-force",
    )


def force_tradeoff_text(st: StabilityStudy) -> str:
    c_opt, v_opt = white_noise_force_optimum(st.m, st.k, st.S0)
    pos = st.positive()
    if not pos:
        return (
            f"The force passed to the support under random load is least at c = √(km) = {fmt(c_opt, 3)} N s/m "
            f"({fmt(v_opt, 3)} N²)."
        )
    vals = [f"{fmt(white_noise_force_variance(st.osc(c), st.S0), 3)} N² ({n}, {_c_text(c)})" for n, c in pos]
    return (
        "The force passed to the support is a trade-off even under the paper's own load: its variance "
        f"πS0(k/c + c/m) is least at c = √(km) = {fmt(c_opt, 3)} N s/m ({fmt(v_opt, 3)} N² at S0 = {st.S0:g} "
        f"N² s/rad), against {_list(vals)}."
    )


# ----------------------------------------------------------------------------- cost


def cost_figure(st: StabilityStudy):
    """Damper force amplitude and mean dissipated power against forcing frequency (c > 0)."""
    fig, (af, ap) = figure(1, 2, height=3.3)
    wn = st.omega_n
    w = np.unique(np.concatenate([np.linspace(0.01 * wn, 3.0 * wn, 2001), wn * (1 + np.linspace(-0.03, 0.03, 601))]))
    for n, c in st.positive():
        d = damper_load(st.osc(c), st.F0, w)
        af.semilogy(w, d.force_amplitude, color=COLORS[n], label=f"{n}: $c$ = {c:g} N s/m")
        ap.semilogy(w, d.mean_power, color=COLORS[n], label=f"{n}: $c$ = {c:g} N s/m")
    for a in (af, ap):
        a.axvline(wn, color="0.4", lw=0.7, ls="--")
        a.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
    af.axhline(st.F0, color="0.4", lw=0.7, ls=":")
    af.set_ylabel(r"damper force amplitude $c\,\omega |X|$ (N)")
    ap.set_ylabel(r"mean dissipated power (W)")
    if not st.positive():
        for a in (af, ap):
            a.text(0.5, 0.5, "no positive damping in this run", transform=a.transAxes, ha="center")
    else:
        fig.legend(*af.get_legend_handles_labels(), loc="outside upper center", ncols=3, frameon=False)
    return fig


def cost_table(st: StabilityStudy) -> Table:
    """Damper force amplitude and mean power at the paper's forcing frequency and at omega_n, by damping."""
    rows = []
    for n, c in st.by_value():
        osc = st.osc(c)
        for label, w in ((f"{st.omega_res:g} rad/s (paper)", st.omega_res), ("ω_n", st.omega_n)):
            row = {"case": n, "c": c, "w": label}
            if c < 0.0:
                row.update({"x": WHY_NO_STEADY, "f": WHY_NO_STEADY, "p": WHY_NO_STEADY})
            elif c == 0.0 and w == st.omega_n:  # undamped resonance: no damper, no steady amplitude
                row.update({"x": WHY_UNDAMPED_PEAK, "f": 0.0, "p": 0.0})
            else:
                d = damper_load(osc, st.F0, w)
                x = float(d.amplitude)
                row.update(
                    {
                        "x": x if math.isfinite(x) else WHY_UNDAMPED_PEAK,
                        "f": float(d.force_amplitude),
                        "p": float(d.mean_power),
                    }
                )
            rows.append(row)
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
    pos = st.positive()
    text = ""
    if pos:
        p = {n: float(damper_load(st.osc(c), st.F0, st.omega_n).mean_power) for n, c in pos}
        hardest = max(p, key=p.get)
        powers = [f"{fmt(p[n], 3)} W ({n}, {_c_text(c)})" for n, c in pos]
        text = (
            f"At ω_n the damper force equals the applied force F0 = {st.F0:g} N for every positive damping (it is "
            f"what balances the force there), and the mean power it must dissipate is F0²/(2c): {_list(powers)}. "
            f"The {hardest} damping, the lightest, works hardest at resonance; away from resonance the heavier "
            "damper carries the larger force."
        )
    zero = [n for n, c in st.by_value() if c == 0.0]
    neg = [n for n, c in st.by_value() if c < 0.0]
    if zero:
        text += (
            f" With c = 0 ({_list(zero)}) there is no damper: zero force and power, and at ω_n the amplitude grows "
            "without bound."
        )
    if neg:
        text += (
            f" With c < 0 ({_list([f'{n}, {_c_text(st.dampings[n])}' for n in neg])}) there is no steady state: "
            "the negative damper feeds power in and the motion grows."
        )
    return text.strip()


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
    pos = st.positive()
    for i, (n, c) in enumerate(pos):
        d = st.design[n]
        right = i < len(pos) - 1 or len(pos) == 1
        ax.plot(d.transmissibility, d.peak_magnification, markers[n], color=COLORS[n], ms=9, mec="k", zorder=3)
        ax.annotate(
            f"“{LABELS[n]}”\n$c$ = {c:g} N s/m, $t_s$ = {fmt(d.settling_time, 3)} s",
            (d.transmissibility, d.peak_magnification),
            xytext=(10, 4) if right else (-10, 14),
            ha="left" if right else "right",
            textcoords="offset points",
            fontsize=8,
        )
    off = [f"“{LABELS[n]}” ($c$ = {c:g} N s/m)" for n, c in st.by_value() if c <= 0.0]
    if off:
        ax.text(
            0.98,
            0.97,
            "not on these axes (no finite peak or settling):\n" + ", ".join(off),
            transform=ax.transAxes,
            ha="right",
            va="top",
            fontsize=7.5,
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
    """One row per paper label, judged by the values of c (any order, any sign)."""
    d = st.design
    stable = [n for n, _c in st.positive()]
    not_stable = [n for n, _c in st.by_value() if n not in stable]
    rows = []
    for n, c in st.dampings.items():
        x = d[n]
        others = [o for o in stable if o != n]
        if n not in stable:
            check = f"{x.stability}: no finite resonant peak, no settling, no stationary random response"
            verdict = {
                "low": f"“prone to instability” is literally true here: c = {c:g} N s/m is {x.stability}",
                "nominal": "not a compromise: it is not stable",
                "high": f"contradicted: c = {c:g} N s/m is {x.stability}",
            }[n]
        elif n == "low":
            best_iso = min(stable, key=lambda o: d[o].transmissibility)
            if others:
                nxt = min(others, key=lambda o: d[o].transmissibility)
                o = d[nxt]
                check = (
                    f"best isolation at {st.isolation_ratio:g} ω_n of the stable ones: "
                    f"{'yes' if best_iso == n else 'no'}; against the {nxt} damping (c = {o.c:g} N s/m): "
                    f"T {fmt(x.transmissibility / o.transmissibility, 3)} times, resonant peak "
                    f"{fmt(x.peak_magnification / o.peak_magnification, 3)} times, settling "
                    f"{fmt(x.settling_time / o.settling_time, 3)} times"
                )
            else:
                check = "the only stable damping of the three: nothing to compare its isolation with"
            verdict = (
                "supported only in the isolation sense, at a high price"
                if best_iso == n and others
                else "not supported"
            )
        elif n == "high":
            lowest_peak = min(stable, key=lambda o: d[o].peak_magnification)
            fastest = min(stable, key=lambda o: d[o].settling_time)
            best_iso = min(stable, key=lambda o: d[o].transmissibility)
            check = (
                f"lowest resonant peak of the stable ones: {'yes' if n == lowest_peak else 'no'}; "
                f"fastest settling of the stable ones: {'yes' if n == fastest else 'no'}; "
                f"transmits {fmt(x.transmissibility / d[best_iso].transmissibility, 3)} times the best isolator's T "
                f"at {st.isolation_ratio:g} ω_n"
            )
            if not not_stable:
                verdict = "not a distinction: all three are asymptotically stable"
            elif len(stable) == 1:
                verdict = "the only asymptotically stable one of the three"
            else:
                verdict = f"stable, unlike c = {_list([f'{st.dampings[o]:g}' for o in not_stable])} N s/m"
        else:
            if len(others) == 2:
                lo, hi = d[others[0]], d[others[1]]
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
            else:
                check = (
                    f"fewer than two other stable dampings to lie between; settling "
                    f"{fmt(x.settling_time / st.star.settling_time, 3)} times the optimum at ζ* = {st.zeta_star:.3f}"
                )
                verdict = "no compromise to judge: the others are not both stable"
        rows.append(
            {
                "label": f"“{LABELS[n]}”",
                "c": c,
                "zeta": x.zeta,
                "peak": x.peak_magnification if x.peak_magnification is not None else (
                    WHY_UNDAMPED_PEAK if c == 0.0 else WHY_NO_STEADY),
                "iso": x.transmissibility if x.transmissibility is not None else WHY_NO_STEADY,
                "ts": x.settling_time if x.settling_time is not None else (
                    WHY_NO_SETTLING_0 if c == 0.0 else WHY_NO_STEADY),
                "rms": x.rms_per_sqrt_S0 * math.sqrt(st.S0) if x.rms_per_sqrt_S0 is not None else WHY_NO_VARIANCE,
                "check": check,
                "verdict": verdict,
            }
        )  # fmt: skip
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
        scale = max(st.omega_n, abs(c) / st.m)
        roots = max(roots, float(np.max(np.abs(np.sort_complex(p) - np.sort_complex(ref)))) / scale)
    env = 0.0
    for g in st.growth.values():
        env = max(env, float(np.max((np.abs(g["x"]) - g["env"]) / np.maximum(g["env"], 1e-300))))
    band = 0.0
    for n, s in st.steps.items():
        band = max(band, abs(abs(float(step_response(st.osc(st.dampings[n]), s.settling_time)) - 1.0) - BAND))
    s = st.star
    band = max(band, abs(abs(float(step_response(st.osc(st.c_star), s.settling_time)) - 1.0) - BAND))
    rows = [
        {"check": "|T(√2 ω_n) − 1| over 200 ζ from 1e-4 to 100", "value": bound(cross, 1e-13)},
        {"check": "poles against numpy.roots, relative to max(ω_n, |c|/m)", "value": bound(roots, 1e-12)},
        {"check": "|x| above its closed-form envelope, relative", "value": bound(max(env, 0.0), 1e-9)},
        {"check": "| |y(t_s) − 1| − 0.02 | at the settling times", "value": bound(band, 1e-12)},
    ]
    return Table(
        rows,
        [Column("check", "self-check"), Column("value", "value")],
        caption="Self-checks at rounding level (printed as bounds).",
        name="tab-stability-checks",
    )


def summary_text(st: StabilityStudy) -> str:
    """The chapter's findings as Markdown bullets, each from the study's numbers."""
    pos = st.positive()
    bad = [(n, c) for n, c in st.by_value() if c <= 0.0]
    if not bad:
        first = (
            f"* All three of this run's dampings are asymptotically stable; the lightest ({_c_text(pos[0][1])}) "
            f"decays with τ = {fmt(st.osc(pos[0][1]).time_constant, 3)} s. With k > 0, instability needs c ≤ 0: "
            "linear growth "
            "at exact undamped resonance, exponential growth with c < 0."
        )
    else:
        first = (
            "* Not all of this run's dampings are asymptotically stable: "
            + _list([f"{_c_text(c)} is {st.design[n].stability}" for n, c in bad])
            + ". With k > 0, instability needs c ≤ 0: linear growth at exact undamped resonance, exponential "
            "growth with c < 0."
        )
    lines = [
        first,
        "* Under a force on the mass more damping lowers the displacement at every frequency and under random "
        "load (σ_x ∝ 1/√c). " + force_tradeoff_text(st),
    ]
    if len({c for _n, c in pos}) >= 2:
        (nl, cl), (nh, ch) = pos[0], pos[-1]
        lines.append(
            f"* Under base motion it is a trade-off: all curves cross T = 1 at √2 ω_n; at {st.isolation_ratio:g} ω_n "
            f"the heaviest positive damping ({_c_text(ch)}) transmits {fmt(st.design[nh].transmissibility, 3)}, the "
            f"lightest ({_c_text(cl)}) {fmt(st.design[nl].transmissibility, 3)}."
        )
    else:
        lines.append("* Under base motion it is a trade-off: all curves cross T = 1 at √2 ω_n, above which more "
                     "damping transmits more.")  # fmt: skip
    settle = [f"{fmt(st.steps[n].settling_time, 3)} s ({_c_text(c)})" for n, c in pos]
    lines.append(
        f"* The step response settles fastest at ζ* = {st.zeta_star:.4f} (c = {fmt(st.c_star, 3)} N s/m, "
        f"t_s = {fmt(st.star.settling_time, 3)} s)"
        + (
            f"; this run's positive dampings need {_list(settle)}."
            if settle
            else "; none of this run's dampings settles."
        )
    )
    lines.append(
        "* At resonance the damper force is F0 for every positive c and the power F0²/(2c): the light damper works "
        "hardest."
    )
    return "\n".join(lines)


def explorer_sentence(st: StabilityStudy) -> str:
    """Where the sliders start, and why when the run's nominal damping is outside their range."""
    c = st.dampings["nominal"]
    zeta = st.osc(c).damping_ratio
    start = min(max(zeta, ZETA_MIN), ZETA_MAX)
    text = f"The sliders start at ζ = {start:.4g}"
    if zeta == start:
        return text + f", the nominal damping of this run ({_c_text(c)})."
    if c <= 0.0:
        return text + (
            f", their lowest value: the nominal damping of this run ({_c_text(c)}) is not positive, and the sliders "
            "cover positive damping only."
        )
    return text + f", the end of their range nearest to the nominal damping of this run ({_c_text(c)}, ζ = {zeta:.4g})."


# ----------------------------------------------------------------------------- sliders

#: Range of the damping-ratio slider (log scale), 1.
ZETA_MIN, ZETA_MAX = 0.005, 5.0
#: Positions of the logarithmic slider.
ZETA_STEPS = 600
_counter = itertools.count(1)


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

    Starts at damping c (N s/m, any sign) and base frequency omega (rad/s, >= 0), moved into the
    sliders' ranges (damping ratio 0.005 to 5, frequency 0 to 4 omega_n) when outside; c <= 0
    starts at the lowest damping ratio (:func:`explorer_sentence` says so).
    """
    osc = Oscillator(m, check_real("c", c, unit="N s/m"), k)
    omega = check_real("omega", omega, low=0.0, unit="rad/s")
    zeta = min(max(osc.damping_ratio, ZETA_MIN), ZETA_MAX)  # c <= 0: the lowest damping ratio
    return StabilityExplorer(osc.m, osc.k, zeta, min(omega, 4.0 * osc.natural_frequency))
