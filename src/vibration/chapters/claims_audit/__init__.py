"""Chapter 2, the paper's claims audited."""

from vibration.chapters.claims_audit.params import SCHEMA, Params

__all__ = ["SCHEMA", "Params"]
