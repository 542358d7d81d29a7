"""``vibration.tmd``: :mod:`vibration.physics.tmd` under its short name (the same module object).

``import vibration.tmd`` and ``from vibration.tmd import ...`` load it; ``vibration.tmd`` loads it on
first use.
"""

import sys

from .physics import tmd as _module

sys.modules[__name__] = _module
