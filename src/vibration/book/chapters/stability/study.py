"""Stability and damping as a design choice: the chapter's computation, once, as frozen records.

:func:`stability_study` takes the validated :class:`~vibration.book.chapters.stability.params.Params`
and runs every computation the chapter shows (all physics from :mod:`vibration.physics.stability`):
the stability class of each damping, the three ways a forced response grows, the design metrics
(resonant peak, isolation, settling) of each damping and of the settling-optimal one, the step
metrics and the white-noise Monte Carlo. Figures, tables and sentences are functions of the
resulting :class:`StabilityStudy`, so a run with other parameters never contradicts its own tables.
No prose here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.stability.params import Params
from vibration.book.presentation.records import with_params
from vibration.physics.exact import exact_response
from vibration.physics.model import Oscillator, SineForce
from vibration.physics.stability import (
    DesignMetrics,
    StepMetrics,
    design_metrics,
    growth_envelope,
    settling_optimal_zeta,
    stability_class,
    step_metrics,
    white_noise_force_optimum,
    white_noise_monte_carlo,
)

#: The paper's names for its three dampings (Discussion 4.2), in the order low, nominal, high.
LABELS = {"low": "comfort", "nominal": "optimised compromise", "high": "absolute stability"}
#: Settling band of the step response, fraction of the final value.
BAND = 0.02
#: Largest growth exponent drawn for the exponential case (e^50 ~ 5 x 10^21).
MAX_GROWTH = 50.0
#: Samples of a growth case: 40 per radian of the fastest frequency, within these bounds.
GROWTH_SAMPLES = (20_001, 200_001)
#: Damping ratio of the paper's low damping (0.1 N s/m, 1 kg, 20 N/m): the bounded growth case's
#: fallback when none of the run's dampings is positive with oscillating poles.
PAPER_LOW_ZETA = 0.1 / (2.0 * math.sqrt(20.0))
#: The three growth laws, in the order the chapter draws them.
GROWTH_CASES = ("bounded", "linear", "exponential")


@dataclass(frozen=True, eq=False, kw_only=True)
class GrowthCase:
    """One forced response from rest over a window, with its closed-form envelope."""

    case: str  # "bounded", "linear" or "exponential"
    osc: Oscillator
    force: SineForce
    t: np.ndarray  # s
    x: np.ndarray  # exact displacement, m
    env: np.ndarray  # closed-form envelope (an upper bound of |x|), m
    capped: bool  # window shortened so that the growth factor stays below e^MAX_GROWTH

    @property
    def t_end(self) -> float:
        """End of the window, s."""
        return float(self.t[-1])

    @property
    def peak(self) -> float:
        """Largest |x| in the window, m."""
        return float(np.max(np.abs(self.x)))


@with_params("m", "k", "F0", "omega_res", "t_growth", "isolation_ratio", "S0", "n_paths", "seed")
@dataclass(frozen=True, eq=False, kw_only=True)
class StabilityStudy:
    """Every number of the chapter, computed once by :func:`stability_study` (SI units).

    The run's parameters are readable by name (``st.m`` for ``st.params.m``): see
    :func:`~vibration.book.presentation.records.with_params`.
    """

    params: Params
    dampings: dict  # "low"/"nominal"/"high" -> c, N s/m (any sign, any order)
    design: dict  # name -> DesignMetrics of each damping
    steps: dict  # name -> StepMetrics (only c > 0)
    monte_carlo: dict  # name -> MonteCarlo (only c > 0)
    zeta_star: float  # settling-optimal damping ratio, 1
    star: DesignMetrics  # design metrics at zeta_star
    star_step: StepMetrics  # step metrics at zeta_star
    growth: dict  # case -> GrowthCase, in GROWTH_CASES order
    bounded_name: str | None  # damping of the run the bounded case uses (None: the paper's ratio)
    support_optimum: tuple[float, float]  # c = sqrt(km) (N s/m) and the least support-force variance (N²)

    # the parameters, by name (SI units; the others by @with_params)
    @property
    def c_unstable(self) -> float:
        return self.params.c_unstable + 0.0  # -0.0 is 0

    @property
    def omega_n(self) -> float:
        """Natural frequency, rad/s."""
        return math.sqrt(self.k / self.m)

    @property
    def c_crit(self) -> float:
        """Critical damping, N s/m."""
        return 2.0 * math.sqrt(self.k) * math.sqrt(self.m)

    @property
    def c_star(self) -> float:
        """Damping of the settling-optimal ratio, N s/m."""
        return self.zeta_star * self.c_crit

    def osc(self, c: float) -> Oscillator:
        """The oscillator of this run with damping ``c`` (N s/m)."""
        return Oscillator(m=self.m, c=c, k=self.k)

    def by_value(self) -> list[tuple[str, float]]:
        """The paper's three dampings as (name, c), sorted by the value of c (ties in paper order)."""
        order = list(self.dampings)
        return sorted(self.dampings.items(), key=lambda p: (p[1], order.index(p[0])))

    def positive(self) -> list[tuple[str, float]]:
        """The asymptotically stable ones (c > 0), by value."""
        return [(n, c) for n, c in self.by_value() if c > 0.0]

    def distinct_positive(self) -> bool:
        """At least two different positive dampings: the lightest and heaviest can be compared."""
        return len({c for _n, c in self.positive()}) >= 2

    def pole_cases(self) -> list[tuple[str, float]]:
        """(key, c) of the pole chart: the three dampings by value, then undamped and the flutter model."""
        return [*self.by_value(), ("undamped", 0.0), ("unstable", self.c_unstable)]

    def growth_rate(self) -> float:
        """Largest real part of the flutter model's poles, 1/s (> 0 only when c_unstable < 0)."""
        return stability_class(self.osc(self.c_unstable)).spectral_abscissa


def _growth_case(case: str, osc: Oscillator, force: SineForce, t_end: float, capped: bool) -> GrowthCase:
    lo, hi = GROWTH_SAMPLES
    n = int(min(hi, max(lo, 40 * t_end * max(osc.natural_frequency, force.omega))))
    t = np.linspace(0.0, t_end, n)
    return GrowthCase(
        case=case,
        osc=osc,
        force=force,
        t=t,
        x=exact_response(osc, force, t).x,
        env=growth_envelope(osc, force, t),
        capped=capped,
    )


def stability_study(params: Params | None = None, **values) -> StabilityStudy:
    """Run the chapter: stability, growth, transmissibility, step, random load.

    Parameters
    ----------
    params : Params, optional
        The validated parameters (ranges: :data:`~vibration.book.chapters.stability.params.SCHEMA`);
        or give them as keyword arguments, checked by the schema. The three dampings may have any
        sign and any order; quantities that do not exist for ``c <= 0`` are left out of the records.

    Returns
    -------
    StabilityStudy
        Frozen record of every result the chapter shows.

    Examples
    --------
    >>> s = stability_study(n_paths=20)
    >>> round(s.zeta_star, 4), s.design["high"].stability
    (0.7797, 'asymptotically stable')
    >>> s = stability_study(c_low=-0.1, c_high=0.3, n_paths=20, t_growth=20.0)
    >>> [n for n, _c in s.by_value()], s.design["low"].stability, "low" in s.monte_carlo
    (['low', 'high', 'nominal'], 'unstable', False)
    """
    p = params if params is not None else Params.from_values(values)
    dampings = {"low": p.c_low + 0.0, "nominal": p.c_nominal + 0.0, "high": p.c_high + 0.0}
    for c in (*dampings.values(), p.c_unstable):
        Oscillator(m=p.m, c=c, k=p.k)  # representable rates, or a ParameterError naming c
    design, steps, mc = {}, {}, {}
    for i, (name, c) in enumerate(dampings.items()):
        osc = Oscillator(m=p.m, c=c, k=p.k)
        design[name] = design_metrics(osc, p.isolation_ratio, BAND)
        if c > 0.0:
            steps[name] = step_metrics(osc, BAND)
            mc[name] = white_noise_monte_carlo(osc, p.S0, n_paths=p.n_paths, seed=p.seed + i)
    zeta_star = settling_optimal_zeta(BAND)
    c_crit = 2.0 * math.sqrt(p.k) * math.sqrt(p.m)
    star_osc = Oscillator(m=p.m, c=zeta_star * c_crit, k=p.k)
    # growth: bounded (the lightest positive damping with oscillating poles, at omega_res),
    # linear (c = 0 at omega_n exactly), exponential (c_unstable at omega_res)
    order = list(dampings)
    positive = sorted(
        ((n, c) for n, c in dampings.items() if 0.0 < c < c_crit), key=lambda q: (q[1], order.index(q[0]))
    )
    bounded_name, c_b = positive[0] if positive else (None, PAPER_LOW_ZETA * c_crit)
    c_u = p.c_unstable + 0.0
    rate = stability_class(Oscillator(m=p.m, c=c_u, k=p.k)).spectral_abscissa
    t_exp = p.t_growth if rate <= 0.0 else min(p.t_growth, MAX_GROWTH / rate)
    wn = math.sqrt(p.k / p.m)
    growth = {
        "bounded": _growth_case(
            "bounded", Oscillator(m=p.m, c=c_b, k=p.k), SineForce(F0=p.F0, omega=p.omega_res), p.t_growth, False
        ),
        "linear": _growth_case(
            "linear", Oscillator(m=p.m, c=0.0, k=p.k), SineForce(F0=p.F0, omega=wn), p.t_growth, False
        ),
        "exponential": _growth_case(
            "exponential",
            Oscillator(m=p.m, c=c_u, k=p.k),
            SineForce(F0=p.F0, omega=p.omega_res),
            t_exp,
            t_exp < p.t_growth,
        ),
    }
    return StabilityStudy(
        params=p,
        dampings=dampings,
        design=design,
        steps=steps,
        monte_carlo=mc,
        zeta_star=zeta_star,
        star=design_metrics(star_osc, p.isolation_ratio, BAND),
        star_step=step_metrics(star_osc, BAND),
        growth=growth,
        bounded_name=bounded_name,
        support_optimum=white_noise_force_optimum(p.m, p.k, p.S0),
    )
