"""Stability and damping as a design choice (Part II)."""

__all__: list[str] = []
