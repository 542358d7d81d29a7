"""The paper's inputs in data/: the five scenarios and the claims table."""

from __future__ import annotations

import math

import pytest

from vibration import Oscillator, SineForce, load_claims, load_scenarios, paper_defaults

# the paper, section 2.3: m = 1 kg, k = 20 N/m, F0 = 5 N, 50 s from rest
PAPER = {
    "reference": {"c": 0.5, "omega": 3.0},
    "resonance": {"c": 0.5, "omega": 4.47},
    "damping_low": {"c": 0.1, "omega": 4.47},
    "damping_nominal": {"c": 0.5, "omega": 4.47},
    "damping_high": {"c": 15.0, "omega": 4.47},
}
KINDS = {"approx", "greater", "less", "category"}


@pytest.fixture(scope="module")
def scenarios():
    return load_scenarios()


@pytest.fixture(scope="module")
def claims():
    return load_claims()


def test_the_five_scenarios_in_order(scenarios):
    assert list(scenarios) == list(PAPER)


@pytest.mark.parametrize("sid", list(PAPER))
def test_scenario_values(scenarios, sid):
    sc = scenarios[sid]
    assert sc.scenario_id == sid
    assert sc.label.strip()
    assert isinstance(sc.oscillator, Oscillator) and isinstance(sc.force, SineForce)
    assert sc.oscillator.m == 1.0  # kg
    assert sc.oscillator.k == 20.0  # N/m
    assert sc.force.F0 == 5.0  # N
    assert sc.t_end == 50.0  # s
    assert sc.x0 == 0.0 and sc.v0 == 0.0  # at rest
    assert sc.oscillator.c == PAPER[sid]["c"]  # N s/m
    assert sc.force.omega == PAPER[sid]["omega"]  # rad/s


def test_resonance_frequency_is_sqrt_k_over_m_to_three_figures(scenarios):
    wn = scenarios["resonance"].oscillator.natural_frequency
    assert scenarios["resonance"].force.omega == pytest.approx(wn, abs=0.005)
    assert wn == pytest.approx(math.sqrt(20.0), rel=1e-15)


def test_regimes_of_the_damping_study(scenarios):
    assert scenarios["damping_low"].oscillator.regime == "underdamped"
    assert scenarios["damping_nominal"].oscillator.regime == "underdamped"
    assert scenarios["damping_high"].oscillator.regime == "overdamped"


def test_paper_defaults_follow_the_scenarios(scenarios):
    d = paper_defaults()
    assert (d["m"], d["k"], d["F0"], d["t_end"]) == (1.0, 20.0, 5.0, 50.0)
    assert d["omega_ref"] == scenarios["reference"].force.omega == 3.0
    assert d["omega_res"] == scenarios["resonance"].force.omega == 4.47
    assert (d["c_low"], d["c_nominal"], d["c_high"]) == (0.1, 0.5, 15.0)


def test_claims_are_complete(claims):
    assert len(claims) > 0
    for row in claims:
        assert row["claim"].strip(), row
        assert row["quantity"].strip(), row
        assert row["paper_value"].strip(), row
        assert row["kind"] in KINDS, row


def test_claim_ids_are_unique(claims):
    ids = [row["claim_id"] for row in claims]
    assert all(ids) and len(set(ids)) == len(ids)


def test_claims_refer_to_existing_scenarios(claims, scenarios):
    for row in claims:
        if row["scenario_id"]:
            assert row["scenario_id"] in scenarios, row


def test_numeric_claims_are_numbers(claims):
    for row in claims:
        if row["kind"] != "category":
            value = float(row["paper_value"])
            assert math.isfinite(value), row


def test_data_folder_can_be_relocated(tmp_path, monkeypatch):
    """$VIBRATION_DATA points the loaders at another folder (here a one-scenario copy)."""
    (tmp_path / "scenarios.csv").write_text(
        "scenario_id,label,figure,m_kg,c_Ns_per_m,k_N_per_m,F0_N,omega_rad_per_s,t_end_s,x0_m,v0_m_per_s\n"
        "only,Only case,,2.0,1.0,8.0,3.0,2.0,10.0,0.1,0.0\n",
        encoding="utf-8",
    )
    monkeypatch.setenv("VIBRATION_DATA", str(tmp_path))
    sc = load_scenarios()
    assert list(sc) == ["only"]
    assert (sc["only"].oscillator.m, sc["only"].force.omega, sc["only"].x0) == (2.0, 2.0, 0.1)
