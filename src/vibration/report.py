"""``python -m vibration.report``: the report runner (see :mod:`vibration.book.publishing.report`)."""

import sys

from .book.publishing.report import main

if __name__ == "__main__":
    sys.exit(main())
