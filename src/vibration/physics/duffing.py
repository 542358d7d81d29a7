"""The Duffing oscillator: harmonic balance, sweeps, jumps and chaos (Part II)."""

__all__: list[str] = []
