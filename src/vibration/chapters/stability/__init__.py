"""Chapter 6, stability and damping as a design choice."""

from vibration.chapters.stability.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
