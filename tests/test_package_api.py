"""The package's top level: every public name of every chapter, once, from the module that defines it."""

from __future__ import annotations

from collections import Counter

import vibration
from vibration.physics import control, duffing, learning, stability, tmd, twin

CHAPTERS = (stability, control, tmd, duffing, twin, learning)

#: The names the issues say acceptance checks call at the top level.
REQUIRED = {
    stability: ["poles", "transmissibility", "step_metrics", "white_noise_variance"],
    control: ["lqr", "zv_shaper", "zvd_shaper", "skyhook_transmissibility"],
    tmd: ["den_hartog", "hinf_tuning", "h2_tuning", "tmd_magnification", "MDOF"],
    duffing: ["Duffing", "hb_amplitudes", "folds", "sweep"],
    twin: ["load_measurements", "identify", "detect_change"],
}


def test_no_public_name_is_exported_twice():
    names = Counter(n for module in CHAPTERS for n in module.__all__)
    core = set(vibration.__all__) - {n for module in CHAPTERS for n in module.__all__}
    twice = {n: c for n, c in names.items() if c > 1}
    assert twice == {}, f"exported by two chapters: {twice}"
    assert not (core & set(names)), f"chapter names shadow core names: {core & set(names)}"


def test_every_chapter_name_reaches_the_top_level_from_its_module():
    for module in CHAPTERS:
        for name in module.__all__:
            assert getattr(vibration, name) is getattr(module, name), (module.__name__, name)
            assert name in vibration.__all__


def test_the_names_the_issues_ask_for_exist():
    for module, names in REQUIRED.items():
        for name in names:
            assert name in module.__all__, (module.__name__, name)
            assert callable(getattr(vibration, name)), name


def test_learning_module_registers_the_environment():
    import gymnasium

    import vibration.learn

    assert "vibration/Oscillator-v0" in gymnasium.registry
    assert callable(vibration.learn.train) and callable(vibration.learn.lqr_reference)
    assert vibration.learn.OscillatorEnv.__name__ == "OscillatorEnv"
