"""Chapter 8, tuned mass dampers."""

from vibration.chapters.tmd.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
