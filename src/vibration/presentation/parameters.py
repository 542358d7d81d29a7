"""Parameters several chapters share, declared once, and the rules that tie parameters together.

The paper's model (m, k, F0, the window and its forcing frequencies and dampings) appears in
most chapters. Each chapter's schema takes these declarations with :func:`shared`, changing only
what differs in that chapter (usually the meaning), so a range is written in one place. The
rules are the checks on several values at once that more than one chapter needs.

Examples
--------
>>> shared("m").default, shared("m").unit
(1.0, 'kg')
>>> shared("c_nominal", meaning="passive damping of the plant").meaning
'passive damping of the plant'
>>> ordered("c_min", "c_max", "N s/m")({"c_min": 2.0, "c_max": 1.0})
Traceback (most recent call last):
...
vibration.physics.model.ParameterError: c_max = 1.0 N s/m must exceed c_min = 2.0 N s/m
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

from ..physics.model import N_POINTS_MAX, ParameterError
from .schema import Param

#: The paper's parameters and the Part I ones several chapters reuse: name -> declaration.
SHARED: dict[str, Param] = {
    p.name: p
    for p in (
        Param(name="m", symbol="m", default=1.0, unit="kg", low=1e-3, high=1e3, meaning="mass"),
        Param(name="k", symbol="k", default=20.0, unit="N/m", low=1e-3, high=1e6, meaning="spring stiffness"),
        Param(
            name="F0", symbol="F_0", default=5.0, unit="N", low=0.0, high=1e4, meaning="force amplitude", low_open=True
        ),
        Param(
            name="t_end",
            symbol="t_end",
            default=50.0,
            unit="s",
            low=0.0,
            high=1e3,
            meaning="end of the simulated window, from rest at time zero",
            low_open=True,
        ),  # fmt: skip
        Param(
            name="omega_ref",
            symbol="ω_ref",
            default=3.0,
            unit="rad/s",
            low=0.0,
            high=1e3,
            meaning="reference forcing frequency",
            low_open=True,
        ),
        Param(
            name="omega_res",
            symbol="ω_res",
            default=4.47,
            unit="rad/s",
            low=0.0,
            high=1e3,
            meaning="the paper's “resonant” forcing frequency",
            low_open=True,
        ),  # fmt: skip
        Param(
            name="c_low",
            symbol="c_low",
            default=0.1,
            unit="N s/m",
            low=-1e4,
            high=1e4,
            meaning="low damping coefficient (0: undamped, < 0: self-excited)",
        ),
        Param(
            name="c_nominal",
            symbol="c_nom",
            default=0.5,
            unit="N s/m",
            low=-1e4,
            high=1e4,
            meaning="nominal damping coefficient",
        ),
        Param(
            name="c_high",
            symbol="c_high",
            default=15.0,
            unit="N s/m",
            low=-1e4,
            high=1e4,
            meaning="high damping coefficient",
        ),
        Param(
            name="n_points",
            symbol="N",
            default=5001,
            unit="",
            low=2,
            high=min(200_001, N_POINTS_MAX),
            meaning="output samples over the window",
        ),
    )
}

#: Most forcing or natural periods the paper's window may hold (the paper's holds 36).
MAX_PERIODS = 1000
#: Largest growth exponent (-c / 2m) t_end of negative damping (e^50 ~ 5e21 stays finite in every table).
MAX_GROWTH = 50.0
#: Largest (c / m) t_end, the stiffness the paper's explicit RK45 is asked to cross (the paper's: 750).
MAX_STIFFNESS = 1e6
#: Fewest samples an identification record may hold (t_record / dt).
MIN_RECORD_SAMPLES = 200


def shared(name: str, **changes) -> Param:
    """The shared declaration of ``name``, with ``changes`` (e.g. ``meaning``, ``default``) for one chapter."""
    try:
        param = SHARED[name]
    except KeyError:
        raise KeyError(f"{name!r} is not a shared parameter: allowed {', '.join(SHARED)}") from None
    return dataclasses.replace(param, **changes)


def ordered(low: str, high: str, unit: str) -> Callable[[dict], None]:
    """A rule: parameter ``high`` must exceed parameter ``low``."""

    def rule(p: dict) -> None:
        if not p[high] > p[low]:
            raise ParameterError(f"{high} = {p[high]!r} {unit} must exceed {low} = {p[low]!r} {unit}")

    rule.__name__ = f"{high}_exceeds_{low}"
    return rule


def sampling(p: dict) -> None:
    """``f_max`` below the Nyquist frequency of ``dt``, and ``t_record`` of at least 200 samples (where declared)."""
    f_max, dt, t_record = p.get("f_max"), p.get("dt"), p.get("t_record")
    if f_max is not None and dt is not None and not f_max < 0.5 / dt:
        raise ParameterError(
            f"f_max = {f_max!r} Hz is not below the Nyquist frequency 1/(2 dt) = {0.5 / dt:.4g} Hz of dt = {dt!r} s: "
            f"allowed f_max < {0.5 / dt:.4g} Hz"
        )
    if t_record is not None and dt is not None and t_record / dt < MIN_RECORD_SAMPLES:
        raise ParameterError(
            f"t_record = {t_record!r} s holds {t_record / dt:.3g} samples of dt = {dt!r} s: allowed at least "
            f"{MIN_RECORD_SAMPLES} samples (t_record >= {MIN_RECORD_SAMPLES * dt:.4g} s)"
        )


def paper_window(p: dict) -> None:
    """The paper's window stays affordable: periods it holds, growth of negative damping, RK45's stiffness."""
    m, k, t_end = p.get("m"), p.get("k"), p.get("t_end")
    if None in (m, k, t_end):
        return
    fastest = max([math.sqrt(k / m)] + [w for w in map(p.get, ("omega_ref", "omega_res", "omega_max")) if w])
    periods = fastest * t_end / (2 * math.pi)
    if periods > MAX_PERIODS:
        raise ParameterError(
            f"t_end = {t_end!r} s holds {periods:.0f} periods of the fastest frequency ({fastest:.4g} rad/s, "
            f"from m = {m!r} kg, k = {k!r} N/m and the forcing): allowed at most {MAX_PERIODS}"
        )
    dampings = [x for x in map(p.get, ("c_low", "c_nominal", "c_high")) if x is not None]
    for name in ("c_low", "c_nominal", "c_high"):
        c = p.get(name)
        if c is not None and c < 0 and -c / (2 * m) * t_end > MAX_GROWTH:
            raise ParameterError(
                f"{name} = {c!r} N s/m with m = {m!r} kg over t_end = {t_end!r} s: the negative damping grows the "
                f"response like exp({-c / (2 * m) * t_end:.3g}): allowed (-c/2m) t_end at most {MAX_GROWTH:g}"
            )
    c = max([abs(x) for x in dampings] or [0.0])  # the ones RK45 meets
    if c / m * t_end > MAX_STIFFNESS:
        raise ParameterError(
            f"c = {c!r} N s/m with m = {m!r} kg over t_end = {t_end!r} s: (c/m) t_end = {c / m * t_end:.3g} "
            f"is out of range: allowed at most {MAX_STIFFNESS:g} (the paper's explicit RK45 would crawl)"
        )


def above(name: str, bound: float, unit: str, why: str) -> Callable[[dict], None]:
    """A rule: parameter ``name`` must exceed ``bound`` in this chapter (its shared range allows more).

    >>> above("c", 0.0, "N s/m", "damped")({"c": 0.0})
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: c = 0.0 N s/m is out of range for this chapter: allowed c > 0 N s/m (damped)
    """

    def rule(p: dict) -> None:
        if not p[name] > bound:
            raise ParameterError(
                f"{name} = {p[name]!r} {unit} is out of range for this chapter: "
                f"allowed {name} > {bound:g} {unit} ({why})"
            )

    rule.__name__ = f"{name}_above_{bound:g}"
    return rule


def below(name: str, bound: float, unit: str, why: str) -> Callable[[dict], None]:
    """A rule: parameter ``name`` must stay below ``bound`` in this chapter."""

    def rule(p: dict) -> None:
        if not p[name] < bound:
            raise ParameterError(
                f"{name} = {p[name]!r} {unit} is out of range for this chapter: "
                f"allowed {name} < {bound:g} {unit} ({why})"
            )

    rule.__name__ = f"{name}_below_{bound:g}"
    return rule


def at_least(name: str, bound: float, unit: str, why: str) -> Callable[[dict], None]:
    """A rule: parameter ``name`` must be at least ``bound`` in this chapter."""

    def rule(p: dict) -> None:
        if not p[name] >= bound:
            raise ParameterError(
                f"{name} = {p[name]!r} {unit} is out of range for this chapter: "
                f"allowed {name} >= {bound:g} {unit} ({why})"
            )

    rule.__name__ = f"{name}_at_least_{bound:g}"
    return rule


def damping_ratio_at_most(limit: float, name: str = "c_nominal") -> Callable[[dict], None]:
    """A rule: the damping ``name`` is non-negative with ζ = c / (2√(km)) at most ``limit``."""

    def rule(p: dict) -> None:
        c, zeta = p[name], p[name] / (2.0 * math.sqrt(p["k"] * p["m"]))
        if not 0.0 <= zeta <= limit:
            raise ParameterError(
                f"{name} = {c!r} N s/m with m = {p['m']!r} kg, k = {p['k']!r} N/m gives ζ = {zeta:.4g}: allowed "
                f"0 <= ζ <= {limit:g} ({name} <= {limit * 2.0 * math.sqrt(p['k'] * p['m']):.4g} N s/m)"
            )

    rule.__name__ = f"{name}_damping_ratio_at_most_{limit:g}"
    return rule
