"""Chapter 12's exercises: objectives, and answers that follow the folder's data (checked independently)."""

from __future__ import annotations

import math
import re

import numpy as np
import pohl_generator as gen
import pytest
from scipy import signal

from vibration.book.chapters.real_oscillator import exercises as ex
from vibration.book.chapters.real_oscillator.params import Params
from vibration.book.chapters.real_oscillator.study import lab_folder
from vibration.physics.lab import harmonic_fit, load_lab_data, steadiness


def test_objectives_and_prerequisites():
    assert 3 <= len(ex.OBJECTIVES) <= 5 and ex.PREREQUISITES
    assert all(re.match(r"(Compute|Estimate|Explain|Judge)\b", o) for o in ex.OBJECTIVES)


@pytest.mark.slow  # over 2 s: make test-slow runs it
def test_answers_follow_todays_data():
    items = {e.id: e for e in ex.exercises(Params())}
    assert {"12.1", "12.2", "12.3", "12.4"} <= set(items)
    data = load_lab_data(lab_folder(Params().lab_data))
    run = data.select(kind="free")[0]
    # 12.1: the loss from the raw extrema (scipy's own peak finder, no refinement) within two encoder steps
    y = np.asarray(run.angle)
    i0 = int(np.argmax(np.abs(y - np.median(y))))
    hi, _ = signal.find_peaks(y, prominence=0.1)
    lo, _ = signal.find_peaks(-y, prominence=0.1)
    idx = np.sort(np.concatenate([hi, lo]))
    idx = idx[idx > i0][:3]
    x0, x1 = abs(y[idx[0]] - y[idx[1]]) / 2, abs(y[idx[1]] - y[idx[2]]) / 2
    loss, zeta = items["12.1"].answers
    assert abs(loss.value - (x0 - x1)) < 2 * math.pi / 180
    # the ratio follows from the numbers the question states (closed form)
    given = [float(v) for v in re.findall(r"= ([0-9.]+) rad", items["12.1"].text)]
    d = math.log(given[0] / given[1])
    assert zeta.accepts(d / math.hypot(math.pi, d))
    # 12.3: the steady count at the looser tolerance, from the late-drift test called directly
    n = 0
    for r in data.select(kind="driven"):
        w = harmonic_fit(r.t, r.data.drive_angle).omega
        n += steadiness(r.t, r.angle, w, tolerance=ex.EXPLORE_TOLERANCE).steady
    assert items["12.3"].answers[0].accepts(n)
    assert "-p tolerance" in items["12.3"].text
    assert items["12.4"].correct == "a"


@pytest.mark.slow  # a whole study of a generated lab's files
def test_exercises_on_another_lab(tmp_path):
    gen.write_lab(tmp_path)
    items = {e.id: e for e in ex.exercises(Params(lab_data=str(tmp_path)))}
    # 12.2: dry friction alone would be half the median loss; the simulated wheel at 0 mA is mostly dry friction
    assert items["12.2"].answers[0].accepts(ex_value(items["12.2"]) / 2)
    assert 0.5 * gen.DELTA < items["12.2"].answers[0].value < 2.0 * gen.DELTA


def ex_value(e) -> float:
    return float(re.search(r"median ([0-9.]+) rad", e.text).group(1))
