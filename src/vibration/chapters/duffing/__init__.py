"""Chapter 9, the Duffing oscillator."""

from vibration.chapters.duffing.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
