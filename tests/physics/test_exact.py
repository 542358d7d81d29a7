"""The closed form against independent methods, in every regime.

Two references, neither sharing code or formulas with ``vibration.physics.exact``:

* ``expm_response``: the matrix exponential of the linear system augmented with
  the forcing oscillator, state ``[x, v, sin wt, cos wt]``;
* ``decimal_response``: the textbook solution (undetermined coefficients for the
  particular part, the regime's own homogeneous form) evaluated in 80-digit
  ``decimal`` arithmetic, so cancellation near resonance or near critical damping
  costs nothing at double precision.

Errors are measured as ``max|err| / max|ref|`` over the window. Measured (this
machine, SciPy 1.17): exact vs expm worst 5e-13 (undamped, 20 s, where expm's
own error dominates), exact vs decimal worst 1.1e-14. The cases that once failed
(forced with c < -c_crit, subnormal damping at exact resonance, forcing slower
than 1e-9 rad/s, c = -0.0) are fixed and stay in the parameter lists below;
pointwise 50-digit checks of the two accuracy corners (strong negative damping,
windows much shorter than a period) are in ``tests/physics/test_accuracy.py``.
"""

from __future__ import annotations

import math
from decimal import Decimal, localcontext

import numpy as np
import pytest
from scipy.linalg import expm

from vibration import Oscillator, SineForce, exact_response, steady_state

SQRT20 = math.sqrt(20.0)
C_CRIT = 2.0 * SQRT20  # critical damping of m = 1 kg, k = 20 N/m, N s/m

RTOL_EXPM = 1e-10  # spec; expm itself is good to ~5e-13 on these windows
RTOL_DECIMAL = 1e-13  # measured worst 1.1e-14


# --- references ---


def expm_response(m, c, k, F0, w, t, x0, v0):
    """x, v from expm(A t) y0 with y = [x, v, sin wt, cos wt]."""
    A = np.array(
        [
            [0.0, 1.0, 0.0, 0.0],
            [-k / m, -c / m, F0 / m, 0.0],
            [0.0, 0.0, 0.0, w],
            [0.0, 0.0, -w, 0.0],
        ]
    )
    t = np.asarray(t, dtype=float)
    y = expm(t[:, None, None] * A[None, :, :]) @ np.array([x0, v0, 0.0, 1.0])
    return y[:, 0], y[:, 1]


_PREC = 80  # decimal digits


def _pi() -> Decimal:
    """pi by Machin's formula, to the current precision."""

    def arctan_inv(n: int) -> Decimal:
        x = Decimal(1) / n
        x2, term, total, i = x * x, x, x, 1
        eps = Decimal(10) ** -(_PREC + 5)
        while True:
            term = -term * x2
            step = term / (2 * i + 1)
            if abs(step) < eps:
                return total
            total += step
            i += 1

    return 4 * (4 * arctan_inv(5) - arctan_inv(239))


def _sincos(x: Decimal, pi: Decimal) -> tuple[Decimal, Decimal]:
    r = x - (x / (2 * pi)).to_integral_value() * 2 * pi
    eps = Decimal(10) ** -(_PREC + 5)
    s, term, i = Decimal(0), r, 1
    while abs(term) > eps:
        s += term
        term = -term * r * r / ((i + 1) * (i + 2))
        i += 2
    c, term, i = Decimal(0), Decimal(1), 0
    while abs(term) > eps:
        c += term
        term = -term * r * r / ((i + 1) * (i + 2))
        i += 2
    return s, c


def decimal_response(m, c, k, F0, w, t, x0, v0):
    """Textbook closed form of ``m x'' + c x' + k x = F0 sin(w t)`` in decimal arithmetic.

    The float inputs are converted exactly, so this is the exact solution for the
    very parameters the package receives (e.g. w = float(sqrt 20) is not exactly
    at resonance with k/m = 20; the 80 digits absorb the 1e16 cancellation).
    """
    with localcontext() as ctx:
        ctx.prec = _PREC
        pi = _pi()
        m, c, k, F0, w, x0, v0 = (Decimal(float(p)) for p in (m, c, k, F0, w, x0, v0))
        a, b = k - m * w * w, c * w
        secular = F0 != 0 and a == 0 and b == 0  # exact resonance: x_p = A t cos(w t)
        P = Q = A = Decimal(0)
        if secular:
            A = -F0 / (2 * m * w)
        elif F0 != 0:
            P, Q = F0 * a / (a * a + b * b), -F0 * b / (a * a + b * b)  # x_p = P sin + Q cos
        y0, yd0 = x0 - Q, v0 - w * P - A  # initial values of the homogeneous part
        sigma, wn2 = c / (2 * m), k / m
        q = wn2 - sigma * sigma
        xs, vs = [], []
        for ti in np.asarray(t, dtype=float):
            T = Decimal(float(ti))
            sw, cw = _sincos(w * T, pi)
            xp = P * sw + Q * cw + A * T * cw
            vp = w * (P * cw - Q * sw) + A * (cw - w * T * sw)
            if q > 0:
                wd = q.sqrt()
                sd, cd = _sincos(wd * T, pi)
                e = (-sigma * T).exp()
                y = e * (y0 * cd + (yd0 + sigma * y0) / wd * sd)
                yd = e * (yd0 * cd - (sigma * yd0 + wn2 * y0) / wd * sd)
            elif q == 0:
                e = (-sigma * T).exp()
                y = e * (y0 + (yd0 + sigma * y0) * T)
                yd = e * (yd0 - sigma * (yd0 + sigma * y0) * T)
            else:
                mu = (-q).sqrt()
                r1, r2 = -sigma + mu, -sigma - mu
                c1 = (yd0 - r2 * y0) / (r1 - r2)
                c2 = y0 - c1
                e1, e2 = (r1 * T).exp(), (r2 * T).exp()
                y, yd = c1 * e1 + c2 * e2, c1 * r1 * e1 + c2 * r2 * e2
            xs.append(float(xp + y))
            vs.append(float(vp + yd))
    return np.array(xs), np.array(vs)


def max_rel_err(got, ref):
    """max|got - ref| / max|ref|; 0 only when both vanish identically."""
    err = float(np.max(np.abs(np.asarray(got) - np.asarray(ref))))
    scale = float(np.max(np.abs(ref)))
    if scale == 0.0:
        return 0.0 if err == 0.0 else math.inf
    return err / scale


# --- the regimes (m kg, c N s/m, k N/m, F0 N, omega rad/s, window s, regime) ---

CASES = {
    "underdamped": (1.0, 0.5, 20.0, 5.0, 3.0, 20.0, "underdamped"),
    "underdamped-at-resonance": (1.0, 0.5, 20.0, 5.0, 4.47, 20.0, "underdamped"),
    "critical-exact": (1.0, C_CRIT, 20.0, 5.0, 3.0, 20.0, "critically damped"),
    "critical+1e-9": (1.0, C_CRIT * (1 + 1e-9), 20.0, 5.0, 3.0, 20.0, "overdamped"),
    "critical-1e-9": (1.0, C_CRIT * (1 - 1e-9), 20.0, 5.0, 3.0, 20.0, "underdamped"),
    "critical+1e-6": (1.0, C_CRIT * (1 + 1e-6), 20.0, 5.0, 3.0, 20.0, "overdamped"),
    "critical-1e-6": (1.0, C_CRIT * (1 - 1e-6), 20.0, 5.0, 3.0, 20.0, "underdamped"),
    "overdamped-15": (1.0, 15.0, 20.0, 5.0, 4.47, 20.0, "overdamped"),
    "overdamped-200": (1.0, 200.0, 20.0, 5.0, 4.47, 20.0, "overdamped"),
    "undamped-off-resonance": (1.0, 0.0, 20.0, 5.0, 3.0, 20.0, "undamped"),
    "undamped-resonance": (1.0, 0.0, 20.0, 5.0, SQRT20, 20.0, "undamped"),
    "undamped-resonance-exact-k4": (1.0, 0.0, 4.0, 1.0, 2.0, 20.0, "undamped"),
    "undamped-w(1+1e-9)": (1.0, 0.0, 20.0, 5.0, SQRT20 * (1 + 1e-9), 20.0, "undamped"),
    "undamped-w(1-1e-9)": (1.0, 0.0, 20.0, 5.0, SQRT20 * (1 - 1e-9), 20.0, "undamped"),
    "undamped-w(1+1e-6)": (1.0, 0.0, 20.0, 5.0, SQRT20 * (1 + 1e-6), 20.0, "undamped"),
    "undamped-w(1-1e-6)": (1.0, 0.0, 20.0, 5.0, SQRT20 * (1 - 1e-6), 20.0, "undamped"),
    "tiny-damping-at-resonance": (1.0, 1e-9, 20.0, 5.0, SQRT20, 20.0, "underdamped"),
    "negative-0.2": (1.0, -0.2, 20.0, 5.0, 3.0, 20.0, "unstable"),
    "negative-0.2-at-resonance": (1.0, -0.2, 20.0, 5.0, SQRT20, 20.0, "unstable"),
    "negative-critical": (1.0, -C_CRIT, 20.0, 5.0, 3.0, 5.0, "unstable"),
    # growth exp(13.5 t): 2 s is 27 e-foldings, where expm is still accurate (1e-12)
    "negative-15": (1.0, -15.0, 20.0, 5.0, 3.0, 2.0, "unstable"),
    "omega-zero": (1.0, 0.5, 20.0, 5.0, 0.0, 20.0, "underdamped"),
    "free-decay": (1.0, 0.5, 20.0, 0.0, 3.0, 20.0, "underdamped"),
    "free-decay-overdamped": (1.0, 15.0, 20.0, 0.0, 3.0, 20.0, "overdamped"),
    "mass-3-k-7": (3.0, 0.4, 7.0, 2.0, 1.1, 20.0, "underdamped"),
    "mass-3-k-7-critical": (3.0, 2.0 * math.sqrt(21.0), 7.0, 2.0, 1.1, 20.0, "critically damped"),
}
INITIAL = {"rest": (0.0, 0.0), "x0v0": (0.3, -0.7), "x0": (-1.0, 0.0), "v0": (0.0, 1.0)}


def _cases():
    for name, case in CASES.items():
        for ic_name, ic in INITIAL.items():
            yield pytest.param(*case, *ic, id=f"{name}-{ic_name}")


@pytest.mark.slow  # over 1.5 s: make test-slow runs it
@pytest.mark.parametrize(("m", "c", "k", "F0", "w", "T", "regime", "x0", "v0"), list(_cases()))
def test_against_expm(m, c, k, F0, w, T, regime, x0, v0):
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w)
    assert osc.regime == regime
    t = np.linspace(0.0, T, 2001)
    r = exact_response(osc, force, t, x0=x0, v0=v0)
    x_ref, v_ref = expm_response(m, c, k, F0, w, t, x0, v0)
    assert r.t.shape == r.x.shape == r.v.shape == t.shape
    assert max_rel_err(r.x, x_ref) <= RTOL_EXPM
    assert max_rel_err(r.v, v_ref) <= RTOL_EXPM


@pytest.mark.parametrize(
    ("m", "c", "k", "F0", "w", "T", "regime", "x0", "v0"),
    [p for p in _cases() if p.id.endswith(("-rest", "-x0v0"))],
)
def test_against_decimal_closed_form(m, c, k, F0, w, T, regime, x0, v0):
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w)
    t = np.linspace(0.0, T, 201)
    r = exact_response(osc, force, t, x0=x0, v0=v0)
    x_ref, v_ref = decimal_response(m, c, k, F0, w, t, x0, v0)
    assert max_rel_err(r.x, x_ref) <= RTOL_DECIMAL
    assert max_rel_err(r.v, v_ref) <= RTOL_DECIMAL


@pytest.mark.parametrize(("c", "T"), [(-15.0, 0.5), (-15.0, 1.0), (-12.0, 1.0), (-3.0 * C_CRIT, 0.5)])
def test_strongly_negative_damping_pointwise(c, T):
    """Beyond critical negative damping (two real positive roots), point by point.

    Early samples are where a wrong forced part shows: the growing free mode has
    not yet swamped it.
    """
    osc, force = Oscillator(m=1.0, c=c, k=20.0), SineForce(F0=5.0, omega=3.0)
    t = np.linspace(0.0, T, 51)[1:]
    x_ref, v_ref = decimal_response(1.0, c, 20.0, 5.0, 3.0, t, 0.0, 0.0)
    r = exact_response(osc, force, t)
    # relative 1e-12 point by point, with an absolute floor of 1e-13 of the window's
    # largest value (the split into steady state and transient cancels near t = 0)
    np.testing.assert_allclose(r.x, x_ref, rtol=1e-12, atol=1e-13 * np.max(np.abs(x_ref)))
    np.testing.assert_allclose(r.v, v_ref, rtol=1e-12, atol=1e-13 * np.max(np.abs(v_ref)))


@pytest.mark.parametrize("c", [1e-310, 3e-309])
def test_subnormal_damping_at_resonance(c):
    """A subnormal damping coefficient is, to double precision, no damping at all."""
    t = np.linspace(0.0, 20.0, 201)
    r = exact_response(Oscillator(m=1.0, c=c, k=1.0), SineForce(F0=1.0, omega=1.0), t)
    secular = 0.5 * (np.sin(t) - t * np.cos(t))  # F0/(2 m wn^2) (sin wn t - wn t cos wn t)
    assert max_rel_err(r.x, secular) <= 1e-12
    assert max_rel_err(r.v, 0.5 * t * np.sin(t)) <= 1e-12


@pytest.mark.parametrize("c", [0.0, 0.5, 15.0])
@pytest.mark.parametrize("w", [1e-3, 1e-6, 1e-9, 1e-12])
def test_slow_forcing(c, w):
    """omega << omega_n: x from rest is O(omega F0 / k), and must be accurate relative to itself."""
    t = np.linspace(0.0, 20.0, 201)
    r = exact_response(Oscillator(m=1.0, c=c, k=20.0), SineForce(F0=5.0, omega=w), t)
    x_ref, v_ref = decimal_response(1.0, c, 20.0, 5.0, w, t, 0.0, 0.0)
    assert max_rel_err(r.x, x_ref) <= RTOL_EXPM
    assert max_rel_err(r.v, v_ref) <= RTOL_EXPM


def test_negative_and_unordered_times():
    """The closed form holds backwards in time too, in any order."""
    rng = np.random.default_rng(20240611)
    t = rng.permutation(np.linspace(-3.0, 3.0, 601))
    for m, c, k, F0, w in [
        (1.0, 0.5, 20.0, 5.0, 3.0),
        (1.0, 15.0, 20.0, 5.0, 4.47),
        (1.0, 0.0, 20.0, 5.0, SQRT20),
    ]:
        r = exact_response(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w), t, x0=0.3, v0=-0.7)
        x_ref, v_ref = expm_response(m, c, k, F0, w, t, 0.3, -0.7)
        assert max_rel_err(r.x, x_ref) <= RTOL_EXPM
        assert max_rel_err(r.v, v_ref) <= RTOL_EXPM


# --- textbook closed forms ---


@pytest.mark.parametrize(("k", "w"), [(20.0, SQRT20), (4.0, 2.0)])
@pytest.mark.parametrize(("x0", "v0"), [(0.0, 0.0), (0.3, -0.7)])
def test_undamped_resonance_secular_solution(k, w, x0, v0):
    """x = F0/(2 m wn^2) (sin wn t - wn t cos wn t) + x0 cos wn t + v0/wn sin wn t."""
    m, F0 = 1.0, 5.0
    wn = math.sqrt(k / m)
    t = np.linspace(0.0, 20.0, 2001)
    r = exact_response(Oscillator(m=m, c=0.0, k=k), SineForce(F0=F0, omega=w), t, x0=x0, v0=v0)
    x = F0 / (2 * m * wn**2) * (np.sin(wn * t) - wn * t * np.cos(wn * t))
    x += x0 * np.cos(wn * t) + v0 / wn * np.sin(wn * t)
    v = F0 / (2 * m) * t * np.sin(wn * t) - x0 * wn * np.sin(wn * t) + v0 * np.cos(wn * t)
    assert max_rel_err(r.x, x) <= 1e-12
    assert max_rel_err(r.v, v) <= 1e-12


def test_docstring_example_value_at_pi():
    """Undamped, k = 4, w = 2: x(pi) = F0/(2 m wn^2) (0 - 2 pi) = -pi/4."""
    r = exact_response(Oscillator(m=1.0, c=0.0, k=4.0), SineForce(F0=1.0, omega=2.0), [0.0, math.pi])
    assert r.x[0] == 0.0
    assert r.x[1] == pytest.approx(-math.pi / 4, rel=1e-14)


@pytest.mark.parametrize("c", [0.5, 2.0, C_CRIT, 15.0])
def test_free_decay_from_textbook_forms(c):
    """F0 = 0: the textbook homogeneous solution of each regime, in floating point."""
    m, k, x0, v0 = 1.0, 20.0, 0.4, -1.3
    sigma, wn2 = c / (2 * m), k / m
    t = np.linspace(0.0, 10.0, 1001)
    r = exact_response(Oscillator(m=m, c=c, k=k), SineForce(F0=0.0, omega=3.0), t, x0=x0, v0=v0)
    if Oscillator(m=m, c=c, k=k).regime == "underdamped":
        wd = math.sqrt(wn2 - sigma**2)
        x = np.exp(-sigma * t) * (x0 * np.cos(wd * t) + (v0 + sigma * x0) / wd * np.sin(wd * t))
    elif Oscillator(m=m, c=c, k=k).regime == "critically damped":
        x = np.exp(-sigma * t) * (x0 + (v0 + sigma * x0) * t)
    else:
        mu = math.sqrt(sigma**2 - wn2)
        r1, r2 = -sigma + mu, -sigma - mu
        c1 = (v0 - r2 * x0) / (r1 - r2)
        x = c1 * np.exp(r1 * t) + (x0 - c1) * np.exp(r2 * t)
    assert max_rel_err(r.x, x) <= 1e-12


def test_shapes_scalar_and_list():
    osc, f = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    r = exact_response(osc, f, 1.5)
    assert r.x.shape == () and r.v.shape == () and r.t.shape == ()
    r2 = exact_response(osc, f, [1.5])
    assert r2.x.shape == (1,)
    assert float(r.x) == r2.x[0]
    assert r.method == "exact" and r.nfev == 0 and r.status == 0 and r.success


@pytest.mark.parametrize("case", ["underdamped", "critical-exact", "overdamped-15", "undamped-resonance"])
def test_initial_conditions_hold_exactly(case):
    m, c, k, F0, w, *_ = CASES[case]
    r = exact_response(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w), [0.0], x0=0.3, v0=-0.7)
    assert r.x[0] == pytest.approx(0.3, abs=1e-15)
    assert r.v[0] == pytest.approx(-0.7, abs=1e-15)


# --- steady state: textbook values and a second formulation ---


@pytest.mark.parametrize(
    ("m", "c", "k", "F0", "w"),
    [
        (1.0, 0.5, 20.0, 5.0, 3.0),
        (1.0, 0.5, 20.0, 5.0, 4.47),
        (1.0, 15.0, 20.0, 5.0, 4.47),
        (1.0, 0.1, 20.0, 5.0, 9.0),
        (3.0, 0.4, 7.0, 2.0, 1.1),
        (1.0, 0.0, 20.0, 5.0, 3.0),
        (1.0, 0.0, 20.0, 5.0, 9.0),
    ],
)
def test_steady_state_textbook(m, c, k, F0, w):
    ss = steady_state(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w))
    amp = F0 / math.sqrt((k - m * w**2) ** 2 + (c * w) ** 2)
    assert ss.amplitude == pytest.approx(amp, rel=1e-13)
    assert ss.phase == pytest.approx(math.atan2(c * w, k - m * w**2), rel=1e-13, abs=1e-15)
    assert 0.0 <= ss.phase <= math.pi
    assert ss.static_deflection == pytest.approx(F0 / k, rel=1e-15)
    assert ss.magnification == pytest.approx(amp / (F0 / k), rel=1e-13)
    assert ss.velocity_amplitude == pytest.approx(w * amp, rel=1e-13)


def test_steady_state_reference_case_values():
    """The paper's reference case: about 0.45 m (the paper rounds it to 0.5 m)."""
    ss = steady_state(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0))
    assert ss.amplitude == pytest.approx(5.0 / math.hypot(11.0, 1.5), rel=1e-14)  # 0.4504 m
    assert ss.amplitude == pytest.approx(0.4504, abs=5e-5)
    assert ss.phase == pytest.approx(math.atan(1.5 / 11.0), rel=1e-14)  # 0.1355 rad


def test_steady_state_phase_spans_zero_to_pi():
    osc = Oscillator(m=1.0, c=0.5, k=20.0)
    phases = [steady_state(osc, SineForce(F0=1.0, omega=w)).phase for w in np.linspace(0.0, 50.0, 501)]
    assert phases[0] == 0.0
    assert all(0.0 <= p <= math.pi for p in phases)
    assert np.all(np.diff(phases) > 0)
    assert steady_state(osc, SineForce(F0=1.0, omega=SQRT20)).phase == pytest.approx(math.pi / 2, rel=1e-15)
    assert phases[-1] > 0.99 * math.pi


def test_steady_state_phase_with_negative_zero_damping():
    """c = -0.0 is c = 0 (undamped): the lag is 0 below resonance and pi above, not -pi."""
    osc = Oscillator(m=1.0, c=-0.0, k=20.0)
    assert osc.regime == "undamped"
    assert steady_state(osc, SineForce(F0=5.0, omega=3.0)).phase == 0.0
    assert steady_state(osc, SineForce(F0=5.0, omega=9.0)).phase == pytest.approx(math.pi, rel=1e-15)


def test_steady_state_undamped_resonance_and_zero_force():
    ss = steady_state(Oscillator(m=1.0, c=0.0, k=4.0), SineForce(F0=5.0, omega=2.0))
    assert ss.amplitude == math.inf and ss.magnification == math.inf
    assert ss.phase == pytest.approx(math.pi / 2, rel=1e-15)
    ss0 = steady_state(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=0.0, omega=3.0))
    assert ss0.amplitude == 0.0 and ss0.velocity_amplitude == 0.0


@pytest.mark.parametrize(
    ("m", "c", "k", "F0", "w", "t_start"),
    [
        (1.0, 0.5, 20.0, 5.0, 3.0, 200.0),  # transient exp(-0.25 t): e^-50 at 200 s
        (1.0, 0.5, 20.0, 5.0, 4.47, 200.0),
        (1.0, 0.1, 20.0, 5.0, 4.47, 1000.0),  # exp(-0.05 t): e^-50
        (1.0, 15.0, 20.0, 5.0, 4.47, 40.0),  # slow root -1.48 1/s: e^-59
        (1.0, C_CRIT, 20.0, 5.0, 3.0, 20.0),
        (3.0, 0.4, 7.0, 2.0, 1.1, 800.0),  # sigma = 1/15 1/s
    ],
)
def test_large_time_equals_steady_state(m, c, k, F0, w, t_start):
    """Second formulation: once the transient has decayed, x = A sin(w t - phi)."""
    osc, force = Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w)
    ss = steady_state(osc, force)
    t = np.linspace(t_start, t_start + 10.0, 1001)
    r = exact_response(osc, force, t, x0=0.3, v0=-0.7)
    # both sides evaluate sin of an argument ~ w t ~ 5e3 rad: allow eps * w t
    tol = 1e-12 + 4e-16 * w * t[-1]
    np.testing.assert_allclose(r.x, ss.amplitude * np.sin(w * t - ss.phase), rtol=0, atol=tol * ss.amplitude)
    np.testing.assert_allclose(
        r.v, ss.velocity_amplitude * np.cos(w * t - ss.phase), rtol=0, atol=tol * ss.velocity_amplitude
    )


# --- validation ---


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_times_must_be_finite(raises_parameter_error, bad):
    osc, f = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0)
    with raises_parameter_error("t", bad, "finite"):
        exact_response(osc, f, [0.0, 1.0, bad, 2.0])
    with raises_parameter_error("t", bad, "finite"):
        exact_response(osc, f, bad)


def test_times_must_be_one_dimensional(raises_parameter_error):
    with raises_parameter_error("t", (3, 2), "1-D"):
        exact_response(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), np.zeros((3, 2)))


@pytest.mark.parametrize("name", ["x0", "v0"])
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, "0.1", True, None])
def test_initial_conditions_must_be_finite_reals(raises_parameter_error, name, bad):
    with raises_parameter_error(name, bad, "finite"):
        exact_response(Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=3.0), [0.0, 1.0], **{name: bad})
