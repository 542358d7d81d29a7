"""The front page."""

from vibration.chapters.overview.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
