"""Chapter 8's registry of absorber tunings: one frozen :class:`Design` per tuning, named once.

The study's results are keyed by these records (``study.scores[HINF]``), never by display strings or
tuple positions; tables, figures and sentences read each tuning's words from its record.

>>> [d.key for d in TUNINGS]
['den_hartog', 'hinf_closed', 'h2_closed', 'hinf', 'h2', 'robust']
>>> HINF.name, HINF.closed_form, [d.key for d in DESIGNS]
('H∞ optimum', False, ['den_hartog', 'hinf', 'h2', 'robust'])
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib.resources import files

__all__ = [
    "CLOSED",
    "DEN_HARTOG",
    "DESIGNS",
    "H2",
    "H2_CLOSED",
    "HINF",
    "HINF_CLOSED",
    "OPTIMA",
    "ROBUST",
    "RULES",
    "TUNINGS",
    "Design",
]


@dataclass(frozen=True, kw_only=True)
class Design:
    """One tuning of the absorber (mass ratio μ given): how it is named, drawn and told in the chapter."""

    key: str  # identifier (letters, digits and _): key-result names, "worst_peak_<key>"
    name: str  # its name as a table row and a key result's meaning: "H∞ optimum"
    closed_form: bool  # derived for an undamped primary (True) or optimised for the actual damping (False)
    case: str  # case of the book's visual language that draws its line (presentation.style)
    look: str  # its line in a caption's words: "purple", "green dashed"
    legend: str  # legend label (mathtext)
    noun: str  # in a sentence, with its article: "the H∞ optimum"
    prose: str  # in a sentence, after an article the sentence supplies: "H∞ optimum"
    curve: str  # a caption's name for its curve within its panel's group: "H∞"


def _read() -> tuple[Design, ...]:
    text = files(__package__).joinpath("designs.toml").read_text(encoding="utf-8")
    return tuple(Design(**entry) for entry in tomllib.loads(text)["design"])


#: Every tuning of the chapter: Den Hartog's rule and the closed-form H∞ (Nishihara and Asami) and H2
#: (Warburton) optima of an undamped primary, then the numerical optima for the primary's actual damping
#: of the nominal peak (H∞), the rms displacement under white noise (H2) and the worst peak over the
#: band of stiffness errors (robust min-max). The words are in ``designs.toml``.
TUNINGS = _read()
if [d.key for d in TUNINGS] != ["den_hartog", "hinf_closed", "h2_closed", "hinf", "h2", "robust"]:
    raise ValueError(f"designs.toml lists the tunings {[d.key for d in TUNINGS]}, not the chapter's six in order")
DEN_HARTOG, HINF_CLOSED, H2_CLOSED, HINF, H2, ROBUST = TUNINGS
#: The rules of the tunings table (every mass ratio): the three closed forms and the H∞ optimum.
RULES = (DEN_HARTOG, HINF_CLOSED, H2_CLOSED, HINF)
#: The designs compared on the actual primary: the classical rule and the optimum of each criterion.
DESIGNS = (DEN_HARTOG, HINF, H2, ROBUST)
#: The two groups the figures draw side by side: tunings for an undamped primary, optima for the actual damping.
CLOSED = tuple(d for d in TUNINGS if d.closed_form)
OPTIMA = tuple(d for d in TUNINGS if not d.closed_form)
