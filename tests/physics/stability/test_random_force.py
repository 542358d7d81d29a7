"""Chapter 6 (issue 21): the force passed to the support under white noise, and its optimum damping.

Checked against an independent frequency-domain integral, S0 int |k + i c w|^2 / |k - m w^2 + i c w|^2 dw,
and against a numerical minimisation over c.
"""

from __future__ import annotations

import math

import pytest
from scipy.integrate import quad
from scipy.optimize import minimize_scalar

from vibration import Oscillator, ParameterError
from vibration.physics.stability import white_noise_force_optimum, white_noise_force_variance


@pytest.mark.parametrize("m, c, k", [(1.0, 0.1, 20.0), (1.0, 0.5, 20.0), (1.0, 15.0, 20.0), (2.5, 3.0, 7.0)])
def test_force_variance_against_the_spectral_integral(m, c, k):
    """var(k x + c v) = k^2 var x + c^2 var v (x, v uncorrelated), each as an integral of its spectrum."""
    S0 = 0.1
    wn = math.sqrt(k / m)

    def sx(w):
        return S0 / abs(k - m * w * w + 1j * c * w) ** 2

    def sv(w):
        return S0 * w * w / abs(k - m * w * w + 1j * c * w) ** 2

    def two_sided(f):
        pts = [0.0, 0.5 * wn, wn, 2 * wn, 20 * wn]
        return 2.0 * (
            sum(quad(f, a, b, limit=500)[0] for a, b in zip(pts, pts[1:], strict=False))
            + quad(f, pts[-1], math.inf, limit=500)[0]
        )

    var = k * k * two_sided(sx) + c * c * two_sided(sv)
    assert white_noise_force_variance(Oscillator(m=m, c=c, k=k), S0) == pytest.approx(var, rel=1e-7)


def test_optimum_against_numerical_minimisation():
    m, k, S0 = 1.0, 20.0, 0.1
    res = minimize_scalar(lambda c: white_noise_force_variance(Oscillator(m=m, c=c, k=k), S0), bounds=(0.01, 100.0),
                          method="bounded", options={"xatol": 1e-10})  # fmt: skip
    c_opt, v_opt = white_noise_force_optimum(m, k, S0)
    assert c_opt == pytest.approx(res.x, rel=1e-5)
    assert v_opt == pytest.approx(res.fun, rel=1e-12)
    for c in (0.1, 0.5, 15.0):
        assert white_noise_force_variance(Oscillator(m=m, c=c, k=k), S0) > v_opt


def test_force_variance_refuses_non_positive_damping():
    with pytest.raises(ParameterError, match="c = 0"):
        white_noise_force_variance(Oscillator(m=1.0, c=0.0, k=20.0), 0.1)
