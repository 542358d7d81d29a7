"""Figures drawn once per study for the tests that read them: drawing is most of a chapter test's time, and
the tests only read the figures, their captions and their remarks."""

from __future__ import annotations

import functools


def drawn_once(make):
    """``make(study)``, computed once for each study object and then handed back again."""
    cache: dict[int, tuple[object, object]] = {}

    @functools.wraps(make)
    def draw(study):
        held = cache.get(id(study))
        if held is None or held[0] is not study:
            held = cache[id(study)] = (study, make(study))
        return held[1]

    return draw
