"""Chapter 5, explore the parameters."""

from vibration.chapters.explore.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
