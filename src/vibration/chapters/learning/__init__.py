"""Chapter 11, a learning controller."""

from vibration.chapters.learning.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
