"""Chapter 8's registry of absorber tunings: one frozen :class:`Design` per tuning, named once.

The study's results are keyed by these records (``study.scores[HINF]``), never by display strings or
tuple positions; tables, figures and sentences read each tuning's words from its record.

>>> [d.key for d in TUNINGS]
['den_hartog', 'hinf_closed', 'h2_closed', 'hinf', 'h2', 'robust']
>>> HINF.name, HINF.closed_form, [d.key for d in DESIGNS]
('H∞ optimum', False, ['den_hartog', 'hinf', 'h2', 'robust'])
"""

from __future__ import annotations

from dataclasses import dataclass

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


DEN_HARTOG = Design(
    key="den_hartog",
    name="Den Hartog",
    closed_form=True,
    case="Den Hartog",
    look="orange",
    legend="Den Hartog",
    noun="Den Hartog's rule",
    prose="Den Hartog's rule",
    curve="Den Hartog's rule",
)
HINF_CLOSED = Design(
    key="hinf_closed",
    name="H∞ closed form, ζₚ = 0",
    closed_form=True,
    case="exact",
    look="black dashed",
    legend=r"H$\infty$ closed form",
    noun="the closed-form H∞ optimum",
    prose="closed-form H∞ tuning of an undamped primary",
    curve="closed-form H∞",
)
H2_CLOSED = Design(
    key="h2_closed",
    name="H2 closed form, ζₚ = 0",
    closed_form=True,
    case="H2",
    look="sky blue dash-dot",
    legend="H2 closed form (Warburton)",
    noun="Warburton's H2 optimum",
    prose="Warburton's H2 tuning",
    curve="Warburton's H2",
)
HINF = Design(
    key="hinf",
    name="H∞ optimum",
    closed_form=False,
    case="H∞",
    look="purple",
    legend=r"H$\infty$ optimum",
    noun="the H∞ optimum",
    prose="H∞ optimum",
    curve="H∞",
)
H2 = Design(
    key="h2",
    name="H2 optimum",
    closed_form=False,
    case="H2",
    look="sky blue dash-dot",
    legend="H2 optimum",
    noun="the H2 optimum",
    prose="H2 optimum",
    curve="H2",
)
ROBUST = Design(
    key="robust",
    name="robust min-max",
    closed_form=False,
    case="robust",
    look="green dashed",
    legend="robust min-max",
    noun="the robust min-max design",
    prose="robust min-max design",
    curve="robust min-max",
)

#: Every tuning of the chapter: Den Hartog's rule and the closed-form H∞ (Nishihara and Asami) and H2
#: (Warburton) optima of an undamped primary, then the numerical optima for the primary's actual damping
#: of the nominal peak (H∞), the rms displacement under white noise (H2) and the worst peak over the
#: band of stiffness errors (robust min-max).
TUNINGS = (DEN_HARTOG, HINF_CLOSED, H2_CLOSED, HINF, H2, ROBUST)
#: The rules of the tunings table (every mass ratio): the three closed forms and the H∞ optimum.
RULES = (DEN_HARTOG, HINF_CLOSED, H2_CLOSED, HINF)
#: The designs compared on the actual primary: the classical rule and the optimum of each criterion.
DESIGNS = (DEN_HARTOG, HINF, H2, ROBUST)
#: The two groups the figures draw side by side: tunings for an undamped primary, optima for the actual damping.
CLOSED = tuple(d for d in TUNINGS if d.closed_form)
OPTIMA = tuple(d for d in TUNINGS if not d.closed_form)
