"""A learning controller measured against LQR (Part II)."""

__all__: list[str] = []
