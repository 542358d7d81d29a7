"""Chapter 4, frequency response and design map."""

from vibration.chapters.frequency_response.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
