"""``vibration.twin``: :mod:`vibration.physics.twin` under its short name (the same module object).

``import vibration.twin`` and ``from vibration.twin import ...`` load it; ``vibration.twin`` loads it on
first use.
"""

import sys

from .physics import twin as _module

sys.modules[__name__] = _module
