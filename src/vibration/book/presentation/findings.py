"""The paper's five scenarios, shared by the Part I chapters: built from a run's parameters, named once.

:func:`scenarios_from` builds the reference run, the resonance run and the three dampings at
resonance from a chapter's (possibly changed) parameters; :func:`scenarios_of` does the same
from a chapter's ``Params`` record. The paper's resonance case and its nominal damping are the
same run (c_nominal at omega_res): :func:`same_run` finds such pairs.

Examples
--------
>>> sc = scenarios_from(1.0, 20.0, 5.0, t_end=50.0, omega_ref=3.0, omega_res=4.47, c_low=0.1,
...                     c_nominal=0.5, c_high=15.0)
>>> [case_name(s) for s in sc]
['reference', 'resonance', 'low damping', 'nominal damping', 'high damping']
>>> sc["resonance"] == sc["damping_nominal"]
False
>>> same_run(sc["resonance"], sc["damping_nominal"])
True
"""

from __future__ import annotations

from ...physics.model import Oscillator, SineForce, check_real
from ...physics.paper import Scenario
from .tables import fmt

#: Short names of the paper's scenarios, as the tables and sentences call them.
CASE_NAMES = {
    "reference": "reference",
    "resonance": "resonance",
    "damping_low": "low damping",
    "damping_nominal": "nominal damping",
    "damping_high": "high damping",
}

#: Why a quantity does not exist when the damping is not positive.
NO_STEADY = "no steady state is reached when c ≤ 0"


def case_name(sid: str) -> str:
    """Short name of scenario ``sid`` (the id itself when it is not one of the paper's)."""
    return CASE_NAMES.get(sid, sid)


def same_run(a: Scenario, b: Scenario) -> bool:
    """Whether two scenarios are the same computation (oscillator, force, window and start)."""
    return (a.oscillator, a.force, a.t_end, a.x0, a.v0) == (b.oscillator, b.force, b.t_end, b.x0, b.v0)


def scenarios_from(
    m: float,
    k: float,
    F0: float,
    *,
    t_end: float,
    omega_ref: float,
    omega_res: float,
    c_low: float,
    c_nominal: float,
    c_high: float,
) -> dict[str, Scenario]:
    """The paper's five scenarios built from (possibly overridden) chapter parameters.

    Parameters
    ----------
    m, k, F0 : float
        Mass (kg), stiffness (N/m), force amplitude (N).
    t_end : float
        End of the window, s (> 0).
    omega_ref, omega_res : float
        Reference and "resonant" forcing frequencies, rad/s.
    c_low, c_nominal, c_high : float
        Dampings, N s/m (any sign: 0 is undamped, negative is self-excited).

    Examples
    --------
    >>> sc = scenarios_from(1.0, 20.0, 5.0, t_end=50.0, omega_ref=3.0, omega_res=4.47, c_low=0.1,
    ...                     c_nominal=0.5, c_high=15.0)
    >>> [s.oscillator.c for s in sc.values()]
    [0.5, 0.5, 0.1, 0.5, 15.0]
    """
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
    rows = [
        ("reference", "Reference case (far from resonance)", "", c_nominal, omega_ref),
        ("resonance", "Resonance case", "Figure 1", c_nominal, omega_res),
        ("damping_low", "Low damping at resonance", "Figure 2", c_low, omega_res),
        ("damping_nominal", "Nominal damping at resonance", "Figure 2", c_nominal, omega_res),
        ("damping_high", "High damping at resonance", "Figure 2", c_high, omega_res),
    ]
    return {
        sid: Scenario(
            scenario_id=sid,
            label=label,
            figure=fig,
            oscillator=Oscillator(m=m, c=c, k=k),
            force=SineForce(F0=F0, omega=w),
            t_end=t_end,
            x0=0.0,
            v0=0.0,
        )
        for sid, label, fig, c, w in rows
    }


#: The parameters the paper's scenarios are built from (the arguments of :func:`scenarios_from`).
SCENARIO_PARAMETERS = ("m", "k", "F0", "t_end", "omega_ref", "omega_res", "c_low", "c_nominal", "c_high")


def scenarios_of(params) -> dict[str, Scenario]:
    """:func:`scenarios_from` for a chapter's ``Params`` record (any object with the
    :data:`SCENARIO_PARAMETERS` as attributes)."""
    return scenarios_from(**{name: getattr(params, name) for name in SCENARIO_PARAMETERS})


def at_least(value: float, floor: float):
    """``value``, or the text ``"< floor"`` when it is below ``floor``.

    For cells at rounding level, whose last digits depend on the CPU's
    floating-point paths: strict nbval then compares the bound, not the noise.

    Examples
    --------
    >>> at_least(3.2e-3, 1e-12), at_least(4.4e-16, 1e-12)
    (0.0032, '< 10⁻¹²')
    """
    return value if value >= floor else f"< {fmt(floor)}"
