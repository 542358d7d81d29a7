"""``vibration.learning``: :mod:`vibration.physics.learning` under its short name (the same module object).

``import vibration.learning`` and ``from vibration.learning import ...`` load it; ``vibration.learning`` loads it on
first use.
"""

import sys

from .physics import learning as _module

sys.modules[__name__] = _module
