"""``python -m vibration.report``: the report runner (see :mod:`vibration.publishing.report`)."""

import sys

from .publishing.report import main

if __name__ == "__main__":
    sys.exit(main())
