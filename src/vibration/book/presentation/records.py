"""What a chapter's study record shares with its parameters: each parameter readable on the record by name.

A study record keeps the validated parameters it ran on in its ``params`` field; :func:`with_params` makes
the named ones read-only properties of the record class, so figures and sentences write ``st.m`` (kg) for
``st.params.m`` and each value is stored once. A keyword gives a parameter another name on the record.

Examples
--------
>>> from dataclasses import dataclass
>>> @dataclass(frozen=True, kw_only=True)
... class P:
...     m: float  # mass, kg
...     c_nominal: float  # damping, N s/m
>>> @with_params("m", c="c_nominal")
... @dataclass(frozen=True, kw_only=True)
... class Study:
...     params: P
>>> st = Study(params=P(m=1.0, c_nominal=0.5))
>>> st.m, st.c   # kg, N s/m
(1.0, 0.5)
"""

from __future__ import annotations

from operator import attrgetter


def from_params(name: str) -> property:
    """A read-only property giving the record's ``params.<name>`` (in the parameter's own unit)."""
    if not name.isidentifier():
        raise ValueError(f"name = {name!r} is not a parameter name: allowed a Python identifier")
    return property(attrgetter(f"params.{name}"), doc=f"The run's parameter ``{name}`` (see ``params``).")


def with_params(*names: str, **aliases: str):
    """Class decorator: each of ``names`` (and each ``alias=parameter``) a :func:`from_params` property.

    Raises
    ------
    TypeError
        When the class already defines one of those names (a field or a method would be shadowed).
    """

    def decorate(cls):
        for attr, param in {**{n: n for n in names}, **aliases}.items():
            if attr in vars(cls) or attr in getattr(cls, "__dataclass_fields__", {}):
                raise TypeError(f"{cls.__name__}.{attr} exists: allowed only names the record does not define")
            setattr(cls, attr, from_params(param))
        return cls

    return decorate


__all__ = ["from_params", "with_params"]
