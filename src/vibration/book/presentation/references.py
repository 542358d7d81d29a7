"""The book's bibliography: every work the text cites, one record each.

The audited paper's text names no authors, venue or year, so it is cited by its title and by what
its text shows (:data:`PAPER_KNOWN`).
:func:`bibliography_markdown` writes the book's References page; :func:`find` tells a test
whether a citation in the text (a surname and a year) is in the list.

Examples
--------
>>> find("Nishihara", 2002).key
'nishihara-asami-2002'
>>> find("Nobody", 1900) is None
True
>>> find("Hartog", 1931).surnames
('Den', 'Hartog')
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, kw_only=True)
class Reference:
    """One cited work."""

    key: str
    authors: str  # as printed, surnames first
    year: int | None
    title: str
    venue: str  # journal with volume and pages, or publisher
    note: str = ""  # where the book uses it

    @property
    def surnames(self) -> tuple[str, ...]:
        """Surnames of the authors, for matching citations in the text."""
        out = []
        for person in self.authors.replace(" and ", ", ").split(", "):
            for word in person.split():  # the words before the initials: "Den Hartog J. P." -> Den, Hartog
                if word.endswith(".") or word.startswith("("):
                    break
                out.append(word)
        return tuple(out)


PAPER_TITLE = "The Effect of Resonance and Damping on Dynamic System Stability: A Numerical Approach"

#: What is known of the audited paper beyond its title: its text names no authors, venue or year.
PAPER_KNOWN = (
    "Authors, venue and year not stated: the text names none and has no reference list. It has an abstract, "
    "sections 2 to 5 (Material and Method to Conclusion) and a closing section on application areas, and solves "
    "its model with SciPy's initial-value solver, which first appeared in SciPy 1.0 (2017): the paper dates from "
    "2017 or later"
)

REFERENCES: tuple[Reference, ...] = (
    Reference(
        key="paper", authors="(no authors named)", year=None, title=PAPER_TITLE, venue=PAPER_KNOWN, note="Part I"
    ),
    Reference(
        key="den-hartog-1931",
        authors="Den Hartog J. P.",
        year=1931,
        title="Forced vibrations with combined Coulomb and viscous friction",
        venue="Transactions of the ASME 53 (APM-53-9), 107–115",
        note="chapter 12",
    ),
    Reference(
        key="den-hartog-1956",
        authors="Den Hartog J. P.",
        year=1956,
        title="Mechanical Vibrations",
        venue="4th ed., McGraw-Hill",
        note="chapter 8",
    ),
    Reference(
        key="warburton-1982",
        authors="Warburton G. B.",
        year=1982,
        title="Optimum absorber parameters for various combinations of response and excitation parameters",
        venue="Earthquake Engineering and Structural Dynamics 10 (3), 381–401",
        note="chapter 8",
    ),
    Reference(
        key="nishihara-asami-2002",
        authors="Nishihara O. and Asami T.",
        year=2002,
        title="Closed-form solutions to the exact optimizations of dynamic vibration absorbers (minimizations of "
        "the maximum amplitude magnification factors)",
        venue="Journal of Vibration and Acoustics 124 (4), 576–582",
        note="chapter 8",
    ),
    Reference(
        key="chopra-2012",
        authors="Chopra A. K.",
        year=2012,
        title="Dynamics of Structures",
        venue="4th ed., Prentice Hall",
        note="chapter 8",
    ),
    Reference(
        key="karnopp-1974",
        authors="Karnopp D., Crosby M. J. and Harwood R. A.",
        year=1974,
        title="Vibration control using semi-active force generators",
        venue="Journal of Engineering for Industry 96 (2), 619–626",
        note="chapter 7",
    ),
    Reference(
        key="dyke-1996",
        authors="Dyke S. J., Spencer B. F., Sain M. K. and Carlson J. D.",
        year=1996,
        title="Modeling and control of magnetorheological dampers for seismic response reduction",
        venue="Smart Materials and Structures 5 (5), 565–575",
        note="chapter 7",
    ),
    Reference(
        key="spencer-1997",
        authors="Spencer B. F., Dyke S. J., Sain M. K. and Carlson J. D.",
        year=1997,
        title="Phenomenological model for magnetorheological dampers",
        venue="Journal of Engineering Mechanics 123 (3), 230–238",
        note="chapter 7",
    ),
    Reference(
        key="singer-seering-1990",
        authors="Singer N. C. and Seering W. P.",
        year=1990,
        title="Preshaping command inputs to reduce system vibration",
        venue="Journal of Dynamic Systems, Measurement, and Control 112 (1), 76–82",
        note="chapter 7",
    ),
    Reference(
        key="bryson-ho-1975",
        authors="Bryson A. E. and Ho Y.-C.",
        year=1975,
        title="Applied Optimal Control",
        venue="Hemisphere",
        note="chapter 7 (weights of the LQR)",
    ),
    Reference(
        key="fehlberg-1969",
        authors="Fehlberg E.",
        year=1969,
        title="Low-order classical Runge–Kutta formulas with stepsize control and their application to some heat "
        "transfer problems",
        venue="NASA Technical Report R-315",
        note="chapter 3",
    ),
    Reference(
        key="dormand-prince-1980",
        authors="Dormand J. R. and Prince P. J.",
        year=1980,
        title="A family of embedded Runge–Kutta formulae",
        venue="Journal of Computational and Applied Mathematics 6 (1), 19–26",
        note="chapters 1 and 3",
    ),
    Reference(
        key="ueda-1979",
        authors="Ueda Y.",
        year=1979,
        title="Randomly transitional phenomena in the system governed by Duffing's equation",
        venue="Journal of Statistical Physics 20 (2), 181–196",
        note="chapter 9",
    ),
    Reference(
        key="kovacic-brennan-2011",
        authors="Kovacic I. and Brennan M. J. (eds)",
        year=2011,
        title="The Duffing Equation: Nonlinear Oscillators and their Behaviour",
        venue="Wiley",
        note="chapter 9",
    ),
    Reference(
        key="benettin-1976",
        authors="Benettin G., Galgani L. and Strelcyn J.-M.",
        year=1976,
        title="Kolmogorov entropy and numerical experiments",
        venue="Physical Review A 14 (6), 2338–2345",
        note="chapter 9",
    ),
    Reference(
        key="benettin-1980",
        authors="Benettin G., Galgani L., Giorgilli A. and Strelcyn J.-M.",
        year=1980,
        title="Lyapunov characteristic exponents for smooth dynamical systems and for Hamiltonian systems; a method "
        "for computing all of them",
        venue="Meccanica 15, 9–20 and 21–30",
        note="chapter 9",
    ),
    Reference(
        key="wolf-1985",
        authors="Wolf A., Swift J. B., Swinney H. L. and Vastano J. A.",
        year=1985,
        title="Determining Lyapunov exponents from a time series",
        venue="Physica D 16 (3), 285–317",
        note="chapter 9",
    ),
    Reference(
        key="sprott-2003",
        authors="Sprott J. C.",
        year=2003,
        title="Chaos and Time-Series Analysis",
        venue="Oxford University Press",
        note="chapter 9 (published Lyapunov exponent)",
    ),
    Reference(
        key="kalman-1960",
        authors="Kalman R. E.",
        year=1960,
        title="A new approach to linear filtering and prediction problems",
        venue="Journal of Basic Engineering 82 (1), 35–45",
        note="chapter 10",
    ),
    Reference(
        key="page-1954",
        authors="Page E. S.",
        year=1954,
        title="Continuous inspection schemes",
        venue="Biometrika 41 (1/2), 100–115",
        note="chapter 10",
    ),
    Reference(
        key="brook-evans-1972",
        authors="Brook D. and Evans D. A.",
        year=1972,
        title="An approach to the probability distribution of CUSUM run length",
        venue="Biometrika 59 (3), 539–549",
        note="chapter 10",
    ),
    Reference(
        key="siegmund-1985",
        authors="Siegmund D.",
        year=1985,
        title="Sequential Analysis: Tests and Confidence Intervals",
        venue="Springer",
        note="chapter 10",
    ),
    Reference(
        key="mania-2018",
        authors="Mania H., Guy A. and Recht B.",
        year=2018,
        title="Simple random search of static linear policies is competitive for reinforcement learning",
        venue="Advances in Neural Information Processing Systems 31",
        note="chapter 11",
    ),
    Reference(
        key="hansen-2016",
        authors="Hansen N.",
        year=2016,
        title="The CMA evolution strategy: a tutorial",
        venue="arXiv:1604.00772",
        note="chapter 11",
    ),
    Reference(
        key="newey-west-1987",
        authors="Newey W. K. and West K. D.",
        year=1987,
        title="A simple, positive semi-definite, heteroskedasticity and autocorrelation consistent covariance matrix",
        venue="Econometrica 55 (3), 703–708",
        note="chapter 12",
    ),
    Reference(
        key="akaike-1974",
        authors="Akaike H.",
        year=1974,
        title="A new look at the statistical model identification",
        venue="IEEE Transactions on Automatic Control 19 (6), 716–723",
        note="chapter 12 (information criterion)",
    ),
    Reference(
        key="wilson-1927",
        authors="Wilson E. B.",
        year=1927,
        title="Probable inference, the law of succession, and statistical inference",
        venue="Journal of the American Statistical Association 22 (158), 209–212",
        note="chapters 10 and 12 (binomial intervals)",
    ),
)


def find(surname: str, year: int) -> Reference | None:
    """The reference with that author surname and year, if the bibliography holds it."""
    for ref in REFERENCES:
        if ref.year == year and any(s.lower() == surname.lower() for s in ref.surnames):
            return ref
    return None


def bibliography_markdown() -> str:
    """The book's References page (MyST Markdown), in author order, the audited paper first."""
    lines = ["# References", "", "Every work the book cites. The audited paper's text names no authors, venue or "
             "year; it is cited by its title and by what its text shows.", ""]  # fmt: skip
    paper, rest = REFERENCES[0], sorted(REFERENCES[1:], key=lambda r: (r.authors.lower(), r.year or 0))
    for ref in (paper, *rest):
        year = f" ({ref.year})" if ref.year else ""
        who = "" if ref.key == "paper" else f"{ref.authors}{year}. "
        used = f" Used in {ref.note}." if ref.note else ""
        lines.append(f"(ref-{ref.key})=\n{who}*{ref.title}*. {ref.venue}.{used}\n")
    return "\n".join(lines)


def paper_citation() -> str:
    """The audited paper's full citation as far as it is known (front page, print edition)."""
    return f"*{PAPER_TITLE}*. {PAPER_KNOWN}."
