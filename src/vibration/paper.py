"""``vibration.paper``: :mod:`vibration.physics.paper` under its short name (the same module object).

``import vibration.paper`` and ``from vibration.paper import ...`` load it; ``vibration.paper`` loads it on
first use.
"""

import sys

from .physics import paper as _module

sys.modules[__name__] = _module
