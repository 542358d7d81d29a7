"""Chapter 1's objectives, prerequisites and exercises, every answer computed from the run's parameters."""

from __future__ import annotations

import math

from vibration.physics.exact import steady_state
from vibration.physics.model import Oscillator, SineForce
from vibration.presentation.exercises import Answer, Exercise, Sheet
from vibration.presentation.exercises import fmt as g

from .params import Params

SHEET = Sheet(
    chapter=Params.SCHEMA.notebook,
    question="Does the paper's RK45 solution of the forced oscillator match the exact one, figure by figure?",
    level="core",
    objectives=(
        "Compute the natural frequency ω<sub>n</sub>, the damping ratio ζ and the damped frequency ω<sub>d</sub> "
        "from m, c and k.",
        "Classify a damping as underdamped, critically damped or overdamped.",
        "Compute the steady amplitude X and the phase lag φ of the forced response at a given ω.",
        "Explain why a numerical solution is checked against the exact one, and how far apart they may be.",
    ),
    prerequisites=(
        "Newton's second law for a mass on a spring",
        "linear second-order ODEs with constant coefficients",
        "complex numbers and sinusoids",
    ),
)
CHAPTER, QUESTION, LEVEL, OBJECTIVES, PREREQUISITES = SHEET.module_constants()


def exercises(params: Params) -> tuple[Exercise, ...]:
    """The chapter's exercises for ``params``, answers computed by the package."""
    p = params
    nom = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    wn, zeta, cc = nom.natural_frequency, nom.damping_ratio, nom.critical_damping
    sigma, wd = nom.decay_rate, nom.damped_natural_frequency
    out = [
        SHEET.numerical(
            "01.1",
            text=(
                f"For m = {g(p.m)} kg, k = {g(p.k)} N/m and the nominal damping c = {g(p.c_nominal)} N s/m, compute "
                "the natural frequency ω<sub>n</sub> (rad/s) and the damping ratio ζ."
            ),
            worked=(
                f"ω<sub>n</sub> = √(k/m) = √({g(p.k)}/{g(p.m)}) = {g(wn)} rad/s. The critical damping is "
                f"c<sub>c</sub> = 2√(km) = {g(cc)} N s/m, so ζ = c/c<sub>c</sub> = "
                f"{g(p.c_nominal)}/{g(cc)} = {g(zeta)}."
            ),
            answers=(
                Answer(quantity="omega_n", symbol="ω<sub>n</sub>", value=wn, unit="rad/s", rtol=2e-3),
                Answer(quantity="zeta", symbol="ζ", value=zeta, unit="", rtol=2e-3, atol=1e-6),
            ),
        ),
        SHEET.numerical(
            "01.2",
            text=(
                "Compute the decay rate σ = c/(2m) (1/s) and the damped natural frequency ω<sub>d</sub> (rad/s) of "
                "the nominal damping (ω<sub>d</sub> = 0 when the free motion does not oscillate)."
            ),
            worked=(
                f"σ = c/(2m) = {g(p.c_nominal)}/(2 × {g(p.m)}) = {g(sigma)} 1/s. "
                + (
                    f"ω<sub>d</sub> = √(ω<sub>n</sub>² − σ²) = √({g(wn)}² − {g(sigma)}²) = {g(wd)} rad/s, "
                    f"that is ω<sub>n</sub>√(1 − ζ²) with ζ = {g(zeta)}."
                    if wd > 0
                    else f"σ ≥ ω<sub>n</sub> = {g(wn)} rad/s: the free motion does not oscillate, ω<sub>d</sub> = 0."
                )
            ),
            answers=(
                Answer(quantity="sigma", symbol="σ", value=sigma, unit="1/s", rtol=2e-3, atol=1e-9),
                Answer(quantity="omega_d", symbol="ω<sub>d</sub>", value=wd, unit="rad/s", rtol=2e-3, atol=1e-6 * wn),
            ),
        ),
    ]
    ss = steady_state(nom, SineForce(F0=p.F0, omega=p.omega_ref))
    den = math.hypot(p.k - p.m * p.omega_ref**2, p.c_nominal * p.omega_ref)
    out.append(
        SHEET.numerical(
            "01.3",
            text=(
                f"The force F<sub>0</sub> sin ωt with F<sub>0</sub> = {g(p.F0)} N acts at the reference frequency "
                f"ω = {g(p.omega_ref)} rad/s on the nominal oscillator. Compute the steady amplitude X (m) and the "
                "phase lag φ (rad) of x behind the force."
            ),
            worked=(
                f"X = F<sub>0</sub>/√((k − mω²)² + (cω)²) = {g(p.F0)}/√(({g(p.k)} − {g(p.m)} × {g(p.omega_ref)}²)² + "
                f"({g(p.c_nominal)} × {g(p.omega_ref)})²) = {g(p.F0)}/{g(den)} = {g(ss.amplitude)} m. "
                f"φ = atan2(cω, k − mω²) = atan2({g(p.c_nominal * p.omega_ref)}, {g(p.k - p.m * p.omega_ref**2)}) "
                f"= {g(ss.phase)} rad ({g(math.degrees(ss.phase), 3)}°)."
            ),
            answers=(
                Answer(quantity="X", symbol="X", value=ss.amplitude, unit="m", rtol=5e-3),
                Answer(quantity="phi", symbol="φ", value=ss.phase, unit="rad", rtol=5e-3, atol=1e-4),
            ),
        )
    )
    high = Oscillator(m=p.m, c=p.c_high, k=p.k)
    regimes = {"a": "underdamped", "b": "critically damped", "c": "overdamped", "d": "undamped or unstable"}
    key = next((k for k, v in regimes.items() if v == high.regime), "d")
    out.append(
        SHEET.conceptual(
            "01.4",
            text=f"Which regime is the high damping c = {g(p.c_high)} N s/m in?",
            worked=(
                f"ζ = c/(2√(km)) = {g(p.c_high)}/{g(cc)} = {g(high.damping_ratio)}: "
                + (
                    "below 1, the free motion oscillates."
                    if key == "a"
                    else "equal to 1, the fastest return without oscillation."
                    if key == "b"
                    else "above 1, two real roots and no oscillation."
                    if key == "c"
                    else "c ≤ 0: no positive damping."
                )
            ),
            options=regimes,
            correct=key,
        )
    )
    res = lambda c: steady_state(Oscillator(m=p.m, c=c, k=p.k), SineForce(F0=p.F0, omega=p.omega_res)).amplitude  # noqa: E731
    if p.c_nominal > 0:
        x1, x2 = res(p.c_nominal), res(2 * p.c_nominal)
        out.append(
            SHEET.explore(
                "01.5",
                text=(
                    f"Run this chapter again with twice the nominal damping (`-p c_nominal {g(2 * p.c_nominal)}`). "
                    f"By what factor does the steady amplitude at ω = {g(p.omega_res)} rad/s fall (old over new)?"
                ),
                worked=(
                    f"With c = {g(p.c_nominal)} N s/m, X = {g(x1)} m; with c = {g(2 * p.c_nominal)} N s/m, "
                    f"X = {g(x2)} m (the formula of exercise 01.3 at ω = {g(p.omega_res)} rad/s). "
                    f"The ratio is {g(x1)}/{g(x2)} = {g(x1 / x2)}: close to 2 when ω is near ω<sub>n</sub>, where "
                    "the damper alone limits the amplitude."
                ),
                answers=Answer(quantity="ratio", symbol="X(c)/X(2c)", value=x1 / x2, unit="", rtol=5e-3),
            )
        )
    return tuple(out)
