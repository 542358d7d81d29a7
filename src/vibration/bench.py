"""``python -m vibration.bench``: speed ratios (see :mod:`vibration.book.publishing.bench`)."""

import sys

from .book.publishing.bench import main

if __name__ == "__main__":
    sys.exit(main())
