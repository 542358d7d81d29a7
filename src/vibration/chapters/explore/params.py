"""Chapter 5, explore the parameters: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import paper_window, shared
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="05_explore",
    params=(
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("t_end", meaning="end of the time window, from rest at time zero"),
        shared("omega_res", meaning='starting forcing frequency, the paper\'s "resonant" one'),
        shared("c_nominal", meaning="starting damping coefficient, the paper's nominal one"),
    ),
    together=(paper_window,),
)

Params = SCHEMA.record_type()
