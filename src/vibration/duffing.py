"""``vibration.duffing``: :mod:`vibration.physics.duffing` under its short name (the same module object).

``import vibration.duffing`` and ``from vibration.duffing import ...`` load it; ``vibration.duffing`` loads it on
first use.
"""

import sys

from .physics import duffing as _module

sys.modules[__name__] = _module
