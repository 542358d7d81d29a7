"""The book's notation, registered once: symbol, meaning, unit, defining equation and first chapter.

The glossary appendix is rendered from :data:`SYMBOLS`. Each symbol means one thing in the whole
book; the letters that meant two things are settled here (:data:`SETTLED`):

- ``Q`` is the quality factor; the weights of a linear-quadratic regulator are ``q_x``, ``q_v`` and
  ``q_u`` (never ``Q``, nor ``r``, the frequency ratio);
- ``f`` is a frequency in Hz; the tuning ratio of an absorber is ``ν = ω_a/ω_p``;
- ``Δ`` is a difference (``ΔE``, ``Δω``, ``Δk``); the friction angle of chapter 12 is ``θ_f``;
- ``c`` is a viscous damping coefficient; the resting angle of chapter 12 is ``θ_0``;
- ``p`` is a p-value; the exponent of a damping law is ``n``.

Examples
--------
>>> lookup("ω_d").meaning
'damped natural frequency'
>>> lookup("ζ").unit, lookup("ζ").first_chapter
('1', 1)
>>> lookup("Q").meaning
'quality factor'
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["SETTLED", "SYMBOLS", "Symbol", "lookup"]


@dataclass(frozen=True, kw_only=True)
class Symbol:
    """One symbol of the book."""

    symbol: str  # as the book writes it in text, "_" starting a subscript ("ω_n")
    meaning: str
    unit: str  # SI unit; "1" when dimensionless
    equation: str  # its defining equation or relation (plain text, typeset symbols)
    first_chapter: int  # the chapter where it first appears (0: the front page)
    tex: tuple[str, ...] = ()  # how the chapters' equations write it ("\\omega_n"), for the coverage test


SYMBOLS: tuple[Symbol, ...] = (
    Symbol(symbol="m", meaning="mass", unit="kg", equation="m ẍ + c ẋ + k x = F(t)", first_chapter=0, tex=("m",)),
    Symbol(symbol="c", meaning="viscous damping coefficient", unit="N s/m", equation="damper force c ẋ",
           first_chapter=0, tex=("c",)),
    Symbol(symbol="k", meaning="spring stiffness", unit="N/m", equation="spring force k x", first_chapter=0,
           tex=("k",)),
    Symbol(symbol="x", meaning="displacement of the mass", unit="m", equation="x(t), from rest: x(0) = 0",
           first_chapter=0, tex=("x", "\\dot", "\\ddot")),
    Symbol(symbol="v", meaning="velocity of the mass", unit="m/s", equation="v = ẋ", first_chapter=1, tex=("v",)),
    Symbol(symbol="t", meaning="time", unit="s", equation="from 0 (rest) to t_end", first_chapter=0, tex=("t",)),
    Symbol(symbol="F", meaning="applied force", unit="N", equation="F(t) = F_0 sin ωt", first_chapter=1,
           tex=("F",)),
    Symbol(symbol="F_0", meaning="force amplitude", unit="N", equation="F(t) = F_0 sin ωt", first_chapter=0,
           tex=("F_0",)),
    Symbol(symbol="g", meaning="acceleration of gravity", unit="m/s²", equation="weight m g (the free-body diagram)",
           first_chapter=1, tex=("g",)),
    Symbol(symbol="N", meaning="normal force of the rollers on the block", unit="N",
           equation="N = m g (the free-body diagram)", first_chapter=1, tex=("N",)),
    Symbol(symbol="ω", meaning="forcing (angular) frequency", unit="rad/s", equation="F(t) = F_0 sin ωt",
           first_chapter=0, tex=("\\omega",)),
    Symbol(symbol="f", meaning="frequency in hertz", unit="Hz", equation="f = ω/(2π)", first_chapter=1, tex=("f",)),
    Symbol(symbol="ω_n", meaning="undamped natural frequency", unit="rad/s", equation="ω_n = √(k/m)",
           first_chapter=0, tex=("\\omega_n",)),
    Symbol(symbol="ω_d", meaning="damped natural frequency", unit="rad/s",
           equation="ω_d = ω_n √(1 − ζ²) = √(ω_n² − σ²)", first_chapter=1, tex=("\\omega_d",)),
    Symbol(symbol="ω_ref", meaning="the paper's reference forcing frequency", unit="rad/s",
           equation="ω_ref = 3 rad/s in the paper", first_chapter=1, tex=("\\omega_\\mathrm",)),
    Symbol(symbol="ω_res", meaning="the paper's “resonant” forcing frequency", unit="rad/s",
           equation="ω_res = 4.47 rad/s ≈ ω_n in the paper", first_chapter=1, tex=("\\omega_\\mathrm",)),
    Symbol(symbol="ω_p", meaning="frequency of the magnification peak", unit="rad/s", equation="ω_p = ω_n √(1 − 2ζ²)",
           first_chapter=4),
    Symbol(symbol="ζ", meaning="damping ratio", unit="1", equation="ζ = c/(2√(km)) = c/c_c", first_chapter=1,
           tex=("\\zeta",)),
    Symbol(symbol="c_c", meaning="critical damping coefficient", unit="N s/m", equation="c_c = 2√(km)",
           first_chapter=1, tex=("c_c",)),
    Symbol(symbol="σ", meaning="decay rate of the free motion", unit="1/s", equation="σ = c/(2m) = ζ ω_n",
           first_chapter=1, tex=("\\sigma",)),
    Symbol(symbol="τ", meaning="time constant of the envelope", unit="s", equation="τ = 1/σ = 2m/c",
           first_chapter=2, tex=("\\tau",)),
    Symbol(symbol="r", meaning="frequency ratio", unit="1", equation="r = ω/ω_n", first_chapter=1, tex=("r",)),
    Symbol(symbol="s", meaning="root of the characteristic equation (complex frequency)", unit="1/s",
           equation="m s² + c s + k = 0", first_chapter=1, tex=("s", "s_1", "s_2")),
    Symbol(symbol="X", meaning="steady-state amplitude", unit="m", equation="X = F_0/√((k − mω²)² + (cω)²)",
           first_chapter=1, tex=("X",)),
    Symbol(symbol="φ", meaning="phase lag of x behind the force", unit="rad", equation="tan φ = cω/(k − mω²)",
           first_chapter=1, tex=("\\varphi",)),
    Symbol(symbol="M", meaning="magnification (dynamic amplification)", unit="1", equation="M = X/(F_0/k)",
           first_chapter=1, tex=("M",)),
    Symbol(symbol="x_ss", meaning="steady-state response", unit="m", equation="x_ss = X sin(ωt − φ)",
           first_chapter=1, tex=("x_\\mathrm",)),
    Symbol(symbol="v_ss", meaning="steady-state velocity", unit="m/s", equation="v_ss = ωX cos(ωt − φ)",
           first_chapter=1, tex=("v_\\mathrm",)),
    Symbol(symbol="x_h", meaning="transient (homogeneous) response", unit="m", equation="x = x_ss + x_h",
           first_chapter=1, tex=("x_h",)),
    Symbol(symbol="v_h", meaning="transient velocity", unit="m/s", equation="v_h = ẋ_h", first_chapter=1,
           tex=("v_h",)),
    Symbol(symbol="x_0", meaning="initial displacement", unit="m", equation="x(0) = x_0", first_chapter=1,
           tex=("x_0",)),
    Symbol(symbol="v_0", meaning="initial velocity", unit="m/s", equation="ẋ(0) = v_0", first_chapter=1,
           tex=("v_0",)),
    Symbol(symbol="a", meaning="transient's initial displacement", unit="m", equation="a = x_0 + X sin φ",
           first_chapter=1, tex=("a",)),
    Symbol(symbol="b", meaning="transient's initial velocity", unit="m/s", equation="b = v_0 − ωX cos φ",
           first_chapter=1, tex=("b",)),
    Symbol(symbol="T_f", meaning="forcing period", unit="s", equation="T_f = 2π/ω", first_chapter=3),
    Symbol(symbol="Δt", meaning="sampling step", unit="s", equation="t_i = i Δt", first_chapter=3),
    Symbol(symbol="T_rec", meaning="length of one identification record", unit="s", equation="T_rec = N Δt",
           first_chapter=10),
    Symbol(symbol="t_end", meaning="end of the simulated window", unit="s", equation="window [0, t_end]",
           first_chapter=1, tex=("t_\\mathrm",)),
    Symbol(symbol="t_s", meaning="2 % settling time", unit="s",
           equation="last time |x_h| exceeds 2 % of X (envelope R exp(−σt) when underdamped)", first_chapter=2),
    Symbol(symbol="Q", meaning="quality factor", unit="1", equation="Q = 1/(2ζ) = √(km)/c = ω_n/Δω",
           first_chapter=4),
    Symbol(symbol="Δω", meaning="half-power bandwidth", unit="rad/s", equation="Δω = 2ζω_n = c/m", first_chapter=4,
           tex=("\\Delta",)),
    Symbol(symbol="E", meaning="stored (kinetic plus elastic) energy", unit="J", equation="E = ½ m v² + ½ k x²",
           first_chapter=4, tex=("E",)),
    Symbol(symbol="ΔE", meaning="change of the stored energy", unit="J", equation="W = D + ΔE", first_chapter=4,
           tex=("\\Delta",)),
    Symbol(symbol="W", meaning="work done by the force", unit="J", equation="W = ∫ F v dt", first_chapter=4,
           tex=("W",)),
    Symbol(symbol="D", meaning="energy dissipated by the damper", unit="J", equation="D = ∫ c v² dt",
           first_chapter=4, tex=("D",)),
    Symbol(symbol="c_i", meaning="nodes of a Runge-Kutta method (stage times over the step)", unit="1",
           equation="stage i is evaluated at t + c_i h", first_chapter=3, tex=("c_i",)),
    Symbol(symbol="y", meaning="state vector of the solver", unit="m, m/s", equation="y = (x, v), ẏ = f(t, y)",
           first_chapter=3, tex=("y",)),
    Symbol(symbol="T", meaning="transmissibility of a base-excited mount", unit="1",
           equation="T = √((1 + (2ζr)²)/((1 − r²)² + (2ζr)²))", first_chapter=6),
    Symbol(symbol="S_0", meaning="two-sided spectral density of a white-noise force", unit="N² s/rad",
           equation="σ_x² = π S_0/(kc)", first_chapter=6),
    Symbol(symbol="k_p", meaning="position gain", unit="N/m", equation="u = −k_p x − k_d ẋ", first_chapter=7),
    Symbol(symbol="k_d", meaning="velocity gain", unit="N s/m", equation="u = −k_p x − k_d ẋ", first_chapter=7),
    Symbol(symbol="u", meaning="control force", unit="N", equation="m ẍ + c ẋ + k x = F + u", first_chapter=7),
    Symbol(symbol="q_x", meaning="LQR weight of the displacement", unit="1/m²",
           equation="J = ∫ (q_x x² + q_v v² + q_u u²) dt", first_chapter=7),
    Symbol(symbol="q_v", meaning="LQR weight of the velocity", unit="s²/m²",
           equation="J = ∫ (q_x x² + q_v v² + q_u u²) dt", first_chapter=7),
    Symbol(symbol="q_u", meaning="LQR weight of the control force (not r, the frequency ratio)", unit="1/N²",
           equation="J = ∫ (q_x x² + q_v v² + q_u u²) dt", first_chapter=7),
    Symbol(symbol="K", meaning="state-feedback gains", unit="N/m, N s/m", equation="u = −K (x, v)",
           first_chapter=7),
    Symbol(symbol="μ", meaning="mass ratio of an absorber", unit="1", equation="μ = m_a/m_p", first_chapter=8),
    Symbol(symbol="ν", meaning="tuning ratio of an absorber (not f, a frequency)", unit="1",
           equation="ν = ω_a/ω_p; Den Hartog: ν = 1/(1 + μ)", first_chapter=8),
    Symbol(symbol="ζ_a", meaning="damping ratio of an absorber", unit="1", equation="ζ_a = c_a/(2 m_a ω_a)",
           first_chapter=8),
    Symbol(symbol="k_3", meaning="cubic stiffness", unit="N/m³", equation="m ẍ + c ẋ + k x + k_3 x³ = F(t)",
           first_chapter=9),
    Symbol(symbol="ω_b", meaning="backbone frequency", unit="rad/s", equation="ω_b² = k/m + (3/4)(k_3/m) A²",
           first_chapter=9),
    Symbol(symbol="Δk/k", meaning="relative loss of stiffness", unit="1", equation="k → k (1 − Δk/k)",
           first_chapter=10),
    Symbol(symbol="p", meaning="p-value of a statistical test (not an exponent)", unit="1",
           equation="probability of a result at least as extreme under the null hypothesis", first_chapter=10),
    Symbol(symbol="n", meaning="exponent of a power damping law (not p)", unit="1", equation="damping torque ∝ |θ̇|ⁿ",
           first_chapter=12),
    Symbol(symbol="θ_0", meaning="resting angle of the wheel (not c, a damping)", unit="rad",
           equation="θ = θ_0 when the wheel is at rest", first_chapter=12),
    Symbol(symbol="θ_f", meaning="friction angle (not Δ, a difference)", unit="rad",
           equation="dry friction stops the wheel within ±θ_f of θ_0", first_chapter=12),
)  # fmt: skip

#: The letters that meant two things, and what each meaning is written as now.
SETTLED: dict[str, tuple[str, str]] = {
    "Q": ("quality factor", "LQR weights: q_x, q_v, q_u"),
    "r": ("frequency ratio ω/ω_n", "LQR weight of the force: q_u"),
    "f": ("frequency in Hz", "tuning ratio: ν"),
    "Δ": ("a difference (ΔE, Δω, Δk)", "friction angle: θ_f"),
    "c": ("viscous damping coefficient", "resting angle: θ_0"),
    "p": ("p-value", "damping-law exponent: n"),
}


def lookup(symbol: str) -> Symbol:
    """The registered symbol ``symbol`` (its first entry when a letter has one per chapter part)."""
    for s in SYMBOLS:
        if s.symbol == symbol:
            return s
    raise KeyError(f"{symbol!r} is not in the book's notation: add it to vibration.presentation.notation.SYMBOLS")
