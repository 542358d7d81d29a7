"""Every public callable of ``vibration.__all__`` under the bad-input battery (issue 32).

The fast part (``make test``): every public callable has an entry, every baseline runs, and hypothesis draws a
sample of the battery. The whole battery, every parameter of every entry against every bad value of its kind, is
marked slow (``make test-slow``).
"""

from __future__ import annotations

import pytest
from battery import call, cases
from entries import ENTRIES
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import vibration
import vibration.book

#: Every callable a user reaches: the library's __all__, the names of its namespaces that earlier versions kept at
#: the top level (they still resolve there), and the book's teaching helpers.
REACHABLE = {name: getattr(vibration, name) for name in vibration.__all__ + sorted(vibration._WHERE)}
REACHABLE |= {name: getattr(vibration.book, name) for name in vibration.book.__all__}

CASES = [(entry.name, name, label) for entry in ENTRIES.values() for name, label, _ in cases(entry)]
#: Findings of the battery in code another change owns (Part III's readers and models, being rewritten): each
#: an expected failure, strict, so the fix that makes it pass must remove it from here.
KNOWN: dict[tuple[str, str, str], str] = {}
VALUES = {(entry.name, name, label): value for entry in ENTRIES.values() for name, label, value in cases(entry)}


def test_every_public_callable_has_a_fuzz_entry():
    public = {name for name, value in REACHABLE.items() if callable(value)}
    missing = sorted(public - set(ENTRIES))
    assert missing == [], f"public callables without a fuzz entry (add one line to tests/fuzz/entries.py): {missing}"
    stale = sorted(set(ENTRIES) - public)
    assert stale == [], f"fuzz entries of names no longer public: {stale}"
    for name, entry in ENTRIES.items():
        assert entry.fn is REACHABLE[name], name
        assert not entry.skip or entry.why, f"{name} skips {entry.skip} without saying why"


@pytest.mark.parametrize("name", sorted(n for n, e in ENTRIES.items() if not e.record))
def test_the_baseline_call_is_valid(name):
    call(ENTRIES[name])


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=st.sampled_from([c for c in CASES if c not in KNOWN]))
def test_a_sample_of_the_battery(case):
    entry, name, label = case
    call(ENTRIES[entry], name, VALUES[case])


@pytest.mark.slow
@pytest.mark.parametrize(
    "case",
    [pytest.param(c, marks=pytest.mark.xfail(reason=KNOWN[c], strict=True)) if c in KNOWN else c for c in CASES],
    ids=["-".join(c) for c in CASES],
)
def test_the_whole_battery(case):
    entry, name, label = case
    call(ENTRIES[entry], name, VALUES[case])
