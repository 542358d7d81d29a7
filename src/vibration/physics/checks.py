"""The shared validators of the physics layer (one module: every package imports these).

Scalars: :func:`check_real`, :func:`check_int`, :func:`check_choice` and :func:`check_records`
(re-exported from :mod:`vibration.physics.model`, where the records that use them live).
Derived quantities: :func:`check_derived` (a number computed from the arguments must be finite) and
:func:`check_count` (a step or sample count computed from the arguments must be finite and within a
budget), so that an input beyond floating point is refused naming the arguments, never an
``OverflowError`` or a silent nan.

Array arguments: one checker that refuses what a real-valued, finite sample array cannot be.

:func:`check_array` complements :func:`vibration.physics.model.check_real` (scalars) for
arguments such as time grids, frequency grids and sampled responses. It refuses strings,
booleans, complex numbers, objects, nan and inf, empty arrays, arrays of the wrong
dimension and arrays beyond a size limit, with a :class:`ParameterError` that names the
parameter, what it was and what is allowed.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from .model import N_POINTS_MAX, Oscillator, ParameterError, check_int, check_real, check_records

__all__ = [
    "OverBudget",
    "check_array",
    "check_choice",
    "check_count",
    "check_derived",
    "check_int",
    "check_oscillator",
    "check_real",
    "check_records",
    "check_start",
    "like_input",
    "optional",
]


def like_input(values, like):
    """``values`` as a float when ``like`` (the input it was computed from) is a scalar, else as it is.

    The one return convention of the library's functions of time or frequency.

    >>> like_input(np.array(2.0), 3.0), like_input(np.array([2.0]), [3.0])
    (2.0, array([2.]))
    """
    return float(values) if np.ndim(like) == 0 else values


def optional(module: str, *, extra: str, what: str):
    """Import the optional package ``module``, or raise an ``ImportError`` naming the extra that installs it.

    >>> optional("math", extra="control", what="lqr").__name__
    'math'
    """
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise ImportError(
            f"{what} needs the optional package {module!r}: install the extra with pip install 'vibration[{extra}]'",
            name=module,
        ) from exc


def _show(value) -> str:
    text = " ".join(repr(value).split())
    return text if len(text) <= 80 else text[:77] + "..."


class OverBudget(Exception):
    """Raised inside a right-hand side when its budget of evaluations is spent.

    The integrators of the physics layer wrap the right-hand side they hand to the solver in a
    counter; past its limit the counter raises this exception, which the caller catches and turns
    into a :class:`ParameterError` naming the arguments that made the run too long. It never
    reaches the user.

    Examples
    --------
    >>> try:
    ...     raise OverBudget
    ... except OverBudget:
    ...     print("stopped")
    stopped
    """


def check_oscillator(osc, name: str = "osc") -> Oscillator:
    """Return ``osc`` when it is an :class:`Oscillator`, or raise :class:`ParameterError`.

    Parameters
    ----------
    osc : Oscillator
        The record to check (mass kg, damping N s/m, stiffness N/m, validated by its constructor).
    name : str
        Parameter name used in the message.

    Returns
    -------
    Oscillator
        ``osc`` itself.

    Raises
    ------
    ParameterError
        When ``osc`` is anything else; the message names the parameter, what it was and what is allowed.

    Examples
    --------
    >>> check_oscillator(Oscillator(m=1.0, c=0.5, k=20.0)).k
    20.0
    >>> check_oscillator((1.0, 0.5, 20.0))
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: osc = (1.0, 0.5, 20.0) is not an Oscillator: allowed Oscillator(m, c, k)
    """
    if not isinstance(osc, Oscillator):
        raise ParameterError(f"{name} = {_show(osc)} is not an Oscillator: allowed Oscillator(m, c, k)")
    return osc


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
    arr = _real_dtype_array(name, value, u)
    _check_shape(name, value, arr, ndim, min_size, max_size)
    out = arr.astype(float)
    _check_elements(name, out, u, low, high, low_open, increasing)
    return out + 0.0


def _real_dtype_array(name: str, value, u: str) -> np.ndarray:
    """``value`` as a numpy array of integers or floats (not yet converted), or :class:`ParameterError`."""
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
    return arr


def _check_shape(name: str, value, arr: np.ndarray, ndim: tuple[int, ...], min_size: int, max_size: int) -> None:
    """Refuse an array ``arr`` (given as ``value``) whose number of dimensions or of elements is not allowed."""
    if arr.ndim not in ndim:
        dims = " or ".join(f"{d}-D" for d in ndim) if len(ndim) <= 4 else f"at most {max(ndim)}-D"
        raise ParameterError(f"{name} has shape {arr.shape} ({name} = {_show(value)}): allowed {dims}")
    if not min_size <= arr.size <= max_size:
        raise ParameterError(
            f"{name} has {arr.size} elements ({name} = {_show(value)}): allowed "
            + ("a non-empty array, " if arr.size == 0 else "")
            + f"{min_size} to {max_size} elements"
        )


def _check_elements(
    name: str, out: np.ndarray, u: str, low: float | None, high: float | None, low_open: bool, increasing: bool
) -> None:
    """Refuse a float array ``out`` with a non-finite element, one out of bounds, or not strictly increasing."""
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


def _inputs(inputs: dict) -> str:
    return ", ".join(f"{k} = {_show(v)}" for k, v in inputs.items())


def check_start(start, name: str = "start") -> tuple[float, float]:
    """An initial state ``(x0, v0)``: displacement (m) and velocity (m/s), both finite reals.

    Examples
    --------
    >>> check_start((3, 0.0))
    (3.0, 0.0)
    >>> check_start(3.0)
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: start = 3.0 is not valid: allowed a pair (x0 in m, v0 in m/s)
    """
    if isinstance(start, (str, bytes)) or not hasattr(start, "__len__") or len(start) != 2:
        raise ParameterError(f"{name} = {_show(start)} is not valid: allowed a pair (x0 in m, v0 in m/s)")
    if name == "start":  # the library's initial state is x0 and v0
        return check_real("x0", start[0], unit="m"), check_real("v0", start[1], unit="m/s")
    return check_real(f"{name}[0] (x0)", start[0], unit="m"), check_real(f"{name}[1] (v0)", start[1], unit="m/s")


def check_choice(name: str, value, choices) -> str:
    """Return ``value`` when it is one of ``choices`` (strings), or raise :class:`ParameterError`.

    Examples
    --------
    >>> check_choice("rule", "H2", ("H∞", "H2"))
    'H2'
    >>> check_choice("rule", ["H2"], ("H∞", "H2"))
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: rule = ['H2'] is not one of the allowed values: allowed 'H∞' or 'H2'
    """
    allowed = " or ".join(repr(c) for c in choices)
    if not isinstance(value, str) or value not in choices:
        raise ParameterError(f"{name} = {_show(value)} is not one of the allowed values: allowed {allowed}")
    return value


def check_derived(what: str, value: float, *, inputs: dict, allowed: str) -> float:
    """Return ``value`` (a number computed from the arguments) when finite, or raise :class:`ParameterError`.

    Parameters
    ----------
    what : str
        The derived quantity, with its unit, as the message names it (``"the forcing period 2π/omega (s)"``).
    value : float
        Its value.
    inputs : dict
        The arguments it came from, by name: the message shows each with its value.
    allowed : str
        What the arguments may be.

    Examples
    --------
    >>> check_derived("T (s)", float("inf"), inputs={"omega": 1e-320}, allowed="omega >= 1e-300")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: omega = 1e-320 makes T (s) inf, beyond floating point: allowed ...
    """
    v = float(value)
    if not math.isfinite(v):
        raise ParameterError(f"{_inputs(inputs)} makes {what} {v!r}, beyond floating point: allowed {allowed}")
    return v


def check_count(what: str, value: float, *, inputs: dict, high: int, advice: str = "") -> int:
    """Return ``ceil(value)`` (a step or sample count computed from the arguments), or raise :class:`ParameterError`.

    The count must be finite and at most ``high``: an input beyond floating point (a step of
    1e-320 s, a rate of 1e300 1/s) is refused naming the arguments, never an ``OverflowError``.

    Examples
    --------
    >>> check_count("RK4 steps", 1234.2, inputs={"t_end": 12.342, "dt": 0.01}, high=10**6)
    1235
    >>> check_count("RK4 steps", float("inf"), inputs={"dt": 1e-320}, high=10**6)
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: dt = 1e-320 needs inf RK4 steps: allowed at most 1000000
    """
    v = float(value)
    if not (math.isfinite(v) and v <= high):
        tail = f" ({advice})" if advice else ""
        raise ParameterError(f"{_inputs(inputs)} needs {v:.4g} {what}: allowed at most {high}{tail}")
    return max(int(math.ceil(v)), 0)
