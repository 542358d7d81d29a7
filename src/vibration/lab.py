"""``vibration.lab``: :mod:`vibration.physics.lab` under its short name (the same module object).

``import vibration.lab`` and ``from vibration.lab import ...`` load it; ``vibration.lab`` loads it on
first use.
"""

import sys

from .physics import lab as _module

sys.modules[__name__] = _module
