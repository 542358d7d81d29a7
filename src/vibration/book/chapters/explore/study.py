"""Chapter 5's computation: the explorer's readout at its starting point, and what moving a slider does there.

:func:`readout` is the one place the explorer's numbers come from (natural frequency, damping ratio,
regime, steady amplitude, peak in the window, settling time), for the live widget and for the chapter's
table alike. :func:`explore_study` evaluates it at the run's parameters and adds the experiments the
chapter's sentences report: halving and doubling the damping at the starting frequency and far below
resonance, and the dampings at which the resonant peak and the oscillation disappear.

Examples
--------
>>> st = explore_study()
>>> st.start.regime, round(st.start.amplitude, 4)        # m
('underdamped', 2.2371)
>>> round(st.halved.amplitude / st.start.amplitude, 3), round(st.c_no_peak, 3)   # 1, N s/m
(2.0, 6.325)
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.explore.params import Params
from vibration.physics.exact import exact_response, steady_state
from vibration.physics.frequency import settling_time
from vibration.physics.model import Oscillator, ParameterError, SineForce

#: Range of the damping sliders, N s/m (logarithmic; the live slider and the book's panel both reach it).
C_MIN, C_MAX = 0.01, 20.0

#: Samples of the window the explorer draws (and the readout's peak is taken on).
N_POINTS = 5001

#: Forcing frequency, as a fraction of the natural frequency, of the "far below resonance" experiment.
FAR_BELOW = 0.5


@dataclass(frozen=True, kw_only=True)
class Readout:
    """The explorer's numbers for one setting of its controls (SI units)."""

    omega_n: float  # natural frequency, rad/s
    f_n: float  # natural frequency, Hz
    omega: float  # forcing frequency, rad/s
    f: float  # forcing frequency, Hz
    ratio: float  # omega / omega_n
    zeta: float  # damping ratio
    regime: str  # underdamped, critically damped, overdamped, ...
    magnification: float  # steady amplitude over the static deflection F0/k
    amplitude: float  # steady-state amplitude |X|, m
    peak: float  # largest |x| in the window from rest, m
    settling: float  # 2 % settling time, s (inf when it never settles)
    steady_reached: str  # "yes" when the settling time falls inside the window, else "no"
    t_end: float  # window, s

    def as_dict(self) -> dict:
        """The fields as a dict (the live explorer's ``values``)."""
        return dataclasses.asdict(self)


def readout(osc: Oscillator, force: SineForce, t_end: float, *, n_points: int = N_POINTS, response=None) -> Readout:
    """The explorer's readout for ``osc`` forced by ``force`` from rest over ``[0, t_end]`` s.

    ``response`` may pass the exact response already computed on ``linspace(0, t_end, n_points)``.
    Raises :class:`ParameterError` when the response overflows (non-finite values).
    """
    resp = response if response is not None else exact_response(osc, force, np.linspace(0.0, t_end, n_points))
    if not (np.all(np.isfinite(resp.x)) and np.all(np.isfinite(resp.v))):
        raise ParameterError(
            "the exact response overflows in this window (non-finite values): shorten t_end or change m, k, F0"
        )
    ss = steady_state(osc, force)
    ts = settling_time(osc, force)
    omega_n = osc.natural_frequency
    return Readout(
        omega_n=omega_n,
        f_n=omega_n / (2.0 * math.pi),
        omega=force.omega,
        f=force.frequency_hz,
        ratio=force.omega / omega_n,
        zeta=osc.damping_ratio,
        regime=osc.regime,
        magnification=ss.magnification,
        amplitude=ss.amplitude,
        peak=float(np.max(np.abs(resp.x))),
        settling=ts,
        steady_reached="yes" if ts <= t_end else "no",
        t_end=t_end,
    )


@dataclass(frozen=True, kw_only=True)
class ExploreStudy:
    """The explorer's starting point and the experiments the chapter reports (SI units)."""

    params: Params
    c_start: float  # damping the sliders start at, N s/m (the run's, or C_MIN when it is not positive)
    start: Readout  # at (omega_res, c_start)
    halved: Readout  # at (omega_res, c_start / 2)
    doubled: Readout  # at (omega_res, 2 c_start)
    far: Readout  # at (FAR_BELOW omega_n, c_start)
    far_halved: Readout  # at (FAR_BELOW omega_n, c_start / 2)
    c_critical: float  # 2√(km), N s/m: above it the free motion no longer oscillates
    c_no_peak: float  # √(2km), N s/m (ζ = 1/√2): from it on the magnification has no peak
    critical: Readout  # at (omega_res, c_critical)
    twice_critical: Readout  # at (omega_res, 2 c_critical)

    @property
    def clamped(self) -> bool:
        """True when the run's damping is not positive and the sliders start at :data:`C_MIN` instead."""
        return self.c_start != self.params.c_nominal


def explore_study(params: Params | None = None, **values) -> ExploreStudy:
    """The starting readout and the halving/doubling experiments at the run's parameters.

    Parameters
    ----------
    params : Params, optional
        The chapter's validated parameters (m kg, k N/m, F0 N, t_end s, omega_res rad/s, c_nominal N s/m);
        or give some of them as keyword arguments (the rest keep their defaults).

    Examples
    --------
    >>> explore_study(c_nominal=-0.1).c_start     # N s/m: a logarithmic slider cannot hold c <= 0
    0.01
    """
    p = params if params is not None else Params.from_values(values)
    c = p.c_nominal if p.c_nominal > 0 else C_MIN
    wn = math.sqrt(p.k / p.m)

    def at(w: float, damping: float) -> Readout:
        return readout(Oscillator(m=p.m, c=damping, k=p.k), SineForce(F0=p.F0, omega=w), p.t_end)

    return ExploreStudy(
        params=p,
        c_start=c,
        start=at(p.omega_res, c),
        halved=at(p.omega_res, c / 2),
        doubled=at(p.omega_res, 2 * c),
        far=at(FAR_BELOW * wn, c),
        far_halved=at(FAR_BELOW * wn, c / 2),
        c_critical=2.0 * math.sqrt(p.k * p.m),
        c_no_peak=math.sqrt(2.0 * p.k * p.m),
        critical=at(p.omega_res, 2.0 * math.sqrt(p.k * p.m)),
        twice_critical=at(p.omega_res, 4.0 * math.sqrt(p.k * p.m)),
    )
