"""``vibration.stability``: :mod:`vibration.physics.stability` under its short name (the same module object).

``import vibration.stability`` and ``from vibration.stability import ...`` load it; ``vibration.stability`` loads it on
first use.
"""

import sys

from .physics import stability as _module

sys.modules[__name__] = _module
