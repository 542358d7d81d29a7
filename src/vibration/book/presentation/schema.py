"""A chapter's parameters, declared once: name, symbol, default, unit, range and meaning.

The runner range-checks ``-p`` values with it, a test checks the notebook's ``parameters`` cell
against it, and the chapter's parameter table reads it.

Examples
--------
>>> t_skip = Param(name="t_skip", symbol="t_skip", default=2.0, unit="s", low=0.0, high=20.0,
...                meaning="start of the window")
>>> s = Schema(notebook="12_real_oscillator", params=(t_skip,))
>>> s.check({"t_skip": 3.0})
{'t_skip': 3.0}
>>> s.check({"t_skip": 30.0})
Traceback (most recent call last):
...
vibration.physics.model.ParameterError: t_skip = 30.0 s is out of range: allowed t_skip >= 0 s, t_skip <= 20 s, finite
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from ...physics.model import ParameterError, check_int, check_real
from .named import by_name, check_unique


@dataclass(frozen=True, kw_only=True)
class Param:
    """One parameter of a chapter."""

    name: str  # the notebook's variable and the runner's -p NAME
    symbol: str  # how the book writes it, e.g. "ω_res" (a "_" starts a subscript)
    default: float | int | str
    unit: str  # SI unit, "" when dimensionless
    low: float | None = None  # inclusive lower bound (exclusive when low_open)
    high: float | None = None  # inclusive upper bound
    meaning: str = ""
    low_open: bool = False
    choices: tuple = ()  # for text parameters: the allowed values
    path: bool = False  # a text parameter naming a folder (the default may be relative to the project)
    items: tuple[int, int] | None = None  # a list of numbers: how many it holds at least and at most
    default_from: tuple[str, ...] = ()  # a list left empty takes the values of these parameters

    def check(self, value):
        """The value, converted and range-checked, or :class:`ParameterError`."""
        if self.items is not None:
            return self._check_list(value)
        if self.path:
            if not isinstance(value, str) or not value.strip() or len(value) > 4096 or "\0" in value:
                raise ParameterError(f"{self.name} = {value!r:.80} is not a path: allowed a folder name")
            if value == self.default:
                return value
            folder = Path(value).expanduser()
            if not folder.is_dir():
                raise ParameterError(f"{self.name} = {value!r} is not a folder: allowed an existing folder")
            return str(folder.resolve())
        if self.choices:
            if value not in self.choices:
                raise ParameterError(
                    f"{self.name} = {value!r} is not allowed: allowed one of {', '.join(map(repr, self.choices))}"
                )
            return value
        if isinstance(self.default, int) and not isinstance(self.default, bool):
            return check_int(self.name, value, low=int(self.low), high=int(self.high))
        return check_real(self.name, value, low=self.low, low_open=self.low_open, high=self.high, unit=self.unit)

    def resolved(self, values: Mapping) -> tuple:
        """The list an empty value stands for: the values of :attr:`default_from` in ``values``, equal ones once
        (c_low = c_nominal is one damping)."""
        return self.check(list(dict.fromkeys(values[n] for n in self.default_from)))

    def _check_list(self, value) -> tuple:
        """A list of numbers: its length within ``items``, each element in range, no two equal; a tuple."""
        fewest, most = self.items
        if isinstance(value, str | bytes) or not hasattr(value, "__len__"):
            raise ParameterError(f"{self.name} = {value!r:.80} is not a list: allowed a list such as [0.1, 0.5, 15]")
        if not (fewest <= len(value) <= most) and not (len(value) == 0 and self.default_from):
            raise ParameterError(
                f"{self.name} holds {len(value)} values: allowed {fewest} to {most}"
                + (" (or none, for the default)" if self.default_from else "")
            )
        out = tuple(
            check_real(f"{self.name}[{i}]", x, low=self.low, low_open=self.low_open, high=self.high, unit=self.unit)
            for i, x in enumerate(value)
        )
        for i, x in enumerate(out):
            if x in out[:i]:
                raise ParameterError(
                    f"{self.name}[{i}] = {x!r} {self.unit} repeats {self.name}[{out.index(x)}]: allowed distinct values"
                )
        return out


@dataclass(frozen=True, kw_only=True)
class Schema:
    """The parameters of one chapter (its notebook's stem) and the rules that tie several together."""

    notebook: str  # e.g. "12_real_oscillator"
    params: tuple[Param, ...]
    #: checks on the whole set of values (e.g. ordered ranges); each raises ParameterError
    together: tuple[Callable[[dict], None], ...] = field(default=())

    def __post_init__(self) -> None:
        check_unique([p.name for p in self.params], f"schema {self.notebook}: a parameter")

    def __getitem__(self, name: str) -> Param:
        return by_name(self.params, name)

    def defaults(self) -> dict:
        """Every parameter at its default."""
        return {p.name: p.default for p in self.params}

    def names(self) -> tuple[str, ...]:
        """The parameters' names, in declaration order."""
        return tuple(p.name for p in self.params)

    def record_type(self, name: str = "Params", *, module: str | None = None) -> type:
        """A frozen dataclass with one field per parameter (defaults from here), checked on construction.

        The chapter's ``Params = SCHEMA.record_type(module=__name__)`` writes each parameter once: ``Params(**values)``
        checks every value and the rules that tie them together; ``Params.from_values(mapping)`` takes
        a mapping (missing names keep their defaults); ``Params.from_namespace(globals())`` takes every
        parameter from a notebook's namespace after its parameters cell, in one call that restates no name.
        With ``module``, the module that binds the class under ``name``, its records pickle.

        >>> n = Param(name="n", symbol="n", default=3, unit="", low=1, high=9, meaning="count")
        >>> c = Param(name="c", symbol="c", default=0.5, unit="N s/m", low=0.0, high=9.0, meaning="d")
        >>> S = Schema(notebook="x", params=(n, c))
        >>> P = S.record_type()
        >>> P(), P.from_values({"n": 4}).n
        (Params(n=3, c=0.5), 4)
        >>> P.from_namespace({"n": 5, "c": 0.25, "other": "not a parameter"})
        Params(n=5, c=0.25)
        >>> P.from_namespace({"n": 5})
        Traceback (most recent call last):
        ...
        vibration.physics.model.ParameterError: parameter 'c' is not in the namespace: allowed one defining n, c
        >>> P(n=10)
        Traceback (most recent call last):
        ...
        vibration.physics.model.ParameterError: n = 10 is out of range: allowed integer 1 <= n <= 9
        """
        schema = self

        def post_init(rec) -> None:
            checked = schema.check({f.name: getattr(rec, f.name) for f in dataclasses.fields(rec)})
            for key, value in checked.items():  # store the converted value (an int given for a float, ...)
                object.__setattr__(rec, key, value)

        def from_values(cls, values: Mapping | None = None):
            return cls(**(schema.defaults() | schema.check(dict(values or {}))))

        def from_namespace(cls, namespace: Mapping):
            missing = [n for n in schema.names() if n not in namespace]
            if missing:
                raise ParameterError(
                    f"parameter {missing[0]!r} is not in the namespace: allowed one defining "
                    + ", ".join(schema.names())
                )
            return cls(**{n: namespace[n] for n in schema.names()})

        def as_dict(rec) -> dict:
            return {f.name: getattr(rec, f.name) for f in dataclasses.fields(rec)}

        types = {str: str, int: int, float: float, bool: bool, tuple: tuple}
        cls = dataclasses.make_dataclass(
            name,
            [(p.name, types[type(p.default)], field(default=p.default)) for p in self.params],
            namespace={
                "__post_init__": post_init,
                "from_values": classmethod(from_values),
                "from_namespace": classmethod(from_namespace),
                "as_dict": as_dict,
                "SCHEMA": self,
                "__doc__": f"The validated parameters of {self.notebook} (defaults and ranges: its SCHEMA).",
            },
            frozen=True,
            kw_only=True,
        )
        if module is not None:  # found where it is bound, so a record pickles (worker processes, caches)
            cls.__module__ = module
        return cls

    def check(self, values: Mapping) -> dict:
        """``values`` (some or all parameters) checked one by one and together with the defaults of the rest."""
        out = {}
        for name, value in values.items():
            try:
                param = self[name]
            except KeyError:
                allowed = ", ".join(p.name for p in self.params)
                raise ParameterError(
                    f"parameter {name!r} = {value!r} is not one of {self.notebook}'s: allowed {allowed}"
                ) from None
            out[name] = param.check(value)
        full = self.defaults() | out
        for p in self.params:  # an empty list with a default source takes those parameters' values
            if p.default_from and not full[p.name]:
                full[p.name] = p.resolved(full)
                if p.name in out:
                    out[p.name] = full[p.name]
        for rule in self.together:
            rule(full)
        return out
