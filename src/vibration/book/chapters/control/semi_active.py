"""Chapter 7's semi-active suspension: the base-excited oscillator swept in frequency and run in time with
the ideal, on-off and clipped skyhook and a scaled MR damper, their transmissibility, forces and powers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.control.params import Params
from vibration.book.chapters.control.steady import t_steady
from vibration.physics.control import (
    SPENCER_1997,
    SPENCER_1997_STROKE,
    Metrics,
    MRDamper,
    SemiActiveResponse,
    SemiActiveSweep,
    SkyhookPower,
    passive_transmissibility,
    response_metrics,
    semi_active_response,
    semi_active_sweep,
    skyhook_power,
    skyhook_transmissibility,
)
from vibration.physics.model import Oscillator

#: RK4 steps per period of the on-off skyhook refinement at omega_n (the sweeps use 1000).
REFINE_STEPS = (1000, 4000, 16000, 64000)


@dataclass(frozen=True, kw_only=True)
class SemiActiveFindings:
    """What the sweeps show: where clipped skyhook beats every passive damper, and what it costs."""

    band: tuple[float, float]  # frequency ratios where clipped skyhook beats the best passive damper (nan: none)
    all_near: bool  # it beats it over the whole band 1/sqrt(2) .. sqrt(2)
    any_near: bool  # it beats it somewhere in that band
    t_res: dict[str, float]  # transmissibility at omega_n: "soft", "firm", "skyhook", "clipped", "on-off", "mr"
    loss_soft: float  # largest clipped/soft ratio above sqrt(2) omega_n, 1
    gain_firm: float  # smallest firm/clipped ratio above sqrt(2) omega_n, 1
    mr_loss_soft: float  # largest MR/soft ratio above sqrt(2) omega_n, 1
    switches: float  # median command changes per period of the on-off law, 1
    force_res: float  # RMS force of the clipped damper at omega_n, N
    force_res_firm: float  # RMS force of the firm passive damper at omega_n, N


@dataclass(frozen=True, kw_only=True)
class SemiActiveStudy:
    """Semi-active suspension: sweeps across frequency and time runs at the forcing frequency."""

    osc: Oscillator  # m, passive c, k
    Y: float  # base amplitude, m
    omega: float  # base frequency of the time runs, rad/s
    c_sky: float  # skyhook gain, N s/m
    c_min: float  # device damping bounds, N s/m
    c_max: float
    damper: MRDamper  # scaled MR damper
    mr_scale: tuple[float, float]  # (length, force) scale factors
    ratios: np.ndarray  # frequency ratios of the sweep, 1
    closed: dict[str, np.ndarray]  # "soft"/"firm"/"skyhook"/"envelope" -> transmissibility (closed form)
    sweeps: dict[str, SemiActiveSweep]  # "on-off"/"clipped"/"mr"
    runs: dict[str, SemiActiveResponse]  # "soft"/"firm"/"skyhook"/"on-off"/"clipped"/"mr"
    metrics: dict[str, Metrics]
    t_steady: float  # s
    refine: dict[int, float]  # RK4 steps per period -> on-off skyhook peak transmissibility at omega_n, 1
    power: SkyhookPower  # closed form at omega
    power_run: dict[str, float]  # the same four mean powers measured on the skyhook run's steady tail, W
    closed_run_error: dict[str, float]  # "soft"/"skyhook": run's steady max|x|/Y against the closed form, relative
    worst_power: float  # largest instantaneous power f v_rel the on-off and clipped dampers deliver, W
    findings: SemiActiveFindings


def _passive_force_rms(osc: Oscillator, c_d: float, Y: float, w: float) -> float:
    """RMS force of a passive device damper c_d in steady state under base motion, N."""
    h = (osc.k + 1j * (osc.c + c_d) * w) / (osc.k - osc.m * w * w + 1j * (osc.c + c_d) * w)
    return c_d * w * Y * abs(h - 1.0) / math.sqrt(2.0)


def _findings(osc, ratios, closed, sweeps, c_max, Y) -> SemiActiveFindings:
    cl = sweeps["clipped"].peak
    beats = cl < closed["envelope"]
    near = np.abs(np.log(ratios)) <= np.log(np.sqrt(2.0))
    hi = ratios >= math.sqrt(2.0)
    i1 = int(np.argmin(np.abs(ratios - 1.0)))
    idx = np.nonzero(beats)[0]
    return SemiActiveFindings(
        band=(float(ratios[idx.min()]), float(ratios[idx.max()])) if idx.size else (math.nan, math.nan),
        all_near=bool(np.all(beats[near])),
        any_near=bool(np.any(beats[near])),
        t_res={
            "soft": float(closed["soft"][i1]),
            "firm": float(closed["firm"][i1]),
            "skyhook": float(closed["skyhook"][i1]),
            "clipped": float(cl[i1]),
            "on-off": float(sweeps["on-off"].peak[i1]),
            "mr": float(sweeps["mr"].peak[i1]),
        },
        loss_soft=float(np.max(cl[hi] / closed["soft"][hi])),
        gain_firm=float(np.min(closed["firm"][hi] / cl[hi])),
        mr_loss_soft=float(np.max(sweeps["mr"].peak[hi] / closed["soft"][hi])),
        switches=float(np.median(sweeps["on-off"].switches)),
        force_res=float(sweeps["clipped"].force_rms[i1]),
        force_res_firm=_passive_force_rms(osc, c_max, Y, ratios[i1] * osc.natural_frequency),
    )


def _closed_forms(osc: Oscillator, p: Params, ratios: np.ndarray, w: np.ndarray) -> dict[str, np.ndarray]:
    """Closed-form transmissibility: soft and firm passive dampers, ideal skyhook, the best passive envelope."""
    return {
        "soft": passive_transmissibility(Oscillator(m=p.m, c=p.c_nominal + p.c_sa_min, k=p.k), w),
        "firm": passive_transmissibility(Oscillator(m=p.m, c=p.c_nominal + p.c_sa_max, k=p.k), w),
        "skyhook": skyhook_transmissibility(osc, p.c_sky, w),
        "envelope": np.where(ratios < math.sqrt(2.0), 1.0, 1.0 / np.abs(ratios**2 - 1.0 + (ratios == 1.0))),
    }


def _runs(osc: Oscillator, p: Params, Y: float, damper: MRDamper) -> dict[str, SemiActiveResponse]:
    """Time runs of every law at the forcing frequency: soft, firm, skyhook, on-off, clipped, MR."""
    c_min, c_max = p.c_sa_min, p.c_sa_max
    runs = {}
    for name, law, cmin, cmax in (
        ("soft", "passive", c_min, c_min),
        ("firm", "passive", c_max, c_max),
        ("skyhook", "skyhook", c_min, c_max),
        ("on-off", "on-off", c_min, c_max),
        ("clipped", "clipped", c_min, c_max),
        ("mr", "mr", c_min, c_max),
    ):
        runs[name] = semi_active_response(
            osc, law, p.omega_res, Y=Y, c_sky=p.c_sky, c_min=cmin, c_max=cmax, damper=damper, t_end=p.t_end,
            n_points=p.n_points,
        )  # fmt: skip
    return runs


def _power_run(sky: SemiActiveResponse, c_sky: float, ts: float) -> dict[str, float]:
    """The skyhook run's mean powers over its steady tail (trapezoidal rule), W."""
    tail = sky.t >= ts
    tt = sky.t[tail]
    p_rel = (sky.f * (sky.v - sky.v_base))[tail]
    span = tt[-1] - tt[0]

    def mean(y):
        return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(tt))) / span

    return {
        "removed": mean(c_sky * sky.v[tail] ** 2),
        "net": mean(p_rel),
        "supplied": mean(np.maximum(p_rel, 0.0)),
        "gross": mean(np.abs(p_rel)),
    }


def _closed_run_error(osc: Oscillator, p: Params, runs: dict, Y: float, ts: float) -> dict[str, float]:
    """The soft and skyhook runs' steady max|x|/Y against the closed form, relative."""
    omega = p.omega_res
    closed_run_error = {}
    for name, exact in (
        ("soft", float(passive_transmissibility(Oscillator(m=p.m, c=p.c_nominal + p.c_sa_min, k=p.k), omega))),
        ("skyhook", float(skyhook_transmissibility(osc, p.c_sky, omega))),
    ):
        r = runs[name]
        closed_run_error[name] = abs(float(np.max(np.abs(r.x[r.t >= ts]))) / Y / exact - 1.0)
    return closed_run_error


def semi_active_study(params: Params | None = None, **values) -> SemiActiveStudy:
    """Base excitation ``Y = F0 / k`` (so that ``k Y = F0``): sweeps and runs of every law.

    The MR damper is :data:`~vibration.physics.control.SPENCER_1997` scaled so that its stroke at
    the test amplitude (1.5 cm) maps onto ``Y`` and its full-voltage yield force onto ``f_mr`` (N).

    Examples
    --------
    >>> s = semi_active_study(t_end=5.0, n_points=101, n_sweep=10)
    >>> round(s.Y, 3), sorted(s.sweeps)
    (0.25, ['clipped', 'mr', 'on-off'])
    """
    p = params if params is not None else Params.from_values(values)
    osc = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    c_min, c_max, omega = p.c_sa_min, p.c_sa_max, p.omega_res
    Y = p.F0 / p.k
    wn = osc.natural_frequency
    ratios = np.unique(np.concatenate([np.geomspace(0.3, 4.0, p.n_sweep), [1.0, math.sqrt(2.0)]]))
    w = ratios * wn
    closed = _closed_forms(osc, p, ratios, w)
    scale = (Y / SPENCER_1997_STROKE, p.f_mr / SPENCER_1997.yield_force)
    damper = SPENCER_1997.scaled(*scale)
    kw = {"c_sky": p.c_sky, "c_min": c_min, "c_max": c_max}
    sweeps = {law: semi_active_sweep(osc, law, w, Y=Y, damper=damper, **kw) for law in ("on-off", "clipped", "mr")}
    runs = _runs(osc, p, Y, damper)
    ts = t_steady(p.t_end, omega)
    metrics = {name: response_metrics(r.t, r.x, r.f, v_rel=r.v - r.v_base, t_steady=ts) for name, r in runs.items()}
    refine = {
        spp: float(semi_active_sweep(osc, "on-off", np.array([wn]), Y=Y, steps_per_period=spp, **kw).peak[0])
        for spp in REFINE_STEPS
    }
    power_run = _power_run(runs["skyhook"], p.c_sky, ts)
    closed_run_error = _closed_run_error(osc, p, runs, Y, ts)
    worst = max(float(np.max(runs[n].f * (runs[n].v - runs[n].v_base))) for n in ("on-off", "clipped"))
    return SemiActiveStudy(
        osc=osc,
        Y=Y,
        omega=omega,
        c_sky=p.c_sky,
        c_min=c_min,
        c_max=c_max,
        damper=damper,
        mr_scale=scale,
        ratios=ratios,
        closed=closed,
        sweeps=sweeps,
        runs=runs,
        metrics=metrics,
        t_steady=ts,
        refine=refine,
        power=skyhook_power(osc, p.c_sky, Y, omega=omega),
        power_run=power_run,
        closed_run_error=closed_run_error,
        worst_power=worst,
        findings=_findings(osc, ratios, closed, sweeps, c_max, Y),
    )
