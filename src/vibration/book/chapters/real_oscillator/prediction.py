"""The calibrated prediction of the real oscillator's steady driven runs, by harmonic balance and by simulation.

Choices, stated once:

* **Calibration.** Each law's gain :math:`g` is the least-squares fit (in log amplitude) of its
  harmonic-balance steady amplitude to the steady runs at least ``calibration_detuning`` away from
  resonance whose amplitude exceeds five Coulomb angles (where the wheel does not stick); the other
  steady runs are predicted. The pooled error is the rms relative error over the predicted runs.
* **Simulation.** The same runs, the same log least squares, each run simulated from its measured start
  with its measured drive; the gain is searched on a grid about the harmonic-balance gain.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from vibration.book.chapters.real_oscillator.damping import Setting
from vibration.book.chapters.real_oscillator.driven import Driven
from vibration.book.chapters.real_oscillator.params import Params
from vibration.physics.lab import PooledDecayFit, law_forced_amplitude, simulate_driven
from vibration.physics.model import ParameterError

#: Gain factors of the sensitivity curve (times each law's calibrated gain).
GAIN_FACTORS = tuple(np.round(np.linspace(0.8, 1.2, 9), 3))
#: Runs below this many Coulomb angles of amplitude are dominated by sticking (not used to calibrate).
STICK_MULTIPLE = 5.0
#: Bounds of the gain search (per unit of drive signal).
GAIN_BOUNDS = (1e-4, 1e3)
#: Largest omega h of the simulations' Runge-Kutta step (about 125 steps per period).
SIM_OMEGA_STEP = 0.05
#: Start velocity: a straight line through the samples of the first this many seconds.
START_WINDOW = 0.25


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
    pooled_error: float
    session_errors: dict
    sensitivity: tuple
    resonance: dict
    sim_gain: float = math.nan
    sim_errors: dict = field(default_factory=dict, repr=False)
    sim_pooled_error: float = math.nan
    sim_session_errors: dict = field(default_factory=dict)
    sim_sensitivity: tuple = ()
    calibration: tuple = field(repr=False)
    predicted: tuple = field(repr=False)
    errors: dict = field(repr=False)


def _law_terms(mean: dict) -> dict:
    """The damping terms of a pooled law's mean coefficients, as the oscillator's keywords (none negative)."""
    return {
        "zeta": max(mean["zeta"], 0.0),
        "friction": max(mean["friction"], 0.0),
        "quadratic": max(mean["quadratic"], 0.0),
        "power": max(mean["power"], 0.0),
        "power_exponent": mean["power_exponent"] if mean["power"] > 0 else 2.0,
    }


def law_amplitude(pooled: PooledDecayFit, omega, force) -> np.ndarray:
    """Harmonic-balance steady amplitude (rad) of a pooled law at drive frequencies omega and static force g U."""
    m = pooled.mean
    return law_forced_amplitude(
        omega,
        omega_n=m["omega_n"],
        force=force,
        **_law_terms(m),
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


def simulated_amplitudes(pooled: PooledDecayFit, runs, gains, *, periods: int) -> np.ndarray:
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
            **_law_terms(m),
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
        amp = simulated_amplitudes(pooled, runs, gain * factors, periods=params.periods)
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
        final = simulated_amplitudes(pooled, [runs[i] for i in ir], [g_sim], periods=params.periods)[:, 0]
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
