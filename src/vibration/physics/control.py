"""Control: active (PD, PID, LQR), semi-active (skyhook, MR damper) and input shaping (Part II)."""

__all__: list[str] = []
