"""The closed forms written out in chapter 1, coded as printed, against vibration.exact_response.

Each regime's equation of the chapter's "The exact solution" section is implemented here
independently (plain numpy, the chapter's notation) and must agree with the package's
stable divided-difference formula to 1e-10 of the response's scale.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibration import Oscillator, SineForce, exact_response, steady_state

T = np.linspace(0.0, 20.0, 2001)
RTOL = 1e-10


def _as_printed(m, c, k, F0, w, x0, v0, t):
    """x, v by the chapter's equations (steady state + transient, or the undamped forms)."""
    wn = math.sqrt(k / m)
    zeta = c / (2 * math.sqrt(k * m))
    s = c / (2 * m)
    if c == 0:
        cs, sn = np.cos(wn * t), np.sin(wn * t)
        free_x = x0 * cs + v0 / wn * sn
        free_v = -x0 * wn * sn + v0 * cs
        if w == wn:
            return free_x + F0 / (2 * k) * (sn - wn * t * cs), free_v + F0 / (2 * m) * t * sn
        a = F0 / (k - m * w * w)
        return (
            free_x + a * (np.sin(w * t) - w / wn * sn),
            free_v + a * w * (np.cos(w * t) - cs),
        )
    X = F0 / math.hypot(k - m * w * w, c * w)
    phi = math.atan2(c * w, k - m * w * w)
    xs, vs = X * np.sin(w * t - phi), w * X * np.cos(w * t - phi)
    a, b = x0 + X * math.sin(phi), v0 - w * X * math.cos(phi)
    if abs(zeta) < 1:
        wd = math.sqrt(wn * wn - s * s)
        e = np.exp(-s * t)
        xh = e * (a * np.cos(wd * t) + (b + s * a) / wd * np.sin(wd * t))
        vh = e * (b * np.cos(wd * t) - (s * b + wn * wn * a) / wd * np.sin(wd * t))
    elif zeta == 1:
        e = np.exp(-s * t)
        xh = e * (a + (b + s * a) * t)
        vh = e * (b - (s * b + wn * wn * a) * t)
    else:
        mu = math.sqrt(s * s - wn * wn)
        s1, s2 = -s + mu, -s - mu
        e1, e2 = np.exp(s1 * t), np.exp(s2 * t)
        xh = ((b - s2 * a) * e1 - (b - s1 * a) * e2) / (s1 - s2)
        vh = (s1 * (b - s2 * a) * e1 - s2 * (b - s1 * a) * e2) / (s1 - s2)
    return xs + xh, vs + vh


CASES = {
    "underdamped, the paper's resonance": (1.0, 0.5, 20.0, 5.0, 4.47),
    "underdamped, reference": (1.0, 0.5, 20.0, 5.0, 3.0),
    "critically damped": (1.0, 2 * math.sqrt(20.0), 20.0, 5.0, 4.47),
    "overdamped": (1.0, 15.0, 20.0, 5.0, 4.47),
    "undamped off resonance": (1.0, 0.0, 20.0, 5.0, 3.0),
    "undamped at exact resonance": (1.0, 0.0, 4.0, 1.0, 2.0),
    "negative damping, oscillating": (1.0, -0.1, 20.0, 5.0, 4.47),
    "negative damping, real roots": (1.0, -12.0, 20.0, 5.0, 3.0),
}


@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize(("x0", "v0"), [(0.0, 0.0), (0.3, -1.2)], ids=["from rest", "from x0 v0"])
def test_each_printed_equation_matches_exact_response(case, x0, v0):
    m, c, k, F0, w = CASES[case]
    osc = Oscillator(m=m, c=c, k=k)
    if case == "critically damped":
        assert osc.regime == "critically damped"
    x, v = _as_printed(m, c, k, F0, w, x0, v0, T)
    ref = exact_response(osc, SineForce(F0=F0, omega=w), T, x0=x0, v0=v0)
    scale_x, scale_v = np.max(np.abs(ref.x)), np.max(np.abs(ref.v))
    assert np.max(np.abs(x - ref.x)) <= RTOL * scale_x, case
    assert np.max(np.abs(v - ref.v)) <= RTOL * scale_v, case


def test_steady_amplitude_and_phase_as_printed():
    for m, c, k, F0, w in [(1.0, 0.5, 20.0, 5.0, 4.47), (1.0, 15.0, 20.0, 5.0, 3.0), (2.0, 0.3, 7.0, 3.0, 9.0)]:
        ss = steady_state(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w))
        assert ss.amplitude == pytest.approx(F0 / math.sqrt((k - m * w * w) ** 2 + (c * w) ** 2), rel=1e-14)
        assert ss.phase == pytest.approx(math.atan2(c * w, k - m * w * w), rel=1e-14)
        assert 0.0 <= ss.phase <= math.pi
