"""Tuned mass dampers and multi-degree-of-freedom structures (Part II)."""

__all__: list[str] = []
