"""Chapter 8's tables, each a function of a :class:`~vibration.book.chapters.tmd.study.TMDStudy`.

Every number column prints one count of significant figures (trailing zeros kept, × 10ⁿ instead
of e-notation: :class:`~vibration.book.chapters.tmd.digits.Sig`); headers and captions write symbols with
``_`` subscripts, which the table helper typesets; cells and notes use Unicode subscripts.
"""

from __future__ import annotations

import math

from vibration.book.chapters.tmd.designs import TUNINGS
from vibration.book.chapters.tmd.digits import Sig, sig
from vibration.book.chapters.tmd.study import TMDStudy
from vibration.book.presentation.tables import Column, Missing, Table, bound, columns, self_checks
from vibration.physics.tmd import mistuned_peak

#: Tables of the chapter in the order the notebook shows them (the tests build every one).
__all__ = [
    "building_load_table",
    "building_source",
    "building_table",
    "checks_table",
    "design_table",
    "response_table",
    "tuning_table",
]

_NO_ABSORBER = Missing(reason="no absorber")
_NO_REDUCTION = Missing(reason="a reduction of the absorber's own motion is not meaningful")
_UNDAMPED = Missing(reason="the bare primary is undamped: its rms displacement under white noise is infinite")


def _table(rows: list[dict], columns: list[Column], caption: str, name: str, notes=()) -> Table:
    """A :class:`Table` whose float cells print with their column's significant figures, trailing zeros kept."""
    digits = {c.key: c.digits for c in columns}
    fixed = [
        {k: (Sig(value=v, digits=digits[k]) if isinstance(v, float) and k in digits else v) for k, v in row.items()}
        for row in rows
    ]
    return Table(rows=fixed, columns=columns, caption=caption, name=name, notes=tuple(notes))


def tuning_table(st: TMDStudy) -> Table:
    """f, ζ_a (both conventions) and the peaks of each rule at each mass ratio, undamped and actual primary."""
    rows = []
    for mu, rules in st.tunings.items():
        best = min(st.peaks_actual[mu].values())
        for rule, t in rules.items():
            rows.append(
                {
                    "mu": f"{mu:g}",
                    "rule": rule.name,
                    "f": t.f,
                    "za": t.zeta_a,
                    "zap": t.zeta_a_primary,
                    "peak0": float(mistuned_peak(t, 0.0, 0.0)),
                    "peak": st.peaks_actual[mu][rule],
                    "excess": 100.0 * (st.peaks_actual[mu][rule] / best - 1.0),
                }
            )
    return _table(
        rows,
        columns(
            f"""
            mu      μ
            rule    rule
            f       f = ω_a/ω_p                      5
            za      ζ_a on ω_a                       4
            zap     ζ'_a = f ζ_a on ω_p              4  hidden
            peak0   peak, ζ_p = 0                    5
            peak    peak, ζ_p = {sig(st.zeta_p, 3)}  5
            excess  excess over the best (%)         2
            """
        ),
        caption=(
            "Absorber tunings and the largest magnification |X_p|/(F_0/k_p) they give on an undamped primary and on "
            "the actual primary; the last column compares the rules on the actual primary."
        ),
        name="tab-tmd-tunings",
        notes=(
            "ζₐ = cₐ/(2 mₐ ωₐ) throughout; Den Hartog's book states ζ′ₐ = cₐ/(2 mₐ ωₚ) = f ζₐ. The H∞ optimum is found "
            "numerically for the actual primary damping; the closed forms are optimal for an undamped primary.",
        ),
    )


def response_table(st: TMDStudy) -> Table:
    """Steady amplitude and window peak at the paper's forcing frequency, with and without the absorber."""
    t = st.chosen
    rows = [
        {"case": "primary without absorber", "amp": st.amp_without, "peak": st.peak_without, "red": 0.0},
        {
            "case": f"primary with the H∞ optimum (μ = {st.mu:g}, f = {sig(t.f)}, ζₐ = {sig(t.zeta_a)})",
            "amp": st.amp_with,
            "peak": st.peak_with,
            "red": 100.0 * (1.0 - st.amp_with / st.amp_without),
        },
        {
            "case": "absorber (relative to the ground)",
            "amp": st.amp_absorber,
            "peak": float(max(abs(st.x_absorber.min()), abs(st.x_absorber.max()))),
            "red": _NO_REDUCTION,
        },
    ]
    return _table(
        rows,
        columns(
            f"""
            case  case
            amp   steady amplitude (m)                     4
            peak  largest |x|, 0 ≤ t ≤ {st.t_end:g} s (m)  4
            red   steady reduction (%)                     3
            """
        ),
        caption=f"Response from rest to F_0 sin(ωt) at ω = {st.omega_res:g} rad/s with F_0 = {st.F0:g} N.",
        name="tab-tmd-response",
    )


def design_table(st: TMDStudy) -> Table:
    """Every tuning on the actual primary, on every criterion: peaks across the band, rms, stroke."""
    e = f"{100 * st.mistuning:g}"
    rows = []
    for design in TUNINGS:
        d = st.scores[design]
        rows.append(
            {
                "design": design.name,
                "f": d.tuning.f,
                "za": d.tuning.zeta_a,
                "nominal": d.nominal_peak,
                "lo": d.peak_low,
                "hi": d.peak_high,
                "worst": d.worst_peak,
                "rms": d.rms_ratio if math.isfinite(d.rms_ratio) else _UNDAMPED,
                "zmax": d.stroke_peak,
                "zf": st.x_static * d.stroke_force,
            }
        )
    bare = st.robust_none
    rows.append(
        {
            "design": "no absorber",
            "f": _NO_ABSORBER,
            "za": _NO_ABSORBER,
            "nominal": st.bare_peak,
            "lo": float(bare[0]),
            "hi": float(bare[-1]),
            "worst": float(bare.max()),
            "rms": 1.0 if st.zeta_p > 0 else _UNDAMPED,
            "zmax": _NO_ABSORBER,
            "zf": _NO_ABSORBER,
        }
    )
    return _table(
        rows,
        columns(
            f"""
            design   tuning
            f        f = ω_a/ω_p                               4
            za       ζ_a on ω_a                                4
            nominal  peak, nominal                             4
            lo       peak, k_p −{e} %                          4
            hi       peak, k_p +{e} %                          4
            worst    worst peak, k_p ±{e} %                    4
            rms      rms / rms without absorber                4
            zmax     largest stroke / (F_0/k_p)                4
            zf       stroke at ω = {st.omega_res:g} rad/s (m)  4
            """
        ),
        caption=(
            f"Every tuning judged on every criterion on the actual primary (ζ_p = {sig(st.zeta_p, 3)}, μ = {st.mu:g}): "
            "the nominal peak, the peak when the primary's stiffness is off (absorber unchanged), the rms "
            "displacement under a white-noise force and the absorber's stroke."
        ),
        name="tab-tmd-designs",
        notes=(
            "Peaks are |Xₚ|/(F₀/kₚ) with the nominal kₚ. The worst peak is the largest over the whole band, found by a "
            "dense search refined at its maximum.",
            "rms ratio: √(∫|H|² dr ÷ (π/(4ζₚ))), the H2 integral over the bare primary's. Stroke: the absorber's "
            f"travel relative to the primary, |Xₐ − Xₚ|; in metres for F₀ = {st.F0:g} N, kₚ = {st.k:g} N/m.",
        ),
    )


def building_source(st: TMDStudy) -> str:
    """Where the building's values come from, and whether this run uses them (plain text, a table note)."""
    chopra = (
        "the uniform five-storey shear frame of Chopra, Dynamics of Structures (100 kips/g floors, 31.54 kips/in "
        "storeys, T₁ = 2 s)"
    )
    if st.is_chopra:
        return (
            f"After {chopra}; the floor mass {sig(st.params.storey_mass, 8)} kg and storey stiffness "
            f"{sig(st.params.storey_stiffness, 5)} N/m are SI conversions of those values, and the first period "
            f"computed from them is {sig(st.first_period, 5)} s."
        )
    return (
        f"Illustrative values: this run's storey count, floor mass or storey stiffness differ from {chopra}, which "
        f"the chapter follows by default; here T₁ = {sig(st.first_period, 4)} s."
    )


def building_table(st: TMDStudy) -> Table:
    """Periods, frequencies and damping of the building's modes, and how far each moves the roof."""
    b = st.building
    w = b.natural_frequencies
    rows = []
    for i, wi in enumerate(w):
        phi = b.modes[:, i]
        rows.append(
            {
                "mode": i + 1,
                "T": float(2 * math.pi / wi),
                "fhz": float(wi / (2 * math.pi)),
                "zeta": float(b.modal_damping_ratios[i]),
                "roof": float(phi[-1] / phi[abs(phi).argmax()]),
            }
        )
    return _table(
        rows,
        columns(
            """
            mode  mode
            T     T (s)                     4
            fhz   f (Hz)                    4
            zeta  ζ                         3
            roof  roof / largest component  3
            """
        ),
        caption=f"Modes of the {b.n}-storey shear building (classical modal damping).",
        name="tab-tmd-building",
        notes=(building_source(st),),
    )


def building_load_table(st: TMDStudy) -> Table:
    """Largest roof response near the first mode under a roof force and under ground acceleration."""
    top = st.load_cases[0].omega_max / (2 * math.pi)
    rows = [
        {
            "load": c.name,
            "unit": c.unit,
            "h0": c.scale * c.peak_without,
            "f0": c.omega_without / (2 * math.pi),
            "h1": c.scale * c.peak_with,
            "f1": c.omega_with / (2 * math.pi),
            "red": 100.0 * c.reduction,
        }
        for c in st.load_cases
    ]
    return _table(
        rows,
        columns(
            """
            load  load
            unit  unit
            h0    largest roof amplitude without absorber  4
            f0    its frequency (Hz)                       4
            h1    largest with the roof absorber           4
            f1    its frequency with (Hz)                  4
            red   reduction (%)                            3
            """
        ),
        caption=(
            f"Largest steady roof amplitude between 0 and {sig(top, 4)} Hz (near the first mode) per unit load: a "
            "harmonic roof force, and a harmonic ground acceleration (roof displacement relative to the ground)."
        ),
        name="tab-tmd-building-loads",
    )


def checks_table(st: TMDStudy) -> Table:
    """Independent checks of the chapter's numbers, printed as bounds."""
    return self_checks(
        ((c.name, bound(c.value, c.tolerance), c.ok) for c in st.checks),
        caption="Independent checks of the chapter's numbers.",
        name="tab-tmd-checks",
        headers=("check", "difference", "within"),
    )
