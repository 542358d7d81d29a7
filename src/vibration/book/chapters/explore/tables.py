"""Chapter 5's readout table, a function of one :class:`ExploreStudy`.

Examples
--------
>>> from vibration.book.chapters.explore.study import explore_study
>>> print(repr(readout_table(explore_study())).splitlines()[3].split())
['natural', 'frequency', 'ωₙ', '4.4721', 'rad/s']
"""

from __future__ import annotations

from vibration.book.chapters.explore.study import ExploreStudy
from vibration.book.presentation.numbers import sig as num
from vibration.book.presentation.tables import Table, columns, text_rows

#: The readout's lines: the quantity as the reader reads it, its field of the readout, its unit (none for a ratio).
_READOUT = text_rows(
    """
    natural frequency ωₙ                omega_n         rad/s
    natural frequency fₙ                f_n             Hz
    forcing frequency ω                 omega           rad/s
    forcing frequency f                 f               Hz
    frequency ratio ω/ωₙ                ratio
    damping ratio ζ                     zeta
    regime                              regime
    magnification |X|/(F₀/k)            magnification
    steady-state amplitude |X|          amplitude       m
    peak |x| in the window              peak            m
    2 % settling time                   settling        s
    steady state reached in the window  steady_reached
    time window                         t_end           s
    """
)


def readout_table(study: ExploreStudy) -> Table:
    """The explorer's readout at the starting point, five significant digits."""
    r = study.start
    rows = [{"q": q, "v": getattr(r, attr), "u": unit[0] if unit else ""} for q, attr, *unit in _READOUT]
    return Table(
        rows=rows,
        columns=columns(
            """
            q  quantity
            v  value     5
            u  unit
            """
        ),
        caption=(
            f"The explorer's readout at its starting point (ω = {num(r.omega)} rad/s, c = {num(study.c_start)} "
            "N s/m): what the live explorer shows before any slider moves."
        ),
        name="tab-explore-start",
    )
