"""``python -m vibration.bench``: speed ratios (see :mod:`vibration.publishing.bench`)."""

import sys

from .publishing.bench import main

if __name__ == "__main__":
    sys.exit(main())
