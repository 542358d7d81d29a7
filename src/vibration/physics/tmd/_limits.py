"""Limits of the tuned-mass-damper and MDOF functions, and the validation they share."""

from __future__ import annotations

import functools
import inspect

import numpy as np

from ..checks import check_array
from ..model import ParameterError, check_real

#: Largest mass ratio accepted, 1.
MU_MAX = 10.0
#: Smallest mass ratio accepted, 1 (below it the fixed points merge at r = 1 in floating point).
MU_MIN = 1e-9
#: Largest tuning ratio accepted, 1.
F_MAX = 10.0
#: Largest damping ratio accepted (absorber or primary) in the magnification, 1.
ZETA_MAX = 10.0
#: Largest primary damping ratio for which the optimal tunings are computed, 1.
ZETA_P_OPT_MAX = 0.5
#: Relative tolerance of the symmetry of M, C, K and of the classical-damping test.
SYM_TOL = 1e-10
#: Largest number of degrees of freedom of an MDOF model.
N_DOF_MAX = 500
#: Largest number of stiffness errors :func:`mistuned_peak` evaluates (one peak search each).
MISTUNED_MAX = 10_000
#: Largest work of one frequency-response or time-response call, in units of n³ (one n x n solve each):
#: ``len(omegas) n³`` for :meth:`MDOF.frf`, ``len(t) (2n + 2)³`` for the matrix exponentials of :meth:`MDOF.response`.
WORK_MAX = 2e9
#: Range of the magnitude of every non-zero entry of M, C, K (kg, N s/m, N/m) and of the physical inputs that
#: build them: their products and eigenvalues stay finite, normal floats (a subnormal entry stops LAPACK's SVD).
ENTRY_MIN, ENTRY_MAX = 1e-100, 1e100
#: Largest ratio of the largest to the smallest floor mass or storey stiffness of a shear building: beyond it the
#: smallest eigenvalue of K is lost in the rounding of the largest.
SPREAD_MAX = 1e12
#: Largest number of entries (len(t) times 2n) of one response array.
ENTRIES_MAX = 20_000_000


# ----------------------------------------------------------------------------- validation
def _no_nan(fn):
    """Run ``fn`` with numpy's floating-point warnings off and refuse a nan anywhere in its result.

    ``inf`` stays where it is documented (an undamped resonance); a nan would be an overflow or an
    undefined value coming out silently, so it is a :class:`ParameterError` instead.
    """

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with np.errstate(all="ignore"):
            out = fn(*args, **kwargs)
        values = out._finite_fields() if hasattr(out, "_finite_fields") else out  # a TMDTuning: its numbers
        try:
            arr = np.asarray(values, dtype=float)
        except (TypeError, ValueError):  # a tuple of arrays of different shapes
            arr = np.concatenate([np.ravel(np.asarray(v, dtype=float)) for v in values])
        if np.any(np.isnan(arr)):
            try:
                bound = inspect.signature(fn).bind(*args, **kwargs).arguments
                shown = ", ".join(f"{k} = {v!r:.60}" for k, v in bound.items())
            except TypeError:
                shown = f"{args!r:.200}"
            raise ParameterError(
                f"{fn.__name__} with {shown}: the result is not defined in floating point (an overflow or "
                f"underflow of these arguments' products); allowed mu in [{MU_MIN:g}, {MU_MAX:g}], f in (0, "
                f"{F_MAX:g}], damping ratios in [0, {ZETA_MAX:g}] whose products stay finite"
            )
        return out

    return wrapper


def _mu(mu) -> float:
    return check_real("mu", mu, low=MU_MIN, high=MU_MAX, unit="(m_a/m_p)")


def _f(f) -> float:
    return check_real("f", f, low=0.0, low_open=True, high=F_MAX, unit="(ω_a/ω_p)")


def _zeta(name: str, z, high: float = ZETA_MAX) -> float:
    return check_real(name, z, low=0.0, high=high)


def _ratios(r) -> np.ndarray:
    return check_array("r", r, low=0.0, ndim=(0, 1, 2), unit="(ω/ω_p)")
