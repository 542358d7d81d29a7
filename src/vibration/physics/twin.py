"""A digital twin: measurements, identification, tracking and change detection (Part II)."""

__all__: list[str] = []
