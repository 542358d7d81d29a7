"""Chapter 10, a digital twin."""

from vibration.chapters.digital_twin.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
