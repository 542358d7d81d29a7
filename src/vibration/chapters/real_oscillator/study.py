r"""The real oscillator: free decays, driven runs, a calibrated prediction, the paper's claims, the twin.

Pure computation on the lab data in ``data/lab_oscillator/`` (read-only, provenance in its README).
The model, for the wheel angle :math:`\theta` (rad) under the measured drive angle :math:`u` (rad),

.. math::

    \ddot\theta + 2\zeta\omega_n\dot\theta + \omega_n^2(\theta - c) + \omega_n^2\Delta\,\mathrm{sgn}\,\dot\theta
    = \omega_n^2\,g\,u(t),

with the natural angular frequency :math:`\omega_n`, the damping ratio :math:`\zeta`, the Coulomb
friction angle :math:`\Delta`, the resting angle :math:`c` and the drive gain :math:`g` (rad of
static wheel angle per rad of drive). Everything returned is a frozen record; sentences, tables and
figures are functions of :class:`RealOscillatorStudy` (modules ``text`` and ``figures``).

Choices, stated once:

* **Pooling.** A parameter over runs is the inverse-variance weighted mean; its standard error
  :math:`1/\sqrt{\sum w_i}` is multiplied by the Birge ratio :math:`\sqrt{\chi^2/(n-1)}` when that is
  above 1, i.e. inflated by the scatter between runs that the runs' own errors do not explain.
* **Windows.** Each driven run's drive frequency comes from a one-harmonic fit of its whole drive
  record. The early window is its first ``n_early`` whole drive periods, the late window its last
  ``n_late`` (fewer when the run is short: the early window takes at most half of the whole
  periods, the late one the rest; more when the periods are short: a window lasts at least 1 s,
  the 20 samples a fit needs). In each window drive and wheel are fitted at that frequency.
  The amplitude's standard error is the larger of the fit's and of the batch error of the
  per-period amplitudes (one fit per whole period: the residuals of one fit are correlated).
* **Steady state.** A run counts as steady when its early and late wheel amplitudes differ by at
  most ``z_steady`` combined standard errors and the model's build-up time :math:`1/(\zeta\omega_n)`
  is shorter than the record; otherwise it is a transient.
* **Calibration.** The drive gain of each model is the least-squares fit of the simulated to the
  measured late amplitude ratio on the ``n_calibration`` lowest-frequency runs only; every other
  run is then predicted from its own measured drive, its own start (angle, and velocity from a
  parabola through the first five samples) and a resting angle set from its record's means (the
  logger zeroes both encoders at each start, so the spring's rest angle in its frame is not measured).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize, stats

from vibration.chapters.real_oscillator.params import Params
from vibration.physics.lab import (
    FreeDecayFit,
    PeakDecayFit,
    fit_free_decay,
    friction_forced_amplitude,
    friction_forced_amplitude_hb,
    harmonic_fit,
    load_logger_runs,
    peak_decay_fit,
    simulate_friction_oscillator,
)
from vibration.physics.model import ParameterError
from vibration.physics.paper import data_dir

#: Encoder step of the wheel angle (rad): one degree.
QUANT_STEP = math.pi / 180.0
#: Standard deviation of uniform rounding to that step (rad).
QUANT_FLOOR = QUANT_STEP / math.sqrt(12.0)
#: Fitted damping ratios and friction angles below this are at their bound 0.
ZERO = 1e-8
#: Laws fitted to each free decay.
LAWS = ("viscous", "coulomb", "combined")
#: Free-decay files: label -> file name (the brake off, then on).
DECAY_FILES = {"off": "free_decay_no_magnet.csv", "on": "free_decay_magnet.csv"}
#: Driven sessions: number -> file name.
DRIVEN_FILES = {1: "driven_session1.csv", 2: "driven_session2.csv"}
#: Runge-Kutta steps per 0.05 s sample of the stick-slip simulation (error far below the encoder step).
SUBSTEPS = 10
#: Shortest window (s): 20 samples at 20 Hz, the fewest a one-harmonic fit accepts.
MIN_WINDOW = 1.0
#: Bounds of the drive gain search (rad per rad of drive).
GAIN_BOUNDS = (0.05, 2.0)
#: Significance level and power of the two-sample design question.
ALPHA, POWER = 0.05, 0.8
#: Relative change of the steady amplitude that counts as "the brake matters" in the band of claim 4.
BRAKE_MATTERS = 0.1


# ----------------------------------------------------------------------------- records


@dataclass(frozen=True)
class Provenance:
    """Where the data come from, as the data README states it."""

    repository: str
    commit: str
    folder: str
    date: str


@dataclass(frozen=True, eq=False)
class DecayRun:
    """One free decay: the three whole-trace fits, the chosen law, and the peak estimator."""

    brake: str  # "off" or "on"
    run: int
    t: np.ndarray = field(repr=False)  # s
    angle: np.ndarray = field(repr=False)  # rad
    fits: dict = field(repr=False)  # law -> FreeDecayFit
    peak: PeakDecayFit | None  # combined law, from the extrema only (None when it cannot be formed)
    chosen: str  # law with the lowest BIC

    @property
    def combined(self) -> FreeDecayFit:
        return self.fits["combined"]


@dataclass(frozen=True)
class Pooled:
    """Weighted mean over runs with its standard error (inflated by the Birge ratio when above 1)."""

    mean: float
    stderr: float
    birge: float  # sqrt(chi^2 / (n - 1)) of the runs about the mean
    n: int
    sd: float  # sample standard deviation between runs
    median_se: float  # median of the runs' own standard errors


@dataclass(frozen=True)
class DecaySet:
    """The free decays of one brake setting, pooled per law."""

    brake: str
    runs: tuple[DecayRun, ...]
    pooled: dict  # (law, parameter) -> Pooled, parameter in omega_n, zeta, friction
    peak_pooled: dict  # parameter -> Pooled, from the peak estimator (combined law)
    law_counts: dict  # law -> number of runs whose BIC chose it


@dataclass(frozen=True)
class Window:
    """One-harmonic fits of drive and wheel at the drive frequency over whole periods."""

    t_start: float  # s
    t_end: float  # s
    periods: int
    drive_amp: float  # rad
    drive_amp_se: float
    wheel_amp: float  # rad
    wheel_amp_se: float
    lag: float  # phase of the wheel behind the drive (rad), in [-pi/2, 3 pi/2)
    lag_se: float
    wheel_offset: float  # rad
    drive_offset: float  # rad

    @property
    def ratio(self) -> float:
        return self.wheel_amp / self.drive_amp

    @property
    def ratio_se(self) -> float:
        return self.ratio * math.hypot(self.wheel_amp_se / self.wheel_amp, self.drive_amp_se / self.drive_amp)


@dataclass(frozen=True, eq=False)
class DrivenRun:
    """One driven run: its windows, its steadiness, and the two models' predictions."""

    session: int
    run: int
    voltage: float  # V, median motor supply
    omega: float  # drive angular frequency (rad/s)
    duration: float  # s
    whole_periods: int
    early: Window
    late: Window
    steady: bool
    amp_change_z: float  # (late - early) wheel amplitude in combined standard errors
    t: np.ndarray = field(repr=False)
    angle: np.ndarray = field(repr=False)
    drive: np.ndarray = field(repr=False)
    theta0: float = 0.0  # rad, initial angle
    omega0: float = 0.0  # rad/s, initial velocity estimate


@dataclass(frozen=True)
class Model:
    """One model of the wheel: parameters from the free decays, gain from the calibration runs."""

    name: str  # "linear" or "combined"
    omega_n: float  # rad/s
    zeta: float
    friction: float  # rad
    gain: float  # rad per rad of drive
    zeta_se: float
    friction_se: float


@dataclass(frozen=True, eq=False)
class Prediction:
    """One model's simulation of one driven run from its own start and measured drive."""

    model: str
    session: int
    run: int
    calibration: bool  # the run calibrated the gain (not a prediction)
    theta: np.ndarray = field(repr=False)  # rad, simulated at the run's samples
    rms_error: float = 0.0  # rad, over the whole record
    rel_error: float = 0.0  # rms error / rms of the measured angle about its mean
    late_ratio: float = 0.0  # simulated late amplitude ratio


@dataclass(frozen=True)
class Curves:
    """Steady resonance curves of both models at the mean drive amplitude."""

    omega: np.ndarray  # rad/s
    linear_ratio: np.ndarray
    linear_lag: np.ndarray  # rad
    combined_ratio: np.ndarray  # Den Hartog, exact (NaN where the motion has stops)
    combined_hb: np.ndarray  # harmonic balance
    combined_lag: np.ndarray  # rad, harmonic balance (equivalent viscous damping)
    drive_amp: float  # rad
    hb_max_rel_diff: float  # largest |exact - hb| / exact where both exist


@dataclass(frozen=True)
class Coverage:
    """Does a run's own standard error cover the scatter between runs?"""

    brake: str
    parameter: str
    median_se: float
    sd: float
    ratio: float
    covered: bool


@dataclass(frozen=True)
class TwoSample:
    """Welch's two-sample test of a per-run parameter, brake on against off, and the runs it needs."""

    parameter: str
    mean_off: float
    mean_on: float
    sd_off: float
    sd_on: float
    n_off: int
    n_on: int
    t: float
    p: float
    mann_whitney_p: float
    runs_needed: int  # per setting, for a two-sided test at ALPHA with POWER, at the observed effect and scatter


@dataclass(frozen=True, eq=False)
class RealOscillatorStudy:
    """Everything the chapter shows, computed once from the data and the parameters."""

    params: Params
    provenance: Provenance
    decays: dict  # brake -> DecaySet
    driven: tuple[DrivenRun, ...]
    models: dict  # name -> Model
    predictions: tuple[Prediction, ...]
    curves: Curves
    drive_amp: float  # rad, mean late drive amplitude of all runs
    coverage: tuple[Coverage, ...]
    tests: tuple[TwoSample, ...]
    brake_dzeta: float
    brake_dzeta_se: float
    build_up_time: float  # s, 1/(zeta omega_n) of the combined model
    low_ratio: float  # mean late ratio of the calibration runs
    low_ratio_se: float
    peak_ratio: float  # largest mean late ratio of one voltage group
    peak_ratio_se: float
    peak_group: tuple  # (session, voltage) of that group
    peak_group_steady: bool
    stick_drive_hb: float  # rad, drive amplitude below which the wheel sticks at resonance (4 Delta / (pi g))
    stick_drive_exact: float  # rad, the same by Den Hartog's non-stop condition at r = 1
    steady_peak_linear: float  # rad, steady wheel amplitude at resonance, linear model
    steady_peak_combined: float  # rad, combined model (brake setting of the prediction)
    steady_peak_brake: dict  # brake -> steady resonance amplitude of the combined model (rad)
    brake_band: float  # |omega/omega_n - 1| inside which the brake changes the amplitude by > BRAKE_MATTERS
    detuning_factor: float  # measured ratio at the peak over the ratio of the group 10 % below it
    detuning_omega: tuple  # (omega of the peak group, omega of the detuned group), rad/s

    @property
    def calibration_runs(self) -> list[DrivenRun]:
        return [d for d in self.driven if self.is_calibration(d)]

    def is_calibration(self, d: DrivenRun) -> bool:
        return any(p.calibration and p.session == d.session and p.run == d.run for p in self.predictions)

    def prediction(self, model: str, d: DrivenRun) -> Prediction:
        for p in self.predictions:
            if p.model == model and p.session == d.session and p.run == d.run:
                return p
        raise KeyError((model, d.session, d.run))

    def pooled_error(
        self, model: str, calibration: bool = False, steady: bool | None = None
    ) -> tuple[float, float, int]:
        """Pooled rms error (rad), relative error and run count over the prediction (or calibration) runs.

        The rms over all samples of the selected runs, and that over the rms of their measured angles
        about each run's mean; ``steady`` selects steady runs (True), transients (False) or both (None).
        """
        num = den = 0.0
        n = samples = 0
        for d in self.driven:
            p = self.prediction(model, d)
            if p.calibration != calibration or (steady is not None and d.steady != steady):
                continue
            e = d.angle - p.theta
            a = d.angle - d.angle.mean()
            num, den, n, samples = num + float(e @ e), den + float(a @ a), n + 1, samples + e.size
        if n == 0:
            return math.nan, math.nan, 0
        return math.sqrt(num / samples), math.sqrt(num / den), n


# ----------------------------------------------------------------------------- helpers


def provenance(path=None) -> Provenance:
    """Source repository, commit, folder and date of the lab data, read from their README."""
    text = (path or data_dir() / "lab_oscillator" / "README.md").read_text(encoding="utf-8")
    repo = re.search(r"GitHub repository\s+`([^`]+)`", text)
    commit = re.search(r"commit\s+`([0-9a-f]{40})`", text)
    folder = re.search(r"folder\s+`([^`]+)`", text)
    date = re.search(r"measured on ([0-9]{1,2} [A-Z][a-z]+ [0-9]{4})", text)
    if not (repo and commit and folder and date):
        raise ParameterError("data/lab_oscillator/README.md: provenance (repository, commit, folder, date) not found")
    return Provenance(repo.group(1), commit.group(1), folder.group(1), date.group(1))


def pool(values, stderrs) -> Pooled:
    """Inverse-variance weighted mean, its error inflated by the Birge ratio when above 1.

    Examples
    --------
    >>> p = pool([1.0, 1.0, 1.0], [0.1, 0.1, 0.1])
    >>> round(p.mean, 12), round(p.stderr, 6), p.birge
    (1.0, 0.057735, 0.0)
    >>> round(pool([0.0, 2.0], [0.1, 0.1]).stderr, 6)  # scatter 20 times the errors: inflated
    1.0
    """
    x = np.asarray(values, float)
    se = np.maximum(np.asarray(stderrs, float), 1e-12)
    w = 1.0 / se**2
    mean = float(np.sum(w * x) / np.sum(w))
    base = float(1.0 / math.sqrt(np.sum(w)))
    n = x.size
    birge = float(math.sqrt(np.sum(w * (x - mean) ** 2) / (n - 1))) if n > 1 else 0.0
    sd = float(np.std(x, ddof=1)) if n > 1 else 0.0
    return Pooled(mean, base * max(1.0, birge), birge, n, sd, float(np.median(se)))


def at_bound(x: float) -> float:
    """A fitted zeta or Delta within ZERO of its bound 0 is 0 (the solver stops within rounding of the bound)."""
    return 0.0 if abs(x) < ZERO else float(x)


def _select(runs, which: str):
    if which == "1-5":
        return [r for r in runs if 1 <= r.run <= 5]
    if which == "6-10":
        return [r for r in runs if 6 <= r.run <= 10]
    return list(runs)


def _decay_set(brake: str, which: str) -> DecaySet:
    runs = []
    for r in _select(load_logger_runs(data_dir() / "lab_oscillator" / DECAY_FILES[brake]), which):
        fits = {law: fit_free_decay(r.t, r.angle, law=law) for law in LAWS}
        try:
            peak = peak_decay_fit(r.t, r.angle, law="combined")
        except ParameterError:
            peak = None
        chosen = min(LAWS, key=lambda law: fits[law].bic)
        runs.append(DecayRun(brake, r.run, r.t, r.angle, fits, peak, chosen))
    pooled = {}
    for law in LAWS:
        for par in ("omega_n", "zeta", "friction"):
            if (law, par) in (("viscous", "friction"), ("coulomb", "zeta")):
                continue
            pooled[(law, par)] = pool(
                [at_bound(getattr(d.fits[law], par)) for d in runs], [d.fits[law].stderr[par] for d in runs]
            )
    peaks = [d.peak for d in runs if d.peak is not None]
    peak_pooled = (
        {
            par: pool([getattr(p, par) for p in peaks], [p.stderr[par] for p in peaks])
            for par in ("omega_n", "zeta", "friction")
        }
        if len(peaks) >= 2
        else {}
    )
    counts = {law: sum(d.chosen == law for d in runs) for law in LAWS}
    return DecaySet(brake, tuple(runs), pooled, peak_pooled, counts)


def _wrap_lag(x: float) -> float:
    return (x + 0.5 * math.pi) % (2.0 * math.pi) - 0.5 * math.pi


def _window(t, wheel, drive, omega, t0, periods) -> Window:
    T = 2.0 * math.pi / omega
    t1 = t0 + periods * T
    m = (t >= t0 - 1e-9) & (t < t1 - 1e-9)
    fw = harmonic_fit(t[m], wheel[m], omega=omega)
    fd = harmonic_fit(t[m], drive[m], omega=omega)
    se_w, se_d = fw.stderr["amplitude"], fd.stderr["amplitude"]
    se_pw = math.hypot(fw.stderr["phase"], fd.stderr["phase"])
    if periods >= 2:  # batch errors: one fit per whole period
        aw, ad, lg = [], [], []
        for k in range(periods):
            mk = (t >= t0 + k * T - 1e-9) & (t < t0 + (k + 1) * T - 1e-9)
            if np.count_nonzero(mk) < 20 or np.ptp(wheel[mk]) == 0:
                continue
            gw = harmonic_fit(t[mk], wheel[mk], omega=omega)
            gd = harmonic_fit(t[mk], drive[mk], omega=omega)
            aw.append(gw.amplitude)
            ad.append(gd.amplitude)
            lg.append(_wrap_lag(gd.phase - gw.phase))
        if len(aw) >= 2:
            rt = math.sqrt(len(aw))
            se_w = max(se_w, float(np.std(aw, ddof=1)) / rt)
            se_d = max(se_d, float(np.std(ad, ddof=1)) / rt)
            se_pw = max(se_pw, float(np.std(lg, ddof=1)) / rt)
    return Window(
        float(t0),
        float(t1),
        int(periods),
        fd.amplitude,
        se_d,
        fw.amplitude,
        se_w,
        _wrap_lag(fd.phase - fw.phase),
        se_pw,
        fw.offset,
        fd.offset,
    )


def _initial_velocity(t, y) -> float:
    c = np.polyfit(t[:5] - t[0], y[:5], 2)
    return float(c[1])


def _driven(params: Params, build_up: float) -> list[DrivenRun]:
    out = []
    for session, name in DRIVEN_FILES.items():
        for r in load_logger_runs(data_dir() / "lab_oscillator" / name):
            t, y, u = np.asarray(r.t), np.asarray(r.angle), np.asarray(r.drive_angle)
            omega = harmonic_fit(t, u).omega
            T = 2.0 * math.pi / omega
            n_whole = int(math.floor((t[-1] - t[0]) / T + 1e-9))
            n_min = math.ceil(MIN_WINDOW / T)  # a window holds at least MIN_WINDOW seconds of samples
            n_e = max(n_min, min(params.n_early, n_whole // 2))
            n_l = max(n_min, min(params.n_late, n_whole - n_e))
            early = _window(t, y, u, omega, float(t[0]), n_e)
            # the late window ends half a sample step after the last sample, so that no sample sits on a
            # boundary, where the last bit of T would decide whether it counts (and differ between machines)
            half_step = 0.5 * float(np.median(np.diff(t)))
            late = _window(t, y, u, omega, float(t[-1]) + half_step - n_l * T, n_l)
            z = (late.wheel_amp - early.wheel_amp) / math.hypot(late.wheel_amp_se, early.wheel_amp_se)
            steady = abs(z) <= params.z_steady and build_up <= float(t[-1] - t[0])
            out.append(
                DrivenRun(
                    session,
                    r.run,
                    float(np.median(r.voltage)),
                    float(omega),
                    float(t[-1] - t[0]),
                    n_whole,
                    early,
                    late,
                    bool(steady),
                    float(z),
                    t,
                    y,
                    u,
                    float(y[0]),
                    _initial_velocity(t, y),
                )
            )
    return out


def _simulate(d: DrivenRun, m: Model) -> np.ndarray:
    # the spring's rest angle in the logger's frame: record mean of the wheel minus g times that of the drive
    n_whole = int(math.floor((d.t[-1] - d.t[0]) * d.omega / (2 * math.pi) + 1e-9))
    w = d.t < d.t[0] + n_whole * 2 * math.pi / d.omega
    offset = float(d.angle[w].mean() - m.gain * d.drive[w].mean())
    th, _ = simulate_friction_oscillator(
        d.t,
        d.drive,
        m.omega_n,
        m.zeta,
        m.friction,
        m.gain,
        theta0=d.theta0,
        omega0=d.omega0,
        offset=offset,
        substeps=SUBSTEPS,
    )
    return th


def _late_ratio(d: DrivenRun, theta: np.ndarray) -> float:
    m = (d.t >= d.late.t_start - 1e-9) & (d.t < d.late.t_end - 1e-9)
    return harmonic_fit(d.t[m], theta[m], omega=d.omega).amplitude / d.late.drive_amp


def _calibrate(base: Model, runs: list[DrivenRun]) -> Model:
    target = np.array([d.late.ratio for d in runs])

    def cost(g):
        m = Model(base.name, base.omega_n, base.zeta, base.friction, float(g), base.zeta_se, base.friction_se)
        sim = np.array([_late_ratio(d, _simulate(d, m)) for d in runs])
        return float(np.sum((sim - target) ** 2))

    res = optimize.minimize_scalar(cost, bounds=GAIN_BOUNDS, method="bounded", options={"xatol": 1e-4})
    return Model(base.name, base.omega_n, base.zeta, base.friction, float(res.x), base.zeta_se, base.friction_se)


def _curves(models: dict, drive_amp: float) -> Curves:
    lin, com = models["linear"], models["combined"]
    wn = com.omega_n
    omega = np.linspace(0.25 * wn, 1.75 * wn, 240)  # an even count: r = 1 itself is not a grid point
    r_l = omega / lin.omega_n
    lin_ratio = lin.gain / np.sqrt((1 - r_l**2) ** 2 + (2 * lin.zeta * r_l) ** 2)
    lin_lag = np.arctan2(2 * lin.zeta * r_l, 1 - r_l**2)
    r = omega / wn
    delta = com.friction / (com.gain * drive_amp)
    exact = com.gain * np.asarray(friction_forced_amplitude(r, com.zeta, delta))
    hb = com.gain * np.asarray(friction_forced_amplitude_hb(r, com.zeta, delta))
    with np.errstate(invalid="ignore", divide="ignore"):
        x = hb / com.gain  # X / X_st
        zeta_eq = com.zeta + 2.0 * delta / (math.pi * r * x)
        lag = np.arctan2(2 * zeta_eq * r, 1 - r**2)
    both = np.isfinite(exact) & np.isfinite(hb)
    diff = float(np.max(np.abs(exact[both] - hb[both]) / exact[both])) if both.any() else math.nan
    for a in (omega, lin_ratio, lin_lag, exact, hb, lag):
        a.flags.writeable = False
    return Curves(omega, lin_ratio, lin_lag, exact, hb, lag, float(drive_amp), diff)


def _steady_peak(zeta: float, friction: float, gain: float, drive_amp: float) -> float:
    """Steady wheel amplitude (rad) at resonance of the combined model (Den Hartog, exact; inf if unbounded)."""
    if zeta <= 0.0:
        return math.inf if 4.0 * friction / (math.pi * gain * drive_amp) < 1.0 else 0.0
    x = friction_forced_amplitude(1.0, min(zeta, 0.999), friction / (gain * drive_amp))
    return float(x * gain * drive_amp) if math.isfinite(x) else math.nan


def _stick_exact(zeta: float, friction: float, gain: float) -> float:
    """Smallest drive amplitude (rad) with a continuous steady motion at r = 1 (Den Hartog's non-stop condition)."""

    def moves(delta):
        return math.isfinite(friction_forced_amplitude(1.0, max(zeta, 1e-6), delta))

    lo, hi = 0.0, 4.0 / math.pi * 1.5  # delta = Delta / X_st; moves at lo, search the first failure
    if moves(hi):
        return friction / (gain * hi)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if moves(mid):
            lo = mid
        else:
            hi = mid
    return friction / (gain * lo)


def _runs_needed(d: float, s1: float, s2: float) -> int:
    if d == 0:
        return 10**6
    z = stats.norm.ppf(1 - ALPHA / 2) + stats.norm.ppf(POWER)
    return int(max(2, math.ceil(z * z * (s1 * s1 + s2 * s2) / (d * d))))


def _two_sample(decays: dict, parameter: str) -> TwoSample:
    off = np.array([getattr(d.combined, parameter) for d in decays["off"].runs])
    on = np.array([getattr(d.combined, parameter) for d in decays["on"].runs])
    tt = stats.ttest_ind(on, off, equal_var=False)
    mw = stats.mannwhitneyu(on, off, alternative="two-sided")
    s_off, s_on = float(np.std(off, ddof=1)), float(np.std(on, ddof=1))
    return TwoSample(
        parameter,
        float(off.mean()),
        float(on.mean()),
        s_off,
        s_on,
        off.size,
        on.size,
        float(tt.statistic),
        float(tt.pvalue),
        float(mw.pvalue),
        _runs_needed(float(on.mean() - off.mean()), s_off, s_on),
    )


def _group_means(driven, select) -> dict:
    """(session, rounded voltage) -> (mean omega, mean late ratio, its standard error, all steady)."""
    groups: dict = {}
    for d in driven:
        if select(d):
            groups.setdefault((d.session, round(d.voltage, 2)), []).append(d)
    out = {}
    for key, ds in groups.items():
        r = np.array([d.late.ratio for d in ds])
        se = float(np.std(r, ddof=1) / math.sqrt(r.size)) if r.size > 1 else ds[0].late.ratio_se
        se = max(se, float(np.sqrt(np.mean([d.late.ratio_se**2 for d in ds]) / r.size)))
        out[key] = (float(np.mean([d.omega for d in ds])), float(r.mean()), se, all(d.steady for d in ds))
    return out


# ----------------------------------------------------------------------------- the study


def real_oscillator_study(params: Params | None = None, **values) -> RealOscillatorStudy:
    """Run the whole chapter's computation on the lab data.

    Parameters
    ----------
    params : Params, optional
        The validated parameters; or give them as keyword arguments (checked by the schema).

    Returns
    -------
    RealOscillatorStudy
        Frozen record of every result the chapter shows.
    """
    p = params if params is not None else Params.from_values(values)
    prov = provenance()
    decays = {b: _decay_set(b, p.decay_runs) for b in ("off", "on")}
    src = decays[p.brake]
    lin = Model(
        "linear",
        src.pooled[("viscous", "omega_n")].mean,
        src.pooled[("viscous", "zeta")].mean,
        0.0,
        1.0,
        src.pooled[("viscous", "zeta")].stderr,
        0.0,
    )
    com = Model(
        "combined",
        src.pooled[("combined", "omega_n")].mean,
        src.pooled[("combined", "zeta")].mean,
        src.pooled[("combined", "friction")].mean,
        1.0,
        src.pooled[("combined", "zeta")].stderr,
        src.pooled[("combined", "friction")].stderr,
    )
    build_up = 1.0 / (com.zeta * com.omega_n) if com.zeta > 0 else math.inf
    driven = _driven(p, build_up)
    order = sorted(driven, key=lambda d: d.omega)
    calib = order[: p.n_calibration]
    calib_keys = {(d.session, d.run) for d in calib}
    models = {m.name: _calibrate(m, calib) for m in (lin, com)}
    preds = []
    for d in driven:
        for m in models.values():
            th = _simulate(d, m)
            th.flags.writeable = False
            e = d.angle - th
            preds.append(
                Prediction(
                    m.name,
                    d.session,
                    d.run,
                    (d.session, d.run) in calib_keys,
                    th,
                    float(np.sqrt(np.mean(e * e))),
                    float(np.sqrt(np.mean(e * e)) / np.std(d.angle)),
                    _late_ratio(d, th),
                )
            )
    drive_amp = float(np.mean([d.late.drive_amp for d in driven]))
    curves = _curves(models, drive_amp)

    # amplification: the calibration runs' ratio against the largest group mean
    low = np.array([d.late.ratio for d in calib])
    low_se = float(np.std(low, ddof=1) / math.sqrt(low.size)) if low.size > 1 else calib[0].late.ratio_se
    groups = _group_means(driven, lambda d: True)
    peak_key = max(groups, key=lambda k: groups[k][1])
    peak_w, peak_r, peak_se, peak_steady = groups[peak_key]
    # detuning: the group of the same session nearest 10 % below the peak frequency
    same = {k: v for k, v in groups.items() if k[0] == peak_key[0] and v[0] < peak_w}
    det_key = min(same, key=lambda k: abs(same[k][0] - 0.9 * peak_w)) if same else peak_key
    detuning = peak_r / groups[det_key][1]

    # the brake and the bounds on growth (combined model, each brake setting's own free decays)
    g = models["combined"].gain
    peaks_by_brake = {
        b: _steady_peak(
            decays[b].pooled[("combined", "zeta")].mean, decays[b].pooled[("combined", "friction")].mean, g, drive_amp
        )
        for b in ("off", "on")
    }
    band = _brake_band(decays, g, drive_amp, com.omega_n)
    steady_lin = (
        models["linear"].gain * drive_amp / (2 * models["linear"].zeta) if models["linear"].zeta > 0 else math.inf
    )
    steady_com = _steady_peak(com.zeta, com.friction, g, drive_amp)
    stick_hb = 4.0 * com.friction / (math.pi * g)
    stick_ex = _stick_exact(com.zeta, com.friction, g)

    zo, zn = decays["on"].pooled[("combined", "zeta")], decays["off"].pooled[("combined", "zeta")]
    dz, dz_se = zo.mean - zn.mean, math.hypot(zo.stderr, zn.stderr)

    coverage = []
    for b in ("off", "on"):
        for par in ("omega_n", "zeta", "friction"):
            pl = decays[b].pooled[("combined", par)]
            ratio = pl.sd / pl.median_se if pl.median_se > 0 else math.inf
            coverage.append(Coverage(b, par, pl.median_se, pl.sd, ratio, ratio <= p.spread_ratio_max))
    tests = tuple(_two_sample(decays, par) for par in ("zeta", "friction"))

    partial = dict(
        low_ratio=float(low.mean()),
        low_ratio_se=low_se,
        peak_ratio=peak_r,
        peak_ratio_se=peak_se,
        peak_group=peak_key,
        peak_group_steady=peak_steady,
        stick_drive_hb=stick_hb,
        stick_drive_exact=stick_ex,
        steady_peak_linear=steady_lin,
        steady_peak_combined=steady_com,
        steady_peak_brake=peaks_by_brake,
        brake_band=band,
        detuning_factor=float(detuning),
        detuning_omega=(peak_w, groups[det_key][0]),
    )
    return RealOscillatorStudy(
        params=p,
        provenance=prov,
        decays=decays,
        driven=tuple(driven),
        models=models,
        predictions=tuple(preds),
        curves=curves,
        drive_amp=drive_amp,
        coverage=tuple(coverage),
        tests=tests,
        brake_dzeta=dz,
        brake_dzeta_se=dz_se,
        build_up_time=build_up,
        **partial,
    )


def _brake_band(decays, gain, drive_amp, omega_n) -> float:
    """Half-width in omega/omega_n of the band where the brake changes the steady amplitude by > BRAKE_MATTERS."""
    r = np.linspace(0.3, 1.7, 561)
    amps = {}
    for b in ("off", "on"):
        z = max(decays[b].pooled[("combined", "zeta")].mean, 1e-4)
        d = decays[b].pooled[("combined", "friction")].mean / (gain * drive_amp)
        amps[b] = np.asarray(friction_forced_amplitude_hb(r, z, d))
    with np.errstate(invalid="ignore"):
        change = np.abs(amps["on"] / amps["off"] - 1.0)
    matters = ~(change <= BRAKE_MATTERS)  # NaN (no motion in one setting) counts as mattering
    if not matters.any():
        return 0.0
    return float(np.max(np.abs(r[matters] - 1.0)))
