"""Which Runge-Kutta pair SciPy's ``RK45`` is: its nodes as exact fractions against the candidates'."""

from __future__ import annotations

from fractions import Fraction

from scipy.integrate import RK45

__all__ = ["RK_PAIRS", "rk45_pair", "scipy_rk45_nodes"]

#: Nodes c_i of the two 5(4)/4(5) pairs the paper's "RK45" could mean
#: (Dormand & Prince 1980; Fehlberg 1969), to identify SciPy's tableau.
RK_PAIRS = {
    "Dormand-Prince 5(4)": (0, Fraction(1, 5), Fraction(3, 10), Fraction(4, 5), Fraction(8, 9), 1),
    "Runge-Kutta-Fehlberg 4(5)": (0, Fraction(1, 4), Fraction(3, 8), Fraction(12, 13), 1, Fraction(1, 2)),
}


def scipy_rk45_nodes() -> tuple[Fraction, ...]:
    """Nodes ``c_i`` of SciPy's ``RK45`` tableau as exact fractions.

    Examples
    --------
    >>> ", ".join(str(c) for c in scipy_rk45_nodes())
    '0, 1/5, 3/10, 4/5, 8/9, 1'
    """
    return tuple(Fraction(float(c)).limit_denominator(1000) for c in RK45.C)


def rk45_pair() -> str:
    """Name of the Runge-Kutta pair whose nodes equal SciPy's ``RK45.C``.

    Examples
    --------
    >>> rk45_pair()
    'Dormand-Prince 5(4)'
    """
    nodes = scipy_rk45_nodes()
    for name, ref in RK_PAIRS.items():
        if nodes == tuple(Fraction(x) for x in ref):
            return name
    return "unknown: nodes " + ", ".join(str(c) for c in nodes)
