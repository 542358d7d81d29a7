"""Marks for the doctests pytest collects under ``src`` (the tests' own helpers are in ``tests/conftest.py``)."""

import pytest

#: Doctests whose example computes a whole chapter study or figure set (seconds each): ``make test-slow`` runs them.
SLOW_DOCTESTS = {
    "vibration.book.chapters.duffing.study.duffing_study",
    "vibration.book.chapters.tmd.figures.building_schematic",
    "vibration.physics.duffing.orbits.continue_orbits",
}


def pytest_collection_modifyitems(items):
    for item in items:
        if item.name in SLOW_DOCTESTS:
            item.add_marker(pytest.mark.slow)
