"""Chapter 3, solver accuracy."""

from vibration.chapters.solver_accuracy.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
