"""The paper's claims replayed on the hardware: each gets exactly one verdict the data support.

Verdicts are one of :data:`VERDICTS`; a claim the folder's runs cannot decide is "not testable with
these data", with the measurement that would test it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from vibration.book.chapters.real_oscillator.notation import angle, pm
from vibration.book.chapters.real_oscillator.study import RealOscillatorStudy, omega_n
from vibration.book.presentation.narrative import g
from vibration.book.presentation.numbers import error
from vibration.book.presentation.tables import Table, columns
from vibration.physics.paper import load_claims

VERDICTS = ("supported", "partly supported", "not supported", "not testable with these data")
#: The paper's amplification and the factor within which "approximately" holds.
PAPER_AMPLIFICATION, ABOUT_FACTOR = 10.0, 1.5
#: The paper's "almost completely suppressed": at most this fraction of the lightly damped amplitude.
SUPPRESSED = 0.1
#: Runs within this relative distance of ωₙ are "at resonance"; beyond LOW_RATIO ωₙ "far below".
NEAR, LOW_RATIO = 0.05, 0.7
#: Each claim in a few words (the key-results box).
SHORT = {
    "C09": "about 10-fold at resonance",
    "C18": "damping suppresses resonance",
    "C19": "grows uncontrollably",
    "C-damping": "damping matters most near resonance",
}


@dataclass(frozen=True, kw_only=True)
class Claim:
    """One claim with its verdict."""

    claim_id: str
    claim: str
    short: str
    verdict: str
    detail: str


def _claim(claim_id: str, claim: str, *, verdict: str, detail: str) -> Claim:
    """The claim ``claim_id`` (the paper's words ``claim``) with its verdict and evidence."""
    return Claim(claim_id=claim_id, claim=claim, short=SHORT[claim_id], verdict=verdict, detail=detail)


def _ratio_groups(st, brake):
    """Steady groups of a brake setting with amplitude per unit drive (and its error)."""
    out = []
    for gr in st.groups:
        if gr.brake != brake or not gr.n_steady:
            continue
        u = float(np.mean([d.drive_amp for d in gr.runs if d.steady.steady]))
        if not (math.isfinite(u) and u > 0):
            continue
        out.append((gr, gr.amplitude / u, (gr.amplitude_stderr if math.isfinite(gr.amplitude_stderr) else 0.0) / u))
    return out


def _amplification(st):
    wn = omega_n(st)
    res = {}
    for brake in dict.fromkeys(d.run.brake for d in st.driven):
        rg = _ratio_groups(st, brake)
        low = [x for x in rg if x[0].omega <= LOW_RATIO * wn]
        if not low:
            continue
        gl, rl, sl = min(low, key=lambda x: x[0].omega)
        r2 = (gl.omega / wn) ** 2
        static, static_se = rl * abs(1.0 - r2), sl * abs(1.0 - r2)
        for sess in dict.fromkeys(x[0].session for x in rg):
            near = [x for x in rg if x[0].session == sess and abs(x[0].omega / wn - 1.0) <= NEAR]
            if not near:
                continue
            gp, rp, sp = max(near, key=lambda x: x[1])
            a = rp / static
            se = a * math.hypot(sp / rp if rp else 0.0, static_se / static if static else 0.0)
            # across sessions only with the session-to-session spread as a systematic error
            sys = a * st.spread.spread if gl.session != sess else 0.0
            res[(brake, sess)] = (a, se, gp, gl.session, sys)
    return res


def _c09(st, quote) -> Claim:
    amp = _amplification(st)
    if not amp:
        return _claim(
            "C09",
            quote,
            verdict=VERDICTS[3],
            detail="needs steady runs at resonance and far below it (ω ≤ 0.7 ωₙ) at one brake setting",
        )
    ok = [abs(math.log(a / PAPER_AMPLIFICATION)) <= math.log(ABOUT_FACTOR) for a, *_ in amp.values()]
    verdict = VERDICTS[0] if all(ok) else VERDICTS[1] if any(ok) else VERDICTS[2]

    def one(b, s, a, se, gp, static_session, sys):
        where = f"brake {b}, session {s}, steady at {angle(gp.amplitude)}"
        if static_session == s:
            return f"{pm(a, se, 3)} ({where})"
        if math.isfinite(sys):
            return (
                f"{pm(a, se, 3)} ± {error(sys)} systematic ({where}; static amplitude from session {static_session}, "
                "the systematic error from the session-to-session spread)"
            )
        return (
            f"{pm(a, se, 3)} ({where}; static amplitude from session {static_session}, the session-to-session "
            "spread unknown: no matched frequencies)"
        )

    detail = "; ".join(one(b, s, *v) for (b, s), v in amp.items())
    return _claim(
        "C09",
        quote,
        verdict=verdict,
        detail=f"steady resonant amplitude over the static one: {detail}",
    )


def _settings_order(st):
    """Driven brake settings ordered from least to most damped (ζ_eq in the band; manifest order otherwise)."""
    names = [s.brake for s in st.settings]
    driven = list(dict.fromkeys(d.run.brake for d in st.driven))

    def key(b):
        s = st.settings[names.index(b)] if b in names else None
        return s.zeta_eq if s is not None and math.isfinite(s.zeta_eq) else names.index(b) if b in names else 0

    return sorted(driven, key=key)


def _peak(st, brake, session):
    wn = omega_n(st)
    rg = [x for x in _ratio_groups(st, brake) if x[0].session == session and abs(x[0].omega / wn - 1.0) <= NEAR]
    return max(rg, key=lambda x: x[1]) if rg else None


def _c18(st, quote) -> Claim:
    order = _settings_order(st)
    pairs = []
    if len(order) >= 2:
        lo_b, hi_b = order[0], order[-1]
        for sess in dict.fromkeys(d.run.session for d in st.driven):
            a, b = _peak(st, lo_b, sess), _peak(st, hi_b, sess)
            if a and b:
                r = b[1] / a[1]
                se = r * math.hypot(a[2] / a[1], b[2] / b[1])
                pairs.append((sess, r, se, a[0], b[0]))
    if not pairs:
        brakes = ", ".join(order) or "none"
        return _claim(
            "C18",
            quote,
            verdict=VERDICTS[3],
            detail=f"no session has steady driven runs near resonance at two brake settings (they exist with the "
            f"brake {brakes}); such runs at a second setting in the same session (for example without the brake) "
            "would test it",
        )
    rs = [r for _, r, _, _, _ in pairs]
    if all(r <= SUPPRESSED for r in rs):
        verdict = VERDICTS[0]
    elif all(r + 2 * se < 1.0 for _, r, se, _, _ in pairs):
        verdict = VERDICTS[1]
    else:
        verdict = VERDICTS[2]
    detail = "; ".join(
        f"session {s}: brake {order[-1]} reaches {pm(r, se, 2)} of the resonant amplitude per unit drive at brake "
        f"{order[0]} ({angle(b.amplitude)} against {angle(a.amplitude)})"
        for s, r, se, a, b in pairs
    )
    return _claim("C18", quote, verdict=verdict, detail=detail)


def _c19(st, quote) -> Claim:
    wn = omega_n(st)
    near = [d for d in st.driven if abs(d.omega / wn - 1.0) <= NEAR]
    steady = [d for d in near if d.steady.steady]
    if not near:
        return _claim(
            "C19",
            quote,
            verdict=VERDICTS[3],
            detail="no driven run near resonance; runs within 5 % of ωₙ would test it",
        )
    if not steady:
        return _claim(
            "C19",
            quote,
            verdict=VERDICTS[3],
            detail=f"none of the {len(near)} runs near resonance is steady by the end of its record; longer records "
            "would test it",
        )
    t90 = float(np.median([d.steady.t90 for d in steady]))
    top = max(d.steady.amplitude for d in steady)
    return _claim(
        "C19",
        quote,
        verdict=VERDICTS[2],
        detail=f"{len(steady)} of {len(near)} runs near resonance are steady: the amplitude saturates, 90 % reached "
        f"in a median {g(t90, 2)} s, largest {angle(top)}",
    )


def _c_critical(st) -> Claim:
    order = _settings_order(st)
    text = "damping matters most near resonance (the paper's conclusion, paraphrased)"
    wn = omega_n(st)
    if len(order) < 2:
        return _claim(
            "C-damping",
            text,
            verdict=VERDICTS[3],
            detail="driven runs at one brake setting only; runs at a second setting, on and off resonance, would "
            "test it",
        )
    lo, hi = order[0], order[-1]
    near, off = [], []
    ga = {(x[0].session, round(x[0].omega, 1)): x for x in _ratio_groups(st, lo)}
    for x in _ratio_groups(st, hi):
        m = min(
            (v for k, v in ga.items() if k[0] == x[0].session and abs(v[0].omega / x[0].omega - 1.0) <= 0.02),
            key=lambda v: abs(v[0].omega - x[0].omega),
            default=None,
        )
        if m is None:
            continue
        r = x[1] / m[1]
        (near if abs(x[0].omega / wn - 1.0) <= NEAR else off if abs(x[0].omega / wn - 1.0) >= 0.1 else []).append(r)
    if not near or not off:
        return _claim(
            "C-damping",
            text,
            verdict=VERDICTS[3],
            detail="needs steady runs at both brake settings at matched frequencies, near and away from resonance",
        )
    rn, ro = float(np.mean(near)), float(np.mean(off))
    if 1.0 - rn > 2.0 * abs(1.0 - ro) and rn < 0.9:
        verdict = VERDICTS[0]
    elif rn < ro:
        verdict = VERDICTS[1]
    else:
        verdict = VERDICTS[2]
    return _claim(
        "C-damping",
        text,
        verdict=verdict,
        detail=f"amplitude at brake {hi} over that at brake {lo}: {g(rn, 3)} near resonance, {g(ro, 3)} away from it",
    )


def claims(st: RealOscillatorStudy) -> list[Claim]:
    """The paper's claims on the hardware, each with one verdict."""
    quotes = {c["claim_id"]: c["claim"] for c in load_claims()}
    return [_c09(st, quotes["C09"]), _c18(st, quotes["C18"]), _c19(st, quotes["C19"]), _c_critical(st)]


def claims_table(st: RealOscillatorStudy) -> Table:
    """The claims with verdicts and evidence."""
    rows = [{"claim": f"“{c.claim}”", "verdict": c.verdict, "detail": c.detail} for c in claims(st)]
    return Table(
        rows=rows,
        columns=columns(
            """
            claim    the paper
            verdict  verdict
            detail   evidence
            """
        ),
        caption="The paper's claims on the real oscillator, each with the verdict the measurements support and its "
        "evidence.",
        name="tab-real-claim-verdicts",
        csv=False,
    )
