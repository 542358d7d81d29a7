"""Driven runs of the real oscillator: the measured drive, the late-drift test, groups at one drive frequency,
the sessions and the spread between them.

Choices, stated once:

* **Steadiness.** A driven run is steady when its one-harmonic amplitude changes by at most
  ``tolerance`` (or by less than two standard errors) from the first to the last of its final
  ``periods`` drive periods; steady amplitudes come from steady runs only.
* **Groups.** Driven runs of one brake setting and session whose measured drive frequencies lie within
  ``frequency_tolerance`` of the group's first form a group.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from vibration.book.chapters.real_oscillator.params import Params
from vibration.physics.lab import Steadiness, harmonic_fit, steadiness
from vibration.physics.model import ParameterError


@dataclass(frozen=True, kw_only=True, eq=False)
class Driven:
    """One driven run: measured drive, late drift, amplitude.

    Attributes
    ----------
    run : LabRun
        The record.
    omega : float
        Drive angular frequency (rad/s) from a one-harmonic fit of the drive signal (of the wheel when
        there is none).
    drive_amp : float
        Drive signal amplitude (its unit ``drive_unit``); ``drive_phase`` its phase (rad) in
        ``sin(omega t + phase)``, t the record's own time.
    frequency_drift : float
        Relative change of the drive frequency from the first to the second half of the record.
    centre_drift : float
        Change of the wheel's mean angle from the first to the last drive period (rad).
    steady : Steadiness
        The late-drift test.
    """

    run: object = field(repr=False)
    omega: float
    drive_amp: float
    drive_phase: float
    drive_unit: str
    frequency_drift: float
    centre_drift: float
    steady: Steadiness


@dataclass(frozen=True, kw_only=True, eq=False)
class Group:
    """Driven runs of one brake setting and session at one drive frequency (within the tolerance)."""

    brake: str
    session: str
    omega: float
    runs: tuple = field(repr=False)
    amplitude: float  # mean steady amplitude (rad), nan without steady runs
    amplitude_stderr: float
    n_steady: int


@dataclass(frozen=True, kw_only=True)
class SessionSummary:
    """The driven runs of one session: their drive-frequency and centre drifts.

    Attributes
    ----------
    session : str
        Its label; ``runs`` and ``steady`` the number of driven runs and of steady ones.
    frequency_drift : tuple
        Median, smallest and largest relative drive-frequency drift over the runs.
    centre_drift : tuple
        Median, smallest and largest centre drift (rad) over the runs.
    """

    session: str
    runs: int
    steady: int
    frequency_drift: tuple
    centre_drift: tuple


@dataclass(frozen=True, kw_only=True)
class SessionSpread:
    """Session-to-session spread of the steady amplitude per unit drive at matched drive frequency.

    Attributes
    ----------
    spread : float
        rms over matched pairs of ln(r_a / r_b), r the mean steady amplitude per unit drive of a group, for
        groups of one brake setting in two sessions whose drive frequencies agree within the frequency
        tolerance: the relative systematic error of any comparison across sessions (nan without pairs).
    pairs : int
        Matched pairs.
    mean_log_ratio : float
        Mean ln(r_a / r_b) (first session over second, in manifest order).
    """

    spread: float
    pairs: int
    mean_log_ratio: float


#: The spread when no two sessions share a drive frequency.
NO_SPREAD = SessionSpread(spread=math.nan, pairs=0, mean_log_ratio=math.nan)


def _sessions(driven) -> tuple:
    out = []
    for sess in dict.fromkeys(d.run.session for d in driven):
        ds = [d for d in driven if d.run.session == sess]
        f = np.array([d.frequency_drift for d in ds])
        c = np.array([d.centre_drift for d in ds])
        out.append(
            SessionSummary(
                session=sess,
                runs=len(ds),
                steady=sum(d.steady.steady for d in ds),
                frequency_drift=(float(np.median(f)), float(f.min()), float(f.max())),
                centre_drift=(float(np.median(c)), float(c.min()), float(c.max())),
            )
        )
    return tuple(out)


def _per_drive(gr) -> float:
    u = [d.drive_amp for d in gr.runs if d.steady.steady and math.isfinite(d.drive_amp)]
    return gr.amplitude / float(np.mean(u)) if u and math.isfinite(gr.amplitude) and np.mean(u) > 0 else math.nan


def session_spread(groups, tol: float) -> SessionSpread:
    """The session-to-session spread of steady groups at matched drive frequency (see :class:`SessionSpread`)."""
    sessions = list(dict.fromkeys(gr.session for gr in groups))
    logs = []
    for i, sa in enumerate(sessions):
        for sb in sessions[i + 1 :]:
            for ga in groups:
                if ga.session != sa or not ga.n_steady:
                    continue
                for gb in groups:
                    if gb.session != sb or gb.brake != ga.brake or not gb.n_steady:
                        continue
                    if abs(gb.omega / ga.omega - 1.0) > tol:
                        continue
                    ra, rb = _per_drive(ga), _per_drive(gb)
                    if math.isfinite(ra) and math.isfinite(rb) and ra > 0 and rb > 0:
                        logs.append(math.log(ra / rb))
    if not logs:
        return NO_SPREAD
    v = np.array(logs)
    return SessionSpread(spread=float(np.sqrt(np.mean(v * v))), pairs=int(v.size), mean_log_ratio=float(v.mean()))


def _driven(r, params: Params) -> Driven | None:
    t, y = r.t, r.angle
    u = r.data.drive_angle
    sig = u if u is not None and np.ptp(u) > 0 else y
    try:
        h = harmonic_fit(t, sig)
        half = t < 0.5 * (t[0] + t[-1])
        h1, h2 = harmonic_fit(t[half], sig[half], None), harmonic_fit(t[~half], sig[~half], None)
        s = steadiness(t, y, h.omega, periods=params.periods, tolerance=params.tolerance)
    except ParameterError:
        return None
    period = 2.0 * math.pi / h.omega
    first, last = t <= t[0] + period, t >= t[-1] - period
    return Driven(
        run=r,
        omega=float(h.omega),
        drive_amp=float(h.amplitude) if sig is u else math.nan,
        drive_phase=float(h.phase),
        drive_unit=r.data.drive_unit if sig is u else "",
        frequency_drift=float((h2.omega - h1.omega) / h.omega),
        centre_drift=float(np.mean(y[last]) - np.mean(y[first])),
        steady=s,
    )


def driven_run(r, params: Params) -> Driven | None:
    """One driven run's drive frequency, drifts and late-drift test (None when it cannot be analysed)."""
    return _driven(r, params)


def _groups(driven, tol) -> tuple:
    out = []
    keys = dict.fromkeys((d.run.brake, d.run.session) for d in driven)
    for brake, session in keys:
        ds = sorted((d for d in driven if d.run.brake == brake and d.run.session == session), key=lambda d: d.omega)
        current: list[Driven] = []
        for d in [*ds, None]:
            if d is not None and current and d.omega <= current[0].omega * (1.0 + tol):
                current.append(d)
                continue
            if current:
                st = [c.steady.amplitude for c in current if c.steady.steady]
                if len(st) > 1:
                    se = float(np.std(st, ddof=1) / math.sqrt(len(st)))
                elif st:
                    se = float(next(c.steady.amplitude_stderr for c in current if c.steady.steady))
                else:
                    se = math.nan
                out.append(
                    Group(
                        brake=brake,
                        session=session,
                        omega=float(np.mean([c.omega for c in current])),
                        runs=tuple(current),
                        amplitude=float(np.mean(st)) if st else math.nan,
                        amplitude_stderr=se,
                        n_steady=len(st),
                    )
                )
            current = [d] if d is not None else []
    return tuple(out)
