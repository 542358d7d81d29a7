"""Parameters several chapters share, declared once, the shapes most parameters take, and the rules that tie them.

The paper's model (m, k, F0, the window and its forcing frequencies and dampings) appears in
most chapters. Each chapter's schema takes these declarations with :func:`shared_params` (or
:func:`shared` for one), changing only what differs in that chapter (usually the meaning), so a
range is written in one place. A chapter's own parameters are declared through the builders of
the shapes they share (:func:`positive`, :func:`frequency`, :func:`damping`, :func:`ratio`,
:func:`count`, :func:`seed`, and :func:`quantity` for any other range): each returns a
:class:`~vibration.book.presentation.schema.Param`. The rules are the checks on several values at once
that more than one chapter needs. A chapter declares its parameters as data, in its package's
``params.toml`` (one line a parameter, naming the shape it takes as its ``kind``), which :func:`declared`
reads into the chapter's schema.

Examples
--------
>>> shared("m").default, shared("m").unit
(1.0, 'kg')
>>> shared("c_nominal", meaning="passive damping of the plant").meaning
'passive damping of the plant'
>>> [p.unit for p in shared_params("m", "k", "c_nominal")]
['kg', 'N/m', 'N s/m']
>>> frequency("omega_max", "ω_max", 10.0, high=1e3, meaning="upper forcing frequency").low_open
True
>>> ordered("c_min", "c_max", "N s/m")({"c_min": 2.0, "c_max": 1.0})
Traceback (most recent call last):
...
vibration.physics.model.ParameterError: c_max = 1.0 N s/m must exceed c_min = 2.0 N s/m
"""

from __future__ import annotations

import dataclasses
import math
import operator
import tomllib
from collections.abc import Callable
from importlib.resources import files

from ...physics.model import N_POINTS_MAX, ParameterError
from .schema import Param, Schema

# ---------------------------------------------------------------------------------------------------------
# The shapes a parameter takes (name, symbol and default first; the rest by keyword)


def quantity(
    name: str, symbol: str, default: float, *, unit: str, low: float, high: float, meaning: str, low_open: bool = False
) -> Param:
    """A real parameter in ``unit`` between ``low`` (exclusive when ``low_open``) and ``high``."""
    return Param(
        name=name, symbol=symbol, default=default, unit=unit, low=low, high=high, meaning=meaning, low_open=low_open
    )


def positive(name: str, symbol: str, default: float, *, unit: str, high: float, meaning: str) -> Param:
    """A real parameter above zero, at most ``high`` (in ``unit``)."""
    return quantity(name, symbol, default, unit=unit, low=0.0, high=high, meaning=meaning, low_open=True)


def frequency(name: str, symbol: str, default: float, *, high: float, meaning: str) -> Param:
    """An angular frequency above zero, at most ``high`` rad/s."""
    return positive(name, symbol, default, unit="rad/s", high=high, meaning=meaning)


def damping(name: str, symbol: str, default: float, *, low: float, high: float, meaning: str) -> Param:
    """A viscous damping coefficient from ``low`` to ``high`` N s/m (negative: energy fed in)."""
    return quantity(name, symbol, default, unit="N s/m", low=low, high=high, meaning=meaning)


def ratio(name: str, symbol: str, default: float, *, low: float, high: float, meaning: str) -> Param:
    """A dimensionless real parameter from ``low`` to ``high``."""
    return quantity(name, symbol, default, unit="", low=low, high=high, meaning=meaning)


def count(name: str, symbol: str, default: int, *, low: int, high: int, meaning: str) -> Param:
    """A whole number from ``low`` to ``high``: samples, runs, paths, steps."""
    return Param(name=name, symbol=symbol, default=default, unit="", low=low, high=high, meaning=meaning)


#: Largest seed a random generator of the package takes (a 32-bit signed integer).
SEED_MAX = 2**31 - 1


def seed(default: int, *, meaning: str) -> Param:
    """The chapter's random seed ``seed``, from 0 to :data:`SEED_MAX` (written "seed": s is a complex frequency)."""
    return count("seed", "seed", default, low=0, high=SEED_MAX, meaning=meaning)


# ---------------------------------------------------------------------------------------------------------
# The shared declarations

#: The paper's parameters and the Part I ones several chapters reuse: name -> declaration.
SHARED: dict[str, Param] = {
    p.name: p
    for p in (
        quantity("m", "m", 1.0, unit="kg", low=1e-3, high=1e3, meaning="mass"),
        quantity("k", "k", 20.0, unit="N/m", low=1e-3, high=1e6, meaning="spring stiffness"),
        positive("F0", "F_0", 5.0, unit="N", high=1e4, meaning="force amplitude"),
        positive(
            "t_end", "t_end", 50.0, unit="s", high=1e3, meaning="end of the simulated window, from rest at time zero"
        ),
        frequency("omega_ref", "ω_ref", 3.0, high=1e3, meaning="reference forcing frequency"),
        frequency("omega_res", "ω_res", 4.47, high=1e3, meaning='the paper\'s "resonant" forcing frequency'),
        damping(
            "c_low",
            "c_low",
            0.1,
            low=-1e4,
            high=1e4,
            meaning="low damping coefficient (0: undamped, < 0: self-excited)",
        ),
        damping("c_nominal", "c_nom", 0.5, low=-1e4, high=1e4, meaning="nominal damping coefficient"),
        damping("c_high", "c_high", 15.0, low=-1e4, high=1e4, meaning="high damping coefficient"),
        Param(
            name="dampings",
            symbol="c",
            default=(),
            unit="N s/m",
            low=-1e4,
            high=1e4,
            items=(1, 6),
            default_from=("c_low", "c_nominal", "c_high"),
            meaning="the dampings compared at the resonant frequency (none given: the low, nominal and high dampings)",
        ),  # fmt: skip
        count(
            "n_points", "N_pts", 5001, low=2, high=min(200_001, N_POINTS_MAX), meaning="output samples over the window"
        ),
    )
}

#: The paper's model and window in the paper's order: the parameters of chapters 1, 2 and 4.
PAPER_MODEL = ("m", "k", "F0", "t_end", "omega_ref", "omega_res", "c_low", "c_nominal", "c_high", "n_points")

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


def shared_params(*names: str) -> tuple[Param, ...]:
    """The shared declarations of ``names``, unchanged, in that order (:func:`shared` changes one)."""
    return tuple(shared(name) for name in names)


def _declaration(name: str, kind: str, fields: dict) -> Param:
    """One line of a ``params.toml``: parameter ``name`` built by the shape ``kind`` from ``fields``."""
    if kind == "shared":
        return shared(name, **fields)
    if kind == "seed":
        if name != "seed":
            raise ValueError(f"parameter {name!r} is declared a seed: the seed parameter is named 'seed'")
        return seed(**fields)
    if kind == "param":  # any other: the fields of Param itself
        return Param(name=name, **fields)
    builders = {"quantity": quantity, "positive": positive, "frequency": frequency, "damping": damping,
                "ratio": ratio, "count": count}  # fmt: skip
    if kind not in builders:
        allowed = ", ".join(["shared", "seed", "param", *builders])
        raise ValueError(f"parameter {name!r} is of kind {kind!r}: allowed {allowed}")
    return builders[kind](name, **fields)


def declared(package: str, *, together: tuple[Callable[[dict], None], ...] = (), name: str = "params.toml") -> Schema:
    """The schema a chapter declares as data in ``params.toml`` of its package, with the rules that tie its values.

    The file names the chapter's notebook (``notebook = "08_tmd"``) and, in its ``[params]`` table in the
    chapter's order, one declaration a parameter: its ``kind`` (``"shared"``, a shape of this module:
    ``"quantity"``, ``"positive"``, ``"frequency"``, ``"damping"``, ``"ratio"``, ``"count"``, ``"seed"``, or
    ``"param"`` for the fields of :class:`~vibration.book.presentation.schema.Param` itself) and the arguments of that
    shape: ``mu = {kind = "positive", symbol = "μ", default = 0.05, unit = "", high = 1.0, meaning = "..."}``;
    ``m = {kind = "shared", meaning = "primary mass"}`` takes the shared declaration, changing only its meaning.

    >>> s = declared("vibration.book.chapters.tmd")
    >>> s.notebook, s["m"].meaning, s["m"].unit, s["mu"].low_open
    ('08_tmd', 'primary mass', 'kg', True)
    """
    data = tomllib.loads(files(package).joinpath(name).read_text(encoding="utf-8"))
    params = []
    for param, fields in data["params"].items():
        rest = dict(fields)
        params.append(_declaration(param, rest.pop("kind"), rest))
    return Schema(notebook=data["notebook"], params=tuple(params), together=together)


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
    named = {n: p.get(n) for n in ("c_low", "c_nominal", "c_high")}
    named |= {f"dampings[{i}]": x for i, x in enumerate(p.get("dampings") or ())}
    dampings = [x for x in named.values() if x is not None]
    for name, c in named.items():
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


#: How a chapter's bound on one parameter compares: relation -> (test, the rule's name).
_RELATIONS = {">": (operator.gt, "above"), "<": (operator.lt, "below"), ">=": (operator.ge, "at_least")}


def _bound(name: str, relation: str, bound: float, unit: str, why: str) -> Callable[[dict], None]:
    """A rule: parameter ``name`` stands in ``relation`` to ``bound`` in this chapter (its shared range allows more)."""
    holds, word = _RELATIONS[relation]

    def rule(p: dict) -> None:
        if not holds(p[name], bound):
            raise ParameterError(
                f"{name} = {p[name]!r} {unit} is out of range for this chapter: "
                f"allowed {name} {relation} {bound:g} {unit} ({why})"
            )

    rule.__name__ = f"{name}_{word}_{bound:g}"
    return rule


def above(name: str, bound: float, unit: str, *, why: str) -> Callable[[dict], None]:
    """A rule: parameter ``name`` must exceed ``bound`` in this chapter (its shared range allows more).

    >>> above("c", 0.0, "N s/m", why="damped")({"c": 0.0})
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: c = 0.0 N s/m is out of range for this chapter: allowed c > 0 N s/m (damped)
    """
    return _bound(name, ">", bound, unit, why)


def below(name: str, bound: float, unit: str, *, why: str) -> Callable[[dict], None]:
    """A rule: parameter ``name`` must stay below ``bound`` in this chapter."""
    return _bound(name, "<", bound, unit, why)


def at_least(name: str, bound: float, unit: str, *, why: str) -> Callable[[dict], None]:
    """A rule: parameter ``name`` must be at least ``bound`` in this chapter."""
    return _bound(name, ">=", bound, unit, why)


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
