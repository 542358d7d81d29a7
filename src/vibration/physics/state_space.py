"""The oscillator in state-space form, and handed to python-control."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .checks import check_oscillator
from .model import Oscillator


@dataclass(frozen=True, kw_only=True, eq=False)
class StateSpace:
    """``y' = A y + B F``, ``z = C y + D F`` with the state ``y = (x m, v m/s)``, the input F (N), outputs x and v."""

    A: np.ndarray = field(repr=False)  # 2 x 2, 1/s and 1/s^2
    B: np.ndarray = field(repr=False)  # 2 x 1, 1/kg
    C: np.ndarray = field(repr=False)  # 2 x 2, identity: the outputs are x (m) and v (m/s)
    D: np.ndarray = field(repr=False)  # 2 x 1, zero

    def __repr__(self) -> str:
        (_, _), (a, b) = self.A
        return f"StateSpace(x' = v, v' = {a:.6g} x + {b:.6g} v + {self.B[1, 0]:.6g} F; outputs x (m), v (m/s))"

    def to_control(self):
        """The same system as python-control's ``StateSpace`` (``pip install 'vibration[control]'``)."""
        try:
            import control
        except ImportError:
            raise ImportError(
                "StateSpace.to_control needs python-control: install the extra with pip install 'vibration[control]'"
            ) from None
        return control.ss(self.A, self.B, self.C, self.D, states=["x", "v"], inputs=["F"], outputs=["x", "v"])


def state_space(osc: Oscillator) -> StateSpace:
    """The state-space matrices of ``m x'' + c x' + k x = F``.

    >>> ss = state_space(Oscillator(m=1.0, c=0.5, k=20.0))
    >>> ss.A.tolist(), ss.B.ravel().tolist()
    ([[0.0, 1.0], [-20.0, -0.5]], [0.0, 1.0])
    """
    check_oscillator(osc)
    A = np.array([[0.0, 1.0], [-osc.k / osc.m, -osc.c / osc.m]])
    B = np.array([[0.0], [1.0 / osc.m]])
    return StateSpace(A=A, B=B, C=np.eye(2), D=np.zeros((2, 1)))
