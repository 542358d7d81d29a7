"""The MR damper: the modified Bouc-Wen model, its similitude scaling, and Spencer et al.'s identified device."""

from __future__ import annotations

from dataclasses import dataclass, replace

from ..model import check_real

__all__ = ["SPENCER_1997", "SPENCER_1997_STROKE", "MRDamper"]


@dataclass(frozen=True, kw_only=True)
class MRDamper:
    """Modified Bouc-Wen model of an MR damper (Spencer, Dyke, Sain and Carlson 1997), SI units.

    ``F = c1 y' + k1 x``, ``y' = (alpha z + c0 x' + k0 (x - y)) / (c0 + c1)``,
    ``z' = -gamma |x' - y'| z |z|^(n-1) - beta (x' - y') |z|^n + A (x' - y')``, with
    ``alpha = alpha_a + alpha_b u``, ``c0 = c0a + c0b u``, ``c1 = c1a + c1b u`` and the
    coil filter ``u' = -eta (u - V)`` on the commanded voltage ``V`` in ``[0, v_max]``.
    ``x`` is the piston displacement (relative to the base), ``F`` the force it resists with.
    The accumulator preload ``k1 x0`` of the original is left out: a constant force only
    shifts the static equilibrium.
    """

    c0a: float  # viscous damping at large velocity, 0 V, N s/m
    c0b: float  # its voltage slope, N s/(m V)
    k0: float  # stiffness at large velocity, N/m
    c1a: float  # viscous damping at low velocity (roll-off), 0 V, N s/m
    c1b: float  # its voltage slope, N s/(m V)
    k1: float  # accumulator stiffness, N/m
    alpha_a: float  # evolutionary coefficient, 0 V, N/m
    alpha_b: float  # its voltage slope, N/(m V)
    gamma: float  # Bouc-Wen shape, 1/m^2 (for n = 2)
    beta: float  # Bouc-Wen shape, 1/m^2 (for n = 2)
    A: float  # Bouc-Wen scale, 1
    n: float  # Bouc-Wen exponent, 1
    eta: float  # coil (first-order filter) rate, 1/s
    v_max: float  # largest command voltage, V

    def __post_init__(self) -> None:
        for name in ("c0a", "c0b", "k0", "c1a", "c1b", "k1", "alpha_a", "alpha_b", "gamma", "beta", "A"):
            object.__setattr__(self, name, check_real(name, getattr(self, name), low=0.0))
        object.__setattr__(self, "c1a", check_real("c1a", self.c1a, low=0.0, low_open=True, unit="N s/m"))
        object.__setattr__(self, "n", check_real("n", self.n, low=1.0, high=4.0))
        object.__setattr__(self, "eta", check_real("eta", self.eta, low=0.0, low_open=True, unit="1/s"))
        object.__setattr__(self, "v_max", check_real("v_max", self.v_max, low=0.0, unit="V"))

    @property
    def z_max(self) -> float:
        """Largest evolutionary displacement ``(A / (gamma + beta))^(1/n)``, m."""
        return (self.A / (self.gamma + self.beta)) ** (1.0 / self.n)

    @property
    def yield_force(self) -> float:
        """Hysteretic force ``alpha z_max`` at full voltage, N."""
        return (self.alpha_a + self.alpha_b * self.v_max) * self.z_max

    def scaled(self, length: float, force: float) -> MRDamper:
        """Similitude copy: displacements times ``length``, forces times ``force``, time unchanged.

        Stiffnesses and damping coefficients scale by ``force / length``, ``gamma`` and
        ``beta`` (for n = 2) by ``1 / length^n``, ``A``, ``n``, ``eta`` and the voltage are unchanged, so
        the scaled device run at ``length`` times the stroke gives exactly ``force`` times
        the force history.

        Examples
        --------
        >>> d = SPENCER_1997.scaled(length=2.0, force=0.5)
        >>> round(d.yield_force / SPENCER_1997.yield_force, 12), round(d.z_max / SPENCER_1997.z_max, 12)
        (0.5, 2.0)
        """
        length = check_real("length", length, low=0.0, low_open=True)
        force = check_real("force", force, low=0.0, low_open=True)
        s, g = force / length, length ** (-self.n)
        return replace(
            self,
            c0a=self.c0a * s,
            c0b=self.c0b * s,
            k0=self.k0 * s,
            c1a=self.c1a * s,
            c1b=self.c1b * s,
            k1=self.k1 * s,
            alpha_a=self.alpha_a * s,
            alpha_b=self.alpha_b * s,
            gamma=self.gamma * g,
            beta=self.beta * g,
        )


#: Spencer, Dyke, Sain and Carlson (1997), "Phenomenological model for magnetorheological
#: dampers", J. Eng. Mech. 123(3):230-238, parameters of the modified Bouc-Wen model
#: identified for their prototype damper (about 3000 N capacity, tested at 1.5 cm and
#: 2.5 Hz, 0-2.25 V): c0a 21.0 N s/cm, c0b 3.50 N s/(cm V), k0 46.9 N/cm, c1a 283 N s/cm,
#: c1b 2.95 N s/(cm V), k1 5.00 N/cm, x0 14.3 cm (preload, not used), alpha_a 140 N/cm,
#: alpha_b 695 N/(cm V), gamma = beta = 363 cm^-2, A 301, n 2, eta 190 1/s; here in SI.
SPENCER_1997 = MRDamper(
    c0a=21.0e2,
    c0b=3.50e2,
    k0=46.9e2,
    c1a=283.0e2,
    c1b=2.95e2,
    k1=5.00e2,
    alpha_a=140.0e2,
    alpha_b=695.0e2,
    gamma=363.0e4,
    beta=363.0e4,
    A=301.0,
    n=2.0,
    eta=190.0,
    v_max=2.25,
)

#: Displacement amplitude of the tests the parameters were identified on, m (1.5 cm).
SPENCER_1997_STROKE = 0.015
