"""Chapter 7, control: every run of the chapter, once, as frozen records (no prose).

:func:`control_study` takes the chapter's validated :class:`~vibration.book.chapters.control.params.Params`
and runs the physics of :mod:`vibration.physics.control` three times over, one module each:

* :func:`~.active.active_study`: passive, PD, LQR and PID at the forcing ``F0 sin(omega_res t)``, the LQR
  trade-off along its force weight, the force-limited PID move under three integrator treatments,
  the loops' costs (delay margin, noise) and the negative-damping (flutter) plant;
* :func:`~.semi_active.semi_active_study`: the base-excited suspension, swept in frequency and run in time
  with the ideal, on-off and clipped skyhook and a scaled MR damper;
* :func:`~.shaping.shaping_study`: a point-to-point move, unshaped and with ZV and ZVD shapers designed on a
  model whose natural frequency is off by ``freq_error``.

Every name of those modules a reader or a chapter module uses is importable from here too. Figures, tables
and sentences (modules ``figures``, ``tables``, ``text``) read only these records, so a run with other
parameters never contradicts itself.

Examples
--------
>>> s = shaping_study(Params(move=0.1, freq_error=0.1), n_ratio=21)
>>> s.shapers["ZV"].kind, round(float(s.residual["ZV"]), 3)
('ZV', 0.143)
"""

from __future__ import annotations

from dataclasses import dataclass

from vibration.book.chapters.control.active import (
    DESIGNS,
    FEASIBLE_FRACTION,
    MOVE_SCHEMES,
    ActiveStudy,
    ClosedLoop,
    Design,
    FlutterCase,
    Hold,
    MoveRun,
    Tradeoff,
    active_study,
    loop_amplitude,
)
from vibration.book.chapters.control.params import Params
from vibration.book.chapters.control.semi_active import (
    REFINE_STEPS,
    SemiActiveFindings,
    SemiActiveStudy,
    semi_active_study,
)
from vibration.book.chapters.control.shaping import SHAPER_LEVEL, ShapingStudy, shaping_study
from vibration.book.chapters.control.steady import STEADY_PERIODS, t_steady

# ----------------------------------------------------------------------------- the chapter


@dataclass(frozen=True, kw_only=True)
class ControlStudy:
    """The whole chapter: its parameters and the three studies."""

    params: Params
    active: ActiveStudy
    semi: SemiActiveStudy
    shaping: ShapingStudy


def control_study(params: Params | None = None, **values) -> ControlStudy:
    """Chapter 7 on one parameter record: its active, semi-active and input-shaping studies.

    ``params`` is the chapter's validated record (plant, gains, force limit, suspension, move), or the values
    are given as keyword arguments and checked by the schema. Returns the three studies' frozen records
    (``active``, ``semi``, ``shaping``) with the parameters they ran on.
    """
    p = params if params is not None else Params.from_values(values)
    return ControlStudy(params=p, active=active_study(p), semi=semi_active_study(p), shaping=shaping_study(p))


__all__ = [
    "DESIGNS",
    "FEASIBLE_FRACTION",
    "MOVE_SCHEMES",
    "REFINE_STEPS",
    "SHAPER_LEVEL",
    "STEADY_PERIODS",
    "ActiveStudy",
    "ClosedLoop",
    "ControlStudy",
    "Design",
    "FlutterCase",
    "Hold",
    "MoveRun",
    "SemiActiveFindings",
    "SemiActiveStudy",
    "ShapingStudy",
    "Tradeoff",
    "active_study",
    "control_study",
    "loop_amplitude",
    "semi_active_study",
    "shaping_study",
    "t_steady",
]
