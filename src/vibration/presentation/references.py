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


@dataclass(frozen=True)
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
    Reference("paper", "(no authors named)", None, PAPER_TITLE, PAPER_KNOWN, "Part I"),
    Reference("den-hartog-1931", "Den Hartog J. P.", 1931,
              "Forced vibrations with combined Coulomb and viscous friction",
              "Transactions of the ASME 53 (APM-53-9), 107–115", "chapter 12"),
    Reference("den-hartog-1956", "Den Hartog J. P.", 1956, "Mechanical Vibrations", "4th ed., McGraw-Hill",
              "chapter 8"),
    Reference("warburton-1982", "Warburton G. B.", 1982,
              "Optimum absorber parameters for various combinations of response and excitation parameters",
              "Earthquake Engineering and Structural Dynamics 10 (3), 381–401", "chapter 8"),
    Reference("nishihara-asami-2002", "Nishihara O. and Asami T.", 2002,
              "Closed-form solutions to the exact optimizations of dynamic vibration absorbers (minimizations of "
              "the maximum amplitude magnification factors)",
              "Journal of Vibration and Acoustics 124 (4), 576–582", "chapter 8"),
    Reference("chopra-2012", "Chopra A. K.", 2012, "Dynamics of Structures", "4th ed., Prentice Hall", "chapter 8"),
    Reference("karnopp-1974", "Karnopp D., Crosby M. J. and Harwood R. A.", 1974,
              "Vibration control using semi-active force generators",
              "Journal of Engineering for Industry 96 (2), 619–626", "chapter 7"),
    Reference("dyke-1996", "Dyke S. J., Spencer B. F., Sain M. K. and Carlson J. D.", 1996,
              "Modeling and control of magnetorheological dampers for seismic response reduction",
              "Smart Materials and Structures 5 (5), 565–575", "chapter 7"),
    Reference("spencer-1997", "Spencer B. F., Dyke S. J., Sain M. K. and Carlson J. D.", 1997,
              "Phenomenological model for magnetorheological dampers",
              "Journal of Engineering Mechanics 123 (3), 230–238", "chapter 7"),
    Reference("singer-seering-1990", "Singer N. C. and Seering W. P.", 1990,
              "Preshaping command inputs to reduce system vibration",
              "Journal of Dynamic Systems, Measurement, and Control 112 (1), 76–82", "chapter 7"),
    Reference("bryson-ho-1975", "Bryson A. E. and Ho Y.-C.", 1975, "Applied Optimal Control",
              "Hemisphere", "chapter 7 (weights of the LQR)"),
    Reference("fehlberg-1969", "Fehlberg E.", 1969,
              "Low-order classical Runge–Kutta formulas with stepsize control and their application to some heat "
              "transfer problems", "NASA Technical Report R-315", "chapter 3"),
    Reference("dormand-prince-1980", "Dormand J. R. and Prince P. J.", 1980,
              "A family of embedded Runge–Kutta formulae", "Journal of Computational and Applied Mathematics 6 (1), "
              "19–26", "chapters 1 and 3"),
    Reference("ueda-1979", "Ueda Y.", 1979, "Randomly transitional phenomena in the system governed by Duffing's "
              "equation", "Journal of Statistical Physics 20 (2), 181–196", "chapter 9"),
    Reference("kovacic-brennan-2011", "Kovacic I. and Brennan M. J. (eds)", 2011,
              "The Duffing Equation: Nonlinear Oscillators and their Behaviour", "Wiley", "chapter 9"),
    Reference("benettin-1976", "Benettin G., Galgani L. and Strelcyn J.-M.", 1976,
              "Kolmogorov entropy and numerical experiments", "Physical Review A 14 (6), 2338–2345", "chapter 9"),
    Reference("benettin-1980", "Benettin G., Galgani L., Giorgilli A. and Strelcyn J.-M.", 1980,
              "Lyapunov characteristic exponents for smooth dynamical systems and for Hamiltonian systems; a method "
              "for computing all of them", "Meccanica 15, 9–20 and 21–30", "chapter 9"),
    Reference("wolf-1985", "Wolf A., Swift J. B., Swinney H. L. and Vastano J. A.", 1985,
              "Determining Lyapunov exponents from a time series", "Physica D 16 (3), 285–317", "chapter 9"),
    Reference("sprott-2003", "Sprott J. C.", 2003, "Chaos and Time-Series Analysis", "Oxford University Press",
              "chapter 9 (published Lyapunov exponent)"),
    Reference("kalman-1960", "Kalman R. E.", 1960, "A new approach to linear filtering and prediction problems",
              "Journal of Basic Engineering 82 (1), 35–45", "chapter 10"),
    Reference("page-1954", "Page E. S.", 1954, "Continuous inspection schemes", "Biometrika 41 (1/2), 100–115",
              "chapter 10"),
    Reference("brook-evans-1972", "Brook D. and Evans D. A.", 1972,
              "An approach to the probability distribution of CUSUM run length", "Biometrika 59 (3), 539–549",
              "chapter 10"),
    Reference("siegmund-1985", "Siegmund D.", 1985, "Sequential Analysis: Tests and Confidence Intervals",
              "Springer", "chapter 10"),
    Reference("mania-2018", "Mania H., Guy A. and Recht B.", 2018,
              "Simple random search of static linear policies is competitive for reinforcement learning",
              "Advances in Neural Information Processing Systems 31", "chapter 11"),
    Reference("hansen-2016", "Hansen N.", 2016, "The CMA evolution strategy: a tutorial", "arXiv:1604.00772",
              "chapter 11"),
    Reference("newey-west-1987", "Newey W. K. and West K. D.", 1987,
              "A simple, positive semi-definite, heteroskedasticity and autocorrelation consistent covariance "
              "matrix", "Econometrica 55 (3), 703–708", "chapter 12"),
    Reference("akaike-1974", "Akaike H.", 1974, "A new look at the statistical model identification",
              "IEEE Transactions on Automatic Control 19 (6), 716–723", "chapter 12 (information criterion)"),
    Reference("wilson-1927", "Wilson E. B.", 1927, "Probable inference, the law of succession, and statistical "
              "inference", "Journal of the American Statistical Association 22 (158), 209–212",
              "chapters 10 and 12 (binomial intervals)"),
)  # fmt: skip


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
