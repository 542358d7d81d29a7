"""Shared test helpers and the hypothesis profiles.

Profiles (choose with ``HYPOTHESIS_PROFILE=<name>``):

* ``vibration`` (default): no deadline (the first call of a compiled or
  cached path can be slow), a modest number of examples so the suite stays fast,
  derandomized (the same examples on every run and machine, so CI cannot fail on a
  draw no one has seen);
* ``thorough``: ten times the examples, drawn at random, for an occasional deeper search
  (what it finds becomes a fix and, where useful, an ``@example``).
"""

from __future__ import annotations

import contextlib
import numbers
import os
import re
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

import vibration

#: pytester runs nbval with the numeric plugin on small notebooks (tests/notebooks/test_portable.py).
pytest_plugins = ["pytester"]

settings.register_profile(
    "vibration",
    deadline=None,
    max_examples=40,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow],
    print_blob=True,
)
settings.register_profile(
    "thorough",
    deadline=None,
    max_examples=400,
    suppress_health_check=[HealthCheck.too_slow],
    print_blob=True,
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "vibration"))


def pytest_configure(config):
    """Beside strict nbval, compare the machine-dependent table values within their declared tolerances."""
    if config.pluginmanager.hasplugin("nbval"):
        import nbval_numeric

        nbval_numeric.install()


_NO_VALUE = object()


def _value_text(value) -> str:
    """How a bad value must appear in the message (numbers as Python prints them)."""
    if isinstance(value, bool | str):
        return repr(value)
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return repr(value)


@contextlib.contextmanager
def _raises_parameter_error(name: str, bad=_NO_VALUE, *allowed: str):
    """Expect :class:`vibration.ParameterError` (also a ``ValueError``) whose
    message names ``name``, shows the bad value ``bad`` and states the allowed
    range: the word "allowed" and every fragment in ``allowed``."""
    with pytest.raises(vibration.ParameterError) as info:
        yield info
    err = info.value
    assert isinstance(err, ValueError)
    msg = str(err)
    assert re.search(rf"(?<![A-Za-z0-9_]){re.escape(name)}(?![A-Za-z0-9_])", msg), (name, msg)
    if bad is not _NO_VALUE:
        assert _value_text(bad) in msg, (_value_text(bad), msg)
    assert "allowed" in msg, msg
    for fragment in allowed:
        assert fragment in msg, (fragment, msg)


@pytest.fixture
def raises_parameter_error():
    """``with raises_parameter_error("m", 0.0, "> 0"): Oscillator(m=0.0, c=0.5, k=20.0)``."""
    return _raises_parameter_error


# ----------------------------------------------------------------------------- browser tests

#: Debian's Chromium, installed by `make browser` (never `playwright install`).
CHROMIUM = "/usr/bin/chromium"
#: Flags for a closed network: without the background-networking ones Chromium keeps calling home.
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]
ROOT = Path(__file__).resolve().parents[1]
SCREENSHOTS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "screenshots")
SCREENSHOT_DIR = Path(SCREENSHOTS)  # the same folder, as a path


def _run_folder(tmp_path_factory) -> Path:
    """The temporary folder this run's workers share: pytest-xdist's workers share the parent of their own
    folders; without workers, the run's own folder (never the one every run shares)."""
    basetemp = tmp_path_factory.getbasetemp()
    return basetemp.parent if os.environ.get("PYTEST_XDIST_WORKER") else basetemp


@contextlib.contextmanager
def _first_of_the_run(tmp_path_factory, name: str):
    """Hold the run's lock for ``name``: the first worker to ask makes the shared thing, the others wait."""
    import fcntl

    shared = _run_folder(tmp_path_factory)
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield shared
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


@pytest.fixture(scope="session")
def committed_book(tmp_path_factory) -> Path:
    """The HTML book from the committed notebooks (stored outputs, no kernel), built once for the whole run
    (by the first worker that asks; tests only read it)."""
    from vibration.book.publishing import report

    with _first_of_the_run(tmp_path_factory, "committed-book") as shared:
        out = shared / "committed-book" / "report"
        if not out.is_dir():  # built aside and renamed, so a failed build leaves no book behind
            partial = out.with_name("partial") / "report"
            shutil.rmtree(partial.parent, ignore_errors=True)
            report.book_from_sources(report.discover(ROOT), partial, pdf=False)
            partial.rename(out)
    return out


@pytest.fixture(scope="session")
def real_oscillator_default(tmp_path_factory):
    """Chapter 12's study of the bundled measurements at the default parameters (about 25 s), computed once
    for the whole run and handed to the other workers as a pickle; tests must not change it (it is frozen)."""
    import pickle

    from vibration.book.chapters.real_oscillator.study import real_oscillator_study

    with _first_of_the_run(tmp_path_factory, "real-oscillator-study") as shared:
        path = shared / "real-oscillator-study.pickle"
        if path.is_file():
            return pickle.loads(path.read_bytes())
        st = real_oscillator_study()
        partial = path.with_suffix(".partial")
        partial.write_bytes(pickle.dumps(st))
        partial.rename(path)
        return st


@pytest.fixture(scope="session")
def browser():
    """One headless Chromium for the whole session (one playwright instance per process)."""
    if not os.path.exists(CHROMIUM):
        pytest.fail(f"{CHROMIUM} is missing: run `make browser` (make test does)")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
        try:
            yield b
        finally:
            b.close()


def open_offline(browser, path, viewport=(1120, 900)):
    """Open the file ``path`` with every request that is not ``file:``/``data:`` aborted.

    Returns ``(page, outside_requests, console_errors)``; the lists fill as the page runs.
    """
    page = browser.new_page(viewport={"width": viewport[0], "height": viewport[1]})
    outside: list[str] = []
    errors: list[str] = []

    def route(r):
        url = r.request.url
        if url.startswith(("file:", "data:")):
            r.continue_()
        else:
            outside.append(url)
            r.abort()

    page.route("**/*", route)
    page.on("console", lambda msg: errors.append(msg.text) if msg.type == "error" else None)
    page.on("pageerror", lambda exc: errors.append(str(exc)))
    page.goto(path.as_uri())
    page.wait_for_load_state("load")
    return page, outside, errors


#: Parameter sets beyond the paper's and the "heavy" one that chapter tests repeat: make test checks the
#: paper's and one far set; these run in make test-slow (CI runs both), so make test stays within minutes.
SLOW_PARAMETER_SETS = {"soft", "stiff", "light", "negative", "zero-negative", "zero"}


#: Doctests under ``src`` whose example computes a whole chapter study or figure set (seconds each): marked slow here
#: (this file's hook sees every collected item, those under ``src`` too).
SLOW_DOCTESTS = {
    "vibration.book.chapters.duffing.study.duffing_study",
    "vibration.book.chapters.tmd.figures.building_schematic",
    "vibration.physics.duffing.orbits.continue_orbits",
}


def pytest_collection_modifyitems(config, items):
    for item in items:
        callspec = getattr(item, "callspec", None)
        if callspec is not None and set(callspec.id.split("-")) & SLOW_PARAMETER_SETS:
            item.add_marker(pytest.mark.slow)
        if item.name in SLOW_DOCTESTS:
            item.add_marker(pytest.mark.slow)


def panel_state(page, index: int = 0) -> dict:
    return page.evaluate(
        """(i) => {
            const p = document.querySelectorAll('div.vib-panel')[i];
            return {
                points: p.querySelector('svg.vib-time polyline.vib-x').getAttribute('points'),
                vel: p.querySelector('svg.vib-vel polyline.vib-x').getAttribute('points'),
                frf: p.querySelector('svg.vib-freq circle.vib-op').getAttribute('cx'),
                readout: p.querySelector('table.vib-readout').innerText,
                omega: p.querySelector('output.vib-omega-out').textContent,
                c: p.querySelector('output.vib-c-out').textContent,
            };
        }""",
        index,
    )


def nbval_sanitize(text: str) -> str:
    """``text`` after the regex sanitisers of tests/nbval_sanitize.cfg, as strict nbval compares it."""
    import configparser

    cfg = configparser.ConfigParser()
    cfg.read(Path(__file__).with_name("nbval_sanitize.cfg"), encoding="utf-8")
    for section in cfg.sections():
        text = re.sub(cfg[section]["regex"], cfg[section]["replace"], text)
    return text
