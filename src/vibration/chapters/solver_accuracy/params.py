"""Chapter 3, solver accuracy: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import paper_window, shared
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="03_solver_accuracy",
    params=(
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("t_end"),
        shared("omega_res", meaning='the paper\'s "resonant" forcing frequency'),
        shared("c_nominal"),
        shared("n_points"),
    ),
    together=(paper_window,),
)

Params = SCHEMA.record_type()
