"""How chapter 9 writes numbers: the book's format (:mod:`vibration.book.presentation.numbers`), plus the tolerances
of its machine-dependent values.

Tables keep trailing zeros (:func:`~vibration.book.presentation.numbers.column`, one precision per column);
sentences use :func:`~vibration.book.presentation.numbers.sig`. A chaotic trajectory amplifies the last bit of
every rounding, so the Lyapunov exponents, their standard errors and everything computed from them differ
between numerical environments (compiled code for another instruction set, another BLAS). They are written
like any other number, through :class:`~vibration.book.presentation.numbers.Approx`, with the tolerances below;
the regression comparison applies them.

The tolerances were chosen from measurement. Under the portable environment of the regression run
(generic CPU target, no AVX, one thread) and under this machine's default one the chapter's numbers came out
bit for bit the same; but any other rounding of one operation sends a chaotic trajectory elsewhere, and what
it then gives was measured by starting every run one unit in the last place away (up and down). The
exponents moved by up to 0.9 of their standard error (0.5 % pooled, 4.5 % over the 2000-period row), the
standard errors by a factor up to 1.9, the runs' z-scores by up to 1.9, their χ² from 5.1 to 11, the
pooled exponent's difference from the published one by 15 % (its z-score by 32 %) and the averaging length
derived from it by a factor 2.7. The periodic case, the Floquet exponent and every number of the
harmonic-balance, sweep and continuation parts did not move in the digits printed, and print plainly.

Examples
--------
>>> within(0.00037), within(0.0042), within(0.03)
('0.1 %', '0.5 %', '5 %')
>>> apm(0.10417, 0.00093, 20_000)  # doctest: +ELLIPSIS
'<span ... data-value="0.10417" data-tol="a0.0042">0.1042</span> ± <span ... data-tol="f3">0.0009</span>'
"""

from __future__ import annotations

import math
import re

from vibration.book.presentation.numbers import Approx, minus, percent, pm, sig

#: A chaotic run's exponent over N periods scatters with standard deviation σ₁/√N, σ₁ up to 0.18 1/s
#: (measured from the batch means); it may move by this many 1/s over √N, about five standard errors
#: (measured: up to 0.9 of one). The tolerance depends on N alone, so it reads the same on every machine.
EXPONENT_SPREAD = 0.6
#: Relative tolerance of a time inversely proportional to the pooled exponent (1/λ₁; measured 0.5 %).
INVERSE_RTOL = 0.05
#: Factor tolerance of a standard error by batch means (measured: up to 1.9).
ERROR_FACTOR = 3.0
#: Factor tolerance of the runs' χ² for 5 degrees of freedom (measured 5.1 to 11; a factor 10 around 5
#: covers its 1 % and 99.9 % points).
CHI2_FACTOR = 10.0
#: Absolute tolerance of a z-score of one run against the pooled value (measured: up to 1.9).
Z_ATOL = 5.0
#: Factor tolerance of the pooled exponent's difference from the published one, of its z-score and of its
#: share in percent (measured: 15 % and 32 %).
DIFFERENCE_FACTOR = 2.5
#: Factor tolerance of the averaging length a run needs to resolve that difference, which goes as the square
#: of the standard deviation over the difference (measured: a factor 2.7).
LENGTH_FACTOR = 10.0


def exponent_approx(value: float, n_periods: float) -> Approx:
    """A chaotic exponent (or λ₂ = −c/m − λ₁) from ``n_periods`` forcing periods, with its tolerance."""
    return Approx(value=value, atol=float(f"{EXPONENT_SPREAD / math.sqrt(n_periods):.2g}"))


def exponent(value: float, n_periods: float, digits: int = 4) -> str:
    """A chaotic exponent for a sentence (:func:`~vibration.book.presentation.numbers.sig`), with its tolerance."""
    return exponent_approx(value, n_periods).html(sig(value, digits))


def inverse(numerator: float, exponent_: float, digits: int = 2) -> str:
    """A time ``numerator / exponent_`` (1/λ₁, ln 10/λ₁, s) of the pooled exponent, with its tolerance."""
    value = numerator / exponent_
    return Approx(value=value, rtol=INVERSE_RTOL).html(sig(value, digits))


def apm(value: float, se: float, n_periods: float) -> str:
    """A chaotic exponent from ``n_periods`` periods ± its standard error
    (:func:`~vibration.book.presentation.numbers.pm`), each part with its tolerance; without a finite standard
    error the exponent alone, to three figures."""
    if not (math.isfinite(se) and se > 0):
        return exponent(value, n_periods, 3)
    m = re.fullmatch(r"(\(?)(.+) ± (.+?)(\)×10.+)?", pm(value, se))
    head, v, e, tail = m.group(1), m.group(2), m.group(3), m.group(4) or ""
    approx_v = exponent_approx(value, n_periods).html(v)
    return f"{head}{approx_v} ± {Approx(value=se, factor=ERROR_FACTOR).html(e)}{tail}"


def within(fraction: float, floor: float = 1e-3) -> str:
    """A relative difference as a round bound for a caption: the smallest of 0.1, 0.2, 0.5, 1, 2, 5, ... %
    at or above it (at least ``floor``), so the words do not move with the last digits."""
    step = floor
    while step < fraction:
        for factor in (2.0, 2.5, 2.0):  # 1 -> 2 -> 5 -> 10
            step *= factor
            if step >= fraction:
                break
    return percent(step)


def forcing_term(p) -> str:
    """Ueda's forcing as the captions write it: ``F cos t`` at 1 rad/s, else ``F cos(ω t)`` with its value."""
    return "F cos t" if p.omega_ueda == 1.0 else f"F cos({p.omega_ueda:g} t)"


def k3_text(k3: float) -> str:
    """The cubic stiffness as the captions and tables write it: ``k₃ = −1 N/m³``."""
    return minus(f"k₃ = {k3:g} N/m³")
