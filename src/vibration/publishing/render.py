"""Retired: the book (:mod:`vibration.publishing.book`) renders the chapters now.

Kept only as an alias of :func:`vibration.publishing.mathml.external_urls` and
:func:`~vibration.publishing.mathml.latex_to_mathml` for older imports.
"""

from .mathml import external_urls, latex_to_mathml

__all__ = ["external_urls", "latex_to_mathml"]
