"""``vibration.learn``: the short name of :mod:`vibration.physics.learning.env` (needs the ``learn`` extra).

The environment, its registration and the learners live in the physics layer; this module only forwards
to that one (``vibration.learn.train is vibration.physics.learning.env.train``), so that
``import vibration.learn as learn`` reads as the chapter's examples do.
"""

from .physics.learning import env as _env

__all__ = list(_env.__all__)


def __getattr__(name: str):
    return getattr(_env, name)


def __dir__() -> list[str]:
    return sorted(set(__all__) | set(dir(_env)))
