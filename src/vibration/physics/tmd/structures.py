"""Models built from MDOF records: modal damping, the shear building, absorbers on a structure."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..checks import check_array, check_choice
from ..model import ParameterError, check_real
from ._limits import ENTRY_MAX, ENTRY_MIN, N_DOF_MAX, SPREAD_MAX, ZETA_MAX, ZETA_P_OPT_MAX
from .mdof import MDOF, _matrix
from .tuning import TMDTuning, den_hartog, h2_tuning, hinf_tuning


def modal_damping_matrix(M, K, zeta) -> np.ndarray:
    """Classical damping matrix C = M Φ diag(2 ζ_i ω_i) Φᵀ M with given modal damping ratios.

    Parameters
    ----------
    M, K : array_like
        Mass (kg) and stiffness (N/m) matrices, symmetric positive definite.
    zeta : float or array_like
        Damping ratio of every mode (or one per mode, ascending frequency), 1 (0 to 10).

    Returns
    -------
    numpy.ndarray
        C, N s/m.

    Examples
    --------
    >>> C = modal_damping_matrix([[1.0]], [[20.0]], 0.0559)
    >>> round(float(C[0, 0]), 3)
    0.5
    """
    model = MDOF(M=M, C=np.zeros_like(_matrix("M", M, None)), K=K)
    z = check_array("zeta", zeta, low=0.0, high=ZETA_MAX, ndim=(0, 1), max_size=N_DOF_MAX)
    if np.any((z > 0.0) & (z < ZETA_MIN)):
        raise ParameterError(
            f"zeta contains {float(z[(z > 0.0) & (z < ZETA_MIN)][0])!r}: allowed zeta = 0 or {ZETA_MIN:g} <= zeta <= "
            f"{ZETA_MAX:g} (a smaller damping ratio underflows the damping matrix)"
        )
    if z.size not in (1, model.n):
        raise ParameterError(f"zeta has {z.size} values: allowed 1 or one per mode ({model.n})")
    z = np.broadcast_to(z, (model.n,))
    w, phi = model.natural_frequencies, model.modes
    Mphi = model.M @ phi
    C = Mphi @ np.diag(2.0 * z * w) @ Mphi.T
    return 0.5 * (C + C.T)


def shear_building(masses, stiffnesses, zeta=0.05) -> MDOF:
    """Shear building: floor masses on storeys of given lateral stiffness, classical modal damping.

    Degree of freedom i is floor i + 1 counted from the ground (the last is the roof);
    storey i joins floor i to the floor below (the ground for i = 0).

    Parameters
    ----------
    masses : array_like
        Floor masses, kg (> 0), ground floor first.
    stiffnesses : array_like
        Storey stiffnesses, N/m (> 0), same length.
    zeta : float or array_like
        Modal damping ratio of every mode (or one per mode), 1.

    Returns
    -------
    MDOF

    Examples
    --------
    >>> b = shear_building([1.0, 1.0], [1.0, 1.0], zeta=0.0)
    >>> b.K.tolist()
    [[2.0, -1.0], [-1.0, 1.0]]
    """
    m = np.atleast_1d(
        check_array("masses", masses, low=ENTRY_MIN, high=ENTRY_MAX, ndim=(0, 1), max_size=N_DOF_MAX, unit="kg")
    )
    k = np.atleast_1d(
        check_array(
            "stiffnesses", stiffnesses, low=ENTRY_MIN, high=ENTRY_MAX, ndim=(0, 1), max_size=N_DOF_MAX, unit="N/m"
        )
    )
    for name, arr, unit in (("masses", m, "kg"), ("stiffnesses", k, "N/m")):
        if arr.max() > SPREAD_MAX * arr.min():
            raise ParameterError(
                f"{name} spans {arr.min():.3g} to {arr.max():.3g} {unit}, a ratio of {arr.max() / arr.min():.3g}: "
                f"allowed a largest-to-smallest ratio of at most {SPREAD_MAX:g}"
            )
    if k.shape != m.shape:
        raise ParameterError(
            f"masses has {m.size} values and stiffnesses {k.size}: "
            f"allowed two 1-D arrays of equal length 1..{N_DOF_MAX}"
        )
    n = m.size
    K = np.zeros((n, n))
    for i in range(n):
        K[i, i] += k[i]
        if i + 1 < n:
            K[i, i] += k[i + 1]
            K[i, i + 1] = K[i + 1, i] = -k[i + 1]
    M = np.diag(m)
    return MDOF(M=M, C=modal_damping_matrix(M, K, zeta), K=K)


def add_absorber(model: MDOF, dof: int, m_a, *, k_a, c_a) -> MDOF:
    """The model with an absorber (mass, spring, dashpot) attached to degree of freedom ``dof``.

    The absorber is the new last degree of freedom.

    Parameters
    ----------
    model : MDOF
    dof : int
        Index of the degree of freedom carrying it (negative counts from the end).
    m_a, k_a, c_a : float
        Absorber mass (kg, > 0), stiffness (N/m, > 0), damping (N s/m, >= 0).

    Returns
    -------
    MDOF

    Examples
    --------
    >>> s = add_absorber(MDOF(M=[[1.0]], C=[[0.0]], K=[[20.0]]), 0, 0.05, k_a=0.9, c_a=0.01)
    >>> s.n, s.is_classically_damped
    (2, False)
    """
    if not isinstance(model, MDOF):
        raise ParameterError(f"model = {model!r} is not an MDOF: allowed MDOF(M, C, K)")
    n = model.n
    if isinstance(dof, bool) or not isinstance(dof, int | np.integer) or not -n <= dof < n:
        raise ParameterError(f"dof = {dof!r} is out of range: allowed an integer -{n} <= dof < {n}")
    j = int(dof) % n
    m_a = check_real("m_a", m_a, low=ENTRY_MIN, high=ENTRY_MAX, unit="kg")
    k_a = check_real("k_a", k_a, low=ENTRY_MIN, high=ENTRY_MAX, unit="N/m")
    c_a = check_real("c_a", c_a, low=0.0, high=ENTRY_MAX, unit="N s/m")
    if 0.0 < c_a < ENTRY_MIN:
        raise ParameterError(f"c_a = {c_a!r} N s/m is out of range: allowed c_a = 0 or {ENTRY_MIN:g} <= c_a N s/m")
    M, C, K = (np.zeros((n + 1, n + 1)) for _ in range(3))
    M[:n, :n], C[:n, :n], K[:n, :n] = model.M, model.C, model.K
    M[n, n] = m_a
    for A, v in ((C, c_a), (K, k_a)):
        A[j, j] += v
        A[n, n] += v
        A[j, n] -= v
        A[n, j] -= v
    return MDOF(M=M, C=C, K=K)


def tmd_system(m, c, k, *, tuning: TMDTuning) -> MDOF:
    """Two-degree-of-freedom model: the primary (m kg, c N s/m, k N/m) and the absorber of ``tuning``.

    Degree of freedom 0 is the primary, 1 the absorber.

    Examples
    --------
    >>> s = tmd_system(1.0, 0.5, 20.0, tuning=den_hartog(0.05))
    >>> s.n, round(float(s.M[1, 1]), 3)
    (2, 0.05)
    """
    if not isinstance(tuning, TMDTuning):
        raise ParameterError(f"tuning = {tuning!r} is not a TMDTuning: allowed den_hartog(...), hinf_tuning(...)")
    m = check_real("m", m, low=ENTRY_MIN, high=ENTRY_MAX, unit="kg")
    c = check_real("c", c, low=0.0, high=ENTRY_MAX, unit="N s/m")
    k = check_real("k", k, low=ENTRY_MIN, high=ENTRY_MAX, unit="N/m")
    if 0.0 < c < ENTRY_MIN:
        raise ParameterError(f"c = {c!r} N s/m is out of range: allowed c = 0 or {ENTRY_MIN:g} <= c N s/m")
    m_a, k_a, c_a = tuning.absorber(m, k)
    for name, value, unit in (("m_a", m_a, "kg"), ("k_a", k_a, "N/m"), ("c_a", c_a, "N s/m")):
        if not (ENTRY_MIN <= value <= ENTRY_MAX or (name == "c_a" and value == 0.0)):
            raise ParameterError(
                f"m = {m!r} kg, k = {k!r} N/m and the tuning (mu = {tuning.mu!r}, f = {tuning.f!r}, zeta_a = "
                f"{tuning.zeta_a!r}) give the absorber's {name} = {value:.3g} {unit}: allowed {ENTRY_MIN:g} to "
                f"{ENTRY_MAX:g} {unit}"
            )
    return add_absorber(MDOF(M=[[m]], C=[[c]], K=[[k]]), 0, m_a, k_a=k_a, c_a=c_a)


@dataclass(frozen=True, kw_only=True)
class ModeAbsorber:
    """An absorber tuned to one mode of an MDOF structure through its equivalent single-degree-of-freedom system."""

    tuning: TMDTuning  # tuning on the equivalent primary (mass ratio to the modal mass)
    modal_mass: float  # generalised mass of the mode normalised to 1 at the carrying degree of freedom, kg
    omega: float  # natural frequency of the mode, rad/s
    zeta: float  # damping ratio of the mode, 1
    m_a: float  # absorber mass, kg
    k_a: float  # absorber stiffness, N/m
    c_a: float  # absorber damping, N s/m


def first_mode_absorber(model: MDOF, mu, dof: int = -1, *, rule: str = "H∞") -> ModeAbsorber:
    """Absorber at ``dof`` tuned to the first mode (equivalent SDOF: modal mass, frequency, damping).

    The first mode φ is scaled to 1 at ``dof``; the equivalent primary has mass
    M1 = φᵀ M φ, stiffness ω1² M1 and the mode's damping ratio, and the absorber
    mass is μ M1. The rule ("H∞": :func:`hinf_tuning` on the damped equivalent
    primary, "Den Hartog", or "H2": :func:`h2_tuning`) gives f and ζ_a.

    Parameters
    ----------
    model : MDOF
        Classically damped structure.
    mu : float
        Absorber mass over the first modal mass, 1 (0 < mu <= 10).
    dof : int
        Degree of freedom carrying the absorber (default: the last, the roof).
    rule : {"H∞", "Den Hartog", "H2"}

    Returns
    -------
    ModeAbsorber

    Examples
    --------
    >>> a = first_mode_absorber(MDOF(M=[[1.0]], C=[[0.5]], K=[[20.0]]), 0.05)
    >>> round(a.modal_mass, 3), round(a.zeta, 4), round(a.tuning.f, 4)
    (1.0, 0.0559, 0.9331)
    """
    if not isinstance(model, MDOF):
        raise ParameterError(f"model = {model!r} is not an MDOF: allowed MDOF(M, C, K)")
    n = model.n
    if isinstance(dof, bool) or not isinstance(dof, int | np.integer) or not -n <= dof < n:
        raise ParameterError(f"dof = {dof!r} is out of range: allowed an integer -{n} <= dof < {n}")
    rules = {"H∞": hinf_tuning, "Den Hartog": den_hartog, "H2": h2_tuning}
    rule = check_choice("rule", rule, tuple(rules))
    phi = model.modes[:, 0]
    if phi[dof] == 0.0:
        raise ParameterError(f"dof = {dof}: the first mode does not move there, allowed a moving degree of freedom")
    phi = phi / phi[dof]
    m1 = float(phi @ model.M @ phi)
    w1 = float(model.natural_frequencies[0])
    z1 = float(model.modal_damping_ratios[0])
    tuning = rules[rule](mu, zeta_p=min(z1, ZETA_P_OPT_MAX))
    m_a, k_a, c_a = tuning.absorber(m1, w1 * w1 * m1)
    return ModeAbsorber(tuning=tuning, modal_mass=m1, omega=w1, zeta=z1, m_a=m_a, k_a=k_a, c_a=c_a)


def ground_acceleration_load(model: MDOF) -> np.ndarray:
    """Effective load of a unit ground acceleration: −M ι, N per (m/s²), with ι a vector of ones.

    Every degree of freedom is a horizontal translation, so under ground acceleration a_g sin(ω t)
    the displacements relative to the ground obey M x'' + C x' + K x = −M ι a_g sin(ω t); with this
    load :meth:`MDOF.frf` gives the relative displacement per unit ground acceleration, s².

    Examples
    --------
    >>> ground_acceleration_load(shear_building([2.0, 1.0], [1.0, 1.0], zeta=0.0)).tolist()
    [-2.0, -1.0]
    """
    if not isinstance(model, MDOF):
        raise ParameterError(f"model = {model!r} is not an MDOF: allowed MDOF(M, C, K)")
    return -(model.M @ np.ones(model.n))


#: Smallest non-zero modal damping ratio (the damping matrix's entries stay normal floats).
ZETA_MIN = 1e-50

#: Frequencies of the grid of :func:`frf_peak` before the refinement.
N_FRF_GRID = 2001


def frf_peak(model: MDOF, load, dof: int, *, omega_min, omega_max) -> tuple[float, float]:
    """Largest steady amplitude of one degree of freedom over a frequency band, and where it is reached.

    |X_dof(ω)| of :meth:`MDOF.frf` on a grid of 2001 frequencies, then each interior local maximum of
    the grid refined by bounded Brent on its bracket (to 1e-12 of the band, relative).

    Parameters
    ----------
    model : MDOF
    load : array_like
        Force amplitudes, N, shape (n,).
    dof : int
        Degree of freedom whose amplitude is maximised (negative counts from the end).
    omega_min, omega_max : float
        The band, rad/s (0 <= omega_min < omega_max).

    Returns
    -------
    (float, float)
        The largest |X_dof| (m per unit of the load's scale) and its frequency, rad/s.

    Examples
    --------
    >>> s = MDOF(M=[[1.0]], C=[[0.5]], K=[[20.0]])
    >>> x, w = frf_peak(s, [5.0], 0, omega_min=3.0, omega_max=6.0)
    >>> round(x, 4), round(w, 4)        # F0/k / (2ζ sqrt(1 − ζ²)) at ω_n sqrt(1 − 2ζ²)
    (2.2396, 4.4581)
    """
    from scipy.optimize import minimize_scalar

    if not isinstance(model, MDOF):
        raise ParameterError(f"model = {model!r} is not an MDOF: allowed MDOF(M, C, K)")
    n = model.n
    if isinstance(dof, bool) or not isinstance(dof, int | np.integer) or not -n <= dof < n:
        raise ParameterError(f"dof = {dof!r} is out of range: allowed an integer -{n} <= dof < {n}")
    lo = check_real("omega_min", omega_min, low=0.0, unit="rad/s")
    hi = check_real("omega_max", omega_max, low=lo, low_open=True, unit="rad/s")
    p = model._load(load)
    w = np.linspace(lo, hi, N_FRF_GRID)
    a = np.abs(model.frf(w, p)[:, dof])
    i = int(np.argmax(a))
    best, w_best = float(a[i]), float(w[i])

    def amp(x):
        return -float(np.abs(model.frf([x], p)[0, dof]))

    for j in range(1, N_FRF_GRID - 1):
        if a[j] >= a[j - 1] and a[j] >= a[j + 1] and a[j] >= 0.5 * best:
            res = minimize_scalar(amp, bounds=(w[j - 1], w[j + 1]), method="bounded", options={"xatol": 1e-12 * hi})
            if -res.fun > best:
                best, w_best = float(-res.fun), float(res.x)
    return best, w_best
