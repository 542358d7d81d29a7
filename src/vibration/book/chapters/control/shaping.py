"""Chapter 7's input shaping: a point-to-point move, unshaped and with ZV and ZVD shapers designed on a
model whose natural frequency is off by ``freq_error``, and the shapers' sensitivity to that error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.control.params import Params
from vibration.physics.control import (
    Shaper,
    insensitivity_band,
    residual_amplitude,
    shaped_move,
    shaper_residual,
    zv_shaper,
    zvd_shaper,
)
from vibration.physics.model import Oscillator, check_int

#: Largest residual vibration (fraction of the unshaped step's) that a shaper's band tolerates.
SHAPER_LEVEL = 0.05


@dataclass(frozen=True, kw_only=True)
class ShapingStudy:
    """Point-to-point moves with and without input shaping, and the sensitivity curves."""

    model: Oscillator  # the oscillator the shapers are designed on
    actual: Oscillator  # the real one (natural frequency off by freq_error)
    move: float  # distance, m
    freq_error: float  # relative natural-frequency error, 1
    shapers: dict[str, Shaper]  # "ZV"/"ZVD"
    t: np.ndarray  # times, s
    x: dict[str, np.ndarray]  # "none"/"ZV"/"ZVD" -> displacement, m
    residual: dict[str, float]  # residual vibration ratio (closed form), 1
    residual_sim: dict[str, float]  # ratio measured on the simulated move, 1
    amplitude: dict[str, float]  # ringing amplitude just after the move, m
    ratios: np.ndarray  # real / model natural frequency, 1
    sensitivity: dict[str, np.ndarray]  # "ZV"/"ZVD" -> residual vibration ratio along ratios, 1
    design_residual: float  # largest residual ratio at the design point, 1
    bands: dict[str, tuple[float, float]]  # "ZV"/"ZVD" -> ratios where V <= SHAPER_LEVEL (exact roots), 1


def shaping_study(
    params: Params | None = None, *, t_end: float = 10.0, n_points: int = 2001, n_ratio: int = 201, **values
) -> ShapingStudy:
    """ZV and ZVD on the model ``(m, c_nominal, k)``; moves of ``move`` m on the real oscillator whose
    natural frequency is ``(1 + freq_error)`` times the model's (k scaled by its square).

    ``t_end`` (s) and ``n_points`` set the window of the moves, ``n_ratio`` the sensitivity grid.
    """
    p = params if params is not None else Params.from_values(values)
    n_ratio = check_int("n_ratio", n_ratio, low=2, high=100_000)
    model = Oscillator(m=p.m, c=p.c_nominal, k=p.k)
    actual = Oscillator(m=p.m, c=p.c_nominal, k=p.k * (1.0 + p.freq_error) ** 2)
    shapers = {"ZV": zv_shaper(model), "ZVD": zvd_shaper(model)}
    xs, res, sim, amp = {}, {}, {}, {}
    t0, x0, v0, _ = shaped_move(actual, None, p.move, t_end=t_end, n_points=n_points)
    a0 = residual_amplitude(actual, t0, x0, v=v0, target=p.move)
    for name, sh in (("none", None), *shapers.items()):
        t, x, v, _ = shaped_move(actual, sh, p.move, t_end=t_end, n_points=n_points)
        xs[name] = x
        res[name] = shaper_residual(sh, actual)
        tn = 0.0 if sh is None else sh.duration
        after = t > tn + 1e-12
        ring = residual_amplitude(actual, t, x, v=v, target=p.move)
        ratio = np.median(ring[after] / a0[after]) * math.exp(-actual.decay_rate * tn)  # Singer-Seering V
        sim[name] = float(ratio) if p.move != 0 else 0.0
        amp[name] = float(ring[after][0] * math.exp(actual.decay_rate * (t[after][0] - tn)))
    ratios = np.linspace(0.5, 1.5, n_ratio)
    sens = {
        name: np.array([shaper_residual(sh, Oscillator(m=p.m, c=p.c_nominal, k=p.k * q * q)) for q in ratios])
        for name, sh in shapers.items()
    }
    return ShapingStudy(
        model=model,
        actual=actual,
        move=p.move,
        freq_error=p.freq_error,
        shapers=shapers,
        t=t0,
        x=xs,
        residual=res,
        residual_sim=sim,
        amplitude=amp,
        ratios=ratios,
        sensitivity=sens,
        design_residual=max(shaper_residual(sh, model) for sh in shapers.values()),
        bands={name: insensitivity_band(sh, model, SHAPER_LEVEL) for name, sh in shapers.items()},
    )
