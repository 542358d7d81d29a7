"""Chapter 2, the paper's claims audited: its parameters, declared once.

The runner range-checks ``-p`` values with :data:`SCHEMA`, a test checks the notebook's parameters
cell against it, and the chapter's computation takes a :class:`Params` record built from it.
"""

from __future__ import annotations

from vibration.presentation.parameters import paper_window, shared
from vibration.presentation.schema import Schema

SCHEMA = Schema(
    notebook="02_claims_audit",
    params=(
        shared("m"),
        shared("k"),
        shared("F0"),
        shared("t_end"),
        shared("omega_ref"),
        shared("omega_res", meaning='the paper\'s "resonant" forcing frequency'),
        shared("c_low"),
        shared("c_nominal"),
        shared("c_high"),
        shared("n_points"),
    ),
    together=(paper_window,),
)

Params = SCHEMA.record_type()
