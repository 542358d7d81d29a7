"""Another laboratory's Pohl wheel, simulated with a known law and written as CASSY Lab 2 files with a manifest.

The law: theta'' + 2 zeta(I) omega_n theta' + omega_n^2 Delta sgn theta' + omega_n^2 theta = omega_n^2 g U(t),
with the eddy-current brake's viscous ratio zeta(I) = ZETA0 + K_BRAKE I^2 (I the brake current in A) and a
constant Coulomb angle DELTA. Integrated with SciPy's solve_ivp between velocity reversals (its own event loop,
independent of the package), sampled at 10 Hz, rounded to the sensor's 0.001 rad and written in the German
export format (UTF-8 with BOM, ';', decimal comma, derived columns included).
"""

from __future__ import annotations

import math
import zlib
from pathlib import Path

import numpy as np
from scipy import integrate

OMEGA_N = 4.40  # rad/s
DELTA = 0.020  # rad
ZETA0 = 0.003
K_BRAKE = 0.08  # 1/A^2
GAIN = 0.06  # rad per V of the exciter's signal
STEP = 0.001  # rad, sensor resolution
RATE = 10.0  # Hz
CURRENTS = (0.0, 0.2, 0.4, 0.7)  # A
DRIVEN_CURRENTS = (0.2, 0.7)
DRIVE_OMEGAS = (3.6, 4.1, 4.4, 4.7, 5.2)  # rad/s
DRIVEN_SECONDS = {0.2: 130.0, 0.7: 60.0}  # record lengths: about 3.5 build-up times at 200 mA, 11 at 700 mA
HEADER = (
    "Zeit t / s",
    "Weg &b_A1 / rad",
    "Spannung U_B1 / V",
    "Frequenz f / Hz",
    "FFT fft / rad",
    "zeitliche Ableitung w_1 / rad/s",
)


def zeta_of(current: float) -> float:
    """The brake's viscous damping ratio at a current (A)."""
    return ZETA0 + K_BRAKE * current * current


def _free(t_eval: np.ndarray, zeta: float, theta0: float) -> np.ndarray:
    w2 = OMEGA_N**2
    out = np.empty_like(t_eval)
    t_now, y, v = 0.0, theta0, 0.0
    while True:
        if abs(y) <= DELTA:  # at rest inside the dead band: stuck for good
            out[t_eval >= t_now] = y
            return out
        s = -math.copysign(1.0, y)  # direction of the next motion

        def rhs(_t, x, s=s):
            return [x[1], -w2 * x[0] - 2.0 * zeta * OMEGA_N * x[1] - w2 * DELTA * s]

        def stop(_t, x, s=s, t0=t_now):
            return x[1] if _t > t0 + 1e-6 else s

        stop.terminal, stop.direction = True, -s
        sol = integrate.solve_ivp(
            rhs, (t_now, t_eval[-1]), [y, v], method="DOP853", rtol=1e-10, atol=1e-12, events=stop, dense_output=True
        )
        t_end = float(sol.t_events[0][0]) if sol.t_events[0].size else float(t_eval[-1])
        m = (t_eval >= t_now) & (t_eval <= t_end)
        out[m] = sol.sol(t_eval[m])[0]
        if not sol.t_events[0].size:
            return out
        t_now, y, v = t_end, float(sol.sol(t_end)[0]), 0.0


def _driven(t_eval: np.ndarray, zeta: float, omega: float, volts: float) -> np.ndarray:
    w2 = OMEGA_N**2

    def rhs(t, x):
        return [
            x[1],
            -w2 * x[0]
            - 2.0 * zeta * OMEGA_N * x[1]
            - w2 * DELTA * math.tanh(x[1] / 0.01)
            + w2 * GAIN * volts * math.sin(omega * t),
        ]

    sol = integrate.solve_ivp(rhs, (0.0, t_eval[-1]), [0.0, 0.0], method="LSODA", rtol=1e-8, atol=1e-10, t_eval=t_eval)
    return sol.y[0]


def _fmt(x: float) -> str:
    return f"{x:.4f}".replace(".", ",")


def _write(path: Path, t, theta, volts) -> None:
    rng = np.random.default_rng(zlib.crc32(path.name.encode()))
    theta = np.round((theta + rng.normal(0.0, 0.3 * STEP, theta.size)) / STEP) * STEP
    w = np.gradient(theta, t)
    lines = [";".join(HEADER)]
    for i in range(t.size):
        f = _fmt(0.7) if i < t.size // 2 else ""
        fft = _fmt(abs(theta[i])) if i < t.size // 2 else ""
        lines.append(";".join([_fmt(t[i]), _fmt(theta[i]), _fmt(volts[i]), f, fft, _fmt(w[i])]))
    path.write_bytes(("\ufeff" + "\r\n".join(lines) + "\r\n").encode("utf-8"))


def write_lab(folder) -> dict:
    """Write the lab's files and manifest into ``folder``; returns the true law's constants."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    rows = ["file,kind,brake,brake_current_A,session,run"]
    for current in CURRENTS:
        label = f"{round(current * 1000)} mA"
        for j, theta0 in enumerate((2.5, 3.0, 3.5)):
            duration = 500.0 if current == 0.0 else 70.0 + 40.0 * j
            t = np.arange(0.0, duration, 1.0 / RATE)
            theta = _free(t, zeta_of(current), theta0)
            name = f"frei_{round(current * 1000)}mA_{j + 1}.csv"
            _write(folder / name, t, theta, 0.002 * np.ones_like(t))
            rows.append(f"{name},free,{label},{current},A,")
    for current in DRIVEN_CURRENTS:
        label = f"{round(current * 1000)} mA"
        for j, omega in enumerate(DRIVE_OMEGAS):
            t = np.arange(0.0, DRIVEN_SECONDS[current], 1.0 / RATE)
            volts = 4.0
            theta = _driven(t, zeta_of(current), omega, volts)
            name = f"erzwungen_{round(current * 1000)}mA_{j + 1}.csv"
            _write(folder / name, t, theta, volts * np.sin(omega * t))
            rows.append(f"{name},driven,{label},{current},A,")
    (folder / "runs.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    (folder / "rig.csv").write_text(
        "encoder_step_rad,max_angle_rad,description\n0.001,30.0,simulated Pohl wheel (eddy-current brake)\n",
        encoding="utf-8",
    )
    return {"omega_n": OMEGA_N, "friction": DELTA, "zeta0": ZETA0, "k_brake": K_BRAKE, "gain": GAIN}


if __name__ == "__main__":  # pragma: no cover - manual use: python tests/pohl_generator.py DIR
    import sys

    write_lab(sys.argv[1])
