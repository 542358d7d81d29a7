r"""The real oscillator on any laboratory's Pohl wheel: damping against amplitude, the law the data choose, the
brake at matched amplitude, steadiness by late drift, a calibrated prediction, and the paper's claims.

Pure computation on a folder read by :func:`vibration.physics.lab.load_lab_data` (logger files and a
manifest). The model, for the wheel angle :math:`\theta` (rad) under the measured drive signal :math:`u`,

.. math::

    \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2\Delta\,\mathrm{sgn}\dot\theta + b\dot\theta|\dot\theta|
    + a|\dot\theta|^p\mathrm{sgn}\dot\theta + \omega_n^2(\theta - \theta_0) = \omega_n^2\,g\,u(t),

with any subset of the damping terms (:data:`LAWS`), the resting angle :math:`\theta_0` and the drive gain
:math:`g` (rad of static wheel angle per unit of drive signal).

Choices, stated once:

* **Laws.** Each candidate law is fitted to every free decay of a brake setting; the setting's law is
  the one of smallest BIC summed over its runs, and each run's own choice is counted.
* **Band.** The brake settings are compared over the amplitudes all of them cover: from the largest of
  their 10th percentiles of half-period amplitude to the smallest of their 90th percentiles.
* **Steadiness.** A driven run is steady when its one-harmonic amplitude changes by at most
  ``tolerance`` (or by less than two standard errors) from the first to the last of its final
  ``periods`` drive periods; steady amplitudes come from steady runs only.
* **Groups.** Driven runs of one brake setting and session whose measured drive frequencies lie within
  ``frequency_tolerance`` of the group's first form a group.
* **Calibration.** Each law's gain :math:`g` is the least-squares fit (in log amplitude) of its
  harmonic-balance steady amplitude to the steady runs at least ``calibration_detuning`` away from
  resonance whose amplitude exceeds five Coulomb angles (where the wheel does not stick); the other
  steady runs are predicted. The pooled error is the rms relative error over the predicted runs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import optimize

from vibration.chapters.real_oscillator.params import DEFAULT_LAB, Params
from vibration.physics.lab import (
    DampingCurve,
    DampingDifference,
    JointBrakeFit,
    LabData,
    PooledDecayFit,
    Steadiness,
    compare_damping,
    damping_vs_amplitude,
    fit_free_decays,
    harmonic_fit,
    joint_brake_fit,
    law_forced_amplitude,
    load_lab_data,
    simulate_driven,
    steadiness,
)
from vibration.physics.model import ParameterError
from vibration.physics.paper import data_dir

#: Candidate damping laws, from the paper's to the amplitude-dependent ones.
LAWS = ("viscous", "coulomb", "coulomb+viscous", "coulomb+quadratic", "coulomb+power")
#: The paper's model (a linear viscous damper).
PAPER_LAW = "viscous"
#: Gain factors of the sensitivity curve (times each law's calibrated gain).
GAIN_FACTORS = tuple(np.round(np.linspace(0.8, 1.2, 9), 3))
#: Runs below this many Coulomb angles of amplitude are dominated by sticking (not used to calibrate).
STICK_MULTIPLE = 5.0
#: Bounds of the gain search (per unit of drive signal).
GAIN_BOUNDS = (1e-4, 1e3)
#: Percentiles of each setting's half-period amplitudes that bound the comparison band.
BAND_PERCENTILES = (10.0, 90.0)
#: Largest omega h of the simulations' Runge-Kutta step (about 125 steps per period).
SIM_OMEGA_STEP = 0.05
#: Start velocity: a straight line through the samples of the first this many seconds.
START_WINDOW = 0.25


# ----------------------------------------------------------------------------- records


@dataclass(frozen=True, kw_only=True, eq=False)
class Setting:
    """The free decays of one brake setting.

    Attributes
    ----------
    brake : str
        Its label; ``current`` the brake current (A) or None.
    runs : tuple
        The LabRun records.
    curves : tuple of DampingCurve
        Damping against amplitude, per run.
    fits : dict
        Law -> PooledDecayFit.
    law : str
        The law of smallest summed BIC.
    wins : dict
        Law -> number of runs whose own BIC chose it.
    amplitude_range : tuple
        Smallest and largest half-period amplitude (rad).
    zeta_eq, zeta_eq_stderr : float
        Mean over runs of the run's mean zeta_eq inside the comparison band, and its run-to-run error.
    n_band : int
        Runs with half periods inside the band.
    """

    brake: str
    current: float | None
    runs: tuple = field(repr=False)
    curves: tuple = field(repr=False)
    fits: dict = field(repr=False)
    law: str
    wins: dict
    amplitude_range: tuple
    zeta_eq: float
    zeta_eq_stderr: float
    n_band: int


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


@dataclass(frozen=True, kw_only=True, eq=False)
class Prediction:
    """One law's calibrated prediction of the steady driven runs of one brake setting.

    Attributes
    ----------
    law, brake : str
    gain : float
        Calibrated drive gain.
    omega_n : float
        The pooled natural frequency (rad/s).
    coefficients : dict
        The pooled law's coefficients.
    calibration : tuple of Driven
        Runs the gain was fitted on; ``predicted`` the others.
    errors : dict
        id(Driven) -> relative error of the steady amplitude (model / measured - 1).
    pooled_error : float
        rms relative error over the predicted runs; ``session_errors`` the same per session.
    sensitivity : tuple
        (gain factor, pooled error) pairs.
    resonance : dict
        Session -> (omega, amplitude) of the model's largest steady amplitude at the session's mean drive.
    sim_gain : float
        The gain calibrated by simulation (the same runs, the same log least squares, each run simulated
        from its measured start with its measured drive), nan when no simulation was possible.
    sim_errors : dict
        id(Driven) -> relative error of the simulated one-harmonic amplitude over the run's own late
        window; ``sim_pooled_error`` and ``sim_session_errors`` as for harmonic balance.
    sim_sensitivity : tuple
        (gain / harmonic-balance gain, pooled error by simulation) pairs.
    """

    law: str
    brake: str
    gain: float
    omega_n: float
    coefficients: dict
    calibration: tuple = field(repr=False)
    predicted: tuple = field(repr=False)
    errors: dict = field(repr=False)
    pooled_error: float
    session_errors: dict
    sensitivity: tuple
    resonance: dict
    sim_gain: float = math.nan
    sim_errors: dict = field(default_factory=dict, repr=False)
    sim_pooled_error: float = math.nan
    sim_session_errors: dict = field(default_factory=dict)
    sim_sensitivity: tuple = ()


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


def _setting_curves(runs) -> tuple:
    return tuple(damping_vs_amplitude(r.t, r.angle) for r in runs)


def _band(settings_curves) -> tuple | None:
    lows, highs = [], []
    for curves in settings_curves:
        x = np.concatenate([c.amplitude for c in curves]) if curves else np.array([])
        if x.size < 3:
            return None
        lo, hi = np.percentile(x, BAND_PERCENTILES)
        lows.append(lo)
        highs.append(hi)
    lo, hi = float(max(lows)), float(min(highs))
    return (lo, hi) if lo < hi else None


def _band_stats(curves, band) -> tuple[float, float, int]:
    if band is None:
        return math.nan, math.nan, 0
    lo, hi = band
    per = [c.zeta_eq[(c.amplitude >= lo) & (c.amplitude <= hi)] for c in curves]
    per = [float(v.mean()) for v in per if v.size]
    if not per:
        return math.nan, math.nan, 0
    se = float(np.std(per, ddof=1) / math.sqrt(len(per))) if len(per) > 1 else math.nan
    return float(np.mean(per)), se, len(per)


def _setting(brake, current, runs, band) -> Setting:
    curves = _setting_curves(runs)
    fits = {}
    for law in LAWS:
        try:
            fits[law] = fit_free_decays(runs, law)
        except ParameterError:
            continue
    if not fits:
        raise ParameterError(f"lab_data: no free decay of brake setting {brake!r} could be fitted")
    law = min(fits, key=lambda k: fits[k].bic)
    wins = dict.fromkeys(fits, 0)
    for i in range(len(runs)):
        best = min(fits, key=lambda k: fits[k].fits[i].bic)
        wins[best] += 1
    x = np.concatenate([c.amplitude for c in curves])
    z, zse, n_band = _band_stats(curves, band)
    return Setting(
        brake=brake,
        current=current,
        runs=tuple(runs),
        curves=curves,
        fits=fits,
        law=law,
        wins=wins,
        amplitude_range=(float(x.min()), float(x.max())) if x.size else (math.nan, math.nan),
        zeta_eq=z,
        zeta_eq_stderr=zse,
        n_band=n_band,
    )


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


def law_amplitude(pooled: PooledDecayFit, omega, force) -> np.ndarray:
    """Harmonic-balance steady amplitude (rad) of a pooled law at drive frequencies omega and static force g U."""
    m = pooled.mean
    return law_forced_amplitude(
        omega,
        omega_n=m["omega_n"],
        force=force,
        zeta=max(m["zeta"], 0.0),
        friction=max(m["friction"], 0.0),
        quadratic=max(m["quadratic"], 0.0),
        power=max(m["power"], 0.0),
        power_exponent=m["power_exponent"] if m["power"] > 0 else 2.0,
    )


def _start(d: Driven) -> tuple[float, float, float]:
    """Centre (mean angle over the first drive period), start angle about it and start velocity (rad, rad/s)."""
    t, y = d.run.t, d.run.angle
    period = 2.0 * math.pi / d.omega
    centre = float(np.mean(y[t <= t[0] + period]))
    m = t <= t[0] + START_WINDOW
    if np.count_nonzero(m) < 3:
        m = np.arange(t.size) < 3
    slope = float(np.polyfit(t[m] - t[0], y[m], 1)[0])
    return centre, float(y[0]) - centre, slope


def _late_amplitudes(t, sims, omega, periods) -> np.ndarray:
    """One-harmonic amplitude (sine, cosine, offset, trend) of each row of sims over the last periods."""
    late = t >= t[-1] - periods * 2.0 * math.pi / omega - 1e-9
    tl = t[late]
    X = np.column_stack([np.sin(omega * tl), np.cos(omega * tl), np.ones_like(tl), tl - tl.mean()])
    coef, *_ = np.linalg.lstsq(X, sims[:, late].T, rcond=None)
    return np.hypot(coef[0], coef[1])


def simulated_amplitudes(pooled: PooledDecayFit, runs, gains, periods: int) -> np.ndarray:
    """Late one-harmonic amplitude (rad) of each driven run simulated with a pooled law at each gain.

    Each run starts from its own measured angle and velocity about the centre of its first drive period and
    is driven by the sine fitted to its drive signal (frequency, amplitude, phase); the amplitude is taken
    over the same late window (the final ``periods`` drive periods) as the measured one.

    Returns
    -------
    numpy.ndarray
        Shape (runs, gains).
    """
    m = pooled.mean
    gains = np.asarray(gains, dtype=float)
    out = np.full((len(runs), gains.size), np.nan)
    by_dt: dict = {}
    for i, d in enumerate(runs):
        dt = float(np.median(np.diff(d.run.t)))
        by_dt.setdefault(round(dt, 6), []).append(i)
    for dt, idx in by_dt.items():
        rs = [runs[i] for i in idx]
        duration = max(float(r.run.t[-1] - r.run.t[0]) for r in rs) + dt
        top = max(m["omega_n"], max(r.omega for r in rs))
        substeps = max(1, math.ceil(dt * top / SIM_OMEGA_STEP))
        starts = [_start(r) for r in rs]
        k = gains.size
        t_sim, th = simulate_driven(
            duration,
            sample_interval=dt,
            omega_n=m["omega_n"],
            force=np.concatenate([g * np.array([r.drive_amp for r in rs]) for g in gains]),
            omega=np.tile([r.omega for r in rs], k),
            phase=np.tile([r.omega * float(r.run.t[0]) + r.drive_phase for r in rs], k),
            zeta=max(m["zeta"], 0.0),
            friction=max(m["friction"], 0.0),
            quadratic=max(m["quadratic"], 0.0),
            power=max(m["power"], 0.0),
            power_exponent=m["power_exponent"] if m["power"] > 0 else 2.0,
            theta0=np.tile([s[1] for s in starts], k),
            velocity0=np.tile([s[2] for s in starts], k),
            substeps=substeps,
        )
        for j, (i, r) in enumerate(zip(idx, rs, strict=True)):
            tr = r.run.t - r.run.t[0]
            rows = np.array([np.interp(tr, t_sim, th[j + q * len(rs)]) for q in range(k)])
            out[i] = _late_amplitudes(tr, rows, r.omega, periods)
    return out


def _simulate(pooled, cal, rest, gain, params: Params) -> dict:
    """Calibrate the gain by simulation on a grid about the harmonic-balance gain, then predict the rest."""
    runs = list(dict.fromkeys([*cal, *rest]))
    factors = np.array(GAIN_FACTORS, dtype=float)
    try:
        amp = simulated_amplitudes(pooled, runs, gain * factors, params.periods)
    except ParameterError:
        return {}
    meas = np.array([d.steady.amplitude for d in runs])
    ic = [runs.index(d) for d in cal]
    ir = [runs.index(d) for d in rest]
    with np.errstate(divide="ignore", invalid="ignore"):
        logr = np.log(np.maximum(amp, 1e-9) / meas[:, None])
    cost = np.sum(np.square(logr[ic]), axis=0)
    j = int(np.argmin(cost))
    lf = np.log(factors)
    best = lf[j]
    if 0 < j < factors.size - 1:  # parabola through the grid minimum and its neighbours
        c2, c1, _ = np.polyfit(lf[j - 1 : j + 2], cost[j - 1 : j + 2], 2)
        if c2 > 0:
            best = float(np.clip(-c1 / (2.0 * c2), lf[j - 1], lf[j + 1]))
    g_sim = float(gain * math.exp(best))
    try:
        final = simulated_amplitudes(pooled, [runs[i] for i in ir], [g_sim], params.periods)[:, 0]
    except ParameterError:
        return {}
    rel = final / meas[ir] - 1.0
    errors = {id(runs[i]): float(e) for i, e in zip(ir, rel, strict=True)}

    def rms(v):
        v = np.asarray([x for x in v if math.isfinite(x)])
        return float(math.sqrt(np.mean(np.square(v)))) if v.size else math.inf

    sessions = list(dict.fromkeys(runs[i].run.session for i in ir))
    grid_rel = amp[ir] / meas[ir][:, None] - 1.0
    return {
        "sim_gain": g_sim,
        "sim_errors": errors,
        "sim_pooled_error": rms(rel),
        "sim_session_errors": {
            s: rms([e for i, e in zip(ir, rel, strict=True) if runs[i].run.session == s]) for s in sessions
        },
        "sim_sensitivity": tuple((float(f), rms(grid_rel[:, q])) for q, f in enumerate(factors)),
    }


def _predict(law: str, setting: Setting, driven, params: Params) -> Prediction | None:
    pooled = setting.fits.get(law)
    if pooled is None:
        return None
    steady = [d for d in driven if d.steady.steady and math.isfinite(d.drive_amp) and d.steady.amplitude > 0]
    if not steady:
        return None
    wn = pooled.mean["omega_n"]
    friction = max(setting.fits.get("coulomb+viscous", pooled).mean["friction"], 0.0)
    cal = [
        d
        for d in steady
        if abs(d.omega / wn - 1.0) >= params.calibration_detuning and d.steady.amplitude >= STICK_MULTIPLE * friction
    ]
    if not cal:
        cal = [d for d in steady if abs(d.omega / wn - 1.0) >= params.calibration_detuning]
    if not cal:
        return None
    rest = [d for d in steady if d not in cal] or list(steady)

    def model(d, g):
        return float(law_amplitude(pooled, d.omega, g * d.drive_amp)[0])

    def cost(lg):
        g = math.exp(lg)
        r = [math.log(max(model(d, g), 1e-9) / d.steady.amplitude) for d in cal]
        return float(np.sum(np.square(r)))

    sol = optimize.minimize_scalar(
        cost, bounds=tuple(math.log(b) for b in GAIN_BOUNDS), method="bounded", options={"xatol": 1e-6, "maxiter": 200}
    )
    gain = float(math.exp(sol.x))

    def pooled_err(g, runs):
        e = [model(d, g) / d.steady.amplitude - 1.0 for d in runs]
        e = [x for x in e if math.isfinite(x)]
        return float(math.sqrt(np.mean(np.square(e)))) if e else math.inf

    errors = {id(d): model(d, gain) / d.steady.amplitude - 1.0 for d in rest}
    sessions = list(dict.fromkeys(d.run.session for d in rest))
    session_errors = {s: pooled_err(gain, [d for d in rest if d.run.session == s]) for s in sessions}
    sens = tuple((float(f), pooled_err(gain * f, rest)) for f in GAIN_FACTORS)
    resonance = {}
    grid = np.linspace(0.8 * wn, 1.2 * wn, 161)
    for s in dict.fromkeys(d.run.session for d in steady):
        u = float(np.mean([d.drive_amp for d in driven if d.run.session == s and math.isfinite(d.drive_amp)]))
        amp = law_amplitude(pooled, grid, gain * u)
        i = int(np.argmax(amp))
        resonance[s] = (float(grid[i]), float(amp[i]))
    return Prediction(
        law=law,
        brake=setting.brake,
        gain=gain,
        omega_n=wn,
        coefficients=dict(pooled.coefficients),
        calibration=tuple(cal),
        predicted=tuple(rest),
        errors=errors,
        pooled_error=pooled_err(gain, rest),
        session_errors=session_errors,
        sensitivity=sens,
        resonance=resonance,
        **_simulate(pooled, cal, rest, gain, params),
    )


def _current_law(settings) -> dict | None:
    pts = [
        (s.current, s.fits["coulomb+viscous"])
        for s in settings
        if s.current is not None and "coulomb+viscous" in s.fits
    ]
    if len(pts) <= 2:
        return None
    i2 = np.array([p[0] ** 2 for p in pts])
    z = np.array([p[1].mean["zeta"] for p in pts])
    se = np.array([max(p[1].stderr["zeta"], 1e-6) for p in pts])
    X = np.column_stack([np.ones_like(i2), i2])
    W = 1.0 / se**2
    cov = np.linalg.pinv(X.T @ (X * W[:, None]))
    coef = cov @ (X.T @ (W * z))
    chi2 = float(np.sum(W * (z - X @ coef) ** 2))
    dof = max(1, len(pts) - 2)
    scale = max(1.0, math.sqrt(chi2 / dof))
    return {
        "zeta0": float(coef[0]),
        "k": float(coef[1]),
        "zeta0_stderr": float(math.sqrt(cov[0, 0]) * scale),
        "k_stderr": float(math.sqrt(cov[1, 1]) * scale),
        "chi2": chi2,
        "dof": dof,
        "currents": tuple(float(p[0]) for p in pts),
        "zeta": tuple(float(v) for v in z),
        "zeta_stderr": tuple(float(v) for v in se),
    }


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
    "driven_run",
    "lab_folder",
    "law_amplitude",
    "real_oscillator_study",
    "session_spread",
    "simulated_amplitudes",
]
