r"""The real oscillator on any laboratory's Pohl wheel: damping against amplitude, the law the data choose, the
brake at matched amplitude, steadiness by late drift, a calibrated prediction, and the paper's claims.

Pure computation on a folder read by :func:`vibration.physics.lab.load_lab_data` (logger files and a
manifest). The model, for the wheel angle :math:`\theta` (rad) under the measured drive angle :math:`\theta_d` (rad),

.. math::

    \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\theta_f\,\mathrm{sgn}\dot\theta + \beta\dot\theta|\dot\theta|
    + \alpha|\dot\theta|^n\mathrm{sgn}\dot\theta + \omega_n^2(\theta - \theta_0) = \omega_n^2\,G\,\theta_d(t),

with any subset of the damping terms (:data:`LAWS`), the resting angle :math:`\theta_0` and the drive gain
:math:`G` (rad of static wheel angle per rad of drive angle).

The computation lives in three modules, each stating its choices: :mod:`.damping` (the laws the free decays
choose, the comparison band, the brake law), :mod:`.driven` (steadiness by late drift, groups at one drive
frequency, sessions) and :mod:`.prediction` (the calibrated prediction by harmonic balance and by
simulation). :func:`real_oscillator_study` runs them on a folder into one :class:`RealOscillatorStudy`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

from vibration.book.chapters.real_oscillator.damping import (
    LAWS,
    PAPER_LAW,
    Setting,
    _band,
    _current_law,
    _setting,
    _setting_curves,
)
from vibration.book.chapters.real_oscillator.driven import (
    NO_SPREAD,
    Driven,
    Group,
    SessionSpread,
    SessionSummary,
    _driven,
    _groups,
    _sessions,
    driven_run,
    session_spread,
)
from vibration.book.chapters.real_oscillator.params import DEFAULT_LAB, Params
from vibration.book.chapters.real_oscillator.prediction import (
    Prediction,
    _predict,
    law_amplitude,
    simulated_amplitudes,
)
from vibration.physics.lab import (
    DampingCurve,
    DampingDifference,
    JointBrakeFit,
    LabData,
    compare_damping,
    joint_brake_fit,
    load_lab_data,
)
from vibration.physics.model import ParameterError
from vibration.physics.paper import data_dir


@dataclass(frozen=True, kw_only=True, eq=False)
class RealOscillatorStudy:
    """Everything the chapter shows, computed once from a folder."""

    params: Params
    folder: str
    data: LabData = field(repr=False)
    settings: tuple
    band: tuple | None
    comparisons: tuple  # (brake a, brake b, DampingDifference, JointBrakeFit)
    current_law: dict | None  # zeta0, k, stderrs and the currents used, when > 2 settings have currents
    driven: tuple
    groups: tuple
    predictions: dict  # (brake, law) -> Prediction
    sessions: tuple = ()  # SessionSummary per session of driven runs
    spread: SessionSpread = field(default_factory=lambda: NO_SPREAD)


# ----------------------------------------------------------------------------- helpers


def lab_folder(value: str) -> Path:
    """The folder a ``lab_data`` value names (the default is the package's copy of the lab data)."""
    if value == DEFAULT_LAB:
        return data_dir() / "lab_oscillator"
    return Path(value)


def best_prediction(st: RealOscillatorStudy) -> Prediction | None:
    """The prediction of smallest pooled error (None without predictions)."""
    ps = [p for p in st.predictions.values() if math.isfinite(p.pooled_error)]
    return min(ps, key=lambda p: p.pooled_error) if ps else None


def omega_n(st: RealOscillatorStudy) -> float:
    """The natural frequency (rad/s) of the last brake setting's Coulomb-and-viscous law (else its chosen law)."""
    s = st.settings[-1]
    return s.fits["coulomb+viscous"].mean["omega_n"] if "coulomb+viscous" in s.fits else s.fits[s.law].mean["omega_n"]


def steady_counts(st: RealOscillatorStudy) -> tuple[int, int, int, int]:
    """Steady runs, runs, steady runs within 5 % of ω_n, runs within 5 % of ω_n."""
    wn = omega_n(st)
    near = [d for d in st.driven if abs(d.omega / wn - 1.0) <= 0.05]
    return (
        sum(d.steady.steady for d in st.driven),
        len(st.driven),
        sum(d.steady.steady for d in near),
        len(near),
    )


# ----------------------------------------------------------------------------- the study


def real_oscillator_study(params: Params | None = None, **values) -> RealOscillatorStudy:
    """Compute the chapter from the folder ``params.lab_data``.

    Parameters
    ----------
    params : Params, optional
        The chapter's parameters (defaults otherwise); keyword ``values`` override them.

    Returns
    -------
    RealOscillatorStudy

    Raises
    ------
    ParameterError
        Bad parameters, or a folder without free decays (naming file, row and column where it is malformed).
    """
    params = Params.from_values({**(params.as_dict() if params else {}), **values})
    folder = lab_folder(params.lab_data)
    data = load_lab_data(folder)
    free = data.select(kind="free")
    if not free:
        raise ParameterError(f"lab_data = {params.lab_data!r}: the manifest lists no free decay: allowed at least one")
    brakes = list(dict.fromkeys(r.brake for r in free))
    curves = [_setting_curves(data.select(kind="free", brake=b)) for b in brakes]
    band = _band(curves) if len(brakes) > 1 else _band(curves[:1])
    settings = tuple(_setting(b, data.current(b), data.select(kind="free", brake=b), band) for b in brakes)
    comparisons = []
    if band is not None:
        ref = settings[0]
        for s in settings[1:]:
            try:
                d = compare_damping(ref.runs, s.runs, band)
                j = joint_brake_fit(ref.runs, s.runs)
            except ParameterError:
                continue
            comparisons.append((ref.brake, s.brake, d, j))
    driven = tuple(x for x in (_driven(r, params) for r in data.select(kind="driven")) if x is not None)
    groups = _groups(driven, params.frequency_tolerance)
    predictions = {}
    for s in settings:
        ds = [d for d in driven if d.run.brake == s.brake]
        if not ds:
            continue
        for law in s.fits:
            p = _predict(law, s, ds, params)
            if p is not None:
                predictions[(s.brake, law)] = p
    return RealOscillatorStudy(
        params=params,
        folder=str(folder),
        data=data,
        settings=settings,
        band=band,
        comparisons=tuple(comparisons),
        current_law=_current_law(settings),
        driven=driven,
        groups=groups,
        predictions=predictions,
        sessions=_sessions(driven),
        spread=session_spread(groups, params.frequency_tolerance),
    )


__all__ = [
    "LAWS",
    "PAPER_LAW",
    "DampingCurve",
    "DampingDifference",
    "Driven",
    "Group",
    "JointBrakeFit",
    "Prediction",
    "RealOscillatorStudy",
    "SessionSpread",
    "SessionSummary",
    "Setting",
    "best_prediction",
    "driven_run",
    "lab_folder",
    "law_amplitude",
    "omega_n",
    "real_oscillator_study",
    "session_spread",
    "simulated_amplitudes",
    "steady_counts",
]
