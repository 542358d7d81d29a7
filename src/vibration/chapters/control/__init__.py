"""Chapter 7, control."""

from vibration.chapters.control.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
