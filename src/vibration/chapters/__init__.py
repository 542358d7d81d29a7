"""The report's chapters, one package each (new chapters are born here).

A chapter package holds everything that is that chapter's and nothing else: its parameter
schema (``params.py``, a :class:`vibration.presentation.schema.Schema` named ``SCHEMA``), its
study (pure computation returning frozen records), its figures, tables and sentences, and its
kernel-free panel. Chapters import the physics library and the shared presentation helpers,
never each other (import-linter checks both); the publishing layer finds them by their schema.
"""
