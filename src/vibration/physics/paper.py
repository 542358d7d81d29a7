"""The paper's scenarios and claims, read from ``data/`` (the one place they live)."""

from __future__ import annotations

import csv
import os
from dataclasses import dataclass
from pathlib import Path

from .model import Oscillator, SineForce, check_real


def data_dir() -> Path:
    """Folder holding ``scenarios.csv``, ``claims.csv`` and the lab data.

    ``$VIBRATION_DATA`` if set, else the package's data: ``vibration/_data``, which in the source
    tree links to the project's ``data/`` and in an installed wheel holds a copy of it.
    """
    from importlib.resources import as_file, files

    env = os.environ.get("VIBRATION_DATA")
    if env:
        return Path(env)
    with as_file(files("vibration").joinpath("_data")) as path:  # a real folder for a regular install
        return Path(path)


@dataclass(frozen=True, kw_only=True)
class Scenario:
    """One simulated case of the paper."""

    scenario_id: str  # key, e.g. "resonance"
    label: str  # human-readable name
    figure: str  # figure of the paper that shows it ("" if none)
    oscillator: Oscillator  # m (kg), c (N s/m), k (N/m)
    force: SineForce  # F0 (N), omega (rad/s)
    t_end: float  # end of the window, s
    x0: float  # initial displacement, m
    v0: float  # initial velocity, m/s


def _read(name: str) -> list[dict[str, str]]:
    path = data_dir() / name
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def load_scenarios() -> dict[str, Scenario]:
    """The paper's scenarios keyed by ``scenario_id``, in file order.

    Examples
    --------
    >>> sc = load_scenarios()
    >>> list(sc)
    ['reference', 'resonance', 'damping_low', 'damping_nominal', 'damping_high']
    >>> sc["resonance"].force.omega, sc["damping_high"].oscillator.c
    (4.47, 15.0)
    """
    out = {}
    for row in _read("scenarios.csv"):
        out[row["scenario_id"]] = Scenario(
            scenario_id=row["scenario_id"],
            label=row["label"],
            figure=row["figure"],
            oscillator=Oscillator(m=float(row["m_kg"]), c=float(row["c_Ns_per_m"]), k=float(row["k_N_per_m"])),
            force=SineForce(F0=float(row["F0_N"]), omega=float(row["omega_rad_per_s"])),
            t_end=check_real("t_end", float(row["t_end_s"]), low=0.0, low_open=True, unit="s"),
            x0=float(row["x0_m"]),
            v0=float(row["v0_m_per_s"]),
        )
    return out


def load_claims() -> list[dict[str, str]]:
    """The paper's checkable claims as rows of ``claims.csv`` (strings, as written).

    Examples
    --------
    >>> claims = load_claims()
    >>> claims[0]["claim_id"], claims[0]["quantity"], claims[0]["paper_value"]
    ('C01', 'natural_frequency', '4.47')
    """
    return _read("claims.csv")


def paper_defaults() -> dict[str, float]:
    """The notebooks' parameter defaults as named in their ``parameters`` cells.

    Every chapter that declares one of these names must default it to this
    value (a test enforces it).

    Examples
    --------
    >>> d = paper_defaults()
    >>> d["m"], d["k"], d["F0"], d["omega_ref"], d["omega_res"], d["c_low"], d["c_high"]
    (1.0, 20.0, 5.0, 3.0, 4.47, 0.1, 15.0)
    """
    sc = load_scenarios()
    ref, res = sc["reference"], sc["resonance"]
    return {
        "m": ref.oscillator.m,
        "k": ref.oscillator.k,
        "F0": ref.force.F0,
        "t_end": ref.t_end,
        "omega_ref": ref.force.omega,
        "omega_res": res.force.omega,
        "c_nominal": res.oscillator.c,
        "c_low": sc["damping_low"].oscillator.c,
        "c_high": sc["damping_high"].oscillator.c,
    }
