"""Fuzz tests of physics/stability.py and physics/tmd.py (issue 20): invalid and extreme inputs give a
ParameterError that says what is allowed, or a finite result, each call within a wall-clock budget.

The watchdog and the finiteness check are those of tests/test_fuzz_control.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_fuzz_control import BAD_ARRAYS, BAD_SCALARS, _finite, guarded, refused

from vibration.physics import stability as stb
from vibration.physics import tmd
from vibration.physics.model import Oscillator, ParameterError, SineForce

OSC = Oscillator(m=1.0, c=0.5, k=20.0)

extreme = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-300, 1e-6, 1e6, 1e8, 1e150, 1e300, -1.0, -1e8]),
)
oscs = st.builds(
    Oscillator,
    m=st.sampled_from([1e-3, 1.0, 1e3]),
    c=st.sampled_from([-0.5, 0.0, 0.02, 0.5, 15.0, 1e6]),
    k=st.sampled_from([1e-6, 1.0, 20.0, 1e8]),
)
#: Arrays no function here accepts (the frequency, time and ratio grids may be 2-D, any shape).
BAD = [b for b in BAD_ARRAYS if np.ndim(b) != 2 or np.size(b) == 0]
ids = lambda b: type(b).__name__ + str(np.shape(b)) if b is not None else "None"  # noqa: E731


def _ok_or_documented_inf(out):
    """transmissibility and tmd_magnification document ``inf`` at an exact undamped resonance."""
    arr = np.asarray(out, dtype=float)
    assert not np.any(np.isnan(arr)), out


# ----------------------------------------------------------------------------- stability


@pytest.mark.parametrize("bad", BAD, ids=ids)
def test_stability_array_arguments_refused(bad):
    force = SineForce(F0=5.0, omega=4.47)
    refused(stb.transmissibility, OSC, bad)
    refused(stb.growth_envelope, OSC, force, bad)
    refused(stb.step_response, OSC, bad)
    refused(stb.damper_load, OSC, 5.0, bad)


@pytest.mark.parametrize("bad", BAD_SCALARS, ids=ids)
def test_stability_scalar_arguments_refused(bad):
    refused(stb.poles, bad)
    refused(stb.step_metrics, OSC, bad)
    refused(stb.settling_optimal_zeta, bad)
    refused(stb.white_noise_variance, OSC, bad)
    refused(stb.white_noise_velocity_variance, OSC, bad)
    refused(stb.simulate_white_noise, OSC, 1.0, bad)
    refused(stb.white_noise_monte_carlo, OSC, 1.0, n_paths=bad)
    refused(stb.damper_load, OSC, bad, 1.0)
    refused(stb.design_metrics, OSC, bad)


def test_stability_overflow_is_an_error():
    flutter = Oscillator(m=1.0, c=-0.5, k=20.0)
    refused(stb.growth_envelope, flutter, SineForce(F0=5.0, omega=4.47), [0.0, 1e6])
    refused(stb.step_response, flutter, [0.0, 1e6])
    refused(stb.damper_load, Oscillator(m=1.0, c=0.0, k=4.0), 1.0, [2.0])


def test_stability_work_is_bounded():
    refused(stb.simulate_white_noise, OSC, 1.0, 1e300, dt=1e-300)
    refused(stb.simulate_white_noise, OSC, 1.0, 1e6, dt=1e-3, n_paths=100)
    refused(stb.white_noise_monte_carlo, OSC, 1.0, n_paths=100_000, dt=1e-4)
    refused(stb.white_noise_monte_carlo, OSC, 1.0, duration=1e300, dt=1e-300)
    refused(stb.step_response, OSC, np.zeros(2_000_000))


@settings(max_examples=25, deadline=None)
@given(osc=oscs, w=st.one_of(extreme, st.lists(extreme, min_size=1, max_size=4)), F0=extreme)
def test_frequency_functions_fuzz(osc, w, F0):
    out = guarded(stb.transmissibility, osc, w, finite=False)
    if not isinstance(out, ParameterError):
        _ok_or_documented_inf(out)
    guarded(stb.damper_load, osc, F0, w)


@settings(max_examples=25, deadline=None)
@given(osc=oscs, F0=st.sampled_from([0.0, 1.0, 1e6]), w=st.sampled_from([0.0, 1e-6, 4.47, 1e6]), t=extreme)
def test_time_functions_fuzz(osc, F0, w, t):
    guarded(stb.growth_envelope, osc, SineForce(F0=F0, omega=w), [0.0, t])
    guarded(stb.step_response, osc, [0.0, t])


@settings(max_examples=25, deadline=None)
@given(osc=oscs, band=extreme, ratio=extreme)
def test_scalar_functions_fuzz(osc, band, ratio):
    guarded(stb.poles, osc, finite=False)
    guarded(stb.stability_class, osc)
    guarded(stb.isolation_frequency, osc)
    out = guarded(stb.peak_transmissibility, osc, finite=False)
    if not isinstance(out, ParameterError):
        _ok_or_documented_inf(out)
    guarded(stb.peak_magnification, osc, finite=False)
    guarded(stb.step_metrics, osc, band, finite=False)
    guarded(stb.settling_optimal_zeta, band)
    guarded(stb.design_metrics, osc, ratio, band, finite=False)


@settings(max_examples=15, deadline=None)
@given(osc=oscs, S0=extreme, t_end=extreme, dt=st.one_of(st.none(), extreme), seed=st.sampled_from([-1, 0, 2**70]))
def test_random_functions_fuzz(osc, S0, t_end, dt, seed):
    guarded(stb.white_noise_variance, osc, S0)
    guarded(stb.white_noise_velocity_variance, osc, S0)
    guarded(stb.simulate_white_noise, osc, S0, t_end, dt=dt, n_paths=2, seed=seed)


@settings(max_examples=8, deadline=None)
@given(osc=oscs, S0=st.sampled_from([0.0, 1.0, 1e6]), n=st.sampled_from([2, 5]), dur=st.one_of(st.none(), extreme))
def test_monte_carlo_fuzz(osc, S0, n, dur):
    guarded(stb.white_noise_monte_carlo, osc, S0, n_paths=n, duration=dur)


# ----------------------------------------------------------------------------- tmd


@pytest.mark.parametrize("bad", BAD, ids=ids)
def test_tmd_array_arguments_refused(bad):
    model = tmd.MDOF(M=[[1.0]], C=[[0.5]], K=[[20.0]])
    refused(tmd.tmd_magnification, 0.05, 1.0, 0.1, r=bad)
    refused(tmd.mistuned_peak, tmd.den_hartog(0.05), bad)
    refused(model.frf, bad, [1.0])
    refused(model.frf, [1.0], bad)
    refused(model.response, bad, [1.0], 1.0)
    refused(model.response, [0.0, 1.0], bad, 1.0)
    if bad is not None:  # None is the default: from rest
        refused(model.response, [0.0, 1.0], [1.0], 1.0, x0=bad)
    refused(tmd.shear_building, bad, [1.0])
    refused(tmd.shear_building, [1.0], bad)
    refused(tmd.modal_damping_matrix, [[1.0]], [[20.0]], bad)


@pytest.mark.parametrize("bad", BAD_SCALARS, ids=ids)
def test_tmd_scalar_arguments_refused(bad):
    refused(tmd.tmd_magnification, bad, 1.0, 0.1, r=1.0)
    refused(tmd.tmd_peak, 0.05, bad, 0.1)
    refused(tmd.h2_norm, 0.05, 1.0, bad)
    refused(tmd.den_hartog, bad)
    refused(tmd.hinf_tuning, 0.05, bad)
    refused(tmd.h2_tuning, bad)
    refused(tmd.tmd_fixed_points, 0.05, bad)
    refused(tmd.tmd_system, bad, 0.5, 20.0, tuning=tmd.den_hartog(0.05))
    refused(tmd.add_absorber, tmd.MDOF(M=[[1.0]], C=[[0.0]], K=[[20.0]]), 0, bad, k_a=1.0, c_a=0.1)
    refused(tmd.first_mode_absorber, tmd.MDOF(M=[[1.0]], C=[[0.5]], K=[[20.0]]), bad)
    refused(lambda m: tmd.MDOF(M=m, C=[[0.0]], K=[[1.0]]), bad)


def test_tmd_work_is_bounded():
    big = tmd.shear_building(np.ones(200), np.ones(200))
    refused(big.frf, np.linspace(0.0, 1.0, 300_000), np.ones(200))
    refused(big.response, np.linspace(0.0, 1.0, 100_000), np.ones(200), 1.0)
    refused(big.response, np.linspace(0.0, 1.0, 1000), np.ones(200), 1.0, method="expm")
    refused(tmd.mistuned_peak, tmd.den_hartog(0.05), np.zeros(20_000))
    refused(tmd.shear_building, np.ones(600), np.ones(600))


@settings(max_examples=25, deadline=None)
@given(mu=extreme, f=extreme, za=extreme, zp=extreme, r=st.one_of(extreme, st.lists(extreme, min_size=1, max_size=4)))
def test_tmd_curves_fuzz(mu, f, za, zp, r):
    out = guarded(tmd.tmd_magnification, mu, f, za, r=r, zeta_p=zp, finite=False)
    if not isinstance(out, ParameterError):
        _ok_or_documented_inf(out)
    guarded(tmd.tmd_peak, mu, f, za, zeta_p=zp, finite=False)
    guarded(tmd.h2_norm, mu, f, za, zeta_p=zp, finite=False)
    guarded(tmd.tmd_fixed_points, mu, f)


@settings(max_examples=10, deadline=None)
@given(
    mu=st.sampled_from([1e-6, 1e-3, 0.05, 1.0, 10.0, 0.0, -1.0, math.nan, 11.0]),
    zp=st.sampled_from([0.0, 1e-9, 0.05, 0.5, 0.6, -0.1]),
    method=st.sampled_from(["auto", "closed form", "numerical", "bogus"]),
)
def test_tmd_tunings_fuzz(mu, zp, method):
    for fn in (tmd.hinf_tuning, tmd.h2_tuning):
        out = guarded(fn, mu, zp, method)
        if isinstance(out, tmd.TMDTuning):
            _finite((out.f, out.zeta_a, out.peak))
            guarded(tmd.mistuned_peak, out, [-0.5, 0.0, 1.0])
    guarded(tmd.den_hartog, mu, zp, finite=False)


@settings(max_examples=15, deadline=None)
@given(
    m=st.sampled_from([1e-3, 1.0, 1e6]),
    c=st.sampled_from([0.0, 0.5, 1e6]),
    k=st.sampled_from([1e-6, 20.0, 1e8]),
    t=extreme,
    w=extreme,
)
def test_mdof_fuzz(m, c, k, t, w):
    model = guarded(tmd.tmd_system, m, c, k, tuning=tmd.den_hartog(0.05), finite=False)
    if isinstance(model, ParameterError):
        return
    out = guarded(model.frf, [w], [1.0, 0.0], finite=False)
    if not isinstance(out, ParameterError):
        assert not np.any(np.isnan(out))
    guarded(model.response, [0.0, t], [1.0, 0.0], w)
    guarded(model.response, [0.0, t], [1.0, 0.0], w, method="expm")
    guarded(tmd.first_mode_absorber, model, 0.05, finite=False)
