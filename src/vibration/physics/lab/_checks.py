"""Input validation shared by the lab analyses (sampled series, bounded sizes)."""

from __future__ import annotations

import numpy as np

from vibration.physics.model import ParameterError

#: Largest number of samples an analysis accepts.
MAX_SAMPLES = 1_000_000
#: Fewest samples an analysis accepts.
MIN_SAMPLES = 20


def as_series(name: str, value, *, unit: str = "", min_size: int = MIN_SAMPLES) -> np.ndarray:
    """Return ``value`` as a 1-D float array of finite reals, or raise :class:`ParameterError`.

    Bool, complex, object and string arrays are refused, as are NaN and infinities.
    """
    try:
        arr = np.asarray(value)
    except Exception:  # noqa: BLE001 - any conversion failure is a wrong input
        raise ParameterError(f"{name} = {value!r} is not an array: allowed a 1-D array of real numbers") from None
    if arr.dtype == bool or arr.dtype.kind not in "iuf":
        raise ParameterError(
            f"{name} has dtype {arr.dtype} which is out of range: allowed a 1-D array of real numbers (not bool or "
            "complex)"
        )
    if arr.ndim != 1:
        raise ParameterError(f"{name} has shape {arr.shape} which is out of range: allowed a 1-D array")
    if arr.size > MAX_SAMPLES:
        raise ParameterError(f"{name} has {arr.size} samples which is out of range: allowed at most {MAX_SAMPLES}")
    if arr.size < min_size:
        raise ParameterError(f"{name} has {arr.size} samples which is out of range: allowed at least {min_size}")
    out = arr.astype(float)
    bad = ~np.isfinite(out)
    if bad.any():
        i = int(np.argmax(bad))
        u = f" {unit}" if unit else ""
        raise ParameterError(f"{name}[{i}] = {out[i]!r}{u} is out of range: allowed finite values")
    return out


def time_and_signal(t, y, *, t_name: str = "t", y_name: str = "y", y_unit: str = "") -> tuple[np.ndarray, np.ndarray]:
    """Validate a sampled signal: strictly increasing finite time (s), same-length finite values, not constant."""
    ta = as_series(t_name, t, unit="s")
    ya = as_series(y_name, y, unit=y_unit)
    if ta.size != ya.size:
        raise ParameterError(
            f"{y_name} has {ya.size} samples and {t_name} has {ta.size}: allowed the same number of samples"
        )
    dt = np.diff(ta)
    if not np.all(dt > 0):
        i = int(np.argmax(~(dt > 0))) + 1
        raise ParameterError(
            f"{t_name}[{i}] = {ta[i]!r} s after {ta[i - 1]!r} s is out of range: allowed strictly increasing time"
        )
    if np.ptp(ya) == 0:
        raise ParameterError(f"{y_name} is constant ({ya[0]!r}): allowed a signal that varies")
    return ta, ya
