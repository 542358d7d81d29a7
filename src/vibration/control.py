"""``vibration.control``: :mod:`vibration.physics.control` under its short name (the same module object).

``import vibration.control`` and ``from vibration.control import ...`` load it; ``vibration.control`` loads it on
first use.
"""

import sys

from .physics import control as _module

sys.modules[__name__] = _module
