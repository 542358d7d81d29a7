"""``vibration.learn``: the short name of :mod:`vibration.physics.learning.env` (needs the ``learn`` extra).

The environment, its registration and the learners live in the physics layer; this module is that
module itself (``vibration.learn is vibration.physics.learning.env``), kept so that
``import vibration.learn as learn`` reads as the chapter's examples do.
"""

import sys

from .physics.learning import env as _env

sys.modules[__name__] = _env
