"""Array arguments: one checker that refuses what a real-valued, finite sample array cannot be.

:func:`check_array` complements :func:`vibration.physics.model.check_real` (scalars) for
arguments such as time grids, frequency grids and sampled responses. It refuses strings,
booleans, complex numbers, objects, nan and inf, empty arrays, arrays of the wrong
dimension and arrays beyond a size limit, with a :class:`ParameterError` that names the
parameter, what it was and what is allowed.
"""

from __future__ import annotations

import numbers

import numpy as np

from .model import N_POINTS_MAX, ParameterError

__all__ = ["check_array"]


def _show(value) -> str:
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def check_array(
    name: str,
    value,
    *,
    low: float | None = None,
    high: float | None = None,
    low_open: bool = False,
    ndim: tuple[int, ...] = (0, 1),
    min_size: int = 1,
    max_size: int = N_POINTS_MAX,
    increasing: bool = False,
    unit: str = "",
) -> np.ndarray:
    """Return ``value`` as a float array, or raise :class:`ParameterError`.

    Parameters
    ----------
    name : str
        Parameter name used in the message.
    value : array_like
        Real numbers (Python or numpy ints and floats; no bools, complex, strings, objects).
    low, high : float, optional
        Inclusive bounds on every element (``low`` exclusive when ``low_open``).
    ndim : tuple of int
        Allowed numbers of dimensions (scalar 0, vector 1, ...).
    min_size, max_size : int
        Allowed number of elements.
    increasing : bool
        Require strictly increasing elements (a 1-D grid of times).
    unit : str
        Unit shown in the message.

    Examples
    --------
    >>> check_array("t", [0.0, 1.0, 2.0], low=0.0, unit="s")
    array([0., 1., 2.])
    >>> check_array("t", [0.0, float("nan")], unit="s")
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: t contains nan s: allowed finite real numbers
    """
    u = f" {unit}" if unit else ""
    if isinstance(value, (str, bytes)):
        raise ParameterError(f"{name} = {_show(value)} is a string: allowed an array of real numbers{u}")
    if isinstance(value, np.ndarray):
        arr = value
    elif isinstance(value, numbers.Number) or value is None:
        arr = np.asarray(value)
    else:
        try:
            arr = np.asarray(value)
        except (TypeError, ValueError):
            raise ParameterError(
                f"{name} = {_show(value)} is not an array of numbers: allowed real numbers{u}"
            ) from None
    kind = arr.dtype.kind
    if kind == "b":
        raise ParameterError(f"{name} = {_show(value)} holds booleans: allowed real numbers{u}")
    if kind == "c":
        raise ParameterError(f"{name} = {_show(value)} holds complex numbers: allowed real numbers{u}")
    if kind not in "iuf":
        raise ParameterError(
            f"{name} = {_show(value)} is not an array of real numbers (dtype {arr.dtype}): allowed real numbers{u}"
        )
    if arr.ndim not in ndim:
        raise ParameterError(f"{name} has shape {arr.shape}: allowed {' or '.join(f'{d}-D' for d in ndim)}")
    if not min_size <= arr.size <= max_size:
        raise ParameterError(f"{name} has {arr.size} elements: allowed {min_size} to {max_size}")
    out = arr.astype(float)
    bad = ~np.isfinite(out)
    if bad.any():
        raise ParameterError(f"{name} contains {float(out[bad].ravel()[0])!r}{u}: allowed finite real numbers")
    if low is not None:
        below = out <= low if low_open else out < low
        if below.any():
            sign = ">" if low_open else ">="
            raise ParameterError(
                f"{name} contains {float(out[below].ravel()[0])!r}{u}: allowed {name} {sign} {low:g}{u}"
            )
    if high is not None and (out > high).any():
        raise ParameterError(f"{name} contains {float(out[out > high].ravel()[0])!r}{u}: allowed {name} <= {high:g}{u}")
    if increasing and out.ndim == 1 and out.size > 1 and not np.all(np.diff(out) > 0.0):
        j = int(np.argmax(~(np.diff(out) > 0.0)))
        raise ParameterError(
            f"{name} is not strictly increasing ({name}[{j}] = {out[j]!r}, {name}[{j + 1}] = {out[j + 1]!r}): "
            "allowed strictly increasing values"
        )
    return out + 0.0
