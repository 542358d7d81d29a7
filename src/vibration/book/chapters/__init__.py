"""The report's chapters, one package each (new chapters are born here).

A chapter package holds everything that is that chapter's and nothing else: its parameter
schema (``params.py``, a :class:`vibration.book.presentation.schema.Schema` named ``SCHEMA``), its
study (pure computation returning frozen records), its figures, tables and sentences, and its
kernel-free panel. Chapters import the physics library and the shared presentation helpers,
never each other (import-linter checks both); the publishing layer finds them by their schema.

``$VIBRATION_EXTRA_CHAPTERS`` (folders separated like ``$PATH``) adds folders whose packages
count as chapters too: a chapter drafted outside the source tree, or the throw-away chapter the
template test builds. ``python -m vibration.report --new-chapter 13_topic`` writes a new one.
"""

import os

EXTRA_ENV = "VIBRATION_EXTRA_CHAPTERS"
__path__ += [p for p in os.environ.get(EXTRA_ENV, "").split(os.pathsep) if p]  # noqa: F821 (a package's own)
