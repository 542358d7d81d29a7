"""Chapter 1, the paper reproduced."""

from vibration.chapters.reproduction.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
